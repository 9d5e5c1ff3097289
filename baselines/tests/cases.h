/* cases.h - the body pairs the referee tests put every method through:
 * random pairs drawn as in the paper (Sec. 6.1 and 6.3) and extreme pairs
 * (eps near 0.01 and 1.99, axis ratios 1e3, shears up to 10, reflections,
 * far translations, axis-aligned boxes whose sums are exactly coplanar). */
#ifndef MINK_TEST_CASES_H
#define MINK_TEST_CASES_H

#include <mink/mink.h>

#include "ensure.h"

typedef struct Case2 { const char *name; mkBody2 a, b; } Case2;
typedef struct Case3 { const char *name; mkBody3 a, b; } Case3;

static inline mkBody2 case_body2(double a, double b, double eps, double rot, double shear, double tx, double ty)
{
	mkShape2 s = {a, b, eps};
	return mkBody2_Make(s, mkMat2_Mul(mkMat2_Rotation(rot), mkMat2_Shear(shear)), (mkVec2){tx, ty});
}

static inline mkBody3 case_body3(double a, double b, double c, double e1, double e2, const double *q, double tx, double ty,
	double tz)
{
	mkShape3 s = {a, b, c, e1, e2};
	return mkBody3_Make(s, mkMat3_FromQuat(q[0], q[1], q[2], q[3]), (mkVec3){tx, ty, tz});
}

/* Fills up to 10 cases; returns the count. */
static inline int cases2(Case2 *c, unsigned long long seed)
{
	int k = 0;
	for (int t = 0; t < 4; ++t) { /* random: SQ, ES, EE, SQ */
		double e1 = t == 2 ? 1.0 : mk_test_uniform(&seed, 0.1, 1.9);
		double e2 = t == 1 || t == 2 ? 1.0 : mk_test_uniform(&seed, 0.1, 1.9);
		c[k].name = t == 2 ? "random EE" : t == 1 ? "random ES" : "random SQ";
		c[k].a = case_body2(mk_test_uniform(&seed, 1, 11), mk_test_uniform(&seed, 1, 11), e1,
			mk_test_uniform(&seed, 0, 2 * MK_PI), mk_test_uniform(&seed, -2, 2), mk_test_uniform(&seed, -5, 5), 1);
		c[k].b = case_body2(mk_test_uniform(&seed, 1, 11), mk_test_uniform(&seed, 1, 11), e2,
			mk_test_uniform(&seed, 0, 2 * MK_PI), mk_test_uniform(&seed, -2, 2), 2, mk_test_uniform(&seed, -5, 5));
		++k;
	}
	c[k++] = (Case2){"box-like 1e3:1 shear 10 vs diamond-like shear -10",
		case_body2(1000, 1, 0.01, 0.3, 10, 5, 5), case_body2(2, 3, 1.99, 1.0, -10, 1, 1)};
	c[k++] = (Case2){"diamond-like 1:1e3 vs ellipse 1e3:1 shear 10",
		case_body2(1, 1000, 1.99, 0.3, 0, 5, 5), case_body2(1000, 1, 1.0, 1.0, 10, 1, 1)};
	c[k++] = (Case2){"axis-aligned boxes (parallel edges)",
		case_body2(3, 2, 0.01, 0, 0, 0, 0), case_body2(1, 1, 0.01, 0, 0, 0, 0)};
	c[k++] = (Case2){"thin and far (1e6), eps 1.99 vs 0.01",
		case_body2(5, 0.005, 1.99, 0.7, 3, 1e6, 1e6), case_body2(0.005, 5, 0.01, 0.2, -3, 0, 0)};
	mkBody2 r = case_body2(4, 1, 0.5, 0.4, 1.5, -3, 2);
	r.M.m[0][0] = -r.M.m[0][0];
	r.M.m[1][0] = -r.M.m[1][0]; /* a reflection: det M < 0 */
	c[k++] = (Case2){"reflected superellipse vs ellipse", r, case_body2(2, 0.5, 1.0, -0.3, 0.5, 1, 1)};
	return k;
}

static inline int cases3(Case3 *c, unsigned long long seed)
{
	int k = 0;
	for (int t = 0; t < 4; ++t) { /* random: SQ, ES, EE, SQ */
		double q1[4], q2[4];
		for (int i = 0; i < 4; ++i) q1[i] = mk_test_uniform(&seed, -1, 1), q2[i] = mk_test_uniform(&seed, -1, 1);
		int ell1 = t == 2, ell2 = t == 1 || t == 2;
		c[k].name = t == 2 ? "random EE" : t == 1 ? "random ES" : "random SQ";
		c[k].a = case_body3(mk_test_uniform(&seed, 1, 10), mk_test_uniform(&seed, 1, 10), mk_test_uniform(&seed, 1, 10),
			ell1 ? 1 : mk_test_uniform(&seed, 0.2, 1.9), ell1 ? 1 : mk_test_uniform(&seed, 0.2, 1.9), q1, 1, 2, 3);
		c[k].b = case_body3(mk_test_uniform(&seed, 1, 6), mk_test_uniform(&seed, 1, 6), mk_test_uniform(&seed, 1, 6),
			ell2 ? 1 : mk_test_uniform(&seed, 0.2, 1.9), ell2 ? 1 : mk_test_uniform(&seed, 0.2, 1.9), q2, -2, 0, 1);
		++k;
	}
	static const double qa[4] = {1, 0.2, 0.3, 0.4}, qb[4] = {0.3, 1, 0, 0}, qi[4] = {1, 0, 0, 0},
		qc[4] = {0.5, 0.5, 0.5, 0.5}, qd[4] = {0.7, 3, 1, 0}, qe[4] = {0.2, -3, 0, 1};
	c[k++] = (Case3){"box-like 1e3:1:2 sheared 10 vs octahedron-like",
		case_body3(1000, 1, 2, 0.01, 0.01, qa, 3, -3, 6), case_body3(2, 3, 1, 1.99, 1.99, qb, 1, -1, 2)};
	mkMat3 shear = {{{1, 10, 0}, {0, 1, 0}, {0, 0, 1}}};
	c[k - 1].a.M = mkMat3_Mul(c[k - 1].a.M, shear);
	c[k++] = (Case3){"eps (1.99, 0.01) vs ellipsoid 1:1e3:1",
		case_body3(1, 2, 3, 1.99, 0.01, qi, 0, 0, 0), case_body3(1, 1000, 1, 1, 1, qc, 1, -1, 2)};
	c[k++] = (Case3){"axis-aligned boxes (coplanar sums)",
		case_body3(3, 2, 1, 0.01, 0.01, qi, 0, 0, 0), case_body3(1, 1, 1, 0.01, 0.01, qi, 0, 0, 0)};
	c[k++] = (Case3){"thin and far (1e6), eps 1.9 vs 0.1",
		case_body3(5, 0.005, 1, 1.9, 1.9, qd, 1e6, -1e6, 2e6), case_body3(0.005, 5, 1, 0.1, 0.1, qe, 0, 0, 0)};
	return k;
}

#endif
