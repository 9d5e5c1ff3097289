/* summary.c - the running-time section of the tables (paper Sec. 6.3):
 * Table 1 (which algorithm applies to which case) beside the cases the run
 * timed, the paper's outcome statements beside the measured quantity that
 * decides each, and the mean times per method and level.
 *
 * The methods are the distinct `method` values of the result file: those the
 * registry knows in registry order, then the others in order of first
 * appearance, so that a method added to the registry (or a result file of a
 * method this code has never heard of) gets its rows without a list here.
 * Only the paper's statements name methods: the proposed closed form
 * (closed-gradient), the geometric one, edge sorting and the convex hull
 * (hull-qhull; Table 1's hull row also counts the CGAL hulls). */
#include "timing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MK_CELL_MAX 256
#define MK_SHOWN_MAX 6

/* The times of one (dim, case, method, level). */
typedef struct mkCellStat {
	int dim, c, method, level;
	long points;     /* points per body */
	long n;          /* ok rows */
	long failed;     /* rows with another status */
	double mean, m2; /* Welford */
	long planned, run;
	double *v;       /* every ok time, sorted after loading */
	long nv, capv;
	double median;
} mkCellStat;

typedef struct mkTimingData {
	mkCellStat *cell;
	long count, cap;
	const char **methods; /* into the table's cells */
	int nmethods;
} mkTimingData;

static int mkIndexOf(const char *const *names, int count, const char *s)
{
	for (int i = 0; i < count; ++i)
		if (strcmp(names[i], s) == 0)
			return i;
	return -1;
}

/* ---- the methods of the data ------------------------------------------------ */

/* The distinct values of column `cmeth`: registry methods in registry order,
 * then unknown names in order of first appearance. Returns 0, or -1 out of
 * memory. */
static int mkTiming_Methods(mkTimingData *tm, const mkTable *t, int cmeth)
{
	const char **seen = malloc((size_t)(t->rows > 0 ? t->rows : 1) * sizeof *seen);
	tm->methods = malloc((size_t)(t->rows > 0 ? t->rows : 1) * sizeof *tm->methods);
	if (!seen || !tm->methods) {
		free(seen);
		return -1;
	}
	int nseen = 0;
	for (long r = 0; r < t->rows; ++r) {
		const char *s = mkTable_Str(t, r, cmeth);
		if (mkIndexOf(seen, nseen, s) < 0)
			seen[nseen++] = s;
	}
	tm->nmethods = 0;
	for (int i = 0; i < mkRegistry_Count(); ++i) {
		int k = mkIndexOf(seen, nseen, mkRegistry_At(i)->name);
		if (k >= 0)
			tm->methods[tm->nmethods++] = seen[k];
	}
	for (int k = 0; k < nseen; ++k)
		if (!mkRegistry_Find(seen[k]))
			tm->methods[tm->nmethods++] = seen[k];
	free(seen);
	return 0;
}

/* The index of a method of the data by name, or -1. */
static int mkTiming_Method(const mkTimingData *tm, const char *name)
{
	return mkIndexOf(tm->methods, tm->nmethods, name);
}

/* ---- loading ----------------------------------------------------------------- */

static const mkCellStat *mkTiming_Find(const mkTimingData *tm, int dim, int c, int method, int level)
{
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim == dim && s->c == c && s->method == method && s->level == level)
			return s;
	}
	return NULL;
}

/* The cell of a row, made when new. NULL out of memory. */
static mkCellStat *mkTiming_Cell(mkTimingData *tm, int dim, int c, int method, int level, long points)
{
	mkCellStat *s = (mkCellStat *)mkTiming_Find(tm, dim, c, method, level);
	if (s)
		return s;
	if (tm->count == tm->cap) {
		long cap = tm->cap ? 2 * tm->cap : 256;
		mkCellStat *grown = realloc(tm->cell, (size_t)cap * sizeof *grown);
		if (!grown)
			return NULL;
		tm->cell = grown;
		tm->cap = cap;
	}
	s = &tm->cell[tm->count++];
	memset(s, 0, sizeof *s);
	s->dim = dim;
	s->c = c;
	s->method = method;
	s->level = level;
	s->points = points;
	return s;
}

