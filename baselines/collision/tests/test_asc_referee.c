/* test_asc_referee.c - the closed-form ASC entry and the referee's bracket.
 *
 * References (none of them computed by the code under test):
 *  - FCL's ellipsoid cases: semi-axes (20, 40, 50) at the origin and a sphere
 *    of radius 10 at x on the x axis: sd = x - 30 exactly (the support values
 *    along x are 20 and 10); the pair rotated and translated together keeps
 *    sd (a rigid motion), in both argument orders;
 *  - two spheres: sd = |d| - r1 - r2 (overlapping too: the depth of two balls
 *    is r1 + r2 - |d|, along the centre line);
 *  - two axis-aligned superquadrics on the x axis, exponents near 0.1 (nearly
 *    box-shaped, nearly kinked support functions) and near 1.9: the x extent
 *    of a superquadric is its semi-axis a, attained at (a, 0, 0), and by the
 *    pair's symmetry the normal is the x axis: sd = x - a1 - a2;
 *  - ASC on random ellipsoid pairs against asc-eigen (Eigen's eigenvalues of
 *    A^-1 B, no code shared) and against the referee where the referee is
 *    certain; near-touching ellipsoid pairs built at a signed distance of
 *    s * scale by moving B2 along minksum-normal's normal (the optimum normal
 *    of a separated pair is unchanged by that move, so the distance is s *
 *    scale up to the rounding of the answer, ~1e-15 of the scale; moved
 *    further than touching the pair overlaps for certain).
 * Tolerances: the referee's bracket is asserted to contain the hand value
 * within 1e-13 of the scale (its target width is 1e-14; support points
 * carry ~1e-16 of the scale); ASC's status must be right wherever |sd| >
 * 1e-11 of the scale (its rounding band is a few 1e-14 of the size). */
#include <mink/colliders.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "draw_paper.h"
#include "ensure.h"

static mkContact mk_run_status(const char *name, mkBody3 b1, mkBody3 b2, mkCollision3 *o)
{
	mkColliderScratch s;
	mkResult r = mkCollider_Run(mkColliders_Find(name), b1, b2, &s, o);
	ENSURE(r == MK_OK);
	return r == MK_OK ? o->status : MK_CONTACT_UNKNOWN;
}

/* The referee on a pair of known sd: certain, and its bracket holds sd. */
static void mk_check_referee(mkBody3 b1, mkBody3 b2, double sd, const char *what)
{
	mkCollision3 o;
	mk_run_status("referee", b1, b2, &o);
	double scale = mkCollide3_PairSize(b1, b2), tol = 1e-13 * scale;
	int ok = o.bound <= sd + tol && fabs(o.distance - sd) <= tol;
	if (sd > 1e-12 * scale) {
		/* Separated: certain, [bound, bound + gap] holds sd, and the upper
		 * bound is the distance of the returned points. */
		ok &= o.status == MK_CONTACT_SEPARATED && o.residual <= 1e-13;
		ok &= o.bound + o.gap >= sd - tol;
		ok &= fabs(mkVec3_Length(mkVec3_Sub(o.p2, o.p1)) - (o.bound + o.gap)) <= tol;
	} else if (sd < -1e-12 * scale) {
		ok &= o.status == MK_CONTACT_OVERLAPPING && o.residual == 0.0;
	}
	ENSURE(ok);
	if (!ok)
		fprintf(stderr, "  referee on %s: sd %.17g, got %s %.17g gap %.3g residual %.3g\n", what, sd,
			mkContact_Name(o.status), o.distance, o.gap, o.residual);
}

static void test_fcl_cases(void)
{
	const double *xs = mkFclCaseX;
	unsigned long long seed = 5;
	for (int rot = 0; rot < 12; ++rot) {
		mkMat3 R = rot == 0 ? mkMat3_Identity() : mk_test_rotation(&seed);
		mkVec3 shift = rot < 2 ? mkVec3_Make(0, 0, 0)
			: mkVec3_Make(mk_test_uniform(&seed, -50, 50), mk_test_uniform(&seed, -50, 50), mk_test_uniform(&seed, -50, 50));
		for (size_t k = 0; k < sizeof mkFclCaseX / sizeof mkFclCaseX[0]; ++k) {
			mkBody3 A, B;
			mk_test_fcl_case(R, shift, xs[k], &A, &B);
			double sd = xs[k] - 30.0;
			mkContact want = sd > 0 ? MK_CONTACT_SEPARATED : sd < 0 ? MK_CONTACT_OVERLAPPING : MK_CONTACT_TOUCHING;
			for (int order = 0; order < 2; ++order) {
				mkBody3 b1 = order ? B : A, b2 = order ? A : B;
				mkCollision3 o;
				mkContact got = mk_run_status("asc", b1, b2, &o);
				ENSURE(got == want);
				if (got != want)
					fprintf(stderr, "  asc on FCL x = %g, rotation %d, order %d: %s (residual %.3g)\n", xs[k], rot, order,
						mkContact_Name(got), o.residual);
				if (rot < 4) {
					char what[64];
					snprintf(what, sizeof what, "FCL x = %g, rotation %d, order %d", xs[k], rot, order);
					mk_check_referee(b1, b2, sd, what);
				}
			}
		}
	}
}

