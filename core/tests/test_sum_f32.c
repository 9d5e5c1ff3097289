/* test_sum_f32.c - the single-precision tier of the batch closed forms
 * (mkSumOptions.precision = MK_PRECISION_F32): its vector kernels against
 * its scalar reference, hand-worked circles, the tails of a batch, every
 * output finite at the corners of the valid ranges, and the options.
 * Its accuracy against 256-bit MPFR is asserted in tests/reference
 * (core.ref.sum2.f32.*, core.ref.sum3.f32.*). */
#include <stdlib.h>
#include <string.h>

#include <mink/mink.h>

#include "ensure.h"

#define MK_TEST_PRECISION MK_PRECISION_F32
#include "sum_tier.h"

/* Two circles (the ellipse kernel) and the same circles as superellipses of
 * eps = 1 + 2^-20 (the general kernel, whose exact answer differs from the
 * circle's by less than 1e-6 of the radius): the contact space is the circle
 * of radius 5 about t1 and the kissing point lies at 2/5 of the way. Each
 * point is a few float operations on numbers of size ~100 (|t2| enters the
 * plus set only): 2e-5 absolute is 200 float ulps of the largest magnitude
 * and 4e-6 of the problem's scale (~105). */
static void test_circles(void)
{
	check_circles(0x1p-20, 2e-5, 1);
}

/* The vector builds against the scalar build of the same tier, on the
 * paper's validation draws. They differ only in the elementary functions
 * (SLEEF's 1-ulp float exp and 3.5-ulp float log against the C library's
 * correctly rounded expf/logf) and in the rounding of a few mixed
 * double/float products of the scalar build: a few float ulps per call,
 * which the powers' exponents (up to 2/(2 - eps) = 20 here) can amplify in
 * the worst direction. The tier states 1e-6 of the scale against the exact
 * answer; against each other we allow 2e-6 (both within 1e-6 of the exact
 * point where it is well-conditioned) and report the largest seen (3.5e-7). */
static void test_agreement(void)
{
	unsigned long long seed = 11;
	double worst = 0.0;
	int n = 1000;
	mkSample2_Angles(n, ux, uy);
	for (int trial = 0; trial < 20; ++trial) {
		mkBody2 b[2];
		for (int j = 0; j < 2; ++j) {
			mkShape2 s = {mk_test_uniform(&seed, 0.5, 10), mk_test_uniform(&seed, 0.5, 10), mk_test_uniform(&seed, 0.1, 1.9)};
			mkMat2 M = mkMat2_Mul(mkMat2_Rotation(2 * MK_PI * mk_test_unit(&seed)), mkMat2_Shear(mk_test_uniform(&seed, -2, 2)));
			b[j] = mkBody2_Make(s, M, (mkVec2){mk_test_uniform(&seed, -10, 10), mk_test_uniform(&seed, -10, 10)});
		}
		double scale = 30 + 3 * (b[0].shape.a + b[0].shape.b + b[1].shape.a + b[1].shape.b);
		for (int param = 0; param < 2; ++param)
			for (int form = 0; form < 2; ++form) {
				ENSURE(run2(b[0], b[1], MK_SET_PLUS, form, param, MK_IMPL_SCALAR, n, 0) == MK_OK);
				for (int ii = 1; ii < 3; ++ii) {
					if (!mkImpl_Available(impls[ii])) continue;
					ENSURE(run2(b[0], b[1], MK_SET_PLUS, form, param, impls[ii], n, 1) == MK_OK);
					for (int i = 0; i < n; ++i)
						for (int c = 0; c < 4; ++c) {
							double d = fabs(o[1][c][i] - o[0][c][i]) / scale;
							if (d > worst) worst = d;
							ENSURE_LE(d, 2e-6);
						}
				}
			}
	}
	int g = 30;
	mkSample3_Grid(g, ux, uy, uz);
	n = g * g;
	for (int trial = 0; trial < 20; ++trial) {
		mkBody3 b[2];
		double scale = draw_pair3(&seed, b);
		for (int param = 0; param < 2; ++param)
			for (int form = 0; form < 2; ++form) {
				ENSURE(run3(b[0], b[1], MK_SET_CONTACT, form, param, MK_IMPL_SCALAR, n, 0) == MK_OK);
				for (int ii = 1; ii < 3; ++ii) {
					if (!mkImpl_Available(impls[ii])) continue;
					ENSURE(run3(b[0], b[1], MK_SET_CONTACT, form, param, impls[ii], n, 1) == MK_OK);
					for (int i = 0; i < n; ++i)
						for (int c = 0; c < 6; ++c) {
							double d = fabs(o[1][c][i] - o[0][c][i]) / scale;
							if (d > worst) worst = d;
							ENSURE_LE(d, 2e-6);
						}
				}
			}
	}
	printf("f32 agreement: vector vs scalar max %.3g (relative to size)\n", worst);
}

