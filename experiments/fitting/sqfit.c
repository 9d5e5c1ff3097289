/* sqfit.c - superquadric fitting by Levenberg-Marquardt (cminpack). */
#include "sqfit.h"
#include "jacobi.h"

#include <math.h>
#include <stdlib.h>

#include <cminpack.h>

/* ||(u, v)||_p for u, v >= 0 and p >= 1, scaled by the larger entry so that
 * neither overflow nor underflow can occur whatever p is. */
static double normP(double u, double v, double p)
{
	double big = u > v ? u : v;
	if (big == 0.0) {
		return 0.0;
	}
	double small = u > v ? v : u;
	return big * pow(1.0 + pow(small / big, p), 1.0 / p);
}

double mkSq_Gauge(mkShape3 s, mkVec3 p)
{
	double g = normP(fabs(p.x) / s.a, fabs(p.y) / s.b, 2.0 / s.eps2);
	return normP(g, fabs(p.z) / s.c, 2.0 / s.eps1);
}

mkMat3 mkSq_QuatToMat(const double q[4])
{
	double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
	double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
	mkMat3 r;
	r.m[0][0] = 1.0 - 2.0 * (y * y + z * z);
	r.m[0][1] = 2.0 * (x * y - w * z);
	r.m[0][2] = 2.0 * (x * z + w * y);
	r.m[1][0] = 2.0 * (x * y + w * z);
	r.m[1][1] = 1.0 - 2.0 * (x * x + z * z);
	r.m[1][2] = 2.0 * (y * z - w * x);
	r.m[2][0] = 2.0 * (x * z - w * y);
	r.m[2][1] = 2.0 * (y * z + w * x);
	r.m[2][2] = 1.0 - 2.0 * (x * x + y * y);
	return r;
}

void mkSq_MatToQuat(mkMat3 R, double q[4])
{
	/* Shepperd: start from the largest of 4w^2, 4x^2, 4y^2, 4z^2 so that the
	 * square root is taken of a number at least 1. */
	double tr = R.m[0][0] + R.m[1][1] + R.m[2][2];
	double w, x, y, z;
	if (tr >= R.m[0][0] && tr >= R.m[1][1] && tr >= R.m[2][2]) {
		double s = 2.0 * sqrt(1.0 + tr); /* 4w */
		w = 0.25 * s;
		x = (R.m[2][1] - R.m[1][2]) / s;
		y = (R.m[0][2] - R.m[2][0]) / s;
		z = (R.m[1][0] - R.m[0][1]) / s;
	} else if (R.m[0][0] >= R.m[1][1] && R.m[0][0] >= R.m[2][2]) {
		double s = 2.0 * sqrt(1.0 + R.m[0][0] - R.m[1][1] - R.m[2][2]); /* 4x */
		w = (R.m[2][1] - R.m[1][2]) / s;
		x = 0.25 * s;
		y = (R.m[0][1] + R.m[1][0]) / s;
		z = (R.m[0][2] + R.m[2][0]) / s;
	} else if (R.m[1][1] >= R.m[2][2]) {
		double s = 2.0 * sqrt(1.0 + R.m[1][1] - R.m[0][0] - R.m[2][2]); /* 4y */
		w = (R.m[0][2] - R.m[2][0]) / s;
		x = (R.m[0][1] + R.m[1][0]) / s;
		y = 0.25 * s;
		z = (R.m[1][2] + R.m[2][1]) / s;
	} else {
		double s = 2.0 * sqrt(1.0 + R.m[2][2] - R.m[0][0] - R.m[1][1]); /* 4z */
		w = (R.m[1][0] - R.m[0][1]) / s;
		x = (R.m[0][2] + R.m[2][0]) / s;
		y = (R.m[1][2] + R.m[2][1]) / s;
		z = 0.25 * s;
	}
	double sign = w < 0.0 ? -1.0 : 1.0;
	double n = sqrt(w * w + x * x + y * y + z * z);
	q[0] = sign * w / n;
	q[1] = sign * x / n;
	q[2] = sign * y / n;
	q[3] = sign * z / n;
}

