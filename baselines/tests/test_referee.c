/* test_referee.c - every method of the registry through the referee, on
 * random and extreme pairs, for both sets, in the dimension given as the
 * argument (2 or 3; CTest runs both, as test_referee2 and test_referee3).
 * The referee's verdicts are the assertions; the figures are printed.
 * Boundary points a method declares unordered (mkMethod_Indexing) are
 * judged by the referee with the error measure, having no normals.
 * 2D: closed forms at 512 points, sampled methods at 96 samples per body
 * (9216 pairwise sums). 3D: closed forms on a 16 x 16 grid, sampled methods
 * on an 8 x 8 grid per body (4096 pairwise sums: the exact hull check costs
 * sums times hull faces). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/error.h>
#include <mink/referee.h>
#include <mink/registry.h>

#include "cases.h"

static Case2 c2[16];
static Case3 c3[16];

/* Case k's name when method m takes it (then also run and checked, the
 * verdict in *v); NULL when m refuses the pair. */
static const char *run_case(const mkMethod *m, int dim, int k, mkSet set, int n, mkPointSet *out,
	const mkRefereeOptions *opt, mkVerdict *v)
{
	char msg[256];
	memset(v, 0, sizeof *v);
	if (dim == 2) {
		if (!mkMethod2_Accepts(m, c2[k].a, c2[k].b, set, msg, sizeof msg)) return NULL;
		ENSURE(m->run2(c2[k].a, c2[k].b, set, n, out) == MK_OK);
		ENSURE(mkReferee2_Check(m, c2[k].a, c2[k].b, set, n, out, opt, v) == MK_OK);
		return c2[k].name;
	}
	if (!mkMethod3_Accepts(m, c3[k].a, c3[k].b, set, msg, sizeof msg)) return NULL;
	ENSURE(m->run3(c3[k].a, c3[k].b, set, n, out) == MK_OK);
	ENSURE(mkReferee3_Check(m, c3[k].a, c3[k].b, set, n, out, opt, v) == MK_OK);
	return c3[k].name;
}

int main(int argc, char **argv)
{
	int dim = argc == 2 ? atoi(argv[1]) : 0;
	if (dim != 2 && dim != 3) {
		fprintf(stderr, "usage: test_referee 2|3\n");
		return 2;
	}
	int nc = dim == 2 ? cases2(c2, 2022) : cases3(c3, 2022);
	mkPointSet out = {0};
	/* The support check with 4096 dense samples per body (2D) or a 48 x 48
	 * dense grid per body (3D): the local bounds at each support point do
	 * the sharp work, the dense samples only back them up, so fewer than the
	 * defaults (8192, 128 x 128) keep the test quick. */
	mkRefereeOptions opt = {dim == 2 ? 4096 : 48, 0, 0, 0};
	const double allowance = MK_REFEREE_ULPS * DBL_EPSILON / 2; /* of the scale */
	for (int i = 0; i < mkRegistry_Count(); ++i) {
		const mkMethod *m = mkRegistry_At(i);
		if (!(m->flags & (dim == 2 ? MK_METHOD_2D : MK_METHOD_3D))) continue;
		int sampled = !!(m->flags & MK_METHOD_SAMPLED), runs = 0, exact = 0;
		int n = dim == 2 ? (sampled ? 96 : 512) : (sampled ? 8 : 16);
		double depth = -HUGE_VAL, excess = -HUGE_VAL, outside = 0;
		/* An approximate tier is held to the accuracy it states
		 * (mkMethod_Tolerance, relative to the scale) instead of the rounding
		 * allowance. */
		mkRefereeOptions mopt = opt;
		if (m->flags & MK_METHOD_APPROX)
			mopt.tol_factor = mkMethod_Tolerance(m) / allowance;
		for (int k = 0; k < nc; ++k)
			for (int set = 0; set < 2; ++set) {
				mkVerdict v;
				const char *name = run_case(m, dim, k, (mkSet)set, n, &out, &mopt, &v);
				if (!name) continue;
				ENSURE(v.pass);
				if (!v.pass) fprintf(stderr, "  %s, %s, %s: %s\n", m->name, name, set ? "plus" : "contact", v.message);
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
					depth = fmax(depth, v.depth / v.extent);
					excess = fmax(excess, v.excess / v.extent);
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
	return mk_summary(dim == 2 ? "test_referee2" : "test_referee3");
}
