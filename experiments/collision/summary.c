/* summary.c - the collision section of results/tables.md: the paper's
 * Table 3 beside the reproduced means, and per pair kind and registry entry
 * the times, success, agreement with the referee and the errors. */
#include "collision.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MK_CELL_MAX 64

/* The registry entry that runs each algorithm of the paper's Table 3 (its
 * names in mink_exp/paper.h): the paper's own formulations (LM on surface
 * angles, the 10 x 10 polytope GJK, ASC by eigenvalues). The one place this
 * mapping lives. */
static const char *const mkTable3Entry[][2] = {
	{ "GJK", "gjk-poly" },
	{ "ASC", "asc-eigen" },
	{ "Implicit", "implicit" },
	{ "Common Normal", "common-normal" },
	{ "MinkSum (Ray)", "minksum-ray-lm" },
	{ "MinkSum (Normal)", "minksum-normal-lm" },
};

static const char *mkEntryOf(const char *paper_name)
{
	for (size_t i = 0; i < MK_COUNT(mkTable3Entry); ++i)
		if (strcmp(mkTable3Entry[i][0], paper_name) == 0)
			return mkTable3Entry[i][1];
	return NULL;
}

static int mkCompareDouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The nearest-rank quantile q of v[0..n) (sorted here); the median is the
 * mean of the middle two for even n. NaN when n == 0. */
static double mkQuantile(double *v, long n, double q)
{
	if (n == 0)
		return NAN;
	qsort(v, (size_t)n, sizeof *v, mkCompareDouble);
	if (q == 0.5)
		return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
	long i = (long)ceil(q * (double)n) - 1;
	return v[i < 0 ? 0 : i >= n ? n - 1 : i];
}

/* The mean time (ms) of `entry` on pair kind `pair`; NaN without rows. */
static double mkMeanMs(const mkTable *t, const char *pair, const char *entry)
{
	int cpair = mkTable_Col(t, "pair"), calg = mkTable_Col(t, "algorithm"), csec = mkTable_Col(t, "seconds");
	mkMean m;
	memset(&m, 0, sizeof m);
	for (long r = 0; entry && r < t->rows; ++r) {
		double s = mkTable_Num(t, r, csec);
		if (!isnan(s) && strcmp(mkTable_Str(t, r, cpair), pair) == 0 && strcmp(mkTable_Str(t, r, calg), entry) == 0)
			mkMean_Add(&m, 1e3 * s);
	}
	return mkMean_Get(&m);
}

static void mkFmt_Measured(char *buf, double v)
{
	if (isnan(v))
		snprintf(buf, MK_CELL_MAX, "%s", mkNotYet);
	else
		snprintf(buf, MK_CELL_MAX, "%.3g", v);
}

/* Table 3: the published mean times beside the reproduced ones. */
static void mkCollision_Table3(mkDoc *d, const mkTable *t, int usable, mkTally *tally)
{
	static const char *const head[] = { "algorithm", "published ellipsoids (ms)", "reproduced", "ratio",
		"published superquadrics (ms)", "reproduced", "ratio", "registry entry" };
	mkDoc_TableBegin(d, "Collision detection: mean time per query over 10⁴ random poses.", 8, head);
	for (int i = 0; i < mkPaper_Table3Count; ++i) {
		const mkPaperTable3 *pub = &mkPaper_Table3[i];
		const char *entry = mkEntryOf(pub->algorithm);
		double ve = usable ? mkMeanMs(t, "ellipsoids", entry) : NAN;
		double vs = usable ? mkMeanMs(t, "superquadrics", entry) : NAN;
		char a[4][MK_CELL_MAX];
		mkFmt_Measured(a[0], ve);
		mkFmt_Ratio(a[1], MK_CELL_MAX, ve, pub->ellipsoids_ms);
		if (isnan(pub->superquadrics_ms))
			snprintf(a[2], MK_CELL_MAX, "—");
		else
			mkFmt_Measured(a[2], vs);
		mkFmt_Ratio(a[3], MK_CELL_MAX, vs, pub->superquadrics_ms);
		const char *row[8] = { pub->algorithm, pub->ellipsoids_text, a[0], a[1], pub->superquadrics_text, a[2], a[3],
			entry ? entry : "—" };
		mkDoc_Row(d, row);
		mkTally_Add(tally, !isnan(ve));
		if (!isnan(pub->superquadrics_ms))
			mkTally_Add(tally, !isnan(vs));
	}
	mkDoc_TableEnd(d);
}

