/* sum.c - the batch entry points: argument checks, the per-call constants,
 * the choice of kernel, the published gradient formula as a reference, the
 * paper's parameter sampling and the ellipsoid special forms. */
#include "mink/sum.h"

#include <assert.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "kernels/kernel.h"


mkSumOptions mkSumOptions_Default(void)
{
	mkSumOptions o = {MK_SET_CONTACT, MK_FORM_GRADIENT, MK_PARAM_SURFACE, MK_IMPL_AUTO, MK_PRECISION_DOUBLE};
	return o;
}

static const char *const set_names[] = {"contact", "plus"};
static const char *const form_names[] = {"normal", "gradient", "paper"};
static const char *const param_names[] = {"surface", "normal"};
static const char *const impl_names[] = {"auto", "scalar", "avx2", "avx512"};
static const char *const precision_names[] = {"double", "f32"};

#define NAME_OF(tab, v) ((int)(v) >= 0 && (size_t)(v) < sizeof tab / sizeof tab[0] ? tab[(int)(v)] : "?")

static int parse_name(const char *const *tab, int n, const char *s)
{
	if (!s) return -1;
	for (int i = 0; i < n; ++i)
		if (strcmp(tab[i], s) == 0) return i;
	return -1;
}

const char *mkSet_Name(mkSet v) { return NAME_OF(set_names, v); }
const char *mkForm_Name(mkForm v) { return NAME_OF(form_names, v); }
const char *mkParam_Name(mkParam v) { return NAME_OF(param_names, v); }
const char *mkImpl_Name(mkImpl v) { return NAME_OF(impl_names, v); }
const char *mkPrecision_Name(mkPrecision v) { return NAME_OF(precision_names, v); }
int mkSet_Parse(const char *s) { return parse_name(set_names, 2, s); }
int mkForm_Parse(const char *s) { return parse_name(form_names, 3, s); }
int mkParam_Parse(const char *s) { return parse_name(param_names, 2, s); }
int mkImpl_Parse(const char *s) { return parse_name(impl_names, 4, s); }
int mkPrecision_Parse(const char *s) { return parse_name(precision_names, 2, s); }

/* Calls the kernel NAME built for the resolved impl: NAME_avx512,
 * NAME_avx2 or NAME_scalar (every kernel has the three builds). */
#if defined(MINK_HAVE_X86_KERNELS)
#define MK_DISPATCH(impl, name, ...) \
	do { \
		switch (impl) { \
		case MK_IMPL_AVX512: name##_avx512(__VA_ARGS__); break; \
		case MK_IMPL_AVX2: name##_avx2(__VA_ARGS__); break; \
		default: name##_scalar(__VA_ARGS__); break; \
		} \
	} while (0)
#else
#define MK_DISPATCH(impl, name, ...) name##_scalar(__VA_ARGS__)
#endif

int mkImpl_Available(mkImpl impl)
{
	switch (impl) {
	case MK_IMPL_AUTO:
	case MK_IMPL_SCALAR:
		return 1;
#if defined(MINK_HAVE_X86_KERNELS)
	case MK_IMPL_AVX2:
		return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
	case MK_IMPL_AVX512:
		return __builtin_cpu_supports("avx512f");
#endif
	default:
		return 0;
	}
}

mkImpl mkImpl_Resolve(mkImpl impl)
{
	if (impl != MK_IMPL_AUTO) return impl;
	if (mkImpl_Available(MK_IMPL_AVX512)) return MK_IMPL_AVX512;
	if (mkImpl_Available(MK_IMPL_AVX2)) return MK_IMPL_AVX2;
	return MK_IMPL_SCALAR;
}

static int options_ok(const mkSumOptions *o)
{
	return o && (o->set == MK_SET_CONTACT || o->set == MK_SET_PLUS)
		&& (o->form == MK_FORM_NORMAL || o->form == MK_FORM_GRADIENT || o->form == MK_FORM_PAPER)
		&& (o->param == MK_PARAM_SURFACE || o->param == MK_PARAM_NORMAL)
		&& (int)o->impl >= MK_IMPL_AUTO && o->impl <= MK_IMPL_AVX512
		&& (o->precision == MK_PRECISION_DOUBLE || o->precision == MK_PRECISION_F32);
}

static void plan2(mkKPlan2 *p, mkBody2 b1, mkBody2 b2, const mkSumOptions *o)
{
	mkKShape2_Prepare(&p->s1, b1.shape);
	mkKShape2_Prepare(&p->s2, b2.shape);
	mkMat2 M1T = mkMat2_Transpose(b1.M), M2T = mkMat2_Transpose(b2.M);
	int plus = o->set == MK_SET_PLUS;
	double sg = plus ? 1.0 : -1.0;
	mkMat2 D2 = o->param == MK_PARAM_SURFACE ? mkMat2_Mul(M2T, mkMat2_Transpose(mkMat2_Inverse(b1.M))) : M2T;
	memcpy(p->M1, b1.M.m, sizeof p->M1);
	memcpy(p->M1T, M1T.m, sizeof p->M1T);
	memcpy(p->M2, b2.M.m, sizeof p->M2);
	for (int i = 0; i < 2; ++i)
		for (int j = 0; j < 2; ++j) p->D2[i][j] = sg * D2.m[i][j];
	p->t1[0] = b1.t.x; p->t1[1] = b1.t.y;
	p->t2p[0] = plus ? b2.t.x : 0.0; p->t2p[1] = plus ? b2.t.y : 0.0;
	p->sigma = sg;
	p->form = o->form; p->param = o->param;
}

