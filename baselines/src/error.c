/* error.c - the error measure of mink/error.h: the Hausdorff distance, the
 * points' distance off the boundary and the area / volume error of any
 * method's output against the true sum, from the textbook support functions
 * of the bodies. The derivations of the bounds are in docs/error-measure.md;
 * the comments here say which step of them each piece carries out.
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

#include "referee_cgal.h"

#define UNIT_ROUND (DBL_EPSILON / 2)
/* Rounding allowance, in units of u times the scale: a support value is a
 * few pows (each <= 1 ulp, the outer power 1/q contracting their errors)
 * and two small matrix products, so some 10 u of |x|; a dot product with a
 * point adds a few u of |p|. 64 keeps a margin. */
#define ROUND_ULPS 64.0
#define TOL_DEFAULT 1e-6
#define EVAL_BUDGET 4000000L /* support evaluations for refining gap_in */

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

static double canon3(mkShape3 s, double m0, double m1, double m2, double *x)
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
	double h = canon3(b->shape, m[0], m[1], m[2], xc);
	for (int i = 0; i < 3; ++i) x[i] = M[i][0] * xc[0] + M[i][1] * xc[1] + M[i][2] * xc[2];
	return h;
}

typedef struct Prob2 {
	mkBody2 b1, b2;
	double o[2]; /* centre of K */
	double S;    /* scale */
	double R;    /* bound on |x - o| over K */
	double round;/* rounding allowance ROUND_ULPS u S */
} Prob2;

typedef struct Prob3 {
	mkBody3 b1, b2;
	double o[3];
	double S, R, round;
	int lead; /* 2 when body 2 is the boxier (smaller exponent): the volume
	             grid and the ray-parameter search follow that body */
} Prob3;

static const mkBody3 *lead_body(const Prob3 *P)
{
	return P->lead == 2 ? &P->b2 : &P->b1;
}

/* h_K and x_K (relative to o) at the unit direction (nx, ny). */
static double hk2(const Prob2 *P, double nx, double ny, double *x)
{
	double x1[2], x2[2];
	double h = body2(&P->b1, nx, ny, x1) + body2(&P->b2, nx, ny, x2);
	x[0] = x1[0] + x2[0];
	x[1] = x1[1] + x2[1];
	return h;
}

static double hk3(const Prob3 *P, const double *n, double *x)
{
	double x1[3], x2[3];
	double h = body3(&P->b1, n, x1) + body3(&P->b2, n, x2);
	for (int i = 0; i < 3; ++i) x[i] = x1[i] + x2[i];
	return h;
}

static double frob2(mkMat2 m)
{
	return sqrt(m.m[0][0] * m.m[0][0] + m.m[0][1] * m.m[0][1] + m.m[1][0] * m.m[1][0] + m.m[1][1] * m.m[1][1]);
}

static double frob3(mkMat3 m)
{
	double s = 0;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) s += m.m[i][j] * m.m[i][j];
	return sqrt(s);
}

double mkError2_Scale(mkBody2 b1, mkBody2 b2, mkSet set)
{
	double s = hypot(b1.t.x, b1.t.y) + frob2(b1.M) * hypot(b1.shape.a, b1.shape.b)
		+ frob2(b2.M) * hypot(b2.shape.a, b2.shape.b);
	if (set == MK_SET_PLUS) s += hypot(b2.t.x, b2.t.y);
	return s;
}

double mkError3_Scale(mkBody3 b1, mkBody3 b2, mkSet set)
{
	double s = mkVec3_Length(b1.t) + frob3(b1.M) * mkVec3_Length(mkVec3_Make(b1.shape.a, b1.shape.b, b1.shape.c))
		+ frob3(b2.M) * mkVec3_Length(mkVec3_Make(b2.shape.a, b2.shape.b, b2.shape.c));
	if (set == MK_SET_PLUS) s += mkVec3_Length(b2.t);
	return s;
}

static int prob2_init(Prob2 *P, mkBody2 b1, mkBody2 b2, mkSet set)
{
	if (set != MK_SET_CONTACT && set != MK_SET_PLUS) return 0;
	if (!mkBody2_IsValid(b1, "body1", NULL, 0) || !mkBody2_IsValid(b2, "body2", NULL, 0)) return 0;
	P->b1 = b1;
	P->b2 = b2;
	P->o[0] = b1.t.x + (set == MK_SET_PLUS ? b2.t.x : 0.0);
	P->o[1] = b1.t.y + (set == MK_SET_PLUS ? b2.t.y : 0.0);
	P->S = mkError2_Scale(b1, b2, set);
	P->R = frob2(b1.M) * hypot(b1.shape.a, b1.shape.b) + frob2(b2.M) * hypot(b2.shape.a, b2.shape.b);
	P->round = ROUND_ULPS * UNIT_ROUND * P->S;
	return 1;
}

static int prob3_init(Prob3 *P, mkBody3 b1, mkBody3 b2, mkSet set)
{
	if (set != MK_SET_CONTACT && set != MK_SET_PLUS) return 0;
	if (!mkBody3_IsValid(b1, "body1", NULL, 0) || !mkBody3_IsValid(b2, "body2", NULL, 0)) return 0;
	P->b1 = b1;
	P->b2 = b2;
	int plus = set == MK_SET_PLUS;
	P->o[0] = b1.t.x + (plus ? b2.t.x : 0.0);
	P->o[1] = b1.t.y + (plus ? b2.t.y : 0.0);
	P->o[2] = b1.t.z + (plus ? b2.t.z : 0.0);
	P->S = mkError3_Scale(b1, b2, set);
	P->R = frob3(b1.M) * mkVec3_Length(mkVec3_Make(b1.shape.a, b1.shape.b, b1.shape.c))
		+ frob3(b2.M) * mkVec3_Length(mkVec3_Make(b2.shape.a, b2.shape.b, b2.shape.c));
	P->round = ROUND_ULPS * UNIT_ROUND * P->S;
	P->lead = fmin(b2.shape.eps1, b2.shape.eps2) < fmin(b1.shape.eps1, b1.shape.eps2) ? 2 : 1;
	return 1;
}

double mkError2_Support(mkBody2 b1, mkBody2 b2, mkSet set, mkVec2 n, mkVec2 *point)
{
	Prob2 P;
	double len = hypot(n.x, n.y);
	if (!prob2_init(&P, b1, b2, set) || !(len > 0) || !isfinite(len)) {
		if (point) *point = mkVec2_Make(NAN, NAN);
		return NAN;
	}
	double x[2], h = hk2(&P, n.x / len, n.y / len, x);
	if (point) *point = mkVec2_Make(P.o[0] + x[0], P.o[1] + x[1]);
	return (h + (n.x / len) * P.o[0] + (n.y / len) * P.o[1]) * len;
}

double mkError3_Support(mkBody3 b1, mkBody3 b2, mkSet set, mkVec3 n, mkVec3 *point)
{
	Prob3 P;
	double len = mkVec3_Length(n);
	if (!prob3_init(&P, b1, b2, set) || !(len > 0) || !isfinite(len)) {
		if (point) *point = mkVec3_Make(NAN, NAN, NAN);
		return NAN;
	}
	double u[3] = {n.x / len, n.y / len, n.z / len}, x[3], h = hk3(&P, u, x);
	if (point) *point = mkVec3_Make(P.o[0] + x[0], P.o[1] + x[1], P.o[2] + x[2]);
	return (h + u[0] * P.o[0] + u[1] * P.o[1] + u[2] * P.o[2]) * len;
}

/* ---- compensated sums ------------------------------------------------------
 * Neumaier's summation: the error is about 2u times the sum of |terms|
 * instead of count times u, which matters for areas summed over millions of
 * terms. */
typedef struct Sum { double s, c; } Sum;

static void sum_add(Sum *a, double v)
{
	double t = a->s + v;
	if (fabs(a->s) >= fabs(v)) a->c += (a->s - t) + v;
	else a->c += (v - t) + a->s;
	a->s = t;
}

static double sum_get(const Sum *a) { return a->s + a->c; }

/* ---- the area of K (2D) ------------------------------------------------------
 * Exact support points x_i at increasing normal angles t_i span an inscribed
 * polygon (area A_in <= |K|); their tangent lines bound a circumscribed one,
 * which exceeds it by one triangle per interval, of area g0 g1 / (2 sin dt)
 * with g0 = <n_i, x_i - x_{i+1}> and g1 = <n_{i+1}, x_{i+1} - x_i> (the
 * heights of each point below the other's tangent line; the triangle's
 * angles at the chord are asin(g0/L) and asin(g1/L)). So |K| lies in
 * [A_in, A_in + T], T the triangles' sum. Intervals whose triangle exceeds
 * the target share are bisected until T <= AREA_TARGET A_in. */
#define AREA_TARGET 1e-11
#define AREA_START 4096
#define AREA_CAP (1 << 22)

