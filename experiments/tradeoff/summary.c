/* summary.c - the tradeoff section of results/tables.md (mkTradeoff_Summary
 * in tradeoff.h): from the rows, the medians over the pairs of each
 * (dim, case, method, n), then per (dim, case) the time to reach each
 * error, the closed form's speed-up at equal error, its error ratio at
 * equal time and the baseline points it does not dominate. */
#include "tradeoff.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/registry.h>

/* One point of a curve: the medians over the pairs of a level. */
typedef struct mkPoint {
	int dim, c, n;
	const char *method;
	double sec, err;
	long rows;
} mkPoint;

typedef struct mkCurveData {
	mkPoint *p;
	long count;
} mkCurveData;

static const double mkThresholds[] = { 1e-2, 1e-3, 1e-6, 1e-9 };

/* A closed form is a registry method that returns boundary points and is
 * not a published peer (neither MK_METHOD_SAMPLED nor MK_METHOD_BASELINE),
 * decided by its flags, not its name; the rows name a closed form sampled
 * otherwise as "NAME@sampling". Sampled methods, baselines and methods the
 * registry does not know (external ones) are the baselines. */
static int mkIsClosed(const char *method)
{
	char name[128];
	size_t len = strcspn(method, "@");
	if (len >= sizeof name)
		return 0;
	memcpy(name, method, len);
	name[len] = '\0';
	const mkMethod *m = mkRegistry_Find(name);
	return m && !(m->flags & (MK_METHOD_SAMPLED | MK_METHOD_BASELINE));
}

/* The points in order of first appearance; NaN errors sort last (a median
 * with a non-finite pair is then the larger one). */
static int mkCurveData_Load(mkCurveData *cd, const mkTable *t)
{
	int cd_ = mkTable_Col(t, "dim"), cc = mkTable_Col(t, "case"), cm = mkTable_Col(t, "method"),
	    cn = mkTable_Col(t, "n"), cs = mkTable_Col(t, "seconds"), ce = mkTable_Col(t, "hausdorff_rel");
	long *group = malloc((size_t)(t->rows + 1) * sizeof *group);
	double *sec = malloc((size_t)(t->rows + 1) * sizeof *sec), *err = malloc((size_t)(t->rows + 1) * sizeof *err);
	cd->p = malloc((size_t)(t->rows + 1) * sizeof *cd->p);
	cd->count = 0;
	if (!group || !sec || !err || !cd->p) {
		free(group), free(sec), free(err);
		return -1;
	}
	for (long r = 0; r < t->rows; ++r) {
		mkPoint q = { (int)mkTable_Num(t, r, cd_), 0, (int)mkTable_Num(t, r, cn), mkTable_Str(t, r, cm), 0, 0, 0 };
		for (int c = 0; c < MK_TRADEOFF_CASES; ++c)
			if (strcmp(mkTable_Str(t, r, cc), mkTradeoff_CaseNames[c]) == 0)
				q.c = c;
		long g = cd->count;
		for (long i = cd->count - 1; i >= 0; --i)
			if (cd->p[i].dim == q.dim && cd->p[i].c == q.c && cd->p[i].n == q.n && strcmp(cd->p[i].method, q.method) == 0) {
				g = i;
				break;
			}
		if (g == cd->count)
			cd->p[cd->count++] = q;
		group[r] = g;
		cd->p[g].rows++;
	}
	for (long g = 0; g < cd->count; ++g) {
		long m = 0;
		for (long r = 0; r < t->rows; ++r)
			if (group[r] == g) {
				sec[m] = mkTable_Num(t, r, cs);
				double e = mkTable_Num(t, r, ce);
				err[m++] = isnan(e) ? INFINITY : e;
			}
		cd->p[g].sec = mkTradeoff_Median(sec, m);
		cd->p[g].err = mkTradeoff_Median(err, m);
	}
	free(group), free(sec), free(err);
	return 0;
}

