/* cmd_sum.c - `mink sum`: boundary points as CSV. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/mink.h>
#include <mink_exp/outfile.h>
#ifdef MINK_HAVE_REGISTRY
#include <mink/external.h>
#include <mink/registry.h>
#endif

#include "cli.h"
#include "commands.h"

#define N2_MAX 10000000L /* 2D points */
#define N3_MAX 3000L     /* 3D grid side: 9e6 points */

static void help(FILE *fp)
{
	fprintf(fp,
		"usage: mink sum --dim 2|3 --body1 SPEC --body2 SPEC [options]\n"
		"\n"
		"Boundary points of the contact space B1 (+) (-B2) (where B2's centre may go\n"
		"so that B2 touches B1) or of B1 (+) B2, as CSV with header x,y or x,y,z\n"
		"(and kx,ky[,kz] with --contact).\n"
		"\n"
		"SPEC: KIND key=value ...  with KIND circle, ellipse, superellipse (2D) or sphere,\n"
		"ellipsoid, superquadric (3D); keys a, b, c, eps (2D), eps1, eps2 (3D), rot=ANGLE\n"
		"(2D), quat=w,x,y,z (3D), shear=S (2D, M = R [1 S; 0 1]), M=m11,m12,... (row-major,\n"
		"replaces rot/quat/shear), at=x,y[,z]. The body is at + M B_canonical. For the\n"
		"contact space B2's 'at' is ignored.\n"
		"\n");
}

typedef struct SumArgs {
	int dim;
	const char *spec1, *spec2, *out, *method;
	long n;
	int have_n;
	mkSumOptions opt;
	int contact;
} SumArgs;

static int write_rows(FILE *fp, int dim, int count, const double *const *cols, int ncols)
{
	static const char *names[] = {"x", "y", "z", "kx", "ky", "kz"};
	int per = dim; /* columns per point group */
	for (int c = 0; c < ncols; ++c) {
		int g = c / per, k = c % per;
		fprintf(fp, "%s%s", c ? "," : "", names[g * 3 + k]);
	}
	fputc('\n', fp);
	for (int i = 0; i < count; ++i) {
		for (int c = 0; c < ncols; ++c) fprintf(fp, "%s%.17g", c ? "," : "", cols[c][i]);
		fputc('\n', fp);
	}
	return ferror(fp) ? -1 : 0;
}

/* Emit to --out (atomically) or stdout. */
static int emit(const SumArgs *a, int count, const double *const *cols, int ncols)
{
	if (!a->out) {
		if (write_rows(stdout, a->dim, count, cols, ncols) || fflush(stdout)) {
			fprintf(stderr, "mink sum: writing to standard output failed\n");
			return 1;
		}
		return 0;
	}
	mkOutFile f;
	char msg[512];
	if (mkOutFile_Open(&f, a->out, msg, sizeof msg)) {
		fprintf(stderr, "mink sum: --out %s: %s\n", a->out, msg);
		return 1;
	}
	if (write_rows(f.fp, a->dim, count, cols, ncols)) {
		mkOutFile_Discard(&f);
		fprintf(stderr, "mink sum: --out %s: write failed\n", a->out);
		return 1;
	}
	if (mkOutFile_Commit(&f, msg, sizeof msg)) {
		fprintf(stderr, "mink sum: --out %s: %s\n", a->out, msg);
		return 1;
	}
	return 0;
}

