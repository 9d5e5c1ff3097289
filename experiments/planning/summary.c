/* summary.c - the planning experiment's section of results/tables.md: per
 * scene and planner the two checkers' success, median planning times and
 * their ratio, how many returned paths the certification found free, and
 * success against the time budget (the figure's curves, read at every one
 * of MK_PLANNING_BUDGETS log-spaced budgets). */
#include "planning_summary.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MK_PLANNING_GROUPS 64

/* The columns of results/planning.csv the summary reads. */
typedef struct mkPlCols {
	int scene, planner, checker, budget, success, seconds, truefree;
} mkPlCols;

/* One scene x planner: its rows' indices per checker. */
typedef struct mkPlGroup {
	char scene[64], planner[64];
	long *rows[2];
	long n[2];
} mkPlGroup;

static int mkPl_Compare(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* A run's time to its path: seconds when it found one, else infinite. */
static double mkPl_Time(const mkTable *t, const mkPlCols *c, long r)
{
	double s = mkTable_Num(t, r, c->seconds);
	return mkTable_Num(t, r, c->success) == 1 && s >= 0.0 ? s : INFINITY;
}

/* The median time to a path of rows[0 .. n) (a run without a path counts
 * as infinite; even n: the mean of the middle two, infinite when either
 * is); NaN when n = 0. */
static double mkPl_Median(const mkTable *t, const mkPlCols *c, const long *rows, long n)
{
	double *v = n > 0 ? malloc((size_t)n * sizeof *v) : NULL;
	if (!v) return NAN;
	for (long k = 0; k < n; ++k) v[k] = mkPl_Time(t, c, rows[k]);
	qsort(v, (size_t)n, sizeof *v, mkPl_Compare);
	double m = n % 2 ? v[n / 2] : (isinf(v[n / 2]) ? INFINITY : 0.5 * (v[n / 2 - 1] + v[n / 2]));
	free(v);
	return m;
}

double mkPlanning_Budget(int k, double top)
{
	double lo = log10(MK_PLANNING_BUDGET_MIN), hi = log10(top);
	return k == MK_PLANNING_BUDGETS - 1 ? top : pow(10.0, lo + (hi - lo) * k / (MK_PLANNING_BUDGETS - 1));
}

/* Runs of the rows with a path found within b seconds (b infinite: with a
 * path). */
static long mkPl_Within(const mkTable *t, const mkPlCols *c, const long *rows, long n, double b)
{
	long s = 0;
	for (long k = 0; k < n; ++k) {
		double x = mkPl_Time(t, c, rows[k]);
		s += isfinite(x) && x <= b;
	}
	return s;
}

/* Runs of the rows whose path the certification found hitting the true
 * shapes (path_true_free 0), or uncertain (-1). */
static long mkPl_Paths(const mkTable *t, const mkPlCols *c, const long *rows, long n, int value)
{
	long s = 0;
	for (long k = 0; k < n; ++k) s += mkTable_Num(t, rows[k], c->success) == 1 && mkTable_Num(t, rows[k], c->truefree) == value;
	return s;
}

static double mkPl_LogChoose(long n, long k)
{
	return lgamma((double)n + 1.0) - lgamma((double)k + 1.0) - lgamma((double)(n - k) + 1.0);
}

double mkPlanning_Fisher(long s0, long n0, long s1, long n1)
{
	long N = n0 + n1, K = s0 + s1;
	double p = 0.0, all = mkPl_LogChoose(N, n1);
	for (long x = s1; x <= n1 && x <= K; ++x)
		if (K - x <= n0) p += exp(mkPl_LogChoose(K, x) + mkPl_LogChoose(N - K, n1 - x) - all);
	return p > 1.0 ? 1.0 : p;
}

static void mkPl_Seconds(char *buf, size_t len, double v)
{
	if (isnan(v)) snprintf(buf, len, "–");
	else if (isinf(v)) snprintf(buf, len, "no path");
	else snprintf(buf, len, "%.2g", v);
}

/* The groups in the order of their first rows; 0 when more than fit. */
static int mkPl_Groups(const mkTable *t, const mkPlCols *c, mkPlGroup *g, int *count)
{
	int n = 0;
	for (long r = 0; r < t->rows; ++r) {
		const char *sc = mkTable_Str(t, r, c->scene), *pl = mkTable_Str(t, r, c->planner), *ch = mkTable_Str(t, r, c->checker);
		int which = strcmp(ch, "mink") == 0 ? 0 : strcmp(ch, "fcl") == 0 ? 1 : -1;
		if (which < 0) continue;
		int k = 0;
		while (k < n && (strcmp(g[k].scene, sc) || strcmp(g[k].planner, pl))) ++k;
		if (k == n) {
			if (n == MK_PLANNING_GROUPS) return 0;
			memset(&g[n], 0, sizeof g[n]);
			snprintf(g[n].scene, sizeof g[n].scene, "%s", sc);
			snprintf(g[n].planner, sizeof g[n].planner, "%s", pl);
			g[n].rows[0] = malloc((size_t)t->rows * sizeof(long));
			g[n].rows[1] = malloc((size_t)t->rows * sizeof(long));
			++n;
			*count = n;
			if (!g[k].rows[0] || !g[k].rows[1]) return 0;
		}
		g[k].rows[which][g[k].n[which]++] = r;
	}
	*count = n;
	return 1;
}

void mkPlanning_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	static const char *const columns[] = { "scene", "planner", "checker", "budget_s", "success", "seconds",
		"path_true_free", NULL };
	(void)tally; /* not in the paper: no published numbers */
	mkSection s;
	if (!mkSection_Begin(&s, d, "Planning with certified checks (not in the paper)", dir, "planning.csv", columns,
			"The planning table is not produced.")) {
		mkSection_End(&s);
		return;
	}
	const mkTable *t = &s.t;
	mkPlCols c = { mkTable_Col(t, "scene"), mkTable_Col(t, "planner"), mkTable_Col(t, "checker"),
		mkTable_Col(t, "budget_s"), mkTable_Col(t, "success"), mkTable_Col(t, "seconds"), mkTable_Col(t, "path_true_free") };
	mkPlGroup g[MK_PLANNING_GROUPS];
	int n = 0;
	if (!mkPl_Groups(t, &c, g, &n)) {
		mkDoc_Para(d, "More than %d scene and planner groups, or out of memory: not summarised.", MK_PLANNING_GROUPS);
	} else {
		mkDoc_Para(d, "OMPL's planners with mink's certified checks against FCL 0.7 with OMPL's discrete motion "
			"check, the same seeds (docs/experiments/planning.md). Medians over all runs of a group, a run "
			"without a path counting as infinite; ratio = mink's median / FCL's. A path is certified free when "
			"every segment is (`mink plan --check` for the declared shapes); hitting = some segment in certified "
			"contact with them.");
		static const char *const head[] = { "scene", "planner", "runs", "success mink / fcl", "median s mink",
			"median s fcl", "ratio", "mink paths certified free", "fcl paths hitting (uncertain)" };
		mkDoc_TableBegin(d, "Planning: success, median time, certification", 9, head);
		for (int k = 0; k < n; ++k) {
			char v[9][64];
			double m0 = mkPl_Median(t, &c, g[k].rows[0], g[k].n[0]), m1 = mkPl_Median(t, &c, g[k].rows[1], g[k].n[1]);
			long ok0 = mkPl_Within(t, &c, g[k].rows[0], g[k].n[0], INFINITY);
			long ok1 = mkPl_Within(t, &c, g[k].rows[1], g[k].n[1], INFINITY);
			snprintf(v[0], 64, "%.63s", g[k].scene);
			snprintf(v[1], 64, "%.63s", g[k].planner);
			snprintf(v[2], 64, g[k].n[0] == g[k].n[1] ? "%ld" : "%ld / %ld", g[k].n[0], g[k].n[1]);
			snprintf(v[3], 64, "%ld / %ld", ok0, ok1);
			mkPl_Seconds(v[4], 64, m0);
			mkPl_Seconds(v[5], 64, m1);
			if (isfinite(m0) && isfinite(m1) && m1 > 0.0) snprintf(v[6], 64, "%.2f", m0 / m1);
			else snprintf(v[6], 64, "–");
			snprintf(v[7], 64, "%ld of %ld", mkPl_Paths(t, &c, g[k].rows[0], g[k].n[0], 1), ok0);
			snprintf(v[8], 64, "%ld of %ld (%ld)", mkPl_Paths(t, &c, g[k].rows[1], g[k].n[1], 0), ok1,
				mkPl_Paths(t, &c, g[k].rows[1], g[k].n[1], -1));
			const char *cells[9] = { v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8] };
			mkDoc_Row(d, cells);
		}
		mkDoc_TableEnd(d);

		static const char *const bhead[] = { "scene", "planner", "2 ms", "5 ms", "20 ms", "100 ms", "1 s",
			"budgets below fcl", "largest gap below" };
		mkDoc_TableBegin(d, "Planning: runs with a path within a budget, mink / fcl", 9, bhead);
		static const double shown[5] = { 0.002, 0.005, 0.02, 0.1, 1.0 };
		int below_groups = 0;
		for (int k = 0; k < n; ++k) {
			char v[9][64];
			double top = 0.0;
			for (int w = 0; w < 2; ++w)
				for (long e = 0; e < g[k].n[w]; ++e) top = fmax(top, mkTable_Num(t, g[k].rows[w][e], c.budget));
			snprintf(v[0], 64, "%.63s", g[k].scene);
			snprintf(v[1], 64, "%.63s", g[k].planner);
			for (int e = 0; e < 5; ++e)
				if (shown[e] <= top)
					snprintf(v[2 + e], 64, "%ld / %ld", mkPl_Within(t, &c, g[k].rows[0], g[k].n[0], shown[e]),
						mkPl_Within(t, &c, g[k].rows[1], g[k].n[1], shown[e]));
				else
					snprintf(v[2 + e], 64, "–");
			int below = 0;
			long gap = 0;
			double at = NAN, pmin = 1.0;
			for (int e = 0; top > MK_PLANNING_BUDGET_MIN && e < MK_PLANNING_BUDGETS; ++e) {
				double b = mkPlanning_Budget(e, top);
				long s0 = mkPl_Within(t, &c, g[k].rows[0], g[k].n[0], b), s1 = mkPl_Within(t, &c, g[k].rows[1], g[k].n[1], b);
				if (s0 * g[k].n[1] < s1 * g[k].n[0]) { /* mink's fraction below FCL's */
					++below;
					if (s1 - s0 > gap) { gap = s1 - s0; at = b; }
					pmin = fmin(pmin, mkPlanning_Fisher(s0, g[k].n[0], s1, g[k].n[1]));
				}
			}
			below_groups += below > 0;
			snprintf(v[7], 64, "%d of %d", below, MK_PLANNING_BUDGETS);
			if (below) snprintf(v[8], 64, "%ld runs at %.2g s (p %.2f)", gap, at, pmin);
			else snprintf(v[8], 64, "–");
			const char *cells[9] = { v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8] };
			mkDoc_Row(d, cells);
		}
		mkDoc_TableEnd(d);
		mkDoc_Para(d, "Budgets: %d log-spaced from %g s to each group's budget; below = mink's fraction of runs with "
			"a path within the budget under FCL's. Groups with some budget below: %d of %d. p: the smallest, over "
			"the budgets below, of a one-sided Fisher exact test's p-value (the chance of FCL's count or more if "
			"both checkers had the same success rate at that budget): small p is evidence of a lower rate, large "
			"p a difference the runs' number cannot tell from chance.", MK_PLANNING_BUDGETS, MK_PLANNING_BUDGET_MIN,
			below_groups, n);
	}
	for (int k = 0; k < n; ++k) { free(g[k].rows[0]); free(g[k].rows[1]); }
	mkSection_End(&s);
}
