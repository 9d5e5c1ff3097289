/* refcheck.c - judging the core's batch output against the MPFR reference.
 *
 * Tolerances. The core computes each point along one chain of double
 * operations: normalise u; f1(u) and the gradient g1(u) (powers with
 * exponents at most 2); n = M1^-T g1 (adjugate and product); the direction
 * w2 = -+M2^T n seen by B2; B2's support point at w2 (Theorem 1: a q-norm and
 * powers with exponent q - 1 = eps/(2 - eps); Theorem 2: g^-1, a
 * normalisation and f); and x = t1 + M1 f1 -+ M2 s2 (+ t2). Each operation
 * rounds by at most u = 2^-53 (pow, exp, log within 1 ulp, libm or SLEEF).
 * The error falls into three parts:
 *
 * (i) The direction. The computed w2 is w2 + D with |D_i| <= K u W_i, where
 *     W = |M2^T| |M1^-T| |g1| (surface parameters) or |M^T| |u| (normal
 *     parameters): the componentwise bound gamma_d |A| |x| of a
 *     matrix-vector product, applied to both products, plus the relative
 *     errors of the components of g1 (normalising u, 2u; the powers
 *     sp(u_i, 2 - e) and r^(e2 - e1), at most 2 * 2u + u each) and of the
 *     adjugate entries (2u in 3D): about 14u in all. K = 32 leaves a factor
 *     of two. The same holds for B1's direction M1^T n under normal
 *     parameters. What such a perturbation does to the exact answer is a
 *     property of the problem, not of the code: we evaluate it in MPFR,
 *     U_b = sum_i max_(+-) |M_b (s_b(w_b +- K u W_i e_i) - s_b(w_b))|
 *     (one perturbation per axis; to first order their sum bounds any
 *     perturbation in the box). U is tiny for well-conditioned points and
 *     reaches the size of a face where the support point jumps across it
 *     (eps -> 0, or eps -> 2 near the corners): there a tiny turn of the
 *     direction moves the exact point a long way, whatever the code does.
 * (ii) The support map itself. It takes the ratios |w_i|/h <= 1 to the power
 *     q - 1 (up to 1999 at eps = 2 - 1e-3); a relative error d of h (about
 *     4u) scales the components by (1 + d)^(q - 1), i.e. moves the point off
 *     the boundary by (q - 1) d of the body's size. With A_e = max(1, q - 1)
 *     over the exponents of both bodies this is at most K u A_e S.
 * (iii) Forming x: 3u per component of |t1| + |M1| |f1| + |M2| |s2| <= S,
 *     since |M v| <= |M|_F |v| and |f(u)| <= |a|. Allowed as 3 K u S.
 * Hence   eA <= K u (3 + A_e) + (U1 + U2) / S,
 *         eK <= K u (3 + A_e) + U1 / S   (U1 = 0 under surface parameters),
 *         e12 <= twice the eA bound (both forms near the same exact point).
 * eB: the exact support point y(n') of a body for a perturbed normal n'
 * satisfies 0 <= h(n) - <n, y(n')> = <n - n', y(n) - y(n')> <= |n - n'| U
 * (because <n', y(n')> >= <n', y(n)>). Mapping the perturbation of w_b back,
 * |n - n'| <= a_b = 2 cond_F(M_b) K u |W_b| / |w_b|, so
 *         eB <= K u (3 + A_e) + (a1 U1 + a2 U2) / S.
 * eB is therefore the sharp test where the direction is ill-conditioned:
 * there eA's bound grows with U while eB's stays at rounding level.
 * The MPFR work for U is done only for points whose error exceeds the
 * rounding part, so well-conditioned cases cost one reference evaluation.
 *
 * The single-precision tier (refGroup.precision = MK_PRECISION_F32) is held
 * to its stated accuracy instead: the rounding part is MK_F32_TOL (the
 * tier's claim, not a derived bound), and the perturbations of the direction
 * in (i) are K u_f W with u_f = 2^-24, the unit roundoff of float, since the
 * tier forms its directions in float; the same reasoning gives
 *         eA <= MK_F32_TOL + 2 (U1 + U2) / S,  eB <= MK_F32_TOL + (a1 U1 + a2 U2) / S
 * (the factor 2 on the first-order U: see ucond below).
 * Points count as ill-conditioned in its statistics when (U1 + U2) / S > 1e-7. */
