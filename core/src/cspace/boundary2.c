/* boundary2.c - 2D C-obstacle boundaries from fixed normals (uniform or
 * given), each arc certified by arc2.c, or by the adaptive walk (walk2.c);
 * the single-boundary 2D functions of mink/cobstacle.h. */
#include "cspace/work.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/geom_inline.h"

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