mkResult mkSqFit_Start(const double *x, const double *y, const double *z, int m, mkSqFit *start)
{
	if (x == NULL || y == NULL || z == NULL || start == NULL || m < 1) {
		return MK_ERR_ARGUMENT;
	}
	double cx = 0.0, cy = 0.0, cz = 0.0;
	for (int k = 0; k < m; ++k) {
		if (!isfinite(x[k]) || !isfinite(y[k]) || !isfinite(z[k])) {
			return MK_ERR_ARGUMENT;
		}
		cx += x[k];
		cy += y[k];
		cz += z[k];
	}
	cx /= m;
	cy /= m;
	cz /= m;

	mkMat3 S = { { { 0.0 } } };
	for (int k = 0; k < m; ++k) {
		double d[3] = { x[k] - cx, y[k] - cy, z[k] - cz };
		for (int i = 0; i < 3; ++i) {
			for (int j = i; j < 3; ++j) {
				S.m[i][j] += d[i] * d[j];
			}
		}
	}
	double w[3];
	mkMat3 V;
	if (mkSym3_Eigen(S, w, &V) < 0) {
		return MK_ERR_RANGE;
	}
	if (!(w[0] > 0.0)) {
		return MK_ERR_RANGE;
	}

	mkSqFit s = { 0 };
	/* The published start: semi-axes sqrt(eigenvalue) / 20. */
	s.shape.a = sqrt(w[0]) / 20.0;
	s.shape.b = sqrt(w[1]) / 20.0;
	s.shape.c = sqrt(w[2]) / 20.0;
	s.shape.eps1 = 1.0;
	s.shape.eps2 = 1.0;
	s.R = V;
	mkSq_MatToQuat(V, s.q);
	s.t.x = cx;
	s.t.y = cy;
	s.t.z = cz;
	s.cost = NAN;
	*start = s;
	return MK_OK;
}

/* ---- the change of variables --------------------------------------------- */

static double epsFromVar(double p)
{
	double e = MK_SQFIT_EPS_LO + (MK_SQFIT_EPS_HI - MK_SQFIT_EPS_LO) * 0.5 * (1.0 + sin(p));
	/* rounding may step one ulp past a bound */
	return fmin(fmax(e, MK_SQFIT_EPS_LO), MK_SQFIT_EPS_HI);
}

static double varFromEps(double e)
{
	double s = 2.0 * (e - MK_SQFIT_EPS_LO) / (MK_SQFIT_EPS_HI - MK_SQFIT_EPS_LO) - 1.0;
	return asin(fmin(fmax(s, -1.0), 1.0));
}

typedef struct FitModel {
	mkShape3 shape;
	double q[4];
	mkMat3 R;
	mkVec3 t;
} FitModel;

/* Returns 0 when the quaternion part is zero (no rotation defined). */
static int modelFromVars(const double *p, FitModel *fm)
{
	fm->shape.a = exp(p[0]);
	fm->shape.b = exp(p[1]);
	fm->shape.c = exp(p[2]);
	fm->shape.eps1 = epsFromVar(p[3]);
	fm->shape.eps2 = epsFromVar(p[4]);
	fm->t.x = p[5];
	fm->t.y = p[6];
	fm->t.z = p[7];
	double qn = 0.0;
	for (int i = 0; i < 4; ++i) {
		fm->q[i] = sin(p[8 + i]);
		qn += fm->q[i] * fm->q[i];
	}
	if (!(qn > 0.0) || !isfinite(qn)) {
		return 0;
	}
	qn = sqrt(qn);
	for (int i = 0; i < 4; ++i) {
		fm->q[i] /= qn;
	}
	fm->R = mkSq_QuatToMat(fm->q);
	return 1;
}

typedef struct FitData {
	const double *x, *y, *z;
	int jacobianCalls; /* residual calls made for the finite-difference Jacobian */
} FitData;

static mkVec3 toBody(mkMat3 R, mkVec3 t, double x, double y, double z)
{
	double dx = x - t.x, dy = y - t.y, dz = z - t.z;
	mkVec3 b;
	b.x = R.m[0][0] * dx + R.m[1][0] * dy + R.m[2][0] * dz;
	b.y = R.m[0][1] * dx + R.m[1][1] * dy + R.m[2][1] * dz;
	b.z = R.m[0][2] * dx + R.m[1][2] * dy + R.m[2][2] * dz;
	return b;
}

static int residuals(void *ctx, int m, int n, const double *p, double *fvec, int iflag)
{
	(void)n;
	FitData *d = ctx;
	if (iflag == 2) {
		d->jacobianCalls += 1;
	}
	FitModel fm;
	if (!modelFromVars(p, &fm)) {
		return -1;
	}
	double w = sqrt(fm.shape.a * fm.shape.b * fm.shape.c);
	for (int k = 0; k < m; ++k) {
		double g = mkSq_Gauge(fm.shape, toBody(fm.R, fm.t, d->x[k], d->y[k], d->z[k]));
		/* Psi^eps1 - 1 = N^2 - 1 = (N - 1)(N + 1), the product keeping
		 * the digits of points close to the surface */
		fvec[k] = w * (g - 1.0) * (g + 1.0);
	}
	return 0;
}

