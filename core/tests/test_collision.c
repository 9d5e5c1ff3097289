/* test_collision.c - mink/collision.h's queries: MinkSum (Normal) in each
 * build this processor can run, its warm start, and MinkSum (Ray). The
 * support map they iterate on: test_collision_support.c.
 *
 * References, none of them sharing code with the solver:
 *  - FCL's ellipsoid test cases (semi-axes (20, 40, 50) and (10, 10, 10),
 *    the second moved along x): with axis-aligned bodies the signed distance
 *    is x - 30 exactly (the support values along x are 20 and 10), and a
 *    common rotation of the pair about the origin does not change it;
 *  - two spheres: sd = |c2 - c1| - r1 - r2;
 *  - random paper-draw pairs: the answer must be stationary (no direction
 *    found by a grid and a pattern search over mkCollide3_Bound, which is
 *    built on mkBody3_SupportValue, beats it by more than 1e-12 of the
 *    scale), its witness points must lie on the bodies (gauge from
 *    mkBody3_Implicit within 1e-9), and the two-sided certificate must hold;
 *  - ellipsoid pairs (their own code path) against the general superquadric
 *    code on exponents 1 - 1e-12. */
#include <mink/mink.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "draw3.h"
#include "ensure.h"

/* The solver's two builds (collision_impl.h): every test of MinkSum
 * (Normal) below runs once per build this processor can run (main), through
 * mk_normal; mkCollide3_NormalFrom goes through the library's own choice. */
#include "collide/collision_impl.h"
static mkImpl mk_build = MK_IMPL_SCALAR;
static mkResult mk_normal(mkBody3 b1, mkBody3 b2, mkCollision3 *out)
{
	return mkCollide3_NormalImpl(mk_build, b1, b2, NULL, out);
}

/* The gauge of a placed body at x: Psi^(eps1/2), 1 on the boundary. */
static double mk_gauge(mkBody3 b, mkVec3 x)
{
	return pow(mkBody3_Implicit(b, x), 0.5 * b.shape.eps1);
}

/* FCL's ellipsoid cases. */
static void test_fcl_cases(void)
{
	const double xs[] = { 40.0, 30.1, 30.0, 29.9, 29.99, 0.0 };
	mkShape3 s1 = { 20, 40, 50, 1, 1 }, s2 = { 10, 10, 10, 1, 1 };
	unsigned long long seed = 5;
	for (int rot = 0; rot < 6; ++rot) {
		mkMat3 R = rot == 0 ? mkMat3_Identity() : mk_test_rotation(&seed);
		for (int k = 0; k < (int)(sizeof xs / sizeof xs[0]); ++k) {
			double want = xs[k] - 30.0;
			mkVec3 c2 = mkMat3_MulVec(R, mkVec3_Make(xs[k], 0, 0));
			mkBody3 A = mkBody3_Make(s1, R, mkVec3_Make(0, 0, 0));
			mkBody3 B = mkBody3_Make(s2, R, c2);
			for (int order = 0; order < 2; ++order) {
				mkBody3 b1 = order ? B : A, b2 = order ? A : B;
				mkCollision3 c;
				mkResult r = mk_normal(b1, b2, &c);
				ENSURE(r == MK_OK);
				/* Rounding of the rotated poses: a few ulps of the scale (~100). */
				ENSURE_NEAR(c.distance, want, 1e-12 * c.scale);
				mkContact st = xs[k] > 30.0 ? MK_CONTACT_SEPARATED : xs[k] == 30.0 ? MK_CONTACT_TOUCHING
					: MK_CONTACT_OVERLAPPING;
				ENSURE(c.status == st);
				if (r == MK_OK && c.status == MK_CONTACT_SEPARATED) {
					ENSURE_NEAR(mkVec3_Length(mkVec3_Sub(c.p2, c.p1)), want, 1e-12 * c.scale);
					ENSURE_LE(c.gap, 1e-12 * c.scale);
				}
				if (r == MK_OK) {
					ENSURE_NEAR(mk_gauge(b1, c.p1), 1.0, 1e-12);
					ENSURE_NEAR(mk_gauge(b2, c.p2), 1.0, 1e-12);
				}
				mkCollision3 ray;
				r = mkCollide3_Ray(b1, b2, &ray);
				ENSURE(r == MK_OK);
				if (xs[k] != 0.0) {
					/* Along x the boundary of the contact space is at 30. */
					ENSURE_NEAR(ray.directional, want, 1e-12 * ray.scale);
					ENSURE(ray.status == st);
				} else {
					ENSURE(ray.status == MK_CONTACT_OVERLAPPING);
				}
			}
		}
	}
}

static void test_spheres(void)
{
	unsigned long long seed = 99;
	for (int k = 0; k < 50; ++k) {
		double r1 = mk_test_uniform(&seed, 0.5, 5), r2 = mk_test_uniform(&seed, 0.5, 5);
		mkShape3 s1 = { r1, r1, r1, 1, 1 }, s2 = { r2, r2, r2, 1, 1 };
		mkVec3 c1 = mkVec3_Make(mk_test_uniform(&seed, -5, 5), mk_test_uniform(&seed, -5, 5), mk_test_uniform(&seed, -5, 5));
		mkVec3 c2 = mkVec3_Make(mk_test_uniform(&seed, -5, 5), mk_test_uniform(&seed, -5, 5), mk_test_uniform(&seed, -5, 5));
		mkBody3 b1 = mkBody3_Make(s1, mk_test_rotation(&seed), c1), b2 = mkBody3_Make(s2, mk_test_rotation(&seed), c2);
		double dist = mkVec3_Length(mkVec3_Sub(c2, c1));
		mkCollision3 c;
		ENSURE(mk_normal(b1, b2, &c) == MK_OK);
		/* A sphere containing the other's centre: the depth is still
		 * r1 + r2 - |d| (translate along the centre line). */
		ENSURE_NEAR(c.distance, dist - r1 - r2, 1e-12 * c.scale);
	}
}

