/* closed.c - the core's closed forms as a family of registry entries (one
 * per form, bound in registry.c): one boundary point per surface parameter
 * of body 1 (mkSample2_Angles / mkSample3_Grid), computed by the core's
 * batch kernels. Also the surface parameters themselves, which the
 * geometric method shares. */
#include <stdlib.h>

#include <mink/registry.h>

#include "registry_internal.h"

mkResult mkSurface2_Params(int n, mkPointSet *out, double **u)
{
	*u = malloc(2 * (size_t)n * sizeof **u);
	if (!*u) return MK_ERR_MEMORY;
	mkResult r = mkSample2_Angles(n, *u, *u + n);
	if (r == MK_OK) r = mkPointSet_Resize(out, 2, n);
	return r;
}

mkResult mkSurface3_Params(int n, mkPointSet *out, double **u)
{
	int count = n * n;
	*u = malloc(3 * (size_t)count * sizeof **u);
	if (!*u) return MK_ERR_MEMORY;
	mkResult r = mkSample3_Grid(n, *u, *u + count, *u + 2 * (size_t)count);
	if (r == MK_OK) r = mkPointSet_Resize(out, 3, count);
	return r;
}

/* Surface parameters in; the paper's form exists only as the scalar
 * reference kernel. */
static mkSumOptions options(mkSet set, mkForm form, mkPrecision prec)
{
	mkSumOptions opt = mkSumOptions_Default();
	opt.set = set;
	opt.form = form;
	opt.param = MK_PARAM_SURFACE;
	opt.impl = form == MK_FORM_PAPER ? MK_IMPL_SCALAR : MK_IMPL_AUTO;
	opt.precision = prec;
	return opt;
}

mkResult mkClosed2_Run(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out, mkForm form, mkPrecision prec)
{
	if (!out) return MK_ERR_ARGUMENT;
	if (n < 1) return MK_ERR_RANGE;
	double *u;
	mkResult r = mkSurface2_Params(n, out, &u);
	if (r == MK_OK) {
		mkSumOptions opt = options(set, form, prec);
		r = mkSum2_Batch(b1, b2, &opt, u, u + n, n, out->x, out->y, NULL, NULL);
	}
	free(u);
	return r;
}

mkResult mkClosed3_Run(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out, mkForm form, mkPrecision prec)
{
	if (!out) return MK_ERR_ARGUMENT;
	if (n < 2 || n > MK_CLOSED3_N_MAX) return MK_ERR_RANGE;
	double *u;
	mkResult r = mkSurface3_Params(n, out, &u);
	if (r == MK_OK) {
		int count = n * n;
		mkSumOptions opt = options(set, form, prec);
		r = mkSum3_Batch(b1, b2, &opt, u, u + count, u + 2 * (size_t)count, count,
			out->x, out->y, out->z, NULL, NULL, NULL);
	}
	free(u);
	return r;
}
