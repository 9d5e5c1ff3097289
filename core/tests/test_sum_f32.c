/* test_sum_f32.c - the single-precision tier of the batch closed forms
 * (mkSumOptions.precision = MK_PRECISION_F32): its vector kernels against
 * its scalar reference, hand-worked circles, the tails of a batch, every
 * output finite at the corners of the valid ranges, the options, and the
 * float-array entry points.
 * Its accuracy against 256-bit MPFR is asserted in tests/reference
 * (core.ref.sum2.f32.*, core.ref.sum3.f32.*). */
#include <math.h>
#include <stdio.h>
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

/* The float-array entry points (mkSum2f_Batch, mkSum3f_Batch). Their
 * accuracy against MPFR is asserted in core.ref.sum{2,3}.f32io.*; here:
 *  - where the tier holds they run the same arithmetic as the double-array
 *    call on the same float-valued parameter vectors, except for the unit
 *    test and normalisation (in double there, in float here): against the
 *    double-array f32 call, a few float ulps of the scale (allowed 1e-6 of
 *    it, the tier's stated accuracy; the largest seen is printed);
 *  - every tail length of a batch gives the points of the whole batch, bit
 *    for bit, and writes nothing past n;
 *  - in double precision and outside the tier's domain they return the
 *    double call's points rounded to float, exactly;
 *  - a parameter vector scaled by 1e30 or 1e-30 (its square leaves the float
 *    range) gives the unit vector's point within the tier's accuracy;
 *  - argument errors as for the double-array call. */
static float fu[3][NMAX], fo[2][6][NMAX];