static mkResult area2(const Prob2 *P, double *area, double *bound)
{
	int m = AREA_START;
	/* Per breakpoint: angle, unit normal (c, s) and support point. */
	double *t = malloc(5 * (size_t)m * sizeof *t), *tri_i = NULL;
	if (!t) return MK_ERR_MEMORY;
	for (int i = 0; i < m; ++i) {
		double *r = t + 5 * i;
		r[0] = -MK_PI + 2.0 * MK_PI * i / m;
		r[1] = cos(r[0]);
		r[2] = sin(r[0]);
		hk2(P, r[1], r[2], r + 3);
	}
	double a_in = 0, tri = 0;
	for (int pass = 0;; ++pass) {
		free(tri_i);
		tri_i = malloc((size_t)m * sizeof *tri_i);
		if (!tri_i) {
			free(t);
			return MK_ERR_MEMORY;
		}
		Sum sa = {0, 0}, st = {0, 0};
		for (int i = 0; i < m; ++i) {
			const double *p = t + 5 * i, *q = t + 5 * ((i + 1) % m);
			sum_add(&sa, 0.5 * (p[3] * q[4] - p[4] * q[3]));
			double d0 = q[3] - p[3], d1 = q[4] - p[4];
			double g0 = -(p[1] * d0 + p[2] * d1), g1 = q[1] * d0 + q[2] * d1;
			double sn = p[1] * q[2] - p[2] * q[1]; /* sin of the angle step */
			double T = fmax(g0, 0.0) * fmax(g1, 0.0) / (2.0 * sn);
			tri_i[i] = T;
			sum_add(&st, T);
		}
		a_in = sum_get(&sa);
		tri = sum_get(&st);
		if (tri <= AREA_TARGET * a_in || 2 * m > AREA_CAP || pass > 60) break;
		/* Split the intervals above their share of the target. */
		double share = AREA_TARGET * a_in / m;
		int add = 0;
		for (int i = 0; i < m; ++i) add += tri_i[i] > share;
		if (add == 0 || m + add > AREA_CAP) break;
		int mm = m + add;
		double *t2 = malloc(5 * (size_t)mm * sizeof *t2);
		if (!t2) {
			free(t);
			free(tri_i);
			return MK_ERR_MEMORY;
		}
		int k = 0;
		for (int i = 0; i < m; ++i) {
			memcpy(t2 + 5 * k++, t + 5 * i, 5 * sizeof *t);
			if (tri_i[i] > share) {
				double tj = i + 1 < m ? t[5 * (i + 1)] : t[0] + 2.0 * MK_PI;
				double *r = t2 + 5 * k++;
				r[0] = 0.5 * (t[5 * i] + tj);
				r[1] = cos(r[0]);
				r[2] = sin(r[0]);
				hk2(P, r[1], r[2], r + 3);
			}
		}
		free(t);
		t = t2;
		m = mm;
	}
	free(t);
	free(tri_i);
	/* Rounding: each term of the compensated sums is a product of rounded
	 * coordinates (a few u relative), so 16 u of the area covers them. */
	*area = a_in + 0.5 * tri;
	*bound = 0.5 * tri + 16.0 * UNIT_ROUND * a_in;
	return MK_OK;
}

mkResult mkError2_Area(mkBody2 b1, mkBody2 b2, mkSet set, double *area, double *bound)
{
	Prob2 P;
	if (!area || !bound || !prob2_init(&P, b1, b2, set)) return MK_ERR_ARGUMENT;
	return area2(&P, area, bound);
}

/* ---- gap_in in 2D -------------------------------------------------------------
 * Over the normal cone of vertex v of P (between the outward normals of its
 * two edges), h_P(n) = <n, v>, so h_K - h_P = h_{K-v}, a convex, positively
 * homogeneous function. On an arc [ta, tb] of that cone, a unit direction n
 * is w / |w| for w on the chord from n(ta) to n(tb), |w| >= cos((tb-ta)/2);
 * convexity bounds h_{K-v}(w) by its larger end value, so
 *   max over the arc <= max(f(ta), f(tb), 0) / cos((tb - ta)/2).
 * Arcs whose bound exceeds the best value found (plus the tolerance) are
 * bisected. */
typedef struct Arc {
	double ta, tb, fa, fb;
	int v;
} Arc;

static double arc_bound(const Arc *a)
{
	return fmax(fmax(a->fa, a->fb), 0.0) / cos(0.5 * (a->tb - a->ta));
}

static double phi2(const Prob2 *P, double t, const double *v)
{
	double c = cos(t), s = sin(t), x[2];
	return hk2(P, c, s, x) - (c * v[0] + s * v[1]);
}

/* Width of vertex k's normal cone, alpha[k-1] to alpha[k] counter-clockwise.
 * The polygon is strictly convex (decided exactly), so every width lies in
 * (0, pi) when m >= 3; edges that are parallel to within rounding can give
 * normal angles out of order by an ulp, which would read as a cone of
 * almost 2 pi: such a cone is empty (width 0; the neighbours' cones meet
 * there to within that ulp). */
static double cone_width(const double *alpha, int m, int k)
{
	if (m == 1) return 2 * MK_PI;
	double w = alpha[k] - alpha[(k + m - 1) % m];
	while (w <= 0) w += 2 * MK_PI;
	if (m >= 3 && w > MK_PI) w = 0;
	return w;
}

/* gap_in over the convex polygon Q (m vertices, counter-clockwise), given
 * the outward gap (which sets the level that matters). *hi receives the
 * certified upper bound of max (h_K - h_P). */
static mkResult gap_in2(const Prob2 *P, const double *Q, int m, double gap_out, double tol, double *lo, double *hi)
{
	const double piece = MK_PI / 8;
	/* Breakpoints: each vertex cone split into arcs of at most pi/8. */
	double *alpha = malloc((size_t)m * sizeof *alpha);
	if (!alpha) return MK_ERR_MEMORY;
	for (int k = 0; k < m; ++k) {
		const double *a = Q + 2 * k, *b = Q + 2 * ((k + 1) % m);
		alpha[k] = m == 1 ? 0.0 : atan2(-(b[0] - a[0]), b[1] - a[1]);
	}
	long count = 0;
	for (int k = 0; k < m; ++k) count += (long)ceil(cone_width(alpha, m, k) / piece);
	long cap = count + 64;
	Arc *arcs = malloc((size_t)cap * sizeof *arcs);
	if (!arcs) {
		free(alpha);
		return MK_ERR_MEMORY;
	}
	long na = 0;
	double best = -HUGE_VAL;
	for (int k = 0; k < m; ++k) {
		double start = m == 1 ? -MK_PI : alpha[(k + m - 1) % m];
		double w = cone_width(alpha, m, k);
		int pieces = (int)ceil(w / piece);
		if (pieces == 0) continue;
		const double *v = Q + 2 * k;
		double prev = phi2(P, start, v);
		for (int j = 0; j < pieces; ++j) {
			Arc *a = &arcs[na++];
			a->ta = start + w * j / pieces;
			a->tb = j + 1 == pieces ? start + w : start + w * (j + 1) / pieces;
			a->fa = prev;
			a->fb = phi2(P, a->tb, v);
			a->v = k;
			prev = a->fb;
			best = fmax(best, fmax(a->fa, a->fb));
		}
	}
	free(alpha);
	/* Depth-first refinement with an explicit stack of pending arcs. */
	long sp = 0, scap = 4096, evals = 0;
	Arc *stack = malloc((size_t)scap * sizeof *stack);
	if (!stack) {
		free(arcs);
		return MK_ERR_MEMORY;
	}
	double level = fmax(best, gap_out);
	double top = -HUGE_VAL; /* largest bound of an arc left as it is */
	for (long i = 0; i < na; ++i) {
		stack[sp++] = arcs[i];
		while (sp > 0) {
			Arc a = stack[--sp];
			level = fmax(best, gap_out);
			double ub = arc_bound(&a), need = level + tol * fabs(level) + P->round;
			if (ub <= need || evals >= EVAL_BUDGET || a.tb - a.ta < 1e-15) {
				top = fmax(top, ub);
				continue;
			}
			double tm = 0.5 * (a.ta + a.tb), fm = phi2(P, tm, Q + 2 * a.v);
			++evals;
			best = fmax(best, fm);
			if (sp + 2 > scap) {
				scap *= 2;
				Arc *ns = realloc(stack, (size_t)scap * sizeof *ns);
				if (!ns) {
					free(stack);
					free(arcs);
					return MK_ERR_MEMORY;
				}
				stack = ns;
			}
			Arc l = {a.ta, tm, a.fa, fm, a.v}, r = {tm, a.tb, fm, a.fb, a.v};
			stack[sp++] = r;
			stack[sp++] = l;
		}
	}
	free(stack);
	free(arcs);
	*lo = best;
	*hi = fmax(top, best);
	return MK_OK;
}

/* ---- signed distance of a point to K (2D) ----------------------------------------
 * sd(p) = max over unit n of f(n) = <n, p> - h_K(n); every value of f is a
 * lower bound. Along the angle t, f'(t) = <n'(t), p - x_K(t)>. A table of
 * directions gives the start (near the point's polar angle, then uphill);
 * the maximiser is then bracketed by the sign of f' and the bracket closed
 * by regula falsi (Illinois) with bisection steps. On the final bracket
 * [tl, tr], h_{K-p} >= max(<x_l - p, w>, <x_r - p, w>) on the chord (the
 * tangent lines of K at its ends), which bounds f from above there. */
#define TABLE2 4096

