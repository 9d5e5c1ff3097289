/* error.c - the error measure of mink/error.h, shared part: the textbook
 * support functions of the bodies, the problem every measure starts from,
 * mkDeviation2/3_Support, compensated sums and the result's bookkeeping.
 * The 2D measure is in error2.c, the 3D one in error3_distance.c and
 * error3.c. The derivations of the bounds are in docs/error-measure.md;
 * the comments say which step of them each piece carries out.
 *
 * Coordinates are taken relative to the centre o of K (t1, or t1 + t2 for
 * the plus set), which K is symmetric about: then
 *   h_K(n) = h_C1(M1^T n) + h_C2(M2^T n),  x_K(n) = M1 x_C1(M1^T n) + M2 x_C2(M2^T n)
 * for both sets, because -C2 = C2. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/error.h>

#include "error_internal.h"

/* ---- textbook support functions ------------------------------------------
 * The gauge of the canonical superellipse is the norm ||(x/a, y/b)||_p,
 * p = 2/eps; its support function is the dual norm ||(a m1, b m2)||_q,
 * 1/p + 1/q = 1, i.e. q = 2/(2 - eps), and the support point is the
 * gradient of that, x_i = a_i sign(v_i) (|v_i| / ||v||_q)^(q-1), v = (a m1,
 * b m2). The superquadric's gauge nests two such norms (exponents 2/eps2
 * inside, 2/eps1 outside), and so does its support function (duals 2/(2 -
 * eps2) inside, 2/(2 - eps1) outside). Every norm is taken after dividing by
 * the larger entry, so that q up to 2e6 neither overflows nor loses the
 * larger entry. */

/* ||(v0, v1)||_q, and g_i = sign(v_i) (|v_i| / norm)^(q-1) (qm1 = q - 1). */
static double dual_norm(double v0, double v1, double q, double qm1, double *g0, double *g1)
{
	double big = fmax(fabs(v0), fabs(v1));
	if (!(big > 0)) {
		*g0 = *g1 = 0.0;
		return 0.0;
	}
	double r0 = fabs(v0) / big, r1 = fabs(v1) / big;
	if (q == 2.0) { /* the ellipse: no powers needed */
		double e = sqrt(r0 * r0 + r1 * r1);
		*g0 = v0 / (big * e);
		*g1 = v1 / (big * e);
		return big * e;
	}
	/* The larger entry's ratio is exactly 1, and pow(1, q) = 1 exactly:
	 * skipping that call changes no bit and saves a fifth of the pows. */
	double nrm = pow((r0 == 1.0 ? 1.0 : pow(r0, q)) + (r1 == 1.0 ? 1.0 : pow(r1, q)), 1.0 / q);
	*g0 = copysign(pow(r0 / nrm, qm1), v0);
	*g1 = copysign(pow(r1 / nrm, qm1), v1);
	return big * nrm;
}

/* h_C(m) and x_C(m) for the canonical superellipse. */
static double canon2(mkShape2 s, double m0, double m1, double *x)
{
	double q = 2.0 / (2.0 - s.eps), qm1 = s.eps / (2.0 - s.eps), g0, g1;
	double h = dual_norm(s.a * m0, s.b * m1, q, qm1, &g0, &g1);
	x[0] = s.a * g0;
	x[1] = s.b * g1;
	return h;
}

double mkDev_Canon3(mkShape3 s, double m0, double m1, double m2, double *x)
{
	double q2 = 2.0 / (2.0 - s.eps2), q2m1 = s.eps2 / (2.0 - s.eps2);
	double q1 = 2.0 / (2.0 - s.eps1), q1m1 = s.eps1 / (2.0 - s.eps1);
	double g0, g1, gr, g2;
	double r = dual_norm(s.a * m0, s.b * m1, q2, q2m1, &g0, &g1);
	double h = dual_norm(r, s.c * m2, q1, q1m1, &gr, &g2);
	x[0] = s.a * g0 * gr;
	x[1] = s.b * g1 * gr;
	x[2] = s.c * g2;
	return h;
}

/* h and x (relative to the body's centre) of M C in direction n. */
static double body2(const mkBody2 *b, double nx, double ny, double *x)
{
	const double(*M)[2] = b->M.m;
	double xc[2];
	double h = canon2(b->shape, M[0][0] * nx + M[1][0] * ny, M[0][1] * nx + M[1][1] * ny, xc);
	x[0] = M[0][0] * xc[0] + M[0][1] * xc[1];
	x[1] = M[1][0] * xc[0] + M[1][1] * xc[1];
	return h;
}