#include "refcheck.h"

#include <mink/mpref_measure.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REF_K 32.0

static const mkImpl implList[] = { MK_IMPL_SCALAR, MK_IMPL_AVX2, MK_IMPL_AVX512 };
#define IMPL_COUNT 3

refBody refBody_From2(mkBody2 b)
{
	refBody r;
	memset(&r, 0, sizeof r);
	r.s.dim = 2;
	r.s.a[0] = b.shape.a;
	r.s.a[1] = b.shape.b;
	r.s.e1 = b.shape.eps;
	for (int i = 0; i < 2; ++i)
		for (int j = 0; j < 2; ++j)
			r.M.m[i][j] = b.M.m[i][j];
	r.t[0] = b.t.x;
	r.t[1] = b.t.y;
	return r;
}

refBody refBody_From3(mkBody3 b)
{
	refBody r;
	memset(&r, 0, sizeof r);
	r.s.dim = 3;
	r.s.a[0] = b.shape.a;
	r.s.a[1] = b.shape.b;
	r.s.a[2] = b.shape.c;
	r.s.e1 = b.shape.eps1;
	r.s.e2 = b.shape.eps2;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			r.M.m[i][j] = b.M.m[i][j];
	r.t[0] = b.t.x;
	r.t[1] = b.t.y;
	r.t[2] = b.t.z;
	return r;
}

/* ---- double-precision bounds (a bound need not be exact) --------------- */

static double norm(const double *v, int dim)
{
	double s = 0.0;
	for (int i = 0; i < dim; ++i)
		s += v[i] * v[i];
	return sqrt(s);
}

static double frob(const refMat *M, int dim)
{
	double s = 0.0;
	for (int i = 0; i < dim; ++i)
		for (int j = 0; j < dim; ++j)
			s += M->m[i][j] * M->m[i][j];
	return sqrt(s);
}

/* |cof(M)| entrywise, as the sum of the absolute products (so that it bounds
 * the rounding of the cofactors too), and |det M|. */
static double absCofactor(const refMat *M, int dim, double C[3][3])
{
	if (dim == 2) {
		C[0][0] = fabs(M->m[1][1]);
		C[0][1] = fabs(M->m[1][0]);
		C[1][0] = fabs(M->m[0][1]);
		C[1][1] = fabs(M->m[0][0]);
		return fabs(M->m[0][0] * M->m[1][1] - M->m[0][1] * M->m[1][0]);
	}
	double det = 0.0;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
			double c = M->m[i1][j1] * M->m[i2][j2] - M->m[i1][j2] * M->m[i2][j1];
			C[i][j] = fabs(M->m[i1][j1] * M->m[i2][j2]) + fabs(M->m[i1][j2] * M->m[i2][j1]);
			if (i == 0)
				det += M->m[0][j] * c;
		}
	return fabs(det);
}

static double condF(const refMat *M, int dim)
{
	double C[3][3];
	double det = absCofactor(M, dim, C);
	double s = 0.0;
	for (int i = 0; i < dim; ++i)
		for (int j = 0; j < dim; ++j)
			s += C[i][j] * C[i][j];
	return frob(M, dim) * sqrt(s) / det;
}

/* max(1, q - 1) over the exponents of a shape, q - 1 = e/(2 - e). */
static double exponentGain(refShape s)
{
	double g = 1.0, e[2] = { s.e1, s.dim == 3 ? s.e2 : s.e1 };
	for (int i = 0; i < 2; ++i) {
		double q1 = e[i] / (2.0 - e[i]);
		if (q1 > g)
			g = q1;
	}
	return g;
}

/* ---- the conditioning term, in MPFR ------------------------------------ */

