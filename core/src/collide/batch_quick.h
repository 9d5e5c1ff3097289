/* batch_quick.h - the batch's certificates outside Gilbert's search, as
 * static definitions for batch.c (inlined into its per-pair loop): a
 * pair's answer before any search, and an overlap point where the search
 * gave up. need, below and margin as the search's (batch.c): a separating
 * direction is an answer when its bound f exceeds margin and either
 * f > need or a pair of the bodies' points is nearer than below; an
 * overlap point when its depth exceeds margin.
 *
 * The gauge g(y) = |(|(y1/a, y2/b)|_p2, y3/c)|_p1 of the canonical body
 * (p = 2/eps: the nested norm whose unit ball it is; pair norms from the
 * ratio of the smaller to the larger component, no overflow) at
 * y = M^-1 (x - t). With u = g < 1, x + (1 - u)(B - t) lies in B, and
 * B - t holds the ball of radius rho = sigma_min(M) / |(1/a, 1/b, 1/c)|
 * (the body holds its cross-polytope, since every p >= 1 norm is at most
 * the l1 norm; sigma_min(M) >= 1 / |M^-1|_F). Balls of radii r1, r2 about
 * one point x inside B1 and B2 put the ball of radius r1 + r2 about the
 * origin inside B1 - B2: the depth is at least r1 + r2. On the centre
 * segment the gauges are linear: the end of the common interval that
 * maximises the bound, the gauges evaluated again at the point itself. */
#ifndef MINK_COLLIDE_BATCH_QUICK_H
#define MINK_COLLIDE_BATCH_QUICK_H

#include <mink/batch.h>

#include <float.h>
#include <math.h>

#include "collide/support.h"

/* A certificate's answer. A separation: lower = f (<= sd), upper = |p2 -
 * p1| for the points p1, p2 of the bodies, n the unit direction, clear
 * when f > need. An overlap: lower = -inf, upper = -depth, p1 = p2 = the
 * point of both bodies, n NaN, clear 0. */
typedef struct mkBatchQuick {
	mkContact status;
	double lower, upper;
	mkVec3 n, p1, p2;
	int clear;
} mkBatchQuick;

/* |(u, v)|_p of u, v >= 0, from the ratio of the smaller to the larger. */
static double mkBatch_PairNorm(double u, double v, double p)
{
	double m = u > v ? u : v, k = u > v ? v : u;
	if (!(m > 0.0))
		return 0.0;
	if (p == 2.0) /* an ellipsoid's: no pow */
		return m * sqrt(1.0 + (k / m) * (k / m));
	return m * pow(1.0 + pow(k / m, p), 1.0 / p);
}

/* One body's data for the overlap test. */
typedef struct mkBatchGauge {
	mkMat3 Mi;
	double slack; /* a bound on the relative rounding of g */
	double rho;   /* inradius about the centre */
} mkBatchGauge;

static void mkBatchGauge_Init(mkBatchGauge *g, const mkBody3 *b)
{
	g->Mi = mkMat3_Inverse(b->M);
	double fm = 0.0, fi = 0.0;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			fm += b->M.m[i][j] * b->M.m[i][j];
			fi += g->Mi.m[i][j] * g->Mi.m[i][j];
		}
	const mkShape3 *s = &b->shape;
	double inv = sqrt(1.0 / (s->a * s->a) + 1.0 / (s->b * s->b) + 1.0 / (s->c * s->c));
	g->rho = 1.0 / (sqrt(fi) * inv);
	g->slack = 64.0 * DBL_EPSILON * (1.0 + sqrt(fm * fi));
}

/* The gauge of body b at the point x (rounding slack added). */
static double mkBatchGauge_At(const mkBatchGauge *g, const mkBody3 *b, mkVec3 x)
{
	mkVec3 y = mkMat3_MulVec(g->Mi, mkVec3_Sub(x, b->t));
	const mkShape3 *s = &b->shape;
	double in = mkBatch_PairNorm(fabs(y.x) / s->a, fabs(y.y) / s->b, 2.0 / s->eps2);
	return mkBatch_PairNorm(in, fabs(y.z) / s->c, 2.0 / s->eps1) * (1.0 + g->slack) + g->slack;
}

/* At a point x with gauges v1, v2 < 1 the balls of radii (1 - v_i) rho_i
 * about x lie in the bodies: 1 when their sum *depth exceeds need. */
static int mkBatchGauge_Depth(const mkBatchGauge *g1, const mkBody3 *b1, const mkBatchGauge *g2, const mkBody3 *b2,
	mkVec3 x, double need, double *depth)
{
	double v1 = mkBatchGauge_At(g1, b1, x), v2 = mkBatchGauge_At(g2, b2, x);
	if (!(v1 < 1.0 && v2 < 1.0))
		return 0;
	*depth = (1.0 - v1) * g1->rho + (1.0 - v2) * g2->rho;
	return *depth > need;
}