static void plan3(mkKPlan3 *p, mkBody3 b1, mkBody3 b2, const mkSumOptions *o)
{
	mkKShape3_Prepare(&p->s1, b1.shape);
	mkKShape3_Prepare(&p->s2, b2.shape);
	mkMat3 M1T = mkMat3_Transpose(b1.M), M2T = mkMat3_Transpose(b2.M);
	int plus = o->set == MK_SET_PLUS;
	double sg = plus ? 1.0 : -1.0;
	mkMat3 D2 = o->param == MK_PARAM_SURFACE ? mkMat3_Mul(M2T, mkMat3_Transpose(mkMat3_Inverse(b1.M))) : M2T;
	memcpy(p->M1, b1.M.m, sizeof p->M1);
	memcpy(p->M1T, M1T.m, sizeof p->M1T);
	memcpy(p->M2, b2.M.m, sizeof p->M2);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) p->D2[i][j] = sg * D2.m[i][j];
	p->t1[0] = b1.t.x; p->t1[1] = b1.t.y; p->t1[2] = b1.t.z;
	p->t2p[0] = plus ? b2.t.x : 0.0; p->t2p[1] = plus ? b2.t.y : 0.0; p->t2p[2] = plus ? b2.t.z : 0.0;
	p->sigma = sg;
	p->form = o->form; p->param = o->param;
}

/* ---- the single-precision tier: its constants and its domain ------------------ */

/* The float copies of a plan. Only the directions of M1^T u and of D2 v
 * matter, so both matrices are divided by their largest entry; every length
 * is divided by the largest semi-axis s of the pair (the canonical shapes
 * then have semi-axes in (0, 1]) and M1, M2 are multiplied by s, which puts
 * the points back in place. The products the kernels form then stay inside
 * the normal float range wherever the domain test below holds. */
static void shape2f(mkKShape2f *f, const mkKShape2 *s, double inv)
{
	f->a = (float)(s->a * inv); f->b = (float)(s->b * inv); f->eps = (float)s->eps;
	f->q = (float)s->q; f->qm1 = (float)s->qm1; f->k = (float)s->k;
	f->inv2me = (float)s->inv2me; f->twome = (float)s->twome;
	f->ia = (float)(1.0 / (s->a * inv)); f->ib = (float)(1.0 / (s->b * inv));
	f->ellipse = s->ellipse;
}

static void shape3f(mkKShape3f *f, const mkKShape3 *s, double inv)
{
	f->a = (float)(s->a * inv); f->b = (float)(s->b * inv); f->c = (float)(s->c * inv);
	f->e1 = (float)s->e1; f->e2 = (float)s->e2;
	f->q1 = (float)s->q1; f->q1m1 = (float)s->q1m1; f->k1 = (float)s->k1;
	f->q2 = (float)s->q2; f->q2m1 = (float)s->q2m1; f->k2 = (float)s->k2; f->invq2 = (float)s->invq2;
	f->inv2me1 = (float)s->inv2me1; f->inv2me2 = (float)s->inv2me2;
	f->twome1 = (float)s->twome1; f->twome2 = (float)s->twome2;
	f->ia = (float)(1.0 / (s->a * inv)); f->ib = (float)(1.0 / (s->b * inv)); f->ic = (float)(1.0 / (s->c * inv));
	f->ellipse = s->ellipse;
}

/* dst[i] = src[i] * k rounded to float, for n entries; returns the largest
 * |dst[i]|. */
static double to_f32(float *dst, const double *src, int n, double k)
{
	double mx = 0.0;
	for (int i = 0; i < n; ++i) {
		dst[i] = (float)(src[i] * k);
		if (fabs((double)dst[i]) > mx || dst[i] != dst[i]) mx = fabs((double)dst[i]);
	}
	return mx;
}

static double max_abs(const double *v, int n)
{
	double mx = 0.0;
	for (int i = 0; i < n; ++i) mx = fmax(mx, fabs(v[i]));
	return mx;
}

/* A float map scaled as above is usable when its largest entry is a normal
 * float well away from both ends of the range. */
static int map_ok(double mx) { return mx >= 1e-30 && mx <= 1e30; }