/* One ok time into a cell. Returns 0, or -1 out of memory. */
static int mkCellStat_Add(mkCellStat *s, double v)
{
	s->n += 1;
	double delta = v - s->mean;
	s->mean += delta / (double)s->n;
	s->m2 += delta * (v - s->mean);
	if (s->nv == s->capv) {
		long cap = s->capv ? 2 * s->capv : 16;
		double *grown = realloc(s->v, (size_t)cap * sizeof *grown);
		if (!grown)
			return -1;
		s->v = grown;
		s->capv = cap;
	}
	s->v[s->nv++] = v;
	return 0;
}

static int mkCompareDouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The cells of a timing result. Returns 0, or -1 when a column is missing
 * or memory runs out. */
static int mkTiming_Load(mkTimingData *tm, const mkTable *t)
{
	int cdim = mkTable_Col(t, "dim"), ccase = mkTable_Col(t, "case"), cmeth = mkTable_Col(t, "method");
	int clevel = mkTable_Col(t, "level"), cpts = mkTable_Col(t, "points_per_body");
	int cstat = mkTable_Col(t, "status"), csec = mkTable_Col(t, "seconds");
	int cplan = mkTable_Col(t, "trials_planned"), crun = mkTable_Col(t, "trials_run");
	if (cdim < 0 || ccase < 0 || cmeth < 0 || clevel < 0 || cpts < 0 || cstat < 0 || csec < 0 || cplan < 0
		|| crun < 0 || mkTiming_Methods(tm, t, cmeth) != 0)
		return -1;
	mkCellStat *s = NULL;
	for (long r = 0; r < t->rows; ++r) {
		int dim = (int)mkTable_Num(t, r, cdim);
		int c = mkIndexOf(mkTiming_CaseNames, MK_TIMING_CASES, mkTable_Str(t, r, ccase));
		int method = mkTiming_Method(tm, mkTable_Str(t, r, cmeth));
		int level = (int)mkTable_Num(t, r, clevel);
		if ((dim != 2 && dim != 3) || c < 0)
			continue; /* not a case of the paper */
		if (!s || s->dim != dim || s->c != c || s->method != method || s->level != level)
			s = mkTiming_Cell(tm, dim, c, method, level, (long)mkTable_Num(t, r, cpts));
		if (!s)
			return -1;
		s->planned = (long)mkTable_Num(t, r, cplan);
		s->run = (long)mkTable_Num(t, r, crun);
		double v = mkTable_Num(t, r, csec);
		if (strcmp(mkTable_Str(t, r, cstat), "ok") != 0 || !isfinite(v))
			s->failed += 1;
		else if (mkCellStat_Add(s, v) != 0)
			return -1;
	}
	for (long i = 0; i < tm->count; ++i) {
		s = &tm->cell[i];
		s->median = NAN;
		if (s->nv == 0)
			continue;
		qsort(s->v, (size_t)s->nv, sizeof *s->v, mkCompareDouble);
		s->median = s->nv % 2 ? s->v[s->nv / 2] : 0.5 * (s->v[s->nv / 2 - 1] + s->v[s->nv / 2]);
	}
	return 0;
}

static void mkTiming_Free(mkTimingData *tm)
{
	for (long i = 0; i < tm->count; ++i)
		free(tm->cell[i].v);
	free(tm->cell);
	free(tm->methods);
	memset(tm, 0, sizeof *tm);
}

/* ---- the statistics the statements use --------------------------------------- */

/* Levels (sorted, distinct) present for one dimension; returns the count. */
static int mkTiming_Levels(const mkTimingData *tm, int dim, int *levels, int max)
{
	int n = 0;
	for (long i = 0; i < tm->count; ++i) {
		if (tm->cell[i].dim != dim)
			continue;
		int v = tm->cell[i].level, k = 0;
		while (k < n && levels[k] < v)
			++k;
		if (k < n && levels[k] == v)
			continue;
		if (n == max)
			break;
		memmove(levels + k + 1, levels + k, (size_t)(n - k) * sizeof *levels);
		levels[k] = v;
		++n;
	}
	return n;
}

static double mkStd(const mkCellStat *s)
{
	return s->n ? sqrt(s->m2 / (double)s->n) : NAN; /* population std, as the paper's std(x, 1) */
}