static int run_closed(const SumArgs *a, const mkSpec *s1, const mkSpec *s2)
{
	long count = a->dim == 2 ? a->n : a->n * a->n;
	size_t nb = (size_t)count * sizeof(double);
	int ncols = a->dim * (a->contact ? 2 : 1);
	double *buf[9] = {0};
	int fail = 0;
	for (int i = 0; i < 3 + ncols; ++i)
		if (!(buf[i] = malloc(nb))) fail = 1;
	int rc = 1;
	if (fail) {
		fprintf(stderr, "mink sum: out of memory for %ld points\n", count);
		goto done;
	}
	double **u = buf, **o = buf + 3;
	mkResult r;
	if (a->dim == 2) {
		mkSample2_Angles((int)count, u[0], u[1]);
		r = mkSum2_Batch(s1->body2, s2->body2, &a->opt, u[0], u[1], (int)count, o[0], o[1],
			a->contact ? o[2] : NULL, a->contact ? o[3] : NULL);
	} else {
		mkSample3_Grid((int)a->n, u[0], u[1], u[2]);
		r = mkSum3_Batch(s1->body3, s2->body3, &a->opt, u[0], u[1], u[2], (int)count, o[0], o[1], o[2],
			a->contact ? o[3] : NULL, a->contact ? o[4] : NULL, a->contact ? o[5] : NULL);
	}
	if (r != MK_OK) {
		if (r == MK_ERR_UNSUPPORTED)
			fprintf(stderr, "mink sum: --form %s with --param %s and --impl %s is not supported%s\n",
				mkForm_Name(a->opt.form), mkParam_Name(a->opt.param), mkImpl_Name(a->opt.impl),
				a->opt.form == MK_FORM_PAPER ? " (the paper form needs --param surface and the scalar kernel)"
				: " on this CPU");
		else
			fprintf(stderr, "mink sum: %s\n", mkResult_Name(r));
		goto done;
	}
	rc = emit(a, (int)count, (const double *const *)o, ncols);
done:
	for (int i = 0; i < 9; ++i) free(buf[i]);
	return rc;
}

#ifdef MINK_HAVE_REGISTRY
static int run_method(const SumArgs *a, const mkSpec *s1, const mkSpec *s2)
{
	const mkMethod *m = mkRegistry_Find(a->method);
	if (!m) {
		fprintf(stderr, "mink sum: --method %s is unknown: see 'mink methods' for the list\n", a->method);
		return 2;
	}
	if (!(m->flags & (a->dim == 2 ? MK_METHOD_2D : MK_METHOD_3D))) {
		fprintf(stderr, "mink sum: method %s does not run in %dD\n", m->name, a->dim);
		return 2;
	}
	if (a->contact) {
		fprintf(stderr, "mink sum: --contact needs a closed form (no --method, or --method closed-*)\n");
		return 2;
	}
	char msg[512] = "";
	if (!mkMethod_CheckN(m, a->dim, (int)a->n, msg, sizeof msg)) {
		fprintf(stderr, "mink sum: --n: %s\n", msg);
		return 2;
	}
	int ok = a->dim == 2 ? mkMethod2_Accepts(m, s1->body2, s2->body2, a->opt.set, msg, sizeof msg)
		: mkMethod3_Accepts(m, s1->body3, s2->body3, a->opt.set, msg, sizeof msg);
	if (!ok) {
		fprintf(stderr, "mink sum: method %s does not accept this pair: %s\n", m->name, msg);
		return 2;
	}
	mkPointSet ps = {0};
	mkResult r = a->dim == 2 ? m->run2(s1->body2, s2->body2, a->opt.set, (int)a->n, &ps)
		: m->run3(s1->body3, s2->body3, a->opt.set, (int)a->n, &ps);
	int rc = 1;
	if (r != MK_OK) {
		fprintf(stderr, "mink sum: method %s failed: %s%s%s\n", m->name, mkResult_Name(r),
			mkExternal_Is(m) ? ": " : "", mkExternal_Is(m) ? mkExternal_Message(m) : "");
	} else {
		const double *cols[3] = {ps.x, ps.y, ps.z};
		rc = emit(a, ps.count, cols, a->dim);
	}
	mkPointSet_Free(&ps);
	return rc;
}
#endif

static const char *const mkFormNames[] = { "normal", "gradient", "paper" };
static const char *const mkParamNames[] = { "surface", "normal" };

