/* ensure.h - the checks of the fitting tests: each failure names the
 * expression, the values and the line, and the test goes on, so that one run
 * lists every failure; ENSURE_DONE() gives the exit status. */
#ifndef MK_FIT_ENSURE_H
#define MK_FIT_ENSURE_H

#include <math.h>
#include <stdio.h>

static int ensureFailures = 0;

#define ENSURE(expr) \
	do { \
		if (!(expr)) { \
			fprintf(stderr, "%s:%d: ENSURE(%s) failed\n", __FILE__, __LINE__, #expr); \
			++ensureFailures; \
		} \
	} while (0)

/* |actual - expected| <= tol, NaN failing */
#define ENSURE_NEAR(actual, expected, tol) \
	do { \
		double ensureA = (actual), ensureE = (expected), ensureT = (tol); \
		if (!(fabs(ensureA - ensureE) <= ensureT)) { \
			fprintf(stderr, "%s:%d: ENSURE_NEAR(%s, %s, %s) failed: %.17g vs %.17g (diff %.3g)\n", \
				__FILE__, __LINE__, #actual, #expected, #tol, ensureA, ensureE, fabs(ensureA - ensureE)); \
			++ensureFailures; \
		} \
	} while (0)

/* relative: |actual - expected| <= tol |expected| */
#define ENSURE_REL(actual, expected, tol) ENSURE_NEAR(actual, expected, (tol) * fabs(expected))

#define ENSURE_DONE() \
	(ensureFailures == 0 ? (printf("ok\n"), 0) : (fprintf(stderr, "%d check(s) failed\n", ensureFailures), 1))

#endif