/* The best f over a 30 x 60 grid of directions, refined by a pattern search
 * (steps that gain more than 1e-15 relative, at most 20000 evaluations):
 * a global estimate of sd from mkCollide3_Bound only. */
static double mk_brute(mkBody3 b1, mkBody3 b2)
{
	double best = -INFINITY;
	mkVec3 bn = mkVec3_Make(0, 0, 1);
	for (int i = 0; i < 30; ++i)
		for (int j = 0; j < 60; ++j) {
			double eta = -MK_PI / 2 + MK_PI * (i + 0.5) / 30, om = 2 * MK_PI * j / 60;
			mkVec3 n = mkVec3_Make(cos(eta) * cos(om), cos(eta) * sin(om), sin(eta));
			double v = mkCollide3_Bound(b1, b2, n);
			if (v > best) {
				best = v;
				bn = n;
			}
		}
	double step = 0.1;
	int evals = 0;
	while (step > 1e-12 && evals < 20000) {
		mkVec3 a = fabs(bn.x) < 0.6 ? mkVec3_Make(1, 0, 0) : mkVec3_Make(0, 1, 0);
		mkVec3 t1 = mkVec3_Normalize(mkVec3_Cross(bn, a)), t2 = mkVec3_Cross(bn, t1);
		int moved = 0;
		for (int k = 0; k < 4 && !moved; ++k) {
			mkVec3 t = k < 2 ? t1 : t2;
			mkVec3 c = mkVec3_Normalize(mkVec3_Add(bn, mkVec3_Scale(t, k % 2 ? -step : step)));
			double v = mkCollide3_Bound(b1, b2, c);
			++evals;
			if (v > best + 1e-15 * (1.0 + fabs(best))) {
				best = v;
				bn = c;
				moved = 1;
			}
		}
		if (!moved)
			step *= 0.5;
	}
	return best;
}

/* The shapes of the paper's collision draws, in this order: semi-axes
 * U(1,11)^3 and U(1,6)^3, then (unless ellipsoids) eps1, eps2 ~ U(0.1,1.9)
 * for each body. */
static void draw_shapes(unsigned long long *seed, int ellipsoids, mkShape3 *s1, mkShape3 *s2)
{
	*s1 = (mkShape3){ mk_test_uniform(seed, 1, 11), mk_test_uniform(seed, 1, 11), mk_test_uniform(seed, 1, 11), 1, 1 };
	*s2 = (mkShape3){ mk_test_uniform(seed, 1, 6), mk_test_uniform(seed, 1, 6), mk_test_uniform(seed, 1, 6), 1, 1 };
	if (ellipsoids)
		return;
	s1->eps1 = mk_test_uniform(seed, 0.1, 1.9);
	s1->eps2 = mk_test_uniform(seed, 0.1, 1.9);
	s2->eps1 = mk_test_uniform(seed, 0.1, 1.9);
	s2->eps2 = mk_test_uniform(seed, 0.1, 1.9);
}

static void test_random_pairs(void)
{
	unsigned long long seed = 2022;
	int sep = 0, ovl = 0, fails = 0, wrong = 0;
	for (int trial = 0; trial < 300; ++trial) {
		int ell = trial % 2 == 0;
		mkShape3 s1, s2;
		draw_shapes(&seed, ell, &s1, &s2);
		mkVec3 c1 = mkVec3_Make(mk_test_uniform(&seed, -5, 5), mk_test_uniform(&seed, -5, 5), mk_test_uniform(&seed, -5, 5));
		mkVec3 c2 = mkVec3_Make(mk_test_uniform(&seed, 5, 15), mk_test_uniform(&seed, 5, 15), mk_test_uniform(&seed, 5, 15));
		mkBody3 b1 = mkBody3_Make(s1, mk_test_rotation(&seed), c1), b2 = mkBody3_Make(s2, mk_test_rotation(&seed), c2);
		mkCollision3 c;
		mkResult r = mk_normal(b1, b2, &c);
		if (r != MK_OK) {
			++fails;
			fprintf(stderr, "trial %d: %s (residual %g, iterations %d)\n", trial, mkResult_Name(r), c.residual, c.iterations);
			continue;
		}
		double ref = mk_brute(b1, b2);
		/* The solver's direction is a true bound (independent evaluation). */
		ENSURE_NEAR(mkCollide3_Bound(b1, b2, c.normal), c.distance, 1e-12 * c.scale);
		/* Nobody finds a better direction. */
		ENSURE_LE(ref - c.distance, 1e-12 * c.scale);
		if (c.distance - ref > 1e-9 * c.scale) {
			/* The solver's f is a proven lower bound of sd, so this is
			 * the brute force missing the optimum: reported, not failed. */
			++wrong;
			fprintf(stderr, "trial %d (%s): distance %.17g, brute force %.17g\n", trial, ell ? "ellipsoids" : "superquadrics",
				c.distance, ref);
		}
		ENSURE_NEAR(mk_gauge(b1, c.p1), 1.0, 1e-9);
		ENSURE_NEAR(mk_gauge(b2, c.p2), 1.0, 1e-9);
		if (c.status == MK_CONTACT_SEPARATED) {
			++sep;
			/* The gap is >= 0 up to the rounding of |p2 - p1| and f. */
			ENSURE_LE(-1e-14 * c.scale, c.gap);
			ENSURE_LE(c.gap, 1e-10 * c.scale);
		} else if (c.status == MK_CONTACT_OVERLAPPING) {
			++ovl;
		}
		mkCollision3 ray;
		r = mkCollide3_Ray(b1, b2, &ray);
		ENSURE(r == MK_OK);
		if (r != MK_OK)
			fprintf(stderr, "trial %d: ray %s (residual %g, iterations %d)\n", trial, mkResult_Name(r), ray.residual, ray.iterations);
		if (fabs(c.distance) > 1e-9 * c.scale)
			ENSURE(ray.status == c.status);
	}
	printf("random pairs: %d separated, %d overlapping, %d failed, %d below the brute force\n", sep, ovl, fails, wrong);
	ENSURE(fails == 0);
}