/* What one (pair kind, entry) did. Arrays have room for every row. */
typedef struct mkEntryStat {
	long n, skipped, failed, nd, agreed, nde, npe;
	double sum, *us, *de, *pe;
} mkEntryStat;

static void mkEntryStat_Load(mkEntryStat *st, const mkTable *t, const char *pair, const char *entry)
{
	int cpair = mkTable_Col(t, "pair"), calg = mkTable_Col(t, "algorithm"), csec = mkTable_Col(t, "seconds");
	int cst = mkTable_Col(t, "status"), cerr = mkTable_Col(t, "error"), cag = mkTable_Col(t, "agrees");
	int cref = mkTable_Col(t, "referee_distance");
	st->n = st->skipped = st->failed = st->nd = st->agreed = st->nde = st->npe = 0;
	st->sum = 0.0;
	for (long r = 0; r < t->rows; ++r) {
		if (strcmp(mkTable_Str(t, r, cpair), pair) != 0 || strcmp(mkTable_Str(t, r, calg), entry) != 0)
			continue;
		const char *status = mkTable_Str(t, r, cst);
		if (strcmp(status, "skipped") == 0) {
			st->skipped += 1;
			continue;
		}
		double us = 1e6 * mkTable_Num(t, r, csec), err = mkTable_Num(t, r, cerr), ag = mkTable_Num(t, r, cag);
		st->us[st->n++] = us;
		st->sum += us;
		st->failed += strcmp(status, "failed") == 0;
		if (!isnan(ag)) {
			st->nd += 1;
			st->agreed += ag == 1.0;
		}
		if (!isnan(err)) {
			if (mkTable_Num(t, r, cref) > 0.0)
				st->de[st->nde++] = err;
			else
				st->pe[st->npe++] = err;
		}
	}
}

/* "median / p99 / max" of v[0..n), or "—". */
static void mkFmt_Errors(char *buf, double *v, long n)
{
	if (n == 0) {
		snprintf(buf, MK_CELL_MAX, "—");
		return;
	}
	double med = mkQuantile(v, n, 0.5), p99 = mkQuantile(v, n, 0.99), max = mkQuantile(v, n, 1.0);
	snprintf(buf, MK_CELL_MAX, "%.2g / %.2g / %.2g", med, p99, max);
}

static void mkEntryStat_Row(mkDoc *d, mkEntryStat *st, const char *pair, const char *entry)
{
	char c[8][MK_CELL_MAX];
	snprintf(c[0], MK_CELL_MAX, "%ld", st->n);
	snprintf(c[1], MK_CELL_MAX, "%ld", st->skipped);
	if (st->n) {
		snprintf(c[2], MK_CELL_MAX, "%.3g", st->sum / (double)st->n);
		snprintf(c[3], MK_CELL_MAX, "%.3g", mkQuantile(st->us, st->n, 0.5));
		snprintf(c[4], MK_CELL_MAX, "%.4f", 1.0 - (double)st->failed / (double)st->n);
	} else {
		for (int i = 2; i <= 4; ++i)
			snprintf(c[i], MK_CELL_MAX, "—");
	}
	if (st->nd)
		snprintf(c[5], MK_CELL_MAX, "%.4f (%ld/%ld)", (double)st->agreed / (double)st->nd, st->agreed, st->nd);
	else
		snprintf(c[5], MK_CELL_MAX, "—");
	mkFmt_Errors(c[6], st->de, st->nde);
	mkFmt_Errors(c[7], st->pe, st->npe);
	const char *row[10] = { pair, entry, c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7] };
	mkDoc_Row(d, row);
}

/* The entries of the results in the order of their first row, at most
 * MK_SUMMARY_ENTRIES (the registry has about 20); returns their count. */
#define MK_SUMMARY_ENTRIES 64
static int mkEntryNames(const mkTable *t, int calg, const char *names[MK_SUMMARY_ENTRIES])
{
	int n = 0;
	for (long r = 0; r < t->rows; ++r) {
		const char *entry = mkTable_Str(t, r, calg);
		int i = 0;
		while (i < n && strcmp(names[i], entry) != 0)
			++i;
		if (i == n && n < MK_SUMMARY_ENTRIES)
			names[n++] = entry;
	}
	return n;
}