/* Least-squares slope of log(median time) against log(points per body)
 * over the top decade of sizes present (points >= largest / 10). NaN with
 * fewer than three levels. Medians, because one call preempted by another
 * process moves a mean of few trials by milliseconds. */
static double mkSlope(const mkTimingData *tm, int dim, int c, int method, long *from, long *to)
{
	long most = 0;
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim == dim && s->c == c && s->method == method && s->n > 0 && s->points > most)
			most = s->points;
	}
	double sx = 0, sy = 0, sxx = 0, sxy = 0;
	int k = 0;
	*from = 0;
	*to = most;
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim != dim || s->c != c || s->method != method || s->n == 0 || s->points * 10 < most
			|| !(s->median > 0.0))
			continue;
		double x = log((double)s->points), y = log(s->median);
		sx += x;
		sy += y;
		sxx += x * x;
		sxy += x * y;
		if (!*from || s->points < *from)
			*from = s->points;
		++k;
	}
	if (k < 3)
		return NAN;
	double den = k * sxx - sx * sx;
	return den > 0 ? (k * sxy - sx * sy) / den : NAN;
}

/* Median time ratio a / b at the largest level where both ran; its level
 * in *level. */
static double mkRatioAtTop(const mkTimingData *tm, int dim, int c, int a, int b, int *level)
{
	int best = -1;
	double ratio = NAN;
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim != dim || s->c != c || s->method != a || s->n == 0 || s->level <= best)
			continue;
		const mkCellStat *o = mkTiming_Find(tm, dim, c, b, s->level);
		if (!o || o->n == 0)
			continue;
		best = s->level;
		ratio = s->median / o->median;
	}
	*level = best;
	return ratio;
}

/* Levels where method a's median time is below b's, out of those where both
 * ran. */
static int mkFasterCount(const mkTimingData *tm, int dim, int c, int a, int b, int *both)
{
	int faster = 0;
	*both = 0;
	for (long i = 0; i < tm->count; ++i) {
		const mkCellStat *s = &tm->cell[i];
		if (s->dim != dim || s->c != c || s->method != a || s->n == 0)
			continue;
		const mkCellStat *o = mkTiming_Find(tm, dim, c, b, s->level);
		if (!o || o->n == 0)
			continue;
		*both += 1;
		faster += s->median < o->median;
	}
	return faster;
}

/* ---- the paper's statements --------------------------------------------------- */

/* The methods the statements name (-1 when the data lack one). */
typedef struct mkNamed {
	int cg, geo, es, qh;
} mkNamed;

static void mkStatement(mkDoc *d, const char *statement, int dim, int c, const char *where,
	const char *value, const char *rule, int agrees)
{
	char dimtext[8];
	snprintf(dimtext, sizeof dimtext, "%dD", dim);
	const char *row[7] = { statement, dimtext, mkTiming_CaseNames[c], where, value, rule,
		agrees ? "agrees" : "**disagrees**" };
	mkDoc_Row(d, row);
}

/* The statements of one (dim, case) that the data can decide. Returns
 * whether the closed form's or the hull's could (the paper's main claims). */