/* Box-like pairs (every exponent in [0.05, 0.3], the paper's sizes and
 * separated centres): nearly flat faces and nearly kinked support
 * functions, where the normal does not pin down where on a face the nearest
 * points lie. References independent of the solver: the grid and pattern
 * search on mkCollide3_Bound (mk_brute) and the implicit function (the
 * gauge). Checked: the answer's bound is a true bound and nobody finds a
 * better direction; the witness points lie on the boundaries and their span
 * exceeds the distance by at most 1e-10 of the scale, for separated pairs
 * (the code before the hull iteration left up to 4.9e-4 of the scale here,
 * and failed on one pair);
 * MinkSum (Ray) gives the same status, and B2 moved back along the centre
 * line by Ray's directional gap touches B1, where Ray converged (it ran out
 * of iterations on 2 of these pairs, zigzagging across a kink: its status
 * is certain then, its gap is not resolved; mink/collision.h). */
static void test_boxlike_pairs(void)
{
	unsigned long long seed = 77;
	int sep = 0, stalled = 0;
	double worst = 0.0;
	for (int trial = 0; trial < 40; ++trial) {
		mkBody3 b1, b2;
		mk_test_pair3(&seed, 0.05, 0.3, &b1, &b2);
		mkCollision3 c, ray;
		ENSURE(mk_normal(b1, b2, &c) == MK_OK);
		ENSURE(mkCollide3_Ray(b1, b2, &ray) == MK_OK);
		if (c.status != MK_CONTACT_SEPARATED)
			continue;
		++sep;
		ENSURE_NEAR(mkCollide3_Bound(b1, b2, c.normal), c.distance, 1e-12 * c.scale);
		/* (on a nearly kinked ridge the solver stops when its value stalls,
		 * within about 2e-12 of the scale of the optimum) */
		double ref = mk_brute(b1, b2);
		ENSURE_LE(ref - c.distance, 1e-11 * c.scale);
		ENSURE_NEAR(mk_gauge(b1, c.p1), 1.0, 1e-9);
		ENSURE_NEAR(mk_gauge(b2, c.p2), 1.0, 1e-9);
		double span = mkVec3_Length(mkVec3_Sub(c.p2, c.p1));
		ENSURE_LE(span - c.distance, 1e-10 * c.scale);
		ENSURE_LE(c.gap, 1e-10 * c.scale);
		if (span - c.distance > worst * c.scale)
			worst = (span - c.distance) / c.scale;
		ENSURE(ray.status == c.status);
		if (ray.iterations >= MK_COLLIDE3_MAX_ITER) {
			/* Ray stalled on a kink: its status is certain, its gap is not
			 * resolved (mink/collision.h) */
			++stalled;
			continue;
		}
		mkBody3 b3 = b2;
		b3.t = mkVec3_Sub(b2.t, mkVec3_Scale(mkVec3_Normalize(mkVec3_Sub(b2.t, b1.t)), ray.directional));
		mkCollision3 touch;
		ENSURE(mk_normal(b1, b3, &touch) == MK_OK);
		ENSURE_LE(fabs(touch.distance), 1e-10 * touch.scale);
	}
	printf("box-like pairs: %d separated of 40, largest witness span over the distance %.2g of the scale, "
		"Ray stalled (status only) on %d\n", sep, worst, stalled);
	ENSURE(sep >= 30);
	ENSURE(stalled <= 2);
}

/* Overlapping pairs (centres within 3 of each other): the penetration
 * depth has several local optima; the answer must match the global grid
 * search within 1e-9 of the scale (the pattern search itself stops at
 * steps of 1e-12, so it resolves f to about 1e-12 of the scale on smooth
 * optima). */
