/* ensure.h - the smallest test harness: checks that name the failing
 * expression and keep going, and a summary line that CTest and people read. */
#ifndef MINK_ENSURE_H
#define MINK_ENSURE_H

#include <math.h>
#include <stdio.h>

static int mk_checks, mk_failures;

#define ENSURE(expr) do { ++mk_checks; if (!(expr)) { ++mk_failures; \
	fprintf(stderr, "%s:%d: ENSURE(%s) failed\n", __FILE__, __LINE__, #expr); } } while (0)

/* |a - b| <= tol, NaN never passes. */
#define ENSURE_NEAR(a, b, tol) do { double mk_a = (a), mk_b = (b), mk_t = (tol); ++mk_checks; \
	if (!(fabs(mk_a - mk_b) <= mk_t)) { ++mk_failures; \
	fprintf(stderr, "%s:%d: ENSURE_NEAR(%s, %s, %s) failed: %.17g vs %.17g (diff %.3g > %.3g)\n", \
		__FILE__, __LINE__, #a, #b, #tol, mk_a, mk_b, fabs(mk_a - mk_b), mk_t); } } while (0)

/* |actual - expected| <= tol |expected|, NaN never passes. */
#define ENSURE_REL(actual, expected, tol) ENSURE_NEAR(actual, expected, (tol) * fabs(expected))

/* a <= bound, NaN never passes. */
#define ENSURE_LE(a, bound) do { double mk_a = (a), mk_b = (bound); ++mk_checks; \
	if (!(mk_a <= mk_b)) { ++mk_failures; \
	fprintf(stderr, "%s:%d: ENSURE_LE(%s, %s) failed: %.6g > %.6g\n", __FILE__, __LINE__, #a, #bound, mk_a, mk_b); } \
	} while (0)

/* Print "<name>: N passed, M failed" and return the exit status. */
static inline int mk_summary(const char *name)
{
	printf("%s: %d passed, %d failed\n", name, mk_checks - mk_failures, mk_failures);
	return mk_failures ? 1 : 0;
}

/* A small deterministic generator for test draws (splitmix64). */
static inline double mk_test_unit(unsigned long long *s)
{
	unsigned long long z = (*s += 0x9E3779B97F4A7C15ULL);
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	z ^= z >> 31;
	return (double)(z >> 11) * 0x1.0p-53;
}
static inline double mk_test_uniform(unsigned long long *s, double a, double b) { return a + (b - a) * mk_test_unit(s); }

#endif
