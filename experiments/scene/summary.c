/* summary.c - the scene experiment's section of results/tables.md. */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void mkCell(char *buf, size_t len, const char *fmt, double v)
{
	if (isfinite(v)) snprintf(buf, len, fmt, v); else snprintf(buf, len, "–");
}

/* Part A: one line per (dim, obstacles, tol) from its adaptive and uniform rows. */
static void mkSceneX_PointsTable(mkDoc *d, const mkTable *t)
{
	static const char *const head[] = { "dim", "obstacles (boxes)", "orientations", "T", "adaptive points",
		"adaptive error", "uniform points", "uniform error", "factor" };
	int cp = mkTable_Col(t, "part"), cm = mkTable_Col(t, "mode"), cd = mkTable_Col(t, "dim"),
		co = mkTable_Col(t, "obstacles"), cb = mkTable_Col(t, "boxes"), cr = mkTable_Col(t, "orientations"),
		ct = mkTable_Col(t, "tol"), cn = mkTable_Col(t, "points"), ce = mkTable_Col(t, "error"),
		cc = mkTable_Col(t, "capped"), cf = mkTable_Col(t, "factor");
	mkDoc_TableBegin(d, "Points at equal worst-case certified error (Part A)", 9, head);
	double worst = INFINITY;
	for (long r = 0; r + 1 < t->rows; ++r) {
		if (strcmp(mkTable_Str(t, r, cp), "A") || strcmp(mkTable_Str(t, r, cm), "adaptive")
			|| strcmp(mkTable_Str(t, r + 1, cm), "uniform"))
			continue;
		char c[9][64];
		int capped = mkTable_Num(t, r + 1, cc) == 1;
		snprintf(c[0], 64, "%s", mkTable_Str(t, r, cd));
		snprintf(c[1], 64, "%s (%s)", mkTable_Str(t, r, co), mkTable_Str(t, r, cb));
		snprintf(c[2], 64, "%s", mkTable_Str(t, r, cr));
		mkCell(c[3], 64, "%g", mkTable_Num(t, r, ct));
		mkCell(c[4], 64, "%.0f", mkTable_Num(t, r, cn));
		mkCell(c[5], 64, "%.3g", mkTable_Num(t, r, ce));
		mkCell(c[6], 64, "%.0f", mkTable_Num(t, r + 1, cn));
		mkCell(c[7], 64, "%.3g", mkTable_Num(t, r + 1, ce));
		double f = mkTable_Num(t, r + 1, cf);
		snprintf(c[8], 64, capped ? "> %.1f (capped)" : "%.1f", f);
		if (f < worst) worst = f;
		const char *cells[9] = { c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8] };
		mkDoc_Row(d, cells);
	}
	mkDoc_TableEnd(d);
	if (isfinite(worst))
		mkDoc_Para(d, "Smallest factor over the scenes: %.1f (the bar is at least 3). A capped search "
			"stopped before a whole-scene uniform run too large to afford (or past the largest level); its row "
			"is the largest uniform sampling known to fail (one boundary's error there is above the target), "
			"with the points the whole scene would use, so its factor is a lower bound.", worst);
}

/* The one-thread mean total of a level in <dir>/cobstacle.csv, or NaN. */
static double mkSceneX_OneThread(const mkTable *c, int dim, long obstacles, long orientations)
{
	int cd = mkTable_Col(c, "dim"), co = mkTable_Col(c, "obstacles"), cr = mkTable_Col(c, "orientations"),
		ct = mkTable_Col(c, "total_s");
	mkMean m = { 0 };
	if (cd < 0 || co < 0 || cr < 0 || ct < 0)
		return NAN;
	for (long r = 0; r < c->rows; ++r)
		if (mkTable_Num(c, r, cd) == dim && mkTable_Num(c, r, co) == obstacles && mkTable_Num(c, r, cr) == orientations)
			mkMean_Add(&m, mkTable_Num(c, r, ct));
	return m.n ? mkMean_Get(&m) : NAN;
}

