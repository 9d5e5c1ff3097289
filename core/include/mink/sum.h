/* mink/sum.h - closed-form boundaries of B1 (+) B2 and of the contact space
 * B1 (+) (-B2), in batches.
 *
 * Theorem 1 (normal form):   x(n) = f~1(n) - f~2(-n)
 * Theorem 2 (gradient form): x(m1) = f~~1(m1) - f~~2(-Phi(m1)/|m1| m1)
 * with linear maps as in the paper's eqs. mink_sum_transform_1/2:
 *   x = t1 + M1 f~1(M1^T n) - M2 f~2(-M2^T n)                 (contact space)
 *   x = t1 + t2 + M1 f~1(M1^T n) + M2 f~2(M2^T n)             (B1 (+) B2)
 * The contact space is where B2's centre may go so that B2 touches B1; B2's
 * own translation does not enter it.
 *
 * Parameters. Each output point comes from one unit vector u_k (SoA input):
 *  - MK_PARAM_SURFACE (the paper's sampling): u_k parameterises B1's surface,
 *    x1 = t1 + M1 f1(u_k), and the world normal there is n = M1^-T g1(u_k).
 *    Since f~1(n(u)) = f1(u) exactly, B1's point is taken from f1 in both forms;
 *    the form decides how B2's point is found.
 *  - MK_PARAM_NORMAL: u_k is the world normal n itself, and the form decides
 *    how both bodies' points are found.
 * Forms:
 *  - MK_FORM_NORMAL: the support point (dual-norm gradient; Theorem 1).
 *  - MK_FORM_GRADIENT: f~~ through g^-1 (Theorem 2), evaluated stably: the
 *    normalisation of g^-1 plays Phi's role (see mkShape2_FromGradient).
 *  - MK_FORM_PAPER: Theorem 2 with Phi and f~~ exactly as the paper prints
 *    them, in double; MK_PARAM_SURFACE only, scalar only. A reference for
 *    what the published code computes, not for use.
 * Ellipses/ellipsoids (eps == 1) take the paper's ellipsoid formulas
 * (eqs. ellipsoid_mink_sum_thm_1 / ellipsoid_mink_sum_closed_m), which need
 * only a square root.
 *
 * Memory: the caller owns every buffer; nothing is allocated. Outputs must
 * not alias inputs. kx/ky(/kz) receive the kissing point on the boundary of
 * B1 (world frame) and may be NULL. */
#ifndef MINK_SUM_H
#define MINK_SUM_H

#include "body.h"

MK_EXTERN_C_BEGIN

typedef enum mkSet { MK_SET_CONTACT = 0, MK_SET_PLUS = 1 } mkSet;
typedef enum mkForm { MK_FORM_NORMAL = 0, MK_FORM_GRADIENT = 1, MK_FORM_PAPER = 2 } mkForm;
typedef enum mkParam { MK_PARAM_SURFACE = 0, MK_PARAM_NORMAL = 1 } mkParam;
/* Which compiled kernel runs. AUTO picks the widest the CPU supports. The
 * SCALAR kernel is the reference (libm); the vector kernels use SLEEF's
 * 1-ulp exp/log and are tested against it. */
typedef enum mkImpl { MK_IMPL_AUTO = 0, MK_IMPL_SCALAR = 1, MK_IMPL_AVX2 = 2, MK_IMPL_AVX512 = 3 } mkImpl;

/* The arithmetic of the kernels (docs/fast-tiers.md).
 *  - MK_PRECISION_DOUBLE: double throughout, exp/log within 1 ulp: every
 *    point within a few thousand units of roundoff of the sum's size
 *    (mkSum2_Size).
 *  - MK_PRECISION_F32: the same kernels in single precision (16 lanes with
 *    AVX-512, 8 with AVX2; SLEEF's float exp (1 ulp) and log (3.5 ulp), the
 *    C library's expf/logf in the scalar build), about twice the points per second of
 *    double on superellipses and superquadrics. Inputs and outputs stay
 *    double: parameter vectors are normalised in double, then rounded to
 *    float; the body constants are rounded to float once per call; points
 *    are widened on store. Stated accuracy, relative to the sum's size
 *    S (mkSum2_Size): every point within
 *    MK_F32_TOL S of the exact boundary of the sum (measured along the exact
 *    normal), and within MK_F32_TOL S of the exact point of the same
 *    parameter wherever that point is well-conditioned (moves by less than
 *    1e-7 S when its direction turns by float-sized amounts); measured
 *    against 256-bit MPFR over the whole exponent range [MK_EPS_MIN,
 *    MK_EPS_MAX]. The tier holds this inside its domain: the largest
 *    semi-axis of the pair at most MK_F32_AXIS_RATIO_MAX times the smallest,
 *    and each map's condition number (mkMat2_Cond) at most MK_F32_COND_MAX.
 *    Outside it the batch call runs the double kernel instead (same impl),
 *    so it never returns points that miss the stated accuracy;
 *    mkSum2_TierHolds tells which kernel runs. */
