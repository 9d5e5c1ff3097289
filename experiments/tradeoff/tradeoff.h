/* tradeoff.h - speed against accuracy: every method's error against its
 * time, per dimension (2D, 3D), case (EE, ES, SQ) and resolution.
 *
 * Pairs. Per (dimension, case) the run draws T pairs (--trials), each from
 * its own stream mkTradeoff_Stream(dim, case, trial), and computes the true
 * area / volume of their contact set B1 (+) (-B2) once per pair
 * (mkDeviation2_Area / mkDeviation3_Volume); every method and level then runs on
 * the same T pairs. Draws (the validation experiment's ranges):
 *  2D: a, b ~ U(0,10), redrawn (the whole shape) while a or b < 1e-3;
 *      eps ~ U(0.1,1.9); M = rot(2 pi U) [1 s; 0 1], s ~ U(-2,2).
 *  3D: B1 semi-axes U(1,10)^3, B2 U(1,6)^3, eps1, eps2 ~ U(0.1,1.9), the
 *      reference code's rotation (normalised quaternion of four U(0,1)).
 *  EE: both exponents 1 (not drawn); ES: body 2's are 1; SQ: all drawn.
 *
 * Curves. Every registry method that runs in the dimension and accepts the
 * pair, plus two samplings of the closed form that the registry does not
 * hold (the registry's closed forms use the paper's sampling, uniform in
 * B1's surface angles):
 *   closed-normal@normal-angles  normal form, MK_PARAM_NORMAL over
 *                                mkSample2_Angles / mkSample3_Grid
 *   closed-normal@spaced         normal form, MK_PARAM_SURFACE over
 *                                mkSample2_Spaced / mkSample3_Spaced
 *                                (the reference code's "almost equally
 *                                spaced" sampling, body 1's exponents)
 * Both call mkSum2_Batch / mkSum3_Batch; the time covers the sampling too.
 *
 * One row per (dim, case, method, n, trial): the median wall time of
 * --repeats calls (fewer when one call takes over 50 ms: then one call),
 * and the error of the last call's points by mink/error.h (a level a
 * method refuses, mkMethod_CheckN, is skipped and listed in the sidecar).
 * Levels rise per (dim, case, method). Before each level one untimed call
 * on the first pair warms the method up; when it takes longer than
 * --budget seconds, that level and the higher ones are not run, and the
 * sidecar says so (key `cut`; refusals by the registry under `skipped`).
 * That cut is the only thing in the rows that depends on measured times:
 * with --budget 0 (no cut, no warm-up call) two runs with the
 * same seed write the same CSV but for the `seconds` column.
 *
 * Threads: per level, every pair's calls are timed first, one after
 * another, with nothing else of the run working; then the kept points are
 * measured on --threads threads (and each (dim, case)'s true areas or
 * volumes likewise), and the rows are written in pair order. The 3D
 * measure's figures do not depend on the order of the points; a few rows of
 * the 3D hull methods (many coplanar points) can still differ in the last
 * bits between multi-threaded runs (docs/experiments/tradeoff.md). */
#ifndef MINK_EXP_TRADEOFF_H
#define MINK_EXP_TRADEOFF_H

#include <mink/mink.h>
#include <mink/error.h>
#include <mink/registry.h>
#include <mink/external.h>
#include <mink_exp/exp.h>

/* The CSV's columns, ended by NULL, and their schema version. */
extern const char *const mkTradeoff_Columns[];
#define MK_TRADEOFF_SCHEMA 2

/* The cases, in run order, and their names in the `case` column. */
enum { MK_TRADEOFF_EE = 0, MK_TRADEOFF_ES = 1, MK_TRADEOFF_SQ = 2, MK_TRADEOFF_CASES = 3 };
extern const char *const mkTradeoff_CaseNames[MK_TRADEOFF_CASES];

#define MK_TRADEOFF_LEVELS_MAX 64

#define MK_TRADEOFF_THREADS_MAX 64

