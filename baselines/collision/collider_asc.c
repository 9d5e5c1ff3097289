/* collider_asc.c - the algebraic separation condition of two ellipsoids
 * (Wang, Wang & Kim 2001) in closed form, and the Eigen eigenvalue route of
 * mink/collide.h as a second entry.
 *
 * An ellipsoid B = t + M E is {X : X^T Q X <= 0}, X = (x, 1), with
 * Q = T^-T diag(a^-2, b^-2, c^-2, -1) T^-1, T = [M t; 0 1]. For body 1's A
 * and body 2's B the quartic p(l) = det(l A + B) has two negative roots, and
 * two more that are positive and distinct iff the ellipsoids are separated,
 * a positive double root iff they touch, a complex pair or two more negative
 * roots iff they overlap (two unit spheres d apart:
 * p = -(l + 1)^2 (l^2 - (d^2 - 2) l + 1)).
 *
 * Coordinates. A common affine change of coordinates X = H Y turns every
 * quadric Q into H^T Q H, which multiplies p by det(H)^2 > 0 and keeps its
 * roots. In the coordinates u of body 1's unit ball (x = t1 + M1 diag(a1,
 * b1, c1) u) body 1 is J = diag(1, 1, 1, -1) and body 2 is
 *     B' = [G^T G, G^T g; g^T G, g^T g - 1],
 *     G = diag(1/a2, 1/b2, 1/c2) M2^-1 M1 diag(a1, b1, c1),
 *     g = diag(1/a2, 1/b2, 1/c2) M2^-1 (t1 - t2),
 * so p(l) = det(l J + B') = sum over index sets S of l^|S| (prod over S of
 * J_ii) det(B' without the rows and columns of S): its coefficients are
 * signed sums of B''s principal minors, c4 = -1, c3 = B'_33 - B'_00 - B'_11
 * - B'_22, c2, c1 from the 2 x 2 and 3 x 3 principal minors, c0 = det B' =
 * -det(G)^2. No determinant is evaluated at sample points and no
 * coefficient is interpolated.
 *
 * The maximum of p on l > 0. p(0) = c0 < 0 and p -> -inf. The two negative
 * roots hold a critical point of p between them, so at most the largest
 * root x of the cubic p' lies in l > 0, and max over l > 0 of p is p(x)
 * when x > 0, else p(0) < 0. x by the cubic formula (cos(acos(.) / 3) by
 * a polynomial, no trigonometric call), then two Newton steps on p'. Separated iff p(x) > tol, overlapping iff p(x) < -tol, touching in
 * between, where tol bounds the rounding of p(x) and of its coefficients:
 * 32 eps times the product over the rows of |x J + B'| of the row sums (a
 * bound on every product term of the Leibniz expansion of det(x J + B')).
 * Near touching p(x) is linear in the gap (16 times the gap for the unit
 * spheres), so the band is a few 1e-14 of the size. */
#include <float.h>
#include <math.h>

#include "colliders_internal.h"

/* Largest real root of l^3 + a l^2 + b l + c, polished by two Newton steps.
 *
 * Three real roots (the case of separated ellipsoids): with l = t - a/3 the
 * depressed cubic t^3 + P t + Q has the roots t_k = m cos(phi - 2 pi k / 3),
 * m = 2 sqrt(-P/3), phi = acos(3 Q / (P m)) / 3 in [0, pi/3]. cos(phi) comes
 * from a polynomial (below) and sin(phi) = sqrt(1 - cos^2), so t_0 >= t_1 >=
 * t_2 cost no trigonometric call. P and Q carry an absolute rounding error
 * of order eps a^2, so a root much smaller than |a| (needles and plates: the
 * roots of p' then span 14 decades) is lost in them; only the root of
 * largest magnitude is accurate. When x0 = t_0 - a/3 is below 1e-2 of
 * |a/3| + m (cancelled) and t_2 (the smallest) has the larger magnitude, the
 * largest root comes from the quadratic left after dividing it out,
 * l^2 + B l + C with C = -c / x2, B = (C - b) / x2 (exact coefficients b, c;
 * no cancellation against a), by the stable quadratic formula. */
