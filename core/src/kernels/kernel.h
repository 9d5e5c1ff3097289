/* kernel.h - internal: the prepared constants of one batch call and the
 * per-ISA batch loops compiled from kernel_body.h. Not a public header. */
#ifndef MINK_KERNEL_H
#define MINK_KERNEL_H

#include "mink/sum.h"

/* Per-shape constants, computed once per call so the loops only multiply. */
typedef struct mkKShape2 {
	double a, b, eps;
	double q, qm1, k;  /* dual exponent q = 2/(2-eps), q-1, 1-1/q */
	double inv2me;     /* 1/(2-eps) */
	double twome;      /* 2-eps */
	double loga, logb;
	int ellipse;
} mkKShape2;

typedef struct mkKShape3 {
	double a, b, c, e1, e2;
	double q1, q1m1, k1, q2, q2m1, k2, invq2;
	double inv2me1, inv2me2, twome1, twome2;
	double loga, logb, logc;
	int ellipse;
} mkKShape3;

typedef struct mkKPlan2 {
	mkKShape2 s1, s2;
	double M1[2][2], M1T[2][2], M2[2][2];
	/* B2's direction from the loop's source vector: sigma M2^T M1^-T (applied
	 * to B1's gradient, surface parameters; eq. mink_sum_transform_2) or
	 * sigma M2^T (applied to the normal, normal parameters). */
	double D2[2][2];
	double t1[2];    /* B1's centre: kissing point offset */
	double t2p[2];   /* t2 for the plus set, 0 for the contact space */
	double sigma;    /* -1 contact space, +1 plus */
	int form;        /* MK_FORM_NORMAL or MK_FORM_GRADIENT */
	int param;       /* mkParam */
} mkKPlan2;

typedef struct mkKPlan3 {
	mkKShape3 s1, s2;
	double M1[3][3], M1T[3][3], M2[3][3];
	double D2[3][3]; /* as in mkKPlan2 */
	double t1[3];
	double t2p[3];
	double sigma;
	int form;
	int param;
} mkKPlan3;

void mkKShape2_Prepare(mkKShape2 *k, mkShape2 s);
void mkKShape3_Prepare(mkKShape3 *k, mkShape3 s);

/* Batch loops: one per compiled ISA. kx.. may be NULL. */
void mkK2_Run_scalar(const mkKPlan2 *p, const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky);
void mkK3_Run_scalar(const mkKPlan3 *p, const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz);
#if defined(MINK_HAVE_X86_KERNELS)
void mkK2_Run_avx2(const mkKPlan2 *p, const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky);
void mkK3_Run_avx2(const mkKPlan3 *p, const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz);
void mkK2_Run_avx512(const mkKPlan2 *p, const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky);
void mkK3_Run_avx512(const mkKPlan3 *p, const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz);
#endif

/* The two halves of a surface-parameter batch (kernel_body.h, double builds
 * only): B1's unit parameter, point f(u) and gradient g(u) in its own frame;
 * B2's f~ (form normal) or f~~ (form gradient) of given directions (x may
 * be d: in place); and B2's half with the sums for m poses (PoseRun). */
#define MK_KHALVES_DECL(isa) \
	void mkK2_SurfaceRun_##isa(const mkKShape2 *s, const double *ux, const double *uy, int n, \
		double *x1, double *x2, double *g1, double *g2); \
	void mkK2_DirRun_##isa(const mkKShape2 *s, int form, const double *d1, const double *d2, int n, \
		double *x1, double *x2); \
	void mkK3_SurfaceRun_##isa(const mkKShape3 *s, const double *ux, const double *uy, const double *uz, int n, \
		double *x1, double *x2, double *x3, double *g1, double *g2, double *g3); \
	void mkK3_DirRun_##isa(const mkKShape3 *s, int form, const double *d1, const double *d2, const double *d3, \
		int n, double *x1, double *x2, double *x3); \
	void mkK2_PoseRun_##isa(const mkKShape2 *s2, int form, const double *k1, const double *k2, const double *g1, \
		const double *g2, int n, const double (*D2)[2][2], const double (*M2)[2][2], double sigma, \
		const double *t2p, int m, double *scratch, double *x, double *y); \
	void mkK3_PoseRun_##isa(const mkKShape3 *s2, int form, const double *const k[3], const double *const g[3], \
		int n, const double (*D2)[3][3], const double (*M2)[3][3], double sigma, const double *t2p, int m, \
		double *scratch, double *x, double *y, double *z);
MK_KHALVES_DECL(scalar)
#if defined(MINK_HAVE_X86_KERNELS)
MK_KHALVES_DECL(avx2)
MK_KHALVES_DECL(avx512)
#endif

/* ---- one body against many poses of another (sum.c) ---------------------
 * mkSum2_Batch/mkSum3_Batch(b1, b2_o, opt, u, n) for m poses b2_o of B2 that
 * differ only in their map (M2_o; the set is the contact space, so B2's
 * centre does not enter), with B1's half of the batch computed once: the
 * points t1 + M1 f(u) and the gradients g(u). mkKOne*_Run gives, bit for bit,
 * the points the m batch calls give (core.test_sum_split): the same kernels
 * per lane, the same products in the same order around them. It saves B1's
 * half per pose and pads one tail per m poses instead of one per pose
 * (Table 2's workload, mkCSpace_Run's paper mode). */
typedef struct mkKOne2 {
	mkKPlan2 p;         /* M2, D2 are set per pose */
	mkMat2 W;           /* M1^-T, the surface parameters' D2 factor */
	mkImpl impl;        /* resolved */
	int n;
	double *k[2], *g[2]; /* n each: B1's points t1 + M1 f(u), gradients g(u) */
} mkKOne2;

