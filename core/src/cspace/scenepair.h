/* scenepair.h - the scene query's quick certificates of a pair of
 * superquadric bodies, before the batch (internal to libmink_cspace).
 *
 * mkSqQuick_Pair(o, p, R, best, &depth), o and p the pair's models (an
 * obstacle's and a part's), margin m = 4e-12 of the pair's size (|d| + r_O
 * + r_P, as mkCollide3_PairSize), of the outer models (tried in this
 * order: the centre line, the centre segment, a box-like body's direction
 * and face point, a box-like body against an ellipsoid, the semi-axes'
 * ellipsoids' normal, a box-like obstacle's face normals, the semi-axes'
 * ellipsoids' point):
 *  - f(u) = |d| - h_O(u) - h_P(u) at u = d / |d|, d from o's centre to
 *    p's, is a lower bound of the distance. Returns 1 when f(u) > best + m
 *    (best finite: the pair is certainly at least best away), 3 when
 *    f(u) > m and best is infinite (separated; the exact distance is
 *    wanted), 0 when m < f(u) <= best + m (left to the batch);
 *  - a box-like inner model against an ellipsoid one (either way round):
 *    the point x of the box inside the box-like one (mkSqQuick's w) where
 *    the ellipsoid's gauge is least (mkSqQuick_BoxLeast). Returns 2 when
 *    that gauge is below 1 and x certifies the overlap by the gauges
 *    (mkSqQuick_PointDepth, below), 1 when best is finite and f along the
 *    normal of the ellipsoid's level set at x exceeds best + m (+ 1e-13 of
 *    the size);
 *  - best finite, a body whose exponents are at most 1 (box-like, not an
 *    ellipsoid): f(u) along u from the box of its semi-axes (which holds
 *    it) to the other's centre, by the support values' upper bounds
 *    (mkSq_NormBounds); returns 1 when f(u) > best + m (+ 1e-13 of the
 *    size);
 *  - best finite, when the overlap below is not certified: f along
 *    (S_O + S_P)^-1 d, S = M diag(a^2, b^2, c^2) M^T the shape matrix of a
 *    body's semi-axes' ellipsoid (the normal of the sum's boundary towards
 *    d when the two are ellipsoids of one shape), then along a box-like
 *    obstacle's face normals; returns 1 when one exceeds best + m (+ 1e-13
 *    of the size); then the point c_O + S_O (S_O + S_P)^-1 d, the
 *    contact point of Perram and Wertheim's function of the two
 *    semi-axes' ellipsoids at lambda = 1/2 (where the two, scaled alike
 *    about their centres, touch when 1/2 is its maximiser), as an overlap
 *    candidate, checked by the gauges as below;
 *  - returns 2 when the inner models (the bodies themselves where smooth)
 *    overlap for certain. A point x of the centre segment inside
 *    both, by their gauges g_O, g_P < 1, puts balls of radii (1 - g) rho
 *    about x inside each, so the depth is at least their sum (> m, in
 *    depth). The gauges are linear along the segment (each is homogeneous
 *    about its own centre): g_O(x_t) = t g_O(c_P) and g_P(x_t) = (1 - t)
 *    g_P(c_O) at x_t = c_O + t d, so the best x is an end of the interval
 *    of t where both are below 1 (the gauges rounded up by the slack);
 *  - 0 otherwise.
 * The part's models are R M_P placed: their gauges are read through the
 * quick data made from M_P and R^T. */
#ifndef MINK_CSPACE_SCENEPAIR_H
#define MINK_CSPACE_SCENEPAIR_H

#include "mink/body.h"

/* A body's data for the quick certificates. */
typedef struct mkSqQuick {
	mkMat3 Mi;     /* M^-1 */
	double r;      /* max(a, b, c) |M|_F: the radius in the pair's size (mkCollide3_PairSize) */
	double rho;    /* a ball about the centre inside the body: sigma_min(M) / |(1/a, 1/b, 1/c)| at least */
	double slack;  /* relative rounding of the gauge */
	double w[3];   /* the half-sides of a box about the centre inside the shape (canonical frame): the semi-axes times 2^(-(eps1 + eps2) / 2), less a rounding allowance */
} mkSqQuick;

mkSqQuick mkSqQuick_Make(mkBody3 b);

/* The canonical shape's gauge at y, |(|(y1/a, y2/b)|_p2, y3/c)|_p1 with
 * p = 2 / eps (dual 0), or its support value at y, the dual norm
 * |(|(a y1, b y2)|_q2, c y3)|_q1 with q = 2 / (2 - eps) (dual 1), by
 * base-2 logarithms of the components (scaled by a power of 2 first) and
 * one exponential (base/base2.h), within 1e-14 relative of the powers'
 * definition (core.test_cspace_pair checks it in long double). */
double mkSq_ShapeNorm(mkShape3 s, mkVec3 y, int dual);

/* Bounds lo <= mkSq_ShapeNorm(s, y, dual) <= hi without powers (one exp2 for a box-like shape), by the
 * shapes that hold or lie in the canonical shape: the box of its semi-axes
 * holds it and the octahedron of their ends lies in it (exponents in
 * (0, 2)); the ellipsoid of its semi-axes holds it when both exponents are
 * at least 1 and lies in it when both are at most 1; a box-like shape
 * (both exponents at most 1) also by Hoelder's inequality per level: its
 * gauge at most 2^((eps1 + eps2) / 2) times the box's, its support value at
 * least 2^(-(eps1 + eps2) / 2) times the box's. An ellipsoid's bounds
 * are its norm, by mkSq_ShapeNorm's operations. mkSqQuick_Pair decides by
 * them first where they settle it by a margin of 1e-13 of the pair's size
 * (its answers are those of the norms). */
void mkSq_NormBounds(mkShape3 s, mkVec3 y, int dual, double *lo, double *hi);

/* The point y of the box |y_i| <= w_i where (y - y0)^T H (y - y0) is
 * least (H symmetric positive definite), by the primal active-set method
 * from the point of the box nearest y0: the least on the face of the
 * bounds held, a step to the first bound met, or the bound let go whose
 * multiplier has the wrong sign. At most 8 steps (mkSqQuick_Pair verifies
 * what it makes of the point). */
void mkSqQuick_BoxLeast(double H[3][3], const double y0[3], const double w[3], double y[3]);

/* A body's two models, placed, with their quick data. */
typedef struct mkSqModels {
	const mkBody3 *outer, *inner;
	const mkSqQuick *kouter, *kinner;
} mkSqModels;

int mkSqQuick_Pair(const mkSqModels *o, const mkSqModels *p, const mkMat3 *R, double best, double *depth);

/* A lower bound of the depth of the inner models' overlap by the point x
 * (world frame): the balls of radii (1 - g) rho about x inside each (as
 * mkSqQuick_Pair's), 0 when x is not inside both by their gauges. Where x
 * lies outside the obstacle's inner model o (gauge g in [1, 2)), the point
 * x drawn towards its centre by the factor (1 - 1e-6) / g, just inside it,
 * is tested instead. */
double mkSqQuick_PointDepth(const mkSqModels *o, const mkSqModels *p, const mkMat3 *R, mkVec3 x);

#endif