/* A point *x of both bodies on the centre segment d = t2 - t1 whose balls
 * inside them add to more than need: 1 and *x, *depth (the certified lower
 * bound of the depth), else 0. */
static int mkBatch_OverlapPoint(const mkBody3 *b1, const mkBody3 *b2, mkVec3 d, double need, mkVec3 *x,
	double *depth)
{
	mkBatchGauge g1, g2;
	mkBatchGauge_Init(&g1, b1);
	mkBatchGauge_Init(&g2, b2);
	double t;
	if (mkVec3_LengthInline(d) == 0.0) {
		t = 0.0;
	} else {
		double u1 = mkBatchGauge_At(&g1, b1, b2->t);   /* g1 at t = 1 */
		double u2 = mkBatchGauge_At(&g2, b2, b1->t);   /* g2 at t = 0 */
		double lo = u2 > 0.0 ? fmax(0.0, 1.0 - 1.0 / u2) : 0.0, hi = u1 > 0.0 ? fmin(1.0, 1.0 / u1) : 1.0;
		if (!(lo < hi))
			return 0;
		/* (1 - t u1) rho1 + (1 - (1 - t) u2) rho2: slope u2 rho2 - u1 rho1 */
		t = u2 * g2.rho - u1 * g1.rho > 0.0 ? hi : lo;
	}
	*x = mkVec3_Add(b1->t, mkVec3_Scale(d, t));
	return mkBatchGauge_Depth(&g1, b1, &g2, b2, *x, need, depth);
}

/* Whether the point x has balls inside both bodies adding to more than
 * need (*depth, the certified lower bound of the depth). */
static int mkBatch_OverlapAt(const mkBody3 *b1, const mkBody3 *b2, mkVec3 x, double need, double *depth)
{
	mkBatchGauge g1, g2;
	mkBatchGauge_Init(&g1, b1);
	mkBatchGauge_Init(&g2, b2);
	return mkBatchGauge_Depth(&g1, b1, &g2, b2, x, need, depth);
}

/* A separating direction n with f_lower = f > margin (and the points p1, p2
 * of the bodies): the answer when f > need or |p2 - p1| < below, as the
 * search's certificate (mkGilbert_Step). */
static int mkBatchQuick_Separated(mkBatchQuick *r, double f, mkVec3 n, mkVec3 p1, mkVec3 p2, double need,
	double below)
{
	double upper = mkVec3_LengthInline(mkVec3_Sub(p2, p1));
	if (!(f > need || upper < below))
		return -1; /* (in the touching band, or the clearance undecided) */
	r->status = MK_CONTACT_SEPARATED;
	r->lower = f;
	r->upper = upper;
	r->n = n;
	r->p1 = p1;
	r->p2 = p2;
	r->clear = f > need;
	return MK_PATH_SEPARATING;
}

/* Steps of mkBatchQuick_Ellipsoids after the centre line (measured on the paper's
 * ellipsoid pairs: the centre line certified 1922 of the 1942 separated
 * ones, one step 19 more, two steps the last). */
#define MK_BATCH_ELL_STEPS 2

/* Q = P P^T, P = M diag(a, b, c): h(n) = sqrt(n^T Q n). */
static void mkBatchEll_Q(const mkBody3 *b, double Q[3][3])
{
	double P[3][3];
	mkSupBody_PQ(b, P, Q);
}

static mkVec3 mkBatchEll_Mul(double Q[3][3], mkVec3 n)
{
	return mkVec3_Make(Q[0][0] * n.x + Q[0][1] * n.y + Q[0][2] * n.z, Q[1][0] * n.x + Q[1][1] * n.y + Q[1][2] * n.z,
		Q[2][0] * n.x + Q[2][1] * n.y + Q[2][2] * n.z);
}

/* adj(A) d: the direction of A^-1 d for a positive definite A (det A > 0). */
static mkVec3 mkBatchEll_AdjMul(double A[3][3], mkVec3 d)
{
	double c00 = A[1][1] * A[2][2] - A[1][2] * A[2][1], c01 = A[0][2] * A[2][1] - A[0][1] * A[2][2];
	double c02 = A[0][1] * A[1][2] - A[0][2] * A[1][1], c11 = A[0][0] * A[2][2] - A[0][2] * A[2][0];
	double c12 = A[0][2] * A[1][0] - A[0][0] * A[1][2], c22 = A[0][0] * A[1][1] - A[0][1] * A[1][0];
	return mkVec3_Make(c00 * d.x + c01 * d.y + c02 * d.z, c01 * d.x + c11 * d.y + c12 * d.z,
		c02 * d.x + c12 * d.y + c22 * d.z);
}

