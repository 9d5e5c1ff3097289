/* summary.c - the extremes section of results/tables.md: per method and
 * dimension, the rows kept within 1e-12 of the size S, the worst cell, the
 * non-finite outputs and error returns, and for the exact closed forms
 * whether 1e-13 holds wherever the condition is at most 1e-14.
 *
 * Methods are the distinct `method` values of the data, registry methods in
 * registry order, then unknown names in order of first appearance: no list
 * of names here. */
#include "extremes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const mkExtremes_Needed[] = { "dim", "cell", "family", "set", "method", "eps1_b1", "eps2_b1",
	"eps1_b2", "eps2_b2", "error_rel", "condition", "nonfinite", "status", NULL };

/* One (method, dim) of the data. */
typedef struct mkExStat {
	const char *method;
	int dim, order;
	long rows, kept, errors, nonfinite, allowed, missed;
	double worst;
	long worstRow;  /* -1: no finite error */
} mkExStat;

typedef struct mkExCols {
	int dim, cell, family, set, method, e11, e21, e12, e22, err, cond, nonfinite, status;
} mkExCols;

static int mkExStat_Compare(const void *a, const void *b)
{
	const mkExStat *x = a, *y = b;
	if (x->order != y->order)
		return x->order < y->order ? -1 : 1;
	return x->dim - y->dim;
}

/* The order of a method: its registry index, or the registry's count plus
 * its first appearance. */
static int mkExtremes_Order(const char *name, int appearance)
{
	for (int i = 0; i < mkRegistry_Count(); ++i)
		if (strcmp(mkRegistry_At(i)->name, name) == 0)
			return i;
	return mkRegistry_Count() + appearance;
}

/* Is the method one whose bar is 1e-13 (an exact closed form: exact, not
 * sampled, not an approximate tier)? Unknown names are not. */
static int mkExtremes_IsClosed(const char *name)
{
	const mkMethod *m = mkRegistry_Find(name);
	return m && (m->flags & MK_METHOD_EXACT) && !(m->flags & (MK_METHOD_SAMPLED | MK_METHOD_APPROX));
}

static void mkExStat_Add(mkExStat *s, const mkTable *t, const mkExCols *c, long r)
{
	const char *status = mkTable_Str(t, r, c->status);
	double err = mkTable_Num(t, r, c->err), cond = mkTable_Num(t, r, c->cond), nf = mkTable_Num(t, r, c->nonfinite);
	int ok = strcmp(status, "ok") == 0;
	s->rows += 1;
	s->errors += strncmp(status, "error", 5) == 0;
	s->nonfinite += isfinite(nf) ? (long)nf : 0;
	s->kept += ok && err <= MK_EXTREMES_KEEP;
	if (isfinite(err) && (s->worstRow < 0 || err > s->worst)) {
		s->worst = err;
		s->worstRow = r;
	}
	if (cond <= MK_EXTREMES_COND_OK) {
		s->allowed += 1;
		s->missed += !(ok && err <= MK_EXTREMES_BAR);
	}
}

/* The stats of every (method, dim); *count receives how many. NULL out of memory. */
static mkExStat *mkExtremes_Stats(const mkTable *t, const mkExCols *c, long *count)
{
	mkExStat *st = calloc((size_t)(t->rows > 0 ? t->rows : 1), sizeof *st);
	long n = 0;
	int appearances = 0;
	for (long r = 0; st && r < t->rows; ++r) {
		const char *name = mkTable_Str(t, r, c->method);
		int dim = (int)mkTable_Num(t, r, c->dim), order = -1;
		long k = 0;
		for (; k < n && !(st[k].dim == dim && strcmp(st[k].method, name) == 0); ++k)
			if (strcmp(st[k].method, name) == 0)
				order = st[k].order; /* the same method in the other dimension */
		if (k == n) {
			st[n] = (mkExStat){ name, dim, order >= 0 ? order : mkExtremes_Order(name, appearances++),
				0, 0, 0, 0, 0, 0, 0.0, -1 };
			++n;
		}
		mkExStat_Add(&st[k], t, c, r);
	}
	if (st)
		qsort(st, (size_t)n, sizeof *st, mkExStat_Compare);
	*count = n;
	return st;
}

