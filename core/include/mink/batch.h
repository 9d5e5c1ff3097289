/* mink/batch.h - many collision queries per call (structure of arrays in,
 * caller-owned arrays out, nothing allocated), each call in one mode:
 *
 *  MK_BATCH_STATUS     separated / touching / overlapping, each certified:
 *                      a separated pair by a direction n with
 *                      f(n) = <n, c2 - c1> - h1(n) - h2(-n) > 0 (so sd >=
 *                      f(n)), an overlapping one by a point x of both bodies
 *                      with balls about x inside each (so the depth is at
 *                      least the sum of their radii). Either certificate is
 *                      accepted only beyond MK_BATCH_MARGIN * scale, outside
 *                      the touching band. First, before any search, at the
 *                      centre line n = (c2 - c1) / |c2 - c1|: f(n) bounded
 *                      below without transcendental functions, through
 *                      upper bounds of h1, h2 (each level of a nested norm
 *                      bounded by the smaller of two norm bounds exact on
 *                      the axes and the diagonals, within 15.3 %; exact for
 *                      ellipsoids); two ellipsoids also take
 *                      two steps towards their best direction and try the
 *                      point where the bodies, scaled about their centres,
 *                      would touch. Then Gilbert's
 *                      iteration on B2 - B1 from the centre line (a point of
 *                      both: a tetrahedron of B2 - B1 holding a ball about
 *                      the origin, or, once the hull comes within the margin
 *                      of the origin, its combination of the bodies' points
 *                      tested by their gauges); a pair neither settles goes to the
 *                      one-pair query (mkCollide3_Normal) and takes its
 *                      status: |sd| <= MK_COLLIDE3_TOUCH_TOL * scale is
 *                      touching, as there.
 *  MK_BATCH_CLEARANCE  is sd >= delta (delta >= 0)? Certified yes when
 *                      f(n) >= delta + MK_BATCH_MARGIN * scale, certified no
 *                      when f(n) > MK_BATCH_MARGIN * scale and a point of
 *                      B2 - B1 is shorter than delta - MK_BATCH_MARGIN *
 *                      scale, or an overlap is certified; otherwise the
 *                      one-pair query's sd decides (within MK_BATCH_MARGIN * scale of delta the verdict
 *                      is that of a distance accurate to 1e-12 of the scale,
 *                      not certified). The status is filled as in STATUS.
 *  MK_BATCH_DISTANCE   the signed distance of separated (and touching) pairs,
 *                      as mkCollide3_Normal gives it: for two ellipsoids
 *                      Newton's iteration in vector lanes, from the centre
 *                      line (before any search) and again from the search's
 *                      best direction where that did not answer, answered
 *                      when converged at an n with f(n) > MK_BATCH_MARGIN *
 *                      scale and the bracket lower = f(n), upper =
 *                      |p2 - p1| (the support points at n) at most
 *                      MK_BATCH_DISTANCE_GAP * scale wide (distance f(n),
 *                      path MK_PATH_SEPARATING); else (and for
 *                      superquadrics), once the search found the pair
 *                      separated, by the same call;
 *                      overlapping pairs get their status only (distance
 *                      NaN), certified by an overlap point where one is
 *                      found, else by the one-pair query.
 *  MK_BATCH_FULL       everything mkCollide3_Normal gives, for every pair:
 *                      the distance, the depth of overlaps certified global.
 *
 * The scale of every tolerance is the pair's size (mkCollide3_PairSize).
 * mkCollide3_Batch answers with the bounds first and the one-pair query where
 * they do not settle the pair; mkCollide3_BatchReference answers every pair
 * with the one-pair query in the same form (the reference the batch is
 * tested against). */
#ifndef MINK_BATCH_H
#define MINK_BATCH_H

#include "collision.h"

MK_EXTERN_C_BEGIN

typedef enum mkBatchMode {
	MK_BATCH_STATUS = 0,
	MK_BATCH_CLEARANCE = 1,
	MK_BATCH_DISTANCE = 2,
	MK_BATCH_FULL = 3
} mkBatchMode;

/* A certificate of the status or clearance is accepted only when it holds
 * by more than this (times the pair's scale): 4 times the touching band. */
#define MK_BATCH_MARGIN 4e-12
/* The distance mode answers a pair from the Newton lanes only when its
 * certified bracket, [f(n), |p2 - p1|], is at most this wide (times the
 * pair's scale). */
#define MK_BATCH_DISTANCE_GAP 1e-12
/* Pair evaluations of the certificates' search (Gilbert's iteration on
 * B2 - B1 from the centre line) before a pair goes to the one-pair query. */
#define MK_BATCH_EVALS 32

/* The pairs: pair k is bodies1[i1] and bodies2[i2] with i1 = index1[k]
 * (k when index1 is NULL), i2 likewise, so that one robot part can meet many
 * obstacles without copies. count >= 0. */