static double body3(const mkBody3 *b, const double *n, double *x)
{
	const double(*M)[3] = b->M.m;
	double m[3], xc[3];
	for (int j = 0; j < 3; ++j) m[j] = M[0][j] * n[0] + M[1][j] * n[1] + M[2][j] * n[2];
	double h = mkDev_Canon3(b->shape, m[0], m[1], m[2], xc);
	for (int i = 0; i < 3; ++i) x[i] = M[i][0] * xc[0] + M[i][1] * xc[1] + M[i][2] * xc[2];
	return h;
}



const mkBody3 *mkDev_LeadBody(const mkDevProb3 *P)
{
	return P->lead == 2 ? &P->b2 : &P->b1;
}

/* h_K and x_K (relative to o) at the unit direction (nx, ny). */
double mkDev_Hk2(const mkDevProb2 *P, double nx, double ny, double *x)
{
	double x1[2], x2[2];
	double h = body2(&P->b1, nx, ny, x1) + body2(&P->b2, nx, ny, x2);
	x[0] = x1[0] + x2[0];
	x[1] = x1[1] + x2[1];
	return h;
}

double mkDev_Hk3(const mkDevProb3 *P, const double *n, double *x)
{
	double x1[3], x2[3];
	double h = body3(&P->b1, n, x1) + body3(&P->b2, n, x2);
	for (int i = 0; i < 3; ++i) x[i] = x1[i] + x2[i];
	return h;
}

/* R = |M1|_F |a1| + |M2|_F |a2|, a bound on |x - o| over K: the size of
 * the sum of the bodies moved to the origin (the translation's term is then
 * an exact zero). */
static double mkDev_CentredSize2(mkBody2 b1, mkBody2 b2)
{
	b1.t = b2.t = mkVec2_Make(0.0, 0.0);
	return mkSum2_Size(b1, b2, MK_SET_CONTACT);
}

static double mkDev_CentredSize3(mkBody3 b1, mkBody3 b2)
{
	b1.t = b2.t = mkVec3_Make(0.0, 0.0, 0.0);
	return mkSum3_Size(b1, b2, MK_SET_CONTACT);
}

int mkDev_Prob2Init(mkDevProb2 *P, mkBody2 b1, mkBody2 b2, mkSet set)
{
	if (set != MK_SET_CONTACT && set != MK_SET_PLUS) return 0;
	if (!mkBody2_IsValid(b1, "body1", NULL, 0) || !mkBody2_IsValid(b2, "body2", NULL, 0)) return 0;
	P->b1 = b1;
	P->b2 = b2;
	P->o[0] = b1.t.x + (set == MK_SET_PLUS ? b2.t.x : 0.0);
	P->o[1] = b1.t.y + (set == MK_SET_PLUS ? b2.t.y : 0.0);
	P->S = mkSum2_Size(b1, b2, set);
	P->R = mkDev_CentredSize2(b1, b2);
	P->round = ROUND_ULPS * UNIT_ROUND * P->S;
	return 1;
}

int mkDev_Prob3Init(mkDevProb3 *P, mkBody3 b1, mkBody3 b2, mkSet set)
{
	if (set != MK_SET_CONTACT && set != MK_SET_PLUS) return 0;
	if (!mkBody3_IsValid(b1, "body1", NULL, 0) || !mkBody3_IsValid(b2, "body2", NULL, 0)) return 0;
	P->b1 = b1;
	P->b2 = b2;
	int plus = set == MK_SET_PLUS;
	P->o[0] = b1.t.x + (plus ? b2.t.x : 0.0);
	P->o[1] = b1.t.y + (plus ? b2.t.y : 0.0);
	P->o[2] = b1.t.z + (plus ? b2.t.z : 0.0);
	P->S = mkSum3_Size(b1, b2, set);
	P->R = mkDev_CentredSize3(b1, b2);
	P->round = ROUND_ULPS * UNIT_ROUND * P->S;
	P->lead = fmin(b2.shape.eps1, b2.shape.eps2) < fmin(b1.shape.eps1, b1.shape.eps2) ? 2 : 1;
	return 1;
}

