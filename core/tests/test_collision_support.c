/* test_collision_support.c - the support map the collision queries iterate
 * on (collide/support.h, collide/pair.h): a body's support point and its
 * Jacobian (mkBody3_SupportJacobian) and the solver's one-pass evaluation of
 * a pair (mkSupBody_EvalHess2), against references that share no code with
 * them: mkBody3_Support (the sum kernel's dual-norm code) and central
 * differences of it. The queries themselves: test_collision.c. */
#include <mink/mink.h>

#include <float.h>
#include <math.h>
#include <stdio.h>

#include "draw3.h"
#include "ensure.h"

/* The solver's internal pair evaluation (static functions of pair.h),
 * for test_pair_pass. */
#include "collide/pair.h"

static void test_jacobian(void)
{
	unsigned long long seed = 11;
	for (int trial = 0; trial < 200; ++trial) {
		mkShape3 s = { mk_test_uniform(&seed, 1, 11), mk_test_uniform(&seed, 1, 11), mk_test_uniform(&seed, 1, 11),
			trial % 4 == 0 ? 1.0 : mk_test_uniform(&seed, 0.1, 1.9), trial % 4 == 0 ? 1.0 : mk_test_uniform(&seed, 0.1, 1.9) };
		mkBody3 b = mkBody3_Make(s, mk_test_rotation(&seed), mkVec3_Make(1, 2, 3));
		mkVec3 n = mkVec3_Normalize(mkVec3_Make(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1),
			mk_test_uniform(&seed, -1, 1)));
		mkMat3 J;
		mkVec3 p = mkBody3_SupportJacobian(b, n, &J);
		mkVec3 ref = mkVec3_Sub(mkBody3_Support(b, n), b.t);
		/* Two dual-norm evaluations of the same point: a few ulps of the size. */
		ENSURE_NEAR(mkVec3_Length(mkVec3_Sub(p, ref)), 0.0, 1e-12 * 11.0);
		/* Central differences of mkBody3_Support with step h: truncation
		 * O(h^2 |s'''|) and rounding eps |s| / h; h = 1e-5 keeps both
		 * below 1e-6 relative for these exponents away from the axes, so
		 * the check uses 1e-4 of the Jacobian's size. */
		double h = 1e-5, jmax = 0.0, emax = 0.0;
		mkVec3 e[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
		for (int j = 0; j < 3; ++j) {
			mkVec3 sp = mkBody3_Support(b, mkVec3_Add(n, mkVec3_Scale(e[j], h)));
			mkVec3 sm = mkBody3_Support(b, mkVec3_Sub(n, mkVec3_Scale(e[j], h)));
			mkVec3 col = mkVec3_Scale(mkVec3_Sub(sp, sm), 0.5 / h);
			double c[3] = { col.x, col.y, col.z };
			for (int i = 0; i < 3; ++i) {
				jmax = fmax(jmax, fabs(J.m[i][j]));
				emax = fmax(emax, fabs(J.m[i][j] - c[i]));
			}
		}
		ENSURE_LE(emax, 1e-4 * jmax + 1e-9);
		/* J n = 0 (the support point depends on the direction only), up to
		 * rounding of the size of the body and of J. */
		ENSURE_LE(mkVec3_Length(mkMat3_MulVec(J, n)), 1e-12 * (jmax + 11.0));
	}
}

/* The solver's support map at the edges of its formula, against the
 * dual-norm support of body.c (mkBody3_Support, separate code): exponents
 * from 0.01 to 1.99, directions along the axes and in the coordinate planes
 * (zero components: the pair norms' special cases, unrotated), and
 * directions (rotated or not) where
 * the outer pair of the nested norm ties, |(a y1, b y2)|_q2 = c |y3| or
 * within 1e-12 of it (where the larger of the pair changes, chosen from
 * log(N_in / |p3|) by the solver). Reference: body.c; tolerance a few ulps of
 * the size as in test_jacobian. */
