/* mink/error.h - how far any method's output is from the true boundary of
 * the sum (or contact space), measured without the code that produced it.
 *
 * K is the true set: B1 (+) B2 (MK_SET_PLUS) or B1 (+) (-B2) (MK_SET_CONTACT,
 * B2's translation dropped, as in mink/sum.h). Its support function is
 *   h_K(n) = <n, o> + h_C1(M1^T n) + h_C2(M2^T n),   o = t1 (+ t2 for plus),
 * since both bodies are centrally symmetric; h_C of a canonical superellipse
 * (superquadric) is the textbook dual norm of its gauge, written out in
 * error.c (exponents 2/(2 - eps)), not taken from the core's kernels.
 *
 * P is the polygon / polyhedron of the returned points: their convex hull
 * (2D: mkPolygon2_Convex, which keeps points already in convex cyclic order
 * and drops those rounding made reflex; 3D: CGAL's hull on exact
 * predicates). The measure reports
 *   gap_in   = max over unit n of h_K(n) - h_P(n): how far K reaches beyond
 *              P (for P inside K this is the Hausdorff distance);
 *   gap_out  = max over the points of their signed distance to K,
 *              sd(p) = max over unit n of <n, p> - h_K(n) (> 0 outside K);
 *   hausdorff_abs = max(gap_in, gap_out), the Hausdorff distance between P
 *              and K (both convex: the sup norm of h_K - h_P);
 *   off_boundary_max = max over the points of |sd(p)|, the points' own
 *              distance off the boundary of K;
 *   area_rel = (|P| - |K|) / |K|, area in 2D, volume in 3D (volume_rel).
 * Relative figures divide by the sum's size (mkSum2_Size, mink/sum.h)
 *   S = |t1| (+ |t2| for the plus set) + |M1|_F |a1| + |M2|_F |a2|
 * (|a| the Euclidean norm of the semi-axes), the unit the core's accuracy
 * is stated in (the MPFR reference computes it on its own, refSum_Size).
 *
 * How far the computed values can be from the true ones (docs/error-measure.md
 * derives each bound):
 *   gap_in:  certified. Over the normal cone of a vertex v of P, h_K - h_P
 *            is h_{K-v}, a convex function; on the chord of an arc (2D) or
 *            spherical triangle (3D) of directions it is at most the largest
 *            corner value, and a unit direction is the chord point divided
 *            by at least cos(half the arc). Cones are bisected (2D) or
 *            subdivided in four (3D) until that bound is within
 *            tol of the largest value found; what remains is reported.
 *   gap_out, off_boundary (2D): the maximiser of <n, p> - h_K(n) is
 *            bracketed by the sign of its derivative and closed until the
 *            tangent lines of K at the bracket's ends (a certified upper
 *            bound within it) pin the maximum to 1e-3 of the rounding
 *            allowance, or to about 1e-15 rad. That the bracket holds the
 *            global maximiser is assumed: it is found from a table of 4096
 *            directions near the point's polar angle, which is right for
 *            points closer to K's boundary than its radii of curvature.
 *   gap_out, off_boundary (3D): Newton on the sphere from the point's own
 *            normal cone in P (until the rise its model predicts is below
 *            1e-3 of the rounding allowance); where it stops with the tangential residual
 *            of x_K(n) - p above 1e-7 R (near the axis normals of a boxy
 *            body, where the support map is not differentiable), Newton
 *            again in the boxier body's ray parameter (smooth there), then a branch
 *            and bound over spherical triangles with tangent-plane lower
 *            bounds (certified within its hexagon, budget 1500
 *            evaluations). The bound is that branch and bound's gap, or
 *            Newton's last step (an estimate). Every value found is
 *            attained, so gap_out never exceeds the truth and the depth of
 *            a point inside K is never understated; on boxy superquadrics
 *            boundary points were measured up to 3.4e-11 of the size deep,
 *            with a loose bound (up to 3e-5). Known weakness
 *            (docs/error-measure.md).
 *   area (2D): certified: |K| lies between the inscribed polygon of exact
 *            support points and the circumscribed polygon of their tangent
 *            lines, refined until the two agree to 1e-11 (or a cap).
 *   volume (3D): the triangulated surface of exact support points over
 *            the boxier body's normals on three spaced grids, Richardson-extrapolated;
 *            the bound is the change between two extrapolations (an
 *            estimate; 1e-8 to 3e-6 relative in the tests).
 *   Each bound also carries a rounding allowance, 64 u S (u = 2^-53).
 *
 * In 3D the points and CGAL's hull are put in a canonical order first, so
 * the figures do not depend on the order of the points. Where many points
 * are coplanar, how CGAL triangulates a coplanar facet can still vary (seen
 * between threads), which moves figures by about 1e-15 relative. The
 * measure is reentrant (no global state): separate calls may run on
 * separate threads.
 * The measure never calls the core's closed forms or body functions; it
 * uses only the bodies' parameters. Costs: 2D some 10 to 20 support
 * evaluations per point (a few us); 3D one CGAL hull, one evaluation per
 * hull facet and tens per point (hundreds where the branch and bound runs).
 * |K| costs about a second in 2D: compute it once per pair (mkDeviation2_Area)
 * and pass it in opt->truth. */
