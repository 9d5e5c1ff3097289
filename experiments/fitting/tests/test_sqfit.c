/* test_sqfit.c - the superquadric fit: its gauge, rotations, PCA start, and
 * the Levenberg-Marquardt fit on points with a known exact answer. */
#include "ensure.h"
#include "sqfit.h"

#include <mink/sum.h>

/* Psi written out from its definition, in long double, as the reference. */
static double psiByHand(mkShape3 s, mkVec3 p)
{
	long double in = powl(fabsl((long double)p.x / s.a), 2.0L / s.eps2)
		+ powl(fabsl((long double)p.y / s.b), 2.0L / s.eps2);
	return (double)(powl(in, (long double)s.eps2 / s.eps1) + powl(fabsl((long double)p.z / s.c), 2.0L / s.eps1));
}

static mkMat3 someRotation(void)
{
	const double q[4] = { 0.3, -0.5, 0.7, 0.2 };
	return mkSq_QuatToMat(q);
}

/* ---- gauge ------------------------------------------------------------ */
static void testGauge(void)
{
	mkShape3 s = { 2.0, 3.0, 4.0, 0.5, 1.5 };
	/* on the axes N is the coordinate over the semi-axis, exactly */
	ENSURE_NEAR(mkSq_Gauge(s, (mkVec3){ 2, 0, 0 }), 1.0, 0.0);
	ENSURE_NEAR(mkSq_Gauge(s, (mkVec3){ 0, -3, 0 }), 1.0, 0.0);
	ENSURE_NEAR(mkSq_Gauge(s, (mkVec3){ 0, 0, 4 }), 1.0, 0.0);
	ENSURE_NEAR(mkSq_Gauge(s, (mkVec3){ 1, 0, 0 }), 0.5, 0.0);
	ENSURE_NEAR(mkSq_Gauge(s, (mkVec3){ 0, 0, 0 }), 0.0, 0.0);
	/* N^(2/eps1) = Psi: a few pow calls, each within an ulp or two,
	 * the 2/eps1 = 4 power multiplying relative error by 4: 1e-14 */
	const mkVec3 pts[3] = { { 0.7, -1.9, 2.2 }, { -5.0, 0.1, -0.3 }, { 1e-3, 2e-3, -1e-3 } };
	for (int i = 0; i < 3; ++i) {
		double n = mkSq_Gauge(s, pts[i]);
		ENSURE_REL(pow(n, 2.0 / s.eps1), psiByHand(s, pts[i]), 1e-14);
		ENSURE_REL(pow(n, 2.0 / s.eps1), mkShape3_Implicit(s, pts[i]), 1e-14);
	}
	/* the ellipsoid's gauge is the Euclidean norm of x / a */
	mkShape3 e = { 2.0, 3.0, 4.0, 1.0, 1.0 };
	ENSURE_REL(mkSq_Gauge(e, (mkVec3){ 1, 1, 1 }), sqrt(0.25 + 1.0 / 9 + 1.0 / 16), 4e-16);
	/* far points with a large power: Psi would overflow, N does not */
	mkShape3 box = { 1.0, 1.0, 1.0, 0.1, 0.1 };
	double far = mkSq_Gauge(box, (mkVec3){ 1e200, 1e200, 0 });
	ENSURE(isfinite(far));
	ENSURE_REL(far, 1e200 * pow(2.0, 0.05), 1e-15); /* ||(1,1)||_20 = 2^(1/20) */
}