static void test_support_edges(void)
{
	static const double eps[] = { 0.01, 0.1, 0.5, 1.5, 1.9, 1.99 };
	unsigned long long seed = 29;
	int checked = 0;
	for (int i = 0; i < 6; ++i)
		for (int j = 0; j < 6; ++j)
			for (int trial = 0; trial < 24; ++trial) {
				mkShape3 s = { mk_test_uniform(&seed, 1, 11), mk_test_uniform(&seed, 1, 11), mk_test_uniform(&seed, 1, 11),
					eps[i], eps[j] };
				/* the canonical direction p = D M^T n wanted, then n from it */
				double y[3] = { mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1) };
				int kind = trial / 2 % 6;
				/* Axis and plane directions unrotated: their zero components
				 * must stay exact, since with an exponent near 0 a component
				 * of 1e-17 (a rotation's rounding) already moves the support
				 * point by a macroscopic amount (w = r^(q-1), q - 1 = 0.005:
				 * (1e-17)^0.005 = 0.82): a nearly kinked support function,
				 * where two codes legitimately differ. */
				int rotated = kind >= 3 && trial % 2;
				mkBody3 b = mkBody3_Make(s, rotated ? mk_test_rotation(&seed) : mkMat3_Identity(), mkVec3_Make(1, 2, 3));
				if (kind < 3) {
					/* along an axis (kind; first 12 trials) or in a
					 * coordinate plane (kind's component 0) */
					if (trial < 12) {
						for (int k = 0; k < 3; ++k)
							y[k] = k == kind ? (y[k] < 0 ? -1.0 : 1.0) : 0.0;
					} else
						y[kind] = 0.0;
				} else {
					/* a tie of the outer pair, exact or off by 1e-12 */
					double q2 = 2.0 / (2.0 - s.eps2);
					double pin = pow(pow(fabs(s.a * y[0]), q2) + pow(fabs(s.b * y[1]), q2), 1.0 / q2);
					double off = kind == 3 ? 1.0 : kind == 4 ? 1.0 + 1e-12 : 1.0 - 1e-12;
					y[2] = (y[2] < 0 ? -1.0 : 1.0) * pin * off / s.c;
				}
				/* n = M y: p = D M^T n = D y (up to rounding when rotated) */
				mkVec3 n = mkMat3_MulVec(b.M, mkVec3_Make(y[0], y[1], y[2]));
				mkVec3 p = mkBody3_SupportJacobian(b, n, NULL);
				mkVec3 ref = mkVec3_Sub(mkBody3_Support(b, n), b.t);
				ENSURE_NEAR(mkVec3_Length(mkVec3_Sub(p, ref)), 0.0, 1e-12 * 11.0);
				++checked;
			}
	ENSURE(checked == 6 * 6 * 24);
}

/* x(n) = s1(n) - s2(-n) about the centres, by body.c's dual-norm support
 * (no code of the solver). */
static mkVec3 mk_pair_x(mkBody3 b1, mkBody3 b2, mkVec3 n)
{
	return mkVec3_Sub(mkVec3_Sub(mkBody3_Support(b1, n), b1.t), mkVec3_Sub(mkBody3_Support(b2, mkVec3_Neg(n)), b2.t));
}

static double mk_rel(double a, double b)
{
	return fabs(a - b) / fmax(1.0, fmax(fabs(a), fabs(b)));
}

/* The one-pass evaluation Newton's loop uses for two superquadrics
 * (mkSupBody_EvalHess2), called directly: its support points against
 * mkBody3_Support, its tangent Jacobian (t_i^T (J1(n) + J2(-n)) t_j) against
 * central differences of mkBody3_Support along the tangents, from unit and
 * unnormalised directions; and its records of the pair norms against the
 * separate evaluation the rest of the solver uses (mkSupBody_Eval2 and
 * mkPair_Tangent), including directions along the bodies' axes, where pair
 * norms have zero components. */
