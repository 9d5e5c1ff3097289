/* tradeoff.c - the speed-against-accuracy sweep (tradeoff.h). */
#include "tradeoff.h"

#include <pthread.h>
#include <stdatomic.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const mkTradeoff_CaseNames[MK_TRADEOFF_CASES] = { "EE", "ES", "SQ" };
const char *const mkTradeoff_Columns[] = { "dim", "case", "method", "set", "n", "trial", "points", "seconds",
	"hausdorff_abs", "hausdorff_rel", "area_rel", "nonfinite", "body1", "body2", "status", NULL };

/* The two samplings of the closed form beyond the registry's (tradeoff.h). */
enum { MK_SAMPLING_NORMAL = 0, MK_SAMPLING_SPACED = 1, MK_SAMPLINGS = 2 };
static const char *const mkSamplingNames[MK_SAMPLINGS] = { "closed-normal@normal-angles", "closed-normal@spaced" };

static int mkCurves(void);
static const char *mkCurveName(int curve);

void mkTradeoffOptions_Default(mkTradeoffOptions *o)
{
	static const int l2[] = { 8, 32, 128, 512, 2048, 8192, 32768, 65536 };
	static const int l3[] = { 4, 8, 16, 32, 64, 128, 256 };
	memset(o, 0, sizeof *o);
	o->trials = 20;
	o->seed = 2022;
	o->dim_on[2] = o->dim_on[3] = 1;
	o->level_count[2] = (int)MK_COUNT(l2);
	memcpy(o->level[2], l2, sizeof l2);
	o->level_count[3] = (int)MK_COUNT(l3);
	memcpy(o->level[3], l3, sizeof l3);
	o->budget = 1.0;
	o->repeats = 5;
	o->threads = 2;
	for (int i = 0; i < MK_TRADEOFF_CURVES_MAX; ++i)
		o->curve_on[i] = 1;
}

int mkTradeoff_ParseLevels(void *options, const char *text, char *msg, size_t msglen)
{
	mkTradeoffOptions *o = options;
	int dim = strncmp(text, "2d=", 3) == 0 ? 2 : strncmp(text, "3d=", 3) == 0 ? 3 : 0;
	long lo = dim == 2 ? 3 : 2, hi = dim == 2 ? 1000000 : 4096;
	int v[MK_TRADEOFF_LEVELS_MAX], count = 0;
	const char *s = text + 3;
	while (dim && count < MK_TRADEOFF_LEVELS_MAX) {
		char *end;
		long x = strtol(s, &end, 10);
		if (end == s || (*end != ',' && *end != '\0'))
			break;
		if (x < lo || x > hi || (count > 0 && x <= v[count - 1])) {
			snprintf(msg, msglen, "is out of range: must be rising %dd levels in [%ld, %ld] (%ld is not)", dim, lo,
				hi, x);
			return -1;
		}
		v[count++] = (int)x;
		if (*end == '\0') {
			o->level_count[dim] = count;
			memcpy(o->level[dim], v, (size_t)count * sizeof *v);
			return 0;
		}
		s = end + 1;
	}
	snprintf(msg, msglen, "is not allowed: must be 2d=LIST or 3d=LIST, LIST at most %d comma-separated integers",
		MK_TRADEOFF_LEVELS_MAX);
	return -1;
}

