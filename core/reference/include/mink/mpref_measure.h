/* mink/mpref_measure.h - scoring any method's output against the 256-bit
 * reference (mink/mpref.h): how far its points lie from the exact boundary of
 * the sum, and how far that exact boundary itself moves when the inputs move
 * by one ulp (the problem's condition).
 *
 * K is B1 (+) B2 (plus = 1) or the contact space B1 (+) (-B2) (plus = 0).
 * As in the registry, the contact space ignores B2's translation: it is the
 * set of places for B2's centre, x = k - M2 s2(-M2^T n).
 *
 * Distance. For a convex body K with support function h_K the signed
 * distance of a point p from the boundary (positive outside, negative inside)
 * is
 *     d(p) = max over unit n of  phi(n) = <n, p> - h_K(n).
 * Outside, this is the distance to K (the maximum of a concave function on
 * the ball); inside, -d(p) = min over n of (h_K(n) - <n, p>) is the distance
 * to the nearest supporting line/plane, which is the distance to the
 * boundary. The gradient of phi on the sphere is the tangential part of
 * v = p - x_K(n), x_K(n) the exact boundary point with normal n, so phi is
 * stationary exactly where p - x_K(n) is along n. Every evaluated normal
 * gives phi(n) <= d(p) <= |v(n)| (the second because x_K(n) lies on the
 * boundary); the search maximises phi at 256 bits from a start normal (the
 * exact normal of the intended point for closed forms, a double-precision
 * scan of the sphere otherwise) with Newton steps on the sphere and a
 * Nelder-Mead fallback where phi has kinks (faces of eps -> 0 or 2 bodies).
 * Accuracy is reported per point (refDistance.accuracy): the remaining gain
 * the search predicts. Outside points are also bracketed rigorously by
 * [phi, |v|].
 *
 * Size. S = |t1| (+ |t2| for plus) + |M1|_F |a1| + |M2|_F |a2|, |a| the
 * Euclidean norm of the semi-axes (it bounds |f(u)|): the sum's size, the
 * unit every relative error of the sums is quoted in (the core's
 * mkSum2_Size, computed here on its own).
 *
 * Nothing here calls the core; the inputs are the doubles the core receives. */
#ifndef MINK_MPREF_MEASURE_H
#define MINK_MPREF_MEASURE_H

#include <stdint.h>
#include <mink/mpref.h>

/* The sum's size S (see above); plus selects the set. */
double refSum_Size(const refBody *b1, const refBody *b2, int plus);

/* The result of one distance evaluation. */
typedef struct refDistance {
	double dist;      /* signed distance d(p), positive outside (rounded) */
	double upper;     /* |p - x_K(n)| at the start or the final normal,
	                     whichever is smaller: |d(p)| <= upper */
	double accuracy;  /* estimated |d(p) - dist|: the gain still predicted by
	                     the search when it stopped (0 means not estimated
	                     because phi reached zero to 256 bits) */
	double normal[3]; /* the maximising normal found (unit, double) */
	int evals;        /* support-point evaluations at 256 bits */
} refDistance;

/* Signed distance of p (dim doubles, dim = b1->s.dim) from the boundary of K.
 * hint: a start normal (any length) or NULL; the search starts from the
 * better (in double precision) of the hint and a scan of the sphere. Returns 0, or -1 when p has a non-finite coordinate or
 * the hint is zero or non-finite (out is then left untouched). */
int refSum_Distance(const refBody *b1, const refBody *b2, int plus,
	const double *p, const double *hint, refDistance *out);

/* The score of one method's output on one pair. */
typedef struct refScore {
	double size;      /* S, the sum's size */
	double errorAbs;  /* max over the finite points of |d(p)| */
	double errorRel;  /* errorAbs / S */
	double accuracy;  /* the largest refDistance.accuracy of the distances
	                     computed, relative to S */
	int worst;        /* index of the point attaining errorAbs, -1 if none */
	double worstDist; /* its signed distance (so the side is known) */
	long points;      /* finite points scored */
	long nonfinite;   /* points with a NaN or Inf coordinate (not scored) */
	long searched;    /* points whose distance was searched at 256 bits */
	long refined;     /* of those, the points that needed the
	                     derivative-free search (a kink of phi) */
} refScore;