static void test_pair_pass(void)
{
	unsigned long long seed = 41;
	int fd_checked = 0, axis_checked = 0;
	for (int trial = 0; trial < 400; ++trial) {
		mkBody3 b1, b2;
		mk_test_pair3(&seed, 0.1, 1.9, &b1, &b2);
		int axis = trial % 8 == 7;
		mkVec3 n;
		if (axis) {
			/* along an axis of unrotated bodies: the canonical directions
			 * have exact zeros (a rotation's rounding would not) */
			b1.M = b2.M = mkMat3_Identity();
			int k = trial / 8 % 3;
			n = mkVec3_Make(k == 0, k == 1, k == 2);
			if (trial / 24 % 2)
				n = mkVec3_Neg(n);
		} else
			n = mkVec3_Normalize(mkVec3_Make(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1),
				mk_test_uniform(&seed, -1, 1)));
		double len = trial % 3 == 0 ? 1.0 : mk_test_uniform(&seed, 0.5, 2.0);
		mkPairCtx c;
		mkPairCtx_Init(&c, &b1, &b2);
		mkVec3 t1, t2;
		mkTangents(n, &t1, &t2);
		mkSupAt a1, a2;
		double A[3];
		mkSupBody_EvalHess2(&c.k1, &c.k2, mkVec3_Scale(n, len), len, n, t1, t2, &a1, &a2, A, 1);
		/* without the Jacobian (the solver's light points): the same
		 * records to the last bit, and A left alone */
		{
			mkSupAt l1, l2;
			double L[3] = { 7.0, 7.0, 7.0 };
			mkSupBody_EvalHess2(&c.k1, &c.k2, mkVec3_Scale(n, len), len, n, t1, t2, &l1, &l2, L, 0);
			const mkSupAt *lf[2] = { &l1, &l2 }, *af[2] = { &a1, &a2 };
			for (int k = 0; k < 2; ++k) /* (v is an ellipsoid's, not written here) */
				ENSURE(memcmp(&lf[k]->s, &af[k]->s, sizeof af[k]->s) == 0 && lf[k]->h == af[k]->h
					&& memcmp(lf[k]->sg, af[k]->sg, sizeof af[k]->sg) == 0
					&& memcmp(&lf[k]->in, &af[k]->in, sizeof af[k]->in) == 0
					&& memcmp(&lf[k]->out, &af[k]->out, sizeof af[k]->out) == 0);
			ENSURE(L[0] == 7.0 && L[1] == 7.0 && L[2] == 7.0);
		}
		/* support points and values: a few ulps of the size (11) */
		mkVec3 r1 = mkVec3_Sub(mkBody3_Support(b1, n), b1.t), r2 = mkVec3_Sub(mkBody3_Support(b2, mkVec3_Neg(n)), b2.t);
		ENSURE_NEAR(mkVec3_Length(mkVec3_Sub(a1.s, r1)), 0.0, 1e-12 * 11.0);
		ENSURE_NEAR(mkVec3_Length(mkVec3_Sub(a2.s, r2)), 0.0, 1e-12 * 11.0);
		ENSURE_NEAR(a1.h, mkVec3_Dot(n, r1), 1e-12 * 11.0);
		ENSURE_NEAR(a2.h, -mkVec3_Dot(n, r2), 1e-12 * 11.0);
		/* the records, against the solver's other evaluation at the unit n */
		mkSupAt g1, g2;
		mkSupBody_Eval2(&c.k1, n, &g1, &c.k2, mkVec3_Neg(n), &g2);
		const mkSupAt *f[2] = { &a1, &a2 }, *g[2] = { &g1, &g2 };
		for (int k = 0; k < 2; ++k) {
			ENSURE_LE(mk_rel(f[k]->in.norm, g[k]->in.norm), 1e-13);
			ENSURE_LE(mk_rel(f[k]->out.norm, g[k]->out.norm), 1e-13);
			for (int j = 0; j < 2; ++j) {
				ENSURE_LE(mk_rel(f[k]->in.r[j], g[k]->in.r[j]), 1e-13);
				ENSURE_LE(mk_rel(f[k]->in.w[j], g[k]->in.w[j]), 1e-13);
				ENSURE_LE(mk_rel(f[k]->out.r[j], g[k]->out.r[j]), 1e-13);
				ENSURE_LE(mk_rel(f[k]->out.w[j], g[k]->out.w[j]), 1e-13);
			}
			for (int j = 0; j < 3; ++j)
				ENSURE(f[k]->sg[j] == g[k]->sg[j]);
		}
		mkPairAt e;
		e.a1 = g1;
		e.a2 = g2;
		double G[2][2];
		mkPair_Tangent(&c, &e, t1, t2, G);
		double amax = fmax(fabs(A[0]), fmax(fabs(A[1]), fabs(A[2])));
		ENSURE_LE(fabs(A[0] - G[0][0]), 1e-11 * amax);
		ENSURE_LE(fabs(A[1] - G[0][1]), 1e-11 * amax);
		ENSURE_LE(fabs(A[2] - G[1][1]), 1e-11 * amax);
		if (axis) {
			++axis_checked;
			continue; /* the support functions are not smooth across the axes */
		}
		/* central differences of x along the tangents (truncation and
		 * rounding both below 1e-6 relative at h = 1e-5, as in
		 * test_jacobian) */
		double h = 1e-5;
		mkVec3 col[2];
		mkVec3 t[2] = { t1, t2 };
		for (int j = 0; j < 2; ++j)
			col[j] = mkVec3_Scale(mkVec3_Sub(mk_pair_x(b1, b2, mkVec3_Add(n, mkVec3_Scale(t[j], h))),
				mk_pair_x(b1, b2, mkVec3_Sub(n, mkVec3_Scale(t[j], h)))), 0.5 / h);
		double fd[3] = { mkVec3_Dot(t1, col[0]), 0.5 * (mkVec3_Dot(t1, col[1]) + mkVec3_Dot(t2, col[0])),
			mkVec3_Dot(t2, col[1]) };
		for (int i = 0; i < 3; ++i)
			ENSURE_LE(fabs(A[i] - fd[i]), 1e-4 * amax + 1e-9);
		++fd_checked;
	}
	ENSURE(fd_checked == 350 && axis_checked == 50);
}

int main(void)
{
	test_jacobian();
	test_support_edges();
	test_pair_pass();
	return mk_summary("test_collision_support");
}