/* The fastest point of `method` (NULL: the closed forms, "": the baselines)
 * in (dim, c) with err <= thr; NULL when none. */
static const mkPoint *mkFastest(const mkCurveData *cd, int dim, int c, const char *method, double thr)
{
	const mkPoint *best = NULL;
	for (long i = 0; i < cd->count; ++i) {
		const mkPoint *q = &cd->p[i];
		int take = method == NULL ? mkIsClosed(q->method) : method[0] == '\0' ? !mkIsClosed(q->method)
		                                                                       : strcmp(q->method, method) == 0;
		if (take && q->dim == dim && q->c == c && q->err <= thr && (!best || q->sec < best->sec))
			best = q;
	}
	return best;
}

/* The largest n of `method` in (dim, c). */
static int mkLargestN(const mkCurveData *cd, int dim, int c, const char *method)
{
	int n = 0;
	for (long i = 0; i < cd->count; ++i)
		if (cd->p[i].dim == dim && cd->p[i].c == c && strcmp(cd->p[i].method, method) == 0 && cd->p[i].n > n)
			n = cd->p[i].n;
	return n;
}

/* The time-to-error table of (dim, c). */
static void mkTimeTable(mkDoc *d, const mkCurveData *cd, int dim, int c)
{
	static const char *const head[] = { "method", "err ≤ 1e-2", "err ≤ 1e-3", "err ≤ 1e-6", "err ≤ 1e-9" };
	char caption[128], cells[5][96];
	snprintf(caption, sizeof caption, "%dD %s: median seconds per call to reach a median hausdorff_rel", dim,
		mkTradeoff_CaseNames[c]);
	mkDoc_TableBegin(d, caption, 5, head);
	for (long i = 0; i < cd->count; ++i) {
		const mkPoint *q = &cd->p[i];
		int first = 1;
		for (long j = 0; j < i && first; ++j)
			first = !(cd->p[j].dim == dim && cd->p[j].c == c && strcmp(cd->p[j].method, q->method) == 0);
		if (q->dim != dim || q->c != c || !first)
			continue;
		const char *row[5] = { q->method, cells[1], cells[2], cells[3], cells[4] };
		for (int k = 0; k < 4; ++k) {
			const mkPoint *f = mkFastest(cd, dim, c, q->method, mkThresholds[k]);
			if (f)
				snprintf(cells[k + 1], sizeof cells[k + 1], "%.3g s (n = %d)", f->sec, f->n);
			else
				snprintf(cells[k + 1], sizeof cells[k + 1], "not reached up to n = %d", mkLargestN(cd, dim, c, q->method));
		}
		mkDoc_Row(d, row);
	}
	mkDoc_TableEnd(d);
}

/* The closed form against the fastest baseline in (dim, c): speed-up at
 * each error level, error ratio at equal time, the baseline points the
 * closed form does not dominate. */
