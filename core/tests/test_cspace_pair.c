/* test_cspace_pair.c - the scene query's quick certificates' bounds of a
 * superquadric's norms (cspace/scenepair.h, mkSq_NormBounds) against the
 * shape module's closed forms (other code): for random shapes (exponents
 * over (0, 2), near both ends, exactly 1, and mixed sides of 1) and random
 * directions, lo <= h(y) <= hi for the support value h = mkShape3_SupportValue,
 * and for the gauge g the point y / lo lies on or outside the surface and
 * y / hi on or inside it (mkShape3_Implicit, which is 1 on the surface);
 * an ellipsoid's bounds equal mkSq_ShapeNorm's value to the bit, and
 * every shape's mkSq_ShapeNorm is within 1e-14 of the powers' definition
 * evaluated in long double, at points near 1 and scaled by up to 1e150
 * either way. The
 * least of a convex quadratic over a box (mkSqQuick_BoxLeast) against
 * every face of the box solved by elimination, and the box mkSqQuick_Make
 * puts inside a shape: its corner's gauge at most 1 (long double). */
#include <math.h>
#include <stdio.h>

#include "cspace/scenepair.h"
#include "ensure.h"

static unsigned long long seed = 23;

static double uni(double lo, double hi) { return mk_test_uniform(&seed, lo, hi); }

/* An exponent of the given kind: 0 anywhere in (0, 2), 1 exactly 1, 2 near 0, 3 near 2, 4 below 1, 5 above 1. */
static double mkExponent(int kind)
{
	switch (kind) {
	case 1: return 1.0;
	case 2: return uni(1e-3, 0.1);
	case 3: return uni(1.9, 2.0 - 1e-3);
	case 4: return uni(0.05, 1.0);
	case 5: return uni(1.0, 1.95);
	default: return uni(0.02, 1.98);
	}
}

static double mkQuad(double H[3][3], const double y[3], const double y0[3])
{
	double f = 0.0;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) f += (y[i] - y0[i]) * H[i][j] * (y[j] - y0[j]);
	return f;
}

/* The least of (y - y0)^T H (y - y0) over |y_i| <= w_i by brute force:
 * on each of the 27 faces (each coordinate at -w, free or at w) the
 * stationary point of the free coordinates by Gaussian elimination with
 * pivoting, the least of those inside the box. */
static double mkBoxLeastRef(double H[3][3], const double y0[3], const double w[3])
{
	double best = INFINITY;
	for (int f = 0; f < 27; ++f) {
		int at[3] = {f % 3 - 1, (f / 3) % 3 - 1, f / 9 - 1}, free[3], nf = 0;
		double y[3], A[3][4];
		for (int i = 0; i < 3; ++i) {
			y[i] = at[i] * w[i];
			if (at[i] == 0) free[nf++] = i;
		}
		/* sum_j H_ij (y_j - y0_j) = 0 for each free i */
		for (int r = 0; r < nf; ++r) {
			int i = free[r];
			A[r][3] = 0.0;
			for (int j = 0; j < 3; ++j)
				if (at[j] != 0) A[r][3] -= H[i][j] * (y[j] - y0[j]);
			for (int c = 0; c < nf; ++c) A[r][c] = H[i][free[c]];
		}
		int ok = 1;
		for (int c = 0; c < nf && ok; ++c) {
			int pv = c;
			for (int r = c + 1; r < nf; ++r) if (fabs(A[r][c]) > fabs(A[pv][c])) pv = r;
			if (!(fabs(A[pv][c]) > 0.0)) { ok = 0; break; }
			for (int k = 0; k < 4; ++k) { double t = A[c][k]; A[c][k] = A[pv][k]; A[pv][k] = t; }
			for (int r = 0; r < nf; ++r) {
				if (r == c) continue;
				double q = A[r][c] / A[c][c];
				for (int k = c; k < 4; ++k) if (k < nf || k == 3) A[r][k] -= q * A[c][k];
			}
		}
		if (!ok) continue;
		for (int r = 0; r < nf; ++r) y[free[r]] = y0[free[r]] + A[r][3] / A[r][r];
		int inside = 1;
		for (int i = 0; i < 3; ++i) inside &= fabs(y[i]) <= w[i] * (1.0 + 1e-12);
		if (inside) best = fmin(best, mkQuad(H, y, y0));
	}
	return best;
}

static long mkBoxLeastCases(void)
{
	long n = 0;
	for (int t = 0; t < 20000; ++t) {
		double B[3][3], H[3][3], y0[3], w[3], y[3];
		/* rows of very different lengths for the harder cases: an elongated ellipsoid */
		for (int i = 0; i < 3; ++i) {
			double s = pow(10.0, uni(-(t % 4), t % 4));
			for (int j = 0; j < 3; ++j) B[i][j] = s * uni(-1, 1);
		}
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j) H[i][j] = B[0][i] * B[0][j] + B[1][i] * B[1][j] + B[2][i] * B[2][j];
		for (int i = 0; i < 3; ++i) {
			w[i] = uni(0.1, 10.0);
			y0[i] = uni(-3.0, 3.0) * w[i];
		}
		mkSqQuick_BoxLeast(H, y0, w, y);
		for (int i = 0; i < 3; ++i) ENSURE(fabs(y[i]) <= w[i]);
		double ref = mkBoxLeastRef(H, y0, w), scale = 0.0;
		for (int i = 0; i < 3; ++i) scale += H[i][i] * (fabs(y0[i]) + w[i]) * (fabs(y0[i]) + w[i]);
		ENSURE(isfinite(ref) && mkQuad(H, y, y0) <= ref + 1e-9 * scale);
		++n;
	}
	return n;
}