/* The next direction, (Q1 / h1 + Q2 / h2)^-1 d up to a positive factor. */
static mkVec3 mkBatchEll_Next(double Q1[3][3], double Q2[3][3], double h1, double h2, mkVec3 d)
{
	double A[3][3], i1 = 1.0 / h1, i2 = 1.0 / h2;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			A[i][j] = Q1[i][j] * i1 + Q2[i][j] * i2;
	return mkBatchEll_AdjMul(A, d);
}

/* Two ellipsoids (Q_i = P_i P_i^T, h_i(n) = sqrt(n^T Q_i n)): the separating
 * certificate at the centre line d and then at up to MK_BATCH_ELL_STEPS
 * directions n' = (Q1 / h1 + Q2 / h2)^-1 d (h_i at the last n). That is the
 * fixed point of the largest <n, d> / (h1(n) + h2(n)) (its gradient
 * vanishes where d is parallel to Q1 n / h1 + Q2 n / h2); the pair is
 * separated exactly when that largest value exceeds 1, and every n with
 * f(n) = (<n, d> - h1 - h2) / |n| above the margin certifies it. Where the
 * last has f < 0: the point where the bodies scaled about their centres by
 * mu = <n, d> / (h1 + h2) would touch at the fixed point (inside both
 * when mu < 1) is tried for an overlap (mkBatch_OverlapAt). distance:
 * overlaps only. Returns MK_PATH_SEPARATING or MK_PATH_OVERLAP_POINT with
 * *r, or -1. */
static int mkBatchQuick_Ellipsoids(const mkBody3 *b1, const mkBody3 *b2, double need, double below, double margin,
	int distance, mkBatchQuick *r)
{
	double Q1[3][3], Q2[3][3];
	mkBatchEll_Q(b1, Q1);
	mkBatchEll_Q(b2, Q2);
	mkVec3 d = mkVec3_Sub(b2->t, b1->t), n = d;
	for (int step = 0;; ++step) {
		mkVec3 q1 = mkBatchEll_Mul(Q1, n), q2 = mkBatchEll_Mul(Q2, n);
		double h1 = sqrt(mkVec3_Dot(n, q1)), h2 = sqrt(mkVec3_Dot(n, q2)), nl = mkVec3_LengthInline(n);
		double nd = mkVec3_Dot(n, d), f = (nd - h1 - h2) / nl;
		if (!(h1 > 0.0) || !(h2 > 0.0) || !isfinite(f))
			return -1;
		if (f > margin && distance)
			return -1; /* (the search's direction, then the Newton lanes, give the distance) */
		if (f > margin) {
			mkVec3 p1 = mkVec3_Add(b1->t, mkVec3_Scale(q1, 1.0 / h1)), p2 = mkVec3_Sub(b2->t, mkVec3_Scale(q2, 1.0 / h2));
			return mkBatchQuick_Separated(r, f, mkVec3_Scale(n, 1.0 / nl), p1, p2, need, below);
		}
		if (step == MK_BATCH_ELL_STEPS) {
			/* c1 + mu s1 and c2 - mu s2 (mu = <n, d> / (h1 + h2)) meet at the
			 * fixed point: their mean, a point of both bodies there */
			double mu = nd / (h1 + h2);
			mkVec3 x = mkVec3_Scale(mkVec3_Add(mkVec3_Add(b1->t, mkVec3_Scale(q1, mu / h1)),
				mkVec3_Sub(b2->t, mkVec3_Scale(q2, mu / h2))), 0.5);
			double depth;
			if (f >= 0.0 || !mkBatch_OverlapAt(b1, b2, x, margin, &depth))
				return -1;
			r->status = MK_CONTACT_OVERLAPPING;
			r->lower = -INFINITY;
			r->upper = -depth;
			r->n = mkVec3_Make(NAN, NAN, NAN);
			r->p1 = r->p2 = x;
			r->clear = 0;
			return MK_PATH_OVERLAP_POINT;
		}
		n = mkBatchEll_Next(Q1, Q2, h1, h2, d);
	}
}

/* An upper bound of a pair norm |(u, v)|_q (u, v >= 0) of a support
 * function, q = 2 / (2 - eps): the smaller of two bounds, both exact on the
 * axes and on the diagonals. Where eps < 1 (1 <= q < 2): |.|_1, and
 * 2^(1/q - 1/2) |.|_2 (Hoelder); where eps >= 1 (q >= 2): |.|_2, and
 * 2^(1/q) |.|_inf. The powers of 2 are 2^x with x = (1 - eps) / 2 or
 * 1 - eps / 2 in [0, 1/2], bounded by their chord 1 + 2 x (sqrt 2 - 1)
 * (2^x is convex), rounded up; no transcendental function. Within 15.3 %
 * of the norm (|.|_1 or |.|_2 alone: 41 %). */
