/* collider_asc.c - the algebraic separation condition of two ellipsoids
 * (Wang, Wang & Kim 2001) in closed form, and the Eigen eigenvalue route of
 * mink/collide.h as a second entry.
 *
 * An ellipsoid B = t + M E is {X : X^T Q X <= 0}, X = (x, 1), with
 * Q = [N^T D N, N^T D w; w^T D N, w^T D w - 1], N = M^-1, w = -N t,
 * D = diag(a^-2, b^-2, c^-2). For body 1's A and body 2's B the quartic
 * p(l) = det(l A + B) has two negative roots and two more that are positive
 * and distinct iff the ellipsoids are separated, a positive double root iff
 * they touch, a complex pair iff they overlap (two unit spheres d apart:
 * p = -(l + 1)^2 (l^2 - (d^2 - 2) l + 1)). Since p(0) = det B < 0 and the
 * leading coefficient det A < 0, that is: separated iff the maximum of p on
 * l > 0 is positive. The maximum sits at a positive root of the cubic p'
 * (solved in closed form, then two Newton steps), or at 0.
 *
 * The coefficients: c0 = det B, c4 = det A exactly, c1..c3 from p(+-1),
 * p(+-2) (A and B first divided by their largest entries, which scales the
 * roots by a positive factor and changes no sign). */
#include <float.h>
#include <math.h>

#include "colliders_internal.h"

static void mkQuadric(mkBody3 b, double Q[4][4])
{
	mkMat3 N = mkMat3_Inverse(b.M);
	mkVec3 w = mkVec3_Neg(mkMat3_MulVec(N, b.t));
	double D[3] = { 1.0 / (b.shape.a * b.shape.a), 1.0 / (b.shape.b * b.shape.b), 1.0 / (b.shape.c * b.shape.c) };
	double Nw[4][3]; /* rows: N's rows and w, so that Q = R^T diag(D, -1) R */
	for (int k = 0; k < 3; ++k)
		for (int j = 0; j < 3; ++j)
			Nw[k][j] = N.m[k][j];
	double wv[3] = { w.x, w.y, w.z };
	for (int i = 0; i < 4; ++i)
		for (int j = 0; j < 4; ++j) {
			double s = 0.0;
			for (int k = 0; k < 3; ++k) {
				double ri = i < 3 ? Nw[k][i] : wv[k];
				double rj = j < 3 ? Nw[k][j] : wv[k];
				s += ri * D[k] * rj;
			}
			Q[i][j] = s - (i == 3 && j == 3 ? 1.0 : 0.0);
		}
	double mx = 0.0;
	for (int i = 0; i < 4; ++i)
		for (int j = 0; j < 4; ++j)
			mx = fmax(mx, fabs(Q[i][j]));
	for (int i = 0; i < 4; ++i)
		for (int j = 0; j < 4; ++j)
			Q[i][j] /= mx;
}

/* det of a 4 x 4 matrix by 2 x 2 minors of the top and bottom row pairs. */
static double mkDet4(double m[4][4])
{
	double s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1];
	double s1 = m[0][0] * m[1][2] - m[1][0] * m[0][2];
	double s2 = m[0][0] * m[1][3] - m[1][0] * m[0][3];
	double s3 = m[0][1] * m[1][2] - m[1][1] * m[0][2];
	double s4 = m[0][1] * m[1][3] - m[1][1] * m[0][3];
	double s5 = m[0][2] * m[1][3] - m[1][2] * m[0][3];
	double c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3];
	double c4 = m[2][1] * m[3][3] - m[3][1] * m[2][3];
	double c3 = m[2][1] * m[3][2] - m[3][1] * m[2][2];
	double c2 = m[2][0] * m[3][3] - m[3][0] * m[2][3];
	double c1 = m[2][0] * m[3][2] - m[3][0] * m[2][2];
	double c0 = m[2][0] * m[3][1] - m[3][0] * m[2][1];
	return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
}

static double mkDetAt(double A[4][4], double B[4][4], double l)
{
	double m[4][4];
	for (int i = 0; i < 4; ++i)
		for (int j = 0; j < 4; ++j)
			m[i][j] = l * A[i][j] + B[i][j];
	return mkDet4(m);
}

static double mkPoly(const double c[5], double l)
{
	return (((c[4] * l + c[3]) * l + c[2]) * l + c[1]) * l + c[0];
}

static double mkPolyAbs(const double c[5], double l)
{
	double a = fabs(l);
	return (((fabs(c[4]) * a + fabs(c[3])) * a + fabs(c[2])) * a + fabs(c[1])) * a + fabs(c[0]);
}

