/* mink/referee.h - an independent check that a method's output is what it
 * claims to be, for any entry of the registry (mink/registry.h).
 *
 * Methods that return boundary points (not MK_METHOD_SAMPLED): the support
 * check. Point p_k comes with a witness normal n_k, body 1's outward normal
 * at the surface parameter u_k the point belongs to, from the referee's own
 * formula (the textbook gradient of the superellipse / superquadric, mapped
 * by the cofactor matrix of M1). The referee samples both bodies densely on
 * its own (`dense` points per body in 2D, a dense x dense grid in 3D) and
 * forms, per direction d,
 *   H(d) = max over the dense pairwise sums s of <d, s>
 *        (a lower bound of the true support function h(d), since every
 *         pairwise sum lies in the set), and
 *   U(d) = an upper bound of h(d) from the tangent lines / planes at the
 *        dense samples: by convexity the body lies inside every tangent
 *        half-space, so h(d) <= sum_k l_k <n_k, x_k> whenever
 *        d = sum_k l_k n_k with l_k >= 0 (two neighbouring samples in 2D,
 *        the corners of a grid triangle in 3D).
 * U - H is the sampling error of the dense samples, bounded a posteriori
 * for the very bodies at hand (it shrinks as dense^-2; ~1e-7 of the size
 * at 8192 samples in 2D). Both bounds are then sharpened at the support
 * point itself: the referee inverts its own normal formula to find the
 * parameter whose normal is d, takes that point (a lower bound) and the
 * tangent planes of points 1e-7 to 0.3 rad around it (an upper bound, kept
 * valid whatever the inversion did by a residual term |d - sum l_k n_k| R,
 * R a bound on the body's radius). The sharpened gap is typically ~1e-14
 * of the size in 2D and ~1e-13 in 3D, larger where the normal map is nearly
 * singular (flat faces and sharp edges of 3D bodies with eps near 0 or 2).
 * A boundary point has <n, p> = h(n), so the referee asks
 *   depth  = H(n_k) - <n_k, p_k> <= tol   (no dense pairwise sum lies beyond
 *                                          p_k: p_k is not inside the set)
 *   excess = <d, p_k> - U(d)     <= tol   (p_k is not outside the set), for
 *            d = n_k and a fan of nearby directions.
 * tol is the rounding allowance, MK_REFEREE_ULPS units of roundoff of the
 * sum's extent on the referee's samples (see below); the sampling error never enters a bound in
 * the method's favour.
 *
 * Sampled methods (hull of pairwise sums, edge sorting): the hull check,
 * exact, on CGAL's exact predicates. The referee rebuilds the method's input
 * (mkSampled2/3_Sums over mkSampled2/3_Bodies) and checks that
 *   convex  - the output is a strictly convex polygon in counter-clockwise
 *             order that winds once (2D), or every output point is a vertex
 *             of the output's own convex hull (3D);
 *   subset  - every output vertex is one of the input sums, bit for bit;
 *   extreme - every input sum lies in the closed hull of the output.
 * Together these say the output is exactly the set of extreme points of
 * the input (`extreme` = 1). Two kinds of sampled method cannot promise
 * that, and the referee measures by how much they miss instead: edge
 * sorting forms its vertices by rounding exact sums (an input sum may then
 * lie outside by the rounding of one addition, < 4 u max|coordinate|), and
 * Qhull decides in floating point and merges facets that are coplanar
 * within its roundoff estimate, dropping extreme points that lie that close
 * to its facets. Input sums outside the output's hull are counted, their
 * largest distance to it is measured (CGAL's squared distance to the
 * nearest hull edge or triangle), and the check passes while that distance
 * stays within MK_REFEREE_HULL_ULPS u max|coordinate|.
 *
 * Costs: support check O(points * dense) in 2D and O(points * dense^2) in
 * 3D; hull check O(n^2 log h) in 2D and O(n^4 * faces) in 3D, which keeps
 * 3D hull checks to n of about 12 or less. */
#ifndef MINK_REFEREE_H
#define MINK_REFEREE_H

#include <mink/mink.h>
#include <mink/registry.h> /* mkPointSet_Resize, mkPointSet_Free */

MK_EXTERN_C_BEGIN

/* Rounding allowance of the support check, in units of u = 2^-53 times the
 * sum's extent E = |o|_inf + R1 + R2, o = t1 (+ t2 for the plus set), where R_i is
 * the largest |x - t_i|_inf over the referee's dense samples of body i (its
 * radius in the max norm): a bound on the largest coordinate of any point
 * of the set, as the referee's own samples see it (the error measure's
 * size S, mkSum2_Size, bounds the Euclidean norm from the bodies'
 * parameters instead). Reasoning in referee.c and the tests. */
#define MK_REFEREE_ULPS 4096.0
/* Allowance of the hull check for input sums outside the output's hull, in
 * units of u times the largest input coordinate. Edge sorting needs 4 (one
 * rounded addition per vertex). Qhull's merged facets left extreme points up
 * to 6948 units outside its vertex hull over 2000 random 3D pairs measured
 * here (none in 2D); 65536 units (7.3e-12 relative) keeps a margin of about
 * ten. The CGAL hulls need none: they are exact. */
#define MK_REFEREE_HULL_ULPS 65536.0