static void test_overlaps(void)
{
	unsigned long long seed = 4242;
	int missed = 0, count = 0;
	for (int trial = 0; trial < 100; ++trial) {
		int ell = trial % 2 == 0;
		mkShape3 s1, s2;
		draw_shapes(&seed, ell, &s1, &s2);
		mkVec3 c2 = mkVec3_Make(mk_test_uniform(&seed, -3, 3), mk_test_uniform(&seed, -3, 3), mk_test_uniform(&seed, -3, 3));
		mkBody3 b1 = mkBody3_Make(s1, mk_test_rotation(&seed), mkVec3_Make(0, 0, 0)), b2 = mkBody3_Make(s2, mk_test_rotation(&seed), c2);
		mkCollision3 c;
		mkResult r = mk_normal(b1, b2, &c);
		ENSURE(r == MK_OK);
		if (r != MK_OK)
			continue;
		++count;
		ENSURE(c.status == MK_CONTACT_OVERLAPPING);
		ENSURE_NEAR(mkCollide3_Bound(b1, b2, c.normal), c.distance, 1e-12 * c.scale);
		double ref = mk_brute(b1, b2);
		if (ref - c.distance > 1e-9 * c.scale) {
			++missed;
			fprintf(stderr, "overlap trial %d (%s): depth %.17g, grid search %.17g\n", trial, ell ? "ellipsoids" : "superquadrics",
				-c.distance, -ref);
		}
		/* The depth is certified global: sd in [bound, bound + gap] with
		 * gap <= MK_COLLIDE3_GLOBAL_TOL * scale (plus rounding), and the
		 * grid search (mkCollide3_Bound only, no code of the certificate)
		 * finds nothing above the upper end. */
		ENSURE(c.certified == 1);
		ENSURE_LE(-1e-14 * c.scale, c.gap);
		ENSURE_LE(c.gap, (MK_COLLIDE3_GLOBAL_TOL + 1e-14) * c.scale);
		ENSURE_LE(ref, c.bound + c.gap + 1e-13 * c.scale);
		mkCollision3 ray;
		ENSURE(mkCollide3_Ray(b1, b2, &ray) == MK_OK && ray.status == MK_CONTACT_OVERLAPPING);
	}
	printf("overlaps: %d solved, %d where the grid search found a smaller depth\n", count, missed);
	ENSURE(missed == 0);
}

/* The overlap certificate on box-like bodies (every exponent in [0.05, 0.3]:
 * nearly flat faces, so f has nearly kinked ridges, where the certificate
 * prunes with mixtures of two planes): deep overlaps (centres within 2 of
 * each other per axis). Whatever the certificate says, [bound, bound + gap]
 * must hold: no direction of a dense grid (96 x 192), of 3000 random
 * directions within 0.05 rad of the answer's normal, or found by the grid
 * and pattern search mk_brute, all valued by mkCollide3_Bound alone (no
 * code of the certificate), may lie above bound + gap. */
static void test_boxlike_overlaps(void)
{
	unsigned long long seed = 515;
	int certified = 0, count = 0;
	double worst = -INFINITY;
	for (int trial = 0; trial < 24; ++trial) {
		mkBody3 b1, b2;
		mk_test_pair3(&seed, 0.05, 0.3, &b1, &b2);
		b2.t = mkVec3_Add(b1.t, mkVec3_Make(mk_test_uniform(&seed, -2, 2), mk_test_uniform(&seed, -2, 2),
			mk_test_uniform(&seed, -2, 2)));
		mkCollision3 c;
		ENSURE(mk_normal(b1, b2, &c) == MK_OK);
		if (c.status != MK_CONTACT_OVERLAPPING) {
			ENSURE(c.status == MK_CONTACT_OVERLAPPING);
			continue;
		}
		++count;
		certified += c.certified == 1;
		if (c.certified == 1)
			ENSURE_LE(c.gap, (MK_COLLIDE3_GLOBAL_TOL + 1e-14) * c.scale);
		ENSURE(isfinite(c.gap) && c.gap >= -1e-14 * c.scale);
		double top = c.bound + c.gap + 1e-13 * c.scale, seen = -INFINITY;
		for (int i = 0; i < 96; ++i)
			for (int j = 0; j < 192; ++j) {
				double eta = -MK_PI / 2 + MK_PI * (i + 0.5) / 96, om = 2 * MK_PI * (j + 0.5) / 192;
				double v = mkCollide3_Bound(b1, b2, mkVec3_Make(cos(eta) * cos(om), cos(eta) * sin(om), sin(eta)));
				seen = v > seen ? v : seen;
			}
		mkVec3 t1, t2, n = c.normal;
		t1 = mkVec3_Normalize(mkVec3_Cross(n, fabs(n.x) < 0.6 ? mkVec3_Make(1, 0, 0) : mkVec3_Make(0, 1, 0)));
		t2 = mkVec3_Cross(n, t1);
		for (int k = 0; k < 3000; ++k) {
			double r = 0.05 * mk_test_uniform(&seed, 0, 1), a = 2 * MK_PI * mk_test_uniform(&seed, 0, 1);
			mkVec3 m = mkVec3_Add(n, mkVec3_Add(mkVec3_Scale(t1, r * cos(a)), mkVec3_Scale(t2, r * sin(a))));
			double v = mkCollide3_Bound(b1, b2, mkVec3_Normalize(m));
			seen = v > seen ? v : seen;
		}
		/* and the grid and pattern search of the other overlap tests, which
		 * climbs to the local maximum of its best grid direction */
		double climbed = mk_brute(b1, b2);
		seen = climbed > seen ? climbed : seen;
		ENSURE_LE(seen, top);
		if ((seen - c.bound) / c.scale > worst)
			worst = (seen - c.bound) / c.scale;
	}
	printf("box-like overlaps: %d, certified %d; the largest sampled f above the answer: %.2g of the scale\n", count,
		certified, worst);
	ENSURE(count == 24);
}