typedef struct mkBatchPairs3 {
	int count;
	const mkBody3 *bodies1, *bodies2;
	const int *index1, *index2;
} mkBatchPairs3;

/* Where a pair's answer came from (mkBatchOut3.path). */
typedef enum mkBatchPath {
	MK_PATH_SEPARATING = 0, /* the bounds: a separating direction */
	MK_PATH_OVERLAP_POINT = 1, /* the bounds: a point of both bodies */
	MK_PATH_ONE_PAIR = 2, /* the one-pair query (mkCollide3_Normal) */
	MK_PATH_FAILED = 3 /* the one-pair query failed: status unknown */
} mkBatchPath;

/* The answers, count entries each; every array but status may be NULL
 * (not written). Reals a mode does not give are NaN. */
typedef struct mkBatchOut3 {
	mkContact *status;
	double *distance;   /* DISTANCE: sd of non-overlapping pairs; FULL: sd */
	double *lower;      /* sd >= lower (certified; -inf when only an upper */
	double *upper;      /* bound is known); sd <= upper (+inf likewise);
	                       a separating direction's lower is f(normal) where
	                       the search evaluated it, a bound below f(normal)
	                       where the bounds before any search settled it */
	mkVec3 *normal;     /* the separating direction (bounds) or the solver's */
	mkVec3 *p1, *p2;    /* witnesses: the support points at normal (before
	                       any search: the ends of the bodies' axes farthest
	                       along +-normal, points of the bodies), or the
	                       solver's; an overlap point: p1 = p2 = the point */
	unsigned char *clear; /* CLEARANCE: 1 when sd >= delta, else 0 */
	unsigned char *path;  /* mkBatchPath */
} mkBatchOut3;

/* How a call's pairs were answered (per mkBatchPath), and, in
 * MK_BATCH_DISTANCE, how the separated pairs of ellipsoids fared in the
 * Newton lanes: newton answered there (also counted in separating),
 * newton_left left them for the one-pair query (also counted in one_pair or
 * failed); quick: answered before any search (also counted in separating or
 * overlap_point): by bounds of the support functions at the centre line,
 * or for two ellipsoids by their few direct steps. */
typedef struct mkBatchStats3 {
	int separating, overlap_point, one_pair, failed;
	int newton, newton_left;
	int quick;
} mkBatchStats3;

/* Answers the pairs in the mode (delta: the clearance, finite and >= 0,
 * used by MK_BATCH_CLEARANCE only). Returns MK_OK when every pair was
 * answered, MK_ERR_CONVERGENCE when the one-pair query failed on some
 * (their status unknown, path MK_PATH_FAILED; the others answered), and
 * MK_ERR_ARGUMENT (nothing written) for a NULL pairs, out or out->status, a
 * negative count, NULL body arrays with count > 0, an unknown mode or a bad
 * delta. stats may be NULL. Bodies must be valid (mkBody3_IsValid). */
MK_API mkResult mkCollide3_Batch(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchStats3 *stats);

/* Certified brackets [lower, upper] of the signed distance of the separated
 * pairs at most rel * upper wide (0 < rel < 1): a lower bound of the
 * clearance within rel of it, without the one-pair solver's last digits
 * where the certificates' search gets there (the bracket [f(m), |z|] of its
 * iteration, at most MK_BATCH_EVALS evaluations); the other separated pairs
 * get the one-pair query's bracket. Statuses as MK_BATCH_STATUS (overlaps
 * by their certificate); clear is 1 for separated pairs. Returns as
 * mkCollide3_Batch; MK_ERR_ARGUMENT also for rel outside (0, 1). */
MK_API mkResult mkCollide3_BatchBracket(const mkBatchPairs3 *pairs, double rel, const mkBatchOut3 *out,
	mkBatchStats3 *stats);

/* The same answers from the one-pair query alone (mkCollide3_Normal on every
 * pair; every path MK_PATH_ONE_PAIR or MK_PATH_FAILED): the reference. */
MK_API mkResult mkCollide3_BatchReference(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta,
	const mkBatchOut3 *out, mkBatchStats3 *stats);

/* Which support map the searches of mkCollide3_Batch run on this
 * processor: "avx512" (8 lanes, SLEEF's exp2 / log2), "avx2" (4 lanes), or
 * "scalar" (the solver's, four pairs in lock-step, eight where every pair
 * has an ellipsoid). For results' metadata. */
MK_API const char *mkCollide3_BatchLanes(void);

/* "status", "clearance", "distance", "full"; NULL for another value. */
MK_API const char *mkBatchMode_Name(mkBatchMode mode);
/* The mode of that name; -1 when unknown. */
MK_API int mkBatchMode_FromName(const char *name);

MK_EXTERN_C_END

#endif