int mkKPlan2f_From(mkKPlan2f *f, const mkKPlan2 *p)
{
	double amax = fmax(fmax(p->s1.a, p->s1.b), fmax(p->s2.a, p->s2.b));
	double amin = fmin(fmin(p->s1.a, p->s1.b), fmin(p->s2.a, p->s2.b));
	shape2f(&f->s1, &p->s1, 1.0 / amax);
	shape2f(&f->s2, &p->s2, 1.0 / amax);
	double m1 = to_f32(&f->M1[0][0], &p->M1[0][0], 4, amax);
	double m2 = to_f32(&f->M2[0][0], &p->M2[0][0], 4, amax);
	to_f32(&f->M1T[0][0], &p->M1T[0][0], 4, 1.0 / max_abs(&p->M1T[0][0], 4));
	to_f32(&f->D2[0][0], &p->D2[0][0], 4, 1.0 / max_abs(&p->D2[0][0], 4));
	to_f32(f->t1, p->t1, 2, 1.0);
	to_f32(f->t2p, p->t2p, 2, 1.0);
	f->sigma = (float)p->sigma;
	f->form = p->form; f->param = p->param;
	mkMat2 M1, M2;
	memcpy(M1.m, p->M1, sizeof M1.m);
	memcpy(M2.m, p->M2, sizeof M2.m);
	return amax <= MK_F32_AXIS_RATIO_MAX * amin && mkMat2_Cond(M1) <= MK_F32_COND_MAX
		&& mkMat2_Cond(M2) <= MK_F32_COND_MAX && map_ok(m1) && map_ok(m2);
}

int mkKPlan3f_From(mkKPlan3f *f, const mkKPlan3 *p)
{
	double amax = fmax(fmax(fmax(p->s1.a, p->s1.b), p->s1.c), fmax(fmax(p->s2.a, p->s2.b), p->s2.c));
	double amin = fmin(fmin(fmin(p->s1.a, p->s1.b), p->s1.c), fmin(fmin(p->s2.a, p->s2.b), p->s2.c));
	shape3f(&f->s1, &p->s1, 1.0 / amax);
	shape3f(&f->s2, &p->s2, 1.0 / amax);
	double m1 = to_f32(&f->M1[0][0], &p->M1[0][0], 9, amax);
	double m2 = to_f32(&f->M2[0][0], &p->M2[0][0], 9, amax);
	to_f32(&f->M1T[0][0], &p->M1T[0][0], 9, 1.0 / max_abs(&p->M1T[0][0], 9));
	to_f32(&f->D2[0][0], &p->D2[0][0], 9, 1.0 / max_abs(&p->D2[0][0], 9));
	to_f32(f->t1, p->t1, 3, 1.0);
	to_f32(f->t2p, p->t2p, 3, 1.0);
	f->sigma = (float)p->sigma;
	f->form = p->form; f->param = p->param;
	mkMat3 M1, M2;
	memcpy(M1.m, p->M1, sizeof M1.m);
	memcpy(M2.m, p->M2, sizeof M2.m);
	return amax <= MK_F32_AXIS_RATIO_MAX * amin && mkMat3_Cond(M1) <= MK_F32_COND_MAX
		&& mkMat3_Cond(M2) <= MK_F32_COND_MAX && map_ok(m1) && map_ok(m2);
}

int mkSum2_TierHolds(mkBody2 b1, mkBody2 b2, const mkSumOptions *opt)
{
	if (!options_ok(opt)) return 0;
	if (opt->precision == MK_PRECISION_DOUBLE) return 1;
	if (opt->form == MK_FORM_PAPER) return 0;
	mkKPlan2 p;
	mkKPlan2f f;
	plan2(&p, b1, b2, opt);
	return mkKPlan2f_From(&f, &p);
}

int mkSum3_TierHolds(mkBody3 b1, mkBody3 b2, const mkSumOptions *opt)
{
	if (!options_ok(opt)) return 0;
	if (opt->precision == MK_PRECISION_DOUBLE) return 1;
	if (opt->form == MK_FORM_PAPER) return 0;
	mkKPlan3 p;
	mkKPlan3f f;
	plan3(&p, b1, b2, opt);
	return mkKPlan3f_From(&f, &p);
}

/* ---- the sum's size ---------------------------------------------------------- */

static double mkSum_Frob2(mkMat2 m)
{
	return sqrt(m.m[0][0] * m.m[0][0] + m.m[0][1] * m.m[0][1] + m.m[1][0] * m.m[1][0] + m.m[1][1] * m.m[1][1]);
}

static double mkSum_Frob3(mkMat3 m)
{
	double s = 0;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) s += m.m[i][j] * m.m[i][j];
	return sqrt(s);
}

double mkSum2_Size(mkBody2 b1, mkBody2 b2, mkSet set)
{
	double s = hypot(b1.t.x, b1.t.y) + mkSum_Frob2(b1.M) * hypot(b1.shape.a, b1.shape.b)
		+ mkSum_Frob2(b2.M) * hypot(b2.shape.a, b2.shape.b);
	if (set == MK_SET_PLUS) s += hypot(b2.t.x, b2.t.y);
	return s;
}

double mkSum3_Size(mkBody3 b1, mkBody3 b2, mkSet set)
{
	double s = mkVec3_Length(b1.t) + mkSum_Frob3(b1.M) * mkVec3_Length(mkVec3_Make(b1.shape.a, b1.shape.b, b1.shape.c))
		+ mkSum_Frob3(b2.M) * mkVec3_Length(mkVec3_Make(b2.shape.a, b2.shape.b, b2.shape.c));
	if (set == MK_SET_PLUS) s += mkVec3_Length(b2.t);
	return s;
}

/* ---- the published gradient formula (reference only) -------------------------- */

