/* timing.h - the running-time experiment of the paper (Sec. 6.3, Table 1,
 * Figs. 5-8): how long each registered method takes to produce a point set
 * on the boundary of B1 (+) (-B2), for pairs of ellipses/ellipsoids (EE), a
 * superellipse/superquadric with an ellipse/ellipsoid (ES) and two
 * superellipses/superquadrics (SQ), over a range of resolutions.
 *
 * What one measurement is. One call of the method's registry run function
 * (mkMethod.run2 / run3) on one pair at one resolution, timed with the wall
 * clock of mink_exp/clock.h (CLOCK_MONOTONIC) just before and just after the
 * call. The call covers everything from the bodies to the output point set:
 * the parameter grid, sampling body 1 (closed forms compute B1's point
 * f1(u_k) in their kernel; the sampled methods sample both bodies),
 * pairwise sums and hull, or the polygon merge. The output set is owned by
 * the driver, one per method, and reused, so its allocation is not timed
 * after the first call. Drawing the pair and writing the row are outside
 * the clock. Everything runs on the calling thread (no method starts
 * threads).
 *
 * Warm-up and the trial cap. The trials of one (dimension, case, level,
 * method) cell run back to back. Before them, one warm-up call on the cell's
 * first accepted pair brings code and data into cache; it is not a trial,
 * but its time is kept in the warmup_seconds column and decides how many
 * trials the cell runs: all T when T warm-up times fit in the budget
 * (--budget, seconds per cell), otherwise max(K, floor(budget / warm-up))
 * of them (K = --min-trials), never more than T. Every row says how many
 * trials its cell ran (trials_run), so a capped cell is never mistaken for a
 * full one, and no level is dropped. The cap depends on a measured time, so
 * two runs on different machines may cap different cells; the rows present
 * are otherwise fixed by the arguments.
 *
 * Draws (the reference code's distributions; bodies centred at the origin;
 * mink_exp/draw.h):
 *  2D: a, b ~ U(1,11), eps ~ U(0.1,1.9) (1 for an ellipse, not drawn),
 *      M = rot(2 pi U(0,1)) [1 s; 0 1], s ~ U(-2,2), for each body.
 *  3D: B1 semi-axes ~ U(1,10)^3, B2 ~ U(1,6)^3, eps1, eps2 ~ U(0.2,2.0)
 *      (1 for an ellipsoid, not drawn), pure rotations by mkDraw_Rotation3
 *      (--rotations paper: the reference code's normalised quaternion with
 *      four U(0,1) entries; uniform: uniform on SO(3)). U(0.2,2.0) reaches
 *      beyond the core's largest exponent MK_EPS_MAX = 2 - 1e-6; such draws
 *      are clamped to it and counted in the sidecar (eps_clamped_draws).
 *  Cases: EE both ellipses; ES body 1 a superellipse, body 2 an ellipse (as
 *  the reference code draws them, so that the geometric method applies);
 *  SQ both superellipses. Within a pair, body 1 is drawn before body 2.
 *  Every (dimension, case, level, trial) draws from its own stream
 *  (mkTiming_Stream), so a fresh pair is drawn at every level, as in the
 *  reference code, and all methods of a trial see the same pair.
 *
 * A method runs for a pair only when the registry says it accepts it
 * (mkMethod2/3_Accepts; e.g. the geometric method needs body 2 an ellipse)
 * and the level is in its resolution range (mkMethod_CheckN). Everything
 * skipped is listed in the sidecar (key `skipped`) and on stderr. A call that
 * fails is written as a row with its status.
 *
 * The run's units are cells in the order dim, case, level, method; --shard
 * splits the cells, and the shards' rows, concatenated in order, are the
 * unsplit run's rows. */
#ifndef MINK_EXP_TIMING_H
#define MINK_EXP_TIMING_H

#include <mink/mink.h>
#include <mink/registry.h>
#include <mink_exp/exp.h>

#define MK_TIMING_SCHEMA 1
#define MK_TIMING_LEVELS_MAX 1000
#define MK_TIMING_METHODS_MAX 32

enum { MK_TIMING_EE = 0, MK_TIMING_ES = 1, MK_TIMING_SQ = 2, MK_TIMING_CASES = 3 };
/* "EE", "ES", "SQ". */
extern const char *const mkTiming_CaseNames[MK_TIMING_CASES];
/* The CSV's columns, ended by NULL. */
extern const char *const mkTiming_Columns[];

typedef struct mkTimingLevels {
	int count;
	int v[MK_TIMING_LEVELS_MAX];
} mkTimingLevels;

typedef struct mkTimingOptions {
	long trials;
	uint64_t seed;
	int dim_on[4];                          /* indexed by dimension 2, 3 */
	int case_on[MK_TIMING_CASES];
	int method_on[MK_TIMING_METHODS_MAX];   /* registry order */
	mkTimingLevels levels[4];               /* indexed by dimension 2, 3 */
	mkRotDraw rotations;
	double budget;
	long min_trials;
} mkTimingOptions;

/* The defaults: every case and method, the paper's levels (2D N = 20:10:500,
 * 3D n = 5:5:50), paper rotations, budget 2 s, 3 trials at least. */
void mkTimingOptions_Default(mkTimingOptions *o);

/* Flag callbacks (mink_exp/driver.h, MK_FLAG_TEXT / MK_FLAG_REPEAT):
 * "2d=LIST" or "3d=LIST" into an mkTimingLevels[4] (LIST comma-separated
 * integers or START:STEP:STOP ranges); comma-separated case names or "all"
 * into int[MK_TIMING_CASES]; registry names or "all" into
 * int[MK_TIMING_METHODS_MAX]. */
int mkTiming_ParseLevels(void *levels, const char *text, char *msg, size_t msglen);
int mkTiming_ParseCases(void *on, const char *text, char *msg, size_t msglen);
int mkTiming_ParseMethods(void *on, const char *text, char *msg, size_t msglen);

/* One unit of the run. */
typedef struct mkTimingCell {
	int dim, c, level, method;
} mkTimingCell;

/* The cells in run order (dim, case, level, method); with cells NULL only
 * counts them. */
long mkTiming_Cells(const mkTimingOptions *o, mkTimingCell *cells);

/* A run's bookkeeping: the output sets, what was skipped, counts. */
typedef struct mkTimingRun mkTimingRun;
mkTimingRun *mkTimingRun_New(void);
void mkTimingRun_Free(mkTimingRun *tr);

/* Run one cell and write its rows. first_of_group marks the first cell of
 * its (dim, case, level) in this run, which counts the group's clamped
 * draws. Returns 0, or -1 on a driver error (message printed). */
int mkTiming_RunCell(const mkTimingOptions *o, mkTimingCell cell, int first_of_group, mkTimingRun *tr,
	mkCsv *csv);

/* The sidecar keys that describe the run before it starts (cell range,
 * dims, cases, methods, levels, draws, clock, cap, versions) and after
 * (skipped, counts, load average at the end). */
void mkTiming_MetaBegin(mkMeta *meta, const mkTimingOptions *o, long begin, long end, long total);
void mkTiming_MetaEnd(mkMeta *meta, mkTimingRun *tr, long cells);

/* The section of the tables: <dir>/timing.csv against the paper's Table 1
 * and its outcome statements, and the mean times. The methods are those
 * found in the data, in registry order, then names the registry does not
 * know in order of first appearance. */
void mkTiming_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
