/* draw_paper.h - the paper's collision draw of a 3D pair for the colliders'
 * tests (test_colliders, test_asc_referee), on draw3.h's generator, and FCL's
 * ellipsoid test case. */
#ifndef MINK_TEST_DRAW_PAPER_H
#define MINK_TEST_DRAW_PAPER_H

#include "draw3.h"

/* The paper's collision draw (experiments/collision's ranges): ellipsoids
 * (ell) or superquadrics with exponents U(0.1, 1.9); B2's centre U(5,15)^3,
 * or near: B1's centre plus U(-2,2)^3. Drawn in this order: the semi-axes,
 * the exponents, the centres, the rotations. */
static inline void mk_test_paper_pair3(unsigned long long *seed, int ell, int near, mkBody3 *b1, mkBody3 *b2)
{
	mkShape3 s1 = { mk_test_uniform(seed, 1, 11), mk_test_uniform(seed, 1, 11), mk_test_uniform(seed, 1, 11), 1, 1 };
	mkShape3 s2 = { mk_test_uniform(seed, 1, 6), mk_test_uniform(seed, 1, 6), mk_test_uniform(seed, 1, 6), 1, 1 };
	if (!ell) {
		s1.eps1 = mk_test_uniform(seed, 0.1, 1.9);
		s1.eps2 = mk_test_uniform(seed, 0.1, 1.9);
		s2.eps1 = mk_test_uniform(seed, 0.1, 1.9);
		s2.eps2 = mk_test_uniform(seed, 0.1, 1.9);
	}
	double lo = near ? -2 : 5, hi = near ? 2 : 15;
	mkVec3 c1 = mkVec3_Make(mk_test_uniform(seed, -5, 5), mk_test_uniform(seed, -5, 5), mk_test_uniform(seed, -5, 5));
	mkVec3 c2 = mkVec3_Make(mk_test_uniform(seed, lo, hi), mk_test_uniform(seed, lo, hi), mk_test_uniform(seed, lo, hi));
	if (near)
		c2 = mkVec3_Add(c1, c2);
	*b1 = mkBody3_Make(s1, mk_test_rotation(seed), c1);
	*b2 = mkBody3_Make(s2, mk_test_rotation(seed), c2);
}

/* FCL's ellipsoid test case: B1 with semi-axes (20, 40, 50) and B2 a sphere
 * of radius 10 whose centre lies x along B1's rotated x axis, so that the
 * signed distance is x - 30; both rotated by R and moved by shift. The
 * distances x the tests run are mkFclCaseX. */
static const double mkFclCaseX[6] = { 40.0, 30.1, 30.0, 29.9, 29.99, 0.0 };

static inline void mk_test_fcl_case(mkMat3 R, mkVec3 shift, double x, mkBody3 *A, mkBody3 *B)
{
	mkShape3 s1 = { 20, 40, 50, 1, 1 }, s2 = { 10, 10, 10, 1, 1 };
	*A = mkBody3_Make(s1, R, shift);
	*B = mkBody3_Make(s2, R, mkVec3_Add(shift, mkMat3_MulVec(R, mkVec3_Make(x, 0, 0))));
}

#endif
