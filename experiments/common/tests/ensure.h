/* ensure.h - the check macros of the mink_exp tests: each failure names the
 * expression, the file and the line, and the test goes on so that one run
 * shows every failure; main returns mkTestFailures() != 0. */
#ifndef MINK_EXP_ENSURE_H
#define MINK_EXP_ENSURE_H

#include <math.h>
#include <stdio.h>

static int mkTestFailureCount = 0;

#define ENSURE(expr) \
	do { \
		if (!(expr)) { \
			fprintf(stderr, "%s:%d: ENSURE(%s) failed\n", __FILE__, __LINE__, #expr); \
			++mkTestFailureCount; \
		} \
	} while (0)

#define ENSURE_NEAR(a, b, tol) \
	do { \
		double ensure_a = (a), ensure_b = (b), ensure_t = (tol); \
		if (!(fabs(ensure_a - ensure_b) <= ensure_t)) { \
			fprintf(stderr, "%s:%d: ENSURE_NEAR(%s, %s, %s) failed: %.17g vs %.17g\n", \
				__FILE__, __LINE__, #a, #b, #tol, ensure_a, ensure_b); \
			++mkTestFailureCount; \
		} \
	} while (0)

static int mkTestFailures(void)
{
	if (mkTestFailureCount)
		fprintf(stderr, "%d check(s) failed\n", mkTestFailureCount);
	return mkTestFailureCount;
}

#endif
