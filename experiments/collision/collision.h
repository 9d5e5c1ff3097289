/* collision.h - the collision and distance benchmark (paper Sec. 7.2,
 * Table 3) on the collider registry (mink/colliders.h).
 *
 * One trial is one pair of bodies of one pair kind; every registry entry
 * that takes the pair runs on it (its `prepare` outside the timer, its `run`
 * timed alone with the wall clock of mink_exp/clock.h, one thread), and one
 * row per trial and entry is written. The registry's referee (a certified
 * bracket of the signed distance from the support maps only) gives the
 * reference signed distance of every pair; it is not itself a row. Pairs
 * where it is not certain (column referee_certain 0) are not judged: no
 * error, no agreement. Entries that do not take a
 * pair (mkCollider_Accepts: asc, asc-eigen and fcl on superquadrics) get no
 * row; every entry that takes it gets one, a failure being status `failed`.
 *
 * Pair kinds (each trial draws from its own stream (kind << 32) | trial of
 * the run's seed, body 1 then body 2, each semi-axes, exponents, centre,
 * rotation, so that shards concatenate to the unsplit run):
 *  0 ellipsoids     the paper's draw: B1 semi-axes U(1,11)^3, centre
 *                   U(-5,5)^3; B2 semi-axes U(1,6)^3, centre U(5,15)^3;
 *  1 superquadrics  the same with eps1, eps2 ~ U(0.1,1.9);
 *  2 near           a pair of the paper's draw (ellipsoids on even trials,
 *                   superquadrics on odd ones) with B2 moved along the
 *                   centre line until the referee's signed distance is
 *                   s * size, s = +-1e-1 ... +-1e-6 (cycling with trial / 2),
 *                   size = the smallest semi-axis of the two bodies;
 *  3 deep           the same bodies with centres U(-1,1)^3 and U(-2,2)^3.
 * Kinds 0 and 1 keep the streams of the earlier experiment, so their pairs
 * are the same.
 *
 * The batch entries (mink/batch.h): the trials are taken in chunks of
 * MK_COLLISION_CHUNK (aligned to trial numbers, cut at the run's or shard's
 * ends), and before the one-pair entries run on a chunk's pairs, each pair
 * kind's pairs of the chunk are answered by one mkCollide3_Batch call per
 * mode (rows minksum-batch-<mode>): the call timed as the one-pair runs are
 * (repeated once when under a millisecond, the faster kept) and its time
 * divided by the chunk's pairs, the amortised time per pair. Their rows
 * carry the pair's status, the distance where the mode gives one, and in
 * column path where the answer came from (separating, overlap-point,
 * one-pair, failed); the clearance asked is MK_COLLISION_DELTA. */
#ifndef MINK_EXP_COLLISION_H
#define MINK_EXP_COLLISION_H

#include <mink/colliders.h>
#include <mink/mink.h>
#include <mink_exp/exp.h>

#define MK_COLLISION_SCHEMA 5
#define MK_COLLISION_KINDS 4
/* Room for --limit pairs (NAME=N). */
#define MK_COLLISION_LIMITS 8

/* The CSV's columns, ended by NULL. */
extern const char *const mkCollision_Columns[];
/* "ellipsoids", "superquadrics", "near", "deep": the pair kinds 0..3. */
extern const char *const mkCollision_PairNames[MK_COLLISION_KINDS];

typedef struct mkCollisionOptions {
	uint64_t seed;
	mkRotDraw rotations;
	double margin;   /* status compared only where |referee sd| > margin * scale */
	int nlimits;     /* --limit NAME=N: entry `limit_entry[i]` runs on trials < N only */
	const mkCollider *limit_entry[MK_COLLISION_LIMITS];
	long limit_trials[MK_COLLISION_LIMITS];
} mkCollisionOptions;

/* The batch entries' chunk of trials, and the clearance (length units,
 * about 1e-2 of the paper pairs' scale) their clearance mode asks. */
#define MK_COLLISION_CHUNK 64
#define MK_COLLISION_DELTA 0.25
#define MK_COLLISION_MODES 4

/* The pairs of a chunk of trials [begin, begin + count) and the batch
 * entries' answers on them, per mode and pair kind. */
typedef struct mkCollisionChunk {
	long begin, count;
	mkBody3 b1[MK_COLLISION_KINDS][MK_COLLISION_CHUNK], b2[MK_COLLISION_KINDS][MK_COLLISION_CHUNK];
	mkContact status[MK_COLLISION_MODES][MK_COLLISION_KINDS][MK_COLLISION_CHUNK];
	double distance[MK_COLLISION_MODES][MK_COLLISION_KINDS][MK_COLLISION_CHUNK];
	unsigned char path[MK_COLLISION_MODES][MK_COLLISION_KINDS][MK_COLLISION_CHUNK];
	double seconds[MK_COLLISION_MODES][MK_COLLISION_KINDS]; /* per pair */
} mkCollisionChunk;

/* Parse one --limit value "NAME=N" (NAME a registry entry, N >= 0) into the
 * options (context); 0, or -1 with the reason in msg. */
int mkCollision_ParseLimit(void *context, const char *text, char *msg, size_t msglen);

/* The sidecar keys of a run (pair kinds, draws, referee, limits, every
 * entry's parameters and library version, the paper's Table 3). */
void mkCollision_Meta(mkMeta *meta, const mkCollisionOptions *o, const int on[MK_COLLISION_KINDS]);

/* Draw the pairs of trials [begin, end) (end - begin <= MK_COLLISION_CHUNK)
 * of the kinds on, and answer them with the batch entries. Returns 0, or -1
 * after printing an error. */
int mkCollision_Chunk(const mkCollisionOptions *o, const int on[MK_COLLISION_KINDS], long begin, long end,
	mkCollisionChunk *chunk);

/* One trial of one pair kind (its pair drawn in `chunk`): referee, every
 * one-pair entry, the batch entries' answers, the rows. Returns 0, or -1
 * after printing an error. */
int mkCollision_Trial(const mkCollisionOptions *o, int kind, long trial, const mkCollisionChunk *chunk, mkCsv *csv);

/* The section of the tables: <dir>/collision.csv beside the paper's
 * Table 3, and per pair kind and entry the times, success, agreement and
 * errors. */
void mkCollision_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