static void test_referee_hand(void)
{
	/* Two spheres, separated, near touching and overlapping. */
	const double dd[] = { 9.0, 5.0, 4.0 + 1e-9, 3.5, 1.0 };
	unsigned long long seed = 11;
	for (size_t k = 0; k < sizeof dd / sizeof dd[0]; ++k) {
		mkShape3 s1 = { 2.5, 2.5, 2.5, 1, 1 }, s2 = { 1.5, 1.5, 1.5, 1, 1 };
		mkVec3 u = mkVec3_Normalize(
			mkVec3_Make(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1)));
		mkVec3 c1 = mkVec3_Make(1, -2, 3);
		mkBody3 b1 = mkBody3_Make(s1, mk_test_rotation(&seed), c1);
		mkBody3 b2 = mkBody3_Make(s2, mk_test_rotation(&seed), mkVec3_Add(c1, mkVec3_Scale(u, dd[k])));
		double sd = mkVec3_Length(mkVec3_Sub(b2.t, b1.t)) - 4.0;
		char what[64];
		snprintf(what, sizeof what, "two spheres %g apart", dd[k]);
		mk_check_referee(b1, b2, sd, what);
	}
	/* Superquadrics on the x axis: nearly boxes (eps 0.1), nearly
	 * octahedra (eps 1.9), mixed; sd = x - a1 - a2. */
	const double e[3][2] = { { 0.1, 0.1 }, { 1.9, 1.9 }, { 0.1, 1.9 } };
	const double xs[] = { 12.0, 8.0 + 1e-3, 8.0 + 1e-7, 7.0 };
	for (int i = 0; i < 3; ++i)
		for (size_t k = 0; k < sizeof xs / sizeof xs[0]; ++k) {
			mkShape3 s1 = { 5, 3, 4, e[i][0], e[i][1] }, s2 = { 3, 2, 1, e[i][1], e[i][0] };
			mkBody3 b1 = mkBody3_Make(s1, mkMat3_Identity(), mkVec3_Make(0, 0, 0));
			mkBody3 b2 = mkBody3_Make(s2, mkMat3_Identity(), mkVec3_Make(xs[k], 0, 0));
			char what[64];
			snprintf(what, sizeof what, "superquadrics eps %g/%g at x = %g", e[i][0], e[i][1], xs[k]);
			if (xs[k] > 8.0)
				mk_check_referee(b1, b2, xs[k] - 8.0, what);
			else {
				/* Overlapping by 1 along x: certified, and the depth is at most 1
				 * (the translation by 1 along x separates them). */
				mkCollision3 o;
				ENSURE(mk_run_status("referee", b1, b2, &o) == MK_CONTACT_OVERLAPPING);
				ENSURE(o.residual == 0.0);
				ENSURE(o.distance >= -1.0 - 1e-12);
			}
		}
}

/* Needle against plate (aspect ratios 1e5 to 3e5), crossed, on the x axis:
 * the extents along x are the semi-axes 0.002 and 300, and by symmetry the
 * normal is x: sd = x - 300.002; the pair moved rigidly keeps it. ASC must
 * never be on the wrong side (touching allowed: its band is wide here). */