static double mkCubicLargest(double a, double b, double c)
{
	const double third = 1.0 / 3.0;
	double a3 = a * third;
	double p = b - a * a3, q = (2.0 * a3 * a3 - b) * a3 + c;
	double p3 = p * third;
	double disc = 0.25 * q * q + p3 * p3 * p3, x;
	if (disc > 0.0) {
		/* One real root: the ellipsoids are not separated, and p <= 0 on
		 * l > 0 wherever it is evaluated; x need not be accurate. */
		double r = sqrt(disc);
		x = cbrt(-0.5 * q + r) + cbrt(-0.5 * q - r) - a3;
	} else if (p == 0.0) {
		x = -a3;
	} else {
		/* cos(phi) = cos(acos(arg) / 3): with s = cos(acos(arg) / 2) =
		 * sqrt((1 + arg) / 2), cos(acos(arg) / 3) = cos(2 acos(s) / 3),
		 * analytic in s on [0, 1] (acos(s)^2 is analytic at s = 1): its
		 * degree-6 Chebyshev interpolant in y = 2 s - 1 is within 1.9e-7, and
		 * the Newton steps square that. */
		double m = 2.0 * sqrt(-p3);
		double arg = 3.0 * q / (p * m);
		arg = arg < -1.0 ? -1.0 : arg > 1.0 ? 1.0 : arg;
		double y = 2.0 * sqrt(0.5 + 0.5 * arg) - 1.0;
		double cs = ((((((-3.2867047034201846e-05 * y + 1.3097751764412635e-04) * y - 5.020910405583326e-04) * y
			+ 2.4588651388908517e-03) * y - 1.5509445182466138e-02) * y + 2.4741001122299905e-01) * y
			+ 7.660444431189781e-01);
		double x0 = m * cs - a3;
		x = x0;
		/* x0 lost digits to cancellation (|x0| << |a3| + m): the root of
		 * largest magnitude is then t_2's. */
		double sn = 0.0, x2 = 0.0;
		if (fabs(x0) < 1e-2 * (fabs(a3) + m)) {
			sn = sqrt(cs < 1.0 ? 1.0 - cs * cs : 0.0);
			x2 = m * (-0.5 * cs - 0.8660254037844386 * sn) - a3;
		}
		if (fabs(x2) > fabs(x0)) {
			/* Polish x2, divide it out, solve the quadratic stably. */
			for (int it = 0; it < 2; ++it) {
				double f = ((x2 + a) * x2 + b) * x2 + c, df = (3.0 * x2 + 2.0 * a) * x2 + b;
				if (df != 0.0)
					x2 -= f / df;
			}
			if (x2 != 0.0) {
				double C = -c / x2, B = (C - b) / x2;
				double D = B * B - 4.0 * C;
				double h = -0.5 * (B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(D > 0.0 ? D : 0.0));
				double r1 = h, r2 = h != 0.0 ? C / h : h;
				x = r1 > r2 ? r1 : r2;
			}
		}
	}
	for (int it = 0; it < 2; ++it) {
		double f = ((x + a) * x + b) * x + c, df = (3.0 * x + 2.0 * a) * x + b;
		if (df != 0.0)
			x -= f / df;
	}
	return x;
}