/* Two hand cases of the overlap certificate. (1) A long, thin, box-like
 * superquadric (semi-axes 6, 1.5, 1; eps1 = eps2 = 0.2) inside a sphere of
 * radius 8, its centre offset by delta = 0.05 along its shortest axis u
 * (both bodies under one random rotation). The depth in direction n is
 * D(n) = 8 + h2(-n) - <n, d>. A superquadric with eps1, eps2 <= 1 contains
 * the ellipsoid with its semi-axes, whose support function is at least the
 * smallest semi-axis, so h2 >= 1 and D(n) >= 8 + 1 - delta for every n,
 * with equality at n = u (h2(-u) = 1, the tip of the axis): the depth is
 * 8.95 exactly, sd = -8.95. The opposite direction -u is a second local
 * minimum, D(-u) = 9.05 (checked below), and the sides along the middle
 * axis a third (9.5). (2) The same sphere with a concentric spheroid
 * (6, 1, 1): D(n) = 8 + h2(n) is 9 on the whole circle orthogonal to the
 * long axis, a ring of global minima the branch and bound can only resolve
 * triangle by triangle: its budget runs out, which the answer must say
 * (certified 0) while its bracket [bound, bound + gap] still holds. */
static void test_overlap_certificate_hand(void)
{
	unsigned long long seed = 777;
	for (int k = 0; k < 4; ++k) {
		mkMat3 Q = mk_test_rotation(&seed);
		mkShape3 ball = { 8, 8, 8, 1, 1 }, bar = { 6, 1.5, 1, 0.2, 0.2 };
		mkVec3 u = mkMat3_MulVec(Q, mkVec3_Make(0, 0, 1));
		mkBody3 b1 = mkBody3_Make(ball, mk_test_rotation(&seed), mkVec3_Make(0, 0, 0));
		mkBody3 b2 = mkBody3_Make(bar, Q, mkVec3_Scale(u, 0.05));
		/* the competitor: f(-u) = -D(-u) (rounding of the rotation: ulps) */
		ENSURE_NEAR(mkCollide3_Bound(b1, b2, mkVec3_Neg(u)), -9.05, 1e-13);
		ENSURE_NEAR(mkCollide3_Bound(b1, b2, u), -8.95, 1e-13);
		for (int order = 0; order < 2; ++order) {
			mkCollision3 c;
			ENSURE(mk_normal(order ? b2 : b1, order ? b1 : b2, &c) == MK_OK);
			ENSURE_NEAR(c.distance, -8.95, 1e-12 * c.scale);
			ENSURE(c.status == MK_CONTACT_OVERLAPPING);
			ENSURE(c.certified == 1);
			ENSURE_LE(c.gap, (MK_COLLIDE3_GLOBAL_TOL + 1e-14) * c.scale);
			/* the true sd -8.95 lies in the bracket */
			ENSURE_LE(c.bound, -8.95 + 1e-12 * c.scale);
			ENSURE_LE(-8.95, c.bound + c.gap + 1e-12 * c.scale);
			ENSURE(c.cert_evals > 0);
		}
		mkShape3 rod = { 6, 1, 1, 1, 1 };
		mkBody3 b3 = mkBody3_Make(rod, Q, mkVec3_Make(0, 0, 0));
		mkCollision3 c;
		ENSURE(mk_normal(b1, b3, &c) == MK_OK);
		ENSURE_NEAR(c.distance, -9.0, 1e-12 * c.scale);
		ENSURE(c.certified == 0);
		ENSURE(c.cert_evals >= MK_COLLIDE3_CERT_EVALS - 4);
		ENSURE(isfinite(c.gap));
		ENSURE_LE(-9.0, c.bound + c.gap + 1e-12 * c.scale);
		printf("ring of minima: certified %d after %d evaluations, bracket width %.3g of the scale\n", c.certified,
			c.cert_evals, c.gap / c.scale);
	}
}

/* Ellipsoid pairs take their own code (support through Q = M diag(a,b,c)^2 M^T
 * and a Newton loop in 3D); a superquadric with eps1 = eps2 = 1 - 1e-12 is
 * the same body up to 1e-12 of its size and takes the general code (pair
 * norms, tangent-plane Newton and trust region). The reference for each
 * ellipsoid pair is that general answer: |d log|p|_q / dq| <= ln(3) / q^2
 * bounds each support value's change by about 0.3 |q - 2| |p|, so the signed
 * distances differ by at most about 1.1e-12 of the scale (tolerance 1e-11);
 * statuses agree outside that band. Separated, overlapping and sheared pairs. */