/* sum_i max_(+-) |M (s(w +- delta_i e_i) - s(w))| */
static double response(const refBody *b, const refVec *w, const double *delta)
{
	int dim = b->s.dim;
	refVec s0, wp, sp, md;
	refVec_Init(&s0);
	refVec_Init(&wp);
	refVec_Init(&sp);
	refVec_Init(&md);
	refShape_Support(b->s, w, &s0);
	double U = 0.0;
	for (int i = 0; i < dim; ++i) {
		if (delta[i] == 0.0)
			continue;
		double best = 0.0;
		for (int sg = -1; sg <= 1; sg += 2) {
			refVec_Set(&wp, w);
			mpfr_add_d(wp.c[i], wp.c[i], sg * delta[i], MPFR_RNDN);
			refShape_Support(b->s, &wp, &sp);
			for (int k = 0; k < dim; ++k)
				mpfr_sub(sp.c[k], sp.c[k], s0.c[k], MPFR_RNDN);
			refMat_MulVec(&b->M, dim, &sp, &md);
			double d = refVec_NormD(&md, dim);
			if (d > best)
				best = d;
		}
		U += best;
	}
	refVec_Clear(&s0);
	refVec_Clear(&wp);
	refVec_Clear(&sp);
	refVec_Clear(&md);
	return U;
}

typedef struct refPoint {
	refVec x, k, n;
	mpfr_t h;
	int condDone;
	double U1, U2, a1, a2;
} refPoint;

/* Fill U1, U2, a1, a2 of point p with parameter u (see the top comment). */
static void conditioning(const refBody *b1, const refBody *b2, int plus, int surface,
	const double *u, double unit, refPoint *p)
{
	int dim = b1->s.dim;
	double W1[3] = { 0 }, W2[3] = { 0 }, d[3] = { 0 };
	refVec m, w, g, f, uu;
	refVec_Init(&m);
	refVec_Init(&w);
	refVec_Init(&g);
	refVec_Init(&f);
	refVec_Init(&uu);
	refVec_FromD(&uu, dim, u);
	p->U1 = p->a1 = 0.0;
	if (surface) {
		/* The world gradient m = M1^-T g1 and its componentwise bound
		 * |M1^-T| |g1|, in the same (unnormalised) scale. */
		double C[3][3], gd[3], Mg[3] = { 0 };
		refBody_GradientAt(b1, &uu, &m);
		refShape_Point(b1->s, &uu, &f);
		refShape_Gradient(b1->s, &f, &g);
		refVec_ToD(&g, dim, gd);
		double det = absCofactor(&b1->M, dim, C);
		for (int i = 0; i < dim; ++i) {
			for (int j = 0; j < dim; ++j)
				Mg[i] += C[i][j] * fabs(gd[j]);
			Mg[i] /= det;
		}
		for (int i = 0; i < dim; ++i)
			for (int j = 0; j < dim; ++j)
				W2[i] += fabs(b2->M.m[j][i]) * Mg[j];
	} else {
		refVec_FromD(&m, dim, u);
		for (int i = 0; i < dim; ++i)
			for (int j = 0; j < dim; ++j) {
				W1[i] += fabs(b1->M.m[j][i] * u[j]);
				W2[i] += fabs(b2->M.m[j][i] * u[j]);
			}
		/* B1 looks along M1^T u. */
		refMat_MulTVec(&b1->M, dim, &m, &w);
		for (int i = 0; i < dim; ++i)
			d[i] = REF_K * unit * W1[i];
		p->U1 = response(b1, &w, d);
		p->a1 = 2.0 * condF(&b1->M, dim) * REF_K * unit * norm(W1, dim) / refVec_NormD(&w, dim);
	}
	/* B2 looks along -+M2^T m. */
	refMat_MulTVec(&b2->M, dim, &m, &w);
	if (!plus)
		for (int i = 0; i < dim; ++i)
			mpfr_neg(w.c[i], w.c[i], MPFR_RNDN);
	for (int i = 0; i < dim; ++i)
		d[i] = REF_K * unit * W2[i];
	p->U2 = response(b2, &w, d);
	p->a2 = 2.0 * condF(&b2->M, dim) * REF_K * unit * norm(W2, dim) / refVec_NormD(&w, dim);
	p->condDone = 1;
	refVec_Clear(&m);
	refVec_Clear(&w);
	refVec_Clear(&g);
	refVec_Clear(&f);
	refVec_Clear(&uu);
}