/* Theorem 2 with Phi, eq. mink_sum_transform_2, as printed: B1's point and
 * gradient from its parameter, m2' = M2^T M1^-T m1, m2 = -+Phi(m2')/|m2'| m2',
 * x2 = f~~2(m2) by the printed formula. */
static void paper2(mkBody2 b1, mkBody2 b2, mkSet set, double ux, double uy, double *x, double *k)
{
	mkVec2 u = {ux, uy};
	mkVec2 x1 = mkShape2_Point(b1.shape, u);
	mkVec2 m1 = mkShape2_PointGradient(b1.shape, u);
	mkVec2 mp = mkMat2_MulTVec(b2.M, mkMat2_MulTVec(mkMat2_Inverse(b1.M), m1));
	double sg = set == MK_SET_PLUS ? 1.0 : -1.0;
	double sc = sg * mkShape2_Phi(b2.shape, mp) / hypot(mp.x, mp.y);
	mkVec2 m2 = {sc * mp.x, sc * mp.y};
	mkVec2 x2 = mkShape2_FromGradientPaper(b2.shape, m2);
	mkVec2 p1 = mkMat2_MulVec(b1.M, x1), p2 = mkMat2_MulVec(b2.M, x2);
	k[0] = b1.t.x + p1.x; k[1] = b1.t.y + p1.y;
	x[0] = k[0] + sg * p2.x + (set == MK_SET_PLUS ? b2.t.x : 0.0);
	x[1] = k[1] + sg * p2.y + (set == MK_SET_PLUS ? b2.t.y : 0.0);
}

static void paper3(mkBody3 b1, mkBody3 b2, mkSet set, double ux, double uy, double uz, double *x, double *k)
{
	mkVec3 u = {ux, uy, uz};
	mkVec3 x1 = mkShape3_Point(b1.shape, u);
	mkVec3 m1 = mkShape3_PointGradient(b1.shape, u);
	mkVec3 mp = mkMat3_MulTVec(b2.M, mkMat3_MulTVec(mkMat3_Inverse(b1.M), m1));
	double sg = set == MK_SET_PLUS ? 1.0 : -1.0;
	double sc = sg * mkShape3_Phi(b2.shape, mp) / sqrt(mp.x * mp.x + mp.y * mp.y + mp.z * mp.z);
	mkVec3 m2 = {sc * mp.x, sc * mp.y, sc * mp.z};
	mkVec3 x2 = mkShape3_FromGradientPaper(b2.shape, m2);
	mkVec3 p1 = mkMat3_MulVec(b1.M, x1), p2 = mkMat3_MulVec(b2.M, x2);
	double pl = set == MK_SET_PLUS ? 1.0 : 0.0;
	k[0] = b1.t.x + p1.x; k[1] = b1.t.y + p1.y; k[2] = b1.t.z + p1.z;
	x[0] = k[0] + sg * p2.x + pl * b2.t.x;
	x[1] = k[1] + sg * p2.y + pl * b2.t.y;
	x[2] = k[2] + sg * p2.z + pl * b2.t.z;
}

/* ---- batches ---------------------------------------------------------------------- */

/* The checks every batch entry makes (double or float arrays): arguments,
 * bodies (asserted), and the kernel this CPU runs, into *impl. */
static mkResult batch_start2(mkBody2 b1, mkBody2 b2, const mkSumOptions *opt, int n, const void *ux,
	const void *uy, const void *x, const void *y, const void *kx, const void *ky, mkImpl *impl)
{
	if (n < 0 || !options_ok(opt) || (n > 0 && (!ux || !uy || !x || !y)) || (!kx != !ky))
		return MK_ERR_ARGUMENT;
	assert(mkBody2_IsValid(b1, "body1", NULL, 0) && mkBody2_IsValid(b2, "body2", NULL, 0));
	(void)b1; (void)b2;
	*impl = mkImpl_Resolve(opt->impl);
	return mkImpl_Available(*impl) ? MK_OK : MK_ERR_UNSUPPORTED;
}

static mkResult batch_start3(mkBody3 b1, mkBody3 b2, const mkSumOptions *opt, int n, const void *ux,
	const void *uy, const void *uz, const void *x, const void *y, const void *z, const void *kx,
	const void *ky, const void *kz, mkImpl *impl)
{
	if (n < 0 || !options_ok(opt) || (n > 0 && (!ux || !uy || !uz || !x || !y || !z))
		|| (!kx != !ky) || (!kx != !kz))
		return MK_ERR_ARGUMENT;
	assert(mkBody3_IsValid(b1, "body1", NULL, 0) && mkBody3_IsValid(b2, "body2", NULL, 0));
	(void)b1; (void)b2;
	*impl = mkImpl_Resolve(opt->impl);
	return mkImpl_Available(*impl) ? MK_OK : MK_ERR_UNSUPPORTED;
}