typedef struct mkRefereeOptions {
	int dense;         /* referee samples per body: 2D count, 3D grid side; 0: 8192 (2D), 128 (3D) */
	double tol_factor; /* multiplies the rounding allowance; 0 means 1 */
	int nofan;         /* 1: test the direction n_k only, not the fan around it */
	double unordered_tol; /* unordered points: the largest distance off the boundary
	                         allowed, relative to the sum's size; 0: the method's */
} mkRefereeOptions;

typedef enum mkVerdictKind { MK_VERDICT_SUPPORT = 1, MK_VERDICT_HULL = 2, MK_VERDICT_MEASURE = 3 } mkVerdictKind;

typedef struct mkVerdict {
	int pass;          /* 1 when every check holds */
	int kind;          /* mkVerdictKind */
	int points;        /* output points examined */
	/* support check (absolute lengths; divide by extent for relative) */
	double extent;     /* E above, the sum's extent in the max norm */
	double tol;        /* rounding allowance, absolute */
	double depth;      /* max over points of H(n_k) - <n_k, p_k> */
	double excess;     /* max over points and fan directions of <d, p_k> - U(d) */
	double gap;        /* max over points of U(n_k) - H(n_k), the bounds used (measure:
	                      the error measure's bound on its own distance) */
	double dense_gap;  /* the same for the dense samples alone: their sampling error */
	int worst;         /* index of the point with the largest violation, -1 if none */
	int loose;         /* directions no cone of sample normals held: U(d) there is the
	                      looser single-normal bound (still valid; for information) */
	int nonfinite;     /* output points with NaN or infinite coordinates (fails) */
	/* hull check */
	int inputs;        /* input sums */
	int convex, subset, extreme; /* 1 when that check holds */
	int outside;       /* input sums outside the output's hull */
	double outside_max;/* largest distance of an input sum outside it */
	double outside_tol;/* allowance for it (MK_REFEREE_HULL_ULPS u max|coordinate|) */
	char message[320]; /* one line: the verdict and its figures */
} mkVerdict;

/* Check the output `out` of method m run on (b1, b2, set, n): the support
 * check for methods that are not MK_METHOD_SAMPLED (out must hold n points
 * in 2D, n*n in 3D), the hull check otherwise. Point k's normal is taken
 * from the method's declared indexing (mkMethod_Indexing, mink/registry.h):
 * body 1's normal at u_k (MK_INDEX_PARAMETER) or u_k itself
 * (MK_INDEX_NORMAL). Boundary points declared MK_INDEX_UNORDERED (any count
 * >= 1; n unused) carry no normals: the error measure (mink/error.h) judges
 * them instead (v->kind MK_VERDICT_MEASURE): pass when every point lies
 * within the tolerance off the true boundary (opt->unordered_tol, else the
 * method's stated tolerance, else for an exact method the rounding
 * allowance, each times the sum's size), plus the measure's bound on its
 * own error (v->gap). opt may be NULL. Returns MK_OK when the check ran
 * (v->pass holds the verdict), MK_ERR_ARGUMENT on a NULL pointer, a wrong
 * dimension or point count, MK_ERR_MEMORY when the referee cannot
 * allocate, MK_ERR_UNSUPPORTED (and v->message saying why) for unordered
 * points of a method that states no tolerance when opt gives none. */
MK_API mkResult mkReferee2_Check(const mkMethod *m, mkBody2 b1, mkBody2 b2, mkSet set, int n,
	const mkPointSet *out, const mkRefereeOptions *opt, mkVerdict *v);
MK_API mkResult mkReferee3_Check(const mkMethod *m, mkBody3 b1, mkBody3 b2, mkSet set, int n,
	const mkPointSet *out, const mkRefereeOptions *opt, mkVerdict *v);

/* The support check with witness normals given by the caller (any nonzero
 * vectors; nz is ignored in 2D), for points that are not parameterised by
 * body 1's surface angles. */
MK_API mkResult mkReferee2_Support(mkBody2 b1, mkBody2 b2, mkSet set, const mkPointSet *pts,
	const double *nx, const double *ny, const mkRefereeOptions *opt, mkVerdict *v);
MK_API mkResult mkReferee3_Support(mkBody3 b1, mkBody3 b2, mkSet set, const mkPointSet *pts,
	const double *nx, const double *ny, const double *nz, const mkRefereeOptions *opt, mkVerdict *v);

/* The hull check of a sampled method's output against the pairwise sums of
 * n samples per body (3D: n x n grids); n at most MK_HULL2_N_MAX (2D) or
 * MK_HULL3_N_MAX (3D), since all sums are held in memory. */
MK_API mkResult mkReferee2_Hull(mkBody2 b1, mkBody2 b2, mkSet set, int n, const mkPointSet *out, mkVerdict *v);
MK_API mkResult mkReferee3_Hull(mkBody3 b1, mkBody3 b2, mkSet set, int n, const mkPointSet *out, mkVerdict *v);

/* The referee's own body model, for tests: boundary point and unit outward
 * normal (world frame) of a placed body at surface parameter u (a nonzero
 * vector; only its direction counts). */
MK_API mkVec2 mkReferee2_Point(mkBody2 b, mkVec2 u, mkVec2 *normal);
MK_API mkVec3 mkReferee3_Point(mkBody3 b, mkVec3 u, mkVec3 *normal);

MK_EXTERN_C_END

#endif
