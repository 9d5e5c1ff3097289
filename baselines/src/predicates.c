/* predicates.c - the exact sign of a 2D cross product of two differences of
 * doubles, as in Shewchuk's adaptive predicates: a cheap floating-point
 * evaluation with a proven error bound, and an exact expansion sum when the
 * bound cannot decide. */
#include <float.h>
#include <math.h>

#include <mink/baselines.h>

/* Error-free transformations (round to nearest, no contraction: the build
 * passes -ffp-contract=off, and x86-64 evaluates doubles in SSE registers). */
static void two_sum(double a, double b, double *x, double *y)
{
	double s = a + b;
	double bv = s - a;
	double av = s - bv;
	*x = s;
	*y = (a - av) + (b - bv);
}

/* a * b = x + y exactly while a * b neither overflows nor underflows; fma
 * computes a * b - x with a single rounding, which is then exact. */
static void two_product(double a, double b, double *x, double *y)
{
	double p = a * b;
	*x = p;
	*y = fma(a, b, -p);
}

/* h = e + b for a nonoverlapping expansion e (increasing magnitude), zero
 * components dropped (Shewchuk's grow_expansion_zeroelim). Returns the length
 * of h. h may be e itself: e[i] is always read before h[i] is written. */
static int grow_expansion(int elen, const double *e, double b, double *h)
{
	double q = b, hh;
	int hi = 0;
	for (int i = 0; i < elen; ++i) {
		two_sum(q, e[i], &q, &hh);
		if (hh != 0.0) h[hi++] = hh;
	}
	if (q != 0.0 || hi == 0) h[hi++] = q;
	return hi;
}

static int cross_exact(const double *a, const double *b, const double *c, const double *d)
{
	/* (b0 - a0)(d1 - c1) - (b1 - a1)(d0 - c0), expanded into eight products
	 * of input coordinates, each split exactly into two doubles. */
	const double f[8][2] = {
		{b[0], d[1]}, {-b[0], c[1]}, {-a[0], d[1]}, {a[0], c[1]},
		{-b[1], d[0]}, {b[1], c[0]}, {a[1], d[0]}, {-a[1], c[0]},
	};
	double e[16];
	int len = 0;
	for (int k = 0; k < 8; ++k) {
		double x, y;
		two_product(f[k][0], f[k][1], &x, &y);
		len = grow_expansion(len, e, y, e);
		len = grow_expansion(len, e, x, e);
	}
	/* The largest component carries the sign. */
	double top = e[len - 1];
	return (top > 0) - (top < 0);
}

int mkCross2_Sign(const double *a, const double *b, const double *c, const double *d)
{
	double t1 = (b[0] - a[0]) * (d[1] - c[1]);
	double t2 = (b[1] - a[1]) * (d[0] - c[0]);
	double det = t1 - t2;
	/* Each difference and each product carries a relative error of at most
	 * u = 2^-53, so |T_i - t_i| <= (3u + 3u^2 + u^3)|t_i|; the subtraction adds
	 * u |T1 - T2|. Hence |det - exact| <= 4.0001 u (|T1| + |T2|). The bound is
	 * taken with a factor 8 (4 DBL_EPSILON), which also covers the rounding
	 * of the bound's own evaluation. */
	double bound = 4.0 * DBL_EPSILON * (fabs(t1) + fabs(t2));
	if (det > bound) return 1;
	if (-det > bound) return -1;
	return cross_exact(a, b, c, d);
}

int mkOrient2(const double *a, const double *b, const double *c)
{
	return mkCross2_Sign(a, b, a, c);
}