static void mkCompare(mkDoc *d, const mkCurveData *cd, int dim, int c)
{
	const char *cn = mkTradeoff_CaseNames[c];
	for (int k = 0; k < 4; ++k) {
		const mkPoint *fc = mkFastest(cd, dim, c, NULL, mkThresholds[k]);
		const mkPoint *fb = mkFastest(cd, dim, c, "", mkThresholds[k]);
		if (fc && fb && fb->sec < fc->sec)
			mkDoc_Item(d, "%dD %s, error ≤ %.0e: **a baseline is faster**: %s (n = %d, %.3g s) is %.3g times as fast "
				"as the fastest closed form (%s, n = %d, %.3g s).", dim, cn, mkThresholds[k], fb->method, fb->n,
				fb->sec, fc->sec / fb->sec, fc->method, fc->n, fc->sec);
		else if (fc && fb)
			mkDoc_Item(d, "%dD %s, error ≤ %.0e: the closed form (%s, n = %d, %.3g s) is %.3g times as fast as the "
				"fastest baseline (%s, n = %d, %.3g s).", dim, cn, mkThresholds[k], fc->method, fc->n, fc->sec,
				fb->sec / fc->sec, fb->method, fb->n, fb->sec);
		else if (fc)
			mkDoc_Item(d, "%dD %s, error ≤ %.0e: the closed form reaches it (%s, n = %d, %.3g s); no baseline does.",
				dim, cn, mkThresholds[k], fc->method, fc->n, fc->sec);
		else
			mkDoc_Item(d, "%dD %s, error ≤ %.0e: the closed form does not reach it%s.", dim, cn, mkThresholds[k],
				fb ? "; a baseline does" : ", nor does any baseline");
	}
	double worst = INFINITY;
	const mkPoint *at = NULL;
	long wins = 0, shown = 0, dominated = 0;
	for (long i = 0; i < cd->count; ++i) {
		const mkPoint *b = &cd->p[i];
		if (b->dim != dim || b->c != c || mkIsClosed(b->method))
			continue;
		double best = INFINITY;
		for (long j = 0; j < cd->count; ++j) {
			const mkPoint *q = &cd->p[j];
			if (q->dim == dim && q->c == c && mkIsClosed(q->method) && q->sec <= b->sec && q->err < best)
				best = q->err;
		}
		if (best <= b->err) {
			double ratio = best > 0 ? b->err / best : INFINITY;
			++dominated;
			if (ratio < worst || !at)
				worst = ratio, at = b;
			continue;
		}
		if (wins++ < 8)
			shown++, mkDoc_Item(d, "%dD %s: a baseline wins at %s n = %d (%.3g s, error %.3g): no closed-form point "
				"is as fast and as accurate.", dim, cn, b->method, b->n, b->sec, b->err);
	}
	if (wins > shown)
		mkDoc_Item(d, "%dD %s: %ld more baseline points win in the same way.", dim, cn, wins - shown);
	if (at)
		mkDoc_Item(d, "%dD %s, equal time: over the %ld baseline points the closed form dominates, its best error "
			"in no more time is smaller by a factor of at least %.3g (at %s n = %d, %.3g s).", dim, cn, dominated,
			worst, at->method, at->n, at->sec);
	mkDoc_EndItems(d);
}

void mkTradeoff_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	static const char *const columns[] = { "dim", "case", "method", "n", "seconds", "hausdorff_rel", NULL };
	(void)tally; /* the paper publishes no such figure */
	mkSection s;
	mkCurveData cd = { NULL, 0 };
	int usable = mkSection_Begin(&s, d, "Speed against accuracy (every method's error against its time)", dir,
		"tradeoff.csv", columns, "No time-to-error figures are shown.") && mkCurveData_Load(&cd, &s.t) == 0;
	if (usable) {
		mkDoc_Para(d, "Medians over the pairs of each level: hausdorff_rel of the returned points against the "
			"true contact set, and seconds per call. A method reaches an error at its fastest level whose median "
			"error is at most that; \"closed form\" is every registered method that returns boundary points and is "
			"not a published peer (by its flags), the others (sampled methods, the geometric formula, external ones) "
			"are baselines. "
			"Baseline points the closed form's points do not dominate (none as fast and as accurate) are listed, "
			"the error ratio at equal time is taken over the baseline points it does dominate.");
		for (int dim = 2; dim <= 3; ++dim)
			for (int c = 0; c < MK_TRADEOFF_CASES; ++c) {
				int any = 0;
				for (long i = 0; i < cd.count && !any; ++i)
					any = cd.p[i].dim == dim && cd.p[i].c == c;
				if (!any)
					continue;
				mkTimeTable(d, &cd, dim, c);
				mkCompare(d, &cd, dim, c);
			}
		const char *cut = mkMeta_Get(&s.m, "cut");
		mkDoc_Para(d, "Levels not run because a call exceeded the budget: %s.", cut ? cut : "(not recorded)");
	}
	free(cd.p);
	mkSection_End(&s);
}