int mkCmd_Sum(int argc, char **argv)
{
	SumArgs a = {0};
	a.opt = mkSumOptions_Default();
	long dim = 0;
	int set = (int)a.opt.set, form = (int)a.opt.form, param = (int)a.opt.param, impl = (int)a.opt.impl;
	mkFlag flags[] = {
		MK_FLAG_LONG("--dim", "2|3", "dimension (required)", &dim, 2, 3),
		MK_FLAG_TEXT("--body1", "SPEC", "the first body, e.g. \"superellipse a=3 b=2 eps=0.5 rot=0.3\"", &a.spec1, NULL),
		MK_FLAG_TEXT("--body2", "SPEC", "the second body", &a.spec2, NULL),
		MK_FLAG_LONG("--n", "N", "2D: N points (default 100); 3D: an N x N parameter grid\n(default 50); N >= 3, at "
			"most 10000000 (2D) or 3000 (3D)", &a.n, 3, N2_MAX),
		MK_FLAG_SET("--set", "contact space (default) or B1 (+) B2", &set),
		MK_FLAG_CHOICE("--form", "normal|gradient|paper", "Theorem 1 (normal), Theorem 2 (gradient, default), or the\n"
			"published gradient formula as printed (paper; reference only)", &form, mkFormNames),
		MK_FLAG_CHOICE("--param", "surface|normal", "points uniform in B1's surface angles (default, the paper's)\n"
			"or uniform in the normal's angles", &param, mkParamNames),
		MK_FLAG_IMPL("--impl", "which compiled kernel (default auto)", &impl),
		MK_FLAG_SWITCH("--contact", "add columns kx,ky[,kz]: the kissing point on B1's boundary", &a.contact),
		MK_FLAG_TEXT("--method", "NAME", "run a registered method instead (see 'mink methods'); for\n"
			"sampled methods N is the number of samples per body", &a.method, NULL),
		MK_FLAG_PATH("--out", "FILE", "write to FILE (atomically: complete or not at all);\n"
			"default standard output", &a.out),
	};
	int rc = mkCli_Parse("sum", flags, MK_COUNT(flags), argc, argv, help);
	if (rc != MK_CLI_GO)
		return rc;
	if ((rc = mkCli_Require("sum", &flags[0])) != MK_CLI_GO || (rc = mkCli_Require("sum", &flags[1])) != MK_CLI_GO
		|| (rc = mkCli_Require("sum", &flags[2])) != MK_CLI_GO)
		return rc;
	a.dim = (int)dim;
	a.have_n = flags[3].given;
	a.opt.set = (mkSet)set;
	a.opt.form = (mkForm)form;
	a.opt.param = (mkParam)param;
	a.opt.impl = (mkImpl)impl;
	if (!a.have_n) a.n = a.dim == 2 ? 100 : 50;
	if (a.dim == 3 && a.n > N3_MAX) {
		fprintf(stderr, "mink sum: --n = '%ld' is out of range: in 3D must be an integer in [3, %ld] "
			"(an N x N grid)\n", a.n, N3_MAX);
		return 2;
	}
	mkSpec s1, s2;
	char msg[512];
	if (mkSpec_Parse(a.spec1, a.dim, "body1", &s1, msg, sizeof msg) != MK_OK
		|| mkSpec_Parse(a.spec2, a.dim, "body2", &s2, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "mink sum: %s\n", msg);
		return 2;
	}
	if (a.method) {
		static const char *const closed[] = {"closed-normal", "closed-gradient", "closed-paper"};
		for (int k = 0; k < 3; ++k)
			if (strcmp(a.method, closed[k]) == 0) {
				a.opt.form = (mkForm)k;
				a.method = NULL;
				break;
			}
	}
	if (a.method) {
#ifdef MINK_HAVE_REGISTRY
		return run_method(&a, &s1, &s2);
#else
		fprintf(stderr, "mink sum: --method %s needs the baselines, which this build left out "
			"(configure with -DMINK_BUILD_BASELINES=ON)\n", a.method);
		return 2;
#endif
	}
	return run_closed(&a, &s1, &s2);
}