int main(void)
{
	long checked = 0;
	for (int t = 0; t < 60000; ++t) {
		mkShape3 s = { uni(0.1, 10.0), uni(0.1, 10.0), uni(0.1, 10.0), mkExponent(t % 6), mkExponent((t / 6) % 6) };
		mkVec3 y = { uni(-1, 1), uni(-1, 1), uni(-1, 1) };
		if (t % 7 == 0) y.y = 0.0;   /* on a coordinate plane */
		if (t % 11 == 0) { y.x = y.z = 0.0; y.y = uni(0.1, 1.0); }   /* along an axis */
		double lo, hi;
		mkSq_NormBounds(s, y, 1, &lo, &hi);
		double h = mkShape3_SupportValue(s, y);
		ENSURE(lo <= h * (1.0 + 1e-12) && hi >= h * (1.0 - 1e-12));
		mkSq_NormBounds(s, y, 0, &lo, &hi);
		ENSURE(lo > 0.0 && hi >= lo);
		ENSURE(mkShape3_Implicit(s, mkVec3_Scale(y, 1.0 / lo)) >= 1.0 - 1e-9);
		ENSURE(mkShape3_Implicit(s, mkVec3_Scale(y, 1.0 / hi)) <= 1.0 + 1e-9);
		if (s.eps1 == 1.0 && s.eps2 == 1.0)
			for (int dual = 0; dual < 2; ++dual) {
				mkSq_NormBounds(s, y, dual, &lo, &hi);
				double v = mkSq_ShapeNorm(s, y, dual);
				ENSURE(lo == v && hi == v);
			}
		++checked;
	}
	/* the box inside the shape: its corner's gauge at most 1, in long double by the powers' definition */
	for (int t = 0; t < 20000; ++t) {
		mkShape3 s = { uni(0.1, 10.0), uni(0.1, 10.0), uni(0.1, 10.0), mkExponent(t % 6), mkExponent((t / 6) % 6) };
		mkSqQuick k = mkSqQuick_Make(mkBody3_Make(s, mkMat3_Identity(), mkVec3_Make(0, 0, 0)));
		long double p1 = 2.0L / s.eps1, p2 = 2.0L / s.eps2, u = k.w[0] / (long double)s.a, v = k.w[1] / (long double)s.b;
		long double z = k.w[2] / (long double)s.c, m = fmaxl(u, v), r = fminl(u, v) / m;
		long double xy = m * powl(1.0L + powl(r, p2), 1.0L / p2), M = fmaxl(xy, z), R = fminl(xy, z) / M;
		ENSURE(M * powl(1.0L + powl(R, p1), 1.0L / p1) <= 1.0L);
	}
	/* the norms (mkSq_ShapeNorm, by base-2 logarithms and exponentials) against the powers' definition in
	 * long double: within 1e-14 relative, two orders under the certificates' margin (MK_SQ_QUICK) */
	double worst = 0.0;
	for (int t = 0; t < 60000; ++t) {
		mkShape3 s = { uni(0.1, 10.0), uni(0.1, 10.0), uni(0.1, 10.0), mkExponent(t % 6), mkExponent((t / 6) % 6) };
		mkVec3 y = { uni(-1, 1), uni(-1, 1), uni(-1, 1) };
		if (t % 7 == 0) y.y = 0.0;
		if (t % 13 == 0) y.x = y.y * (1.0 + uni(-1e-9, 1e-9));   /* nearly equal components */
		if (t % 5 == 1) { /* far from 1: scaled by powers of ten up to 1e150 either way (the poses' range) */
			static const double scale[6] = {1e-150, 1e-100, 1e-50, 1e50, 1e100, 1e150};
			y = mkVec3_Scale(y, scale[(t / 5) % 6]);
		}
		for (int dual = 0; dual < 2; ++dual) {
			long double p1 = dual ? 2.0L / (2.0L - s.eps1) : 2.0L / s.eps1, p2 = dual ? 2.0L / (2.0L - s.eps2) : 2.0L / s.eps2;
			long double u = fabsl(y.x), v = fabsl(y.y), z = fabsl(y.z);
			if (dual) { u *= s.a; v *= s.b; z *= s.c; }
			else { u /= s.a; v /= s.b; z /= s.c; }
			long double m = fmaxl(u, v), xy = m > 0.0L ? m * powl(1.0L + powl(fminl(u, v) / m, p2), 1.0L / p2) : 0.0L;
			long double M = fmaxl(xy, z), ref = M * powl(1.0L + powl(fminl(xy, z) / M, p1), 1.0L / p1);
			double err = (double)(fabsl((long double)mkSq_ShapeNorm(s, y, dual) - ref) / ref);
			ENSURE(err <= 1e-14);
			worst = fmax(worst, err);
		}
	}
	printf("test_cspace_pair: norms within %.2e of long double's\n", worst);
	long boxes = mkBoxLeastCases();
	printf("test_cspace_pair: %ld shapes and directions, %ld least points on boxes\n", checked, boxes);
	return mk_summary("test_cspace_pair");
}