typedef struct Table2 {
	double t[TABLE2], c[TABLE2], s[TABLE2], x[2 * TABLE2], h[TABLE2], beta[TABLE2];
} Table2;

static void table2_init(const Prob2 *P, Table2 *T)
{
	for (int j = 0; j < TABLE2; ++j) {
		T->t[j] = -MK_PI + 2.0 * MK_PI * j / TABLE2;
		T->c[j] = cos(T->t[j]);
		T->s[j] = sin(T->t[j]);
		T->h[j] = hk2(P, T->c[j], T->s[j], T->x + 2 * j);
		double b = atan2(T->x[2 * j + 1], T->x[2 * j]);
		if (j > 0)
			while (b < T->beta[j - 1]) b += 2 * MK_PI;
		T->beta[j] = b;
	}
}

typedef struct Eval2 { double t, c, s, f, d, x[2]; } Eval2;

static Eval2 eval2(const Prob2 *P, double t, const double *p)
{
	Eval2 e;
	double c = cos(t), s = sin(t);
	e.t = t;
	e.c = c;
	e.s = s;
	double h = hk2(P, c, s, e.x);
	e.f = c * p[0] + s * p[1] - h;
	e.d = -s * (p[0] - e.x[0]) + c * (p[1] - e.x[1]);
	return e;
}

/* Upper bound of f over [l.t, r.t] from the tangent lines at both ends. */
static double tangent_upper2(const Eval2 *l, const Eval2 *r, const double *p)
{
	double nl[2] = {l->c, l->s}, nr[2] = {r->c, r->s};
	double yl[2] = {l->x[0] - p[0], l->x[1] - p[1]}, yr[2] = {r->x[0] - p[0], r->x[1] - p[1]};
	/* A(s) = (1-s) <yl, nl> + s <yl, nr>, B(s) = (1-s) <yr, nl> + s <yr, nr>. */
	double A0 = yl[0] * nl[0] + yl[1] * nl[1], A1 = yl[0] * nr[0] + yl[1] * nr[1];
	double B0 = yr[0] * nl[0] + yr[1] * nl[1], B1 = yr[0] * nr[0] + yr[1] * nr[1];
	double lb = fmin(fmax(A0, B0), fmax(A1, B1));
	double D0 = A0 - B0, D1 = A1 - B1;
	if ((D0 > 0) != (D1 > 0) && D0 != D1) {
		double s = D0 / (D0 - D1);
		if (s > 0 && s < 1) lb = fmin(lb, (1 - s) * A0 + s * A1);
	}
	double c = cos(0.5 * (r->t - l->t));
	if (lb < 0) lb /= c;
	return -lb;
}

static void signed_distance2(const Prob2 *P, const Table2 *T, const double *p, double *sd, double *ub)
{
	const double step = 2.0 * MK_PI / TABLE2;
	/* Start: the table direction whose support point has p's polar angle. */
	double b = atan2(p[1], p[0]);
	while (b < T->beta[0]) b += 2 * MK_PI;
	while (b >= T->beta[0] + 2 * MK_PI) b -= 2 * MK_PI;
	int lo = 0, hi = TABLE2 - 1;
	while (lo < hi) {
		int mid = (lo + hi + 1) / 2;
		if (T->beta[mid] <= b) lo = mid;
		else hi = mid - 1;
	}
#define TF(j) (T->c[j] * p[0] + T->s[j] * p[1] - T->h[j])
	int best = lo;
	double fb = TF(best);
	for (int w = -16; w <= 16; ++w) {
		int j = ((lo + w) % TABLE2 + TABLE2) % TABLE2;
		double f = TF(j);
		if (f > fb) fb = f, best = j;
	}
	for (int walk = 0; walk < TABLE2; ++walk) { /* uphill to a local maximum */
		int jl = (best + TABLE2 - 1) % TABLE2, jr = (best + 1) % TABLE2;
		double fl = TF(jl), fr = TF(jr);
		if (fl > fb && fl >= fr) fb = fl, best = jl;
		else if (fr > fb) fb = fr, best = jr;
		else break;
	}
#undef TF
	double tc = T->t[best];
	Eval2 l = eval2(P, tc - step, p), r = eval2(P, tc + step, p);
	double top = fmax(fb, fmax(l.f, r.f));
	/* Widen until f' changes sign across the bracket (a few steps at most
	 * for a point near the boundary). */
	for (int k = 0; k < 64 && l.d < 0; ++k) {
		r = l;
		l = eval2(P, l.t - step, p);
		top = fmax(top, l.f);
	}
	for (int k = 0; k < 64 && r.d > 0; ++k) {
		l = r;
		r = eval2(P, r.t + step, p);
		top = fmax(top, r.f);
	}
	double wl = l.d, wr = r.d; /* Illinois weights */
	int side = 0;
	for (int it = 0; it < 200 && r.t - l.t > 4e-16 * (1.0 + fabs(l.t)); ++it) {
		double tm;
		if (it % 3 == 2 || !(wl > 0) || !(wr < 0)) tm = 0.5 * (l.t + r.t);
		else {
			tm = (l.t * (-wr) + r.t * wl) / (wl - wr);
			if (!(tm > l.t && tm < r.t)) tm = 0.5 * (l.t + r.t);
		}
		if (tm <= l.t || tm >= r.t) break;
		Eval2 e = eval2(P, tm, p);
		top = fmax(top, e.f);
		if (e.d == 0) {
			l = r = e;
			break;
		}
		if (e.d > 0) {
			l = e;
			wl = e.d;
			if (side == -1) wr *= 0.5;
			side = -1;
		} else {
			r = e;
			wr = e.d;
			if (side == 1) wl *= 0.5;
			side = 1;
		}
		/* Done when the bracket's certificate (below) already pins the
		 * maximum to a thousandth of the rounding allowance: closing the
		 * bracket further cannot change sd or its bound visibly. */
		if (r.t - l.t < 1e-6 && tangent_upper2(&l, &r, p) - top <= 1e-3 * P->round) break;
	}
	*sd = top;
	*ub = l.t == r.t ? top : fmax(top, tangent_upper2(&l, &r, p));
}

/* ---- polygon area -------------------------------------------------------------- */

static double polygon_area(const double *Q, int m)
{
	Sum s = {0, 0};
	for (int k = 0; k < m; ++k) {
		const double *a = Q + 2 * k, *b = Q + 2 * ((k + 1) % m);
		sum_add(&s, 0.5 * (a[0] * b[1] - a[1] * b[0]));
	}
	return sum_get(&s);
}

static void finish(mkError *e, const char *what)
{
	e->hausdorff_rel = e->hausdorff_abs / e->scale;
	e->off_boundary_rel = e->off_boundary_max / e->scale;
	snprintf(e->message, sizeof e->message,
		"%d points (%d not finite), %d vertices: hausdorff %.3g of the scale (+%.2g), gap in %.3g, out %.3g, "
		"off boundary %.3g (+%.2g); %s error %.3g (+-%.2g)",
		e->points, e->nonfinite, e->vertices, e->hausdorff_rel, e->hausdorff_bound / e->scale, e->gap_in / e->scale,
		e->gap_out / e->scale, e->off_boundary_rel, e->off_boundary_bound / e->scale, what, e->area_rel,
		e->area_bound);
}

/* The true area / volume from the options, when the caller gives it: 1,
 * else 0 (the caller computes it). */
static int take_truth(const mkErrorOptions *opt, mkError *out)
{
	if (!opt || !(opt->truth > 0))
		return 0;
	out->area_k = opt->truth;
	out->area_bound = opt->truth_bound;
	return 1;
}

/* The result when no point is finite: nothing to measure. */
static void no_points(mkError *out, const char *what)
{
	out->hausdorff_abs = out->off_boundary_max = HUGE_VAL;
	out->area_rel = -1.0;
	finish(out, what);
}

static void error_init(mkError *e, int points, double scale)
{
	memset(e, 0, sizeof *e);
	e->points = points;
	e->scale = scale;
	e->worst = -1;
	e->gap_in = e->gap_out = -HUGE_VAL;
}