/* The index of `name` among names[0 .. n), or -1. */
static int mkIndexOf(const char *const *names, int n, const char *name)
{
	for (int i = 0; i < n; ++i)
		if (strcmp(names[i], name) == 0)
			return i;
	return -1;
}

/* How many pairs of each kind the referee could not certify (column
 * referee_certain 0); those are not judged. Results written before the
 * column existed say so. */
static void mkCollision_Uncertain(mkDoc *d, const mkTable *t)
{
	int cc = mkTable_Col(t, "referee_certain"), cpair = mkTable_Col(t, "pair"), ctrial = mkTable_Col(t, "trial");
	if (cc < 0) {
		mkDoc_Para(d, "Referee certainty: not recorded (results written before the referee's certificate).");
		return;
	}
	char text[512] = "";
	for (int k = 0; k < MK_COLLISION_KINDS; ++k) {
		long maxt = -1;
		for (long r = 0; r < t->rows; ++r)
			if (strcmp(mkTable_Str(t, r, cpair), mkCollision_PairNames[k]) == 0 && mkTable_Num(t, r, ctrial) > maxt)
				maxt = (long)mkTable_Num(t, r, ctrial);
		if (maxt < 0)
			continue;
		/* 1: seen, 2: seen and uncertain. */
		char *mark = calloc((size_t)maxt + 1, 1);
		if (!mark)
			return;
		for (long r = 0; r < t->rows; ++r) {
			double tr = mkTable_Num(t, r, ctrial);
			if (strcmp(mkTable_Str(t, r, cpair), mkCollision_PairNames[k]) != 0 || !(tr >= 0))
				continue;
			long i = (long)tr;
			mark[i] = mark[i] == 2 || mkTable_Num(t, r, cc) == 0.0 ? 2 : 1;
		}
		long seen = 0, unc = 0;
		for (long i = 0; i <= maxt; ++i) {
			seen += mark[i] != 0;
			unc += mark[i] == 2;
		}
		free(mark);
		snprintf(text + strlen(text), sizeof text - strlen(text), "%s%s %ld of %ld", text[0] ? ", " : "",
			mkCollision_PairNames[k], unc, seen);
	}
	mkDoc_Para(d, "Pairs the referee could not certify (bracket wider than 1e-10 of the scale, or an overlap "
		"without an enclosing tetrahedron), left out of agreement and errors: %s.", text[0] ? text : "none");
}

/* How many answers of each pair kind and entry came without the
 * certificate their entry gives (column certified 0: for minksum-normal an
 * overlap whose depth its branch and bound could not certify global within
 * its budget), of those that carry the column. Results written before the
 * column existed say so. */
static void mkCollision_Certified(mkDoc *d, const mkTable *t)
{
	int cc = mkTable_Col(t, "certified"), cpair = mkTable_Col(t, "pair"), calg = mkTable_Col(t, "algorithm");
	if (cc < 0) {
		mkDoc_Para(d, "Entries' own certificates: not recorded (results written before the column certified).");
		return;
	}
	/* one pass: per kind and entry, the answers with a value and those 0 */
	const char *names[MK_SUMMARY_ENTRIES];
	int ne = mkEntryNames(t, calg, names);
	long with[MK_COLLISION_KINDS][MK_SUMMARY_ENTRIES] = { { 0 } };
	long without[MK_COLLISION_KINDS][MK_SUMMARY_ENTRIES] = { { 0 } };
	for (long r = 0; r < t->rows; ++r) {
		double v = mkTable_Num(t, r, cc);
		int k = mkIndexOf(mkCollision_PairNames, MK_COLLISION_KINDS, mkTable_Str(t, r, cpair));
		int e = mkIndexOf(names, ne, mkTable_Str(t, r, calg));
		if (isnan(v) || k < 0 || e < 0)
			continue;
		with[k][e] += 1;
		without[k][e] += v == 0.0;
	}
	char text[1024] = "";
	long total = 0;
	for (int k = 0; k < MK_COLLISION_KINDS; ++k)
		for (int e = 0; e < ne; ++e) {
			total += with[k][e];
			if (without[k][e] > 0)
				snprintf(text + strlen(text), sizeof text - strlen(text), "%s%s %s %ld of %ld", text[0] ? ", " : "",
					mkCollision_PairNames[k], names[e], without[k][e], with[k][e]);
		}
	mkDoc_Para(d, "Answers without the certificate their entry gives (column certified 0; minksum-normal: an overlap "
		"whose depth was not certified global within its budget), of %ld certified or not: %s.", total,
		text[0] ? text : "none");
}

