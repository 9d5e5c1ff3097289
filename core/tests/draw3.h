/* draw3.h - the tests' draws of placed 3D bodies, on ensure.h's generator:
 * a rotation from four U(-1,1) quaternion components, and a pair of the
 * paper's collision draws with the exponents in a given range. Shared by
 * core.test_collision and baselines.test_colliders. */
#ifndef MINK_TEST_DRAW3_H
#define MINK_TEST_DRAW3_H

#include <mink/mink.h>

#include "ensure.h"

static inline mkMat3 mk_test_rotation(unsigned long long *seed)
{
	double q[4];
	for (int i = 0; i < 4; ++i)
		q[i] = mk_test_uniform(seed, -1.0, 1.0);
	return mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
}

/* B1 semi-axes U(1,11)^3, centre U(-5,5)^3; B2 semi-axes U(1,6)^3, centre
 * U(5,15)^3; every exponent U(elo, ehi). Drawn in this order: both shapes'
 * semi-axes, their exponents, the centres, the rotations. */
static inline void mk_test_pair3(unsigned long long *seed, double elo, double ehi, mkBody3 *b1, mkBody3 *b2)
{
	mkShape3 s1 = { mk_test_uniform(seed, 1, 11), mk_test_uniform(seed, 1, 11), mk_test_uniform(seed, 1, 11), 1, 1 };
	mkShape3 s2 = { mk_test_uniform(seed, 1, 6), mk_test_uniform(seed, 1, 6), mk_test_uniform(seed, 1, 6), 1, 1 };
	s1.eps1 = mk_test_uniform(seed, elo, ehi);
	s1.eps2 = mk_test_uniform(seed, elo, ehi);
	s2.eps1 = mk_test_uniform(seed, elo, ehi);
	s2.eps2 = mk_test_uniform(seed, elo, ehi);
	mkVec3 c1 = mkVec3_Make(mk_test_uniform(seed, -5, 5), mk_test_uniform(seed, -5, 5), mk_test_uniform(seed, -5, 5));
	mkVec3 c2 = mkVec3_Make(mk_test_uniform(seed, 5, 15), mk_test_uniform(seed, 5, 15), mk_test_uniform(seed, 5, 15));
	mkMat3 R1 = mk_test_rotation(seed);
	*b1 = mkBody3_Make(s1, R1, c1);
	*b2 = mkBody3_Make(s2, mk_test_rotation(seed), c2);
}

#endif