static void test_needle_plate(void)
{
	mkShape3 needle = { 0.002, 500, 0.003, 1, 1 }, plate = { 300, 0.001, 200, 1, 1 };
	const double gaps[] = { 1.0, 1e-3, 1e-6, -1e-3 };
	unsigned long long seed = 23;
	for (int rot = 0; rot < 4; ++rot) {
		mkMat3 R = rot == 0 ? mkMat3_Identity() : mk_test_rotation(&seed);
		for (size_t k = 0; k < sizeof gaps / sizeof gaps[0]; ++k) {
			mkBody3 b1 = mkBody3_Make(needle, R, mkVec3_Make(0, 0, 0));
			mkBody3 b2 = mkBody3_Make(plate, R, mkMat3_MulVec(R, mkVec3_Make(300.002 + gaps[k], 0, 0)));
			char what[64];
			snprintf(what, sizeof what, "needle and plate, gap %g, rotation %d", gaps[k], rot);
			if (gaps[k] > 0) {
				mk_check_referee(b1, b2, gaps[k], what);
			} else {
				/* Overlapping by 1e-3 along x: certified. */
				mkCollision3 o;
				ENSURE(mk_run_status("referee", b1, b2, &o) == MK_CONTACT_OVERLAPPING);
				ENSURE(o.residual == 0.0);
			}
			mkCollision3 a;
			mkContact got = mk_run_status("asc", b1, b2, &a);
			ENSURE(got == MK_CONTACT_TOUCHING || got == (gaps[k] > 0 ? MK_CONTACT_SEPARATED : MK_CONTACT_OVERLAPPING));
		}
	}
}

/* ASC against asc-eigen and the referee on random ellipsoid pairs. */
static void test_asc_random(void)
{
	unsigned long long seed = 4242;
	int disagree_eigen = 0, uncertain = 0, sep = 0, ovl = 0;
	for (int trial = 0; trial < 400; ++trial) {
		mkBody3 b1, b2;
		mk_test_paper_pair3(&seed, 1, trial % 5 == 4, &b1, &b2);
		mkCollision3 a, e, r;
		mkContact sa = mk_run_status("asc", b1, b2, &a);
		mkContact se = mk_run_status("asc-eigen", b1, b2, &e);
		mk_run_status("referee", b1, b2, &r);
		double scale = mkCollide3_PairSize(b1, b2);
		if (!(r.residual <= 1e-10)) {
			++uncertain;
			continue;
		}
		if (fabs(r.distance) > 1e-9 * scale) {
			mkContact want = r.distance > 0 ? MK_CONTACT_SEPARATED : MK_CONTACT_OVERLAPPING;
			ENSURE(sa == want);
			sep += want == MK_CONTACT_SEPARATED;
			ovl += want == MK_CONTACT_OVERLAPPING;
			/* asc-eigen does not tell touching apart (overlapping). */
			disagree_eigen += (se == MK_CONTACT_SEPARATED) != (sa == MK_CONTACT_SEPARATED);
		}
	}
	printf("asc on 400 random ellipsoid pairs: %d separated, %d overlapping by the referee, %d uncertain; "
		"%d differ from asc-eigen\n", sep, ovl, uncertain, disagree_eigen);
	ENSURE(uncertain == 0);
	ENSURE(disagree_eigen == 0);
	ENSURE(sep > 100 && ovl > 50);
}

/* ASC near touching: pairs at +-s * scale, s down to 1e-11. */
static void test_asc_near(void)
{
	unsigned long long seed = 77;
	const double seps[] = { 1e-3, 1e-6, 1e-8, 1e-10, 1e-11, -1e-11, -1e-10, -1e-8, -1e-6 };
	int wrong = 0, runs = 0;
	for (int trial = 0; trial < 60; ++trial) {
		mkBody3 b1, b2;
		mk_test_paper_pair3(&seed, 1, 0, &b1, &b2);
		mkCollision3 c;
		ENSURE(mkCollide3_Normal(b1, b2, &c) == MK_OK);
		if (!(c.distance > 0))
			continue;
		for (size_t k = 0; k < sizeof seps / sizeof seps[0]; ++k) {
			mkBody3 b3 = b2;
			b3.t = mkVec3_Add(b2.t, mkVec3_Scale(c.normal, seps[k] * c.scale - c.distance));
			for (int order = 0; order < 2; ++order) {
				mkCollision3 o;
				mkContact got = mk_run_status("asc", order ? b3 : b1, order ? b1 : b3, &o);
				mkContact want = seps[k] > 0 ? MK_CONTACT_SEPARATED : MK_CONTACT_OVERLAPPING;
				++runs;
				if (got != want) {
					++wrong;
					fprintf(stderr, "  asc near touching, trial %d at %g (order %d): %s, residual %.3g\n", trial, seps[k],
						order, mkContact_Name(got), o.residual);
				}
			}
		}
	}
	printf("asc near touching: %d of %d wrong\n", wrong, runs);
	ENSURE(wrong == 0);
}

int main(void)
{
	test_fcl_cases();
	test_referee_hand();
	test_needle_plate();
	test_asc_random();
	test_asc_near();
	return mk_summary("test_asc_referee");
}