/* Per pair kind and entry (entries of the data, in order of first
 * appearance). */
static void mkCollision_Details(mkDoc *d, const mkTable *t, const mkMeta *m)
{
	static const char *const head[] = { "pair", "entry", "runs", "skipped", "mean (µs)", "median (µs)",
		"success", "agreement", "distance error med / p99 / max", "penetration error med / p99 / max" };
	const char *margin = mkMeta_Get(m, "referee_margin"), *limits = mkMeta_Get(m, "limits");
	mkDoc_Para(d, "Per pair kind and registry entry: success = a verdict (no failure); agreement = the "
		"referee's status (touching counted as contact) where |referee sd| > %s × scale; errors = "
		"|distance − referee| / scale over separated (distance) and overlapping (penetration) pairs, for "
		"entries that return one; skipped = trials beyond a --limit (%s).", margin ? margin : "(not recorded)",
		limits ? limits : "not recorded");
	mkCollision_Uncertain(d, t);
	mkCollision_Certified(d, t);
	mkDoc_TableBegin(d, "Collision and distance: the registry's entries against the referee.", 10, head);
	int calg = mkTable_Col(t, "algorithm");
	size_t room = (size_t)(t->rows > 0 ? t->rows : 1) * sizeof(double);
	mkEntryStat st;
	st.us = malloc(room);
	st.de = malloc(room);
	st.pe = malloc(room);
	const char *names[MK_SUMMARY_ENTRIES];
	int ne = mkEntryNames(t, calg, names);
	for (int k = 0; st.us && st.de && st.pe && k < MK_COLLISION_KINDS; ++k)
		for (int e = 0; e < ne; ++e) {
			mkEntryStat_Load(&st, t, mkCollision_PairNames[k], names[e]);
			if (st.n + st.skipped > 0)
				mkEntryStat_Row(d, &st, mkCollision_PairNames[k], names[e]);
		}
	free(st.us);
	free(st.de);
	free(st.pe);
	mkDoc_TableEnd(d);
}

/* The batch entries (rows minksum-batch-<mode>) and the one-pair entries
 * they are set beside. */
static const char *const mkBatchRows[] = { "minksum-batch-status", "minksum-batch-clearance",
	"minksum-batch-distance", "minksum-batch-full" };
static const char *const mkBatchPeers[] = { "minksum-normal", "ccd-gjk", "ccd-gjk-epa-1e-10" };

/* Median and mean time (µs) of an entry on a pair kind: NaN without rows. */
static void mkTimes(mkEntryStat *st, const mkTable *t, const char *pair, const char *entry, double *med, double *mean)
{
	mkEntryStat_Load(st, t, pair, entry);
	*med = mkQuantile(st->us, st->n, 0.5);
	*mean = st->n ? st->sum / (double)st->n : NAN;
}

/* "a / b": the peer's time over the batch entry's (its pairs per second
 * over the peer's), by median and by mean; "—" without both. */
static void mkFmt_Speedup(char *buf, double pmed, double pmean, double bmed, double bmean)
{
	if (isnan(pmed) || isnan(bmed) || !(bmed > 0.0) || !(bmean > 0.0))
		snprintf(buf, MK_CELL_MAX, "—");
	else
		snprintf(buf, MK_CELL_MAX, "%.2f / %.2f", pmed / bmed, pmean / bmean);
}

/* The rows of entry `entry` on kind `pair` whose path is `path`. */
static long mkCountPath(const mkTable *t, const char *pair, const char *entry, const char *path)
{
	int cpair = mkTable_Col(t, "pair"), calg = mkTable_Col(t, "algorithm"), cpath = mkTable_Col(t, "path");
	long n = 0;
	for (long r = 0; cpath >= 0 && r < t->rows; ++r)
		n += strcmp(mkTable_Str(t, r, cpair), pair) == 0 && strcmp(mkTable_Str(t, r, calg), entry) == 0
			&& strcmp(mkTable_Str(t, r, cpath), path) == 0;
	return n;
}

/* The batch entries' amortised time per pair beside the one-pair entries on
 * the same pairs, and how many pairs the one-pair query answered. */