/* ---- running the core -------------------------------------------------- */

/* floatio: through mkSum2f_Batch/mkSum3f_Batch on float copies of the case's
 * parameter vectors (which the caller has already rounded to float, so the
 * copies are exact), the float outputs widened into out. */
static mkResult runCore(const refCase *c, const mkSumOptions *opt, int floatio, double *out[6])
{
	if (floatio) {
		int n = c->n, dim = c->dim;
		float *f = malloc(sizeof(float) * 9 * (size_t)(n > 0 ? n : 1));
		if (!f) return MK_ERR_MEMORY;
		float *fu[3] = {f, f + n, f + 2 * (size_t)n}, *fo[6];
		for (int i = 0; i < 6; ++i) fo[i] = f + (size_t)(3 + i) * (size_t)n;
		for (int j = 0; j < n; ++j) {
			fu[0][j] = (float)c->ux[j]; fu[1][j] = (float)c->uy[j];
			fu[2][j] = dim == 3 ? (float)c->uz[j] : 0.0f;
		}
		mkResult r = dim == 2
			? mkSum2f_Batch(c->a2, c->b2, opt, fu[0], fu[1], n, fo[0], fo[1], fo[3], fo[4])
			: mkSum3f_Batch(c->a3, c->b3, opt, fu[0], fu[1], fu[2], n, fo[0], fo[1], fo[2], fo[3], fo[4], fo[5]);
		for (int i = 0; i < 6; ++i)
			if (out[i] && (dim == 3 || (i != 2 && i != 5)))
				for (int j = 0; j < n; ++j) out[i][j] = fo[i][j];
		free(f);
		return r;
	}
	if (c->dim == 2)
		return mkSum2_Batch(c->a2, c->b2, opt, c->ux, c->uy, c->n,
			out[0], out[1], out[3], out[4]);
	return mkSum3_Batch(c->a3, c->b3, opt, c->ux, c->uy, c->uz, c->n,
		out[0], out[1], out[2], out[3], out[4], out[5]);
}

/* One kernel's run on one case: the bodies, the set, the parameterisation,
 * S and the tolerances' parts (see refCheck_Case). */
typedef struct refJudge {
	refGroup *g;
	const refBody *b1, *b2;
	int dim, plus, surface;
	mkImpl impl;
	double S, base, unit, ucond, illCut;
} refJudge;

/* Judge point j (parameter u) of both forms, xs[f] and ks[f], against the
 * reference p; Theorem 1 against Theorem 2 on the same input. */