/* Every output finite at the corners of the valid ranges (mink/body.h):
 * exponents at both ends, semi-axes 1e-9 and 1e9, map entries up to 1e9 with
 * condition numbers near 1e12, positions 1e12; parameter vectors on the axes,
 * 1e-30 off them, and of length 1e-300 and 1e300. */
static void test_extremes(void)
{
	static const double eps[] = {MK_EPS_MIN, 1e-3, 0.5, 1.0, 1.5, 2.0 - 1e-3, MK_EPS_MAX};
	const int ne = (int)(sizeof eps / sizeof eps[0]);
	static const double axis[][2] = {{1e-9, 1e9}, {1e9, 1e9}, {1e-9, 1e-9}, {1.0, 1e4}};
	mkMat2 maps[3] = {mkMat2_Identity(), {{{1e9, 1e9 - 1e-3}, {1e9 - 1e-3, 1e9}}}, mkMat2_Mul(mkMat2_Rotation(0.3), mkMat2_Shear(10))};
	mkVec2 pos[2] = {{0, 0}, {1e12, -1e12}};
	long bad = 0, total = 0;
	int n = 0;
	const double tiny[] = {0.0, 1e-30, -1e-30, 1e-300};
	for (int t = 0; t < 4; ++t) {
		ux[n] = 1.0; uy[n] = tiny[t]; ++n;
		ux[n] = tiny[t]; uy[n] = -1.0; ++n;
	}
	mkSample2_Angles(40, ux + n, uy + n);
	for (int k = 0; k < 40; ++k) { ux[n + k] *= (k % 2 ? 1e300 : 1e-300); uy[n + k] *= (k % 2 ? 1e300 : 1e-300); }
	n += 40;
	for (int i = 0; i < ne; ++i)
		for (int j = 0; j < ne; ++j)
			for (int a = 0; a < 4; ++a)
				for (int m = 0; m < 3; ++m) {
					mkBody2 b1 = mkBody2_Make((mkShape2){axis[a][0], axis[a][1], eps[i]}, maps[m], pos[m % 2]);
					mkBody2 b2 = mkBody2_Make((mkShape2){axis[3 - a][1], axis[3 - a][0], eps[j]}, maps[(m + 1) % 3], pos[(m + 1) % 2]);
					if (!mkBody2_IsValid(b1, "b1", NULL, 0) || !mkBody2_IsValid(b2, "b2", NULL, 0)) continue;
					for (int ii = 0; ii < 3; ++ii) {
						if (!mkImpl_Available(impls[ii])) continue;
						for (int form = 0; form < 2; ++form)
							for (int param = 0; param < 2; ++param)
								for (int set = 0; set < 2; ++set) {
									ENSURE(run2(b1, b2, set, form, param, impls[ii], n, 0) == MK_OK);
									for (int k = 0; k < n; ++k)
										for (int c = 0; c < 4; ++c) { ++total; bad += !isfinite(o[0][c][k]); }
								}
					}
				}
	int g = 13;
	mkSample3_Grid(g, ux, uy, uz);
	for (int i = 0; i < ne; ++i)
		for (int j = 0; j < ne; ++j)
			for (int a = 0; a < 4; ++a) {
				mkBody3 c1 = mkBody3_Make((mkShape3){axis[a][0], axis[a][1], 30.0, eps[i], eps[ne - 1 - j]},
					mkMat3_FromQuat(0.3, 0.1, -0.7, 0.2), (mkVec3){a % 2 ? 1e12 : 0, 0, 0});
				mkBody3 c2 = mkBody3_Make((mkShape3){axis[3 - a][1], 1e-2, axis[3 - a][0], eps[j], eps[i]},
					mkMat3_FromQuat(-0.5, 0.5, 0.1, 0.9), (mkVec3){0, 0, a % 2 ? -1e12 : 0});
				for (int ii = 0; ii < 3; ++ii) {
					if (!mkImpl_Available(impls[ii])) continue;
					for (int form = 0; form < 2; ++form)
						for (int param = 0; param < 2; ++param) {
							ENSURE(run3(c1, c2, MK_SET_CONTACT, form, param, impls[ii], g * g, 0) == MK_OK);
							for (int q = 0; q < g * g; ++q)
								for (int c = 0; c < 6; ++c) { ++total; bad += !isfinite(o[0][c][q]); }
						}
				}
			}
	printf("f32 extremes: %ld non-finite values of %ld\n", bad, total);
	ENSURE(total > 0);
	ENSURE(bad == 0);
}

/* Tails and lane padding: a point's value does not depend on the batch it
 * is in (the same lane arithmetic), so every prefix of a batch gives the
 * full batch's values bit for bit, and nothing is written past n. */
