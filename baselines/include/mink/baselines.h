/* mink/baselines.h - the kernels behind the sampled methods of the registry,
 * on plain arrays: body samples, pairwise sums, convex hulls (CGAL, qhull),
 * the edge-sorting merge of two convex polygons and the exact orientation
 * test it is built on.
 *
 * Point arrays are interleaved (x0, y0, x1, y1, ... or x, y, z triples),
 * which is what the hull libraries read. Outputs go into a caller-owned
 * mkPointSet (mink/method.h), resized as needed. CGAL stays behind these
 * functions: no header of the suite includes it. */
#ifndef MINK_BASELINES_H
#define MINK_BASELINES_H

#include <stddef.h>
#include <mink/mink.h>

MK_EXTERN_C_BEGIN

/* ---- samples ------------------------------------------------------------
 * The samples every sampled method starts from. p (2n or 3n*n doubles)
 * receives body 1's boundary points mkBody_Point(b1, u_k) at the
 * parameters of mkSample2_Angles(n) / mkSample3_Grid(n); q receives body 2's
 * points as they enter the sum: t2 - point for the contact set (B2 reflected
 * through its centre, translation dropped), the point itself for the plus
 * set. Fails with MK_ERR_ARGUMENT on n < 1 (2D) or n < 2 (3D). */
MK_API mkResult mkSampled2_Bodies(mkBody2 b1, mkBody2 b2, mkSet set, int n, double *p, double *q);
MK_API mkResult mkSampled3_Bodies(mkBody3 b1, mkBody3 b2, mkSet set, int n, double *p, double *q);

/* All pairwise sums s[i*n + j] = p_i + q_j (each coordinate one rounded
 * addition) of m points p and n points q, interleaved pairs (2D) or triples
 * (3D); s holds 2*m*n or 3*m*n doubles. This set is the input of the hull
 * methods and of the referee's hull checks. */
MK_API void mkSampled2_Sums(const double *p, int m, const double *q, int n, double *s);
MK_API void mkSampled3_Sums(const double *p, int m, const double *q, int n, double *s);

/* ---- exact predicates ---------------------------------------------------
 * Sign (+1, 0, -1) of the cross product (b - a) x (d - c), computed exactly
 * for any finite doubles whose products neither overflow nor underflow
 * (|coordinate| between about 1e-140 and 1e150, or zero): a floating-point
 * filter with a proven error bound, and an exact expansion sum when the
 * filter cannot decide. mkOrient2 (a, b, c) is the sign of (b - a) x (c - a):
 * +1 for a left turn. */
MK_API int mkCross2_Sign(const double *a, const double *b, const double *c, const double *d);
MK_API int mkOrient2(const double *a, const double *b, const double *c);

/* ---- convex polygons ----------------------------------------------------
 * Turn `count` points (interleaved) into a strictly convex polygon in
 * counter-clockwise order that starts at its lowest (then leftmost) vertex,
 * written to out (2*count doubles, may not alias xy); returns the vertex
 * count. When the points already are such a polygon in cyclic order (either
 * orientation, any start), which is checked exactly in O(count), they are
 * only rotated (and reversed); otherwise their convex hull is taken (Andrew's
 * monotone chain, O(count log count), with exact orientation tests), which
 * removes points that rounding made collinear or reflex. Returns -1 on
 * count < 1 or an allocation failure. */
MK_API int mkPolygon2_Convex(const double *xy, int count, double *out);

/* Edge sorting: the Minkowski sum of two strictly convex counter-clockwise
 * polygons that start at their lowest-leftmost vertices (as mkPolygon2_Convex
 * returns them), by merging their edges in slope order, O(m + n). Slopes are
 * compared with the exact mkCross2_Sign; parallel edges are merged into one.
 * out receives the vertices P_i + Q_j (rounded sums), counter-clockwise from
 * the lowest-leftmost, at most m + n of them. Fails with MK_ERR_ARGUMENT on
 * m or n < 1, MK_ERR_MEMORY when out cannot grow. */
MK_API mkResult mkEdgeSort2_Merge(const double *P, int m, const double *Q, int n, mkPointSet *out);

/* ---- convex hulls of point sets -----------------------------------------
 * The vertices of the convex hull of `count` points (interleaved), strictly
 * extreme points only: counter-clockwise from the lowest-leftmost in 2D, in
 * the library's order in 3D. Epick: CGAL's Exact_predicates_inexact_
 * constructions_kernel (exact decisions; the 3D hull is built into a
 * Surface_mesh, the overload CGAL 5.5 gets right with this kernel). Epeck:
 * CGAL's Exact_predicates_exact_constructions_kernel (the same decisions,
 * paying for exact number types). Qhull: libqhull_r's Quickhull, option "Qt"
 * in 3D, as MATLAB's convhull runs it; it decides in floating point with its
 * own merging tolerances. Fail with MK_ERR_ARGUMENT when the points span no
 * area (2D) or volume (3D), MK_ERR_MEMORY on allocation failure,
 * MK_ERR_UNSUPPORTED when the library reports any other error. */
MK_API mkResult mkHull2_CgalEpick(const double *xy, int count, mkPointSet *out);
MK_API mkResult mkHull2_CgalEpeck(const double *xy, int count, mkPointSet *out);
MK_API mkResult mkHull2_Qhull(const double *xy, int count, mkPointSet *out);
MK_API mkResult mkHull3_CgalEpick(const double *xyz, int count, mkPointSet *out);
MK_API mkResult mkHull3_CgalEpeck(const double *xyz, int count, mkPointSet *out);
MK_API mkResult mkHull3_Qhull(const double *xyz, int count, mkPointSet *out);

/* CGAL's minkowski_sum_2 of two simple polygons (interleaved, counter-
 * clockwise) on the exact kernel: the outer boundary of the exact sum
 * without collinear vertices (decided exactly), converted to double,
 * counter-clockwise from its lowest-leftmost vertex.
 * The cross-check of mkEdgeSort2_Merge. Slow: a test reference only. */
MK_API mkResult mkMinkowski2_CgalEpeck(const double *P, int m, const double *Q, int n, mkPointSet *out);

MK_EXTERN_C_END

#endif