/* Part B: one line per level and pair of runs. */
static void mkSceneX_Table2Table(mkDoc *d, const mkTable *t, const mkTable *c)
{
	static const char *const head[] = { "dim", "obstacles", "orientations", "points", "paper (s)",
		"cobstacle, 1 thread (s)", "1 thread (s)", "2 threads (s)", "efficiency", "load" };
	int cp = mkTable_Col(t, "part"), cth = mkTable_Col(t, "threads"), cd = mkTable_Col(t, "dim"),
		co = mkTable_Col(t, "obstacles"), cr = mkTable_Col(t, "orientations"), cn = mkTable_Col(t, "points"),
		cs = mkTable_Col(t, "seconds"), ce = mkTable_Col(t, "efficiency"), cq = mkTable_Col(t, "paper_s"),
		cl = mkTable_Col(t, "load");
	mkDoc_TableBegin(d, "Table 2 on 1 and 2 threads, alternately in one run (Part B)", 10, head);
	for (long r = 0; r + 1 < t->rows; ++r) {
		if (strcmp(mkTable_Str(t, r, cp), "B") || mkTable_Num(t, r, cth) != 1 || mkTable_Num(t, r + 1, cth) != 2)
			continue;
		char v[10][64];
		snprintf(v[0], 64, "%s", mkTable_Str(t, r, cd));
		snprintf(v[1], 64, "%s", mkTable_Str(t, r, co));
		snprintf(v[2], 64, "%s", mkTable_Str(t, r, cr));
		snprintf(v[3], 64, "%s", mkTable_Str(t, r, cn));
		mkCell(v[4], 64, "%g", mkTable_Num(t, r, cq));
		mkCell(v[5], 64, "%.3f", c ? mkSceneX_OneThread(c, (int)mkTable_Num(t, r, cd), (long)mkTable_Num(t, r, co),
			(long)mkTable_Num(t, r, cr)) : NAN);
		mkCell(v[6], 64, "%.3f", mkTable_Num(t, r, cs));
		mkCell(v[7], 64, "%.3f", mkTable_Num(t, r + 1, cs));
		if (mkTable_Num(t, r, cs) < MK_SCENEX_TINY_S)
			snprintf(v[8], 64, "(too small)");
		else
			mkCell(v[8], 64, "%.0f%%", 100.0 * mkTable_Num(t, r + 1, ce));
		mkCell(v[9], 64, "%.2f", mkTable_Num(t, r, cl));
		const char *cells[10] = { v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9] };
		mkDoc_Row(d, cells);
	}
	mkDoc_TableEnd(d);
	mkDoc_Para(d, "Efficiency = t1 / (2 t2) of each pair. Levels whose one-thread run takes under %g s are too "
		"small to measure it (starting the second thread costs a noticeable part of them); the bar "
		"(at least 85%%) is read on the largest level, the 3D row of 1000 obstacles.", MK_SCENEX_TINY_S);
}

void mkScene_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	static const char *const columns[] = { "part", "dim", "obstacles", "boxes", "orientations", "tol", "mode",
		"threads", "points", "seconds", "error", "capped", "factor", "efficiency", "paper_s", "load", NULL };
	(void)tally; /* the published totals are counted by the cobstacle section */
	mkSection s;
	if (mkSection_Begin(&s, d, "C-obstacles certified to a tolerance; Table 2 on every core", dir, "scene.csv",
			columns, "Neither the points factor nor Table 2 on two threads has been measured.")) {
		mkDoc_Para(d, "Part A: adaptive C-obstacle boundaries (mink/cobstacle.h) against the smallest uniform "
			"sampling with the same worst-case certified error over the scene; boxes and cylinders are "
			"modelled the same way for both. Part B: the paper's sampling in the same code on 1 and 2 threads, "
			"alternately in one process; the checksums of the two thread counts were equal (the driver fails "
			"otherwise). Wall times depend on the machine's load (column load: the 1-minute load average).");
		mkSceneX_PointsTable(d, &s.t);
		mkTable c;
		mkMeta cm;
		char path[MK_PATH_MAX];
		int have = mkResult_Load(dir, "cobstacle.csv", &c, &cm, path, sizeof path);
		mkSceneX_Table2Table(d, &s.t, have ? &c : NULL);
		mkResult_Free(&c, &cm);
	}
	mkSection_End(&s);
}