mkResult mkSum2_Batch(mkBody2 b1, mkBody2 b2, const mkSumOptions *opt,
	const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky)
{
	mkImpl impl;
	mkResult r0 = batch_start2(b1, b2, opt, n, ux, uy, x, y, kx, ky, &impl);
	if (r0 != MK_OK) return r0;
	if (opt->form == MK_FORM_PAPER) {
		if (opt->param != MK_PARAM_SURFACE || (opt->impl != MK_IMPL_AUTO && opt->impl != MK_IMPL_SCALAR)
			|| opt->precision != MK_PRECISION_DOUBLE)
			return MK_ERR_UNSUPPORTED;
		for (int i = 0; i < n; ++i) {
			double p[2], k[2];
			paper2(b1, b2, opt->set, ux[i], uy[i], p, k);
			x[i] = p[0]; y[i] = p[1];
			if (kx) { kx[i] = k[0]; ky[i] = k[1]; }
		}
		return MK_OK;
	}
	mkKPlan2 p;
	plan2(&p, b1, b2, opt);
	mkKPlan2f pf;
	if (opt->precision == MK_PRECISION_F32 && mkKPlan2f_From(&pf, &p)) {
		MK_DISPATCH(impl, mkK2_Run_f32, &pf, ux, uy, n, x, y, kx, ky);
		return MK_OK;
	}
	MK_DISPATCH(impl, mkK2_Run, &p, ux, uy, n, x, y, kx, ky);
	return MK_OK;
}

mkResult mkSum3_Batch(mkBody3 b1, mkBody3 b2, const mkSumOptions *opt,
	const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz)
{
	mkImpl impl;
	mkResult r0 = batch_start3(b1, b2, opt, n, ux, uy, uz, x, y, z, kx, ky, kz, &impl);
	if (r0 != MK_OK) return r0;
	if (opt->form == MK_FORM_PAPER) {
		if (opt->param != MK_PARAM_SURFACE || (opt->impl != MK_IMPL_AUTO && opt->impl != MK_IMPL_SCALAR)
			|| opt->precision != MK_PRECISION_DOUBLE)
			return MK_ERR_UNSUPPORTED;
		for (int i = 0; i < n; ++i) {
			double p[3], k[3];
			paper3(b1, b2, opt->set, ux[i], uy[i], uz[i], p, k);
			x[i] = p[0]; y[i] = p[1]; z[i] = p[2];
			if (kx) { kx[i] = k[0]; ky[i] = k[1]; kz[i] = k[2]; }
		}
		return MK_OK;
	}
	mkKPlan3 p;
	plan3(&p, b1, b2, opt);
	mkKPlan3f pf;
	if (opt->precision == MK_PRECISION_F32 && mkKPlan3f_From(&pf, &p)) {
		MK_DISPATCH(impl, mkK3_Run_f32, &pf, ux, uy, uz, n, x, y, z, kx, ky, kz);
		return MK_OK;
	}
	MK_DISPATCH(impl, mkK3_Run, &p, ux, uy, uz, n, x, y, z, kx, ky, kz);
	return MK_OK;
}

/* ---- float arrays --------------------------------------------------------------- */

#define MK_F32IO_CHUNK 256 /* points widened to double at a time (fallback path) */

mkResult mkSum2f_Batch(mkBody2 b1, mkBody2 b2, const mkSumOptions *opt,
	const float *ux, const float *uy, int n,
	float *x, float *y, float *kx, float *ky)
{
	mkImpl impl;
	mkResult r0 = batch_start2(b1, b2, opt, n, ux, uy, x, y, kx, ky, &impl);
	if (r0 != MK_OK) return r0;
	if (opt->precision == MK_PRECISION_F32 && opt->form != MK_FORM_PAPER) {
		mkKPlan2 p;
		mkKPlan2f pf;
		plan2(&p, b1, b2, opt);
		if (mkKPlan2f_From(&pf, &p)) {
			MK_DISPATCH(impl, mkK2_Run_f32io, &pf, ux, uy, n, x, y, kx, ky);
			return MK_OK;
		}
	}
	double u[2][MK_F32IO_CHUNK], o[4][MK_F32IO_CHUNK];
	for (int i = 0; i < n; i += MK_F32IO_CHUNK) {
		int m = n - i < MK_F32IO_CHUNK ? n - i : MK_F32IO_CHUNK;
		for (int j = 0; j < m; ++j) { u[0][j] = ux[i + j]; u[1][j] = uy[i + j]; }
		mkResult r = mkSum2_Batch(b1, b2, opt, u[0], u[1], m, o[0], o[1], kx ? o[2] : NULL, kx ? o[3] : NULL);
		if (r != MK_OK) return r;
		for (int j = 0; j < m; ++j) {
			x[i + j] = (float)o[0][j]; y[i + j] = (float)o[1][j];
			if (kx) { kx[i + j] = (float)o[2][j]; ky[i + j] = (float)o[3][j]; }
		}
	}
	return MK_OK;
}

