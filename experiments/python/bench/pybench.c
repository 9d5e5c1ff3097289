/* pybench.c - the C side of bench/bench_sum.py: one batch call of the
 * closed forms timed in C (no Python in the timed region), on the caller's
 * arrays, for the ratio of mink.sum's throughput to the C call's. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <time.h>

#include <mink/mink.h>

/* The seconds one mkSum2_Batch (dim 2) or mkSum3_Batch (dim 3) call takes
 * with default options (contact space, gradient form, AUTO kernel) on the
 * bodies of two SPEC strings; u and x hold dim rows of n values each.
 * -1 on a bad SPEC or a failed call. */
MK_API double mkPyBench_Sum(int dim, const char *spec1, const char *spec2, const double *u, double *x, int n);

double mkPyBench_Sum(int dim, const char *spec1, const char *spec2, const double *u, double *x, int n)
{
	mkSpec s1, s2;
	if (mkSpec_Parse(spec1, dim, "body1", &s1, NULL, 0) != MK_OK || mkSpec_Parse(spec2, dim, "body2", &s2, NULL, 0) != MK_OK)
		return -1;
	mkSumOptions opt = mkSumOptions_Default();
	struct timespec t0, t1;
	clock_gettime(CLOCK_MONOTONIC, &t0);
	mkResult r = dim == 2 ? mkSum2_Batch(s1.body2, s2.body2, &opt, u, u + n, n, x, x + n, NULL, NULL)
		: mkSum3_Batch(s1.body3, s2.body3, &opt, u, u + n, u + 2 * (long)n, n, x, x + n, x + 2 * (long)n, NULL, NULL, NULL);
	clock_gettime(CLOCK_MONOTONIC, &t1);
	if (r != MK_OK) return -1;
	return (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
}