static mkResult mkRunAsc(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	mkMat3 N2 = mkMat3_Inverse(b2.M);
	mkMat3 W = mkMat3_Mul(N2, b1.M);
	mkVec3 w = mkMat3_MulVec(N2, mkVec3_Sub(b1.t, b2.t));
	const double ax1[3] = { b1.shape.a, b1.shape.b, b1.shape.c };
	const double iv2[3] = { 1.0 / b2.shape.a, 1.0 / b2.shape.b, 1.0 / b2.shape.c };
	const double wv[3] = { w.x, w.y, w.z };
	double G[3][3], g[3];
	for (int i = 0; i < 3; ++i) {
		for (int j = 0; j < 3; ++j)
			G[i][j] = iv2[i] * W.m[i][j] * ax1[j];
		g[i] = iv2[i] * wv[i];
	}
	/* B' = [S v; v^T r]. */
	double S00 = G[0][0] * G[0][0] + G[1][0] * G[1][0] + G[2][0] * G[2][0];
	double S11 = G[0][1] * G[0][1] + G[1][1] * G[1][1] + G[2][1] * G[2][1];
	double S22 = G[0][2] * G[0][2] + G[1][2] * G[1][2] + G[2][2] * G[2][2];
	double S01 = G[0][0] * G[0][1] + G[1][0] * G[1][1] + G[2][0] * G[2][1];
	double S02 = G[0][0] * G[0][2] + G[1][0] * G[1][2] + G[2][0] * G[2][2];
	double S12 = G[0][1] * G[0][2] + G[1][1] * G[1][2] + G[2][1] * G[2][2];
	double v0 = G[0][0] * g[0] + G[1][0] * g[1] + G[2][0] * g[2];
	double v1 = G[0][1] * g[0] + G[1][1] * g[1] + G[2][1] * g[2];
	double v2 = G[0][2] * g[0] + G[1][2] * g[1] + G[2][2] * g[2];
	double r = g[0] * g[0] + g[1] * g[1] + g[2] * g[2] - 1.0;
	/* Principal minors: 2 x 2 of S (m01, m02, m12), with row 3 (m03, m13,
	 * m23), 3 x 3 with row 3 (M013, M023, M123), det S and det B'. */
	double m01 = S00 * S11 - S01 * S01, m02 = S00 * S22 - S02 * S02, m12 = S11 * S22 - S12 * S12;
	double m03 = S00 * r - v0 * v0, m13 = S11 * r - v1 * v1, m23 = S22 * r - v2 * v2;
	double M013 = r * m01 - (S11 * v0 * v0 - 2.0 * S01 * v0 * v1 + S00 * v1 * v1);
	double M023 = r * m02 - (S22 * v0 * v0 - 2.0 * S02 * v0 * v2 + S00 * v2 * v2);
	double M123 = r * m12 - (S22 * v1 * v1 - 2.0 * S12 * v1 * v2 + S11 * v2 * v2);
	double detG = G[0][0] * (G[1][1] * G[2][2] - G[1][2] * G[2][1]) - G[0][1] * (G[1][0] * G[2][2] - G[1][2] * G[2][0])
		+ G[0][2] * (G[1][0] * G[2][1] - G[1][1] * G[2][0]);
	double c[5];
	c[0] = -detG * detG;
	c[1] = M123 + M023 + M013 - detG * detG;
	c[2] = m23 + m13 + m03 - m12 - m02 - m01;
	c[3] = r - S00 - S11 - S22;
	c[4] = -1.0;
	if (!(c[0] < 0.0) || !isfinite(c[1] + c[2] + c[3])) {
		/* A degenerate body (a zero semi-axis, a singular M) or non-finite data. */
		return MK_ERR_CONVERGENCE;
	}
	/* p' = -4 l^3 + 3 c3 l^2 + 2 c2 l + c1, made monic. */
	double x = mkCubicLargest(-0.75 * c[3], -0.5 * c[2], -0.25 * c[1]);
	if (!(x > 0.0))
		x = 0.0;
	double best = (((c[4] * x + c[3]) * x + c[2]) * x + c[1]) * x + c[0];
	/* Rounding band: row sums of |x J + B'|. */
	double av0 = fabs(v0), av1 = fabs(v1), av2 = fabs(v2), as01 = fabs(S01), as02 = fabs(S02), as12 = fabs(S12);
	double band = 32.0 * DBL_EPSILON * (x + S00 + as01 + as02 + av0) * (x + as01 + S11 + as12 + av1)
		* (x + as02 + as12 + S22 + av2) * (x + av0 + av1 + av2 + fabs(r));
	out->residual = best / band * 32.0 * DBL_EPSILON;
	out->status = best > band ? MK_CONTACT_SEPARATED : best < -band ? MK_CONTACT_OVERLAPPING : MK_CONTACT_TOUCHING;
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
	"in body 1's unit-ball coordinates: coefficients from the principal minors of body 2's quadric; max over l > 0 at "
	"the largest root of p' (cubic formula, cos(acos(.)/3) by a degree-6 polynomial in sqrt((1 + .)/2), plus 2 Newton steps); touching iff |max| <= 32 eps prod of the row sums of "
	"|x J + B'|",
	MK_GIVES_STATUS, MK_PAIRS_ELLIPSOIDS, 0, NULL, mkRunAsc, NULL
};

const mkCollider mkCollider_AscEigen = {
	"asc-eigen", "ASC by the eigenvalues of A^-1 B (Eigen's real eigensolver), the earlier route",
	"Eigen EigenSolver on A^-1 B (4x4); real iff |imag| <= 1e-9 |mu|; separated iff two positive roots apart by > 1e-9",
	MK_GIVES_STATUS, MK_PAIRS_ELLIPSOIDS, 0, NULL, mkRunAscEigen, mkEigen
};
