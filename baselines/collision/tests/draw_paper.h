/* draw_paper.h - the paper's collision draw of a 3D pair for the colliders'
 * tests (test_colliders, test_asc_referee), on draw3.h's generator. */
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

#endif