typedef enum mkPrecision { MK_PRECISION_DOUBLE = 0, MK_PRECISION_F32 = 1 } mkPrecision;
#define MK_F32_TOL 1e-6
#define MK_F32_AXIS_RATIO_MAX 1e6
#define MK_F32_COND_MAX 1e6

typedef struct mkSumOptions {
	mkSet set;
	mkForm form;
	mkParam param;
	mkImpl impl;
	mkPrecision precision;
} mkSumOptions;

/* Defaults: contact space, gradient form, surface parameters, AUTO, DOUBLE. */
MK_API mkSumOptions mkSumOptions_Default(void);

/* Name of an enum value ("contact", "gradient", "surface", "avx512", ...) and
 * parsing back; parsing returns -1 on an unknown name. */
MK_API const char *mkSet_Name(mkSet v);
MK_API const char *mkForm_Name(mkForm v);
MK_API const char *mkParam_Name(mkParam v);
MK_API const char *mkImpl_Name(mkImpl v);
MK_API const char *mkPrecision_Name(mkPrecision v); /* "double", "f32" */
MK_API int mkSet_Parse(const char *s);
MK_API int mkForm_Parse(const char *s);
MK_API int mkParam_Parse(const char *s);
MK_API int mkImpl_Parse(const char *s);
MK_API int mkPrecision_Parse(const char *s);

/* 1 if this CPU and build can run the kernel. SCALAR and AUTO always can. */
MK_API int mkImpl_Available(mkImpl impl);
/* The kernel AUTO resolves to on this machine. */
MK_API mkImpl mkImpl_Resolve(mkImpl impl);

/* 1 when a batch call with these bodies and options runs the kernel of
 * opt->precision, 0 when it falls back to the double kernel because the
 * pair lies outside that tier's domain (see mkPrecision) or opt is NULL.
 * Always 1 for MK_PRECISION_DOUBLE. */
MK_API int mkSum2_TierHolds(mkBody2 b1, mkBody2 b2, const mkSumOptions *opt);
MK_API int mkSum3_TierHolds(mkBody3 b1, mkBody3 b2, const mkSumOptions *opt);

/* The sum's size S = |t1| (+ |t2| for MK_SET_PLUS) + |M1|_F |a1| + |M2|_F |a2|,
 * |a| the Euclidean norm of a body's semi-axes: a bound on |x| over the set
 * (B1 (+) B2, or B1 (+) (-B2) without B2's translation), and the unit every
 * relative accuracy of the sums and of the error measure (mink/error.h) is
 * quoted in. Positive for valid bodies. */
MK_API double mkSum2_Size(mkBody2 b1, mkBody2 b2, mkSet set);
MK_API double mkSum3_Size(mkBody3 b1, mkBody3 b2, mkSet set);

/* Batch closed form over n parameter vectors (u may be any nonzero finite
 * vectors; only their directions matter). Fails with MK_ERR_ARGUMENT on n < 0, NULL
 * required pointers or a bad option, MK_ERR_UNSUPPORTED for MK_FORM_PAPER
 * with MK_PARAM_NORMAL, a vector impl or a precision other than double, or
 * an impl this CPU lacks. Bodies
 * must be valid (mkBody2_IsValid); this is asserted, not checked. */
MK_API mkResult mkSum2_Batch(mkBody2 b1, mkBody2 b2, const mkSumOptions *opt,
	const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky);
MK_API mkResult mkSum3_Batch(mkBody3 b1, mkBody3 b2, const mkSumOptions *opt,
	const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz);

/* The same on float arrays, for callers that keep their points in float
 * (drawing, planning margins): with MK_PRECISION_F32, where the tier holds
 * (mkSum2_TierHolds), the kernels read and write the caller's floats, which
 * halves the memory traffic of the double-array call; a parameter vector
 * whose |u|^2 is within 5e-7 of 1 (any float vector rounded from a unit one)
 * is used as given, others are normalised in float. Otherwise (precision
 * double, a pair outside the tier's domain, MK_FORM_PAPER) the inputs are
 * widened to double in blocks, computed by mkSum2_Batch, and its points
 * rounded to float. Same arguments, errors and accuracy (of the float
 * inputs' directions) as mkSum2_Batch. */