mkResult mkError2_Measure(mkBody2 b1, mkBody2 b2, mkSet set, const mkPointSet *pts, const mkErrorOptions *opt,
	mkError *out)
{
	Prob2 P;
	if (!pts || !out || pts->dim != 2 || pts->count < 0 || (pts->count > 0 && (!pts->x || !pts->y)))
		return MK_ERR_ARGUMENT;
	if (!prob2_init(&P, b1, b2, set)) return MK_ERR_ARGUMENT;
	double tol = opt && opt->tol > 0 ? opt->tol : TOL_DEFAULT;
	error_init(out, pts->count, P.S);
	int n = pts->count;
	double *xy = malloc(2 * (size_t)(n > 0 ? n : 1) * sizeof *xy);
	double *Q = malloc(2 * (size_t)(n > 0 ? n : 1) * sizeof *Q);
	int *idx = malloc((size_t)(n > 0 ? n : 1) * sizeof *idx);
	Table2 *T = malloc(sizeof *T);
	mkResult r = xy && Q && idx && T ? MK_OK : MK_ERR_MEMORY;
	int nf = 0;
	if (r == MK_OK)
		for (int k = 0; k < n; ++k) {
			double px = pts->x[k] - P.o[0], py = pts->y[k] - P.o[1];
			if (!isfinite(px) || !isfinite(py)) {
				++out->nonfinite;
				continue;
			}
			xy[2 * nf] = px;
			xy[2 * nf + 1] = py;
			idx[nf++] = k;
		}
	if (r == MK_OK && !take_truth(opt, out))
		r = area2(&P, &out->area_k, &out->area_bound);
	if (r == MK_OK && nf == 0) {
		no_points(out, "area");
	} else if (r == MK_OK) {
		/* The points' signed distances: gap_out and off_boundary. */
		table2_init(&P, T);
		double sd_hi = -HUGE_VAL, off_bound = 0;
		for (int k = 0; k < nf; ++k) {
			double sd, ub;
			signed_distance2(&P, T, xy + 2 * k, &sd, &ub);
			if (sd > out->gap_out) out->gap_out = sd;
			sd_hi = fmax(sd_hi, ub);
			if (fabs(sd) > out->off_boundary_max || out->worst < 0) {
				out->off_boundary_max = fabs(sd);
				out->worst = idx[k];
			}
			off_bound = fmax(off_bound, ub - sd);
		}
		out->off_boundary_bound = off_bound + P.round;
		/* P and gap_in. */
		int m = mkPolygon2_Convex(xy, nf, Q);
		if (m < 1) r = MK_ERR_MEMORY;
		else {
			out->vertices = m;
			out->area_p = m >= 3 ? polygon_area(Q, m) : 0.0;
			double hi;
			r = gap_in2(&P, Q, m, out->gap_out, tol, &out->gap_in, &hi);
			if (r == MK_OK) {
				out->hausdorff_abs = fmax(out->gap_in, out->gap_out);
				out->hausdorff_bound = fmax(hi, sd_hi) - out->hausdorff_abs + P.round;
				out->area_rel = (out->area_p - out->area_k) / out->area_k;
				/* |P| is a compensated sum (16 u relative), |K| carries its
				 * bound; the quotient's own rounding is a few u. */
				out->area_bound = (out->area_bound + 16.0 * UNIT_ROUND * out->area_p) / out->area_k
					+ 4.0 * UNIT_ROUND * fabs(out->area_rel);
				finish(out, "area");
			}
		}
	}
	free(xy);
	free(Q);
	free(idx);
	free(T);
	return r;
}

/* ---- 3D -------------------------------------------------------------------------- */

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double *a, const double *b, double *c)
{
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
}

static int unit3(double *v)
{
	double big = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
	if (!(big > 0) || !isfinite(big)) return 0;
	for (int i = 0; i < 3; ++i) v[i] /= big;
	double len = sqrt(dot3(v, v));
	for (int i = 0; i < 3; ++i) v[i] /= len;
	return 1;
}

/* Two unit vectors completing the unit n to an orthonormal frame. */
static void frame3(const double *n, double *e1, double *e2)
{
	double axis[3] = {0, 0, 0};
	int k = fabs(n[0]) <= fabs(n[1]) ? (fabs(n[0]) <= fabs(n[2]) ? 0 : 2) : (fabs(n[1]) <= fabs(n[2]) ? 1 : 2);
	axis[k] = 1;
	cross3(n, axis, e1);
	unit3(e1);
	cross3(n, e1, e2);
}

/* ---- the volume of K (3D) -----------------------------------------------------------
 * Exact support points of K form a closed triangulated surface over a grid
 * of normals, G + 1 rows from pole to pole and 2G columns; its signed volume
 * (divergence theorem, sum of det(a, b, c) / 6) converges as G^-2. The
 * normals are the boxier body's (the one with the smaller exponent; its
 * textbook gradient mapped by M^-T) at the surface parameters of the
 * "almost equally spaced" grid (the
 * reference code's map of the angles, exponent 1/eps; mink/sum.h), so that
 * the points spread evenly over that body instead of crowding its edges
 * (normals taken evenly in angle leave its flat faces as single triangles
 * and its rounded edges underresolved). Grids G/2, G and 2G give two
 * Richardson extrapolations, V(G) + (V(G) - V(G/2)) / 3 and V(2G) + (V(2G)
 * - V(G)) / 3; the second is the value, and the difference of the two is
 * reported as the bound: an estimate, not a certificate. */
#define VOLUME_G 192

static double spow(double x, double e)
{
	return copysign(pow(fabs(x), e), x);
}

/* (c, s) of a grid angle, exact on the axes, then the spaced map. */
static void spaced_angle(double t, double inv_eps, double *c, double *s)
{
	double cc = cos(t), ss = sin(t);
	if (fabs(cc) < 1e-15) cc = 0.0, ss = ss > 0 ? 1.0 : -1.0;
	if (fabs(ss) < 1e-15) ss = 0.0, cc = cc > 0 ? 1.0 : -1.0;
	double big = fmax(fabs(cc), fabs(ss)), x = spow(cc / big, inv_eps), y = spow(ss / big, inv_eps), l = hypot(x, y);
	*c = x / l;
	*s = y / l;
}

/* A body's outward unit normal at surface parameter (eta, omega) angles
 * given by their cos/sin: the gradient of the canonical gauge,
 * (sp(ce, 2-e1) sp(cw, 2-e2) / a, sp(ce, 2-e1) sp(sw, 2-e2) / b, sp(se, 2-e1) / c),
 * mapped by M^-T (the cofactor matrix, up to a positive factor). */
static void body_normal(const mkBody3 *b, double ce, double se, double cw, double sw, double *n)
{
	const mkShape3 *sh = &b->shape;
	double r = spow(ce, 2.0 - sh->eps1);
	double g[3] = {r * spow(cw, 2.0 - sh->eps2) / sh->a, r * spow(sw, 2.0 - sh->eps2) / sh->b,
		spow(se, 2.0 - sh->eps1) / sh->c};
	mkMat3 C = mkMat3_Transpose(mkMat3_Inverse(b->M));
	for (int i = 0; i < 3; ++i) n[i] = C.m[i][0] * g[0] + C.m[i][1] * g[1] + C.m[i][2] * g[2];
	unit3(n);
}

static mkResult grid_volume(const Prob3 *P, int G, double *vol)
{
	int rows = G + 1, cols = 2 * G;
	double *x = malloc(3 * (size_t)rows * (size_t)cols * sizeof *x);
	if (!x) return MK_ERR_MEMORY;
	const mkBody3 *lb = lead_body(P);
	double ie1 = 1.0 / lb->shape.eps1, ie2 = 1.0 / lb->shape.eps2;
	for (int i = 0; i < rows; ++i) {
		double ce, se;
		spaced_angle(-0.5 * MK_PI + MK_PI * i / G, ie1, &ce, &se);
		for (int j = 0; j < cols; ++j) {
			double cw, sw, n[3];
			spaced_angle(-MK_PI + 2.0 * MK_PI * j / cols, ie2, &cw, &sw);
			body_normal(lb, ce, se, cw, sw, n);
			hk3(P, n, x + 3 * ((size_t)i * cols + j));
		}
	}
	Sum s = {0, 0};
	for (int i = 0; i < G; ++i)
		for (int j = 0; j < cols; ++j) {
			int j1 = (j + 1) % cols;
			const double *a = x + 3 * ((size_t)i * cols + j), *b = x + 3 * ((size_t)i * cols + j1);
			const double *c = x + 3 * ((size_t)(i + 1) * cols + j1), *d = x + 3 * ((size_t)(i + 1) * cols + j);
			double bc[3], cd[3];
			cross3(b, c, bc);
			cross3(c, d, cd);
			sum_add(&s, dot3(a, bc) / 6.0);
			sum_add(&s, dot3(a, cd) / 6.0);
		}
	free(x);
	*vol = fabs(sum_get(&s));
	return MK_OK;
}

static mkResult volume3(const Prob3 *P, double *vol, double *bound)
{
	double v0, v1, v2;
	mkResult r = grid_volume(P, VOLUME_G / 2, &v0);
	if (r == MK_OK) r = grid_volume(P, VOLUME_G, &v1);
	if (r == MK_OK) r = grid_volume(P, 2 * VOLUME_G, &v2);
	if (r != MK_OK) return r;
	double e1 = v1 + (v1 - v0) / 3.0, e2 = v2 + (v2 - v1) / 3.0;
	*vol = e2;
	*bound = fabs(e2 - e1) + 16.0 * UNIT_ROUND * v2;
	return MK_OK;
}

mkResult mkError3_Volume(mkBody3 b1, mkBody3 b2, mkSet set, double *volume, double *bound)
{
	Prob3 P;
	if (!volume || !bound || !prob3_init(&P, b1, b2, set)) return MK_ERR_ARGUMENT;
	return volume3(&P, volume, bound);
}

/* ---- signed distance of a point to K (3D) -------------------------------------------
 * sd(p) = max over unit n of f(n) = <n, p> - h_K(n). Newton on the sphere:
 * with x = x_K(n) and r the tangential part of x - p in a frame (e1, e2) at
 * n, moving n by s1 e1 + s2 e2 changes r by (J + f I) s, J the 2 x 2
 * derivative of x's tangential part (K's radii of curvature, by finite
 * differences). Steps that do not raise f are halved. Every f is a lower
 * bound of sd; the last accepted rise is reported as the estimate of what
 * is left. */