/* Curves: the registry's methods, then the two extra samplings of the closed
 * form ("closed-normal@normal-angles", "closed-normal@spaced"). */
#define MK_TRADEOFF_CURVES_MAX 64

/* What a run covers; levels indexed by dimension 2, 3 (--n of each level,
 * rising). */
typedef struct mkTradeoffOptions {
	int level_count[4], level[4][MK_TRADEOFF_LEVELS_MAX], dim_on[4];
	long trials, repeats;   /* pairs per (dim, case); timed calls per row */
	uint64_t seed;
	double budget;          /* seconds for a level's first call; 0: no cut */
	long threads;           /* threads of the error measure and the true areas /
	                           volumes (the timed calls run alone), 1..MK_TRADEOFF_THREADS_MAX */
	int curve_on[MK_TRADEOFF_CURVES_MAX]; /* 1 for each curve run (--methods) */
} mkTradeoffOptions;

/* 2D n = 8, 32, 128, 512, 2048, 8192, 32768, 65536; 3D n = 4, 8, ..., 256;
 * both dimensions, budget 1 s, 5 repeats, 2 threads. */
void mkTradeoffOptions_Default(mkTradeoffOptions *o);

/* Flag callback (MK_FLAG_REPEAT): "2d=LIST" or "3d=LIST", LIST strictly
 * rising comma-separated integers (2D 3..1000000, 3D 2..4096), into the
 * mkTradeoffOptions it is given. */
int mkTradeoff_ParseLevels(void *options, const char *text, char *msg, size_t msglen);

/* Flag callback (MK_FLAG_TEXT): "all" or comma-separated curve names (the
 * registry's names and the two samplings above), into curve_on. */
int mkTradeoff_ParseMethods(void *on, const char *text, char *msg, size_t msglen);

/* After the harness parsed the flags: take trials and seed from the run,
 * the dimensions from --dim (0: 2D, 1: 3D, 2: both), and write the run's
 * own sidecar keys (levels, budget, repeats, set, clock, draws). */
void mkTradeoff_Start(mkTradeoffOptions *o, const mkRun *run, int dims, mkMeta *meta);

/* The median of v[0..n-1] (n >= 1; v is sorted in place, NaN not allowed). */
double mkTradeoff_Median(double *v, long n);

/* The stream of pair `trial` of (dim, case): (dim << 40) | (case << 32) | trial. */
uint64_t mkTradeoff_Stream(int dim, int c, long trial);

/* Draw the pair (see above). */
void mkTradeoff_Pair2(uint64_t seed, int c, long trial, mkBody2 *b1, mkBody2 *b2);
void mkTradeoff_Pair3(uint64_t seed, int c, long trial, mkBody3 *b1, mkBody3 *b2);

/* A body as SPEC text (mink/spec.h) that parses back to the same doubles:
 * "superellipse a=.. b=.. eps=.. M=m11,m12,m21,m22 at=x,y" ("%.17g"), 3D
 * "superquadric a=.. b=.. c=.. eps1=.. eps2=.. M=(9) at=x,y,z". */
void mkTradeoff_Spec2(mkBody2 b, char *buf, size_t len);
void mkTradeoff_Spec3(mkBody3 b, char *buf, size_t len);

/* Run the whole sweep, rows to csv, what was skipped or cut to meta.
 * Returns 0, or -1 on a failure (message printed on stderr). */
int mkTradeoff_Run(const mkTradeoffOptions *o, mkCsv *csv, mkMeta *meta);

/* The section of the tables from <dir>/tradeoff.csv: per dimension and
 * case the time each method needs to reach a median hausdorff_rel of 1e-2,
 * 1e-3, 1e-6, 1e-9, the closed form's speed-up over the fastest baseline at
 * equal error and its error ratio at equal time, and where a baseline wins.
 * "Closed form" means every registry method that returns boundary points
 * (not MK_METHOD_SAMPLED, by its flags); sampled methods and methods the
 * registry does not know are baselines. The tally is left untouched (the paper
 * publishes no such figure). */
void mkTradeoff_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
