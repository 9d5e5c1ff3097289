/* test_geometric.c - the geometric formula (body 2 an ellipse / ellipsoid)
 * against the core's Theorem 1 on the same surface parameters of body 1.
 * The two are derived differently (an affine map that makes body 2 a unit
 * ball, versus support points) and coded separately; on ellipse pairs they
 * must name the same points to rounding. */
#include <float.h>
#include <math.h>

#include <mink/registry.h>

#include "ensure.h"

/* |t1| + |t2| + |M1| max a1 + |M2| max a2 (max norms): the size every
 * coordinate of the sum is made of. */
static double scale2(mkBody2 a, mkBody2 b)
{
	double s = fmax(fabs(a.t.x), fabs(a.t.y)) + fmax(fabs(b.t.x), fabs(b.t.y));
	mkBody2 w[2] = {a, b};
	for (int k = 0; k < 2; ++k) {
		double m = fmax(fabs(w[k].M.m[0][0]) + fabs(w[k].M.m[0][1]), fabs(w[k].M.m[1][0]) + fabs(w[k].M.m[1][1]));
		s += m * fmax(w[k].shape.a, w[k].shape.b);
	}
	return s;
}

static double scale3(mkBody3 a, mkBody3 b)
{
	double s = fmax(fabs(a.t.x), fmax(fabs(a.t.y), fabs(a.t.z))) + fmax(fabs(b.t.x), fmax(fabs(b.t.y), fabs(b.t.z)));
	mkBody3 w[2] = {a, b};
	for (int k = 0; k < 2; ++k) {
		double m = 0;
		for (int i = 0; i < 3; ++i)
			m = fmax(m, fabs(w[k].M.m[i][0]) + fabs(w[k].M.m[i][1]) + fabs(w[k].M.m[i][2]));
		s += m * fmax(w[k].shape.a, fmax(w[k].shape.b, w[k].shape.c));
	}
	return s;
}

/* Largest coordinate difference of the two methods' outputs g and c (when
 * both ran) over the scale; the point sets are freed. */
static double relative_diff(mkResult rg, mkResult rc, mkPointSet *g, mkPointSet *c, double scale)
{
	double worst = HUGE_VAL;
	if (rg == MK_OK && rc == MK_OK) {
		worst = 0;
		for (int k = 0; k < g->count; ++k) {
			worst = fmax(worst, fmax(fabs(g->x[k] - c->x[k]), fabs(g->y[k] - c->y[k])));
			if (g->dim == 3) worst = fmax(worst, fabs(g->z[k] - c->z[k]));
		}
		worst /= scale;
	}
	mkPointSet_Free(g);
	mkPointSet_Free(c);
	return worst;
}

static double diff2(mkBody2 a, mkBody2 b, mkSet set, int n)
{
	mkPointSet g = {0}, c = {0};
	mkResult rg = mkMethod_Geometric.run2(a, b, set, n, &g), rc = mkMethod_ClosedNormal.run2(a, b, set, n, &c);
	return relative_diff(rg, rc, &g, &c, scale2(a, b));
}

static double diff3(mkBody3 a, mkBody3 b, mkSet set, int n)
{
	mkPointSet g = {0}, c = {0};
	mkResult rg = mkMethod_Geometric.run3(a, b, set, n, &g), rc = mkMethod_ClosedNormal.run3(a, b, set, n, &c);
	return relative_diff(rg, rc, &g, &c, scale3(a, b));
}

