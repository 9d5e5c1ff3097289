/* timing.c - the running-time experiment of the paper (Sec. 6.3, Table 1,
 * Figs. 5-8): how long each registered method takes to produce a point set
 * on the boundary of B1 (+) (-B2), for pairs of ellipses/ellipsoids (EE), a
 * superellipse/superquadric with an ellipse/ellipsoid (ES) and two
 * superellipses/superquadrics (SQ), over a range of resolutions.
 *
 * What one measurement is. One call of the method's registry run function
 * (mkMethod.run2 / run3) on one pair at one resolution, timed with
 * CLOCK_MONOTONIC just before and just after the call. The call covers
 * everything from the bodies to the output point set: the parameter grid,
 * sampling body 1 (closed forms compute B1's point f1(u_k) in their kernel;
 * the sampled methods sample both bodies), pairwise sums and hull, or the
 * polygon merge. The output set is owned by the driver, one per method, and
 * reused, so its allocation is not timed after the first call. Drawing the
 * pair and writing the row are outside the clock. Everything runs on the
 * calling thread (no method starts threads).
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
 * Draws (the reference code's distributions; bodies centred at the origin):
 *  2D: a, b ~ U(1,11), eps ~ U(0.1,1.9) (1 for an ellipse),
 *      M = rot(2 pi U(0,1)) [1 s; 0 1], s ~ U(-2,2), for each body.
 *  3D: B1 semi-axes ~ U(1,10)^3, B2 ~ U(1,6)^3, eps1, eps2 ~ U(0.2,2.0)
 *      (1 for an ellipsoid), pure rotations: the reference code's
 *      normalised quaternion with four U(0,1) entries (--rotations paper,
 *      not uniform on SO(3)) or uniform on SO(3) (--rotations uniform,
 *      Shoemake's subgroup algorithm). U(0.2,2.0) reaches beyond the core's
 *      largest exponent MK_EPS_MAX = 2 - 1e-6; such draws are clamped to it
 *      and counted in the sidecar (eps_clamped_draws).
 *  Cases: EE both ellipses; ES body 1 a superellipse, body 2 an ellipse (as
 *  the reference code draws them, so that the geometric method applies);
 *  SQ both superellipses. Within a pair, body 1 is drawn before body 2, each
 *  as listed above. Every (dimension, case, level, trial) draws from its own
 *  stream (see mkTimingStream), so a fresh pair is drawn at every level, as
 *  in the reference code, and all methods of a trial see the same pair.
 *
 * A method runs for a pair only when the registry says it accepts it
 * (mkMethod2/3_Accepts; e.g. the geometric method needs body 2 an ellipse)
 * and the level is in its resolution range (mkMethod_CheckN). Everything
 * skipped is listed in the sidecar (key `skipped`) and on stderr. A call that
 * fails is written as a row with its status. */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include <mink/mink.h>
#include <mink/registry.h>
#include <mink_exp/exp.h>

#include <gmp.h>
#include <libqhull_r/libqhull_r.h>
#include <mpfr.h>

#include <errno.h>
#include <math.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MK_SCHEMA_VERSION 1
#define MK_LEVELS_MAX 1000
#define MK_METHODS_MAX 32
#define MK_TRIALS_MAX 1000000L
#define MK_LEVEL2_MIN 3
#define MK_LEVEL2_MAX 100000
#define MK_LEVEL3_MIN 3
#define MK_LEVEL3_MAX 3000
#define MK_BUDGET_MAX 1e6
#define MK_FAIL_REPORTS 5

#ifndef MK_TIMING_CGAL_VERSION
#define MK_TIMING_CGAL_VERSION "unknown"
#endif

enum { MK_CASE_EE = 0, MK_CASE_ES = 1, MK_CASE_SQ = 2, MK_CASE_COUNT = 3 };

static const char *const mkCaseNames[MK_CASE_COUNT] = { "EE", "ES", "SQ" };
static const char *const mkRotNames[] = { "paper", "uniform" };
static const char *const mkDimNames[] = { "2", "3", "both" };

typedef struct mkLevels {
	int count;
	int v[MK_LEVELS_MAX];
} mkLevels;

typedef struct mkOptions {
	long trials;
	uint64_t seed;
	int dim_on[4];              /* indexed by dimension 2, 3 */
	int case_on[MK_CASE_COUNT];
	int method_on[MK_METHODS_MAX];
	mkLevels levels[4];         /* indexed by dimension 2, 3 */
	mkRotDraw rotations;
	double budget;
	long min_trials;
	const char *out;
	int out_given;
	mkShard shard;
	int force;
} mkOptions;

/* One random pair and what its draw clamped. */
typedef struct mkPair {
	mkBody2 p1, p2;
	mkBody3 q1, q2;
	int clamped;
} mkPair;

/* ---- command line --------------------------------------------------------- */