static double mkBatchBound_Pair(double u, double v, double eps)
{
	double l1 = u + v, l2 = sqrt(u * u + v * v), li = u > v ? u : v;
	int q2 = eps >= 1.0;   /* q >= 2 */
	double x = q2 ? 1.0 - 0.5 * eps : 0.5 - 0.5 * eps;   /* 1/q, or 1/q - 1/2 */
	double k = (1.0 + x * (2.0 * 0.41421356237309515)) * (1.0 + 4.0 * DBL_EPSILON);
	double a = q2 ? l2 : l1, b = k * (q2 ? li : l2);
	return a < b ? a : b;
}

/* An upper bound H of body b's support function about its centre at n, no
 * transcendental function: the nested dual norm of (a p1, b p2, c p3), p =
 * M^T n, bounded level by level (mkBatchBound_Pair; exact for an
 * ellipsoid). */
static double mkBatchBound_Support(const mkBody3 *b, mkVec3 n)
{
	const double (*M)[3] = b->M.m;
	const mkShape3 *s = &b->shape;
	double x = fabs(M[0][0] * n.x + M[1][0] * n.y + M[2][0] * n.z) * s->a;
	double y = fabs(M[0][1] * n.x + M[1][1] * n.y + M[2][1] * n.z) * s->b;
	double z = fabs(M[0][2] * n.x + M[1][2] * n.y + M[2][2] * n.z) * s->c;
	return mkBatchBound_Pair(mkBatchBound_Pair(x, y, s->eps2), z, s->eps1);
}

/* The end of an axis of body b (a point of its surface for every exponent)
 * farthest along n, about the centre. */
static mkVec3 mkBatchBound_End(const mkBody3 *b, mkVec3 n)
{
	const double (*M)[3] = b->M.m;
	const double ax[3] = { b->shape.a, b->shape.b, b->shape.c };
	double p[3], v[3];
	for (int j = 0; j < 3; ++j) {
		p[j] = M[0][j] * n.x + M[1][j] * n.y + M[2][j] * n.z;
		v[j] = fabs(p[j]) * ax[j];
	}
	int i = v[0] >= v[1] && v[0] >= v[2] ? 0 : v[1] >= v[2] ? 1 : 2;
	double len = p[i] < 0.0 ? -ax[i] : ax[i];
	return mkVec3_Make(M[0][i] * len, M[1][i] * len, M[2][i] * len);
}

/* A pair that is not two ellipsoids, at the centre line n = d / |d|:
 * f_H = <n, d> - H1(n) - H2(-n) <= f(n) <= sd, H_i upper bounds of the
 * support functions about the centres with no transcendental function
 * (each level of the nested dual norm of (a p1, b p2, c p3), p = M^T n,
 * bounded by mkBatchBound_Pair; exact for an ellipsoid); the witnesses are the ends of an axis of each body (points
 * of its surface for every exponent) farthest along +-n. distance: need =
 * margin (the caller only learns that the pair is separated). witness 0:
 * the caller asked for neither the witnesses nor upper, which are then NaN
 * where f > need settles the pair without them. Returns
 * MK_PATH_SEPARATING with *r, or -1. */
static int mkBatchQuick_Bound(const mkBody3 *b1, const mkBody3 *b2, double need, double below, double margin,
	int distance, int witness, mkBatchQuick *r)
{
	mkVec3 d = mkVec3_Sub(b2->t, b1->t);
	double dl = mkVec3_LengthInline(d);
	if (!(dl > 0.0))
		return -1;
	mkVec3 n = mkVec3_Scale(d, 1.0 / dl);
	double f = mkVec3_Dot(n, d) - mkBatchBound_Support(b1, n) - mkBatchBound_Support(b2, mkVec3_Neg(n));
	if (!(f > margin))
		return -1;
	if (!witness && f > (distance ? margin : need)) {
		r->status = MK_CONTACT_SEPARATED;
		r->lower = f;
		r->upper = NAN;
		r->n = n;
		r->p1 = r->p2 = mkVec3_Make(NAN, NAN, NAN);
		r->clear = 1;
		return MK_PATH_SEPARATING;
	}
	mkVec3 p1 = mkVec3_Add(b1->t, mkBatchBound_End(b1, n)), p2 = mkVec3_Add(b2->t, mkBatchBound_End(b2, mkVec3_Neg(n)));
	return mkBatchQuick_Separated(r, f, n, p1, p2, distance ? margin : need, below);
}

#endif