/* ---- rotations ------------------------------------------------------- */
static void testRotations(void)
{
	const double qs[4][4] = { { 1, 0, 0, 0 }, { 0.3, -0.5, 0.7, 0.2 }, { 0, 1, 0, 0 }, { -0.1, 0.2, 0.95, -0.3 } };
	for (int i = 0; i < 4; ++i) {
		mkMat3 r = mkSq_QuatToMat(qs[i]);
		/* the same matrix as the core's */
		mkMat3 c = mkMat3_FromQuat(qs[i][0], qs[i][1], qs[i][2], qs[i][3]);
		double q[4];
		mkSq_MatToQuat(r, q);
		double n = sqrt(qs[i][0] * qs[i][0] + qs[i][1] * qs[i][1] + qs[i][2] * qs[i][2] + qs[i][3] * qs[i][3]);
		double sign = qs[i][0] < 0 ? -1.0 : 1.0;
		ENSURE(q[0] >= 0.0);
		for (int k = 0; k < 4; ++k) {
			/* a round trip through 9 products of unit numbers: 1e-15 */
			ENSURE_NEAR(q[k], sign * qs[i][k] / n, 1e-15);
		}
		for (int a = 0; a < 3; ++a) {
			for (int b = 0; b < 3; ++b) {
				ENSURE_NEAR(r.m[a][b], c.m[a][b], 4e-16);
			}
		}
	}
}

/* ---- PCA start: corners of a rotated, shifted box ---------------------- */
static void testPcaStart(void)
{
	mkMat3 R = someRotation();
	const double h[3] = { 2.0, 6.0, 4.0 }; /* half-sizes, not sorted */
	const mkVec3 t = { 1.0, -2.0, 3.0 };
	double x[8], y[8], z[8];
	for (int k = 0; k < 8; ++k) {
		mkVec3 b = { (k & 1 ? 1 : -1) * h[0], (k & 2 ? 1 : -1) * h[1], (k & 4 ? 1 : -1) * h[2] };
		mkVec3 w = mkMat3_MulVec(R, b);
		x[k] = w.x + t.x;
		y[k] = w.y + t.y;
		z[k] = w.z + t.z;
	}
	mkSqFit s;
	ENSURE(mkSqFit_Start(x, y, z, 8, &s) == MK_OK);
	/* scatter = 8 R diag(h^2) R^T: eigenvalues 8 h_i^2 in ascending
	 * order, so a = sqrt(8) h_sorted / 20; tolerances: a few ulps */
	ENSURE_REL(s.shape.a, sqrt(8.0) * 2.0 / 20.0, 1e-14);
	ENSURE_REL(s.shape.b, sqrt(8.0) * 4.0 / 20.0, 1e-14);
	ENSURE_REL(s.shape.c, sqrt(8.0) * 6.0 / 20.0, 1e-14);
	ENSURE(s.shape.eps1 == 1.0 && s.shape.eps2 == 1.0);
	ENSURE_NEAR(s.t.x, 1.0, 1e-14);
	ENSURE_NEAR(s.t.y, -2.0, 1e-14);
	ENSURE_NEAR(s.t.z, 3.0, 1e-14);
	/* the smallest axis is the box's first column, up to sign */
	const int col[3] = { 0, 2, 1 };
	for (int i = 0; i < 3; ++i) {
		double dot = 0.0;
		for (int r = 0; r < 3; ++r) {
			dot += s.R.m[r][i] * R.m[r][col[i]];
		}
		ENSURE_NEAR(fabs(dot), 1.0, 1e-14);
	}
	double flat[4] = { 0, 1, 0, 1 }, zero[4] = { 0, 0, 0, 0 };
	ENSURE(mkSqFit_Start(flat, flat, zero, 4, &s) == MK_ERR_RANGE);
	ENSURE(mkSqFit_Start(x, y, z, 0, &s) == MK_ERR_ARGUMENT);
}

/* ---- the fit recovers an exact superquadric ----------------------------
 * Points on a known, rotated and shifted superquadric: the cost has a
 * zero-residual minimum there, where Levenberg-Marquardt converges
 * quadratically. minpack stops when the relative step is below 1.5e-8,
 * so parameters, and the volume, are good to about that: 1e-6 leaves
 * room. Points on the fitted surface: |Psi - 1| of the same order. */
