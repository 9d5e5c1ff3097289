/* ref_base2.c - the inline base-2 functions of core/src/base/base2.h against
 * 256-bit MPFR, and their tables against the generator.
 *
 *  - mkExp2(x): within 0.52 ulp of 2^x for normal results (x in [-1022, 1023)),
 *    within 1 ulp for subnormal ones, exact at integers, 0 below -1100 and
 *    at -inf, NaN for NaN;
 *  - mkSoftplus2(x, 2^x): within 2.2e-16 absolute of log2(1 + 2^x) on
 *    [-60, 0], on a fine grid, at every segment boundary and its
 *    neighbours, across the switch to the series at -16, at -0 and 0;
 *  - the tables: base2_tables (core/reference/tools) run again writes a file
 *    identical to the committed core/src/base/base2_tables.h (argv[1] is the
 *    generator, argv[2] the committed file).
 * The bounds are what the functions' derivations promise (base2.h); the
 * test prints the largest errors it met and, for comparison, glibc's exp2
 * and log2(1 + exp2(x)) on the same points. */
#define _POSIX_C_SOURCE 200809L
#include "reftest.h"
#include "base/base2.h"

#include <mpfr.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static mpfr_t X, R, LN2;

/* |error| of v against 2^x in ulps of the correctly rounded result */
static double exp2Ulps(double x, double v)
{
	mpfr_set_d(X, x, MPFR_RNDN);
	mpfr_exp2(R, X, MPFR_RNDN);
	double ref = mpfr_get_d(R, MPFR_RNDN);
	double ulp = ref == 0.0 ? 0x1p-1074 : fmax(ldexp(1.0, ilogb(ref) - 52), 0x1p-1074);
	mpfr_sub_d(R, R, v, MPFR_RNDN);
	mpfr_div_d(R, R, ulp, MPFR_RNDN); /* in MPFR: the difference may be below the double range */
	return fabs(mpfr_get_d(R, MPFR_RNDN));
}

/* |error| of v against log2(1 + 2^x) */
static double softplusErr(double x, double v)
{
	mpfr_set_d(X, x, MPFR_RNDN);
	mpfr_exp2(R, X, MPFR_RNDN);
	mpfr_log1p(R, R, MPFR_RNDN);
	mpfr_div(R, R, LN2, MPFR_RNDN);
	mpfr_sub_d(R, R, v, MPFR_RNDN);
	return fabs(mpfr_get_d(R, MPFR_RNDN));
}

static void checkExp2(void)
{
	refStat normal = { 0 }, sub = { 0 }, glibc = { 0 };
	refRng rng = { 2022 };
	for (double x0 = -1100.0; x0 < 1023.0; x0 += 1.0 / 256.0) {
		double x = x0 + refRng_Uniform(&rng, 0.0, 1.0 / 256.0);
		double e = exp2Ulps(x, mkExp2(x));
		if (x >= -1022.0) {
			refStat_Add(&normal, e);
			refStat_Add(&glibc, exp2Ulps(x, exp2(x)));
			ENSURE_LE(e, 0.52, "mkExp2(%a)", x);
		} else {
			refStat_Add(&sub, e);
			ENSURE_LE(e, 1.0, "mkExp2(%a), subnormal", x);
		}
	}
	/* the rounding boundaries of the table index: x = (k +- 1/2) / 128 and
	 * their neighbours */
	for (int k = -4000; k <= 4000; ++k) {
		double b = (k + 0.5) / 128.0;
		double xs[3] = { nextafter(b, -INFINITY), b, nextafter(b, INFINITY) };
		for (int i = 0; i < 3; ++i)
			ENSURE_LE(exp2Ulps(xs[i], mkExp2(xs[i])), 0.52, "mkExp2(%a)", xs[i]);
	}
	for (int k = -1074; k < 1024; ++k)
		ENSURE_MSG(mkExp2((double)k) == ldexp(1.0, k), "mkExp2(%d) = %a", k, mkExp2((double)k));
	ENSURE(mkExp2(-INFINITY) == 0.0);
	ENSURE(mkExp2(-1200.0) == 0.0);
	ENSURE(isnan(mkExp2(NAN)));
	ENSURE(mkExp2(-0.0) == 1.0);
	printf("mkExp2: normal results %ld, largest error %.3f ulp (glibc exp2 %.3f); subnormal %ld, %.3f ulp\n",
		normal.count, normal.max, glibc.max, sub.count, sub.max);
}

