/* sqfit.h - least-squares fit of a superquadric to a point set (case 1 of
 * the fitting experiment, paper Sec. 6.2).
 *
 * Minimised, over semi-axes a, exponents eps, centre t and rotation R:
 *     sum_k  [ sqrt(abc) (Psi(R^T (x_k - t))^eps1 - 1) ]^2
 * (Vaskevicius & Birk's cost as the paper writes it), by cminpack's
 * Levenberg-Marquardt with a forward-difference Jacobian. Psi^eps1 equals
 * N^2, where N is the superquadric's gauge (a nested norm, homogeneous of
 * degree one), so the residual is evaluated as N^2 - 1 without powers that
 * could overflow.
 *
 * Bounds (the paper's: a >= 0, eps in [0.1, 2], quaternion entries in
 * [-1, 1]) are kept by a smooth change of variables:
 *     a_i   = exp(p_i)                                   (a > 0)
 *     eps_j = lo + (hi - lo) (1 + sin p_j) / 2           (lo = 0.1, hi = 2 - 1e-6)
 *     q_i   = sin(p_i), R = rotation of q / |q|
 * and t is free. The upper exponent bound is the core's largest valid
 * exponent, MK_EPS_MAX, one millionth below 2. */
#ifndef MK_FIT_SQFIT_H
#define MK_FIT_SQFIT_H

#include <mink/body.h>

#define MK_SQFIT_EPS_LO 0.1
#define MK_SQFIT_EPS_HI MK_EPS_MAX
/* Number of optimisation variables: 3 axes, 2 exponents, 3 centre, 4 quaternion. */
#define MK_SQFIT_NVAR 12

typedef struct mkSqFit {
	mkShape3 shape; /* a, b, c, eps1, eps2 */
	double q[4];    /* unit quaternion (w, x, y, z) of R, w >= 0 */
	mkMat3 R;       /* body axes as columns: world = R body + t */
	mkVec3 t;
	double cost;    /* sum of squared residuals at the result */
	int iterations; /* Jacobian evaluations = Levenberg-Marquardt iterations */
	int nfev;       /* residual evaluations, finite differences included */
	int info;       /* minpack's termination code (see mkSqFit_StatusName) */
} mkSqFit;

/* The nested-norm gauge N of the canonical superquadric s at p:
 * N = || ( ||(x/a, y/b)||_{2/eps2}, z/c ) ||_{2/eps1}, so Psi = N^(2/eps1)
 * and the boundary is N = 1. Any finite p; s valid. */
double mkSq_Gauge(mkShape3 s, mkVec3 p);

/* Rotation matrix of the quaternion (w, x, y, z), normalised first, and the
 * inverse map (Shepperd's method) returning w >= 0. Hamilton convention:
 * R rotates body coordinates into world coordinates. The quaternion must be
 * finite and nonzero; R must be a rotation. */
mkMat3 mkSq_QuatToMat(const double q[4]);
void mkSq_MatToQuat(mkMat3 R, double q[4]);

/* The starting guess from principal component analysis: t = centroid, R =
 * eigenvectors of the scatter matrix sum (x - t)(x - t)^T (ascending
 * eigenvalues, det R = +1), a_i = sqrt(lambda_i) / 20, eps = (1, 1), as the
 * published code. Needs m >= 1 finite points; fails with MK_ERR_ARGUMENT
 * otherwise and MK_ERR_RANGE when an eigenvalue is zero (flat point set). */
mkResult mkSqFit_Start(const double *x, const double *y, const double *z, int m, mkSqFit *start);

/* Fit from *start (only its shape, R and t are read). m >= MK_SQFIT_NVAR
 * points are needed (fails with MK_ERR_ARGUMENT otherwise, or on NULL). On
 * MK_OK *out holds the fit, whatever minpack's info says: callers report
 * out->info. MK_ERR_MEMORY when the work arrays cannot be allocated;
 * MK_ERR_RANGE when the start lies outside the bounds. */
mkResult mkSqFit_Run(const double *x, const double *y, const double *z, int m,
	const mkSqFit *start, mkSqFit *out);

/* Mean over the points of |Psi(R^T (x_k - t)) - 1|, the paper's e_implicit,
 * with Psi the core's mkShape3_Implicit. The fit's shape must be valid. */
double mkSqFit_ImplicitError(const mkSqFit *fit, const double *x, const double *y, const double *z, int m);

/* A short name of minpack's info code: "ftol", "xtol", "ftol+xtol", "gtol",
 * "maxfev", "ftol-small", "xtol-small", "gtol-small", "bad-input", "stopped". */
const char *mkSqFit_StatusName(int info);

#endif