static void judgePoint(const refJudge *J, int j, const double *u, double xs[2][3], double ks[2][3], refPoint *p)
{
	for (int f = 0; f < 2; ++f) {
		int finite = 1;
		for (int i = 0; i < J->dim; ++i)
			finite &= isfinite(xs[f][i]) && isfinite(ks[f][i]);
		if (!finite) {
			J->g->nonfinite++;
			ENSURE_MSG(finite, "%s %s-form %s %s point %d u=(%.17g, %.17g, %.17g)",
				mkImpl_Name(J->impl), f ? "gradient" : "normal", J->surface ? "surface" : "normal-param",
				J->plus ? "plus" : "contact", j, u[0], u[1], u[2]);
			continue;
		}
		double eA = refVec_DistD(&p->x, J->dim, xs[f]) / J->S;
		double eK = refVec_DistD(&p->k, J->dim, ks[f]) / J->S;
		refVec xv;
		mpfr_t t;
		refVec_Init(&xv);
		mpfr_init2(t, REF_PREC);
		refVec_FromD(&xv, J->dim, xs[f]);
		refVec_Dot(t, &p->n, &xv, J->dim);
		mpfr_sub(t, t, p->h, MPFR_RNDN);
		double eB = fabs(mpfr_get_d(t, MPFR_RNDN)) / J->S;
		refVec_Clear(&xv);
		mpfr_clear(t);
		if (!p->condDone && (J->g->conditionAll || eA > J->base || eK > J->base || eB > J->base))
			conditioning(J->b1, J->b2, J->plus, J->surface, u, J->unit, p);
		double tolA = J->base, tolK = J->base, tolB = J->base;
		if (p->condDone) {
			tolA += J->ucond * (p->U1 + p->U2) / J->S;
			tolK += J->ucond * p->U1 / J->S;
			tolB += (p->a1 * p->U1 + p->a2 * p->U2) / J->S;
		}
		const char *ctx = "%s %s-form %s %s point %d u=(%.17g, %.17g, %.17g)";
		ENSURE_LE(eA, tolA, ctx, mkImpl_Name(J->impl), f ? "gradient" : "normal",
			J->surface ? "surface" : "normal-param", J->plus ? "plus" : "contact", j, u[0], u[1], u[2]);
		ENSURE_LE(eK, tolK, ctx, mkImpl_Name(J->impl), f ? "gradient" : "normal",
			J->surface ? "surface" : "normal-param", J->plus ? "plus" : "contact", j, u[0], u[1], u[2]);
		ENSURE_LE(eB, tolB, ctx, mkImpl_Name(J->impl), f ? "gradient" : "normal",
			J->surface ? "surface" : "normal-param", J->plus ? "plus" : "contact", j, u[0], u[1], u[2]);
		/* The distance to the ideal point means something only
		 * where the problem is well-conditioned (see (i) above);
		 * the distance from the boundary is quoted everywhere. */
		int ill = p->condDone && (p->U1 + p->U2) / J->S > J->illCut;
		if (!ill)
			refStat_Add(&J->g->eA[J->impl][f], eA);
		if (!(p->condDone && p->U1 / J->S > J->illCut))
			refStat_Add(&J->g->eK[J->impl][f], eK);
		refStat_Add(&J->g->eB[J->impl][f], eB);
		if (!ill)
			refStat_Add(&J->g->ratioA, eA / tolA);
		refStat_Add(&J->g->ratioB, eB / tolB);
	}
	/* Theorem 1 against Theorem 2 on the same input. */
	double d[3];
	for (int i = 0; i < J->dim; ++i)
		d[i] = xs[0][i] - xs[1][i];
	double e12 = norm(d, J->dim) / J->S;
	if (e12 > 2.0 * J->base && !p->condDone)
		conditioning(J->b1, J->b2, J->plus, J->surface, u, J->unit, p);
	double tol12 = 2.0 * (J->base + (p->condDone ? (p->U1 + p->U2) / J->S : 0.0));
	/* the difference itself rounds by 2u S at most; inside K */
	ENSURE_LE(e12, tol12, "Theorem 1 vs 2: %s %s %s point %d u=(%.17g, %.17g, %.17g)",
		mkImpl_Name(J->impl), J->surface ? "surface" : "normal-param", J->plus ? "plus" : "contact",
		j, u[0], u[1], u[2]);
	if (isfinite(e12))
		refStat_Add(&J->g->e12[J->impl], e12);
}

