/* boundary2.c - 2D C-obstacle boundaries from fixed normals (uniform or
 * given) and the certificate of one arc between consecutive normals
 * (Proofs 1-3 of docs/scene.md), which the adaptive walk (walk2.c) uses too;
 * the single-boundary 2D functions of mink/cobstacle.h. */
#include "cspace/work.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/geom_inline.h"

static double mkDistSegment2(mkVec2 v, mkVec2 a, mkVec2 b)
{
	mkVec2 d = mkVec2_Sub(b, a), e = mkVec2_Sub(v, a);
	double dd = mkVec2_Dot(d, d), t = dd > 0.0 ? mkVec2_Dot(e, d) / dd : 0.0;
	if (t < 0.0) t = 0.0;
	if (t > 1.0) t = 1.0;
	return mkVec2_LengthInline(mkVec2_Sub(e, mkVec2_Scale(d, t)));
}

/* The vertex of the tangent lines at (ni, pi) and (nj, pj): pi + s tau_i with
 * tau_i = ni turned by +90 degrees (Proof 2 of docs/scene.md). */
static mkVec2 mkBoundary2_TangentVertex(mkVec2 ni, mkVec2 pi, mkVec2 nj, mkVec2 pj)
{
	mkVec2 tau = {-ni.y, ni.x};
	double s = mkVec2_Dot(nj, mkVec2_Sub(pj, pi)) / mkVec2_Cross(ni, nj);
	return mkVec2_Add(pi, mkVec2_Scale(tau, s));
}

static double mkBoundary2_Size(mkVec2 a) { return fabs(a.x) + fabs(a.y); }


/* The normal at which the chord p_i p_j is split: the chord's outward
 * normal when it lies between the two normals (always, in exact
 * arithmetic), else the bisector. */
mkVec2 mkBoundary2_SplitNormal(mkVec2 ni, mkVec2 nj, mkVec2 pi, mkVec2 pj)
{
	mkVec2 d = mkVec2_Sub(pj, pi);
	mkVec2 m = mkVec2_NormalizeInline(mkVec2_Make(d.y, -d.x));
	if (!(mkVec2_Cross(ni, m) > 0.0 && mkVec2_Cross(m, nj) > 0.0))
		m = mkVec2_NormalizeInline(mkVec2_Add(ni, nj));
	return m;
}

/* The certified error of the arc between consecutive normals ni, nj (points
 * pi, pj), given the split normal m and its point xm = x(m). */
double mkBoundary2_EdgeError(mkBound bound, mkVec2 ni, mkVec2 nj, mkVec2 pi, mkVec2 pj, mkVec2 m, mkVec2 xm)
{
	double rnd = MK_CSPACE_ROUND_REL * (mkBoundary2_Size(pi) + mkBoundary2_Size(pj) + mkBoundary2_Size(xm));
	/* Proof 3: for normals u between ni and nj, h_K(u) minus the
	 * best of <u, pi>, <u, pj> is at most g3 = c / (4 cos(theta/2)) */
	double c = mkVec2_Dot(mkVec2_Sub(ni, nj), mkVec2_Sub(pi, pj));
	c = c > 0.0 ? c : 0.0;
	if (!(mkVec2_Cross(ni, nj) > 0.0)) return INFINITY + rnd; /* 180 degrees or more (or clockwise): nothing certified */
	double other = INFINITY; /* Proof 1 or 2, where it applies */
	if (!(mkVec2_Dot(ni, nj) >= 0.0)) {
		/* a step over 90 degrees: Proof 3 only */
	} else if (bound == MK_BOUND_INNER) {
		/* Proof 1: the chord gap h_K(m) - <m, p>, m the chord normal */
		mkVec2 d = mkVec2_Sub(pj, pi);
		mkVec2 chord = mkVec2_NormalizeInline(mkVec2_Make(d.y, -d.x));
		if (mkVec2_Dot(chord, m) == 1.0 || (chord.x == m.x && chord.y == m.y)) {
			double lo = fmin(mkVec2_Dot(m, pi), mkVec2_Dot(m, pj));
			other = mkVec2_Dot(m, xm) - lo;
			if (other < 0.0) other = 0.0;
		}
	} else {
		/* Proof 2: the tangent vertex's distance to conv{pi, x(m), pj} */
		mkVec2 v = mkBoundary2_TangentVertex(ni, pi, nj, pj);
		other = fmin(mkDistSegment2(v, pi, xm), mkDistSegment2(v, xm, pj));
	}
	/* the smaller of the two; g3 >= c / (4 (1 + 1e-9)) for unit normals, so
	 * g3 is only formed when the other bound might exceed it */
	if (other * (4.0 * (1.0 + 1e-9)) < c) return other + rnd;
	double g3 = c / (4.0 * (0.5 * mkVec2_LengthInline(mkVec2_Add(ni, nj))));
	return (other < g3 ? other : g3) + rnd;
}

