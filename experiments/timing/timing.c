/* timing.c - the running-time experiment: options, draws, cells, the timed
 * calls and the sidecar (what is measured is in timing.h). */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT, clock_getres */
#include "timing.h"

#include <gmp.h>
#include <libqhull_r/libqhull_r.h>
#include <mpfr.h>

#include <errno.h>
#include <math.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/external.h>
#include <time.h>

#define MK_LEVEL2_MIN 3
#define MK_LEVEL2_MAX 100000
#define MK_LEVEL3_MIN 3
#define MK_LEVEL3_MAX 3000
#define MK_FAIL_REPORTS 5

#ifndef MK_TIMING_CGAL_VERSION
#define MK_TIMING_CGAL_VERSION "unknown"
#endif

const char *const mkTiming_CaseNames[MK_TIMING_CASES] = { "EE", "ES", "SQ" };

const char *const mkTiming_Columns[] = {
	"dim", "case", "method", "level", "points_per_body", "trial", "status", "seconds",
	"points_out", "trials_planned", "trials_run", "warmup_seconds", NULL
};

/* ---- options --------------------------------------------------------------- */

void mkTimingOptions_Default(mkTimingOptions *o)
{
	memset(o, 0, sizeof *o);
	o->trials = 100;
	o->seed = 2022;
	o->dim_on[2] = o->dim_on[3] = 1;
	for (int c = 0; c < MK_TIMING_CASES; ++c)
		o->case_on[c] = 1;
	for (int i = 0; i < mkRegistry_Count() && i < MK_TIMING_METHODS_MAX; ++i)
		o->method_on[i] = 1;
	for (int n = 20; n <= 500; n += 10)
		o->levels[2].v[o->levels[2].count++] = n;
	for (int n = 5; n <= 50; n += 5)
		o->levels[3].v[o->levels[3].count++] = n;
	o->rotations = MK_ROT_PAPER;
	o->budget = 2.0;
	o->min_trials = 3;
}

/* One item of a level list: "V" or "START:STEP:STOP". Returns 0, or -1 on
 * a malformed item; *s moves past it. */
static int mkLevelItem(const char **s, long part[3], int *parts)
{
	*parts = 0;
	for (;;) {
		char *end = NULL;
		if (**s < '0' || **s > '9' || *parts == 3)
			return -1;
		errno = 0;
		long v = strtol(*s, &end, 10);
		if (errno == ERANGE)
			return -1;
		part[(*parts)++] = v;
		*s = end;
		if (**s != ':')
			break;
		++*s;
	}
	return *parts == 2 ? -1 : 0;
}

int mkTiming_ParseLevels(void *levels, const char *text, char *msg, size_t msglen)
{
	int dim = strncmp(text, "2d=", 3) == 0 ? 2 : strncmp(text, "3d=", 3) == 0 ? 3 : 0;
	int lo = dim == 2 ? MK_LEVEL2_MIN : MK_LEVEL3_MIN, hi = dim == 2 ? MK_LEVEL2_MAX : MK_LEVEL3_MAX;
	mkTimingLevels lv;
	lv.count = 0;
	const char *s = text + (dim ? 3 : 0);
	while (dim) {
		long part[3];
		int parts;
		if (mkLevelItem(&s, part, &parts) != 0)
			break;
		long start = part[0], step = parts == 3 ? part[1] : 1, stop = parts == 3 ? part[2] : part[0];
		if (step < 1 || stop < start)
			break;
		for (long v = start; v <= stop; v += step) {
			if (v < lo || v > hi) {
				snprintf(msg, msglen, "is out of range: must be %dd levels in [%d, %d] (%ld is not)", dim,
					lo, hi, v);
				return -1;
			}
			if (lv.count == MK_TIMING_LEVELS_MAX) {
				snprintf(msg, msglen, "is too long: must be at most %d %dd levels", MK_TIMING_LEVELS_MAX, dim);
				return -1;
			}
			lv.v[lv.count++] = (int)v;
		}
		if (*s == '\0') {
			((mkTimingLevels *)levels)[dim] = lv;
			return 0;
		}
		if (*s++ != ',')
			break;
	}
	snprintf(msg, msglen, "is not allowed: must be 2d=LIST or 3d=LIST, LIST comma-separated integers or "
		"START:STEP:STOP ranges (STEP >= 1, STOP >= START)");
	return -1;
}

int mkTiming_ParseCases(void *on, const char *text, char *msg, size_t msglen)
{
	return mkArg_NameList(text, mkTiming_CaseNames, MK_TIMING_CASES, (int *)on, msg, msglen);
}