void refCheck_Case(const refCase *c, refGroup *g)
{
	/* The float-array entry points see the parameter vectors rounded to
	 * float: the reference is computed at those vectors. */
	refCase cf = *c;
	double *ur = NULL;
	if (g->floatio) {
		ur = malloc(sizeof(double) * 3 * (size_t)(c->n > 0 ? c->n : 1));
		ENSURE(ur != NULL);
		if (!ur) return;
		for (int j = 0; j < c->n; ++j) {
			ur[j] = (float)c->ux[j];
			ur[c->n + j] = (float)c->uy[j];
			ur[2 * c->n + j] = c->dim == 3 ? (float)c->uz[j] : 0.0;
		}
		cf.ux = ur; cf.uy = ur + c->n; cf.uz = ur + 2 * c->n;
		c = &cf;
	}
	int dim = c->dim, n = c->n;
	refBody b1 = dim == 2 ? refBody_From2(c->a2) : refBody_From3(c->a3);
	refBody b2 = dim == 2 ? refBody_From2(c->b2) : refBody_From3(c->b3);
	double gain = exponentGain(b1.s);
	if (exponentGain(b2.s) > gain)
		gain = exponentGain(b2.s);
	int f32 = g->precision == MK_PRECISION_F32;
	double unit = f32 ? 0x1p-24 : REF_U;
	double base = f32 ? MK_F32_TOL : REF_K * REF_U * (3.0 + gain);
	double illCut = f32 ? 1e-7 : 1e-9;
	/* U is a first-order measure. Where the exact point jumps across a face
	 * (eps near 0), float-sized turns of the direction cross the jump and the
	 * float tier's point lands a hair beyond U's box (by less than 1e-3 of U,
	 * seen at eps1 = 1e-6 in 3D); eA and eK allow twice U there. eB, the
	 * distance from the boundary, stays sharp. */
	double ucond = f32 ? 2.0 : 1.0;

	double *buf = malloc(sizeof(double) * 12 * (size_t)n);
	refPoint *pts = malloc(sizeof(refPoint) * (size_t)n);
	ENSURE(buf != NULL && pts != NULL);
	if (!buf || !pts) {
		free(buf);
		free(pts);
		free(ur);
		return;
	}
	for (int j = 0; j < n; ++j) {
		refVec_Init(&pts[j].x);
		refVec_Init(&pts[j].k);
		refVec_Init(&pts[j].n);
		mpfr_init2(pts[j].h, REF_PREC);
	}
	/* out[0..5]: x, y, z, kx, ky, kz of the normal form; [6..11] gradient. */
	double *outs[2][6];
	for (int f = 0; f < 2; ++f)
		for (int i = 0; i < 6; ++i)
			outs[f][i] = buf + (size_t)(f * 6 + i) * (size_t)n;
	if (dim == 2) {
		outs[0][2] = outs[0][5] = outs[1][2] = outs[1][5] = NULL;
	}

	for (int plus = 0; plus <= 1; ++plus) {
		double S = refSum_Size(&b1, &b2, plus);
		for (int surface = 0; surface <= 1; ++surface) {
			for (int j = 0; j < n; ++j) {
				double u[3] = { c->ux[j], c->uy[j], dim == 3 ? c->uz[j] : 0.0 };
				refVec uu;
				refVec_Init(&uu);
				refVec_FromD(&uu, dim, u);
				refSum_Point(&b1, &b2, plus, surface, &uu, &pts[j].x, &pts[j].k, &pts[j].n);
				refSum_SupportValue(&b1, &b2, plus, &pts[j].n, pts[j].h);
				pts[j].condDone = 0;
				refVec_Clear(&uu);
			}
			g->points += n;
			for (int ii = 0; ii < IMPL_COUNT; ++ii) {
				mkImpl impl = implList[ii];
				if (!mkImpl_Available(impl))
					continue;
				for (int f = 0; f < 2; ++f) {
					mkSumOptions opt = mkSumOptions_Default();
					opt.set = plus ? MK_SET_PLUS : MK_SET_CONTACT;
					opt.param = surface ? MK_PARAM_SURFACE : MK_PARAM_NORMAL;
					opt.form = f ? MK_FORM_GRADIENT : MK_FORM_NORMAL;
					opt.impl = impl;
					opt.precision = g->precision;
					mkResult r = runCore(c, &opt, g->floatio, outs[f]);
					ENSURE(r == MK_OK);
				}
				for (int j = 0; j < n; ++j) {
					refPoint *p = &pts[j];
					double u[3] = { c->ux[j], c->uy[j], dim == 3 ? c->uz[j] : 0.0 };
					double xs[2][3], ks[2][3];
					for (int f = 0; f < 2; ++f)
						for (int i = 0; i < dim; ++i) {
							xs[f][i] = outs[f][i][j];
							ks[f][i] = outs[f][3 + i][j];
						}
					refJudge J = { g, &b1, &b2, dim, plus, surface, impl, S, base, unit, ucond, illCut };
					judgePoint(&J, j, u, xs, ks, p);
				}
			}
			for (int j = 0; j < n; ++j)
				if (pts[j].condDone && (pts[j].U1 + pts[j].U2) / S > illCut)
					g->illConditioned++;
		}
	}
	for (int j = 0; j < n; ++j) {
		refVec_Clear(&pts[j].x);
		refVec_Clear(&pts[j].k);
		refVec_Clear(&pts[j].n);
		mpfr_clear(pts[j].h);
	}
	free(pts);
	free(buf);
	free(ur);
}