static int mkTiming_CaseStatements(mkDoc *d, const mkTimingData *tm, const mkNamed *k, int dim, int c)
{
	long from, to;
	int level, any = 0;
	char where[MK_CELL_MAX], value[MK_CELL_MAX];
	/* 1. closed form linear */
	double sc = mkSlope(tm, dim, c, k->cg, &from, &to);
	if (!isnan(sc)) {
		snprintf(where, sizeof where, "slope of closed-gradient, %ld–%ld points", from, to);
		snprintf(value, sizeof value, "%.2f", sc);
		mkStatement(d, "closed form (proposed) is linear in N", dim, c, where, value, "\\|slope − 1\\| ≤ 0.25",
			fabs(sc - 1.0) <= 0.25);
		any = 1;
	}
	/* 2. convex hull grows much faster */
	double s = mkSlope(tm, dim, c, k->qh, &from, &to);
	double q = mkRatioAtTop(tm, dim, c, k->qh, k->cg, &level);
	if (!isnan(s) && !isnan(sc) && !isnan(q)) {
		snprintf(where, sizeof where, "slopes of hull-qhull and closed-gradient; time ratio at level %d", level);
		snprintf(value, sizeof value, "%.2f vs %.2f; %.3g", s, sc, q);
		mkStatement(d, "convex hull grows much faster", dim, c, where, value,
			"slopes differ by ≥ 0.5 and ratio ≥ 10", s - sc >= 0.5 && q >= 10.0);
		any = 1;
	}
	if (dim == 2) {
		/* 3. edge sorting linear */
		s = mkSlope(tm, dim, c, k->es, &from, &to);
		if (!isnan(s)) {
			snprintf(where, sizeof where, "slope of edge-sort, %ld–%ld points", from, to);
			snprintf(value, sizeof value, "%.2f", s);
			mkStatement(d, "edge sorting is linear", dim, c, where, value, "\\|slope − 1\\| ≤ 0.25",
				fabs(s - 1.0) <= 0.25);
		}
		/* 4./5. edge sorting faster for SQ, slower for ellipses */
		int both = 0, faster = mkFasterCount(tm, dim, c, k->es, k->cg, &both);
		if (both > 0 && c != MK_TIMING_ES) {
			int want_faster = c == MK_TIMING_SQ;
			snprintf(value, sizeof value, "%d of %d", faster, both);
			mkStatement(d, want_faster ? "edge sorting is faster than the closed form for two superellipses"
				: "edge sorting is slower than the closed form for ellipses", dim, c,
				"levels where edge-sort is faster than closed-gradient", value,
				want_faster ? "faster at more than half" : "slower at more than half",
				want_faster ? 2 * faster > both : 2 * (both - faster) > both);
		}
	}
	/* 6. geometric about as fast as proposed (EE, ES) */
	q = mkRatioAtTop(tm, dim, c, k->geo, k->cg, &level);
	if (!isnan(q) && c != MK_TIMING_SQ) {
		snprintf(where, sizeof where, "geometric / closed-gradient time at level %d", level);
		snprintf(value, sizeof value, "%.3g", q);
		mkStatement(d, "closed-form geometric is about as fast as the proposed one", dim, c, where, value,
			"ratio in [0.5, 2]", q >= 0.5 && q <= 2.0);
	}
	return any;
}

static void mkTiming_Statements(mkDoc *d, const mkTimingData *tm, mkTally *tally)
{
	static const char *const head[] = { "published statement (Figs. 5–8)", "dim", "case",
		"reproduced quantity", "value", "rule", "verdict" };
	mkNamed k = { mkTiming_Method(tm, "closed-gradient"), mkTiming_Method(tm, "geometric"),
		mkTiming_Method(tm, "edge-sort"), mkTiming_Method(tm, "hull-qhull") };
	mkDoc_TableBegin(d, "Running time: the paper's outcome statements (no published numbers) and the "
		"measured quantity that decides each, from per-level medians (robust to a call preempted by "
		"another process; the means are in the tables below). Slopes are least-squares slopes of "
		"log(median time) against log(points per body) over the top decade of sizes (1 = linear).", 7, head);
	int any = 0;
	for (int dim = 2; dim <= 3; ++dim)
		for (int c = 0; c < MK_TIMING_CASES; ++c)
			any |= mkTiming_CaseStatements(d, tm, &k, dim, c);
	if (!any) {
		const char *row[7] = { "all statements", "—", "—", "—", mkNotYet, "—", "—" };
		mkDoc_Row(d, row);
	}
	mkDoc_TableEnd(d);
	/* Six statements in the paper's text. */
	for (int i = 0; i < 6; ++i)
		mkTally_Add(tally, any);
}

/* ---- Table 1 and the means ----------------------------------------------------- */

/* "✓ ✓ —": whether any of the methods has timed rows in each case. */
static void mkTiming_Cases(const mkTimingData *tm, int dim, const char *const *names, char *buf, size_t len)
{
	buf[0] = '\0';
	for (int c = 0; c < MK_TIMING_CASES; ++c) {
		int has = 0;
		for (int k = 0; k < 3 && names[k]; ++k) {
			int m = mkTiming_Method(tm, names[k]);
			for (long j = 0; j < tm->count && m >= 0; ++j) {
				const mkCellStat *s = &tm->cell[j];
				has = has || (s->dim == dim && s->c == c && s->method == m && s->n > 0);
			}
		}
		size_t n = strlen(buf);
		snprintf(buf + n, len - n, "%s%s", c ? " " : "", has ? "✓" : "—");
	}
}

