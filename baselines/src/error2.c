/* error2.c - the error measure in 2D (mink/error.h): the area of K, gap_in
 * over the normal cones of P's vertices, the points' signed distances to K,
 * and mkDeviation2_Measure, which puts them together. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/error.h>

#include "error_internal.h"
#include "referee_cgal.h"

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

static mkResult area2(const mkDevProb2 *P, double *area, double *bound)
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
		mkDev_Hk2(P, r[1], r[2], r + 3);
	}
	double a_in = 0, tri = 0;
	for (int pass = 0;; ++pass) {
		free(tri_i);
		tri_i = malloc((size_t)m * sizeof *tri_i);
		if (!tri_i) {
			free(t);
			return MK_ERR_MEMORY;
		}
		mkDevSum sa = {0, 0}, st = {0, 0};
		for (int i = 0; i < m; ++i) {
			const double *p = t + 5 * i, *q = t + 5 * ((i + 1) % m);
			mkDevSum_Add(&sa, 0.5 * (p[3] * q[4] - p[4] * q[3]));
			double d0 = q[3] - p[3], d1 = q[4] - p[4];
			double g0 = -(p[1] * d0 + p[2] * d1), g1 = q[1] * d0 + q[2] * d1;
			double sn = p[1] * q[2] - p[2] * q[1]; /* sin of the angle step */
			double T = fmax(g0, 0.0) * fmax(g1, 0.0) / (2.0 * sn);
			tri_i[i] = T;
			mkDevSum_Add(&st, T);
		}
		a_in = mkDevSum_Get(&sa);
		tri = mkDevSum_Get(&st);
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
				mkDev_Hk2(P, r[1], r[2], r + 3);
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

mkResult mkDeviation2_Area(mkBody2 b1, mkBody2 b2, mkSet set, double *area, double *bound)
{
	mkDevProb2 P;
	if (!area || !bound || !mkDev_Prob2Init(&P, b1, b2, set)) return MK_ERR_ARGUMENT;
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

static double phi2(const mkDevProb2 *P, double t, const double *v)
{
	double c = cos(t), s = sin(t), x[2];
	return mkDev_Hk2(P, c, s, x) - (c * v[0] + s * v[1]);
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
static mkResult gap_in2(const mkDevProb2 *P, const double *Q, int m, double gap_out, double tol, double *lo, double *hi)
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

static void table2_init(const mkDevProb2 *P, Table2 *T)
{
	for (int j = 0; j < TABLE2; ++j) {
		T->t[j] = -MK_PI + 2.0 * MK_PI * j / TABLE2;
		T->c[j] = cos(T->t[j]);
		T->s[j] = sin(T->t[j]);
		T->h[j] = mkDev_Hk2(P, T->c[j], T->s[j], T->x + 2 * j);
		double b = atan2(T->x[2 * j + 1], T->x[2 * j]);
		if (j > 0)
			while (b < T->beta[j - 1]) b += 2 * MK_PI;
		T->beta[j] = b;
	}
}

typedef struct Eval2 { double t, c, s, f, d, x[2]; } Eval2;

static Eval2 eval2(const mkDevProb2 *P, double t, const double *p)
{
	Eval2 e;
	double c = cos(t), s = sin(t);
	e.t = t;
	e.c = c;
	e.s = s;
	double h = mkDev_Hk2(P, c, s, e.x);
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

static void signed_distance2(const mkDevProb2 *P, const Table2 *T, const double *p, double *sd, double *ub)
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
	mkDevSum s = {0, 0};
	for (int k = 0; k < m; ++k) {
		const double *a = Q + 2 * k, *b = Q + 2 * ((k + 1) % m);
		mkDevSum_Add(&s, 0.5 * (a[0] * b[1] - a[1] * b[0]));
	}
	return mkDevSum_Get(&s);
}

mkResult mkDeviation2_Measure(mkBody2 b1, mkBody2 b2, mkSet set, const mkPointSet *pts, const mkDeviationOptions *opt,
	mkDeviation *out)
{
	mkDevProb2 P;
	if (!pts || !out || pts->dim != 2 || pts->count < 0 || (pts->count > 0 && (!pts->x || !pts->y)))
		return MK_ERR_ARGUMENT;
	if (!mkDev_Prob2Init(&P, b1, b2, set)) return MK_ERR_ARGUMENT;
	double tol = opt && opt->tol > 0 ? opt->tol : TOL_DEFAULT;
	mkDev_Init(out, pts->count, P.S);
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
	if (r == MK_OK && !mkDev_TakeTruth(opt, out))
		r = area2(&P, &out->area_k, &out->area_bound);
	if (r == MK_OK && nf == 0) {
		mkDev_NoPoints(out, "area");
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
				mkDev_Finish(out, "area");
			}
		}
	}
	free(xy);
	free(Q);
	free(idx);
	free(T);
	return r;
}