void refGroup_Print(const refGroup *g)
{
	for (int ii = 0; ii < IMPL_COUNT; ++ii) {
		mkImpl impl = implList[ii];
		if (!mkImpl_Available(impl)) {
			printf("%s [%s]: kernel not available on this CPU, not run\n", g->name, mkImpl_Name(impl));
			continue;
		}
		for (int f = 0; f < 2; ++f) {
			const refStat *a = &g->eA[impl][f], *k = &g->eK[impl][f], *b = &g->eB[impl][f];
			printf("%s [%s, %s form]: well-conditioned %ld: |x-x_ref|/S max %.2e mean %.2e, "
				"kiss max %.2e mean %.2e; all %ld: boundary |<n,x>-h(n)|/S max %.2e mean %.2e\n",
				g->name, mkImpl_Name(impl), f ? "gradient" : "normal", a->count,
				a->max, refStat_Mean(a), k->max, refStat_Mean(k), b->count, b->max, refStat_Mean(b));
		}
		printf("%s [%s]: Theorem 1 vs Theorem 2 |x_N-x_G|/S max %.2e mean %.2e\n",
			g->name, mkImpl_Name(impl), g->e12[impl].max, refStat_Mean(&g->e12[impl]));
	}
	printf("%s [precision %s%s]: %ld reference points, %ld%s ill-conditioned (the exact point moves by > %g S "
		"under a rounding-size change of direction), %ld non-finite outputs; worst error/tolerance: "
		"point %.3g (well-conditioned), boundary %.3g\n",
		g->name, mkPrecision_Name(g->precision), g->floatio ? ", float arrays" : "", g->points, g->illConditioned, g->conditionAll ? "" : " found",
		g->precision == MK_PRECISION_F32 ? 1e-7 : 1e-9, g->nonfinite,
		g->ratioA.max, g->ratioB.max);
}

int refSum_Main(int argc, char **argv, const refSumTests *t, mkPrecision *tier, int *floatio)
{
	int which = argc > 1 ? atoi(argv[1]) : 0;
	if (argc > 2) {
		*floatio = strcmp(argv[2], "f32io") == 0;
		int p = *floatio ? MK_PRECISION_F32 : mkPrecision_Parse(argv[2]);
		ENSURE(p >= 0);
		if (p < 0)
			return refTest_Result(argv[0]);
		*tier = (mkPrecision)p;
	}
	/* "all" as the third argument: evaluate the conditioning of every point
	 * of group 4 too, for its statistics (twice the time; the test runs
	 * without, its tolerances need it only where an error is large). */
	int rangeAll = argc > 3 && strcmp(argv[3], "all") == 0;
	if (which == 0 || which == 1)
		t->validation();
	static const double E[] = { 1e-3, 0.01, 0.5, 1.0, 1.5, 1.99, 2.0 - 1e-3 };
	/* the ends of the valid exponent range, where the powers' exponents
	 * reach 5e-7 and 2e6 */
	static const double R[] = { 1e-6, 1e-5, 1e-4, 1.0, 2.0 - 1e-4, 2.0 - 1e-5, 2.0 - 1e-6 };
	char name[64];
	if (which == 0 || which == 2) {
		snprintf(name, sizeof name, "%s extremes", t->name);
		t->extremes(E, name, t->seed + 2, 1);
	}
	if (which == 0 || which == 4) {
		snprintf(name, sizeof name, "%s eps-range", t->name);
		t->extremes(R, name, t->seed + 4, rangeAll);
	}
	if (which == 0 || which == 3)
		t->scaled();
	return refTest_Result(t->name);
}