static void mkTiming_Applicability(mkDoc *d, const mkTimingData *tm)
{
	static const struct { const char *name, *dims, *exact, *cases, *methods[3]; } alg[] = {
		{ "Convex hull (Quickhull; also CGAL)", "Any", "", "✓ ✓ ✓",
			{ "hull-qhull", "hull-cgal-epick", "hull-cgal-epeck" } },
		{ "Edge sorting", "2D", "", "✓ ✓ ✓", { "edge-sort", NULL, NULL } },
		{ "Closed-form geometric", "Any", "✓", "✓ ✓ —", { "geometric", NULL, NULL } },
		{ "Closed-form (proposed): closed-gradient", "Any", "✓", "✓ ✓ ✓", { "closed-gradient", NULL, NULL } },
	};
	static const char *const head[] = { "algorithm", "published: dims", "exact", "published: EE ES SQ",
		"reproduced: 2D EE ES SQ", "reproduced: 3D EE ES SQ" };
	mkDoc_TableBegin(d, "Table 1 of the paper (applicable algorithms per case) beside the cases this run "
		"timed (✓: rows present; —: the method was skipped, see the sidecar's `skipped`).", 6, head);
	for (size_t i = 0; i < sizeof alg / sizeof alg[0]; ++i) {
		char rep[4][32];
		mkTiming_Cases(tm, 2, alg[i].methods, rep[2], sizeof rep[2]);
		mkTiming_Cases(tm, 3, alg[i].methods, rep[3], sizeof rep[3]);
		const char *row[6] = { alg[i].name, alg[i].dims, alg[i].exact[0] ? alg[i].exact : "—", alg[i].cases,
			rep[2], rep[3] };
		mkDoc_Row(d, row);
	}
	mkDoc_TableEnd(d);
}

/* The levels a means table shows: the paper's round sizes (2D N = 20, 100,
 * ..., 500; 3D n = 5, 10, 20, ..., 50) when all were run, otherwise up to
 * `want` levels spread over those present (first, last, evenly between). */
static int mkShownLevels(int dim, const int *levels, int n, int *out, int want)
{
	static const int round2[6] = { 20, 100, 200, 300, 400, 500 }, round3[6] = { 5, 10, 20, 30, 40, 50 };
	const int *round = dim == 2 ? round2 : round3;
	int found = 0;
	for (int i = 0; i < 6; ++i)
		for (int j = 0; j < n; ++j)
			found += levels[j] == round[i];
	if (found == 6 && want >= 6) {
		memcpy(out, round, 6 * sizeof *round);
		return 6;
	}
	if (n <= want) {
		memcpy(out, levels, (size_t)n * sizeof *levels);
		return n;
	}
	for (int i = 0; i < want; ++i)
		out[i] = levels[(int)lround((double)i * (n - 1) / (want - 1))];
	return want;
}

/* One row of a means table: "mean ± std" per shown level, a bracketed
 * count for a capped cell. Returns 0 when the method has no times there. */
static int mkTiming_MeansRow(mkDoc *d, const mkTimingData *tm, int dim, int c, int m, const int *shown, int k)
{
	int any = 0;
	char cells[MK_SHOWN_MAX][MK_CELL_MAX];
	const char *row[2 + MK_SHOWN_MAX] = { mkTiming_CaseNames[c], tm->methods[m] };
	for (int i = 0; i < k; ++i) {
		const mkCellStat *s = mkTiming_Find(tm, dim, c, m, shown[i]);
		if (!s || s->n == 0) {
			snprintf(cells[i], MK_CELL_MAX, "—");
		} else {
			char a[64];
			mkFmt_Time(a, sizeof a, s->mean, mkStd(s));
			if (s->run < s->planned)
				snprintf(cells[i], MK_CELL_MAX, "%s [%ld]", a, s->n);
			else
				snprintf(cells[i], MK_CELL_MAX, "%s", a);
			any = 1;
		}
		row[2 + i] = cells[i];
	}
	if (any)
		mkDoc_Row(d, row);
	return any;
}