static void test_ellipsoid_path(void)
{
	unsigned long long seed = 777;
	const double near1 = 1.0 - 1e-12;
	double worst = 0.0;
	for (int trial = 0; trial < 240; ++trial) {
		mkShape3 s1, s2;
		draw_shapes(&seed, 1, &s1, &s2);
		int kind = trial % 3; /* 0 separated draws, 1 overlapping, 2 sheared */
		double lo = kind == 1 ? -2.0 : 5.0, hi = kind == 1 ? 2.0 : 15.0;
		mkVec3 c1 = mkVec3_Make(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1));
		mkVec3 c2 = mkVec3_Make(mk_test_uniform(&seed, lo, hi), mk_test_uniform(&seed, lo, hi), mk_test_uniform(&seed, lo, hi));
		mkMat3 M1 = mk_test_rotation(&seed), M2 = mk_test_rotation(&seed);
		if (kind == 2) {
			mkMat3 S = mkMat3_Identity();
			S.m[0][1] = mk_test_uniform(&seed, -0.8, 0.8);
			S.m[1][2] = mk_test_uniform(&seed, -0.8, 0.8);
			S.m[2][2] = mk_test_uniform(&seed, 0.5, 1.5);
			M1 = mkMat3_Mul(M1, S);
			M2 = mkMat3_Mul(S, M2);
		}
		mkBody3 e1 = mkBody3_Make(s1, M1, c1), e2 = mkBody3_Make(s2, M2, c2);
		mkBody3 g1 = e1, g2 = e2;
		g1.shape.eps1 = g1.shape.eps2 = g2.shape.eps1 = g2.shape.eps2 = near1;
		mkCollision3 ce, cg;
		ENSURE(mk_normal(e1, e2, &ce) == MK_OK);
		ENSURE(mk_normal(g1, g2, &cg) == MK_OK);
		double diff = fabs(ce.distance - cg.distance) / ce.scale;
		ENSURE_LE(diff, 1e-11);
		if (diff > worst)
			worst = diff;
		if (fabs(cg.distance) > 1e-11 * cg.scale)
			ENSURE(ce.status == cg.status);
		/* The ellipsoid answer is a bound (independent evaluation). */
		ENSURE_NEAR(mkCollide3_Bound(e1, e2, ce.normal), ce.distance, 1e-12 * ce.scale);
		ENSURE_NEAR(mk_gauge(e1, ce.p1), 1.0, 1e-9);
		ENSURE_NEAR(mk_gauge(e2, ce.p2), 1.0, 1e-9);
	}
	printf("ellipsoid path: largest |sd - sd(eps = 1 - 1e-12)| = %.2e of the scale\n", worst);
}

/* Bodies under general linear maps (shear and uneven scaling, not only
 * rotations): the same stationarity check against the grid search. */
static void test_general_maps(void)
{
	unsigned long long seed = 31;
	for (int trial = 0; trial < 40; ++trial) {
		mkShape3 s1 = { mk_test_uniform(&seed, 1, 5), mk_test_uniform(&seed, 1, 5), mk_test_uniform(&seed, 1, 5),
			mk_test_uniform(&seed, 0.3, 1.7), mk_test_uniform(&seed, 0.3, 1.7) };
		mkShape3 s2 = { mk_test_uniform(&seed, 1, 4), mk_test_uniform(&seed, 1, 4), mk_test_uniform(&seed, 1, 4), 1, 1 };
		mkMat3 S = mkMat3_Identity();
		S.m[0][1] = mk_test_uniform(&seed, -0.8, 0.8);
		S.m[1][2] = mk_test_uniform(&seed, -0.8, 0.8);
		S.m[2][2] = mk_test_uniform(&seed, 0.5, 1.5);
		mkBody3 b1 = mkBody3_Make(s1, mkMat3_Mul(mk_test_rotation(&seed), S), mkVec3_Make(0, 0, 0));
		mkVec3 c2 = mkVec3_Make(mk_test_uniform(&seed, -9, 9), mk_test_uniform(&seed, -9, 9), mk_test_uniform(&seed, -9, 9));
		mkBody3 b2 = mkBody3_Make(s2, mkMat3_Mul(S, mk_test_rotation(&seed)), c2);
		mkCollision3 c;
		ENSURE(mk_normal(b1, b2, &c) == MK_OK);
		ENSURE_NEAR(mkCollide3_Bound(b1, b2, c.normal), c.distance, 1e-12 * c.scale);
		ENSURE_LE(mk_brute(b1, b2) - c.distance, 1e-12 * c.scale);
		ENSURE_NEAR(mk_gauge(b1, c.p1), 1.0, 1e-9);
		ENSURE_NEAR(mk_gauge(b2, c.p2), 1.0, 1e-9);
		mkCollision3 ray;
		ENSURE(mkCollide3_Ray(b1, b2, &ray) == MK_OK);
		if (fabs(c.distance) > 1e-9 * c.scale)
			ENSURE(ray.status == c.status);
	}
}

/* Near-touching pairs: B2 is moved along the answer's normal so that the
 * signed distance becomes delta * scale; the new distance must follow. */