MK_API mkResult mkSum2f_Batch(mkBody2 b1, mkBody2 b2, const mkSumOptions *opt,
	const float *ux, const float *uy, int n,
	float *x, float *y, float *kx, float *ky);
MK_API mkResult mkSum3f_Batch(mkBody3 b1, mkBody3 b2, const mkSumOptions *opt,
	const float *ux, const float *uy, const float *uz, int n,
	float *x, float *y, float *z, float *kx, float *ky, float *kz);

/* One point, scalar kernel; *kiss may be NULL. */
MK_API mkVec2 mkSum2_Point(mkBody2 b1, mkBody2 b2, mkSet set, mkForm form, mkParam param, mkVec2 u, mkVec2 *kiss);
MK_API mkVec3 mkSum3_Point(mkBody3 b1, mkBody3 b2, mkSet set, mkForm form, mkParam param, mkVec3 u, mkVec3 *kiss);

/* ---- parameter sampling (the paper's, Sec. 6.1) -------------------------
 * 2D: n angles theta_k = -pi + 2 pi k / n, u_k = (cos, sin): n >= 1.
 * 3D: an n x n grid, eta_i = -pi/2 + pi i/(n-1) (poles included),
 *     omega_j = -pi + 2 pi j / n, u = (cos eta cos omega, cos eta sin omega,
 *     sin eta), stored at index i*n + j: n >= 2. The outputs hold n*n values.
 * Angles at multiples of pi/2 give exact axis vectors (cos(pi/2) = 0, not
 * the 6e-17 of double arithmetic), so poles and axis points are on the axes.
 * Used as B1's surface angles (MK_PARAM_SURFACE) or the normal's angles
 * (MK_PARAM_NORMAL). Return MK_ERR_ARGUMENT on a bad n. */
MK_API mkResult mkSample2_Angles(int n, double *ux, double *uy);
MK_API mkResult mkSample3_Grid(int n, double *ux, double *uy, double *uz);

/* The reference code's "almost equally spaced" sampling of a superellipse
 * (its SuperEllipse class): each grid angle t0 of mkSample2_Angles(n) is
 * mapped to t = atan(sign(tan t0) |tan t0|^(1/eps)) in t0's quadrant, and
 * u_k = (cos t, sin t) is used as B1's surface parameter (MK_PARAM_SURFACE).
 * Then f(u_k) is the point (a cos t0, b sin t0) pushed radially onto the
 * superellipse, so the samples follow the ellipse's even spacing instead of
 * bunching at the axes as eps -> 0. eps is body 1's exponent; the axes stay
 * exact. 3D: the grid of mkSample3_Grid(n) with the same map applied to eta
 * (exponent 1/eps1) and to omega (exponent 1/eps2). The reference code's
 * SuperQuadrics class does not do this (it samples eta and omega evenly);
 * the 3D map is this library's extension of the 2D one. Return
 * MK_ERR_ARGUMENT on a bad n or NULL pointer, MK_ERR_RANGE when an exponent
 * is not a finite number in [MK_EPS_MIN, MK_EPS_MAX]. */
MK_API mkResult mkSample2_Spaced(int n, double eps, double *ux, double *uy);
MK_API mkResult mkSample3_Spaced(int n, double eps1, double eps2, double *ux, double *uy, double *uz);

/* ---- the ellipsoid special forms, for any symmetric positive-definite
 * A1, A2 (bodies A_i u, |u| = 1) --------------------------------------------
 * Theorem 1 (eq. ellipsoid_mink_sum_thm_1): x(n) = A1^2 n/|A1 n| + A2^2 n/|A2 n|
 * Theorem 2 (eq. ellipsoid_mink_sum_closed_m): x(m) = A1^2 m/2 + A2^2 m/|A2 m|,
 * with m = 2 A1^-1 u a gradient of B1. */
MK_API mkVec2 mkEllipse2_SumNormal(mkMat2 A1, mkMat2 A2, mkVec2 n);
MK_API mkVec2 mkEllipse2_SumGradient(mkMat2 A1, mkMat2 A2, mkVec2 m);
MK_API mkVec3 mkEllipse3_SumNormal(mkMat3 A1, mkMat3 A2, mkVec3 n);
MK_API mkVec3 mkEllipse3_SumGradient(mkMat3 A1, mkMat3 A2, mkVec3 m);

MK_EXTERN_C_END

#endif