mkResult mkSqFit_Run(const double *x, const double *y, const double *z, int m,
	const mkSqFit *start, mkSqFit *out)
{
	enum { N = MK_SQFIT_NVAR };
	if (x == NULL || y == NULL || z == NULL || start == NULL || out == NULL || m < N) {
		return MK_ERR_ARGUMENT;
	}
	mkShape3 s0 = start->shape;
	if (!(s0.a > 0.0 && s0.b > 0.0 && s0.c > 0.0)
		|| !(s0.eps1 >= MK_SQFIT_EPS_LO && s0.eps1 <= MK_SQFIT_EPS_HI)
		|| !(s0.eps2 >= MK_SQFIT_EPS_LO && s0.eps2 <= MK_SQFIT_EPS_HI)) {
		return MK_ERR_RANGE;
	}

	double p[N];
	p[0] = log(s0.a);
	p[1] = log(s0.b);
	p[2] = log(s0.c);
	p[3] = varFromEps(s0.eps1);
	p[4] = varFromEps(s0.eps2);
	p[5] = start->t.x;
	p[6] = start->t.y;
	p[7] = start->t.z;
	double q0[4];
	mkSq_MatToQuat(start->R, q0);
	for (int i = 0; i < 4; ++i) {
		p[8 + i] = asin(q0[i]); /* |q_i| <= 1 for a unit quaternion */
	}

	/* Work arrays: fvec, fjac (m x N), qtf, wa1..3 (N), wa4 (m), diag, ipvt. */
	double *work = malloc(sizeof(double) * ((size_t)m * (N + 2) + 5 * N));
	int *ipvt = malloc(sizeof(int) * N);
	if (work == NULL || ipvt == NULL) {
		free(work);
		free(ipvt);
		return MK_ERR_MEMORY;
	}
	double *fvec = work;
	double *fjac = fvec + m;
	double *wa4 = fjac + (size_t)m * N;
	double *qtf = wa4 + m;
	double *wa1 = qtf + N;
	double *wa2 = wa1 + N;
	double *wa3 = wa2 + N;
	double *diag = wa3 + N;

	/* Tolerances: minpack's recommended sqrt(machine epsilon) on both the
	 * relative reduction of the cost and the relative step; the gradient
	 * test off; at most 200 (N + 1) evaluations, as lmdif1 allows; mode 1
	 * (automatic variable scaling) and step bound factor 100. */
	const double tol = 1.4901161193847656e-08;
	FitData data = { x, y, z, 0 };
	int nfev = 0;
	int info = lmdif(residuals, &data, m, N, p, fvec, tol, tol, 0.0, 200 * (N + 1), 0.0,
		diag, 1, 100.0, 0, &nfev, fjac, m, ipvt, qtf, wa1, wa2, wa3, wa4);

	FitModel fm;
	mkSqFit r = { 0 };
	if (modelFromVars(p, &fm)) {
		r.shape = fm.shape;
		r.R = fm.R;
		mkSq_MatToQuat(fm.R, r.q);
		r.t = fm.t;
		/* the cost at the final point, evaluated afresh */
		residuals(&(FitData){ x, y, z, 0 }, m, N, p, fvec, 1);
		double cost = 0.0;
		for (int k = 0; k < m; ++k) {
			cost += fvec[k] * fvec[k];
		}
		r.cost = cost;
	} else {
		r.shape = (mkShape3){ NAN, NAN, NAN, NAN, NAN };
		r.cost = NAN;
		info = -1;
	}
	r.iterations = data.jacobianCalls / N;
	r.nfev = nfev;
	r.info = info;
	*out = r;
	free(work);
	free(ipvt);
	return MK_OK;
}

double mkSqFit_ImplicitError(const mkSqFit *fit, const double *x, const double *y, const double *z, int m)
{
	double sum = 0.0;
	for (int k = 0; k < m; ++k) {
		mkVec3 b = toBody(fit->R, fit->t, x[k], y[k], z[k]);
		sum += fabs(mkShape3_Implicit(fit->shape, b) - 1.0);
	}
	return m > 0 ? sum / m : NAN;
}

const char *mkSqFit_StatusName(int info)
{
	switch (info) {
	case 0: return "bad-input";
	case 1: return "ftol";
	case 2: return "xtol";
	case 3: return "ftol+xtol";
	case 4: return "gtol";
	case 5: return "maxfev";
	case 6: return "ftol-small";
	case 7: return "xtol-small";
	case 8: return "gtol-small";
	default: return "stopped";
	}
}