mkResult mkSum3f_Batch(mkBody3 b1, mkBody3 b2, const mkSumOptions *opt,
	const float *ux, const float *uy, const float *uz, int n,
	float *x, float *y, float *z, float *kx, float *ky, float *kz)
{
	mkImpl impl;
	mkResult r0 = batch_start3(b1, b2, opt, n, ux, uy, uz, x, y, z, kx, ky, kz, &impl);
	if (r0 != MK_OK) return r0;
	if (opt->precision == MK_PRECISION_F32 && opt->form != MK_FORM_PAPER) {
		mkKPlan3 p;
		mkKPlan3f pf;
		plan3(&p, b1, b2, opt);
		if (mkKPlan3f_From(&pf, &p)) {
			MK_DISPATCH(impl, mkK3_Run_f32io, &pf, ux, uy, uz, n, x, y, z, kx, ky, kz);
			return MK_OK;
		}
	}
	double u[3][MK_F32IO_CHUNK], o[6][MK_F32IO_CHUNK];
	for (int i = 0; i < n; i += MK_F32IO_CHUNK) {
		int m = n - i < MK_F32IO_CHUNK ? n - i : MK_F32IO_CHUNK;
		for (int j = 0; j < m; ++j) { u[0][j] = ux[i + j]; u[1][j] = uy[i + j]; u[2][j] = uz[i + j]; }
		mkResult r = mkSum3_Batch(b1, b2, opt, u[0], u[1], u[2], m, o[0], o[1], o[2],
			kx ? o[3] : NULL, kx ? o[4] : NULL, kx ? o[5] : NULL);
		if (r != MK_OK) return r;
		for (int j = 0; j < m; ++j) {
			x[i + j] = (float)o[0][j]; y[i + j] = (float)o[1][j]; z[i + j] = (float)o[2][j];
			if (kx) { kx[i + j] = (float)o[3][j]; ky[i + j] = (float)o[4][j]; kz[i + j] = (float)o[5][j]; }
		}
	}
	return MK_OK;
}

mkVec2 mkSum2_Point(mkBody2 b1, mkBody2 b2, mkSet set, mkForm form, mkParam param, mkVec2 u, mkVec2 *kiss)
{
	mkSumOptions o = {set, form, param, MK_IMPL_SCALAR, MK_PRECISION_DOUBLE};
	mkVec2 r = {NAN, NAN}, k = {NAN, NAN};
	mkSum2_Batch(b1, b2, &o, &u.x, &u.y, 1, &r.x, &r.y, &k.x, &k.y);
	if (kiss) *kiss = k;
	return r;
}

mkVec3 mkSum3_Point(mkBody3 b1, mkBody3 b2, mkSet set, mkForm form, mkParam param, mkVec3 u, mkVec3 *kiss)
{
	mkSumOptions o = {set, form, param, MK_IMPL_SCALAR, MK_PRECISION_DOUBLE};
	mkVec3 r = {NAN, NAN, NAN}, k = {NAN, NAN, NAN};
	mkSum3_Batch(b1, b2, &o, &u.x, &u.y, &u.z, 1, &r.x, &r.y, &r.z, &k.x, &k.y, &k.z);
	if (kiss) *kiss = k;
	return r;
}

/* ---- sampling --------------------------------------------------------------------- */

/* cos and sin of an angle of the sampling grids, exact at multiples of pi/2:
 * cos(pi/2) is 6e-17 in double, and a near-box maps that parameter to a point
 * (6e-17)^eps of a semi-axis away from the axis (2% at eps = 0.1). No grid
 * angle other than those multiples comes within 1e-15 of one. */
static void grid_sincos(double t, double *c, double *s)
{
	*c = cos(t);
	*s = sin(t);
	if (fabs(*c) < 1e-15) { *c = 0.0; *s = *s > 0 ? 1.0 : -1.0; }
	if (fabs(*s) < 1e-15) { *s = 0.0; *c = *c > 0 ? 1.0 : -1.0; }
}

mkResult mkSample2_Angles(int n, double *ux, double *uy)
{
	if (n < 1 || !ux || !uy) return MK_ERR_ARGUMENT;
	for (int k = 0; k < n; ++k)
		grid_sincos(-MK_PI + 2.0 * MK_PI * k / n, &ux[k], &uy[k]);
	return MK_OK;
}

mkResult mkSample3_Grid(int n, double *ux, double *uy, double *uz)
{
	if (n < 2 || n > 46340 || !ux || !uy || !uz) return MK_ERR_ARGUMENT;
	for (int i = 0; i < n; ++i) {
		double ce, se;
		grid_sincos(-0.5 * MK_PI + MK_PI * i / (n - 1), &ce, &se);
		for (int j = 0; j < n; ++j) {
			double cw, sw;
			grid_sincos(-MK_PI + 2.0 * MK_PI * j / n, &cw, &sw);
			ux[i * n + j] = ce * cw;
			uy[i * n + j] = ce * sw;
			uz[i * n + j] = se;
		}
	}
	return MK_OK;
}

/* The reference code's map of a grid angle (c, s) = (cos t0, sin t0): the
 * angle t with tan t = sign(tan t0) |tan t0|^(1/eps) in t0's quadrant, as the
 * unit vector proportional to (sp(c, 1/eps), sp(s, 1/eps)). Both components
 * are divided by the larger first, so that the power of the larger is 1 and
 * the vector never underflows to zero (1/eps reaches 1e6). */
static void spaced_map(double c, double s, double inv_eps, double *cu, double *su)
{
	double big = fmax(fabs(c), fabs(s));
	double x = copysign(pow(fabs(c) / big, inv_eps), c), y = copysign(pow(fabs(s) / big, inv_eps), s);
	double len = hypot(x, y);
	*cu = x / len;
	*su = y / len;
}

