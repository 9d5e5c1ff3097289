/* collision.c - mink/collision.h's small helpers, which the solvers build
 * on: contact names and the contact from a distance, the pair's size, a
 * support point with its Jacobian, a bound at a normal, clearing an answer.
 * MinkSum (Normal)'s entry points are in query.c, its solver in normal.h,
 * MinkSum (Ray) in ray.c. */
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