static void test_float_arrays(void)
{
	unsigned long long seed = 29;
	double worst = 0.0;
	for (int trial = 0; trial < 20; ++trial) {
		mkBody3 b[2];
		double S = draw_pair3(&seed, b);
		int n = 100;
		mkSample3_Grid(10, ux, uy, uz);
		for (int k = 0; k < n; ++k) {
			fu[0][k] = (float)ux[k]; fu[1][k] = (float)uy[k]; fu[2][k] = (float)uz[k];
			ux[k] = fu[0][k]; uy[k] = fu[1][k]; uz[k] = fu[2][k];
		}
		for (int ii = 0; ii < 3; ++ii) {
			if (!mkImpl_Available(impls[ii])) continue;
			mkSumOptions of = mkSumOptions_Default();
			of.precision = MK_PRECISION_F32;
			of.impl = impls[ii];
			of.form = trial % 2 ? MK_FORM_GRADIENT : MK_FORM_NORMAL;
			of.param = trial % 3 ? MK_PARAM_SURFACE : MK_PARAM_NORMAL;
			ENSURE(mkSum3_TierHolds(b[0], b[1], &of));
			ENSURE(mkSum3_Batch(b[0], b[1], &of, ux, uy, uz, n, o[0][0], o[0][1], o[0][2], o[0][3], o[0][4], o[0][5]) == MK_OK);
			ENSURE(mkSum3f_Batch(b[0], b[1], &of, fu[0], fu[1], fu[2], n, fo[0][0], fo[0][1], fo[0][2], fo[0][3], fo[0][4],
				fo[0][5]) == MK_OK);
			for (int c = 0; c < 6; ++c)
				for (int k = 0; k < n; ++k) {
					double e = fabs(o[0][c][k] - (double)fo[0][c][k]) / S;
					ENSURE_LE(e, 1e-6);
					if (e > worst) worst = e;
				}
		}
	}
	printf("float arrays against double arrays (f32 tier, 3D, 20 pairs x 3 kernels): largest difference %.2e of the scale\n",
		worst);

	/* tails, 2D */
	mkBody2 p1 = mkBody2_Make((mkShape2){2, 1, 0.4}, mkMat2_Rotation(0.3), (mkVec2){0, 0});
	mkBody2 p2 = mkBody2_Make((mkShape2){1, 3, 1.0}, mkMat2_Shear(0.5), (mkVec2){1, 0});
	mkSample2_Angles(81, ux, uy);
	for (int k = 0; k < 81; ++k) { fu[0][k] = (float)ux[k]; fu[1][k] = (float)uy[k]; }
	for (int ii = 0; ii < 3; ++ii) {
		if (!mkImpl_Available(impls[ii])) continue;
		mkSumOptions of = mkSumOptions_Default();
		of.precision = MK_PRECISION_F32;
		of.impl = impls[ii];
		ENSURE(mkSum2f_Batch(p1, p2, &of, fu[0], fu[1], 81, fo[0][0], fo[0][1], fo[0][2], fo[0][3]) == MK_OK);
		for (int n = 0; n <= 70; ++n) {
			for (int c = 0; c < 4; ++c)
				for (int k = 0; k < 81; ++k) fo[1][c][k] = -12345.0f;
			ENSURE(mkSum2f_Batch(p1, p2, &of, fu[0], fu[1], n, fo[1][0], fo[1][1], fo[1][2], fo[1][3]) == MK_OK);
			for (int c = 0; c < 4; ++c) {
				for (int k = 0; k < n; ++k) ENSURE(fo[1][c][k] == fo[0][c][k]);
				ENSURE(fo[1][c][n] == -12345.0f);
			}
		}
	}

	/* double precision, and a pair outside the domain: the double call's points rounded */
	mkBody2 thin = mkBody2_Make((mkShape2){1e4, 1e-4, 0.7}, mkMat2_Rotation(0.4), (mkVec2){1, 2});
	for (int k = 0; k < 2; ++k) {
		mkSumOptions od = mkSumOptions_Default(), oo = od;
		oo.precision = k ? MK_PRECISION_F32 : MK_PRECISION_DOUBLE;
		mkBody2 a = k ? thin : p1;
		if (k) ENSURE(!mkSum2_TierHolds(a, p2, &oo));
		int n = 300; /* more than one block of the widening path */
		mkSample2_Angles(n, ux, uy);
		for (int j = 0; j < n; ++j) { fu[0][j] = (float)ux[j]; fu[1][j] = (float)uy[j]; ux[j] = fu[0][j]; uy[j] = fu[1][j]; }
		ENSURE(mkSum2_Batch(a, p2, &od, ux, uy, n, o[0][0], o[0][1], o[0][2], o[0][3]) == MK_OK);
		ENSURE(mkSum2f_Batch(a, p2, &oo, fu[0], fu[1], n, fo[0][0], fo[0][1], fo[0][2], fo[0][3]) == MK_OK);
		for (int c = 0; c < 4; ++c)
			for (int j = 0; j < n; ++j) ENSURE(fo[0][c][j] == (float)o[0][c][j]);
	}

	/* scaled parameter vectors: the same points as the unit ones */
	{
		mkSumOptions of = mkSumOptions_Default();
		of.precision = MK_PRECISION_F32;
		int n = 64;
		mkSample2_Angles(n, ux, uy);
		for (int j = 0; j < n; ++j) { fu[0][j] = (float)ux[j]; fu[1][j] = (float)uy[j]; }
		ENSURE(mkSum2f_Batch(p1, p2, &of, fu[0], fu[1], n, fo[0][0], fo[0][1], NULL, NULL) == MK_OK);
		double S = 14.0; /* |t2| + |M1|_F |a1| + |M2|_F |a2|, rounded up */
		for (int s = 0; s < 2; ++s) {
			float k = s ? 1e30f : 1e-30f;
			for (int j = 0; j < n; ++j) { fu[2][j] = fu[0][j] * k; fo[1][5][j] = fu[1][j] * k; }
			ENSURE(mkSum2f_Batch(p1, p2, &of, fu[2], fo[1][5], n, fo[1][0], fo[1][1], NULL, NULL) == MK_OK);
			for (int j = 0; j < n; ++j) {
				ENSURE_LE(fabs((double)fo[1][0][j] - fo[0][0][j]) / S, 1e-6);
				ENSURE_LE(fabs((double)fo[1][1][j] - fo[0][1][j]) / S, 1e-6);
			}
		}
	}

	/* argument errors */
	mkSumOptions of = mkSumOptions_Default();
	of.precision = MK_PRECISION_F32;
	ENSURE(mkSum2f_Batch(p1, p2, &of, fu[0], fu[1], -1, fo[0][0], fo[0][1], NULL, NULL) == MK_ERR_ARGUMENT);
	ENSURE(mkSum2f_Batch(p1, p2, &of, NULL, fu[1], 3, fo[0][0], fo[0][1], NULL, NULL) == MK_ERR_ARGUMENT);
	ENSURE(mkSum2f_Batch(p1, p2, &of, fu[0], fu[1], 3, fo[0][0], fo[0][1], fo[0][2], NULL) == MK_ERR_ARGUMENT);
	ENSURE(mkSum2f_Batch(p1, p2, NULL, fu[0], fu[1], 3, fo[0][0], fo[0][1], NULL, NULL) == MK_ERR_ARGUMENT);
	of.form = MK_FORM_PAPER;
	of.impl = MK_IMPL_SCALAR;
	ENSURE(mkSum2f_Batch(p1, p2, &of, fu[0], fu[1], 3, fo[0][0], fo[0][1], NULL, NULL) == MK_ERR_UNSUPPORTED);
	of.precision = MK_PRECISION_DOUBLE;
	ENSURE(mkSum2f_Batch(p1, p2, &of, fu[0], fu[1], 3, fo[0][0], fo[0][1], NULL, NULL) == MK_OK);
}

int main(void)
{
	test_circles();
	test_agreement();
	test_extremes();
	test_tails();
	test_options();
	test_float_arrays();
	return mk_summary("test_sum_f32");
}