static void mkCollision_Batch(mkDoc *d, const mkTable *t, const mkMeta *m)
{
	static const char *const head[] = { "pair", "batch entry", "pairs", "median (µs/pair)", "mean (µs/pair)",
		"× minksum-normal", "× ccd-gjk", "× ccd-gjk-epa-1e-10", "by the one-pair query", "failed" };
	int calg = mkTable_Col(t, "algorithm");
	const char *names[MK_SUMMARY_ENTRIES];
	int ne = mkEntryNames(t, calg, names), any = 0;
	for (size_t i = 0; i < MK_COUNT(mkBatchRows); ++i)
		any |= mkIndexOf(names, ne, mkBatchRows[i]) >= 0;
	if (!any) {
		mkDoc_Para(d, "Batch entries (mkCollide3_Batch): not in these results (written before the batch entries).");
		return;
	}
	const char *chunk = mkMeta_Get(m, "batch_chunk"), *lanes = mkMeta_Get(m, "batch_lanes");
	mkDoc_Para(d, "Batch entries: each kind's pairs answered %s pairs per mkCollide3_Batch call (lanes: %s), the "
		"call's time divided by its pairs, beside the one-pair entries on the same pairs (× peer = the peer's "
		"time over the batch entry's, i.e. the batch's pairs per second over the peer's, by median / by mean); "
		"by the one-pair query = pairs answered by mkCollide3_Normal (status and clearance: the pairs the "
		"batch's certificates did not settle; distance: those too and every separated pair, whose distance "
		"it gives; full: every pair).",
		chunk ? chunk : "(not recorded)", lanes ? lanes : "not recorded");
	mkDoc_TableBegin(d, "Batch entries: amortised time per pair, against the one-pair entries.", 10, head);
	size_t room = (size_t)(t->rows > 0 ? t->rows : 1) * sizeof(double);
	mkEntryStat st = { 0, 0, 0, 0, 0, 0, 0, 0.0, malloc(room), malloc(room), malloc(room) };
	for (int k = 0; st.us && st.de && st.pe && k < MK_COLLISION_KINDS; ++k) {
		const char *pair = mkCollision_PairNames[k];
		double pmed[MK_COUNT(mkBatchPeers)], pmean[MK_COUNT(mkBatchPeers)];
		for (size_t p = 0; p < MK_COUNT(mkBatchPeers); ++p)
			mkTimes(&st, t, pair, mkBatchPeers[p], &pmed[p], &pmean[p]);
		for (size_t b = 0; b < MK_COUNT(mkBatchRows); ++b) {
			double med, mean;
			mkTimes(&st, t, pair, mkBatchRows[b], &med, &mean);
			if (st.n == 0)
				continue;
			char c[8][MK_CELL_MAX];
			snprintf(c[0], MK_CELL_MAX, "%ld", st.n);
			snprintf(c[1], MK_CELL_MAX, "%.3g", med);
			snprintf(c[2], MK_CELL_MAX, "%.3g", mean);
			for (size_t p = 0; p < MK_COUNT(mkBatchPeers); ++p)
				mkFmt_Speedup(c[3 + p], pmed[p], pmean[p], med, mean);
			long fb = mkCountPath(t, pair, mkBatchRows[b], "one-pair");
			snprintf(c[6], MK_CELL_MAX, "%.4f (%ld/%ld)", (double)fb / (double)st.n, fb, st.n);
			snprintf(c[7], MK_CELL_MAX, "%ld", st.failed);
			const char *row[10] = { pair, mkBatchRows[b], c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7] };
			mkDoc_Row(d, row);
		}
	}
	free(st.us);
	free(st.de);
	free(st.pe);
	mkDoc_TableEnd(d);
}

void mkCollision_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	static const char *const columns[] = { "pair", "algorithm", "seconds", "status", "referee_distance", "error",
		"agrees", NULL };
	mkSection s;
	int usable = mkSection_Begin(&s, d, "Collision detection (paper §7.2, Table 3)", dir, "collision.csv",
		columns, "None of the 11 published mean times below has a counterpart.");
	if (usable) {
		const char *rot = mkMeta_Get(&s.m, "rotation_draw");
		mkDoc_Para(d, "Rotation draw: %s.", rot ? rot : "not recorded in the sidecar");
	}
	mkCollision_Table3(d, &s.t, usable, tally);
	if (usable) {
		mkCollision_Details(d, &s.t, &s.m);
		mkCollision_Batch(d, &s.t, &s.m);
	}
	mkSection_End(&s);
}