int main(void)
{
	unsigned long long seed = 2015;
	double worst_random = 0, worst_extreme = 0;
	/* Tolerance. Both methods compute x1 + E E^T n / |E^T n| from the same
	 * x1 (body 1's point at u_k) and differ in how n reaches body 2: the
	 * geometric method maps body 1's gradient by the cofactor matrix of M1,
	 * the core by its own kernel (the vector kernels through SLEEF's 1-ulp
	 * pow). Each coordinate is a sum of a few terms of size <= S with a few
	 * roundings each (a few ulps of S, ~1e-15), and the error of n's
	 * direction (a few ulps times cond(M1), <= 10 for the random pairs)
	 * moves body 2's support point by at most (a_max / a_min) a_max per
	 * radian: <= 11 for the random pairs, so ~1e-14 of S at worst. The
	 * extreme pairs (ratio 1e3, shear 10) could in the worst direction reach
	 * 1e3 * 100 * a few ulps ~ 1e-11; on these pairs they stay near 1e-14.
	 * Both are held to 1e-13 of S. */
	const double tol_random = 1e-13, tol_extreme = 1e-13;

	for (int t = 0; t < 40; ++t) {
		mkSet set = t % 2 ? MK_SET_PLUS : MK_SET_CONTACT;
		/* 2D: body 1 a superellipse (or an ellipse), body 2 an ellipse. */
		mkShape2 s1 = {mk_test_uniform(&seed, 1, 11), mk_test_uniform(&seed, 1, 11),
			t % 4 < 2 ? mk_test_uniform(&seed, 0.1, 1.9) : 1.0};
		mkShape2 s2 = {mk_test_uniform(&seed, 1, 11), mk_test_uniform(&seed, 1, 11), 1.0};
		mkBody2 a = mkBody2_Make(s1, mkMat2_Mul(mkMat2_Rotation(mk_test_uniform(&seed, 0, 2 * MK_PI)),
			mkMat2_Shear(mk_test_uniform(&seed, -2, 2))), (mkVec2){mk_test_uniform(&seed, -5, 5), 3});
		mkBody2 b = mkBody2_Make(s2, mkMat2_Mul(mkMat2_Rotation(mk_test_uniform(&seed, 0, 2 * MK_PI)),
			mkMat2_Shear(mk_test_uniform(&seed, -2, 2))), (mkVec2){-2, mk_test_uniform(&seed, -5, 5)});
		worst_random = fmax(worst_random, diff2(a, b, set, 500));
		/* 3D: body 1 a superquadric (or an ellipsoid), body 2 an ellipsoid. */
		mkShape3 q1 = {mk_test_uniform(&seed, 1, 10), mk_test_uniform(&seed, 1, 10), mk_test_uniform(&seed, 1, 10),
			t % 4 < 2 ? mk_test_uniform(&seed, 0.2, 1.9) : 1.0, t % 4 < 2 ? mk_test_uniform(&seed, 0.2, 1.9) : 1.0};
		mkShape3 q2 = {mk_test_uniform(&seed, 1, 6), mk_test_uniform(&seed, 1, 6), mk_test_uniform(&seed, 1, 6), 1, 1};
		mkBody3 c = mkBody3_Make(q1, mkMat3_FromQuat(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1),
			mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1)), (mkVec3){1, 2, 3});
		mkBody3 d = mkBody3_Make(q2, mkMat3_FromQuat(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1),
			mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1)), (mkVec3){-3, 0, 1});
		worst_random = fmax(worst_random, diff3(c, d, set, 30));
	}

	/* Extreme pairs: axis ratio 1e3, shear 10, eps near 0.01 and 1.99 on
	 * body 1, a reflection, a far translation. */
	static const double eps[] = {0.01, 1.0, 1.99};
	for (int k = 0; k < 3; ++k)
		for (int set = 0; set < 2; ++set) {
			mkShape2 s1 = {1000, 1, eps[k]}, s2 = {1, 1000, 1.0};
			mkMat2 R = mkMat2_Mul(mkMat2_Rotation(0.3), mkMat2_Shear(10));
			mkMat2 F = {{{-1, 0}, {0, 1}}};
			mkBody2 a = mkBody2_Make(s1, R, (mkVec2){1e3, -2e3});
			mkBody2 b = mkBody2_Make(s2, mkMat2_Mul(F, mkMat2_Mul(mkMat2_Rotation(-1.1), mkMat2_Shear(-10))),
				(mkVec2){5, 5});
			worst_extreme = fmax(worst_extreme, diff2(a, b, (mkSet)set, 2000));
			mkShape3 q1 = {1000, 1, 30, eps[k], eps[2 - k]}, q2 = {1, 1000, 3, 1, 1};
			mkBody3 c = mkBody3_Make(q1, mkMat3_FromQuat(0.3, 0.5, -0.2, 0.7), (mkVec3){1e3, 0, -1e3});
			mkBody3 d = mkBody3_Make(q2, mkMat3_FromQuat(-0.6, 0.1, 0.9, 0.2), (mkVec3){1, 1, 1});
			worst_extreme = fmax(worst_extreme, diff3(c, d, (mkSet)set, 60));
		}
	printf("geometric vs closed-normal, largest difference / scale: random pairs %.3g, extreme pairs %.3g\n",
		worst_random, worst_extreme);
	ENSURE_LE(worst_random, tol_random);
	ENSURE_LE(worst_extreme, tol_extreme);
	return mk_summary("test_geometric");
}
