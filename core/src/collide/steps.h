/* steps.h - the two-dimensional steps both queries take in a tangent plane:
 * the trust-region step of a quadratic model (with the eigen-decomposition
 * of a symmetric 2 x 2 matrix) and the exact maximisation along a line that
 * backs it up where the model fails. Static definitions. */
#ifndef MINK_COLLIDE_STEPS_H
#define MINK_COLLIDE_STEPS_H

#include "collide/support.h"

/* The initial and largest trust-region radius (a step in the tangent plane
 * of the unit normal, so roughly radians). */
#define MK_TR_INIT 0.25
#define MK_TR_MAX 1.0
/* From this iteration on, a step whose model was poor (ratio below 0.75) is
 * followed by an exact line search along the stiffest direction. */
#define MK_LINE_AFTER 6

/* |(a, b)| for the well-scaled 2-vectors of the solver (gradients and steps
 * far from the double range's ends): libm's hypot guards against overflow
 * at a cost that dominated the whole query. */
MK_PAIR_FN double mkLen2(double a, double b)
{
	return sqrt(a * a + b * b);
}

/* Eigen-decomposition of a symmetric 2 x 2 matrix: lam[0] <= lam[1] with
 * unit eigenvectors v0, v1. */
MK_PAIR_FN void mkEig2(double A[2][2], double lam[2], double v0[2], double v1[2])
{
	double a = A[0][0], b = 0.5 * (A[0][1] + A[1][0]), c = A[1][1];
	double mean = 0.5 * (a + c), half = 0.5 * (a - c);
	double rad = mkLen2(half, b);
	lam[0] = mean - rad;
	lam[1] = mean + rad;
	if (rad == 0.0) {
		v1[0] = 1.0; v1[1] = 0.0;
	} else if (half >= 0.0) {
		double nx = half + rad, ny = b, nn = mkLen2(nx, ny);
		v1[0] = nx / nn; v1[1] = ny / nn;
	} else {
		double nx = b, ny = rad - half, nn = mkLen2(nx, ny);
		v1[0] = nx / nn; v1[1] = ny / nn;
	}
	v0[0] = -v1[1];
	v0[1] = v1[0];
}
/* The trust-region step of the model  m(s) = -g.s + 1/2 s^T A s  (A 2 x 2
 * symmetric) within |s| <= radius: the Newton step when A is positive
 * definite and it fits, else (A + mu I) s = g with mu >= max(0, -lambda_min)
 * on the boundary (Newton on the secular equation; the "hard case" adds the
 * lowest eigenvector). Returns the predicted increase g.s - 1/2 s^T A s. */
MK_PAIR_FN double mkTrustStep(const double g[2], double A[2][2], double radius, double s[2])
{
	/* The common case first: A positive definite and the Newton step inside
	 * the region (Cramer's rule; pred = g.s / 2 for the Newton step). */
	double a = A[0][0], b = 0.5 * (A[0][1] + A[1][0]), c = A[1][1], det = a * c - b * b;
	if (a > 0.0 && det > 1e-12 * (a * c)) {
		double z0 = (c * g[0] - b * g[1]) / det, z1 = (a * g[1] - b * g[0]) / det;
		if (z0 * z0 + z1 * z1 <= radius * radius) {
			s[0] = z0;
			s[1] = z1;
			return 0.5 * (g[0] * z0 + g[1] * z1);
		}
	}
	double lam2[2], v0[2], v1[2];
	mkEig2(A, lam2, v0, v1);
	double l0 = lam2[0], l1 = lam2[1];
	double v0x = v0[0], v0y = v0[1], v1x = v1[0], v1y = v1[1];
	double g0 = v0x * g[0] + v0y * g[1], g1 = v1x * g[0] + v1y * g[1];
	double lam[2] = { l0, l1 }, gg[2] = { g0, g1 }, z[2];
	double mu = 0.0;
	int newton_ok = l0 > 0.0;
	if (newton_ok) {
		z[0] = g0 / l0;
		z[1] = g1 / l1;
		newton_ok = mkLen2(z[0], z[1]) <= radius;
	}
	if (!newton_ok) {
		double lo = l0 > 0.0 ? 0.0 : -l0;
		/* Start just right of the pole; Newton on 1/|s(mu)| - 1/radius is
		 * monotone from the left. */
		double gn = mkLen2(g0, g1);
		mu = lo + 1e-14 * (fabs(l0) + fabs(l1) + gn / radius) + DBL_MIN;
		double norm = 0.0;
		for (int it = 0; it < 60; ++it) {
			double n2 = 0.0, d3 = 0.0;
			for (int i = 0; i < 2; ++i) {
				double den = lam[i] + mu;
				z[i] = gg[i] / den;
				n2 += z[i] * z[i];
				d3 += z[i] * z[i] / den;
			}
			norm = sqrt(n2);
			if (norm <= radius * (1.0 + 1e-10))
				break;
			double step = (norm - radius) / radius * n2 / d3;
			mu += step;
		}
		if (norm < radius * (1.0 - 1e-6) && l0 <= 0.0) {
			/* Hard case: fill the step to the boundary along v0. */
			double extra = sqrt(radius * radius - norm * norm);
			z[0] += z[0] >= 0.0 ? extra : -extra;
		}
	}
	s[0] = v0x * z[0] + v1x * z[1];
	s[1] = v0y * z[0] + v1y * z[1];
	return g0 * z[0] + g1 * z[1] - 0.5 * (l0 * z[0] * z[0] + l1 * z[1] * z[1]);
}