#ifndef MINK_ERROR_H
#define MINK_ERROR_H

#include <mink/mink.h>
#include <mink/registry.h> /* mkPointSet_Resize, mkPointSet_Free */

MK_EXTERN_C_BEGIN

typedef struct mkDeviationOptions {
	double tol;         /* relative precision sought for gap_in; 0: 1e-6 */
	double truth;       /* |K| (area in 2D, volume in 3D) when known, e.g. from an
	                       earlier mkDeviation2_Area / mkDeviation3_Volume on the same
	                       pair; 0: computed on every call */
	double truth_bound; /* its absolute bound, with truth */
} mkDeviationOptions;

/* mkDeviation: the figures above for one point set, how far it deviates
 * from the true set K. A measurement, not a failure: the MK_ERR_* codes
 * (mkResult, mink/base.h) say whether a call ran. */
typedef struct mkDeviation {
	int points;         /* points given */
	int nonfinite;      /* of them with a NaN or infinite coordinate (left out of
	                       every figure; hausdorff is +inf when no point is finite) */
	int vertices;       /* vertices of P */
	double size;        /* S above, the sum's size (mkSum2_Size / mkSum3_Size) */
	double gap_in, gap_out;
	double hausdorff_abs, hausdorff_rel;
	double hausdorff_bound;    /* the true distance is within
	                              [hausdorff_abs - allowance, hausdorff_abs + hausdorff_bound] */
	double off_boundary_max, off_boundary_rel;
	double off_boundary_bound; /* likewise, for off_boundary_max */
	int worst;          /* index of the point with the largest |sd| */
	double area_p, area_k;     /* |P| and |K| (volumes in 3D) */
	double area_rel;    /* (|P| - |K|) / |K|; volume_rel in 3D */
	double area_bound;  /* bound on |area_rel - true value| */
	char message[256];  /* one line with the figures */
} mkDeviation;

/* The textbook support function h_K(n) of the true set and its support
 * point (n any nonzero vector; the point is written when point != NULL).
 * Valid bodies assumed; NaN for a zero or non-finite n. */
MK_API double mkDeviation2_Support(mkBody2 b1, mkBody2 b2, mkSet set, mkVec2 n, mkVec2 *point);
MK_API double mkDeviation3_Support(mkBody3 b1, mkBody3 b2, mkSet set, mkVec3 n, mkVec3 *point);

/* |K| and a bound on its error (see above). Fails with MK_ERR_ARGUMENT on a
 * NULL pointer, a bad set or an invalid body, MK_ERR_MEMORY when it cannot
 * allocate. */
MK_API mkResult mkDeviation2_Area(mkBody2 b1, mkBody2 b2, mkSet set, double *area, double *bound);
MK_API mkResult mkDeviation3_Volume(mkBody3 b1, mkBody3 b2, mkSet set, double *volume, double *bound);

/* Measure the deviation of the points pts (dimension 2 / 3, any order, any count >= 1) against
 * the true set. opt may be NULL. Returns MK_OK when the measure ran (out
 * holds the figures), MK_ERR_ARGUMENT on a NULL pointer, a wrong dimension,
 * a bad set or an invalid body, MK_ERR_MEMORY when it cannot allocate,
 * MK_ERR_UNSUPPORTED when CGAL fails on the 3D hull. Points that span no
 * area (2D: one or two hull vertices) or no volume (3D) are measured all
 * the same (|P| = 0); in 3D gap_in is then measured over a direction set
 * only and its bound is +inf. */
MK_API mkResult mkDeviation2_Measure(mkBody2 b1, mkBody2 b2, mkSet set, const mkPointSet *pts,
	const mkDeviationOptions *opt, mkDeviation *out);
MK_API mkResult mkDeviation3_Measure(mkBody3 b1, mkBody3 b2, mkSet set, const mkPointSet *pts,
	const mkDeviationOptions *opt, mkDeviation *out);

MK_EXTERN_C_END

#endif
