/* demo_run.c - what the figure writers share (demos_internal.h): opening
 * and committing a geometry file with its index row, SPEC numbers, bodies
 * from SPEC text, the run's sum options and point buffers. demos.c and
 * fig4.c write the figures on it. */
#include "demos.h"
#include "demos_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the run: index rows, geometry files --------------------------------- */



const char *const mkDemos_Columns[] = {
	"figure", "panel", "file", "rows", "content", "body1", "body2", "set", "form", "param", "n", "note", NULL
};

int mkDemoRun_Open(mkDemoRun *run, const char *name, const char *const *cols, int ncols, mkCsv *csv)
{
	if (mkRun_OpenSibling(run->run, name, cols, ncols, csv) != 0) {
		run->failed = 1;
		return -1;
	}
	return 0;
}

/* Commit a geometry file with its sidecar and add its index row. */
int mkDemoRun_Commit(mkDemoRun *run, mkCsv *csv, const mkDemoEntry *e)
{
	char msg[1024];
	long rows = csv->rows;
	mkMeta *meta = &run->run->meta;
	mkMeta_SetInt(meta, "figure", e->figure);
	mkMeta_Set(meta, "panel", e->panel);
	mkMeta_Set(meta, "content", e->content);
	mkMeta_Set(meta, "body1", e->body1);
	mkMeta_Set(meta, "body2", e->body2);
	mkMeta_Set(meta, "note", e->note);
	if (mkCsv_Commit(csv, meta, msg, sizeof msg) != 0) {
		fprintf(stderr, "demos: %s\n", msg);
		run->failed = 1;
		return -1;
	}
	mkCsv *ix = &run->run->csv;
	mkCsv_Int(ix, e->figure);
	mkCsv_Str(ix, e->panel);
	mkCsv_Str(ix, e->file);
	mkCsv_Int(ix, rows);
	mkCsv_Str(ix, e->content);
	mkCsv_Str(ix, e->body1);
	mkCsv_Str(ix, e->body2);
	mkCsv_Str(ix, mkSet_Name(MK_SET_CONTACT));
	mkCsv_Str(ix, e->form);
	mkCsv_Str(ix, e->param);
	mkCsv_Int(ix, e->n);
	mkCsv_Str(ix, e->note);
	mkCsv_EndRow(ix);
	return 0;
}

mkDemoNum mkDemo_Fmt(double v)
{
	mkDemoNum n;
	for (int digits = 15; digits <= 17; ++digits) {
		snprintf(n.s, sizeof n.s, "%.*g", digits, v);
		if (strtod(n.s, NULL) == v)
			break;
	}
	return n;
}

/* The body of a SPEC text into *out: an mkBody2 when dim is 2, an mkBody3
 * when 3. Returns 0, or -1 after printing why. */
int mkDemo_ParseBody(const char *text, int dim, const char *what, void *out)
{
	mkSpec spec;
	char msg[512];
	if (mkSpec_Parse(text, dim, what, &spec, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "demos: %s: %s (SPEC '%s')\n", what, msg, text);
		return -1;
	}
	if (dim == 2)
		*(mkBody2 *)out = spec.body2;
	else
		*(mkBody3 *)out = spec.body3;
	return 0;
}

mkSumOptions mkDemo_Options(const mkDemosOptions *o, mkForm form, mkParam param)
{
	mkSumOptions opt = mkSumOptions_Default();
	opt.set = MK_SET_CONTACT;
	opt.form = form;
	opt.param = param;
	opt.impl = o->impl;
	return opt;
}


int mkDemoPts_Alloc(mkDemoPts *p, int n)
{
	memset(p, 0, sizeof *p);
	p->n = n;
	double **all[] = { &p->ux, &p->uy, &p->uz, &p->x, &p->y, &p->z, &p->kx, &p->ky, &p->kz };
	int ok = 1;
	for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) {
		*all[i] = malloc((size_t)n * sizeof(double));
		ok = ok && *all[i] != NULL;
	}
	if (!ok)
		fprintf(stderr, "demos: out of memory for %d points\n", n);
	return ok ? 0 : -1;
}

void mkDemoPts_Free(mkDemoPts *p)
{
	double *all[] = { p->ux, p->uy, p->uz, p->x, p->y, p->z, p->kx, p->ky, p->kz };
	for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
		free(all[i]);
	memset(p, 0, sizeof *p);
}