/* Real roots of x^3 + a x^2 + b x + c (1 or 3). */
static int mkCubic(double a, double b, double c, double x[3])
{
	double p = b - a * a / 3.0, q = 2.0 * a * a * a / 27.0 - a * b / 3.0 + c;
	double disc = 0.25 * q * q + p * p * p / 27.0;
	int n;
	if (disc > 0.0) {
		double r = sqrt(disc);
		x[0] = cbrt(-0.5 * q + r) + cbrt(-0.5 * q - r);
		n = 1;
	} else if (p == 0.0) {
		x[0] = 0.0;
		n = 1;
	} else {
		double m = 2.0 * sqrt(-p / 3.0);
		double arg = 3.0 * q / (p * m) ;
		arg = fmax(-1.0, fmin(1.0, arg));
		double th = acos(arg) / 3.0;
		for (int k = 0; k < 3; ++k)
			x[k] = m * cos(th - 2.0 * MK_PI * k / 3.0);
		n = 3;
	}
	for (int k = 0; k < n; ++k) {
		x[k] -= a / 3.0;
		for (int it = 0; it < 2; ++it) {
			double f = ((x[k] + a) * x[k] + b) * x[k] + c, df = (3.0 * x[k] + 2.0 * a) * x[k] + b;
			if (df != 0.0)
				x[k] -= f / df;
		}
	}
	return n;
}

static mkResult mkRunAsc(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	double A[4][4], B[4][4];
	mkQuadric(b1, A);
	mkQuadric(b2, B);
	double c[5];
	c[0] = mkDet4(B);
	c[4] = mkDet4(A);
	double yp1 = mkDetAt(A, B, 1.0), ym1 = mkDetAt(A, B, -1.0);
	double yp2 = mkDetAt(A, B, 2.0), ym2 = mkDetAt(A, B, -2.0);
	double e1 = 0.5 * (yp1 + ym1), o1 = 0.5 * (yp1 - ym1), o2 = 0.5 * (yp2 - ym2);
	c[2] = e1 - c[0] - c[4];
	c[3] = (o2 - 2.0 * o1) / 6.0;
	c[1] = o1 - c[3];
	if (!(c[4] < 0.0) || !(c[0] < 0.0) || !isfinite(c[1] + c[2] + c[3])) {
		/* Not two ellipsoids' quadrics within rounding (degenerate). */
		return MK_ERR_CONVERGENCE;
	}
	double x[3];
	int n = mkCubic(3.0 * c[3] / (4.0 * c[4]), 2.0 * c[2] / (4.0 * c[4]), c[1] / (4.0 * c[4]), x);
	double best = c[0], size = fabs(c[0]);
	for (int k = 0; k < n; ++k) {
		if (!(x[k] > 0.0))
			continue;
		double v = mkPoly(c, x[k]);
		if (v > best) {
			best = v;
			size = mkPolyAbs(c, x[k]);
		}
	}
	/* p's rounding error at the maximiser: a few ulps of sum |c_i| l^i. */
	double tol = 64.0 * DBL_EPSILON * size;
	out->residual = best / size;
	out->status = best > tol ? MK_CONTACT_SEPARATED : best < -tol ? MK_CONTACT_OVERLAPPING : MK_CONTACT_TOUCHING;
	return MK_OK;
}

static mkResult mkRunAscEigen(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	mkCollide c = mkCollide_ASC(b1, b2);
	mkCollision3_FromLegacy(c, out);
	out->iterations = -1;
	return c.collide < 0 ? MK_ERR_UNSUPPORTED : MK_OK;
}

static const char *mkEigen(void) { return mkCollide_EigenVersion(); }

const mkCollider mkCollider_Asc = {
	"asc", "ASC: algebraic separation of two ellipsoids, max of the quartic det(l A + B) on l > 0 in closed form",
	"coefficients c0, c4 exact, c1..c3 from det at l = +-1, +-2; critical points by the cubic formula plus 2 Newton steps; "
	"touching iff |max| <= 64 eps sum|c_i| l^i",
	MK_GIVES_STATUS, MK_PAIRS_ELLIPSOIDS, 0, NULL, mkRunAsc, NULL
};

const mkCollider mkCollider_AscEigen = {
	"asc-eigen", "ASC by the eigenvalues of A^-1 B (Eigen's real eigensolver), the earlier route",
	"Eigen EigenSolver on A^-1 B (4x4); real iff |imag| <= 1e-9 |mu|; separated iff two positive roots apart by > 1e-9",
	MK_GIVES_STATUS, MK_PAIRS_ELLIPSOIDS, 0, NULL, mkRunAscEigen, mkEigen
};