void mkTradeoff_Start(mkTradeoffOptions *o, const mkRun *run, int dims, mkMeta *meta)
{
	o->trials = run->trials;
	o->seed = run->seed;
	char text[1024];
	for (int dim = 2; dim <= 3; ++dim) {
		o->dim_on[dim] = dims == 2 || dims == dim - 2;
		size_t len = 0;
		for (int l = 0; l < o->level_count[dim] && len < sizeof text; ++l)
			len += (size_t)snprintf(text + len, sizeof text - len, "%s%d", l ? "," : "", o->level[dim][l]);
		mkMeta_Set(meta, dim == 2 ? "levels_2d" : "levels_3d", o->dim_on[dim] ? text : "off");
	}
	char on[2048];
	size_t len = 0;
	on[0] = '\0';
	for (int i = 0; i < mkCurves() && len < sizeof on; ++i)
		if (o->curve_on[i])
			len += (size_t)snprintf(on + len, sizeof on - len, "%s%s", len ? "," : "", mkCurveName(i));
	mkMeta_Set(meta, "methods", on);
	mkMeta_SetDouble(meta, "budget_seconds", o->budget);
	mkMeta_SetInt(meta, "repeats", o->repeats);
	mkMeta_SetInt(meta, "threads", o->threads);
	mkMeta_Set(meta, "set", "contact");
	mkMeta_Set(meta, "clock", "CLOCK_MONOTONIC wall time, median of the repeats; the calls of a level are timed one "
		"after another with nothing else of the run working, then their points are measured on --threads threads");
	mkMeta_Set(meta, "error_measure", "mink/error.h, true area/volume once per pair");
	mkMeta_Set(meta, "draw_2d", "a,b~U(0,10) (redrawn below 1e-3) eps~U(0.1,1.9) M=rot(2pi U)[1 s;0 1] s~U(-2,2)");
	mkMeta_Set(meta, "draw_3d", "B1 axes U(1,10)^3, B2 U(1,6)^3, eps1,eps2~U(0.1,1.9), paper quaternion");
}

uint64_t mkTradeoff_Stream(int dim, int c, long trial)
{
	return (uint64_t)dim << 40 | (uint64_t)c << 32 | (uint64_t)trial;
}

static mkBody2 mkDrawBody2(mkRng *r, int super)
{
	const mkShapeRange2 range = { { 0.0, 10.0 }, { 0.0, 10.0 }, { super ? 0.1 : 1.0, super ? 1.9 : 1.0 } };
	mkShape2 s;
	do
		s = mkDraw_Shape2(r, &range);
	while (s.a < 1e-3 || s.b < 1e-3);
	return mkBody2_Make(s, mkDraw_RotShear2(r, 2.0, NULL, NULL), (mkVec2){ 0, 0 });
}

static mkBody3 mkDrawBody3(mkRng *r, double amax, int super)
{
	double e0 = super ? 0.1 : 1.0, e1 = super ? 1.9 : 1.0;
	const mkShapeRange3 range = { { 1.0, amax }, { 1.0, amax }, { 1.0, amax }, { e0, e1 }, { e0, e1 } };
	mkShape3 s = mkDraw_Shape3(r, &range);
	return mkBody3_Make(s, mkDraw_Rotation3(r, MK_ROT_PAPER), (mkVec3){ 0, 0, 0 });
}

void mkTradeoff_Pair2(uint64_t seed, int c, long trial, mkBody2 *b1, mkBody2 *b2)
{
	mkRng rng;
	mkRng_Seed(&rng, seed, mkTradeoff_Stream(2, c, trial));
	*b1 = mkDrawBody2(&rng, c != MK_TRADEOFF_EE);
	*b2 = mkDrawBody2(&rng, c == MK_TRADEOFF_SQ);
}

void mkTradeoff_Pair3(uint64_t seed, int c, long trial, mkBody3 *b1, mkBody3 *b2)
{
	mkRng rng;
	mkRng_Seed(&rng, seed, mkTradeoff_Stream(3, c, trial));
	*b1 = mkDrawBody3(&rng, 10.0, c != MK_TRADEOFF_EE);
	*b2 = mkDrawBody3(&rng, 6.0, c == MK_TRADEOFF_SQ);
}

void mkTradeoff_Spec2(mkBody2 b, char *buf, size_t len)
{
	mkSpec2_Format(b, buf, len);
}

void mkTradeoff_Spec3(mkBody3 b, char *buf, size_t len)
{
	mkSpec3_Format(b, buf, len);
}

/* The pairs of one (dim, case) and their true volumes. */
typedef struct mkPairs {
	int dim, c;
	long count;
	mkBody2 *p1, *p2;
	mkBody3 *q1, *q2;
	double *truth, *bound;
	mkResult *rc; /* of each pair's true area / volume */
} mkPairs;

