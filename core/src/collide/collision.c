/* collision.c - mink/collision.h's public functions but the two queries'
 * solvers: the small helpers (contact names, the scale, a support point with
 * its Jacobian, a bound at a normal) and MinkSum (Normal)'s entry points,
 * which pick the solver's build for the processor (normal_portable.c, or
 * normal_fma.c where it has AVX2 and FMA). MinkSum (Ray) is in ray.c. */
#include "collide/collision_impl.h"
#include "collide/pair.h"

const char *mkContact_Name(mkContact c)
{
	switch (c) {
	case MK_CONTACT_SEPARATED: return "separated";
	case MK_CONTACT_TOUCHING: return "touching";
	case MK_CONTACT_OVERLAPPING: return "overlapping";
	case MK_CONTACT_UNKNOWN: break;
	}
	return "unknown";
}

mkVec3 mkBody3_SupportJacobian(mkBody3 b, mkVec3 n, mkMat3 *J)
{
	if (!(mkVec3_Dot(n, n) > 0.0)) {
		if (J)
			for (int i = 0; i < 3; ++i)
				for (int j = 0; j < 3; ++j)
					J->m[i][j] = NAN;
		return mkVec3_Make(NAN, NAN, NAN);
	}
	mkSupBody k;
	mkSupBody_Init(&k, &b);
	mkSupAt a;
	mkSupBody_Eval(&k, n, &a);
	if (J)
		mkSupAt_Jacobian(&k, &a, J->m);
	return a.s;
}

double mkCollide3_PairSize(mkBody3 b1, mkBody3 b2)
{
	return mkScale(&b1, &b2);
}

double mkCollide3_Bound(mkBody3 b1, mkBody3 b2, mkVec3 n)
{
	mkVec3 u = mkVec3_NormalizeInline(n);
	mkBody3 c1 = b1, c2 = b2;
	c1.t = c2.t = mkVec3_Make(0.0, 0.0, 0.0);
	return mkVec3_Dot(u, mkVec3_Sub(b2.t, b1.t)) - mkBody3_SupportValue(c1, u)
		- mkBody3_SupportValue(c2, mkVec3_Neg(u));
}

void mkCollision3_Clear(mkCollision3 *out)
{
	mkVec3 nan3 = mkVec3_Make(NAN, NAN, NAN);
	out->status = MK_CONTACT_UNKNOWN;
	out->distance = out->directional = out->bound = out->gap = out->residual = NAN;
	out->normal = out->p1 = out->p2 = nan3;
	out->scale = NAN;
	out->iterations = -1;
	out->restarts = -1;
	out->certified = -1;
	out->cert_evals = -1;
}

mkContact mkContact_FromDistance(double sd, double scale)
{
	if (isnan(sd))
		return MK_CONTACT_UNKNOWN;
	if (sd > MK_COLLIDE3_TOUCH_TOL * scale)
		return MK_CONTACT_SEPARATED;
	if (sd < -MK_COLLIDE3_TOUCH_TOL * scale)
		return MK_CONTACT_OVERLAPPING;
	return MK_CONTACT_TOUCHING;
}

/* The solver in the build impl names (collision_impl.h). */
mkResult mkCollide3_NormalImpl(mkImpl impl, mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out)
{
#if defined(MINK_HAVE_FMA_SOLVER)
	if (impl == MK_IMPL_AVX2 || impl == MK_IMPL_AVX512)
		return mkCollide3_NormalAtFma(b1, b2, start, out);
#endif
	(void)impl;
	return mkCollide3_NormalAtPortable(b1, b2, start, out);
}

/* The solver's build for this processor: the FMA build where it was
 * compiled and the processor has AVX2 and FMA (the kernels' AVX2 tier;
 * mkImpl_Available reads the CPU features libgcc resolved at start-up),
 * the portable one otherwise. */
static mkImpl mkCollide3_Impl(void)
{
#if defined(MINK_HAVE_FMA_SOLVER)
	if (mkImpl_Available(MK_IMPL_AVX2))
		return MK_IMPL_AVX2;
#endif
	return MK_IMPL_SCALAR;
}

const char *mkCollide3_Build(void)
{
	return mkCollide3_Impl() == MK_IMPL_SCALAR ? "portable" : "fma";
}

mkResult mkCollide3_Normal(mkBody3 b1, mkBody3 b2, mkCollision3 *out)
{
	return mkCollide3_NormalImpl(mkCollide3_Impl(), b1, b2, NULL, out);
}

mkResult mkCollide3_NormalFrom(mkBody3 b1, mkBody3 b2, mkVec3 start, mkCollision3 *out)
{
	/* scaled by its largest component first, so that no length of a finite
	 * nonzero vector overflows or underflows */
	double m = fmax(fabs(start.x), fmax(fabs(start.y), fabs(start.z)));
	if (!mkIsFinite3(start) || !(m > 0.0)) {
		mkCollision3_Clear(out);
		return MK_ERR_ARGUMENT;
	}
	mkVec3 n = mkVec3_NormalizeInline(mkVec3_Make(start.x / m, start.y / m, start.z / m));
	return mkCollide3_NormalImpl(mkCollide3_Impl(), b1, b2, &n, out);
}
