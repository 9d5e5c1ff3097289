/* fitting.c - the fitting experiment's rows and summary (fitting.h). */
#include "fitting.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MK_CELL_MAX 256

const char *const mkFitting_Columns[] = {
	"case", "trial", "truth", "model", "sampling", "level", "vertices",
	"volume_true", "volume_model", "e_volume", "e_implicit",
	"a", "b", "c", "eps1", "eps2", "qw", "qx", "qy", "qz", "tx", "ty", "tz",
	"size_x", "size_y", "size_z", "cost", "iterations", "nfev", "status", NULL,
};

void mkFitting_WriteRow(mkCsv *out, const mkFitRow *r)
{
	mkCsv_Int(out, r->caseId);
	mkCsv_Int(out, r->trial);
	mkCsv_Str(out, r->truth);
	mkCsv_Str(out, r->model);
	mkCsv_Str(out, r->sampling);
	mkCsv_Int(out, r->level);
	mkCsv_Int(out, r->vertices);
	mkCsv_Double(out, r->volumeTrue);
	mkCsv_Double(out, r->volumeModel);
	mkCsv_Double(out, r->eVolume);
	mkCsv_Double(out, r->eImplicit);
	mkCsv_Double(out, r->shape.a);
	mkCsv_Double(out, r->shape.b);
	mkCsv_Double(out, r->shape.c);
	mkCsv_Double(out, r->shape.eps1);
	mkCsv_Double(out, r->shape.eps2);
	for (int i = 0; i < 4; ++i) {
		mkCsv_Double(out, r->q[i]);
	}
	mkCsv_Double(out, r->t.x);
	mkCsv_Double(out, r->t.y);
	mkCsv_Double(out, r->t.z);
	for (int i = 0; i < 3; ++i) {
		mkCsv_Double(out, r->size[i]);
	}
	mkCsv_Double(out, r->cost);
	mkCsv_Int(out, r->iterations);
	mkCsv_Int(out, r->nfev);
	mkCsv_Str(out, r->status);
	mkCsv_EndRow(out);
}

/* ---- the summary --------------------------------------------------------- */

/* The mean of the rows a published figure describes (NaN when none). */
static mkMean mkFitting_Mean(const mkTable *t, const mkPaperFitting *pub)
{
	int ccase = mkTable_Col(t, "case"), ctruth = mkTable_Col(t, "truth"), cmodel = mkTable_Col(t, "model");
	int csamp = mkTable_Col(t, "sampling"), clevel = mkTable_Col(t, "level");
	int cvol = mkTable_Col(t, "e_volume"), cimp = mkTable_Col(t, "e_implicit");
	mkMean mean;
	memset(&mean, 0, sizeof mean);
	for (long r = 0; r < t->rows; ++r) {
		if ((int)mkTable_Num(t, r, ccase) != pub->fit_case)
			continue;
		if (pub->truth[0] && strcmp(mkTable_Str(t, r, ctruth), pub->truth) != 0)
			continue;
		if (pub->model[0] && strcmp(mkTable_Str(t, r, cmodel), pub->model) != 0)
			continue;
		if (pub->sampling[0] && strcmp(mkTable_Str(t, r, csamp), pub->sampling) != 0)
			continue;
		if (pub->level && (int)mkTable_Num(t, r, clevel) != pub->level)
			continue;
		mkMean_Add(&mean, mkTable_Num(t, r, pub->implicit ? cimp : cvol));
	}
	return mean;
}

void mkFitting_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	static const char *const columns[] = { "case", "truth", "model", "sampling", "level", "e_volume",
		"e_implicit", NULL };
	mkSection s;
	int usable = mkSection_Begin(&s, d, "Fitting errors (paper §6.2)", dir, "fitting.csv", columns,
		"The nine published means are listed without a counterpart.");
	const mkTable *t = &s.t;
	if (usable) {
		const char *c2 = mkMeta_Get(&s.m, "case2_draw");
		mkDoc_Para(d, "Rotation draw: only case 2 rotates its superquadric (%s); a rotation cannot change a "
			"volume, so the draw does not enter these errors. Ratio = reproduced / published.",
			c2 ? c2 : "draw not recorded");
	}
	static const char *const head[] = { "published figure (mean of 100 trials)", "published", "reproduced",
		"ratio", "rows (finite)" };
	mkDoc_TableBegin(d, "Fitting errors: relative volume error e_volume (and e_implicit in case 1), "
		"published and reproduced means.", 5, head);
	int disagree = 0;
	for (int i = 0; i < mkPaper_FittingCount; ++i) {
		const mkPaperFitting *pub = &mkPaper_Fitting[i];
		mkMean mean;
		memset(&mean, 0, sizeof mean);
		if (usable)
			mean = mkFitting_Mean(t, pub);
		double v = mkMean_Get(&mean);
		char got[MK_CELL_MAX], ratio[MK_CELL_MAX], rows[MK_CELL_MAX];
		if (!usable || (mean.n == 0 && mean.nan == 0)) {
			snprintf(got, sizeof got, "%s", mkNotYet);
			snprintf(rows, sizeof rows, "0");
		} else {
			snprintf(got, sizeof got, "%.4f", v);
			snprintf(rows, sizeof rows, "%ld (%ld)", mean.n + mean.nan, mean.n);
		}
		mkFmt_Ratio(ratio, sizeof ratio, usable ? v : NAN, pub->value);
		const char *row[5] = { pub->what, pub->text, got, ratio, rows };
		mkDoc_Row(d, row);
		mkTally_Add(tally, usable && mean.n > 0);
		double q = v / pub->value;
		if (mean.n > 0 && (q < 0.8 || q > 1.25))
			disagree += 1;
	}
	mkDoc_TableEnd(d);
	if (usable)
		mkDoc_Para(d, "%d of %d figures differ from the published mean by more than 25%% (ratio outside "
			"[0.8, 1.25]); means of 100 random trials of these errors scatter by several percent between "
			"seeds. The `distinct` sampling rows of the CSV (grids without the repeated longitude of the "
			"reference code) are not in this table.", disagree, mkPaper_FittingCount);
	mkSection_End(&s);
}