typedef struct mkKOne3 {
	mkKPlan3 p;
	mkMat3 W;
	mkImpl impl;
	int n;
	double *k[3], *g[3];
} mkKOne3;

/* opt: contact set, surface parameters, form normal or gradient, double
 * precision, an available kernel (else MK_ERR_ARGUMENT / MK_ERR_UNSUPPORTED).
 * buf holds 2 dim n doubles, owned by the caller and used by the struct. */
mkResult mkKOne2_Init(mkKOne2 *w, mkBody2 b1, mkShape2 s2, const mkSumOptions *opt,
	const double *ux, const double *uy, int n, double *buf);
mkResult mkKOne3_Init(mkKOne3 *w, mkBody3 b1, mkShape3 s2, const mkSumOptions *opt,
	const double *ux, const double *uy, const double *uz, int n, double *buf);
/* The m poses M2[0 .. m) (m <= MK_KONE_POSES): points of pose o at
 * x[o n .. (o+1) n), likewise y (z). scratch holds dim n m doubles. */
#define MK_KONE_POSES 64
void mkKOne2_Run(const mkKOne2 *w, const mkMat2 *M2, int m, double *scratch, double *x, double *y);
void mkKOne3_Run(const mkKOne3 *w, const mkMat3 *M2, int m, double *scratch, double *x, double *y, double *z);

/* ---- the single-precision tier (MK_PRECISION_F32) ----------------------
 * The same kernels (kernel_body.h) over float lanes: the prepared constants
 * below are the double ones, rescaled (sum.c) and rounded to float once per
 * call; parameter vectors are normalised in double and then rounded to
 * float, points are widened back to double on store. */
typedef struct mkKShape2f {
	float a, b, eps, q, qm1, k, inv2me, twome;
	float ia, ib; /* 1/a, 1/b (KDIV_AXIS) */
	int ellipse;
} mkKShape2f;

typedef struct mkKShape3f {
	float a, b, c, e1, e2;
	float q1, q1m1, k1, q2, q2m1, k2, invq2;
	float inv2me1, inv2me2, twome1, twome2;
	float ia, ib, ic; /* 1/a, 1/b, 1/c (KDIV_AXIS) */
	int ellipse;
} mkKShape3f;

typedef struct mkKPlan2f {
	mkKShape2f s1, s2;
	float M1[2][2], M1T[2][2], M2[2][2], D2[2][2], t1[2], t2p[2], sigma;
	int form, param;
} mkKPlan2f;

typedef struct mkKPlan3f {
	mkKShape3f s1, s2;
	float M1[3][3], M1T[3][3], M2[3][3], D2[3][3], t1[3], t2p[3], sigma;
	int form, param;
} mkKPlan3f;

/* Round a double plan to float. Returns 1 when the single-precision tier
 * holds its stated accuracy for this plan (sum.c's domain test), else 0
 * (the caller then runs the double kernel). */
int mkKPlan2f_From(mkKPlan2f *f, const mkKPlan2 *p);
int mkKPlan3f_From(mkKPlan3f *f, const mkKPlan3 *p);

void mkK2_Run_f32_scalar(const mkKPlan2f *p, const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky);
void mkK3_Run_f32_scalar(const mkKPlan3f *p, const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz);
#if defined(MINK_HAVE_X86_KERNELS)
void mkK2_Run_f32_avx2(const mkKPlan2f *p, const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky);
void mkK3_Run_f32_avx2(const mkKPlan3f *p, const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz);
void mkK2_Run_f32_avx512(const mkKPlan2f *p, const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky);
void mkK3_Run_f32_avx512(const mkKPlan3f *p, const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz);
#endif

/* The same kernels on the caller's float arrays (mkSum2f_Batch): inputs
 * loaded as floats and normalised in float where |u|^2 is off 1 by more
 * than MK_F32IO_UNIT_TOL, outputs stored as floats. */
#define MK_F32IO_DECL(isa) \
	void mkK2_Run_f32io_##isa(const mkKPlan2f *p, const float *ux, const float *uy, int n, \
		float *x, float *y, float *kx, float *ky); \
	void mkK3_Run_f32io_##isa(const mkKPlan3f *p, const float *ux, const float *uy, const float *uz, int n, \
		float *x, float *y, float *z, float *kx, float *ky, float *kz);
MK_F32IO_DECL(scalar)
#if defined(MINK_HAVE_X86_KERNELS)
MK_F32IO_DECL(avx2)
MK_F32IO_DECL(avx512)
#endif

/* Scalar single-shape maps of the canonical shapes, from the scalar build of
 * kernel_body.h; body.c exposes them through the public API. */
void mkK2_Surface(const mkKShape2 *s, double u1, double u2, double *x, double *m);
void mkK2_Support(const mkKShape2 *s, double d1, double d2, double *x);
void mkK2_GradInv(const mkKShape2 *s, double m1, double m2, double *x);
void mkK3_Surface(const mkKShape3 *s, double u1, double u2, double u3, double *x, double *m);
void mkK3_Support(const mkKShape3 *s, double d1, double d2, double d3, double *x);
void mkK3_GradInv(const mkKShape3 *s, double m1, double m2, double m3, double *x);
/* Logarithms of the unit parameter u of the point f~~(m): 2D log|u1|,
 * log|u2|; 3D log cos(eta), log|sin(eta)|, log|cos(omega)|, log|sin(omega)|. */
void mkK2_GradInvLogs(const mkKShape2 *s, double m1, double m2, double *l);
void mkK3_GradInvLogs(const mkKShape3 *s, double m1, double m2, double m3, double *l);

#endif