static int eps_ok(double eps)
{
	return isfinite(eps) && eps >= MK_EPS_MIN && eps <= MK_EPS_MAX;
}

mkResult mkSample2_Spaced(int n, double eps, double *ux, double *uy)
{
	if (n < 1 || !ux || !uy) return MK_ERR_ARGUMENT;
	if (!eps_ok(eps)) return MK_ERR_RANGE;
	for (int k = 0; k < n; ++k) {
		double c, s;
		grid_sincos(-MK_PI + 2.0 * MK_PI * k / n, &c, &s);
		spaced_map(c, s, 1.0 / eps, &ux[k], &uy[k]);
	}
	return MK_OK;
}

mkResult mkSample3_Spaced(int n, double eps1, double eps2, double *ux, double *uy, double *uz)
{
	if (n < 2 || n > 46340 || !ux || !uy || !uz) return MK_ERR_ARGUMENT;
	if (!eps_ok(eps1) || !eps_ok(eps2)) return MK_ERR_RANGE;
	for (int i = 0; i < n; ++i) {
		double ce, se;
		grid_sincos(-0.5 * MK_PI + MK_PI * i / (n - 1), &ce, &se);
		spaced_map(ce, se, 1.0 / eps1, &ce, &se);
		for (int j = 0; j < n; ++j) {
			double cw, sw;
			grid_sincos(-MK_PI + 2.0 * MK_PI * j / n, &cw, &sw);
			spaced_map(cw, sw, 1.0 / eps2, &cw, &sw);
			ux[i * n + j] = ce * cw;
			uy[i * n + j] = ce * sw;
			uz[i * n + j] = se;
		}
	}
	return MK_OK;
}

/* ---- the ellipsoid special forms -------------------------------------------------- */