double mkDeviation2_Support(mkBody2 b1, mkBody2 b2, mkSet set, mkVec2 n, mkVec2 *point)
{
	mkDevProb2 P;
	double len = hypot(n.x, n.y);
	if (!mkDev_Prob2Init(&P, b1, b2, set) || !(len > 0) || !isfinite(len)) {
		if (point) *point = mkVec2_Make(NAN, NAN);
		return NAN;
	}
	double x[2], h = mkDev_Hk2(&P, n.x / len, n.y / len, x);
	if (point) *point = mkVec2_Make(P.o[0] + x[0], P.o[1] + x[1]);
	return (h + (n.x / len) * P.o[0] + (n.y / len) * P.o[1]) * len;
}

double mkDeviation3_Support(mkBody3 b1, mkBody3 b2, mkSet set, mkVec3 n, mkVec3 *point)
{
	mkDevProb3 P;
	double len = mkVec3_Length(n);
	if (!mkDev_Prob3Init(&P, b1, b2, set) || !(len > 0) || !isfinite(len)) {
		if (point) *point = mkVec3_Make(NAN, NAN, NAN);
		return NAN;
	}
	double u[3] = {n.x / len, n.y / len, n.z / len}, x[3], h = mkDev_Hk3(&P, u, x);
	if (point) *point = mkVec3_Make(P.o[0] + x[0], P.o[1] + x[1], P.o[2] + x[2]);
	return (h + u[0] * P.o[0] + u[1] * P.o[1] + u[2] * P.o[2]) * len;
}

/* ---- compensated sums ------------------------------------------------------
 * Neumaier's summation: the error is about 2u times the sum of |terms|
 * instead of count times u, which matters for areas summed over millions of
 * terms. */

void mkDevSum_Add(mkDevSum *a, double v)
{
	double t = a->s + v;
	if (fabs(a->s) >= fabs(v)) a->c += (a->s - t) + v;
	else a->c += (v - t) + a->s;
	a->s = t;
}

double mkDevSum_Get(const mkDevSum *a) { return a->s + a->c; }

void mkDev_Finish(mkDeviation *e, const char *what)
{
	e->hausdorff_rel = e->hausdorff_abs / e->size;
	e->off_boundary_rel = e->off_boundary_max / e->size;
	snprintf(e->message, sizeof e->message,
		"%d points (%d not finite), %d vertices: hausdorff %.3g of the scale (+%.2g), gap in %.3g, out %.3g, "
		"off boundary %.3g (+%.2g); %s error %.3g (+-%.2g)",
		e->points, e->nonfinite, e->vertices, e->hausdorff_rel, e->hausdorff_bound / e->size, e->gap_in / e->size,
		e->gap_out / e->size, e->off_boundary_rel, e->off_boundary_bound / e->size, what, e->area_rel,
		e->area_bound);
}

/* The true area / volume from the options, when the caller gives it: 1,
 * else 0 (the caller computes it). */
int mkDev_TakeTruth(const mkDeviationOptions *opt, mkDeviation *out)
{
	if (!opt || !(opt->truth > 0))
		return 0;
	out->area_k = opt->truth;
	out->area_bound = opt->truth_bound;
	return 1;
}

/* The result when no point is finite: nothing to measure. */
void mkDev_NoPoints(mkDeviation *out, const char *what)
{
	out->hausdorff_abs = out->off_boundary_max = HUGE_VAL;
	out->area_rel = -1.0;
	mkDev_Finish(out, what);
}

void mkDev_Init(mkDeviation *e, int points, double size)
{
	memset(e, 0, sizeof *e);
	e->points = points;
	e->size = size;
	e->worst = -1;
	e->gap_in = e->gap_out = -HUGE_VAL;
}

/* ---- 3D -------------------------------------------------------------------------- */

double mkDev_Dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void mkDev_Cross3(const double *a, const double *b, double *c)
{
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
}

int mkDev_Unit3(double *v)
{
	double big = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
	if (!(big > 0) || !isfinite(big)) return 0;
	for (int i = 0; i < 3; ++i) v[i] /= big;
	double len = sqrt(mkDev_Dot3(v, v));
	for (int i = 0; i < 3; ++i) v[i] /= len;
	return 1;
}

/* Two unit vectors completing the unit n to an orthonormal frame. */
void mkDev_Frame3(const double *n, double *e1, double *e2)
{
	double axis[3] = {0, 0, 0};
	int k = fabs(n[0]) <= fabs(n[1]) ? (fabs(n[0]) <= fabs(n[2]) ? 0 : 2) : (fabs(n[1]) <= fabs(n[2]) ? 1 : 2);
	axis[k] = 1;
	mkDev_Cross3(n, axis, e1);
	mkDev_Unit3(e1);
	mkDev_Cross3(n, e1, e2);
}