/* The cell of a row as text: family, index, set and exponents. */
static void mkExtremes_CellText(char *buf, size_t len, const mkTable *t, const mkExCols *c, long r)
{
	if (r < 0) {
		snprintf(buf, len, "—");
		return;
	}
	snprintf(buf, len, "%s %s %s, ε (%s, %s) / (%s, %s)", mkTable_Str(t, r, c->family), mkTable_Str(t, r, c->cell),
		mkTable_Str(t, r, c->set), mkTable_Str(t, r, c->e11), mkTable_Str(t, r, c->e21), mkTable_Str(t, r, c->e12),
		mkTable_Str(t, r, c->e22));
}

static void mkExtremes_Table(mkDoc *d, const mkTable *t, const mkExCols *c, const mkExStat *st, long n)
{
	static const char *const head[] = { "method", "dim", "rows", "within 1e-12", "worst error_rel", "worst cell",
		"non-finite points", "error rows", "1e-13 where condition ≤ 1e-14" };
	mkDoc_TableBegin(d, "Per method and dimension: rows (cell × set) within 1e-12 of the scale, the worst one, "
		"failures; for the exact closed forms the 1e-13 bar where the condition allows it.", 9, head);
	for (long k = 0; k < n; ++k) {
		const mkExStat *s = &st[k];
		char dim[8], rows[32], kept[32], worst[32], cell[256], nf[32], err[32], bar[64];
		snprintf(dim, sizeof dim, "%dD", s->dim);
		snprintf(rows, sizeof rows, "%ld", s->rows);
		snprintf(kept, sizeof kept, "%ld of %ld", s->kept, s->rows);
		mkFmt_Sci(worst, sizeof worst, s->worstRow >= 0 ? s->worst : NAN);
		mkExtremes_CellText(cell, sizeof cell, t, c, s->worstRow);
		snprintf(nf, sizeof nf, "%ld", s->nonfinite);
		snprintf(err, sizeof err, "%ld", s->errors);
		if (!mkExtremes_IsClosed(s->method))
			snprintf(bar, sizeof bar, "—");
		else if (s->missed == 0)
			snprintf(bar, sizeof bar, "holds (%ld rows)", s->allowed);
		else
			snprintf(bar, sizeof bar, "**fails** on %ld of %ld rows", s->missed, s->allowed);
		const char *row[9] = { s->method, dim, rows, kept, worst, cell, nf, err, bar };
		mkDoc_Row(d, row);
	}
	mkDoc_TableEnd(d);
}

void mkExtremes_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	(void)tally; /* the paper publishes no number this experiment reproduces */
	mkSection s;
	if (!mkSection_Begin(&s, d, "Numerical stability at the extremes", dir, "extremes.csv", mkExtremes_Needed,
			"The stability map is not shown.")) {
		mkSection_End(&s);
		return;
	}
	const mkTable *t = &s.t;
	mkExCols c = { mkTable_Col(t, "dim"), mkTable_Col(t, "cell"), mkTable_Col(t, "family"), mkTable_Col(t, "set"),
		mkTable_Col(t, "method"), mkTable_Col(t, "eps1_b1"), mkTable_Col(t, "eps2_b1"), mkTable_Col(t, "eps1_b2"),
		mkTable_Col(t, "eps2_b2"), mkTable_Col(t, "error_rel"), mkTable_Col(t, "condition"),
		mkTable_Col(t, "nonfinite"), mkTable_Col(t, "status") };
	long n = 0;
	mkExStat *st = mkExtremes_Stats(t, &c, &n);
	if (!st) {
		mkDoc_Para(d, "Out of memory reading `%s`.", s.path);
		mkSection_End(&s);
		return;
	}
	mkDoc_Para(d, "error_rel is the largest distance of a method's output point from the exact boundary (256-bit "
		"MPFR reference) over the scale S; condition is how far the exact boundary itself moves under one-ulp input "
		"perturbations, in the same unit. A row is within 1e-12 when its status is ok and error_rel ≤ 1e-12.");
	mkExtremes_Table(d, t, &c, st, n);
	free(st);
	mkSection_End(&s);
}