typedef struct Eval3 { double n[3], x[3], f; } Eval3;

static Eval3 eval3(const Prob3 *P, const double *n, const double *p)
{
	Eval3 e;
	memcpy(e.n, n, sizeof e.n);
	double h = hk3(P, n, e.x);
	e.f = dot3(n, p) - h;
	return e;
}

static void move3(const double *n, const double *e1, const double *e2, double s1, double s2, double *out)
{
	for (int i = 0; i < 3; ++i) out[i] = n[i] + s1 * e1[i] + s2 * e2[i];
	unit3(out);
}

/* A lower bound of g = h_{K-p} over the spherical triangle with unit corners
 * n[0..2], from the support points y[i] = x_K(n[i]) - p: on the flat
 * triangle, g(w) >= max_i <y_i, w> (the tangent planes of the convex g), a
 * piecewise-linear function whose minimum over the triangle is at a
 * corner, where two pieces cross on an edge, or where all three meet; and
 * a unit direction is w / |w| with mu <= |w| <= 1 (mu as in tri_bound). */
static double sph_lower(double n[3][3], double y[3][3])
{
	double A[3][3]; /* A[i][j] = <y_i, n_j> */
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) A[i][j] = dot3(y[i], n[j]);
	double lb = HUGE_VAL;
	for (int j = 0; j < 3; ++j) lb = fmin(lb, fmax(A[0][j], fmax(A[1][j], A[2][j])));
	for (int j = 0; j < 3; ++j) {
		int k = (j + 1) % 3;
		for (int i = 0; i < 3; ++i)
			for (int l = i + 1; l < 3; ++l) {
				double dj = A[i][j] - A[l][j], dk = A[i][k] - A[l][k];
				if (dj == dk) continue;
				double t = dj / (dj - dk);
				if (!(t > 0 && t < 1)) continue;
				double v = -HUGE_VAL;
				for (int m = 0; m < 3; ++m) v = fmax(v, (1 - t) * A[m][j] + t * A[m][k]);
				lb = fmin(lb, v);
			}
	}
	/* All three equal: with l2 = 1 - l0 - l1, row i is (A[i][0] - A[i][2]) l0
	 * + (A[i][1] - A[i][2]) l1 + A[i][2]; rows 0 and 1 minus row 2 give a
	 * 2 x 2 system (Cramer). */
	double m00 = (A[0][0] - A[0][2]) - (A[2][0] - A[2][2]), m01 = (A[0][1] - A[0][2]) - (A[2][1] - A[2][2]);
	double m10 = (A[1][0] - A[1][2]) - (A[2][0] - A[2][2]), m11 = (A[1][1] - A[1][2]) - (A[2][1] - A[2][2]);
	double det = m00 * m11 - m01 * m10;
	if (det != 0) {
		double c0 = -(A[0][2] - A[2][2]), c1 = -(A[1][2] - A[2][2]);
		double l0 = (c0 * m11 - m01 * c1) / det, l1 = (m00 * c1 - c0 * m10) / det, l2 = 1 - l0 - l1;
		if (l0 >= 0 && l1 >= 0 && l2 >= 0) {
			double v = -HUGE_VAL;
			for (int m = 0; m < 3; ++m) v = fmax(v, A[m][0] * l0 + A[m][1] * l1 + A[m][2] * l2);
			lb = fmin(lb, v);
		}
	}
	if (lb >= 0) return lb;
	double c[3] = {n[0][0] + n[1][0] + n[2][0], n[0][1] + n[1][1] + n[2][1], n[0][2] + n[1][2] + n[2][2]};
	if (!unit3(c)) return -HUGE_VAL;
	double mu = fmin(dot3(n[0], c), fmin(dot3(n[1], c), dot3(n[2], c)));
	return mu > 0 ? lb / mu : -HUGE_VAL;
}

typedef struct STri { double n[3][3], y[3][3]; int depth; } STri;

#define SD_BUDGET 1500

/* Branch and bound for min g over a hexagon of spherical triangles of
 * radius rho around n0: *best receives the smallest g found (attained, with
 * its direction in nbest), the return value a lower bound of g over the
 * hexagon. */
static double sd_branch(const Prob3 *P, const double *n0, double rho, const double *p, double *best, double *nbest)
{
	STri stack[4 * 64 + 16];
	int sp = 0;
	long evals = 0;
	double e1[3], e2[3], ring[6][3], yr[6][3], yc[3], x[3];
	frame3(n0, e1, e2);
	double g0 = hk3(P, n0, x);
	for (int i = 0; i < 3; ++i) yc[i] = x[i] - p[i];
	g0 -= dot3(n0, p);
	if (g0 < *best) *best = g0, memcpy(nbest, n0, 3 * sizeof *n0);
	for (int k = 0; k < 6; ++k) {
		move3(n0, e1, e2, rho * cos(MK_PI * k / 3), rho * sin(MK_PI * k / 3), ring[k]);
		double g = hk3(P, ring[k], x) - dot3(ring[k], p);
		for (int i = 0; i < 3; ++i) yr[k][i] = x[i] - p[i];
		if (g < *best) *best = g, memcpy(nbest, ring[k], 3 * sizeof *n0);
	}
	for (int k = 0; k < 6; ++k) {
		STri t;
		memcpy(t.n[0], n0, 3 * sizeof *n0), memcpy(t.y[0], yc, sizeof yc);
		memcpy(t.n[1], ring[k], sizeof ring[k]), memcpy(t.y[1], yr[k], sizeof yr[k]);
		memcpy(t.n[2], ring[(k + 1) % 6], sizeof ring[k]), memcpy(t.y[2], yr[(k + 1) % 6], sizeof yr[k]);
		t.depth = 0;
		stack[sp++] = t;
	}
	double low = HUGE_VAL;
	while (sp > 0) {
		STri t = stack[--sp];
		double lb = sph_lower(t.n, t.y), tol = fmax(1e-3 * fabs(*best), P->round);
		if (lb >= *best - tol || evals >= SD_BUDGET || t.depth >= 60 || sp + 4 > (int)(sizeof stack / sizeof *stack)) {
			low = fmin(low, lb);
			continue;
		}
		double m[3][3], ym[3][3];
		for (int k = 0; k < 3; ++k) {
			const double *a = t.n[k], *b = t.n[(k + 1) % 3];
			for (int i = 0; i < 3; ++i) m[k][i] = a[i] + b[i];
			unit3(m[k]);
			double g = hk3(P, m[k], x) - dot3(m[k], p);
			for (int i = 0; i < 3; ++i) ym[k][i] = x[i] - p[i];
			if (g < *best) *best = g, memcpy(nbest, m[k], sizeof m[k]);
		}
		evals += 3;
		/* Children: (n0, m0, m2), (m0, n1, m1), (m2, m1, n2), (m0, m1, m2). */
		const double *cn[4][3] = {{t.n[0], m[0], m[2]}, {m[0], t.n[1], m[1]}, {m[2], m[1], t.n[2]}, {m[0], m[1], m[2]}};
		const double *cy[4][3] = {{t.y[0], ym[0], ym[2]}, {ym[0], t.y[1], ym[1]}, {ym[2], ym[1], t.y[2]}, {ym[0], ym[1], ym[2]}};
		for (int c = 0; c < 4; ++c) {
			STri u;
			for (int k = 0; k < 3; ++k) {
				memcpy(u.n[k], cn[c][k], 3 * sizeof(double));
				memcpy(u.y[k], cy[c][k], 3 * sizeof(double));
			}
			u.depth = t.depth + 1;
			stack[sp++] = u;
		}
	}
	return fmin(low, *best);
}

/* The lead body's outward unit normal (world) where the ray of canonical direction
 * v meets its surface: the gradient of the implicit function Psi there,
 * which depends only on v's direction (Psi is homogeneous), mapped by M^-T.
 * In this parameter the normal is smooth across the flat faces of a boxy
 * body (exponents 2/eps - 1 > 1), where the support map in n is not. */
static void ray_normal(const Prob3 *P, const mkMat3 *MinvT, const double *v, double *n)
{
	const mkShape3 *sh = &lead_body(P)->shape;
	double s0 = v[0] / sh->a, s1 = v[1] / sh->b, s2 = v[2] / sh->c;
	double big = fmax(fabs(s0), fmax(fabs(s1), fabs(s2)));
	s0 /= big, s1 /= big, s2 /= big;
	double A = pow(fabs(s0), 2.0 / sh->eps2) + pow(fabs(s1), 2.0 / sh->eps2);
	double f = A > 0 ? pow(A, sh->eps2 / sh->eps1 - 1.0) : 0.0;
	double g[3] = {A > 0 ? f * spow(s0, 2.0 / sh->eps2 - 1.0) / sh->a : 0.0,
		A > 0 ? f * spow(s1, 2.0 / sh->eps2 - 1.0) / sh->b : 0.0, spow(s2, 2.0 / sh->eps1 - 1.0) / sh->c};
	for (int i = 0; i < 3; ++i) n[i] = MinvT->m[i][0] * g[0] + MinvT->m[i][1] * g[1] + MinvT->m[i][2] * g[2];
	unit3(n);
}