static double norm2(mkVec2 v) { return hypot(v.x, v.y); }
static double norm3(mkVec3 v) { return sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

mkVec2 mkEllipse2_SumNormal(mkMat2 A1, mkMat2 A2, mkVec2 n)
{
	mkVec2 a1 = mkMat2_MulVec(A1, n), a2 = mkMat2_MulVec(A2, n);
	double s1 = 1.0 / norm2(a1), s2 = 1.0 / norm2(a2);
	mkVec2 b1 = mkMat2_MulVec(A1, a1), b2 = mkMat2_MulVec(A2, a2);
	mkVec2 r = {b1.x * s1 + b2.x * s2, b1.y * s1 + b2.y * s2};
	return r;
}

mkVec2 mkEllipse2_SumGradient(mkMat2 A1, mkMat2 A2, mkVec2 m)
{
	mkVec2 a1 = mkMat2_MulVec(A1, m), a2 = mkMat2_MulVec(A2, m);
	double s2 = 1.0 / norm2(a2);
	mkVec2 b1 = mkMat2_MulVec(A1, a1), b2 = mkMat2_MulVec(A2, a2);
	mkVec2 r = {0.5 * b1.x + b2.x * s2, 0.5 * b1.y + b2.y * s2};
	return r;
}

mkVec3 mkEllipse3_SumNormal(mkMat3 A1, mkMat3 A2, mkVec3 n)
{
	mkVec3 a1 = mkMat3_MulVec(A1, n), a2 = mkMat3_MulVec(A2, n);
	double s1 = 1.0 / norm3(a1), s2 = 1.0 / norm3(a2);
	mkVec3 b1 = mkMat3_MulVec(A1, a1), b2 = mkMat3_MulVec(A2, a2);
	mkVec3 r = {b1.x * s1 + b2.x * s2, b1.y * s1 + b2.y * s2, b1.z * s1 + b2.z * s2};
	return r;
}

mkVec3 mkEllipse3_SumGradient(mkMat3 A1, mkMat3 A2, mkVec3 m)
{
	mkVec3 a1 = mkMat3_MulVec(A1, m), a2 = mkMat3_MulVec(A2, m);
	double s2 = 1.0 / norm3(a2);
	mkVec3 b1 = mkMat3_MulVec(A1, a1), b2 = mkMat3_MulVec(A2, a2);
	mkVec3 r = {0.5 * b1.x + b2.x * s2, 0.5 * b1.y + b2.y * s2, 0.5 * b1.z + b2.z * s2};
	return r;
}

/* ---- one body against many poses of another (kernel.h) ----------------------------- */

static int one_options_ok(const mkSumOptions *o)
{
	return options_ok(o) && o->set == MK_SET_CONTACT && o->param == MK_PARAM_SURFACE
		&& (o->form == MK_FORM_NORMAL || o->form == MK_FORM_GRADIENT) && o->precision == MK_PRECISION_DOUBLE;
}

mkResult mkKOne2_Init(mkKOne2 *w, mkBody2 b1, mkShape2 s2, const mkSumOptions *opt,
	const double *ux, const double *uy, int n, double *buf)
{
	if (!one_options_ok(opt) || n < 0 || (n > 0 && (!ux || !uy || !buf))) return MK_ERR_ARGUMENT;
	mkImpl impl = mkImpl_Resolve(opt->impl);
	if (!mkImpl_Available(impl)) return MK_ERR_UNSUPPORTED;
	mkBody2 b2 = {s2, mkMat2_Identity(), {0.0, 0.0}};
	plan2(&w->p, b1, b2, opt);
	w->W = mkMat2_Transpose(mkMat2_Inverse(b1.M)); /* plan2's factor of D2 */
	w->impl = impl;
	w->n = n;
	for (int d = 0; d < 2; ++d) {
		w->k[d] = buf + (size_t)d * n;
		w->g[d] = buf + (size_t)(2 + d) * n;
	}
	MK_DISPATCH(impl, mkK2_SurfaceRun, &w->p.s1, ux, uy, n, w->k[0], w->k[1], w->g[0], w->g[1]);
	const mkKPlan2 *p = &w->p;
	for (int i = 0; i < n; ++i) { /* block2's k1, k2 */
		double x1 = w->k[0][i], x2 = w->k[1][i];
		w->k[0][i] = p->t1[0] + (p->M1[0][0] * x1 + p->M1[0][1] * x2);
		w->k[1][i] = p->t1[1] + (p->M1[1][0] * x1 + p->M1[1][1] * x2);
	}
	return MK_OK;
}

void mkKOne2_Run(const mkKOne2 *w, const mkMat2 *M2, int m, double *scratch, double *x, double *y)
{
	double D2[MK_KONE_POSES][2][2], A[MK_KONE_POSES][2][2];
	const double sg = w->p.sigma;
	assert(m >= 0 && m <= MK_KONE_POSES);
	for (int o = 0; o < m; ++o) { /* plan2's D2 and M2 */
		mkMat2 D = mkMat2_Mul(mkMat2_Transpose(M2[o]), w->W);
		for (int i = 0; i < 2; ++i)
			for (int j = 0; j < 2; ++j) { D2[o][i][j] = sg * D.m[i][j]; A[o][i][j] = M2[o].m[i][j]; }
	}
	const mkKPlan2 *p = &w->p;
	MK_DISPATCH(w->impl, mkK2_PoseRun, &p->s2, p->form, w->k[0], w->k[1], w->g[0], w->g[1], w->n,
		(const double (*)[2][2])D2, (const double (*)[2][2])A, sg, p->t2p, m, scratch, x, y);
}

mkResult mkKOne3_Init(mkKOne3 *w, mkBody3 b1, mkShape3 s2, const mkSumOptions *opt,
	const double *ux, const double *uy, const double *uz, int n, double *buf)
{
	if (!one_options_ok(opt) || n < 0 || (n > 0 && (!ux || !uy || !uz || !buf))) return MK_ERR_ARGUMENT;
	mkImpl impl = mkImpl_Resolve(opt->impl);
	if (!mkImpl_Available(impl)) return MK_ERR_UNSUPPORTED;
	mkBody3 b2 = {s2, mkMat3_Identity(), {0.0, 0.0, 0.0}};
	plan3(&w->p, b1, b2, opt);
	w->W = mkMat3_Transpose(mkMat3_Inverse(b1.M)); /* plan3's factor of D2 */
	w->impl = impl;
	w->n = n;
	for (int d = 0; d < 3; ++d) {
		w->k[d] = buf + (size_t)d * n;
		w->g[d] = buf + (size_t)(3 + d) * n;
	}
	MK_DISPATCH(impl, mkK3_SurfaceRun, &w->p.s1, ux, uy, uz, n, w->k[0], w->k[1], w->k[2], w->g[0], w->g[1],
		w->g[2]);
	const mkKPlan3 *p = &w->p;
	for (int i = 0; i < n; ++i) { /* block3's k1, k2, k3 */
		double x1 = w->k[0][i], x2 = w->k[1][i], x3 = w->k[2][i];
		for (int d = 0; d < 3; ++d)
			w->k[d][i] = p->t1[d] + (p->M1[d][0] * x1 + p->M1[d][1] * x2 + p->M1[d][2] * x3);
	}
	return MK_OK;
}

void mkKOne3_Run(const mkKOne3 *w, const mkMat3 *M2, int m, double *scratch, double *x, double *y, double *z)
{
	double D2[MK_KONE_POSES][3][3], A[MK_KONE_POSES][3][3];
	const double sg = w->p.sigma;
	assert(m >= 0 && m <= MK_KONE_POSES);
	for (int o = 0; o < m; ++o) { /* plan3's D2 and M2 */
		mkMat3 D = mkMat3_Mul(mkMat3_Transpose(M2[o]), w->W);
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j) { D2[o][i][j] = sg * D.m[i][j]; A[o][i][j] = M2[o].m[i][j]; }
	}
	const mkKPlan3 *p = &w->p;
	const double *const k[3] = {w->k[0], w->k[1], w->k[2]}, *const g[3] = {w->g[0], w->g[1], w->g[2]};
	MK_DISPATCH(w->impl, mkK3_PoseRun, &p->s2, p->form, k, g, w->n,
		(const double (*)[3][3])D2, (const double (*)[3][3])A, sg, p->t2p, m, scratch, x, y, z);
}