static void mkUsage(FILE *fp)
{
	fputs(
		"usage: timing [options]\n"
		"The running-time experiment of the paper (Sec. 6.3, Table 1, Figs. 5-8): seconds\n"
		"per call of every registered method on random EE, ES and SQ pairs in 2D and 3D,\n"
		"one CSV row per (dim, case, method, level, trial), plus a metadata sidecar\n"
		"<out>.meta (clock, warm-up, threads, trial caps, skipped methods).\n"
		"\n"
		"  --trials T          trials per level, 1..1000000 (default 100)\n"
		"  --seed S            run seed, 0..2^64-1, decimal or 0x.. (default 2022)\n"
		"  --dims 2|3|both     which dimensions (default both)\n"
		"  --cases LIST        comma-separated EE, ES, SQ, or all (default all)\n"
		"  --methods LIST      comma-separated registry names, or all (default all)\n"
		"  --levels 2d=LIST    2D levels: points per body, 3..100000\n"
		"  --levels 3d=LIST    3D levels: grid side n (n x n points per body), 3..3000;\n"
		"                      LIST is comma-separated integers or START:STEP:STOP ranges\n"
		"                      (default 2d=20:10:500 and 3d=5:5:50, the paper's)\n"
		"  --rotations paper|uniform\n"
		"                      3D rotation draw: the reference code's normalised positive\n"
		"                      quaternion, or uniform on SO(3) (default paper)\n"
		"  --budget SECONDS    time budget per (dim, case, level, method) cell, 0..1e6\n"
		"                      (default 2): when T warm-up times exceed it, the cell runs\n"
		"                      max(K, floor(budget / warm-up)) trials instead of T\n"
		"  --min-trials K      trials a capped cell still runs, 1..1000000 (default 3)\n"
		"  --out PATH          output CSV (default results/timing.csv, or\n"
		"                      results/timing.shard-I-of-N.csv with --shard)\n"
		"  --shard I/N         run only block I (0-based) of N of the run's cells, taken in\n"
		"                      the order dim, case, level, method; the shards' rows,\n"
		"                      concatenated in order, are the unsplit run's rows\n"
		"  --force             replace an existing output file\n"
		"  --help              this text\n"
		"Progress goes to stderr when it is a terminal (MINK_PROGRESS=always|never).\n",
		fp);
}

static const mkOption mkOptionTable[] = {
	{ "--trials", 1 }, { "--seed", 1 }, { "--dims", 1 }, { "--cases", 1 }, { "--methods", 1 },
	{ "--levels", 1 }, { "--rotations", 1 }, { "--budget", 1 }, { "--min-trials", 1 }, { "--out", 1 },
	{ "--shard", 1 }, { "--force", 0 },
};

/* Parse "2d=LIST" or "3d=LIST" into o->levels. */
static int mkParseLevels(const char *text, mkOptions *o, char *msg, size_t msglen)
{
	int dim = 0;
	if (strncmp(text, "2d=", 3) == 0)
		dim = 2;
	else if (strncmp(text, "3d=", 3) == 0)
		dim = 3;
	if (!dim) {
		snprintf(msg, msglen, "--levels: expected 2d=LIST or 3d=LIST (LIST: integers or "
			"START:STEP:STOP, comma-separated), got '%s'", text);
		return -1;
	}
	int lo = dim == 2 ? MK_LEVEL2_MIN : MK_LEVEL3_MIN;
	int hi = dim == 2 ? MK_LEVEL2_MAX : MK_LEVEL3_MAX;
	mkLevels lv;
	lv.count = 0;
	const char *s = text + 3;
	while (1) {
		long part[3];
		int parts = 0;
		for (;;) {
			char *end = NULL;
			if (*s < '0' || *s > '9')
				goto bad;
			errno = 0;
			long v = strtol(s, &end, 10);
			if (errno == ERANGE)
				goto bad;
			if (parts == 3)
				goto bad;
			part[parts++] = v;
			s = end;
			if (*s != ':')
				break;
			++s;
		}
		if (parts == 2)
			goto bad;
		long start = part[0], step = parts == 3 ? part[1] : 1, stop = parts == 3 ? part[2] : part[0];
		if (step < 1 || stop < start)
			goto bad;
		for (long v = start; v <= stop; v += step) {
			if (v < lo || v > hi) {
				snprintf(msg, msglen, "--levels: %dd level %ld is outside [%d, %d] in '%s'", dim, v, lo, hi, text);
				return -1;
			}
			if (lv.count == MK_LEVELS_MAX) {
				snprintf(msg, msglen, "--levels: more than %d %dd levels in '%s'", MK_LEVELS_MAX, dim, text);
				return -1;
			}
			lv.v[lv.count++] = (int)v;
		}
		if (*s == '\0')
			break;
		if (*s != ',')
			goto bad;
		++s;
	}
	o->levels[dim] = lv;
	return 0;
bad:
	snprintf(msg, msglen, "--levels: expected %dd=LIST with LIST comma-separated integers or "
		"START:STEP:STOP ranges (STEP >= 1, STOP >= START), got '%s'", dim, text);
	return -1;
}