/* f as a function of the lead body's canonical ray direction v. */
static double ray_f(const Prob3 *P, const mkMat3 *MinvT, const double *v, const double *p, Eval3 *e)
{
	double n[3];
	ray_normal(P, MinvT, v, n);
	*e = eval3(P, n, p);
	return e->f;
}

/* Newton in the ray parameter, with a finite-difference gradient and
 * Hessian on the tangent plane of v (6 evaluations a step); steps that do
 * not raise f are halved. Raises *e when it finds a larger f. */
static void ray_newton(const Prob3 *P, const double *p, Eval3 *e)
{
	const mkBody3 *lb = lead_body(P);
	mkMat3 MinvT = mkMat3_Transpose(mkMat3_Inverse(lb->M));
	double xc[3], m[3], v[3];
	const double(*M)[3] = lb->M.m;
	for (int j = 0; j < 3; ++j) m[j] = M[0][j] * e->n[0] + M[1][j] * e->n[1] + M[2][j] * e->n[2];
	canon3(lb->shape, m[0], m[1], m[2], xc);
	memcpy(v, xc, sizeof v);
	if (!unit3(v)) return;
	Eval3 cur;
	double fc = ray_f(P, &MinvT, v, p, &cur), h = 1e-5;
	for (int it = 0; it < 30; ++it) {
		double e1[3], e2[3], w[3], F[3][3];
		frame3(v, e1, e2);
		Eval3 tmp;
		for (int a = -1; a <= 1; ++a)
			for (int b = -1; b <= 1; ++b) {
				if (a == 0 && b == 0) {
					F[1][1] = fc;
					continue;
				}
				if (a * b == -1) continue;
				move3(v, e1, e2, a * h, b * h, w);
				F[a + 1][b + 1] = ray_f(P, &MinvT, w, p, &tmp);
			}
		double ga = (F[2][1] - F[0][1]) / (2 * h), gb = (F[1][2] - F[1][0]) / (2 * h);
		double haa = (F[2][1] - 2 * fc + F[0][1]) / (h * h), hbb = (F[1][2] - 2 * fc + F[1][0]) / (h * h);
		double hab = (F[2][2] - F[2][1] - F[1][2] + 2 * fc - F[0][1] - F[1][0] + F[0][0]) / (2 * h * h);
		double det = haa * hbb - hab * hab, sa, sb;
		if (haa < 0 && det > 0) {
			sa = -(hbb * ga - hab * gb) / det;
			sb = -(-hab * ga + haa * gb) / det;
		} else {
			double gn = hypot(ga, gb);
			if (!(gn > 0)) break;
			sa = 1e-3 * ga / gn;
			sb = 1e-3 * gb / gn;
		}
		double len = hypot(sa, sb);
		if (len > 0.1) sa *= 0.1 / len, sb *= 0.1 / len, len = 0.1;
		int moved = 0;
		for (int k = 0; k < 40 && len > 1e-16; ++k) {
			move3(v, e1, e2, sa, sb, w);
			Eval3 t;
			double ft = ray_f(P, &MinvT, w, p, &t);
			if (ft > fc) {
				memcpy(v, w, sizeof v);
				fc = ft;
				cur = t;
				moved = 1;
				break;
			}
			sa *= 0.5, sb *= 0.5, len *= 0.5;
		}
		if (!moved) break;
		h = fmin(1e-5, fmax(1e-7, len));
	}
	if (cur.f > e->f) *e = cur;
}

static void signed_distance3(const Prob3 *P, const double *start, const double *p, double *sd, double *left)
{
	Eval3 e = eval3(P, start, p);
	double last = HUGE_VAL, step = 1e-3;
	for (int it = 0; it < 40; ++it) {
		double e1[3], e2[3], n1[3], n2[3];
		frame3(e.n, e1, e2);
		double r[2] = {0, 0};
		for (int i = 0; i < 3; ++i) {
			r[0] += (e.x[i] - p[i]) * e1[i];
			r[1] += (e.x[i] - p[i]) * e2[i];
		}
		/* Finite-difference step: small enough that x stays on the same
		 * smooth patch even where the radii of curvature are large (the
		 * faces of boxy bodies), large enough that rounding (u |x| / dl)
		 * stays far below the derivative. */
		double dl = fmin(1e-7, fmax(1e-10, step));
		move3(e.n, e1, e2, dl, 0, n1);
		move3(e.n, e1, e2, 0, dl, n2);
		double x1[3], x2[3];
		hk3(P, n1, x1);
		hk3(P, n2, x2);
		double J[2][2];
		for (int i = 0; i < 2; ++i) {
			const double *ei = i == 0 ? e1 : e2;
			J[i][0] = ((x1[0] - e.x[0]) * ei[0] + (x1[1] - e.x[1]) * ei[1] + (x1[2] - e.x[2]) * ei[2]) / dl;
			J[i][1] = ((x2[0] - e.x[0]) * ei[0] + (x2[1] - e.x[1]) * ei[1] + (x2[2] - e.x[2]) * ei[2]) / dl;
		}
		/* (J + f I), symmetrised, kept positive: near a sharp edge or
		 * corner J is nearly 0 and the step is then limited below. */
		double lam = 1e-12 * P->R;
		double a = fmax(J[0][0] + e.f, lam), d = fmax(J[1][1] + e.f, lam), b = 0.5 * (J[0][1] + J[1][0]);
		double det = a * d - b * b;
		double s1, s2;
		if (det > 0) {
			s1 = -(d * r[0] - b * r[1]) / det;
			s2 = -(-b * r[0] + a * r[1]) / det;
		} else {
			s1 = -r[0] / a;
			s2 = -r[1] / d;
		}
		double len = hypot(s1, s2);
		if (len > 0.5) s1 *= 0.5 / len, s2 *= 0.5 / len, len = 0.5;
		if (!(len > 1e-15)) break;
		/* The rise the quadratic model predicts for this step, (r . s) / 2:
		 * below a thousandth of the rounding allowance no step can raise f
		 * visibly (the line search would only halve into rounding noise).
		 * Where the model is wrong (near a flat face) the residual test
		 * below still hands the point on. */
		double rise = 0.5 * fabs(r[0] * s1 + r[1] * s2);
		if (rise <= P->round * 1e-3) {
			last = rise;
			break;
		}
		int moved = 0;
		for (int h = 0; h < 30; ++h) {
			double nn[3];
			move3(e.n, e1, e2, s1, s2, nn);
			Eval3 t = eval3(P, nn, p);
			if (t.f > e.f) {
				last = t.f - e.f;
				e = t;
				moved = 1;
				break;
			}
			s1 *= 0.5;
			s2 *= 0.5;
			len *= 0.5;
			if (len < 1e-15) break;
		}
		step = len;
		if (!moved) {
			last = 0;
			break;
		}
		if (last <= P->round * 1e-3) break;
	}
	*sd = e.f;
	*left = last == HUGE_VAL ? 0.0 : last;
	/* Newton stalls where the support map is not differentiable (the axis
	 * normals of a boxy body). At the maximiser the tangential part of
	 * x_K(n) - p vanishes; where it does not, Newton is run again in the
	 * lead body's ray parameter (smooth there), and if that does not settle it
	 * either, branch and bound on spherical triangles (sph_lower) takes over
	 * around the best direction, recentred while the best direction lies
	 * near the hexagon's rim. */
	double e1[3], e2[3], r0 = 0, r1 = 0;
	frame3(e.n, e1, e2);
	for (int i = 0; i < 3; ++i) {
		r0 += (e.x[i] - p[i]) * e1[i];
		r1 += (e.x[i] - p[i]) * e2[i];
	}
	if (hypot(r0, r1) > 1e-7 * P->R) {
		double f0 = e.f;
		ray_newton(P, p, &e);
		if (e.f > f0) {
			*sd = e.f;
			*left = fmax(*left, e.f - f0);
		}
	}
	r0 = r1 = 0;
	frame3(e.n, e1, e2);
	for (int i = 0; i < 3; ++i) {
		r0 += (e.x[i] - p[i]) * e1[i];
		r1 += (e.x[i] - p[i]) * e2[i];
	}
	if (hypot(r0, r1) > 1e-7 * P->R) {
		double best = -e.f, nb[3], n0[3], rho = 0.02, low = -HUGE_VAL;
		memcpy(nb, e.n, sizeof nb);
		for (int round = 0; round < 4; ++round) {
			memcpy(n0, nb, sizeof n0);
			low = sd_branch(P, n0, rho, p, &best, nb);
			if (dot3(nb, n0) > cos(0.6 * rho)) break;
		}
		*sd = -best;
		*left = fmax(0.0, best - low);
	}
}

/* ---- gap_in in 3D ---------------------------------------------------------------------
 * The normal cone of vertex v of P is spanned by the unit normals of its
 * facets; h_K - h_P = h_{K-v} there. For a spherical triangle of that cone
 * with corners A, B, C, a unit direction in it is w / |w| with w in the flat
 * triangle ABC and |w| >= <w, c> >= min(<A,c>, <B,c>, <C,c>) =: mu for the
 * unit c along A + B + C; by convexity h_{K-v}(w) <= max of the corner values,
 * so the triangle's maximum is at most max(corners, 0) / mu. The whole cone
 * (corners in any order) has the same bound with c along the sum of its
 * facet normals. Cones whose bound is above the level are fanned from c into
 * triangles and subdivided four ways. */