int mkTiming_ParseMethods(void *on, const char *text, char *msg, size_t msglen)
{
	const char *names[MK_TIMING_METHODS_MAX];
	char list[4096];
	if (!mkRegistry_Resolve(text, list, sizeof list, msg, msglen))
		return -1;
	int count = mkRegistry_Names(names, MK_TIMING_METHODS_MAX);
	/* "all" means the table's methods and the external ones named so far. */
	return mkArg_NameList(list, names, count, (int *)on, msg, msglen);
}

/* ---- draws ----------------------------------------------------------------- */

/* One random pair and what its draw clamped. */
typedef struct mkPair {
	mkBody2 p1, p2;
	mkBody3 q1, q2;
	int clamped;
} mkPair;

/* The stream of one pair: dimension, case, level and trial packed into
 * disjoint bit fields (dim - 2 in bits 62-63, case in 60-61, level < 2^28 in
 * 32-59, trial < 2^32 in 0-31), hence injective. */
static uint64_t mkTiming_Stream(int dim, int c, int level, long trial)
{
	return ((uint64_t)(dim - 2) << 62) | ((uint64_t)c << 60) | ((uint64_t)level << 32) | (uint64_t)trial;
}

static mkBody2 mkDrawBody2(mkRng *r, int super)
{
	mkShapeRange2 range = { { 1.0, 11.0 }, { 1.0, 11.0 }, { super ? 0.1 : 1.0, super ? 1.9 : 1.0 } };
	mkShape2 s = mkDraw_Shape2(r, &range);
	mkVec2 t = { 0.0, 0.0 };
	return mkBody2_Make(s, mkDraw_RotShear2(r, 2.0, NULL, NULL), t);
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
	double elo = super ? 0.2 : 1.0, ehi = super ? 2.0 : 1.0;
	mkShapeRange3 range = { { 1.0, amax }, { 1.0, amax }, { 1.0, amax }, { elo, ehi }, { elo, ehi } };
	mkShape3 s = mkDraw_Shape3(r, &range);
	s.eps1 = mkClampEps(s.eps1, clamped);
	s.eps2 = mkClampEps(s.eps2, clamped);
	mkMat3 R = mkDraw_Rotation3(r, rot);
	if (!mkMat3_IsFinite(R))
		R = mkMat3_Identity(); /* all four entries zero: probability 2^-212 */
	mkVec3 t = { 0.0, 0.0, 0.0 };
	return mkBody3_Make(s, R, t);
}

/* The pair of (dim, case, level, trial). Returns 1 when both bodies are
 * valid (always, for these ranges; checked all the same). */
