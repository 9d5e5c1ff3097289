/* demos_internal.h - what the figure writers (demos.c, fig4.c) share, from
 * demo_run.c: the run, an index row, SPEC numbers, body parsing, sum
 * options and point buffers. Not installed. */
#ifndef MINK_DEMOS_INTERNAL_H
#define MINK_DEMOS_INTERNAL_H

#include "demos.h"

typedef struct mkDemoRun {
	const mkDemosOptions *o;
	mkRun *run;
	int failed;
} mkDemoRun;

/* What one geometry file shows, for its index row. */
typedef struct mkDemoEntry {
	int figure;
	const char *panel;
	const char *file;
	const char *content;
	const char *body1;   /* SPEC text, or "" */
	const char *body2;
	const char *form;    /* closed form used, or "" */
	const char *param;
	long n;              /* parameters of the sum (3D: grid side), 0 if none */
	const char *note;
} mkDemoEntry;

/* The shortest of %.15g, %.16g, %.17g that reads back to v, so that the SPEC
 * texts stay readable ("8.6", not "8.5999999999999996") and exact. */
typedef struct mkDemoNum { char s[32]; } mkDemoNum;

/* Buffers of n points (2D or 3D), owned by the caller. */
typedef struct mkDemoPts {
	int n;
	double *ux, *uy, *uz, *x, *y, *z, *kx, *ky, *kz;
} mkDemoPts;

/* Open a geometry file beside the index (0, or -1 with run->failed set). */
int mkDemoRun_Open(mkDemoRun *run, const char *name, const char *const *cols, int ncols, mkCsv *csv);
/* Commit a geometry file with its sidecar and add its index row. */
int mkDemoRun_Commit(mkDemoRun *run, mkCsv *csv, const mkDemoEntry *e);
mkDemoNum mkDemo_Fmt(double v);
/* The body of a SPEC text into *out: an mkBody2 when dim is 2, an mkBody3
 * when 3. Returns 0, or -1 after printing why. */
int mkDemo_ParseBody(const char *text, int dim, const char *what, void *out);
/* The run's sum options for the contact set with this form and parameter. */
mkSumOptions mkDemo_Options(const mkDemosOptions *o, mkForm form, mkParam param);
/* Allocate n points' buffers (0, or -1 after printing why); free them. */
int mkDemoPts_Alloc(mkDemoPts *p, int n);
void mkDemoPts_Free(mkDemoPts *p);

/* Fig. 4: 3D pairs on 50 x 50 grids (fig4.c). */
void mkFigure4(mkDemoRun *run);

#endif