static void checkSoftplus(void)
{
	refStat ours = { 0 }, glibc = { 0 };
	refRng rng = { 2023 };
	const double bound = 2.2e-16;
	for (double x0 = 0.0; x0 > -60.0; x0 -= 1.0 / 4096.0) {
		double x = fmin(0.0, x0 - refRng_Uniform(&rng, 0.0, 1.0 / 4096.0));
		double t = exp2(x), e = softplusErr(x, mkSoftplus2(x, t));
		refStat_Add(&ours, e);
		refStat_Add(&glibc, softplusErr(x, log2(1.0 + t)));
		ENSURE_LE(e, bound, "mkSoftplus2(%a)", x);
	}
	/* every segment boundary (j + 1/2) / W and its neighbours, and the
	 * switch to the series at -MK_SP2_X */
	for (int j = 0; j <= MK_SP2_W * MK_SP2_X; ++j) {
		double b = -(j + 0.5) / MK_SP2_W;
		double xs[5] = { nextafter(b, -INFINITY), b, nextafter(b, INFINITY), -(double)j / MK_SP2_W,
			nextafter(-(double)j / MK_SP2_W, -INFINITY) };
		for (int i = 0; i < 5; ++i) {
			double e = softplusErr(xs[i], mkSoftplus2(xs[i], exp2(xs[i])));
			refStat_Add(&ours, e);
			ENSURE_LE(e, bound, "mkSoftplus2(%a)", xs[i]);
		}
	}
	double edge[4] = { -MK_SP2_X, nextafter(-MK_SP2_X, 0.0), nextafter(-MK_SP2_X, -INFINITY), -0x1p-1074 };
	for (int i = 0; i < 4; ++i)
		ENSURE_LE(softplusErr(edge[i], mkSoftplus2(edge[i], exp2(edge[i]))), bound, "mkSoftplus2(%a)", edge[i]);
	ENSURE(mkSoftplus2(0.0, 1.0) == 1.0 && mkSoftplus2(-0.0, 1.0) == 1.0);
	ENSURE(mkSoftplus2(-INFINITY, 0.0) == 0.0);
	ENSURE(isnan(mkSoftplus2(NAN, NAN)));
	printf("mkSoftplus2: %ld points on [-60, 0], largest error %.3e absolute (glibc log2(1 + exp2(x)) %.3e)\n",
		ours.count, ours.max, glibc.max);
}

/* the committed tables are the generator's output, byte for byte */
static void checkTables(const char *generator, const char *committed)
{
	char out[] = "/tmp/mink_base2_tables_XXXXXX";
	int fd = mkstemp(out);
	ENSURE_MSG(fd >= 0, "mkstemp");
	if (fd < 0)
		return;
	close(fd);
	char cmd[4096];
	snprintf(cmd, sizeof cmd, "'%s' '%s'", generator, out);
	ENSURE_MSG(system(cmd) == 0, "%s", cmd);
	FILE *a = fopen(out, "rb"), *b = fopen(committed, "rb");
	ENSURE_MSG(a && b, "open %s and %s", out, committed);
	if (a && b) {
		long line = 1;
		int ca, cb;
		do {
			ca = fgetc(a);
			cb = fgetc(b);
			line += ca == '\n';
		} while (ca == cb && ca != EOF);
		ENSURE_MSG(ca == cb, "%s differs from the generator's output at line %ld: regenerate it with base2_tables",
			committed, line);
		if (ca == cb)
			printf("tables: %s is the generator's output\n", committed);
	}
	if (a)
		fclose(a);
	if (b)
		fclose(b);
	remove(out);
}

int main(int argc, char **argv)
{
	if (argc != 3) {
		fprintf(stderr, "usage: ref_base2 GENERATOR COMMITTED_TABLES\n");
		return 2;
	}
	mpfr_inits2(256, X, R, LN2, (mpfr_ptr)0);
	mpfr_const_log2(LN2, MPFR_RNDN);
	checkExp2();
	checkSoftplus();
	checkTables(argv[1], argv[2]);
	mpfr_clears(X, R, LN2, (mpfr_ptr)0);
	mpfr_free_cache();
	return refTest_Result("ref_base2");
}