static void test_near_touching(void)
{
	unsigned long long seed = 77;
	const double deltas[] = { 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-8, 1e-10, -1e-8, -1e-10 };
	for (int trial = 0; trial < 40; ++trial) {
		int ell = trial % 2 == 0;
		mkShape3 s1, s2;
		draw_shapes(&seed, ell, &s1, &s2);
		mkBody3 b1 = mkBody3_Make(s1, mk_test_rotation(&seed), mkVec3_Make(0, 0, 0));
		mkVec3 dir = mkVec3_Normalize(mkVec3_Make(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1)));
		mkBody3 b2 = mkBody3_Make(s2, mk_test_rotation(&seed), mkVec3_Scale(dir, 30.0));
		mkCollision3 c;
		ENSURE(mk_normal(b1, b2, &c) == MK_OK);
		for (int k = 0; k < (int)(sizeof deltas / sizeof deltas[0]); ++k) {
			/* Translating B2 by t n changes sd by exactly t when n stays
			 * the optimal normal, which it does (f(n) shifts by t for
			 * every n by <n, t n> only at n itself, and the optimum of a
			 * separated pair moves continuously; here the witnesses stay). */
			double want = deltas[k] * c.scale;
			mkBody3 b3 = b2;
			b3.t = mkVec3_Add(b2.t, mkVec3_Scale(c.normal, want - c.distance));
			mkCollision3 e;
			mkResult r = mk_normal(b1, b3, &e);
			ENSURE(r == MK_OK);
			ENSURE_NEAR(e.distance, want, 1e-12 * e.scale);
			ENSURE(e.status == (want > 0 ? MK_CONTACT_SEPARATED : MK_CONTACT_OVERLAPPING));
		}
	}
}

/* mkCollide3_NormalFrom: the same answer from any start. Two spheres (sd by
 * hand) from the worst start, the opposite of the answer; random separated
 * and overlapping pairs from (a) the answer at a nearby pose (body 2 moved
 * by 1e-2 of the scale and turned by about 0.01 rad), (b) a random
 * direction, (c) the reversed answer: each within 1e-12 of the scale of the
 * grid and pattern search (mkCollide3_Bound only), a true bound at its own
 * normal, the status of the start-free query, overlaps certified; started
 * at its own answer the solver must do less work than from the centre line;
 * a start of length 1e300 or 1e-310 is a direction like any other; a zero
 * or non-finite start is refused. */
static void test_warm_start(void)
{
	unsigned long long seed = 777;
	mkShape3 sphere1 = { 1, 1, 1, 1, 1 }, sphere2 = { 2, 2, 2, 1, 1 };
	mkVec3 u = mkVec3_Normalize(mkVec3_Make(0.3, -0.5, 0.8));
	mkBody3 s1 = mkBody3_Make(sphere1, mkMat3_Identity(), mkVec3_Make(1, 2, 3));
	mkBody3 s2 = mkBody3_Make(sphere2, mk_test_rotation(&seed), mkVec3_Add(mkVec3_Make(1, 2, 3), mkVec3_Scale(u, 10)));
	mkCollision3 c;
	ENSURE(mkCollide3_NormalFrom(s1, s2, mkVec3_Neg(u), &c) == MK_OK);
	ENSURE_NEAR(c.distance, 7.0, 1e-14 * c.scale);
	ENSURE(c.status == MK_CONTACT_SEPARATED);
	/* -u is the minimum of f = 10 cos(angle to u) - 3: no ascent from there,
	 * so the answer comes from the centre line, counted as a restart */
	ENSURE(c.restarts == 1);
	int cold_iters = 0, warm_iters = 0, count = 0;
	for (int trial = 0; trial < 60; ++trial) {
		int ell = trial % 3 == 0, overlap = trial % 4 == 3;
		mkShape3 a, b;
		draw_shapes(&seed, ell, &a, &b);
		double lo = overlap ? -2 : 5, hi = overlap ? 2 : 15;
		mkVec3 c2 = mkVec3_Make(mk_test_uniform(&seed, lo, hi), mk_test_uniform(&seed, lo, hi), mk_test_uniform(&seed, lo, hi));
		mkBody3 b1 = mkBody3_Make(a, mk_test_rotation(&seed), mkVec3_Make(0, 0, 0));
		mkMat3 R = mk_test_rotation(&seed);
		mkBody3 b2 = mkBody3_Make(b, R, c2);
		/* the nearby pose: moved and turned a little */
		double sc = mkCollide3_PairSize(b1, b2);
		mkVec3 step = mkVec3_Scale(mkVec3_Normalize(mkVec3_Make(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1),
			mk_test_uniform(&seed, -1, 1))), 1e-2 * sc);
		mkMat3 turn = mkMat3_FromQuat(1.0, 0.005, -0.004, 0.003);
		mkBody3 b2n = mkBody3_Make(b, mkMat3_Mul(turn, R), mkVec3_Add(c2, step));
		mkCollision3 cold, prev, warm;
		ENSURE(mk_normal(b1, b2, &cold) == MK_OK);
		ENSURE(mk_normal(b1, b2n, &prev) == MK_OK);
		double ref = mk_brute(b1, b2);
		mkVec3 starts[3] = { prev.normal,
			mkVec3_Make(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1)),
			mkVec3_Neg(cold.normal) };
		for (int k = 0; k < 3; ++k) {
			mkResult r = mkCollide3_NormalFrom(b1, b2, starts[k], &warm);
			ENSURE(r == MK_OK);
			if (r != MK_OK) {
				fprintf(stderr, "warm start trial %d, start %d: %s\n", trial, k, mkResult_Name(r));
				continue;
			}
			++count;
			ENSURE_NEAR(mkCollide3_Bound(b1, b2, warm.normal), warm.distance, 1e-12 * warm.scale);
			ENSURE_LE(ref - warm.distance, 1e-12 * warm.scale);
			ENSURE_NEAR(warm.distance, cold.distance, 1e-12 * warm.scale);
			ENSURE(warm.status == cold.status);
			if (warm.status == MK_CONTACT_OVERLAPPING)
				ENSURE(warm.certified == 1);
		}
		/* from its own answer */
		ENSURE(mkCollide3_NormalFrom(b1, b2, cold.normal, &warm) == MK_OK);
		ENSURE_NEAR(warm.distance, cold.distance, 1e-12 * warm.scale);
		if (cold.status == MK_CONTACT_SEPARATED) {
			cold_iters += cold.iterations;
			warm_iters += warm.iterations;
		}
	}
	printf("warm starts: %d answers equal to the start-free ones; iterations on separated pairs from their answer %d, "
	       "from the centre line %d\n", count, warm_iters, cold_iters);
	ENSURE(count == 180);
	ENSURE(2 * warm_iters < cold_iters);
	/* any finite nonzero length is a direction, however large or small */
	mkVec3 off = mkVec3_Add(u, mkVec3_Make(0.3, 0.2, -0.1));
	mkVec3 far[2] = { mkVec3_Scale(off, 1e300), mkVec3_Scale(off, 1e-310) };
	for (int k = 0; k < 2; ++k) {
		ENSURE(mkCollide3_NormalFrom(s1, s2, far[k], &c) == MK_OK);
		ENSURE_NEAR(c.distance, 7.0, 1e-14 * c.scale);
		ENSURE(c.restarts == 0); /* the start itself ended there, no fallback */
	}
	mkVec3 bad[3] = { mkVec3_Make(0, 0, 0), mkVec3_Make(NAN, 0, 1), mkVec3_Make(INFINITY, 0, 0) };
	for (int k = 0; k < 3; ++k) {
		ENSURE(mkCollide3_NormalFrom(s1, s2, bad[k], &c) == MK_ERR_ARGUMENT);
		ENSURE(c.status == MK_CONTACT_UNKNOWN && isnan(c.distance));
	}
}