/* ---- exact line searches ------------------------------------------------ */

/* One probe of a function of one variable t: its value and derivative. */
typedef void (*mkLineFn)(void *ctx, double t, double *v, double *dv);

/* Maximises a function v(t) of one variable that is concave (MinkSum (Ray):
 * -psi along a line) or concave near its maximum (MinkSum (Normal): f along
 * a great circle), from t = 0, where its value is v0 and its slope d0 > 0.
 * The bracket [0, h] is widened by 4 while the slope at its end is still
 * positive; then each step probes where the tangent lines at the bracket's
 * two ends cross (on a concave function they bound it from above there; on
 * a piecewise linear one that point is the kink itself, so a nearly kinked
 * support function, where Newton's model fails, takes a few probes instead
 * of a bisection to rounding), or the midpoint when the last step did not
 * halve the bracket, and keeps the end whose slope has the same sign. It
 * stops when the tangent lines' bound is within 4 ulps of the best value
 * found (|v| + scale), or when no double lies inside the bracket; then it
 * returns 1 (converged), else 0 (out of probes, or the slope never turned).
 * The probes themselves keep the best point (fn's context). */
MK_PAIR_FN int mkLine_Max(mkLineFn fn, void *ctx, double h, double v0, double d0, double scale)
{
	double lo = 0.0, vlo = v0, dlo = d0, hi = h, vhi, dhi;
	double best = v0;
	fn(ctx, hi, &vhi, &dhi);
	for (int k = 0; dhi > 0.0 && k < 40 && hi < 1e8; ++k) {
		best = fmax(best, vhi);
		lo = hi;
		vlo = vhi;
		dlo = dhi;
		hi *= 4.0;
		fn(ctx, hi, &vhi, &dhi);
	}
	best = fmax(best, vhi);
	if (!(dhi <= 0.0))
		return 0; /* still rising (or NaN) */
	int halved = 1;
	for (int k = 0; k < 100; ++k) {
		double t = 0.5 * (lo + hi);
		if (dlo - dhi > 0.0) {
			double cross = (vhi - vlo + dlo * lo - dhi * hi) / (dlo - dhi);
			double bound = vlo + dlo * (cross - lo);
			if (bound - best <= 4.0 * DBL_EPSILON * (fabs(best) + scale))
				return 1;
			if (halved && cross > lo && cross < hi)
				t = cross;
		}
		if (!(t > lo && t < hi))
			return 1; /* the bracket is down to adjacent doubles */
		double v, dv, width = hi - lo;
		fn(ctx, t, &v, &dv);
		best = fmax(best, v);
		if (dv > 0.0) {
			lo = t;
			vlo = v;
			dlo = dv;
		} else {
			hi = t;
			vhi = v;
			dhi = dv;
		}
		halved = hi - lo <= 0.5 * width;
	}
	return 0;
}

#endif