typedef struct Tri3 { double a[3], b[3], c[3], fa, fb, fc; int depth; } Tri3;

static double tri_bound(const Tri3 *t)
{
	double c[3] = {t->a[0] + t->b[0] + t->c[0], t->a[1] + t->b[1] + t->c[1], t->a[2] + t->b[2] + t->c[2]};
	if (!unit3(c)) return HUGE_VAL;
	double mu = fmin(dot3(t->a, c), fmin(dot3(t->b, c), dot3(t->c, c)));
	if (!(mu > 0)) return HUGE_VAL;
	return fmax(fmax(t->fa, t->fb), fmax(t->fc, 0.0)) / mu;
}

static double phi3(const Prob3 *P, const double *n, const double *v)
{
	double x[3];
	return hk3(P, n, x) - dot3(n, v);
}

/* Refine the cone of vertex v (facet normals nf[0..k-1], in any order):
 * returns the largest bound left, raises *best with the values found. */
static double refine_cone(const Prob3 *P, const double *v, const double *nrm, const double *H, const int *fs, int k,
	double gap_out, double tol, double *best, long *evals, Tri3 *stack, int scap)
{
	double c[3] = {0, 0, 0};
	for (int i = 0; i < k; ++i)
		for (int j = 0; j < 3; ++j) c[j] += nrm[3 * fs[i] + j];
	if (!unit3(c)) return HUGE_VAL;
	/* Order the facet normals by angle around c. */
	double e1[3], e2[3];
	frame3(c, e1, e2);
	int order_s[64], *order = k <= 64 ? order_s : malloc((size_t)k * sizeof *order);
	double ang_s[64], *ang = k <= 64 ? ang_s : malloc((size_t)k * sizeof *ang);
	if (!order || !ang) {
		if (order != order_s) free(order);
		if (ang != ang_s) free(ang);
		return HUGE_VAL;
	}
	for (int i = 0; i < k; ++i) {
		const double *f = nrm + 3 * fs[i];
		ang[i] = atan2(dot3(f, e2), dot3(f, e1));
		order[i] = i;
	}
	for (int i = 1; i < k; ++i) /* insertion sort: k is small */
		for (int j = i; j > 0 && ang[order[j]] < ang[order[j - 1]]; --j) {
			int t = order[j];
			order[j] = order[j - 1];
			order[j - 1] = t;
		}
	double fc = phi3(P, c, v);
	++*evals;
	*best = fmax(*best, fc);
	double top = -HUGE_VAL;
	for (int i = 0; i < k; ++i) {
		int fa = fs[order[i]], fb = fs[order[(i + 1) % k]];
		int sp = 0;
		Tri3 t;
		memcpy(t.a, c, sizeof t.a);
		memcpy(t.b, nrm + 3 * fa, sizeof t.b);
		memcpy(t.c, nrm + 3 * fb, sizeof t.c);
		t.fa = fc;
		t.fb = H[fa] - dot3(nrm + 3 * fa, v);
		t.fc = H[fb] - dot3(nrm + 3 * fb, v);
		t.depth = 0;
		stack[sp++] = t;
		while (sp > 0) {
			Tri3 q = stack[--sp];
			double level = fmax(*best, gap_out);
			double ub = tri_bound(&q), need = level + tol * fabs(level) + P->round;
			if (ub <= need || *evals >= EVAL_BUDGET || q.depth >= 40 || sp + 4 > scap) {
				top = fmax(top, ub);
				continue;
			}
			double ab[3], bc[3], ca[3];
			for (int j = 0; j < 3; ++j) {
				ab[j] = q.a[j] + q.b[j];
				bc[j] = q.b[j] + q.c[j];
				ca[j] = q.c[j] + q.a[j];
			}
			unit3(ab);
			unit3(bc);
			unit3(ca);
			double fab = phi3(P, ab, v), fbc = phi3(P, bc, v), fca = phi3(P, ca, v);
			*evals += 3;
			*best = fmax(*best, fmax(fab, fmax(fbc, fca)));
			Tri3 s[4];
			memcpy(s[0].a, q.a, sizeof q.a), memcpy(s[0].b, ab, sizeof ab), memcpy(s[0].c, ca, sizeof ca);
			s[0].fa = q.fa, s[0].fb = fab, s[0].fc = fca;
			memcpy(s[1].a, ab, sizeof ab), memcpy(s[1].b, q.b, sizeof q.b), memcpy(s[1].c, bc, sizeof bc);
			s[1].fa = fab, s[1].fb = q.fb, s[1].fc = fbc;
			memcpy(s[2].a, ca, sizeof ca), memcpy(s[2].b, bc, sizeof bc), memcpy(s[2].c, q.c, sizeof q.c);
			s[2].fa = fca, s[2].fb = fbc, s[2].fc = q.fc;
			memcpy(s[3].a, ab, sizeof ab), memcpy(s[3].b, bc, sizeof bc), memcpy(s[3].c, ca, sizeof ca);
			s[3].fa = fab, s[3].fb = fbc, s[3].fc = fca;
			for (int j = 0; j < 4; ++j) {
				s[j].depth = q.depth + 1;
				stack[sp++] = s[j];
			}
		}
	}
	if (order != order_s) free(order);
	if (ang != ang_s) free(ang);
	return top;
}

/* Points with their index, in lexicographic order (for matching the input
 * points to hull vertices; no global state, so the measure is reentrant). */
typedef struct Keyed { double c[3]; int i; } Keyed;

static int cmp_coords(const double *p, const double *q)
{
	for (int i = 0; i < 3; ++i)
		if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
	return 0;
}

static int cmp_keyed(const void *a, const void *b)
{
	return cmp_coords(((const Keyed *)a)->c, ((const Keyed *)b)->c);
}

static Keyed *sorted_points(const double *xyz, int n)
{
	Keyed *k = malloc((size_t)(n > 0 ? n : 1) * sizeof *k);
	if (!k) return NULL;
	for (int i = 0; i < n; ++i) {
		memcpy(k[i].c, xyz + 3 * i, sizeof k[i].c);
		k[i].i = i;
	}
	qsort(k, (size_t)n, sizeof *k, cmp_keyed);
	return k;
}

static int cmp_tri(const void *a, const void *b)
{
	const int *p = a, *q = b;
	for (int i = 0; i < 3; ++i)
		if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
	return 0;
}

/* Put the hull in an order that depends only on the point set. The hull
 * comes canonical already (mkCgalHull3_Mesh: sorted vertices, each planar
 * face fanned from its smallest corner, sorted triangles); this sorts it
 * once more, so that the measure does not rest on that alone, and drops
 * the vertices CGAL kept on an edge or inside a planar face: they belong to
 * no triangle, so their normal cones would be empty, and whether CGAL keeps
 * such a point can follow its build order. *nv is updated. */
static mkResult canonical_hull(double *V, int *nv, int *T, int nt)
{
	int n = *nv;
	Keyed *hs = sorted_points(V, n);
	int *to = malloc((size_t)(n > 0 ? n : 1) * sizeof *to);
	if (!hs || !to) {
		free(hs);
		free(to);
		return MK_ERR_MEMORY;
	}
	for (int v = 0; v < n; ++v) to[hs[v].i] = -1;
	for (int j = 0; j < 3 * nt; ++j) to[T[j]] = 0; /* used */
	int m = 0;
	for (int v = 0; v < n; ++v) /* in coordinate order */
		if (to[hs[v].i] == 0) {
			to[hs[v].i] = m;
			memcpy(V + 3 * m++, hs[v].c, sizeof hs[v].c);
		}
	for (int f = 0; f < nt; ++f) {
		int *t = T + 3 * f, a = to[t[0]], b = to[t[1]], c = to[t[2]];
		if (a < b && a < c) t[0] = a, t[1] = b, t[2] = c;
		else if (b < c) t[0] = b, t[1] = c, t[2] = a;
		else t[0] = c, t[1] = a, t[2] = b;
	}
	qsort(T, (size_t)nt, 3 * sizeof *T, cmp_tri);
	*nv = m;
	free(hs);
	free(to);
	return MK_OK;
}

#define TABLE3 2048

