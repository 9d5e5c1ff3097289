/* test_predicates.c - the suite's exact orientation test against hand-worked
 * signs and against CGAL's exact predicate (an independent implementation),
 * on inputs built to defeat plain floating point. */
#include <float.h>
#include <math.h>

#include <mink/baselines.h>

#include "ensure.h"
#include "referee_cgal.h"

int main(void)
{
	unsigned long long seed = 42;

	/* Hand-worked: unit triangle, both orientations, a collinear triple, and
	 * points far apart in magnitude. */
	double o[2] = {0, 0}, ex[2] = {1, 0}, ey[2] = {0, 1}, d[2] = {2, 2}, h[2] = {0.5, 0.5};
	ENSURE(mkOrient2(o, ex, ey) == 1);
	ENSURE(mkOrient2(o, ey, ex) == -1);
	ENSURE(mkOrient2(o, h, d) == 0);
	double big[2] = {1e150, 1e150}, tiny[2] = {1e-140, 1e-140};
	ENSURE(mkOrient2(o, tiny, big) == 0);
	/* (b - a) x (d - c) with a parallel pair and an antiparallel pair. */
	ENSURE(mkCross2_Sign(o, ex, ey, d) == 1);
	ENSURE(mkCross2_Sign(o, d, h, o) == 0);

	/* Shewchuk's classic: points on the line y = x near (0.5, 0.5), moved by
	 * a few ulps. Naive evaluation gets many of these wrong; the exact sign
	 * is that of (i - j) for c = (0.5 + i u, 0.5 + j u) against the line
	 * through (12, 12) and (24, 24). */
	int wrong_naive = 0;
	for (int i = -40; i <= 40; ++i)
		for (int j = -40; j <= 40; ++j) {
			double a[2] = {12, 12}, b[2] = {24, 24};
			double c[2] = {0.5 + i * DBL_EPSILON, 0.5 + j * DBL_EPSILON};
			int want = (j > i) - (j < i); /* above the line y = x: left turn */
			ENSURE(mkOrient2(a, b, c) == want);
			ENSURE(mkRefereeCgal2_Orient(a, b, c) == want);
			double naive = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
			if (((naive > 0) - (naive < 0)) != want) ++wrong_naive;
		}
	printf("naive floating point got %d of %d near-collinear signs wrong\n", wrong_naive, 81 * 81);
	ENSURE(wrong_naive > 0); /* the inputs do exercise the exact path */

	/* Random near-degenerate triples (c on the line ab, rounded, nudged by a
	 * few ulps) and random edge pairs: the suite's sign equals CGAL's. */
	int disagree = 0;
	for (int k = 0; k < 200000; ++k) {
		double a[2] = {mk_test_uniform(&seed, -1e3, 1e3), mk_test_uniform(&seed, -1e3, 1e3)};
		double b[2] = {mk_test_uniform(&seed, -1e3, 1e3), mk_test_uniform(&seed, -1e3, 1e3)};
		double t = mk_test_uniform(&seed, -2, 3);
		double c[2] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
		int nud = (int)(mk_test_unit(&seed) * 7) - 3;
		c[1] = nud > 0 ? nextafter(c[1], HUGE_VAL) : nud < 0 ? nextafter(c[1], -HUGE_VAL) : c[1];
		if (mkOrient2(a, b, c) != mkRefereeCgal2_Orient(a, b, c)) ++disagree;
		/* (b - a) x (d - c) = orient(a, b, a + d - c) only in exact arithmetic;
		 * check the four-point form against CGAL with c = a, which makes them
		 * equal. */
		if (mkCross2_Sign(a, b, a, c) != mkRefereeCgal2_Orient(a, b, c)) ++disagree;
	}
	ENSURE(disagree == 0);

	/* The four-point form on nearly parallel edges. With coordinates on a
	 * 2^-30 grid in [-1, 1] and a direction scaled by a multiple of 2^-10,
	 * every difference and sum below is exact, so (b - a) x (d - c) equals
	 * orient(a, b, a + (d - c)) exactly and CGAL can referee it. */
	disagree = 0;
	for (int k = 0; k < 50000; ++k) {
		double g = 0x1.0p-30;
		double a[2] = {floor(mk_test_uniform(&seed, -1, 1) / g) * g, floor(mk_test_uniform(&seed, -1, 1) / g) * g};
		double b[2] = {floor(mk_test_uniform(&seed, -1, 1) / g) * g, floor(mk_test_uniform(&seed, -1, 1) / g) * g};
		double lam = floor(mk_test_uniform(&seed, -4, 4) * 1024) / 1024;
		double dx = lam * (b[0] - a[0]), dy = lam * (b[1] - a[1]); /* parallel, exact */
		int nud = (int)(mk_test_unit(&seed) * 3) - 1;
		dy += nud * g * 0x1.0p-18; /* 2^-48: still exact, within the filter's doubt */
		double c[2] = {floor(mk_test_uniform(&seed, -1, 1) / g) * g, floor(mk_test_uniform(&seed, -1, 1) / g) * g};
		double dd[2] = {c[0] + dx, c[1] + dy};
		double ad[2] = {a[0] + dx, a[1] + dy};
		if (mkCross2_Sign(a, b, c, dd) != mkRefereeCgal2_Orient(a, b, ad)) ++disagree;
	}
	ENSURE(disagree == 0);
	return mk_summary("test_predicates");
}