/* Scratch parameter vectors for the extra samplings. */
typedef struct mkScratch {
	long cap;
	double *u;
} mkScratch;

/* A text that grows, for the sidecar's lists. */
typedef struct mkNotes {
	char text[16384];
	size_t len;
} mkNotes;

static void mkNotes_Add(mkNotes *n, int dim, int c, const char *method, const char *what)
{
	if (n->len + 1 < sizeof n->text)
		n->len += (size_t)snprintf(n->text + n->len, sizeof n->text - n->len, "%s%dD %s %s: %s", n->len ? "; " : "",
			dim, mkTradeoff_CaseNames[c], method, what);
	if (n->len >= sizeof n->text)
		n->len = sizeof n->text - 1;
	fprintf(stderr, "tradeoff: %dD %s %s: %s\n", dim, mkTradeoff_CaseNames[c], method, what);
}

static int mkCurves(void)
{
	int n = mkRegistry_Count() + MK_SAMPLINGS;
	return n < MK_TRADEOFF_CURVES_MAX ? n : MK_TRADEOFF_CURVES_MAX;
}

static const char *mkCurveName(int curve)
{
	int r = mkRegistry_Count();
	return curve < r ? mkRegistry_At(curve)->name : mkSamplingNames[curve - r];
}

int mkTradeoff_ParseMethods(void *on, const char *text, char *msg, size_t msglen)
{
	const char *names[MK_TRADEOFF_CURVES_MAX];
	char list[4096];
	if (!mkRegistry_Resolve(text, list, sizeof list, msg, msglen))
		return -1;
	text = list;
	int n = mkCurves();
	for (int i = 0; i < n; ++i)
		names[i] = mkCurveName(i);
	return mkArg_NameList(text, names, n, (int *)on, msg, msglen);
}

/* One call of curve `curve` on pair k at level n into out. */
static mkResult mkCall(const mkPairs *p, long k, int curve, int n, mkScratch *s, mkPointSet *out)
{
	int r = mkRegistry_Count(), dim = p->dim;
	if (curve < r) {
		const mkMethod *m = mkRegistry_At(curve);
		return dim == 2 ? m->run2(p->p1[k], p->p2[k], MK_SET_CONTACT, n, out)
		                : m->run3(p->q1[k], p->q2[k], MK_SET_CONTACT, n, out);
	}
	long count = dim == 2 ? n : (long)n * n;
	if (count > s->cap) {
		double *u = realloc(s->u, 3 * (size_t)count * sizeof *u);
		if (!u)
			return MK_ERR_MEMORY;
		s->u = u;
		s->cap = count;
	}
	mkResult rc = mkPointSet_Resize(out, dim, (int)count);
	double *ux = s->u, *uy = s->u + count, *uz = s->u + 2 * count;
	mkSumOptions opt = mkSumOptions_Default();
	opt.form = MK_FORM_NORMAL;
	opt.param = curve - r == MK_SAMPLING_NORMAL ? MK_PARAM_NORMAL : MK_PARAM_SURFACE;
	if (rc == MK_OK && dim == 2) {
		rc = curve - r == MK_SAMPLING_NORMAL ? mkSample2_Angles(n, ux, uy) : mkSample2_Spaced(n, p->p1[k].shape.eps, ux, uy);
		if (rc == MK_OK)
			rc = mkSum2_Batch(p->p1[k], p->p2[k], &opt, ux, uy, n, out->x, out->y, NULL, NULL);
	} else if (rc == MK_OK) {
		mkShape3 sh = p->q1[k].shape;
		rc = curve - r == MK_SAMPLING_NORMAL ? mkSample3_Grid(n, ux, uy, uz)
		                                     : mkSample3_Spaced(n, sh.eps1, sh.eps2, ux, uy, uz);
		if (rc == MK_OK)
			rc = mkSum3_Batch(p->q1[k], p->q2[k], &opt, ux, uy, uz, (int)count, out->x, out->y, out->z, NULL, NULL,
				NULL);
	}
	return rc;
}