mkResult mkError3_Measure(mkBody3 b1, mkBody3 b2, mkSet set, const mkPointSet *pts, const mkErrorOptions *opt,
	mkError *out)
{
	Prob3 P;
	if (!pts || !out || pts->dim != 3 || pts->count < 0 || (pts->count > 0 && (!pts->x || !pts->y || !pts->z)))
		return MK_ERR_ARGUMENT;
	if (!prob3_init(&P, b1, b2, set)) return MK_ERR_ARGUMENT;
	double tol = opt && opt->tol > 0 ? opt->tol : TOL_DEFAULT;
	error_init(out, pts->count, P.S);
	int n = pts->count, nf = 0;
	size_t n1 = (size_t)(n > 0 ? n : 1);
	double *xyz = malloc(3 * n1 * sizeof *xyz), *V = NULL, *nrm = NULL, *H = NULL, *tab = NULL;
	int *idx = malloc(n1 * sizeof *idx), *T = NULL, *vstart = NULL, *vfac = NULL, *pv = NULL, *vi = NULL;
	Tri3 *stack = NULL;
	int nv = 0, nt = 0;
	mkResult r = xyz && idx ? MK_OK : MK_ERR_MEMORY;
	if (r == MK_OK)
		for (int k = 0; k < n; ++k) {
			double p[3] = {pts->x[k] - P.o[0], pts->y[k] - P.o[1], pts->z[k] - P.o[2]};
			if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) {
				++out->nonfinite;
				continue;
			}
			memcpy(xyz + 3 * nf, p, sizeof p);
			idx[nf++] = k;
		}
	if (r == MK_OK && nf > 1) {
		/* The points in coordinate order: the hull (and with it every
		 * figure, to the last bit) is then a function of the point set,
		 * not of the order the method returned it in. */
		Keyed *ks = sorted_points(xyz, nf);
		int *was = malloc(n1 * sizeof *was);
		if (!ks || !was) r = MK_ERR_MEMORY;
		else {
			memcpy(was, idx, (size_t)nf * sizeof *idx);
			for (int k = 0; k < nf; ++k) {
				memcpy(xyz + 3 * k, ks[k].c, sizeof ks[k].c);
				idx[k] = was[ks[k].i];
			}
		}
		free(ks);
		free(was);
	}
	if (r == MK_OK && !take_truth(opt, out))
		r = volume3(&P, &out->area_k, &out->area_bound);
	if (r == MK_OK && nf == 0) {
		no_points(out, "volume");
		goto done;
	}
	if (r != MK_OK) goto done;
	int flat = 0;
	int hc = mkCgalHull3_Mesh(xyz, nf, &V, &nv, &T, &nt);
	if (hc == -1) r = MK_ERR_MEMORY;
	else if (hc == -2) flat = 1;
	else if (hc != 0) r = MK_ERR_UNSUPPORTED;
	if (r == MK_OK && !flat) r = canonical_hull(V, &nv, T, nt);
	if (r != MK_OK) goto done;
	/* A table of directions (Fibonacci sphere): starts for points that are
	 * not hull vertices, and gap_in when the points span no volume. */
	tab = malloc(7 * (size_t)TABLE3 * sizeof *tab);
	pv = malloc(n1 * sizeof *pv);
	if (!tab || !pv) {
		r = MK_ERR_MEMORY;
		goto done;
	}
	for (int j = 0; j < TABLE3; ++j) {
		double *d = tab + 7 * j, z = 1.0 - (2.0 * j + 1.0) / TABLE3, rho = sqrt(1.0 - z * z);
		double a = MK_PI * (3.0 - sqrt(5.0)) * j;
		d[0] = rho * cos(a), d[1] = rho * sin(a), d[2] = z;
		d[6] = hk3(&P, d, d + 3);
	}
	/* Facets: unit outward normals and h_K there; vertex -> facets. */
	if (!flat) {
		nrm = malloc(3 * (size_t)nt * sizeof *nrm);
		H = malloc((size_t)nt * sizeof *H);
		vstart = calloc((size_t)nv + 1, sizeof *vstart);
		vfac = malloc(3 * (size_t)nt * sizeof *vfac);
		vi = malloc((size_t)nv * sizeof *vi);
		if (!nrm || !H || !vstart || !vfac || !vi) {
			r = MK_ERR_MEMORY;
			goto done;
		}
		double best = -HUGE_VAL;
		Sum vol = {0, 0};
		for (int f = 0; f < nt; ++f) {
			const double *a = V + 3 * T[3 * f], *b = V + 3 * T[3 * f + 1], *c = V + 3 * T[3 * f + 2];
			double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
			double *nn = nrm + 3 * f, bc[3];
			cross3(ab, ac, nn);
			unit3(nn);
			cross3(b, c, bc);
			sum_add(&vol, dot3(a, bc) / 6.0);
			double x[3];
			H[f] = hk3(&P, nn, x);
			double hp = fmax(dot3(nn, a), fmax(dot3(nn, b), dot3(nn, c)));
			best = fmax(best, H[f] - hp);
			for (int j = 0; j < 3; ++j) ++vstart[T[3 * f + j] + 1];
		}
		out->area_p = sum_get(&vol);
		for (int v = 0; v < nv; ++v) vstart[v + 1] += vstart[v];
		for (int v = 0; v < nv; ++v) vi[v] = vstart[v];
		for (int f = 0; f < nt; ++f)
			for (int j = 0; j < 3; ++j) vfac[vi[T[3 * f + j]]++] = f;
		out->gap_in = best;
		out->vertices = nv;
		/* Match the points to hull vertices (CGAL keeps input coordinates):
		 * both lists are in coordinate order already (above and
		 * canonical_hull), so one merge pass does it. */
		for (int k = 0; k < nf; ++k) pv[k] = -1;
		for (int i = 0, j = 0; i < nf && j < nv;) {
			int c = cmp_coords(xyz + 3 * i, V + 3 * j);
			if (c == 0) pv[i++] = j;
			else if (c < 0) ++i;
			else ++j;
		}
	} else
		for (int k = 0; k < nf; ++k) pv[k] = -1;
	/* Signed distances of every point. */
	double left = 0;
	for (int k = 0; k < nf; ++k) {
		const double *p = xyz + 3 * k;
		double start[3] = {0, 0, 0};
		int v = pv[k];
		if (v >= 0) {
			for (int i = vstart[v]; i < vstart[v + 1]; ++i)
				for (int j = 0; j < 3; ++j) start[j] += nrm[3 * vfac[i] + j];
		}
		if (v < 0 || !unit3(start)) {
			int bj = 0;
			double bf = -HUGE_VAL;
			for (int j = 0; j < TABLE3; ++j) {
				const double *d = tab + 7 * j;
				double f = dot3(d, p) - d[6];
				if (f > bf) bf = f, bj = j;
			}
			memcpy(start, tab + 7 * bj, sizeof start);
		}
		double sd, lf;
		signed_distance3(&P, start, p, &sd, &lf);
		out->gap_out = fmax(out->gap_out, sd);
		if (fabs(sd) > out->off_boundary_max || out->worst < 0) {
			out->off_boundary_max = fabs(sd);
			out->worst = idx[k];
		}
		left = fmax(left, lf);
	}
	out->off_boundary_bound = left + P.round;
	double hi;
	if (flat) {
		/* No volume: gap_in over the table directions only, h_P by brute
		 * force; no certificate. */
		double best = -HUGE_VAL;
		for (int j = 0; j < TABLE3; ++j) {
			const double *d = tab + 7 * j;
			double hp = -HUGE_VAL;
			for (int k = 0; k < nf; ++k) hp = fmax(hp, dot3(d, xyz + 3 * k));
			best = fmax(best, d[6] - hp);
		}
		out->gap_in = best;
		out->vertices = 0;
		out->area_p = 0;
		hi = HUGE_VAL;
	} else {
		/* Certify gap_in over every vertex cone. */
		int scap = 4 * 40 + 64;
		stack = malloc((size_t)scap * sizeof *stack);
		if (!stack) {
			r = MK_ERR_MEMORY;
			goto done;
		}
		long evals = 0;
		double best = out->gap_in, top = best;
		for (int v = 0; v < nv; ++v) {
			const double *pt = V + 3 * v;
			int k = vstart[v + 1] - vstart[v];
			const int *fs = vfac + vstart[v];
			double c[3] = {0, 0, 0}, fmaxv = -HUGE_VAL;
			for (int i = 0; i < k; ++i) {
				for (int j = 0; j < 3; ++j) c[j] += nrm[3 * fs[i] + j];
				fmaxv = fmax(fmaxv, H[fs[i]] - dot3(nrm + 3 * fs[i], pt));
			}
			double ub = HUGE_VAL;
			if (unit3(c)) {
				double mu = HUGE_VAL;
				for (int i = 0; i < k; ++i) mu = fmin(mu, dot3(nrm + 3 * fs[i], c));
				if (mu > 0) ub = fmax(fmaxv, 0.0) / mu;
			}
			double level = fmax(best, out->gap_out);
			if (ub > level + tol * fabs(level) + P.round)
				ub = refine_cone(&P, pt, nrm, H, fs, k, out->gap_out, tol, &best, &evals, stack, scap);
			top = fmax(top, ub);
		}
		out->gap_in = best;
		hi = fmax(top, best);
	}
	out->hausdorff_abs = fmax(out->gap_in, out->gap_out);
	out->hausdorff_bound = fmax(hi, out->gap_out + out->off_boundary_bound) - out->hausdorff_abs + P.round;
	out->area_rel = (out->area_p - out->area_k) / out->area_k;
	out->area_bound = (out->area_bound + 16.0 * UNIT_ROUND * out->area_p) / out->area_k
		+ 4.0 * UNIT_ROUND * fabs(out->area_rel);
	finish(out, "volume");
done:
	free(xyz);
	free(idx);
	free(V);
	free(T);
	free(nrm);
	free(H);
	free(tab);
	free(vstart);
	free(vfac);
	free(vi);
	free(pv);
	free(stack);
	return r;
}
