/* reftest.h - the small test vocabulary shared by the reference tests:
 * ENSURE macros that name the failing expression, a seeded generator and
 * running statistics for the summary lines. */
#ifndef MINK_TEST_REFTEST_H
#define MINK_TEST_REFTEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>

/* Failures are counted, not fatal, so that one run shows every failing case
 * (printing stops after REF_MAX_PRINTED lines). main() returns
 * refTest_Result(). */
extern long refFailures;
#ifndef REF_MAX_PRINTED
#define REF_MAX_PRINTED 40
#endif

#define ENSURE(expr) do { \
	if (!(expr)) { \
		if (++refFailures <= REF_MAX_PRINTED) \
			fprintf(stderr, "%s:%d: ENSURE(%s) failed\n", __FILE__, __LINE__, #expr); \
	} \
} while (0)

/* expr, with a printf-style context naming the case. */
#define ENSURE_MSG(expr, ...) do { \
	if (!(expr)) { \
		if (++refFailures <= REF_MAX_PRINTED) { \
			fprintf(stderr, "%s:%d: ENSURE(%s) failed: ", __FILE__, __LINE__, #expr); \
			fprintf(stderr, __VA_ARGS__); \
			fputc('\n', stderr); \
		} \
	} \
} while (0)

/* a <= b, both printed; ctx is a printf format and its arguments that name
 * the case. A NaN in a or b fails. */
#define ENSURE_LE(a, b, ...) do { \
	double ensureA = (a), ensureB = (b); \
	if (!(ensureA <= ensureB)) { \
		if (++refFailures <= REF_MAX_PRINTED) { \
			fprintf(stderr, "%s:%d: ENSURE(%s <= %s) failed: %.3e > %.3e; ", \
				__FILE__, __LINE__, #a, #b, ensureA, ensureB); \
			fprintf(stderr, __VA_ARGS__); \
			fputc('\n', stderr); \
		} \
	} \
} while (0)

int refTest_Result(const char *name);

/* splitmix64: a fixed-seed generator, the same stream on every machine. */
typedef struct refRng { uint64_t state; } refRng;
uint64_t refRng_Next(refRng *r);
/* Uniform in [lo, hi). */
double refRng_Uniform(refRng *r, double lo, double hi);
/* A random unit vector of dimension dim (2 or 3), uniform in direction:
 * drawn in the unit ball by rejection, then normalised. */
void refRng_Unit(refRng *r, int dim, double *u);

/* Running maximum and mean of nonnegative figures. */
typedef struct refStat { double max, sum; long count; } refStat;
void refStat_Add(refStat *s, double v);
double refStat_Mean(const refStat *s);

#define REF_PI 3.14159265358979323846

/* Unit roundoff of double, 2^-53. */
#define REF_U 0x1p-53

#endif
