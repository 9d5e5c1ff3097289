/* closed.c - the core's closed forms as registry entries: one boundary
 * point per surface parameter of body 1 (mkSample2_Angles / mkSample3_Grid),
 * computed by the core's batch kernels. */
#include <stdlib.h>

#include <mink/registry.h>

#include "registry_internal.h"

static mkResult run2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out, mkForm form, mkPrecision prec)
{
	if (!out) return MK_ERR_ARGUMENT;
	if (n < 1) return MK_ERR_RANGE;
	double *u = malloc(2 * (size_t)n * sizeof *u);
	if (!u) return MK_ERR_MEMORY;
	mkResult r = mkSample2_Angles(n, u, u + n);
	if (r == MK_OK) r = mkPointSet_Resize(out, 2, n);
	if (r == MK_OK) {
		mkSumOptions opt = mkSumOptions_Default();
		opt.set = set;
		opt.form = form;
		opt.param = MK_PARAM_SURFACE;
		/* The paper's form exists only as the scalar reference kernel. */
		opt.impl = form == MK_FORM_PAPER ? MK_IMPL_SCALAR : MK_IMPL_AUTO;
		opt.precision = prec;
		r = mkSum2_Batch(b1, b2, &opt, u, u + n, n, out->x, out->y, NULL, NULL);
	}
	free(u);
	return r;
}

static mkResult run3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out, mkForm form, mkPrecision prec)
{
	if (!out) return MK_ERR_ARGUMENT;
	if (n < 2 || n > MK_CLOSED3_N_MAX) return MK_ERR_RANGE;
	int count = n * n;
	double *u = malloc(3 * (size_t)count * sizeof *u);
	if (!u) return MK_ERR_MEMORY;
	mkResult r = mkSample3_Grid(n, u, u + count, u + 2 * (size_t)count);
	if (r == MK_OK) r = mkPointSet_Resize(out, 3, count);
	if (r == MK_OK) {
		mkSumOptions opt = mkSumOptions_Default();
		opt.set = set;
		opt.form = form;
		opt.param = MK_PARAM_SURFACE;
		opt.impl = form == MK_FORM_PAPER ? MK_IMPL_SCALAR : MK_IMPL_AUTO;
		opt.precision = prec;
		r = mkSum3_Batch(b1, b2, &opt, u, u + count, u + 2 * (size_t)count, count,
			out->x, out->y, out->z, NULL, NULL, NULL);
	}
	free(u);
	return r;
}

static mkResult normal2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return run2(b1, b2, set, n, out, MK_FORM_NORMAL, MK_PRECISION_DOUBLE);
}
static mkResult normal3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return run3(b1, b2, set, n, out, MK_FORM_NORMAL, MK_PRECISION_DOUBLE);
}
static mkResult gradient2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return run2(b1, b2, set, n, out, MK_FORM_GRADIENT, MK_PRECISION_DOUBLE);
}
static mkResult gradient3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return run3(b1, b2, set, n, out, MK_FORM_GRADIENT, MK_PRECISION_DOUBLE);
}
static mkResult paper2(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return run2(b1, b2, set, n, out, MK_FORM_PAPER, MK_PRECISION_DOUBLE);
}
static mkResult paper3(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return run3(b1, b2, set, n, out, MK_FORM_PAPER, MK_PRECISION_DOUBLE);
}

static mkResult normal2f(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return run2(b1, b2, set, n, out, MK_FORM_NORMAL, MK_PRECISION_F32);
}
static mkResult normal3f(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return run3(b1, b2, set, n, out, MK_FORM_NORMAL, MK_PRECISION_F32);
}
static mkResult gradient2f(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	return run2(b1, b2, set, n, out, MK_FORM_GRADIENT, MK_PRECISION_F32);
}
static mkResult gradient3f(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	return run3(b1, b2, set, n, out, MK_FORM_GRADIENT, MK_PRECISION_F32);
}

const mkMethod mkMethod_ClosedNormal = {
	"closed-normal",
	"closed form, Theorem 1: support points f~1(n) - f~2(-n) along body 1's normals",
	"Ruan & Chirikjian, CAD 2022, Theorem 1 and eq. mink_sum_transform_1",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_EXACT,
	mkAcceptAny2, mkAcceptAny3, normal2, normal3,
};

const mkMethod mkMethod_ClosedGradient = {
	"closed-gradient",
	"closed form, Theorem 2: un-normalised gradients, f~~ evaluated stably",
	"Ruan & Chirikjian, CAD 2022, Theorem 2 and eq. mink_sum_transform_2",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_EXACT,
	mkAcceptAny2, mkAcceptAny3, gradient2, gradient3,
};

const mkMethod mkMethod_ClosedPaper = {
	"closed-paper",
	"Theorem 2 exactly as printed (reference only: loses digits near the 3D poles)",
	"Ruan & Chirikjian, CAD 2022, eqs. 2d_sq_f_m, 3d_sq_f_m, Phi_m1_general",
	MK_METHOD_2D | MK_METHOD_3D,
	mkAcceptAny2, mkAcceptAny3, paper2, paper3,
};

/* The single-precision tier (mink/sum.h, MK_PRECISION_F32): the same closed
 * forms, each point within MK_F32_TOL of the scale of the exact boundary;
 * pairs outside the tier's domain run in double. */
const mkMethod mkMethod_ClosedNormalF32 = {
	"closed-normal-f32",
	"closed form, Theorem 1, in single precision (about 2x faster; points within 1e-6 of scale)",
	"Ruan & Chirikjian, CAD 2022, Theorem 1; mink's f32 tier (docs/fast-tiers.md)",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_APPROX,
	mkAcceptAny2, mkAcceptAny3, normal2f, normal3f,
};

const mkMethod mkMethod_ClosedGradientF32 = {
	"closed-gradient-f32",
	"closed form, Theorem 2, in single precision (about 2x faster; points within 1e-6 of scale)",
	"Ruan & Chirikjian, CAD 2022, Theorem 2; mink's f32 tier (docs/fast-tiers.md)",
	MK_METHOD_2D | MK_METHOD_3D | MK_METHOD_APPROX,
	mkAcceptAny2, mkAcceptAny3, gradient2f, gradient3f,
};