/* Comma-separated names out of `names` (or "all") into on[]. */
static int mkParseNameList(const char *flag, const char *text, const char *const *names, int count,
	int *on, char *msg, size_t msglen)
{
	int seen[MK_METHODS_MAX] = { 0 };
	if (strcmp(text, "all") == 0) {
		for (int i = 0; i < count; ++i)
			on[i] = 1;
		return 0;
	}
	const char *s = text;
	while (1) {
		size_t len = strcspn(s, ",");
		int found = -1;
		for (int i = 0; i < count; ++i)
			if (strlen(names[i]) == len && strncmp(names[i], s, len) == 0)
				found = i;
		if (found < 0) {
			int n = snprintf(msg, msglen, "%s: expected a comma-separated list of ", flag);
			for (int i = 0; i < count && n >= 0 && (size_t)n < msglen; ++i)
				n += snprintf(msg + n, msglen - (size_t)n, "%s%s", i ? ", " : "", names[i]);
			if (n >= 0 && (size_t)n < msglen)
				snprintf(msg + n, msglen - (size_t)n, " (or all), got '%s'", text);
			return -1;
		}
		seen[found] = 1;
		if (s[len] == '\0')
			break;
		s += len + 1;
	}
	for (int i = 0; i < count; ++i)
		on[i] = seen[i];
	return 0;
}

/* Parse argv into o. Returns 0 to run, 1 when --help was printed, 2 on a
 * usage error (message printed). */