/* 1 when the curve runs on this pair at level n; otherwise 0 and why. */
static int mkCurveRuns(const mkPairs *p, long k, int curve, int n, char *msg, size_t len)
{
	if (curve >= mkRegistry_Count())
		return 1;
	const mkMethod *m = mkRegistry_At(curve);
	int ok = p->dim == 2 ? mkMethod2_Accepts(m, p->p1[k], p->p2[k], MK_SET_CONTACT, msg, len)
	                     : mkMethod3_Accepts(m, p->q1[k], p->q2[k], MK_SET_CONTACT, msg, len);
	return ok && mkMethod_CheckN(m, p->dim, n, msg, len);
}

static int mkCompareDouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

double mkTradeoff_Median(double *v, long n)
{
	qsort(v, (size_t)n, sizeof *v, mkCompareDouble);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Seconds spent in the error measure this run (for the sidecar). */
static double mkTradeoff_MeasureSeconds;

/* Run `fn(ctx, k)` for k = 0..count-1 on `threads` threads (the calling one
 * among them), each k once, in no fixed order; whatever fn writes must be
 * indexed by k, so that the result does not depend on the schedule. */
typedef struct mkPool {
	void (*fn)(void *ctx, long k);
	void *ctx;
	long count;
	atomic_long next;
} mkPool;

static void *mkPool_Worker(void *arg)
{
	mkPool *pool = arg;
	for (long k; (k = atomic_fetch_add(&pool->next, 1)) < pool->count;)
		pool->fn(pool->ctx, k);
	return NULL;
}

static void mkParallel(int threads, long count, void (*fn)(void *ctx, long k), void *ctx)
{
	mkPool pool;
	pool.fn = fn;
	pool.ctx = ctx;
	pool.count = count;
	atomic_init(&pool.next, 0);
	pthread_t th[MK_TRADEOFF_THREADS_MAX];
	int started = 0;
	for (int t = 1; t < threads && t < count && t < MK_TRADEOFF_THREADS_MAX; ++t) {
		if (pthread_create(&th[started], NULL, mkPool_Worker, &pool) != 0)
			break; /* fewer threads: the calling thread does the rest */
		++started;
	}
	mkPool_Worker(&pool);
	for (int t = 0; t < started; ++t)
		pthread_join(th[t], NULL);
}

/* Time pair k at level n (median of the repeats) into *seconds; the points
 * of the last call are left in out. An external method's time is the one it
 * reports (mink/external.h), without its process and pipes. Single-threaded:
 * nothing else of this run is working while a call is timed. Returns the
 * status of the row: "ok", or the failure, which is the method's (its row
 * says so), never the run's. */
static const char *mkTimeCall(const mkTradeoffOptions *o, const mkPairs *p, long k, int curve, int n, mkScratch *s,
	mkPointSet *out, double *seconds)
{
	double t[64];
	long reps = o->repeats < 64 ? o->repeats : 64, done = 0;
	mkResult rc = MK_OK;
	const mkMethod *m = curve < mkRegistry_Count() ? mkRegistry_At(curve) : NULL;
	for (; done < reps && rc == MK_OK; ++done) {
		double t0 = mkClock_Wall();
		rc = mkCall(p, k, curve, n, s, out);
		t[done] = mkClock_Wall() - t0;
		if (rc == MK_OK && m && mkExternal_Is(m))
			t[done] = mkExternal_Seconds(m);
		if (done == 0 && t[0] > 0.05)
			reps = 1;
	}
	if (rc != MK_OK) {
		int ext = m && mkExternal_Is(m);
		fprintf(stderr, "tradeoff: %dD %s %s n = %d pair %ld: the call failed (%s%s%s)\n", p->dim,
			mkTradeoff_CaseNames[p->c], mkCurveName(curve), n, k, mkResult_Name(rc), ext ? ": " : "",
			ext ? mkExternal_Message(m) : "");
		*seconds = NAN;
		out->count = 0;
		return ext ? mkExternal_Status(m) : mkResult_Name(rc);
	}
	*seconds = mkTradeoff_Median(t, done);
	return "ok";
}

/* A copy of a point set (untimed), into dst's own storage. */
static int mkPointSet_Copy(mkPointSet *dst, const mkPointSet *src)
{
	if (mkPointSet_Resize(dst, src->dim, src->count) != MK_OK)
		return -1;
	size_t bytes = (size_t)src->count * sizeof *src->x;
	memcpy(dst->x, src->x, bytes);
	memcpy(dst->y, src->y, bytes);
	if (src->dim == 3)
		memcpy(dst->z, src->z, bytes);
	return 0;
}

/* One level of one curve: the pairs that ran, their points, times and
 * errors (indexed by pair). */
typedef struct mkLevel {
	const mkPairs *p;
	long count;      /* pairs that ran */
	long *pair;      /* their indices, rising */
	mkPointSet *pts; /* by pair index */
	double *seconds;
	mkDeviation *err;
	mkResult *rc;
	const char **status; /* the call's: "ok" or its failure (then not measured) */
} mkLevel;

static void mkMeasureOne(void *ctx, long i)
{
	mkLevel *L = ctx;
	const mkPairs *p = L->p;
	long k = L->pair[i];
	mkDeviationOptions eo = { 0.0, p->truth[k], p->bound[k] };
	if (strcmp(L->status[k], "ok") != 0) {
		L->rc[k] = MK_OK;
		memset(&L->err[k], 0, sizeof L->err[k]);
		L->err[k].hausdorff_abs = L->err[k].hausdorff_rel = L->err[k].area_rel = NAN;
		return;
	}
	L->rc[k] = p->dim == 2 ? mkDeviation2_Measure(p->p1[k], p->p2[k], MK_SET_CONTACT, &L->pts[k], &eo, &L->err[k])
	                       : mkDeviation3_Measure(p->q1[k], p->q2[k], MK_SET_CONTACT, &L->pts[k], &eo, &L->err[k]);
}

/* Write the row of pair k (measured) to csv. */
static void mkWriteRow(const mkPairs *p, long k, int curve, int n, int points, double seconds, const mkDeviation *e,
	const char *status, mkCsv *csv)
{
	char b1[512], b2[512];
	if (p->dim == 2) {
		mkTradeoff_Spec2(p->p1[k], b1, sizeof b1);
		mkTradeoff_Spec2(p->p2[k], b2, sizeof b2);
	} else {
		mkTradeoff_Spec3(p->q1[k], b1, sizeof b1);
		mkTradeoff_Spec3(p->q2[k], b2, sizeof b2);
	}
	mkCsv_Int(csv, p->dim);
	mkCsv_Str(csv, mkTradeoff_CaseNames[p->c]);
	mkCsv_Str(csv, mkCurveName(curve));
	mkCsv_Str(csv, mkSet_Name(MK_SET_CONTACT));
	mkCsv_Int(csv, n);
	mkCsv_Int(csv, k);
	mkCsv_Int(csv, points);
	mkCsv_Double(csv, seconds);
	mkCsv_Double(csv, e->hausdorff_abs);
	mkCsv_Double(csv, e->hausdorff_rel);
	mkCsv_Double(csv, e->area_rel);
	mkCsv_Int(csv, e->nonfinite);
	mkCsv_Str(csv, b1);
	mkCsv_Str(csv, b2);
	mkCsv_Str(csv, status);
	mkCsv_EndRow(csv);
}

/* Measure the pairs of L on o->threads threads, then write their rows in
 * pair order. */
static int mkLevel_Finish(const mkTradeoffOptions *o, mkLevel *L, int curve, int n, mkCsv *csv)
{
	const mkPairs *p = L->p;
	double m0 = mkClock_Wall();
	mkParallel(o->threads, L->count, mkMeasureOne, L);
	mkTradeoff_MeasureSeconds += mkClock_Wall() - m0;
	for (long i = 0; i < L->count; ++i) {
		long k = L->pair[i];
		if (L->rc[k] != MK_OK) {
			fprintf(stderr, "tradeoff: %dD %s %s n = %d pair %ld: the error measure failed (%s)\n", p->dim,
				mkTradeoff_CaseNames[p->c], mkCurveName(curve), n, k, mkResult_Name(L->rc[k]));
			return -1;
		}
		mkWriteRow(p, k, curve, n, L->pts[k].count, L->seconds[k], &L->err[k], L->status[k], csv);
	}
	return 0;
}

/* Every level of one curve on the pairs, rising until the budget cuts. Per
 * level, first every pair's call is timed (one thread), its points kept;
 * then the points are measured on o->threads threads; the rows follow in
 * pair order, so the CSV does not depend on the number of threads. */
static int mkCurveRun(const mkTradeoffOptions *o, const mkPairs *p, int curve, mkScratch *s, mkPointSet *out,
	mkCsv *csv, mkNotes *skipped, mkNotes *cut)
{
	const char *name = mkCurveName(curve);
	if (!o->curve_on[curve])
		return 0;
	if (curve < mkRegistry_Count() && !(mkRegistry_At(curve)->flags & (p->dim == 2 ? MK_METHOD_2D : MK_METHOD_3D)))
		return 0;
	size_t np = (size_t)p->count;
	mkLevel L;
	memset(&L, 0, sizeof L);
	L.p = p;
	L.pair = malloc(np * sizeof *L.pair);
	L.pts = calloc(np, sizeof *L.pts);
	L.seconds = malloc(np * sizeof *L.seconds);
	L.err = malloc(np * sizeof *L.err);
	L.rc = malloc(np * sizeof *L.rc);
	L.status = malloc(np * sizeof *L.status);
	int failed = !L.pair || !L.pts || !L.seconds || !L.err || !L.rc || !L.status;
	for (int l = 0; l < o->level_count[p->dim] && !failed; ++l) {
		int n = o->level[p->dim][l];
		long refused = 0;
		char msg[256], why[320];
		/* One untimed call on the first pair the method takes: a warm-up, and
		 * the budget's probe, so that a level is never started whose calls
		 * each take longer than the budget. */
		int stop = 0;
		for (long k = 0; k < p->count && o->budget > 0; ++k) {
			if (!mkCurveRuns(p, k, curve, n, msg, sizeof msg))
				continue;
			double t0 = mkClock_Wall(), probe;
			mkResult rc = mkCall(p, k, curve, n, s, out);
			probe = mkClock_Wall() - t0;
			if (rc == MK_OK && probe > o->budget) {
				snprintf(msg, sizeof msg, "n = %d and above not run (one call took %.3g s > budget %g s)", n, probe,
					o->budget);
				mkNotes_Add(cut, p->dim, p->c, name, msg);
				stop = 1;
			}
			break;
		}
		if (stop)
			break;
		L.count = 0;
		long fails = 0;
		for (long k = 0; k < p->count && !failed; ++k) {
			if (!mkCurveRuns(p, k, curve, n, msg, sizeof msg)) {
				if (refused++ == 0)
					snprintf(why, sizeof why, "%s", msg);
				continue;
			}
			L.status[k] = mkTimeCall(o, p, k, curve, n, s, out, &L.seconds[k]);
			if (strcmp(L.status[k], "ok") != 0 && fails++ == 0) {
				snprintf(msg, sizeof msg, "n = %d: a call failed (%s; the rows' status says which)", n, L.status[k]);
				mkNotes_Add(skipped, p->dim, p->c, name, msg);
			}
			if (mkPointSet_Copy(&L.pts[k], out) != 0) {
				fprintf(stderr, "tradeoff: out of memory\n");
				failed = 1;
			}
			L.pair[L.count++] = k;
		}
		if (!failed)
			failed = mkLevel_Finish(o, &L, curve, n, csv) != 0;
		if (!failed && refused > 0) {
			/* The method refuses the pair type (all levels) or this n (all higher n too). */
			char note[400];
			snprintf(note, sizeof note, "n = %d%s, %ld of %ld pairs not run (%s)", n,
				refused == p->count ? " and above" : "", refused, p->count, why);
			mkNotes_Add(skipped, p->dim, p->c, name, note);
			if (refused == p->count)
				break;
		}
	}
	for (size_t k = 0; L.pts && k < np; ++k)
		mkPointSet_Free(&L.pts[k]);
	free(L.pair);
	free(L.pts);
	free(L.seconds);
	free(L.err);
	free(L.rc);
	free(L.status);
	return failed ? -1 : 0;
}

/* Draw the pairs of (dim, case) and their true volumes. */
/* The true area / volume of pair k (a task of mkParallel). */
static void mkPairs_Truth(void *ctx, long k)
{
	mkPairs *p = ctx;
	p->rc[k] = p->dim == 2 ? mkDeviation2_Area(p->p1[k], p->p2[k], MK_SET_CONTACT, &p->truth[k], &p->bound[k])
	                       : mkDeviation3_Volume(p->q1[k], p->q2[k], MK_SET_CONTACT, &p->truth[k], &p->bound[k]);
}

static int mkPairs_Make(const mkTradeoffOptions *o, int dim, int c, mkPairs *p)
{
	memset(p, 0, sizeof *p);
	p->dim = dim;
	p->c = c;
	p->count = o->trials;
	size_t n = (size_t)o->trials;
	p->p1 = malloc(n * sizeof *p->p1);
	p->p2 = malloc(n * sizeof *p->p2);
	p->q1 = malloc(n * sizeof *p->q1);
	p->q2 = malloc(n * sizeof *p->q2);
	p->truth = malloc(2 * n * sizeof *p->truth);
	if (!p->p1 || !p->p2 || !p->q1 || !p->q2 || !p->truth)
		return -1;
	p->bound = p->truth + n;
	p->rc = malloc(n * sizeof *p->rc);
	if (!p->rc)
		return -1;
	for (long k = 0; k < p->count; ++k)
		if (dim == 2)
			mkTradeoff_Pair2(o->seed, c, k, &p->p1[k], &p->p2[k]);
		else
			mkTradeoff_Pair3(o->seed, c, k, &p->q1[k], &p->q2[k]);
	mkParallel(o->threads, p->count, mkPairs_Truth, p);
	for (long k = 0; k < p->count; ++k)
		if (p->rc[k] != MK_OK) {
			fprintf(stderr, "tradeoff: %dD %s pair %ld: the true %s failed (%s)\n", dim, mkTradeoff_CaseNames[c], k,
				dim == 2 ? "area" : "volume", mkResult_Name(p->rc[k]));
			return -1;
		}
	return 0;
}

static void mkPairs_Free(mkPairs *p)
{
	free(p->p1);
	free(p->p2);
	free(p->q1);
	free(p->q2);
	free(p->truth);
	free(p->rc);
}

int mkTradeoff_Run(const mkTradeoffOptions *o, mkCsv *csv, mkMeta *meta)
{
	static mkNotes skipped, cut;
	skipped.len = cut.len = 0;
	skipped.text[0] = cut.text[0] = '\0';
	mkScratch s = { 0, NULL };
	mkPointSet out = { 0, 0, 0, NULL, NULL, NULL };
	int failed = 0;
	double truth_seconds = 0.0;
	mkTradeoff_MeasureSeconds = 0.0;
	for (int dim = 2; dim <= 3 && !failed; ++dim)
		for (int c = 0; c < MK_TRADEOFF_CASES && o->dim_on[dim] && !failed; ++c) {
			mkPairs p;
			double t0 = mkClock_Wall();
			failed = mkPairs_Make(o, dim, c, &p) != 0;
			truth_seconds += mkClock_Wall() - t0;
			for (int curve = 0; curve < mkCurves() && !failed; ++curve)
				failed = mkCurveRun(o, &p, curve, &s, &out, csv, &skipped, &cut) != 0;
			mkPairs_Free(&p);
		}
	free(s.u);
	mkPointSet_Free(&out);
	mkMeta_Set(meta, "skipped", skipped.len ? skipped.text : "none");
	mkMeta_Set(meta, "cut", cut.len ? cut.text : "none");
	mkMeta_SetDouble(meta, "truth_seconds", truth_seconds);
	mkMeta_SetDouble(meta, "measure_seconds", mkTradeoff_MeasureSeconds);
	return failed ? -1 : 0;
}