static void testExactFit(void)
{
	mkShape3 s = { 5.0, 3.0, 2.0, 0.6, 1.3 };
	mkBody3 b = mkBody3_Make(s, someRotation(), (mkVec3){ 1.0, -2.0, 0.5 });
	enum { G = 12, M = G * G };
	double ux[M], uy[M], uz[M], x[M], y[M], z[M];
	ENSURE(mkSample3_Grid(G, ux, uy, uz) == MK_OK);
	for (int k = 0; k < M; ++k) {
		mkVec3 p = mkBody3_Point(b, (mkVec3){ ux[k], uy[k], uz[k] });
		x[k] = p.x;
		y[k] = p.y;
		z[k] = p.z;
	}
	mkSqFit start, fit;
	ENSURE(mkSqFit_Start(x, y, z, M, &start) == MK_OK);
	ENSURE(mkSqFit_Run(x, y, z, M, &start, &fit) == MK_OK);
	printf("exact superquadric: info %d (%s), %d iterations, %d evaluations, cost %.3g\n", fit.info,
		mkSqFit_StatusName(fit.info), fit.iterations, fit.nfev, fit.cost);
	printf("  fitted a = (%.9g, %.9g, %.9g), eps = (%.9g, %.9g)\n", fit.shape.a, fit.shape.b,
		fit.shape.c, fit.shape.eps1, fit.shape.eps2);
	ENSURE(fit.info >= 1 && fit.info <= 4);
	ENSURE(fit.iterations > 0 && fit.nfev >= fit.iterations * MK_SQFIT_NVAR);
	ENSURE_REL(mkShape3_Volume(fit.shape), mkShape3_Volume(s), 1e-6);
	ENSURE_NEAR(fit.shape.eps1, 0.6, 1e-6);
	ENSURE_NEAR(fit.shape.eps2, 1.3, 1e-6);
	ENSURE_NEAR(fit.t.x, 1.0, 1e-6);
	ENSURE_NEAR(fit.t.y, -2.0, 1e-6);
	ENSURE_NEAR(fit.t.z, 0.5, 1e-6);
	ENSURE(mkSqFit_ImplicitError(&fit, x, y, z, M) < 1e-6);
	ENSURE(fit.cost < 1e-12);

	/* too few points for 12 unknowns; a start outside the bounds */
	ENSURE(mkSqFit_Run(x, y, z, MK_SQFIT_NVAR - 1, &start, &fit) == MK_ERR_ARGUMENT);
	mkSqFit bad = start;
	bad.shape.eps1 = 0.05;
	ENSURE(mkSqFit_Run(x, y, z, M, &bad, &fit) == MK_ERR_RANGE);
}

/* ---- the bounds hold: a box's corners pull eps to its lower bound -------
 * Eight corners of a cube are fitted best by the squarest shape allowed;
 * whatever the optimiser does, the exponents stay in [0.1, 2 - 1e-6]. */
static void testBounds(void)
{
	double x[27], y[27], z[27];
	int m = 0;
	for (int k = 0; k < 27; ++k) {
		int i = k % 3, j = (k / 3) % 3, l = k / 9;
		if (i == 1 && j == 1 && l == 1) {
			continue;
		}
		x[m] = 3.0 * (i - 1);
		y[m] = 2.0 * (j - 1);
		z[m] = 1.0 * (l - 1);
		++m;
	}
	mkSqFit start, fit;
	ENSURE(mkSqFit_Start(x, y, z, m, &start) == MK_OK);
	ENSURE(mkSqFit_Run(x, y, z, m, &start, &fit) == MK_OK);
	printf("box surface points: info %d, eps = (%.6g, %.6g), a = (%.6g, %.6g, %.6g)\n", fit.info,
		fit.shape.eps1, fit.shape.eps2, fit.shape.a, fit.shape.b, fit.shape.c);
	ENSURE(fit.shape.eps1 >= MK_SQFIT_EPS_LO && fit.shape.eps1 <= MK_SQFIT_EPS_HI);
	ENSURE(fit.shape.eps2 >= MK_SQFIT_EPS_LO && fit.shape.eps2 <= MK_SQFIT_EPS_HI);
	ENSURE(fit.shape.a > 0 && fit.shape.b > 0 && fit.shape.c > 0);
}

int main(void)
{
	testGauge();
	testRotations();
	testPcaStart();
	testExactFit();
	testBounds();
	return mk_summary("fitting.test_sqfit");
}
