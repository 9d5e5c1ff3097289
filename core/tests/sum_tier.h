/* sum_tier.h - what the tests of the two precision tiers of the batch closed
 * forms share, written once and compiled into each (test_sum.c for the
 * double tier, test_sum_f32.c for MK_PRECISION_F32): the buffers, one call
 * of each dimension's batch, and the circles case worked by hand. Define
 * MK_TEST_PRECISION before including. */
#ifndef MINK_TEST_SUM_TIER_H
#define MINK_TEST_SUM_TIER_H

#include <math.h>

#include <mink/mink.h>

#include "ensure.h"

#define NMAX 4096
static double ux[NMAX], uy[NMAX], uz[NMAX];
static double o[2][6][NMAX];

static const mkImpl impls[] = {MK_IMPL_SCALAR, MK_IMPL_AVX2, MK_IMPL_AVX512};

static mkResult run2(mkBody2 b1, mkBody2 b2, mkSet set, mkForm form, mkParam param, mkImpl impl, int n, int slot)
{
	mkSumOptions opt = {set, form, param, impl, MK_TEST_PRECISION};
	return mkSum2_Batch(b1, b2, &opt, ux, uy, n, o[slot][0], o[slot][1], o[slot][2], o[slot][3]);
}

static mkResult run3(mkBody3 b1, mkBody3 b2, mkSet set, mkForm form, mkParam param, mkImpl impl, int n, int slot)
{
	mkSumOptions opt = {set, form, param, impl, MK_TEST_PRECISION};
	return mkSum3_Batch(b1, b2, &opt, ux, uy, uz, n, o[slot][0], o[slot][1], o[slot][2],
		o[slot][3], o[slot][4], o[slot][5]);
}

/* A random pair of superquadrics of the paper's 3D draws (semi-axes
 * U(1,10) and U(1,6), exponents U(0.1,1.9), rotated) centred at (1,2,3),
 * into b[0], b[1]; returns a bound on the problem's size for relative
 * errors. */
static double draw_pair3(unsigned long long *seed, mkBody3 b[2])
{
	for (int j = 0; j < 2; ++j) {
		double hi = j ? 6 : 10;
		mkShape3 s = {mk_test_uniform(seed, 1, hi), mk_test_uniform(seed, 1, hi), mk_test_uniform(seed, 1, hi),
			mk_test_uniform(seed, 0.1, 1.9), mk_test_uniform(seed, 0.1, 1.9)};
		mkMat3 M = mkMat3_FromQuat(mk_test_unit(seed), mk_test_unit(seed), mk_test_unit(seed), mk_test_unit(seed));
		b[j] = mkBody3_Make(s, M, (mkVec3){1, 2, 3});
	}
	return 10 + 3 * (b[0].shape.a + b[0].shape.b + b[0].shape.c + b[1].shape.a + b[1].shape.b + b[1].shape.c);
}

/* Two circles of radii 2 and 3 (the ellipse kernel), and the same circles as
 * superellipses of eps = 1 + nudge (the general kernel): the contact space is
 * the circle of radius 5 about t1 and the kissing point lies at 2/5 of the
 * way, each coordinate within tol; with `plus`, the plus set is the contact
 * set shifted by t2 = (100, 7). */
static void check_circles(double nudge, double tol, int plus)
{
	mkBody2 b1 = mkBody2_Make((mkShape2){2.0, 2.0, 1.0}, mkMat2_Rotation(0.7), (mkVec2){1.5, -2.0});
	mkBody2 b2 = mkBody2_Make((mkShape2){3.0, 3.0, 1.0}, mkMat2_Identity(), (mkVec2){100.0, 7.0});
	mkBody2 g1 = b1, g2 = b2;
	g1.shape.eps = g2.shape.eps = 1.0 + nudge;
	int n = 257;
	mkSample2_Angles(n, ux, uy);
	for (int v = 0; v < 2; ++v)
		for (int ii = 0; ii < 3; ++ii) {
			if (!mkImpl_Available(impls[ii])) continue;
			for (int form = 0; form < 2; ++form)
				for (int param = 0; param < 2; ++param) {
					ENSURE(run2(v ? g1 : b1, v ? g2 : b2, MK_SET_CONTACT, form, param, impls[ii], n, 0) == MK_OK);
					for (int i = 0; i < n; ++i) {
						double dx = o[0][0][i] - 1.5, dy = o[0][1][i] + 2.0;
						ENSURE_NEAR(hypot(dx, dy), 5.0, tol);
						ENSURE_NEAR(o[0][2][i], 1.5 + 0.4 * dx, tol);
						ENSURE_NEAR(o[0][3][i], -2.0 + 0.4 * dy, tol);
					}
					if (!plus) continue;
					ENSURE(run2(v ? g1 : b1, v ? g2 : b2, MK_SET_PLUS, form, param, impls[ii], n, 1) == MK_OK);
					for (int i = 0; i < n; ++i) {
						ENSURE_NEAR(o[1][0][i] - 100.0, o[0][0][i], tol);
						ENSURE_NEAR(o[1][1][i] - 7.0, o[0][1][i], tol);
					}
				}
		}
}

#endif