/* Score count points (x, y, z; z NULL in 2D). ux, uy, uz (optional, NULL for
 * none; uz NULL in 2D) are the surface parameters of body 1 the points belong
 * to: then each point starts from the exact normal of B1 at u (closed forms);
 * otherwise from a scan (sampled hulls, whose vertices are sums of two
 * boundary points and lie inside K). With parameters every point gets the
 * Newton stage (typically 2 to 8 support evaluations); the points where it
 * stops at a kink keep their bound |d| <= |v| and get the derivative-free
 * search in decreasing order of that bound, until it falls below the largest
 * distance known. Without parameters the scan's phi in double bounds |d|
 * to within 1e-9 S (+ 1e-6 |phi|) and only the points whose bound exceeds
 * the largest distance known are searched at 256 bits. Both are branch and
 * bound: the maximum is exact, the other points are only bounded. Returns 0, or -1 on
 * count < 0, NULL bodies or a NULL array that is needed (out is zeroed
 * first, worst = -1). */
int refSum_Score(const refBody *b1, const refBody *b2, int plus,
	const double *x, const double *y, const double *z, int count,
	const double *ux, const double *uy, const double *uz, refScore *out);

/* A memo of the per-point work of refSum_Score for one pair and set: the
 * scan's start normal and phi per point, and the result of every distance
 * search keyed by the point, its start (the surface parameter u, or the
 * start normal in double) and the stage. Every one of these is a
 * deterministic function of those keys and of the pair, so a score with the
 * memo is bit for bit the score without it; the memo only skips repeating
 * a search for a point some earlier output of the same pair already had
 * (several methods often give the same point to the last bit, sampled hulls
 * from different libraries the same vertices). The memo holds copies of the
 * bodies and of plus: given another pair or set it empties itself first.
 * Not shared between threads. */
typedef struct refScoreMemo refScoreMemo;
refScoreMemo *refScoreMemo_New(void);
void refScoreMemo_Free(refScoreMemo *memo);
/* Searches answered from the memo and searches run, since it was made. */
void refScoreMemo_Counts(const refScoreMemo *memo, long *hits, long *misses);

/* refSum_Score with a memo (NULL: none; then exactly refSum_Score). Returns
 * -1 also when the memo cannot grow (out of memory). */
int refSum_ScoreMemo(const refBody *b1, const refBody *b2, int plus,
	const double *x, const double *y, const double *z, int count,
	const double *ux, const double *uy, const double *uz, refScoreMemo *memo, refScore *out);

/* The problem's condition: a measured sensitivity, not a derivative bound.
 * Every input of the pair (semi-axes, exponents, map entries, translation
 * of both bodies; B2's translation only for plus) is moved by one ulp, up or
 * down at random (nextafter towards +-inf), in `draws` independent draws
 * from a fixed-seed generator. At `samples` parameters u of B1's surface
 * (2D: equally spaced angles; 3D: a samples x samples latitude-longitude
 * grid, poles included) with the exact boundary point x(u) and normal n(u):
 *  boundary = max |h_K'(n) - h_K(n)| / S over normals and draws: how far the
 *             exact boundary moves, in the direction error_rel is measured
 *             (for convex sets the largest such move is their Hausdorff
 *             distance);
 *  point    = max |x'(u) - x(u)| / S: how far the exact point of the same
 *             parameter moves (it can jump along flat faces where the
 *             boundary itself barely moves);
 *  floor    = max |<n, round(x(u)) - x(u)>| / S: the exact point rounded to
 *             double, measured along its normal: the part of the answer no
 *             double output can avoid (the e_gradient floor, in distance);
 *  value    = max(boundary, floor): what the `condition` column reports, in
 *             the unit of error_rel. An error near `value` is the geometry's;
 *             one far above it is the method's.
 * Returns 0, or -1 on samples < 2 or draws < 1. */
typedef struct refCondition {
	double boundary, point, floor, value;
} refCondition;

int refSum_Condition(const refBody *b1, const refBody *b2, int plus,
	int samples, int draws, uint64_t seed, refCondition *out);

/* The parameters refSum_Condition uses (and a closed form would be given):
 * 2D u_k = (cos 2 pi k/n, sin 2 pi k/n); 3D the n x n grid of
 * longitude 2 pi i/n and colatitude pi j/(n-1). Writes n (2D) or n*n (3D)
 * values; uz is NULL in 2D. */
void refSample_Params(int dim, int n, double *ux, double *uy, double *uz);

#endif