static int mkDrawPair(const mkTimingOptions *o, int dim, int c, int level, long trial, mkPair *p)
{
	mkRng rng;
	mkRng_Seed(&rng, o->seed, mkTiming_Stream(dim, c, level, trial));
	memset(p, 0, sizeof *p);
	int super1 = c != MK_TIMING_EE, super2 = c == MK_TIMING_SQ;
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

/* ---- the cells ------------------------------------------------------------- */

long mkTiming_Cells(const mkTimingOptions *o, mkTimingCell *cells)
{
	long count = 0;
	int methods = mkRegistry_Count();
	for (int dim = 2; dim <= 3; ++dim)
		for (int c = 0; c < MK_TIMING_CASES && o->dim_on[dim]; ++c)
			for (int l = 0; l < o->levels[dim].count && o->case_on[c]; ++l)
				for (int m = 0; m < methods && m < MK_TIMING_METHODS_MAX; ++m) {
					if (!o->method_on[m])
						continue;
					if (cells) {
						mkTimingCell cell = { dim, c, o->levels[dim].v[l], m };
						cells[count] = cell;
					}
					++count;
				}
	return count;
}

/* Per (dim, case, method): pairs the method did not accept, and why. */
typedef struct mkSkip {
	long rejected, seen;
	char why[256];
} mkSkip;

struct mkTimingRun {
	mkPointSet out[MK_TIMING_METHODS_MAX];
	mkSkip skip[4][MK_TIMING_CASES][MK_TIMING_METHODS_MAX];
	char *range_skips;     /* "; "-joined out-of-range cells */
	size_t range_len;
	long capped_cells, cells_run, failed_calls, rows, clamped_draws;
};

mkTimingRun *mkTimingRun_New(void)
{
	return calloc(1, sizeof(mkTimingRun));
}

void mkTimingRun_Free(mkTimingRun *tr)
{
	if (!tr)
		return;
	for (int i = 0; i < MK_TIMING_METHODS_MAX; ++i)
		mkPointSet_Free(&tr->out[i]);
	free(tr->range_skips);
	free(tr);
}

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

/* ---- the timed calls ------------------------------------------------------- */

/* One timed call: wall seconds around it. */
static mkResult mkTimedCall(const mkMethod *m, int dim, const mkPair *p, int n, mkPointSet *out,
	double *seconds)
{
	double t0 = mkClock_Wall();
	mkResult r = dim == 2 ? m->run2(p->p1, p->p2, MK_SET_CONTACT, n, out)
		: m->run3(p->q1, p->q2, MK_SET_CONTACT, n, out);
	*seconds = mkClock_Wall() - t0;
	/* An external method's time is its own measure of the job, without its
	 * process and pipes (mink/external.h). */
	if (mkExternal_Is(m))
		*seconds = mkExternal_Seconds(m);
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

/* Whether a cell runs at all: its method runs in its dimension and level.
 * Records the skip when not. */
static int mkCellRuns(const mkTimingOptions *o, mkTimingCell cell, mkTimingRun *tr)
{
	const mkMethod *m = mkRegistry_At(cell.method);
	mkSkip *sk = &tr->skip[cell.dim][cell.c][cell.method];
	char msg[256];
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
		snprintf(item, sizeof item, "%dD %s level %d %s: %s", cell.dim, mkTiming_CaseNames[cell.c], cell.level,
			m->name, msg);
		fprintf(stderr, "timing: skipped %s\n", item);
		mkAppend(&tr->range_skips, &tr->range_len, item);
		return 0;
	}
	return 1;
}

/* Pass 1 of a cell: how many pairs the method accepts and the first of
 * them (-1: none). Returns -1 on an invalid draw (message printed). */
static long mkCellAccepted(const mkTimingOptions *o, mkTimingCell cell, mkTimingRun *tr, long *first)
{
	const mkMethod *m = mkRegistry_At(cell.method);
	mkSkip *sk = &tr->skip[cell.dim][cell.c][cell.method];
	char msg[256];
	long accepted = 0;
	mkPair pair;
	*first = -1;
	for (long t = 0; t < o->trials; ++t) {
		if (!mkDrawPair(o, cell.dim, cell.c, cell.level, t, &pair)) {
			fprintf(stderr, "timing: %dD %s level %d trial %ld: the draw gave an invalid body\n",
				cell.dim, mkTiming_CaseNames[cell.c], cell.level, t);
			return -1;
		}
		sk->seen += 1;
		if (mkAccepts(m, cell.dim, &pair, msg, sizeof msg)) {
			accepted += 1;
			if (*first < 0)
				*first = t;
		} else {
			sk->rejected += 1;
			if (!sk->why[0])
				snprintf(sk->why, sizeof sk->why, "%s", msg);
		}
	}
	return accepted;
}

static void mkTiming_WriteRow(mkCsv *csv, mkTimingCell cell, const mkMethod *m, long trial, mkResult r,
	double seconds, long points_out, long planned, long run, double warmup)
{
	const char *method = m->name;
	/* An external method's failure says what happened: crashed, timeout, ... */
	const char *status = r != MK_OK && mkExternal_Is(m) ? mkExternal_Status(m) : mkResult_Name(r);
	mkCsv_Int(csv, cell.dim);
	mkCsv_Str(csv, mkTiming_CaseNames[cell.c]);
	mkCsv_Str(csv, method);
	mkCsv_Int(csv, cell.level);
	mkCsv_Int(csv, cell.dim == 2 ? cell.level : (long)cell.level * cell.level);
	mkCsv_Int(csv, trial);
	mkCsv_Str(csv, status);
	mkCsv_Double(csv, seconds);
	mkCsv_Int(csv, points_out);
	mkCsv_Int(csv, planned);
	mkCsv_Int(csv, run);
	mkCsv_Double(csv, warmup);
	mkCsv_EndRow(csv);
}

int mkTiming_RunCell(const mkTimingOptions *o, mkTimingCell cell, int first_of_group, mkTimingRun *tr,
	mkCsv *csv)
{
	const mkMethod *m = mkRegistry_At(cell.method);
	const char *cname = mkTiming_CaseNames[cell.c];
	mkPointSet *out = &tr->out[cell.method];
	mkPair pair;
	if (first_of_group)
		for (long t = 0; t < o->trials; ++t)
			if (mkDrawPair(o, cell.dim, cell.c, cell.level, t, &pair))
				tr->clamped_draws += pair.clamped;
	if (!mkCellRuns(o, cell, tr))
		return 0;
	long first, accepted = mkCellAccepted(o, cell, tr, &first);
	if (accepted <= 0)
		return (int)accepted;
	tr->cells_run += 1;

	/* Warm-up on the first accepted pair; its time sets the cell's trials. */
	double warmup = 0.0;
	mkDrawPair(o, cell.dim, cell.c, cell.level, first, &pair);
	mkResult r = mkTimedCall(m, cell.dim, &pair, cell.level, out, &warmup);
	if (r != MK_OK && tr->failed_calls < MK_FAIL_REPORTS)
		fprintf(stderr, "timing: %dD %s level %d %s: warm-up call failed: %s\n", cell.dim, cname,
			cell.level, m->name, mkResult_Name(r));
	long run = mkCellTrials(accepted, warmup, o->budget, o->min_trials);
	if (run < accepted)
		tr->capped_cells += 1;

	/* Pass 2: the first `run` accepted trials, back to back. */
	for (long t = 0, done = 0; t < o->trials && done < run; ++t) {
		mkDrawPair(o, cell.dim, cell.c, cell.level, t, &pair);
		if (!mkAccepts(m, cell.dim, &pair, NULL, 0))
			continue;
		double seconds = 0.0;
		r = mkTimedCall(m, cell.dim, &pair, cell.level, out, &seconds);
		if (r != MK_OK) {
			if (tr->failed_calls < MK_FAIL_REPORTS)
				fprintf(stderr, "timing: %dD %s level %d %s trial %ld failed: %s%s%s\n", cell.dim, cname,
					cell.level, m->name, t, mkResult_Name(r), mkExternal_Is(m) ? ": " : "",
					mkExternal_Is(m) ? mkExternal_Message(m) : "");
			tr->failed_calls += 1;
		}
		mkTiming_WriteRow(csv, cell, m, t, r, seconds, r == MK_OK ? out->count : 0, o->trials, run,
			warmup);
		tr->rows += 1;
		done += 1;
	}
	return 0;
}

/* ---- the sidecar ----------------------------------------------------------- */

/* A level list as text: START:STEP:STOP when it is an arithmetic
 * progression of three or more, else comma-separated. */
static void mkLevelsText(const mkTimingLevels *lv, char *buf, size_t len)
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

/* What was chosen: the cells, dims, cases, methods and levels. */
static void mkTiming_MetaChoice(mkMeta *meta, const mkTimingOptions *o, long begin, long end, long total)
{
	char text[4096];
	if (end > begin)
		snprintf(text, sizeof text, "%ld..%ld of %ld (order: dim, case, level, method)", begin, end - 1, total);
	else
		snprintf(text, sizeof text, "none of %ld", total);
	mkMeta_Set(meta, "cell_range", text);
	mkMeta_Set(meta, "dims", o->dim_on[2] && o->dim_on[3] ? "2,3" : o->dim_on[2] ? "2" : "3");
	size_t n = 0;
	text[0] = '\0';
	for (int c = 0; c < MK_TIMING_CASES; ++c)
		if (o->case_on[c])
			n += (size_t)snprintf(text + n, sizeof text - n, "%s%s", n ? "," : "", mkTiming_CaseNames[c]);
	mkMeta_Set(meta, "cases", text);
	n = 0;
	text[0] = '\0';
	for (int i = 0; i < mkRegistry_Count() && i < MK_TIMING_METHODS_MAX && n < sizeof text; ++i)
		if (o->method_on[i])
			n += (size_t)snprintf(text + n, sizeof text - n, "%s%s", n ? "," : "", mkRegistry_At(i)->name);
	mkMeta_Set(meta, "methods", text);
	mkLevelsText(&o->levels[2], text, sizeof text);
	mkMeta_Set(meta, "levels_2d", o->dim_on[2] ? text : "none");
	mkLevelsText(&o->levels[3], text, sizeof text);
	mkMeta_Set(meta, "levels_3d", o->dim_on[3] ? text : "none");
}

void mkTiming_MetaBegin(mkMeta *meta, const mkTimingOptions *o, long begin, long end, long total)
{
	char text[1024], load0[128];
	mkClock_LoadAverage(load0, sizeof load0);
	mkTiming_MetaChoice(meta, o, begin, end, total);
	mkMeta_Set(meta, "level_meaning", "2D: points per body N; 3D: grid side n, n x n points per body "
		"(closed forms: points on body 1; sampled methods: samples of each body)");
	mkMeta_Set(meta, "rotation_draw", mkRotDraw_Names[o->rotations]);
	mkMeta_Set(meta, "set", "contact (B1 (+) (-B2))");
	mkMeta_Set(meta, "cases_meaning", "EE: two ellipses/ellipsoids; ES: body 1 superellipse/superquadric, "
		"body 2 ellipse/ellipsoid; SQ: two superellipses/superquadrics");
	mkMeta_Set(meta, "draw_2d", "a,b~U(1,11) eps~U(0.1,1.9) (1 for an ellipse) M=rot(2pi U)[1 s;0 1] "
		"s~U(-2,2), each body, centred at 0");
	mkMeta_Set(meta, "draw_3d", "B1 a,b,c~U(1,10) B2 a,b,c~U(1,6) eps1,eps2~U(0.2,2.0) clamped to "
		"[1e-06, 2-1e-06] (1 for an ellipsoid), rotation only, centred at 0");
	mkMeta_Set(meta, "rng", "xoshiro256** seeded by splitmix64, one stream per pair: "
		"(dim-2)<<62 | case<<60 | level<<32 | trial");
	struct timespec res;
	clock_getres(CLOCK_MONOTONIC, &res);
	snprintf(text, sizeof text, "CLOCK_MONOTONIC (clock_gettime), resolution %ld ns", (long)res.tv_nsec);
	mkMeta_Set(meta, "clock", text);
	mkMeta_Set(meta, "timed_call", "one registry run2/run3 call: parameter grid, body sampling (B1 for "
		"closed forms, both bodies for sampled methods), sum/hull/merge into a reused output set; "
		"pair drawing and row writing outside the clock");
	mkMeta_Set(meta, "repetitions", "one call per trial (no averaging inside a row)");
	mkMeta_Set(meta, "warm_up", "one call per (dim, case, level, method) cell on its first accepted pair "
		"before its trials, not a trial; its time is the warmup_seconds column");
	snprintf(text, sizeof text, "trials_run = T if T * warmup <= budget, else max(min_trials, "
		"floor(budget / warmup)) capped at T; budget %g s, min_trials %ld", o->budget, o->min_trials);
	mkMeta_Set(meta, "trial_cap", text);
	mkMeta_SetDouble(meta, "budget_seconds", o->budget);
	mkMeta_SetInt(meta, "min_trials", o->min_trials);
	mkMeta_Set(meta, "threads", "1 (the driver and every method run on the calling thread)");
	cpu_set_t cpus;
	if (sched_getaffinity(0, sizeof cpus, &cpus) == 0)
		mkMeta_SetInt(meta, "cpus_allowed", CPU_COUNT(&cpus));
	mkMeta_Set(meta, "closed_form_impl", mkImpl_Name(mkImpl_Resolve(MK_IMPL_AUTO)));
	mkMeta_Set(meta, "loadavg_start", load0);
	mkMeta_Set(meta, "cgal_version", MK_TIMING_CGAL_VERSION);
	mkMeta_Set(meta, "gmp_version", gmp_version);
	mkMeta_Set(meta, "mpfr_version", mpfr_get_version());
	snprintf(text, sizeof text, "%s", qh_version);
	mkMeta_Set(meta, "qhull_version", text);
}

void mkTiming_MetaEnd(mkMeta *meta, mkTimingRun *tr, long cells)
{
	/* What was skipped, for the sidecar and stderr. */
	char *skipped = NULL, text[128];
	size_t skipped_len = 0;
	for (int dim = 2; dim <= 3; ++dim)
		for (int c = 0; c < MK_TIMING_CASES; ++c)
			for (int m = 0; m < mkRegistry_Count() && m < MK_TIMING_METHODS_MAX; ++m) {
				const mkSkip *sk = &tr->skip[dim][c][m];
				if (!sk->rejected)
					continue;
				char item[512];
				snprintf(item, sizeof item, "%dD %s %s: %ld of %ld pairs not accepted (%s)", dim,
					mkTiming_CaseNames[c], mkRegistry_At(m)->name, sk->rejected, sk->seen, sk->why);
				fprintf(stderr, "timing: skipped %s\n", item);
				mkAppend(&skipped, &skipped_len, item);
			}
	if (tr->range_len)
		mkAppend(&skipped, &skipped_len, tr->range_skips);
	mkMeta_Set(meta, "skipped", skipped ? skipped : "none");
	free(skipped);
	mkMeta_SetInt(meta, "cells", cells);
	mkMeta_SetInt(meta, "cells_run", tr->cells_run);
	mkMeta_SetInt(meta, "capped_cells", tr->capped_cells);
	mkMeta_SetInt(meta, "failed_calls", tr->failed_calls);
	mkMeta_SetInt(meta, "eps_clamped_draws", tr->clamped_draws);
	mkClock_LoadAverage(text, sizeof text);
	mkMeta_Set(meta, "loadavg_end", text);
	if (tr->failed_calls)
		fprintf(stderr, "timing: %ld calls failed; their rows carry the status\n", tr->failed_calls);
}