static void test_tails(void)
{
	mkBody3 b1 = mkBody3_Make((mkShape3){2, 1, 3, 0.4, 1.3}, mkMat3_FromQuat(0.2, 0.3, 0.1, 0.9), (mkVec3){0, 0, 0});
	mkBody3 b2 = mkBody3_Make((mkShape3){1, 3, 2, 1.6, 0.2}, mkMat3_Identity(), (mkVec3){1, 0, 0});
	mkSample3_Grid(9, ux, uy, uz);
	for (int ii = 0; ii < 3; ++ii) {
		if (!mkImpl_Available(impls[ii])) continue;
		ENSURE(run3(b1, b2, MK_SET_CONTACT, MK_FORM_GRADIENT, MK_PARAM_SURFACE, impls[ii], 81, 0) == MK_OK);
		for (int n = 0; n <= 70; ++n) {
			for (int c = 0; c < 6; ++c)
				for (int k = 0; k < 81; ++k) o[1][c][k] = -12345.0;
			ENSURE(run3(b1, b2, MK_SET_CONTACT, MK_FORM_GRADIENT, MK_PARAM_SURFACE, impls[ii], n, 1) == MK_OK);
			for (int c = 0; c < 6; ++c) {
				for (int k = 0; k < n; ++k) ENSURE(o[1][c][k] == o[0][c][k]);
				ENSURE(o[1][c][n] == -12345.0);
			}
		}
	}
}

/* Options: names, a bad precision, the domain and the fallback outside it,
 * and the paper's form (double only). */
static void test_options(void)
{
	mkBody2 b = mkBody2_Make((mkShape2){1, 2, 0.5}, mkMat2_Identity(), (mkVec2){0, 0});
	mkSumOptions opt = mkSumOptions_Default();
	ENSURE(opt.precision == MK_PRECISION_DOUBLE);
	ENSURE(strcmp(mkPrecision_Name(MK_PRECISION_F32), "f32") == 0);
	ENSURE(strcmp(mkPrecision_Name(MK_PRECISION_DOUBLE), "double") == 0);
	ENSURE(mkPrecision_Parse("f32") == MK_PRECISION_F32 && mkPrecision_Parse("half") == -1);
	mkSample2_Angles(3, ux, uy);
	opt.precision = (mkPrecision)7;
	ENSURE(mkSum2_Batch(b, b, &opt, ux, uy, 3, o[0][0], o[0][1], NULL, NULL) == MK_ERR_ARGUMENT);
	ENSURE(!mkSum2_TierHolds(b, b, &opt));
	opt.precision = MK_PRECISION_F32;
	ENSURE(mkSum2_TierHolds(b, b, &opt));

	/* Outside the domain (axis ratio 1e8; a map of condition 1e7) the call
	 * runs the double kernel: the very same bits as a double call. */
	mkBody2 thin = mkBody2_Make((mkShape2){1e4, 1e-4, 0.7}, mkMat2_Rotation(0.4), (mkVec2){1, 2});
	mkMat2 skew = {{{1.0, 0.0}, {0.0, 1e-7}}};
	mkBody2 flat = mkBody2_Make((mkShape2){2, 3, 1.3}, mkMat2_Mul(mkMat2_Rotation(0.3), skew), (mkVec2){0, 0});
	mkBody2 pairs[2][2] = {{thin, b}, {b, flat}};
	for (int k = 0; k < 2; ++k) {
		mkSumOptions od = mkSumOptions_Default(), of = od;
		of.precision = MK_PRECISION_F32;
		ENSURE(!mkSum2_TierHolds(pairs[k][0], pairs[k][1], &of));
		ENSURE(mkSum2_TierHolds(pairs[k][0], pairs[k][1], &od));
		int n = 37;
		mkSample2_Angles(n, ux, uy);
		ENSURE(mkSum2_Batch(pairs[k][0], pairs[k][1], &od, ux, uy, n, o[0][0], o[0][1], NULL, NULL) == MK_OK);
		ENSURE(mkSum2_Batch(pairs[k][0], pairs[k][1], &of, ux, uy, n, o[1][0], o[1][1], NULL, NULL) == MK_OK);
		ENSURE(memcmp(o[0][0], o[1][0], (size_t)n * sizeof(double)) == 0);
		ENSURE(memcmp(o[0][1], o[1][1], (size_t)n * sizeof(double)) == 0);
	}
	mkBody3 slab = mkBody3_Make((mkShape3){1e4, 1, 1e-3, 0.5, 1.5}, mkMat3_Identity(), (mkVec3){0, 0, 0});
	mkBody3 ball = mkBody3_Make((mkShape3){1, 1, 1, 0.5, 1.5}, mkMat3_Identity(), (mkVec3){0, 0, 0});
	mkSumOptions of3 = mkSumOptions_Default();
	of3.precision = MK_PRECISION_F32;
	ENSURE(!mkSum3_TierHolds(slab, ball, &of3));
	ENSURE(mkSum3_TierHolds(ball, ball, &of3));

	opt.form = MK_FORM_PAPER;
	opt.impl = MK_IMPL_SCALAR;
	ENSURE(mkSum2_Batch(b, b, &opt, ux, uy, 3, o[0][0], o[0][1], NULL, NULL) == MK_ERR_UNSUPPORTED);
	ENSURE(!mkSum2_TierHolds(b, b, &opt));
}

int main(void)
{
	test_circles();
	test_agreement();
	test_extremes();
	test_tails();
	test_options();
	return mk_summary("test_sum_f32");
}