static void test_failures_reported(void)
{
	mkShape3 s = { 1, 1, 1, 1, 1 };
	mkMat3 M = mkMat3_Identity();
	mkBody3 b1 = mkBody3_Make(s, M, mkVec3_Make(0, 0, 0));
	mkBody3 b2 = mkBody3_Make(s, M, mkVec3_Make(NAN, 0, 0));
	mkCollision3 c;
	mkResult r = mk_normal(b1, b2, &c);
	ENSURE(r != MK_OK);
	ENSURE(c.status == MK_CONTACT_UNKNOWN);
	ENSURE(isnan(c.distance));
	r = mkCollide3_Ray(b1, b2, &c);
	ENSURE(r != MK_OK);
	ENSURE(c.status == MK_CONTACT_UNKNOWN);
	/* Coincident centres: a deep overlap, answered. */
	b2.t = mkVec3_Make(0, 0, 0);
	ENSURE(mk_normal(b1, b2, &c) == MK_OK);
	ENSURE_NEAR(c.distance, -2.0, 1e-12);
	ENSURE(mkCollide3_Ray(b1, b2, &c) == MK_OK && c.status == MK_CONTACT_OVERLAPPING);
	ENSURE(strcmp(mkContact_Name(MK_CONTACT_TOUCHING), "touching") == 0);
}

/* The two builds on the same pairs: the same status and certificate, the
 * distance within rounding (1e-12 of the scale; measured at most 2.2e-16 on
 * 2000 paper pairs), on separated and overlapping draws. */
static void test_builds_agree(void)
{
	unsigned long long seed = 97;
	for (int trial = 0; trial < 600; ++trial) {
		mkBody3 b1, b2;
		mk_test_pair3(&seed, 0.1, 1.9, &b1, &b2);
		if (trial % 3 == 0)
			b2.t = mkVec3_Scale(mkVec3_Add(b1.t, b2.t), 0.5); /* overlapping */
		mkCollision3 p, f;
		ENSURE(mkCollide3_NormalImpl(MK_IMPL_SCALAR, b1, b2, NULL, &p) == MK_OK);
		ENSURE(mkCollide3_NormalImpl(MK_IMPL_AVX2, b1, b2, NULL, &f) == MK_OK);
		ENSURE(p.status == f.status && p.certified == f.certified);
		ENSURE_LE(fabs(p.distance - f.distance), 1e-12 * p.scale);
	}
}

int main(void)
{
	int fma = mkImpl_Available(MK_IMPL_AVX2) && strcmp(mkCollide3_Build(), "fma") == 0;
	for (int pass = 0; pass < 2; ++pass) {
		if (pass == 1 && !fma) {
			printf("test_collision: NOTE the solver's FMA build is not tested here (%s)\n",
				mkImpl_Available(MK_IMPL_AVX2) ? "the library was configured without it" : "this processor lacks AVX2 or FMA");
			break;
		}
		mk_build = pass == 0 ? MK_IMPL_SCALAR : MK_IMPL_AVX2;
		printf("test_collision: MinkSum (Normal), %s build\n", pass == 0 ? "portable" : "fma");
		test_fcl_cases();
		test_spheres();
		test_random_pairs();
		test_boxlike_pairs();
		test_overlaps();
		test_boxlike_overlaps();
		test_overlap_certificate_hand();
		test_general_maps();
		test_ellipsoid_path();
		test_near_touching();
		test_failures_reported();
	}
	test_warm_start();
	if (fma)
		test_builds_agree();
	return mk_summary("test_collision");
}