static mkVec2 mkWork_Normal2(const mkCSpaceWork *w, int i) { return mkVec2_Make(w->n[0][i], w->n[1][i]); }
static mkVec2 mkWork_Point2(const mkCSpaceWork *w, int i) { return mkVec2_Make(w->p[0][i], w->p[1][i]); }

/* Adaptive (uniform_n == 0 and no given normals: walk2) or fixed normals
 * (uniform_n normals 2 pi k / n, or the given ones), each arc certified
 * by mkBoundary2_EdgeError. Results in w: *count nodes 0 .. count - 1 in
 * counter-clockwise order, w->err2[i] the error of the arc from node i to
 * node i + 1 (mod count). */
mkResult mkBoundary2_Run(mkCSpaceWork *w, mkBody2 b1, mkBody2 b2, mkImpl impl, mkBound bound, double tol, int max_points,
	int uniform_n, const double *given_x, const double *given_y, int *count, double *error)
{
	if (uniform_n == 0 && !given_x) return mkBoundary2_Walk(w, b1, b2, impl, bound, tol, max_points, count, error);
	int K = uniform_n;
	if (!mkCSpaceWork_Verts(w, K, 2) || !mkGrow_Doubles(&w->err2, &w->ecap, K) || !mkCSpaceWork_Batch(w, K, 2))
		return MK_ERR_MEMORY;
	for (int k = 0; k < K; ++k) {
		if (given_x) {
			mkVec2 u = mkVec2_NormalizeInline(mkVec2_Make(given_x[k], given_y[k]));
			w->n[0][k] = u.x; w->n[1][k] = u.y;
		} else {
			mkSinCosExact(2.0 * MK_PI * k / K, &w->n[0][k], &w->n[1][k]);
		}
	}
	mkResult r = mkContact2_Points(b1, b2, impl, w->n[0], w->n[1], K, w->p[0], w->p[1]);
	if (r != MK_OK) return r;
	/* split normals: the chord's outward normal when it lies between the
	 * two normals (always, in exact arithmetic), else the bisector */
	for (int i = 0; i < K; ++i) {
		int j = (i + 1) % K;
		mkVec2 m = mkBoundary2_SplitNormal(mkWork_Normal2(w, i), mkWork_Normal2(w, j), mkWork_Point2(w, i), mkWork_Point2(w, j));
		w->m[0][i] = m.x; w->m[1][i] = m.y;
	}
	r = mkContact2_Points(b1, b2, impl, w->m[0], w->m[1], K, w->q[0], w->q[1]);
	if (r != MK_OK) return r;
	double maxerr = 0.0;
	for (int i = 0; i < K; ++i) {
		int j = (i + 1) % K;
		double err = mkBoundary2_EdgeError(bound, mkWork_Normal2(w, i), mkWork_Normal2(w, j), mkWork_Point2(w, i), mkWork_Point2(w, j), mkVec2_Make(w->m[0][i], w->m[1][i]),
			mkVec2_Make(w->q[0][i], w->q[1][i]));
		if (err > maxerr || err != err) maxerr = err;
		w->err2[i] = err;
	}
	*count = K;
	*error = maxerr;
	return MK_OK;
}

