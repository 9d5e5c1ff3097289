/* test_referee3.c - every 3D method of the registry through the referee, on
 * random and extreme pairs, for both sets. The referee's verdicts are the
 * assertions; the figures are printed. Closed forms run on a 16 x 16 grid,
 * sampled methods on an 8 x 8 grid per body (4096 pairwise sums: the exact
 * hull check costs sums times hull faces). */
#include <float.h>
#include <math.h>
#include <string.h>

#include <mink/referee.h>
#include <mink/registry.h>

#include "cases.h"

int main(void)
{
	Case3 c[16];
	int nc = cases3(c, 2022);
	mkPointSet out = {0};
	/* The support check with a 48 x 48 dense grid per body: the local
	 * bounds at each support point do the sharp work, the dense samples only
	 * back them up, so fewer than the default 128 x 128 keep the test quick. */
	mkRefereeOptions opt = {48, 0, 0};
	const double allowance = MK_REFEREE_ULPS * DBL_EPSILON / 2; /* of the scale */
	for (int i = 0; i < mkRegistry_Count(); ++i) {
		const mkMethod *m = mkRegistry_At(i);
		if (!(m->flags & MK_METHOD_3D)) continue;
		int sampled = !!(m->flags & MK_METHOD_SAMPLED), runs = 0, exact = 0;
		double depth = -HUGE_VAL, excess = -HUGE_VAL, outside = 0;
		for (int k = 0; k < nc; ++k)
			for (int set = 0; set < 2; ++set) {
				char msg[256];
				if (!mkMethod_Accepts3(m, c[k].a, c[k].b, (mkSet)set, msg, sizeof msg)) continue;
				int n = sampled ? 8 : 16;
				mkVerdict v;
				/* An approximate tier is held to the accuracy it states
				 * (mkMethod_Tolerance, relative to the scale) instead of the
				 * rounding allowance. */
				mkRefereeOptions mopt = opt;
				if (m->flags & MK_METHOD_APPROX) mopt.tol_factor = mkMethod_Tolerance(m) / allowance;
				ENSURE(m->run3(c[k].a, c[k].b, (mkSet)set, n, &out) == MK_OK);
				ENSURE(mkReferee_Check3(m, c[k].a, c[k].b, (mkSet)set, n, &out, &mopt, &v) == MK_OK);
				ENSURE(v.pass);
				if (!v.pass) fprintf(stderr, "  %s, %s, %s: %s\n", m->name, c[k].name, set ? "plus" : "contact", v.message);
				++runs;
				if (sampled) {
					exact += v.extreme;
					outside = fmax(outside, v.outside_max / (v.outside_tol / MK_REFEREE_HULL_ULPS));
					/* The CGAL hulls decide exactly: the extreme points, no
					 * allowance. Edge sorting rounds one addition per vertex:
					 * within 4 units of roundoff of the largest coordinate. */
					if (!strncmp(m->name, "hull-cgal", 9)) ENSURE(v.extreme);
					if (!strcmp(m->name, "edge-sort")) ENSURE_LE(v.outside_max, 4 * v.outside_tol / MK_REFEREE_HULL_ULPS);
				} else {
					depth = fmax(depth, v.depth / v.scale);
					excess = fmax(excess, v.excess / v.scale);
				}
			}
		if (sampled)
			printf("%-16s %2d runs: %d exactly the extreme points; worst outside %.3g u max|coord|\n", m->name, runs,
				exact, outside);
		else
			printf("%-16s %2d runs: worst depth %.3g, worst excess %.3g (of the scale; allowance %.3g)\n", m->name,
				runs, depth, excess, (m->flags & MK_METHOD_APPROX) ? mkMethod_Tolerance(m) : allowance);
		ENSURE(runs > 0);
	}
	mkPointSet_Free(&out);
	return mk_summary("test_referee3");
}