static void mkTiming_Means(mkDoc *d, const mkTimingData *tm, int dim)
{
	int levels[1024], shown[MK_SHOWN_MAX];
	int n = mkTiming_Levels(tm, dim, levels, 1024);
	if (n == 0)
		return;
	int k = mkShownLevels(dim, levels, n, shown, MK_SHOWN_MAX);
	const char *head[2 + MK_SHOWN_MAX] = { "case", "method" };
	char names[MK_SHOWN_MAX][48];
	for (int i = 0; i < k; ++i) {
		if (dim == 2)
			snprintf(names[i], sizeof names[i], "N = %d", shown[i]);
		else
			snprintf(names[i], sizeof names[i], "n = %d (%d pts)", shown[i], shown[i] * shown[i]);
		head[2 + i] = names[i];
	}
	char caption[512];
	snprintf(caption, sizeof caption, "%dD mean running time ± population std per call, at %d of the %d "
		"levels run (%s). A count in brackets is the trials a capped cell ran (see `trials_run`).", dim, k, n,
		dim == 2 ? "N points per body" : "n × n points per body");
	mkDoc_TableBegin(d, caption, 2 + k, head);
	for (int c = 0; c < MK_TIMING_CASES; ++c)
		for (int m = 0; m < tm->nmethods; ++m)
			mkTiming_MeansRow(d, tm, dim, c, m, shown, k);
	mkDoc_TableEnd(d);
}

/* ---- the section ---------------------------------------------------------------- */

/* The run's conditions from the sidecar, as a list. */
static void mkTiming_Conditions(mkDoc *d, const mkMeta *m)
{
	static const char *const keys[] = { "rotation_draw", "clock", "timed_call", "warm_up", "trial_cap",
		"threads", "closed_form_impl", "cpu_model", "cpus_allowed", "loadavg_start", "loadavg_end", "skipped" };
	static const char *const label[] = { "Rotation draw (3D)", "Clock", "One measurement", "Warm-up",
		"Trial cap", "Threads", "Closed-form kernel", "CPU", "CPUs allowed", "Load average at start",
		"Load average at end", "Skipped" };
	for (size_t i = 0; i < sizeof keys / sizeof keys[0]; ++i) {
		const char *v = mkMeta_Get(m, keys[i]);
		mkDoc_Item(d, "%s: %s%s", label[i], v ? v : "not recorded",
			strcmp(keys[i], "rotation_draw") == 0 && v && strcmp(v, "paper") == 0
			? " (the reference code's normalised quaternion with four U(0,1) entries, not uniform on SO(3))"
			: "");
	}
	mkDoc_EndItems(d);
}

void mkTiming_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	static const char *const columns[] = { "dim", "case", "method", "level", "points_per_body", "status",
		"seconds", "trials_planned", "trials_run", NULL };
	mkSection s;
	mkTimingData tm;
	memset(&tm, 0, sizeof tm);
	int usable = mkSection_Begin(&s, d, "Running time (paper §6.3, Table 1, Figs. 5–8)", dir, "timing.csv",
		columns, "The paper publishes no running-time numbers for this section, only the statements listed "
		"below, none of which is checked here yet.") && mkTiming_Load(&tm, &s.t) == 0;
	if (usable) {
		mkTiming_Conditions(d, &s.m);
		mkDoc_Para(d, "The paper ran MATLAB R2020b on an Intel Xeon at 2.80 GHz and reports curves, not "
			"numbers; absolute times here are not comparable with its figures, only the shapes and orderings "
			"that its text states.");
	}
	mkTiming_Applicability(d, &tm);
	mkTiming_Statements(d, &tm, tally);
	if (usable) {
		mkTiming_Means(d, &tm, 2);
		mkTiming_Means(d, &tm, 3);
		long failed = 0;
		for (long i = 0; i < tm.count; ++i)
			failed += tm.cell[i].failed;
		if (failed)
			mkDoc_Para(d, "**%ld calls failed** (status other than ok); they are left out of the means.", failed);
	}
	mkTiming_Free(&tm);
	mkSection_End(&s);
}