/* Write the boundary of run2 (inner: the points; outer: the tangent
 * vertices) counter-clockwise from node 0 into out (2 arrays). */
void mkBoundary2_Emit(const mkCSpaceWork *w, mkBound bound, int count, double *ox, double *oy)
{
	for (int i = 0; i < count; ++i) {
		int j = (i + 1) % count;
		if (bound == MK_BOUND_INNER) {
			ox[i] = w->p[0][i]; oy[i] = w->p[1][i];
		} else {
			mkVec2 v = mkBoundary2_TangentVertex(mkVec2_Make(w->n[0][i], w->n[1][i]), mkVec2_Make(w->p[0][i], w->p[1][i]),
				mkVec2_Make(w->n[0][j], w->n[1][j]), mkVec2_Make(w->p[0][j], w->p[1][j]));
			ox[i] = v.x; oy[i] = v.y;
		}
	}
}

static mkResult mkBoundary2_Single(mkBody2 b1, mkBody2 b2, mkBound bound, double tol, int max_points, int uniform_n,
	const double *given_x, const double *given_y, mkImpl impl, double **x, double **y, int *cap, int *count, double *error)
{
	if (!x || !y || !cap || !count || !error || (bound != MK_BOUND_INNER && bound != MK_BOUND_OUTER))
		return MK_ERR_ARGUMENT;
	mkCSpaceWork w;
	memset(&w, 0, sizeof w);
	int n = 0;
	double e = 0.0;
	mkResult r = mkBoundary2_Run(&w, b1, b2, impl, bound, tol, max_points, uniform_n, given_x, given_y, &n, &e);
	if (r == MK_OK) {
		int c1 = *cap, c2 = *cap;
		if (!mkGrow_Doubles(x, &c1, n) || !mkGrow_Doubles(y, &c2, n)) r = MK_ERR_MEMORY;
		else {
			*cap = c1 < c2 ? c1 : c2;
			mkBoundary2_Emit(&w, bound, n, *x, *y);
			*count = n;
			*error = e;
		}
	}
	mkCSpaceWork_Free(&w);
	return r;
}

mkResult mkCSpace2_Adaptive(mkBody2 b1, mkBody2 b2, mkBound bound, double tol, int max_points,
	mkImpl impl, double **x, double **y, int *cap, int *count, double *error)
{
	if (!(tol > 0.0) || !isfinite(tol) || max_points < 8) return MK_ERR_ARGUMENT;
	return mkBoundary2_Single(b1, b2, bound, tol, max_points, 0, NULL, NULL, impl, x, y, cap, count, error);
}

mkResult mkCSpace2_Uniform(mkBody2 b1, mkBody2 b2, mkBound bound, int n, mkImpl impl,
	double **x, double **y, int *cap, int *count, double *error)
{
	if (n < 4) return MK_ERR_ARGUMENT;
	return mkBoundary2_Single(b1, b2, bound, 1.0, n, n, NULL, NULL, impl, x, y, cap, count, error);
}

mkResult mkCSpace2_Certify(mkBody2 b1, mkBody2 b2, mkBound bound, const double *nx, const double *ny, int n,
	mkImpl impl, double **x, double **y, int *cap, int *count, double *error)
{
	if (n < 3 || !nx || !ny) return MK_ERR_ARGUMENT;
	for (int k = 0; k < n; ++k)
		if (!isfinite(nx[k]) || !isfinite(ny[k]) || (nx[k] == 0.0 && ny[k] == 0.0)) return MK_ERR_ARGUMENT;
	return mkBoundary2_Single(b1, b2, bound, 1.0, n, n, nx, ny, impl, x, y, cap, count, error);
}