static int mkParseOptions(int argc, char **argv, mkOptions *o, char *outbuf, size_t outlen)
{
	memset(o, 0, sizeof *o);
	o->trials = 100;
	o->seed = 2022;
	o->dim_on[2] = o->dim_on[3] = 1;
	for (int c = 0; c < MK_CASE_COUNT; ++c)
		o->case_on[c] = 1;
	int methods = mkRegistry_Count();
	for (int i = 0; i < methods && i < MK_METHODS_MAX; ++i)
		o->method_on[i] = 1;
	for (int n = 20; n <= 500; n += 10)
		o->levels[2].v[o->levels[2].count++] = n;
	for (int n = 5; n <= 50; n += 5)
		o->levels[3].v[o->levels[3].count++] = n;
	o->rotations = MK_ROT_PAPER;
	o->budget = 2.0;
	o->min_trials = 3;
	o->out = "results/timing.csv";
	o->shard = mkShard_All();

	const char *method_names[MK_METHODS_MAX];
	for (int i = 0; i < methods && i < MK_METHODS_MAX; ++i)
		method_names[i] = mkRegistry_At(i)->name;

	char msg[1024] = "";
	mkArgs args;
	mkArgs_Begin(&args, argc, argv);
	const char *name, *value;
	int choice = 0, bad = 0;
	mkArgsStep step;
	while (!bad && (step = mkArgs_Step(&args, mkOptionTable, MK_COUNT(mkOptionTable), &name, &value,
			msg, sizeof msg)) != MK_ARGS_END) {
		if (step == MK_ARGS_HELP) {
			mkUsage(stdout);
			return 1;
		}
		if (step == MK_ARGS_ERROR) {
			bad = 1;
		} else if (strcmp(name, "--force") == 0) {
			o->force = 1;
		} else if (strcmp(name, "--trials") == 0) {
			bad = mkArg_Long(name, value, 1, MK_TRIALS_MAX, &o->trials, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--seed") == 0) {
			bad = mkArg_U64(name, value, &o->seed, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--dims") == 0) {
			bad = mkArg_Choice(name, value, mkDimNames, 3, &choice, msg, sizeof msg) != 0;
			o->dim_on[2] = choice != 1;
			o->dim_on[3] = choice != 0;
		} else if (strcmp(name, "--cases") == 0) {
			bad = mkParseNameList(name, value, mkCaseNames, MK_CASE_COUNT, o->case_on, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--methods") == 0) {
			bad = mkParseNameList(name, value, method_names, methods, o->method_on, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--levels") == 0) {
			bad = mkParseLevels(value, o, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--rotations") == 0) {
			bad = mkArg_Choice(name, value, mkRotNames, 2, &choice, msg, sizeof msg) != 0;
			o->rotations = (mkRotDraw)choice;
		} else if (strcmp(name, "--budget") == 0) {
			bad = mkArg_Double(name, value, 0.0, MK_BUDGET_MAX, "a number of seconds", &o->budget, msg,
				sizeof msg) != 0;
		} else if (strcmp(name, "--min-trials") == 0) {
			bad = mkArg_Long(name, value, 1, MK_TRIALS_MAX, &o->min_trials, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--out") == 0) {
			bad = mkArg_Path(name, value, &o->out, msg, sizeof msg) != 0;
			o->out_given = 1;
		} else if (strcmp(name, "--shard") == 0) {
			bad = mkShard_Parse(value, name, &o->shard, msg, sizeof msg) != 0;
		}
	}
	if (bad) {
		fprintf(stderr, "timing: %s\n", msg);
		return 2;
	}
	if (!o->out_given && o->shard.count > 1) {
		snprintf(outbuf, outlen, "results/timing.shard-%d-of-%d.csv", o->shard.index, o->shard.count);
		o->out = outbuf;
	}
	return 0;
}

/* ---- draws ---------------------------------------------------------------- */

/* The stream of one pair: dimension, case, level and trial packed into
 * disjoint bit fields (dim - 2 in bits 62-63, case in 60-61, level < 2^28 in
 * 32-59, trial < 2^32 in 0-31), hence injective. */
static uint64_t mkTimingStream(int dim, int c, int level, long trial)
{
	return ((uint64_t)(dim - 2) << 62) | ((uint64_t)c << 60) | ((uint64_t)level << 32) | (uint64_t)trial;
}

static mkBody2 mkDrawBody2(mkRng *r, int super)
{
	mkShape2 s;
	s.a = mkRng_Uniform(r, 1.0, 11.0);
	s.b = mkRng_Uniform(r, 1.0, 11.0);
	s.eps = super ? mkRng_Uniform(r, 0.1, 1.9) : 1.0;
	double angle = 2.0 * MK_PI * mkRng_Unit(r);
	double shear = mkRng_Uniform(r, -2.0, 2.0);
	mkMat2 M = mkMat2_Mul(mkMat2_Rotation(angle), mkMat2_Shear(shear));
	mkVec2 t = { 0.0, 0.0 };
	return mkBody2_Make(s, M, t);
}

static double mkClampEps(double e, int *clamped)
{
	if (e > MK_EPS_MAX) {
		*clamped += 1;
		return MK_EPS_MAX;
	}
	return e;
}

static mkBody3 mkDrawBody3(mkRng *r, double amax, int super, mkRotDraw rot, int *clamped)
{
	mkShape3 s;
	s.a = mkRng_Uniform(r, 1.0, amax);
	s.b = mkRng_Uniform(r, 1.0, amax);
	s.c = mkRng_Uniform(r, 1.0, amax);
	s.eps1 = super ? mkClampEps(mkRng_Uniform(r, 0.2, 2.0), clamped) : 1.0;
	s.eps2 = super ? mkClampEps(mkRng_Uniform(r, 0.2, 2.0), clamped) : 1.0;
	double q[4];
	if (rot == MK_ROT_PAPER) {
		for (int i = 0; i < 4; ++i)
			q[i] = mkRng_Unit(r);
	} else {
		/* Shoemake (1992): uniform on the unit 3-sphere, hence on SO(3). */
		double u1 = mkRng_Unit(r), u2 = mkRng_Unit(r), u3 = mkRng_Unit(r);
		double r1 = sqrt(1.0 - u1), r2 = sqrt(u1);
		q[0] = r2 * cos(2.0 * MK_PI * u3);
		q[1] = r1 * sin(2.0 * MK_PI * u2);
		q[2] = r1 * cos(2.0 * MK_PI * u2);
		q[3] = r2 * sin(2.0 * MK_PI * u3);
	}
	int ok = 0;
	mkMat3 R = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
	ok = mkMat3_IsFinite(R);
	if (!ok)
		R = mkMat3_Identity(); /* all four entries zero: probability 2^-212 */
	mkVec3 t = { 0.0, 0.0, 0.0 };
	return mkBody3_Make(s, R, t);
}

/* The pair of (dim, case, level, trial). Returns 1 when both bodies are
 * valid (always, for these ranges; checked all the same). */
static int mkDrawPair(const mkOptions *o, int dim, int c, int level, long trial, mkPair *p)
{
	mkRng rng;
	mkRng_Seed(&rng, o->seed, mkTimingStream(dim, c, level, trial));
	memset(p, 0, sizeof *p);
	int super1 = c != MK_CASE_EE, super2 = c == MK_CASE_SQ;
	if (dim == 2) {
		p->p1 = mkDrawBody2(&rng, super1);
		p->p2 = mkDrawBody2(&rng, super2);
		return mkBody2_IsValid(p->p1, "body1", NULL, 0) && mkBody2_IsValid(p->p2, "body2", NULL, 0);
	}
	p->q1 = mkDrawBody3(&rng, 10.0, super1, o->rotations, &p->clamped);
	p->q2 = mkDrawBody3(&rng, 6.0, super2, o->rotations, &p->clamped);
	return mkBody3_IsValid(p->q1, "body1", NULL, 0) && mkBody3_IsValid(p->q2, "body2", NULL, 0);
}

static int mkAccepts(const mkMethod *m, int dim, const mkPair *p, char *msg, size_t msglen)
{
	return dim == 2 ? mkMethod2_Accepts(m, p->p1, p->p2, MK_SET_CONTACT, msg, msglen)
		: mkMethod3_Accepts(m, p->q1, p->q2, MK_SET_CONTACT, msg, msglen);
}

/* ---- the clock ------------------------------------------------------------ */

/* One timed call: seconds between two CLOCK_MONOTONIC readings around it,
 * the difference taken in integer nanoseconds. */
static mkResult mkTimedCall(const mkMethod *m, int dim, const mkPair *p, int n, mkPointSet *out,
	double *seconds)
{
	struct timespec t0, t1;
	clock_gettime(CLOCK_MONOTONIC, &t0);
	mkResult r = dim == 2 ? m->run2(p->p1, p->p2, MK_SET_CONTACT, n, out)
		: m->run3(p->q1, p->q2, MK_SET_CONTACT, n, out);
	clock_gettime(CLOCK_MONOTONIC, &t1);
	long long ns = (long long)(t1.tv_sec - t0.tv_sec) * 1000000000LL + (long long)(t1.tv_nsec - t0.tv_nsec);
	*seconds = 1e-9 * (double)ns;
	return r;
}

/* Trials a cell runs: all when T warm-up times fit the budget, otherwise
 * max(K, floor(budget / warm-up)), never more than T. */
static long mkCellTrials(long planned, double warmup, double budget, long min_trials)
{
	if ((double)planned * warmup <= budget)
		return planned;
	double fit = warmup > 0.0 ? floor(budget / warmup) : (double)planned;
	long k = fit >= (double)planned ? planned : (long)fit;
	if (k < min_trials)
		k = min_trials;
	return k < planned ? k : planned;
}

/* ---- what was skipped ------------------------------------------------------ */

/* Per (dim, case, method): pairs the method did not accept, and why. */
typedef struct mkSkip {
	long rejected, seen;
	char why[256];
} mkSkip;

typedef struct mkRunStats {
	mkSkip skip[4][MK_CASE_COUNT][MK_METHODS_MAX];
	char *range_skips;     /* "; "-joined out-of-range cells */
	size_t range_len;
	long capped_cells, cells_run, failed_calls, rows, clamped_draws;
} mkRunStats;

static void mkAppend(char **text, size_t *len, const char *item)
{
	size_t add = strlen(item) + 3;
	char *grown = realloc(*text, *len + add + 1);
	if (!grown)
		return; /* the sidecar then lacks this note; the stderr line still has it */
	*text = grown;
	if (*len) {
		memcpy(*text + *len, "; ", 2);
		*len += 2;
	}
	memcpy(*text + *len, item, strlen(item) + 1);
	*len += strlen(item);
}

/* ---- rows ----------------------------------------------------------------- */

static const char *const mkColumns[] = {
	"dim", "case", "method", "level", "points_per_body", "trial", "status", "seconds",
	"points_out", "trials_planned", "trials_run", "warmup_seconds"
};
#define MK_COLUMN_COUNT ((int)(sizeof mkColumns / sizeof mkColumns[0]))

/* ---- the cells ------------------------------------------------------------ */

typedef struct mkCell {
	int dim, c, level, method;
} mkCell;

/* Enumerate the cells in run order (dim, case, level, method); with cells
 * NULL only count them. */
static long mkCells(const mkOptions *o, mkCell *cells)
{
	long count = 0;
	int methods = mkRegistry_Count();
	for (int dim = 2; dim <= 3; ++dim) {
		if (!o->dim_on[dim])
			continue;
		for (int c = 0; c < MK_CASE_COUNT; ++c) {
			if (!o->case_on[c])
				continue;
			for (int l = 0; l < o->levels[dim].count; ++l)
				for (int m = 0; m < methods && m < MK_METHODS_MAX; ++m) {
					if (!o->method_on[m])
						continue;
					if (cells) {
						mkCell cell = { dim, c, o->levels[dim].v[l], m };
						cells[count] = cell;
					}
					++count;
				}
		}
	}
	return count;
}

/* Run one cell and write its rows. `first_of_group` marks the first cell of
 * its (dim, case, level) in this run, which counts the group's clamped
 * draws. Returns 0, or -1 on a driver error (message printed). */
static int mkRunCell(const mkOptions *o, mkCell cell, int first_of_group, mkPointSet *out, mkCsv *csv,
	mkRunStats *st)
{
	const mkMethod *m = mkRegistry_At(cell.method);
	const char *cname = mkCaseNames[cell.c];
	mkSkip *sk = &st->skip[cell.dim][cell.c][cell.method];
	char msg[256];
	if (first_of_group) {
		mkPair pair;
		for (long t = 0; t < o->trials; ++t)
			if (mkDrawPair(o, cell.dim, cell.c, cell.level, t, &pair))
				st->clamped_draws += pair.clamped;
	}
	if (!(m->flags & (cell.dim == 2 ? MK_METHOD_2D : MK_METHOD_3D))) {
		/* Not a method of this dimension: the registry's accept test says so
		 * for every pair; record it once per (dim, case, method). */
		sk->seen += o->trials;
		sk->rejected += o->trials;
		if (!sk->why[0])
			snprintf(sk->why, sizeof sk->why, "method %s does not run in %dD", m->name, cell.dim);
		return 0;
	}
	if (!mkMethod_CheckN(m, cell.dim, cell.level, msg, sizeof msg)) {
		char item[512];
		snprintf(item, sizeof item, "%dD %s level %d %s: %s", cell.dim, cname, cell.level, m->name, msg);
		fprintf(stderr, "timing: skipped %s\n", item);
		mkAppend(&st->range_skips, &st->range_len, item);
		return 0;
	}
	/* Pass 1: which pairs the method accepts. */
	long accepted = 0, first = -1;
	mkPair pair;
	for (long t = 0; t < o->trials; ++t) {
		if (!mkDrawPair(o, cell.dim, cell.c, cell.level, t, &pair)) {
			fprintf(stderr, "timing: %dD %s level %d trial %ld: the draw gave an invalid body\n",
				cell.dim, cname, cell.level, t);
			return -1;
		}
		sk->seen += 1;
		if (mkAccepts(m, cell.dim, &pair, msg, sizeof msg)) {
			accepted += 1;
			if (first < 0)
				first = t;
		} else {
			sk->rejected += 1;
			if (!sk->why[0])
				snprintf(sk->why, sizeof sk->why, "%s", msg);
		}
	}
	if (accepted == 0)
		return 0;
	st->cells_run += 1;

	/* Warm-up on the first accepted pair; its time sets the cell's trials. */
	double warmup = 0.0;
	mkDrawPair(o, cell.dim, cell.c, cell.level, first, &pair);
	mkResult r = mkTimedCall(m, cell.dim, &pair, cell.level, out, &warmup);
	if (r != MK_OK && st->failed_calls < MK_FAIL_REPORTS)
		fprintf(stderr, "timing: %dD %s level %d %s: warm-up call failed: %s\n", cell.dim, cname,
			cell.level, m->name, mkResult_Name(r));
	long run = mkCellTrials(accepted, warmup, o->budget, o->min_trials);
	if (run < accepted)
		st->capped_cells += 1;

	/* Pass 2: the first `run` accepted trials, back to back. */
	long done = 0;
	long points = cell.dim == 2 ? cell.level : (long)cell.level * cell.level;
	for (long t = 0; t < o->trials && done < run; ++t) {
		mkDrawPair(o, cell.dim, cell.c, cell.level, t, &pair);
		if (!mkAccepts(m, cell.dim, &pair, NULL, 0))
			continue;
		double seconds = 0.0;
		r = mkTimedCall(m, cell.dim, &pair, cell.level, out, &seconds);
		if (r != MK_OK) {
			if (st->failed_calls < MK_FAIL_REPORTS)
				fprintf(stderr, "timing: %dD %s level %d %s trial %ld failed: %s\n", cell.dim, cname,
					cell.level, m->name, t, mkResult_Name(r));
			st->failed_calls += 1;
		}
		mkCsv_Int(csv, cell.dim);
		mkCsv_Str(csv, cname);
		mkCsv_Str(csv, m->name);
		mkCsv_Int(csv, cell.level);
		mkCsv_Int(csv, points);
		mkCsv_Int(csv, t);
		mkCsv_Str(csv, mkResult_Name(r));
		mkCsv_Double(csv, seconds);
		mkCsv_Int(csv, r == MK_OK ? out->count : 0);
		mkCsv_Int(csv, o->trials);
		mkCsv_Int(csv, run);
		mkCsv_Double(csv, warmup);
		mkCsv_EndRow(csv);
		st->rows += 1;
		done += 1;
	}
	return 0;
}

/* ---- metadata helpers ------------------------------------------------------ */

/* A level list as text: START:STEP:STOP when it is an arithmetic
 * progression of three or more, else comma-separated. */
static void mkLevelsText(const mkLevels *lv, char *buf, size_t len)
{
	int ap = lv->count >= 3;
	for (int i = 2; ap && i < lv->count; ++i)
		ap = lv->v[i] - lv->v[i - 1] == lv->v[1] - lv->v[0] && lv->v[1] > lv->v[0];
	if (ap) {
		snprintf(buf, len, "%d:%d:%d", lv->v[0], lv->v[1] - lv->v[0], lv->v[lv->count - 1]);
		return;
	}
	size_t n = 0;
	buf[0] = '\0';
	for (int i = 0; i < lv->count && n < len; ++i)
		n += (size_t)snprintf(buf + n, len - n, "%s%d", i ? "," : "", lv->v[i]);
}

static void mkLoadAvg(char *buf, size_t len)
{
	snprintf(buf, len, "unknown");
	FILE *fp = fopen("/proc/loadavg", "r");
	if (!fp)
		return;
	if (fgets(buf, (int)len, fp))
		buf[strcspn(buf, "\n")] = '\0';
	fclose(fp);
}

static void mkSetVersions(mkMeta *meta)
{
	char text[128];
	mkMeta_Set(meta, "cgal_version", MK_TIMING_CGAL_VERSION);
	mkMeta_Set(meta, "gmp_version", gmp_version);
	mkMeta_Set(meta, "mpfr_version", mpfr_get_version());
	snprintf(text, sizeof text, "%s", qh_version);
	mkMeta_Set(meta, "qhull_version", text);
}

int main(int argc, char **argv)
{
	mkOptions o;
	char outbuf[128];
	int parsed = mkParseOptions(argc, argv, &o, outbuf, sizeof outbuf);
	if (parsed == 1)
		return 0;
	if (parsed != 0)
		return 2;

	if (mkPath_PrepareOutput("timing", o.out, o.force) != 0)
		return 1;
	char msg[1024];

	long total = mkCells(&o, NULL);
	mkCell *cells = malloc((size_t)(total > 0 ? total : 1) * sizeof *cells);
	mkRunStats *st = calloc(1, sizeof *st);
	if (!cells || !st) {
		fprintf(stderr, "timing: out of memory\n");
		free(cells);
		free(st);
		return 1;
	}
	mkCells(&o, cells);
	long begin, end;
	mkShard_Range(o.shard, total, &begin, &end);

	mkMeta meta;
	mkMeta_Init(&meta, "timing", MK_SCHEMA_VERSION, argc, argv);
	char text[1024], load0[128];
	mkLoadAvg(load0, sizeof load0);
	mkMeta_SetU64(&meta, "seed", o.seed);
	mkMeta_SetInt(&meta, "trials", o.trials);
	snprintf(text, sizeof text, "%d/%d", o.shard.index, o.shard.count);
	mkMeta_Set(&meta, "shard", text);
	if (end > begin)
		snprintf(text, sizeof text, "%ld..%ld of %ld (order: dim, case, level, method)", begin, end - 1, total);
	else
		snprintf(text, sizeof text, "none of %ld", total);
	mkMeta_Set(&meta, "cell_range", text);
	mkMeta_Set(&meta, "dims", o.dim_on[2] && o.dim_on[3] ? "2,3" : o.dim_on[2] ? "2" : "3");
	size_t n = 0;
	text[0] = '\0';
	for (int c = 0; c < MK_CASE_COUNT; ++c)
		if (o.case_on[c])
			n += (size_t)snprintf(text + n, sizeof text - n, "%s%s", n ? "," : "", mkCaseNames[c]);
	mkMeta_Set(&meta, "cases", text);
	n = 0;
	text[0] = '\0';
	for (int i = 0; i < mkRegistry_Count() && i < MK_METHODS_MAX && n < sizeof text; ++i)
		if (o.method_on[i])
			n += (size_t)snprintf(text + n, sizeof text - n, "%s%s", n ? "," : "", mkRegistry_At(i)->name);
	mkMeta_Set(&meta, "methods", text);
	mkLevelsText(&o.levels[2], text, sizeof text);
	mkMeta_Set(&meta, "levels_2d", o.dim_on[2] ? text : "none");
	mkLevelsText(&o.levels[3], text, sizeof text);
	mkMeta_Set(&meta, "levels_3d", o.dim_on[3] ? text : "none");
	mkMeta_Set(&meta, "level_meaning", "2D: points per body N; 3D: grid side n, n x n points per body "
		"(closed forms: points on body 1; sampled methods: samples of each body)");
	mkMeta_Set(&meta, "rotation_draw", mkRotNames[o.rotations]);
	mkMeta_Set(&meta, "set", "contact (B1 (+) (-B2))");
	mkMeta_Set(&meta, "cases_meaning", "EE: two ellipses/ellipsoids; ES: body 1 superellipse/superquadric, "
		"body 2 ellipse/ellipsoid; SQ: two superellipses/superquadrics");
	mkMeta_Set(&meta, "draw_2d", "a,b~U(1,11) eps~U(0.1,1.9) (1 for an ellipse) M=rot(2pi U)[1 s;0 1] "
		"s~U(-2,2), each body, centred at 0");
	mkMeta_Set(&meta, "draw_3d", "B1 a,b,c~U(1,10) B2 a,b,c~U(1,6) eps1,eps2~U(0.2,2.0) clamped to "
		"[1e-06, 2-1e-06] (1 for an ellipsoid), rotation only, centred at 0");
	mkMeta_Set(&meta, "rng", "xoshiro256** seeded by splitmix64, one stream per pair: "
		"(dim-2)<<62 | case<<60 | level<<32 | trial");
	struct timespec res;
	clock_getres(CLOCK_MONOTONIC, &res);
	snprintf(text, sizeof text, "CLOCK_MONOTONIC (clock_gettime), resolution %ld ns", (long)res.tv_nsec);
	mkMeta_Set(&meta, "clock", text);
	mkMeta_Set(&meta, "timed_call", "one registry run2/run3 call: parameter grid, body sampling (B1 for "
		"closed forms, both bodies for sampled methods), sum/hull/merge into a reused output set; "
		"pair drawing and row writing outside the clock");
	mkMeta_Set(&meta, "repetitions", "one call per trial (no averaging inside a row)");
	mkMeta_Set(&meta, "warm_up", "one call per (dim, case, level, method) cell on its first accepted pair "
		"before its trials, not a trial; its time is the warmup_seconds column");
	snprintf(text, sizeof text, "trials_run = T if T * warmup <= budget, else max(min_trials, "
		"floor(budget / warmup)) capped at T; budget %g s, min_trials %ld", o.budget, o.min_trials);
	mkMeta_Set(&meta, "trial_cap", text);
	mkMeta_SetDouble(&meta, "budget_seconds", o.budget);
	mkMeta_SetInt(&meta, "min_trials", o.min_trials);
	mkMeta_Set(&meta, "threads", "1 (the driver and every method run on the calling thread)");
	cpu_set_t cpus;
	if (sched_getaffinity(0, sizeof cpus, &cpus) == 0)
		mkMeta_SetInt(&meta, "cpus_allowed", CPU_COUNT(&cpus));
	mkMeta_Set(&meta, "closed_form_impl", mkImpl_Name(mkImpl_Resolve(MK_IMPL_AUTO)));
	mkMeta_Set(&meta, "loadavg_start", load0);
	mkSetVersions(&meta);

	mkCsv csv;
	if (mkCsv_Open(&csv, o.out, mkColumns, MK_COLUMN_COUNT, msg, sizeof msg) != 0) {
		fprintf(stderr, "timing: %s\n", msg);
		mkMeta_Free(&meta);
		free(cells);
		free(st);
		return 1;
	}

	mkPointSet outs[MK_METHODS_MAX];
	memset(outs, 0, sizeof outs);
	mkProgress prog;
	mkProgress_Begin(&prog, "timing", end - begin);
	int failed = 0;
	for (long i = begin; i < end && !failed; ++i) {
		int first = i == begin || cells[i - 1].dim != cells[i].dim || cells[i - 1].c != cells[i].c
			|| cells[i - 1].level != cells[i].level;
		failed = mkRunCell(&o, cells[i], first, &outs[cells[i].method], &csv, st) != 0;
		mkProgress_Add(&prog, 1);
	}
	mkProgress_End(&prog);
	for (int i = 0; i < MK_METHODS_MAX; ++i)
		mkPointSet_Free(&outs[i]);

	/* What was skipped, for the sidecar and stderr. */
	char *skipped = NULL;
	size_t skipped_len = 0;
	for (int dim = 2; dim <= 3; ++dim)
		for (int c = 0; c < MK_CASE_COUNT; ++c)
			for (int m = 0; m < mkRegistry_Count() && m < MK_METHODS_MAX; ++m) {
				const mkSkip *sk = &st->skip[dim][c][m];
				if (!sk->rejected)
					continue;
				char item[512];
				snprintf(item, sizeof item, "%dD %s %s: %ld of %ld pairs not accepted (%s)", dim,
					mkCaseNames[c], mkRegistry_At(m)->name, sk->rejected, sk->seen, sk->why);
				fprintf(stderr, "timing: skipped %s\n", item);
				mkAppend(&skipped, &skipped_len, item);
			}
	if (st->range_len)
		mkAppend(&skipped, &skipped_len, st->range_skips);
	mkMeta_Set(&meta, "skipped", skipped ? skipped : "none");
	free(skipped);
	free(st->range_skips);
	mkMeta_SetInt(&meta, "cells", end - begin);
	mkMeta_SetInt(&meta, "cells_run", st->cells_run);
	mkMeta_SetInt(&meta, "capped_cells", st->capped_cells);
	mkMeta_SetInt(&meta, "failed_calls", st->failed_calls);
	mkMeta_SetInt(&meta, "eps_clamped_draws", st->clamped_draws);
	mkLoadAvg(text, sizeof text);
	mkMeta_Set(&meta, "loadavg_end", text);
	if (st->failed_calls)
		fprintf(stderr, "timing: %ld calls failed; their rows carry the status\n", st->failed_calls);
	free(cells);
	free(st);

	return mkCsv_Finish(&csv, &meta, failed, "timing");
}
