/* test_cspace_pair.c - the scene query's quick certificates' bounds of a
 * superquadric's norms (cspace/scenepair.h, mkSq_NormBounds) against the
 * shape module's closed forms (other code): for random shapes (exponents
 * over (0, 2), near both ends, exactly 1, and mixed sides of 1) and random
 * directions, lo <= h(y) <= hi for the support value h = mkShape3_SupportValue,
 * and for the gauge g the point y / lo lies on or outside the surface and
 * y / hi on or inside it (mkShape3_Implicit, which is 1 on the surface);
 * an ellipsoid's bounds equal mkSq_ShapeNorm's value to the bit. */
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
	printf("test_cspace_pair: %ld shapes and directions\n", checked);
	return mk_summary("test_cspace_pair");
}
