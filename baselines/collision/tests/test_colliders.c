/* test_colliders.c - every entry of the collider registry (mink/colliders.h).
 *
 * References:
 *  - FCL's own ellipsoid test cases: semi-axes (20, 40, 50) and a sphere of
 *    radius 10 moved along x; the signed distance is x - 30 exactly (support
 *    values 20 and 10 along x), for the pair rotated together about the
 *    origin too, and in both argument orders;
 *  - random pairs of the paper's draw, ellipsoids and superquadrics, against
 *    the referee (GJK bracket and global search over the support maps only);
 *  - near-touching pairs: a pair moved along the answer's normal to a signed
 *    distance of s * scale, s = 1e-1 ... 1e-6, which is exact (the optimum
 *    normal of a separated pair does not change under that move);
 *  - ASC in closed form against ASC by Eigen's eigenvalues and the referee.
 * Each entry has its own accuracy, set below from what it can do: the exact
 * queries to rounding, the peers to their documented tolerances (measured
 * on these cases; see docs/collide.md). A failure (no verdict) is counted
 * and must stay within the entry's allowance, which is 0 for the core's
 * queries and the referee. */
#include <mink/colliders.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ensure.h"

typedef struct mkTol {
	const char *name;
	double margin;  /* |sd| above this (times scale) must get the right status */
	double dist;    /* distance error allowed (times scale) */
	double pen;     /* penetration error allowed (times scale) */
} mkTol;

/* Margins and tolerances relative to the scale (about 100 in FCL's cases):
 *  - core queries and the referee: rounding (the referee's pattern search
 *    resolves its optimum to about 1e-13 of the scale on smooth optima);
 *  - LM queries: the paper's residual 1e-10, their status from the sign of a
 *    converged residual; Common Normal's distance at its 1e-10 residual;
 *  - Implicit: it calls 'overlapping' below 1e-3 of distance (absolute),
 *    Ipopt's tol 1e-10 on the scaled problem gives ~1e-9 on the distance;
 *  - libccd: MPR/EPA stop at 1e-4 (their defaults); MPR's depth is
 *    measured along its portal's direction, not minimised, so only its
 *    status is checked; EPA's depth on deep superquadric overlaps was off by
 *    up to 2e-2 of the scale here; GJK's intersection
 *    test is exact up to rounding of the support points but needs the
 *    origin clear of the simplex by its own 1e-6 tolerance;
 *  - FCL: distance_tolerance 1e-6 (measured errors up to 4e-7 of scale);
 *  - gjk-poly: a 10 x 10 grid polytope inscribed in the bodies, whose
 *    distance from the smooth surface is up to about 5% of a semi-axis. */
static const mkTol mkTols[] = {
	{ "minksum-normal", 1e-12, 1e-12, 1e-12 },
	{ "minksum-ray", 1e-12, 0, 0 },
	{ "minksum-normal-lm", 1e-9, 0, 0 },
	{ "minksum-ray-lm", 1e-9, 0, 0 },
	{ "common-normal", 1e-9, 1e-9, 0 },
	{ "implicit", 2e-5, 1e-7, 0 },
	{ "gjk-poly", 5e-2, 0, 0 },
	{ "ccd-gjk", 1e-7, 0, 0 },
	{ "ccd-mpr", 1e-5, 0, 0 },
	{ "ccd-gjk-epa", 1e-5, 0, 5e-2 },
	{ "fcl", 1e-7, 1e-6, 1e-6 },
	{ "asc", 1e-12, 0, 0 },
	{ "asc-eigen", 1e-8, 0, 0 },
	{ "referee", 1e-12, 1e-12, 1e-12 },
};

static const mkTol *mkTolOf(const char *name)
{
	for (size_t i = 0; i < sizeof mkTols / sizeof mkTols[0]; ++i)
		if (strcmp(mkTols[i].name, name) == 0)
			return &mkTols[i];
	return NULL;
}

static mkMat3 mk_rand_rot(unsigned long long *seed)
{
	double q[4];
	for (int i = 0; i < 4; ++i)
		q[i] = mk_test_uniform(seed, -1.0, 1.0);
	return mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
}

static int mkFails[32], mkWrong[32], mkRuns[32];

/* The entries whose answers are asserted: the core's queries, the closed-form
 * ASC and the referee. The peers are measured: their wrong answers (status,
 * or distance/penetration beyond the tolerance above) are counted and
 * printed, since they are properties of those libraries, not bugs here. */
static int mk_strict(const char *name)
{
	return strcmp(name, "minksum-normal") == 0 || strcmp(name, "minksum-ray") == 0 || strcmp(name, "asc") == 0
		|| strcmp(name, "referee") == 0;
}

/* Run entry c on the pair whose true signed distance is sd and check what it
 * returns against sd. */
static void mk_check_entry(const mkCollider *c, mkBody3 b1, mkBody3 b2, double sd, const char *what)
{
	const mkTol *t = mkTolOf(c->name);
	ENSURE(t != NULL);
	if (!t)
		return;
	mkColliderScratch scratch;
	mkCollision3 o;
	mkResult r = mkCollider_Run(c, b1, b2, &scratch, &o);
	double scale = mkCollide3_Scale(b1, b2);
	int idx = -1;
	for (int i = 0; i < mkColliders_Count(); ++i)
		if (mkColliders_At(i) == c)
			idx = i;
	if (idx < 0)
		return;
	mkRuns[idx] += 1;
	if (r != MK_OK) {
		/* No verdict: said so, and counted. */
		ENSURE(o.status == MK_CONTACT_UNKNOWN);
		mkFails[idx] += 1;
		if (mk_strict(c->name)) {
			fprintf(stderr, "  %s on %s: %s (residual %g, %d iterations)\n", c->name, what, mkResult_Name(r), o.residual,
				o.iterations);
			const mkBody3 *bb[2] = { &b1, &b2 };
			for (int k = 0; k < 2; ++k) {
				const mkBody3 *b = bb[k];
				fprintf(stderr, "    body%d: superquadric a=%.17g b=%.17g c=%.17g eps1=%.17g eps2=%.17g M=", k + 1, b->shape.a,
					b->shape.b, b->shape.c, b->shape.eps1, b->shape.eps2);
				for (int i = 0; i < 9; ++i)
					fprintf(stderr, "%.17g%s", b->M.m[i / 3][i % 3], i < 8 ? "," : "");
				fprintf(stderr, " at=%.17g,%.17g,%.17g\n", b->t.x, b->t.y, b->t.z);
			}
		}
		return;
	}
	int wrong = 0;
	if (fabs(sd) > t->margin * scale) {
		mkContact want = sd > 0.0 ? MK_CONTACT_SEPARATED : MK_CONTACT_OVERLAPPING;
		wrong |= o.status != want;
	}
	if (t->dist > 0.0 && (c->gives & MK_GIVES_DISTANCE) && sd > t->margin * scale && o.status == MK_CONTACT_SEPARATED)
		wrong |= !(fabs(o.distance - sd) <= t->dist * scale);
	if (t->pen > 0.0 && (c->gives & MK_GIVES_PENETRATION) && sd < -t->margin * scale && o.status == MK_CONTACT_OVERLAPPING)
		wrong |= !(fabs(o.distance - sd) <= t->pen * scale);
	mkWrong[idx] += wrong;
	if (mk_strict(c->name)) {
		ENSURE(!wrong);
		if (wrong)
			fprintf(stderr, "  %s on %s: true sd %.17g, status %s, distance %.17g\n", c->name, what, sd,
				mkContact_Name(o.status), o.distance);
	}
}

static void test_registry(void)
{
	ENSURE(mkColliders_Count() >= 14);
	ENSURE(mkColliders_Count() <= 32);
	int referees = 0;
	for (int i = 0; i < mkColliders_Count(); ++i) {
		const mkCollider *c = mkColliders_At(i);
		ENSURE(c && c->name && c->summary && c->params && c->run);
		ENSURE(mkColliders_Find(c->name) == c);
		ENSURE(c->gives & MK_GIVES_STATUS);
		ENSURE(mkTolOf(c->name) != NULL);
		referees += c->referee;
	}
	ENSURE(referees == 1);
	ENSURE(mkColliders_Find("nosuch") == NULL);
	ENSURE(mkColliders_At(-1) == NULL && mkColliders_At(mkColliders_Count()) == NULL);
	ENSURE(mkColliders_Find("minksum-normal") && mkColliders_Find("asc"));
	/* ASC refuses superquadrics with a message naming the body. */
	mkShape3 sq = { 1, 1, 1, 0.5, 1 }, el = { 1, 1, 1, 1, 1 };
	mkBody3 b1 = mkBody3_Make(el, mkMat3_Identity(), mkVec3_Make(0, 0, 0));
	mkBody3 b2 = mkBody3_Make(sq, mkMat3_Identity(), mkVec3_Make(3, 0, 0));
	char msg[256];
	ENSURE(!mkCollider_Accepts(mkColliders_Find("asc"), b1, b2, msg, sizeof msg));
	ENSURE(strstr(msg, "body2") != NULL);
	mkColliderScratch s;
	mkCollision3 o;
	ENSURE(mkCollider_Run(mkColliders_Find("asc"), b1, b2, &s, &o) == MK_ERR_UNSUPPORTED);
	ENSURE(o.status == MK_CONTACT_UNKNOWN);
}

static void test_fcl_cases(void)
{
	const double xs[] = { 40.0, 30.1, 30.0, 29.9, 29.99, 0.0 };
	mkShape3 s1 = { 20, 40, 50, 1, 1 }, s2 = { 10, 10, 10, 1, 1 };
	unsigned long long seed = 17;
	for (int rot = 0; rot < 3; ++rot) {
		mkMat3 R = rot == 0 ? mkMat3_Identity() : mk_rand_rot(&seed);
		for (size_t k = 0; k < sizeof xs / sizeof xs[0]; ++k) {
			mkBody3 A = mkBody3_Make(s1, R, mkVec3_Make(0, 0, 0));
			mkBody3 B = mkBody3_Make(s2, R, mkMat3_MulVec(R, mkVec3_Make(xs[k], 0, 0)));
			for (int order = 0; order < 2; ++order) {
				char what[96];
				snprintf(what, sizeof what, "FCL case x = %g, rotation %d, order %d", xs[k], rot, order);
				for (int i = 0; i < mkColliders_Count(); ++i) {
					const mkCollider *c = mkColliders_At(i);
					mkBody3 b1 = order ? B : A, b2 = order ? A : B;
					mk_check_entry(c, b1, b2, xs[k] - 30.0, what);
					/* Touching (x = 30): the exact entries say so. */
					if (xs[k] == 30.0 && (strcmp(c->name, "minksum-normal") == 0 || strcmp(c->name, "minksum-ray") == 0
						|| strcmp(c->name, "asc") == 0)) {
						mkColliderScratch s;
						mkCollision3 o;
						ENSURE(mkCollider_Run(c, b1, b2, &s, &o) == MK_OK);
						ENSURE(o.status == MK_CONTACT_TOUCHING);
					}
				}
			}
		}
	}
}

/* The paper's draw (experiments/collision.c's ranges). */
static void mk_draw(unsigned long long *seed, int ell, int near, mkBody3 *b1, mkBody3 *b2)
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
	*b1 = mkBody3_Make(s1, mk_rand_rot(seed), c1);
	*b2 = mkBody3_Make(s2, mk_rand_rot(seed), c2);
}

/* Random pairs against the referee, for the fast entries (the slow LM and
 * Ipopt peers run on FCL's cases above and in the benchmark). */
static void test_random_pairs(void)
{
	const char *fast[] = { "minksum-normal", "minksum-ray", "ccd-gjk", "ccd-mpr", "ccd-gjk-epa", "fcl", "asc", "asc-eigen" };
	const mkCollider *referee = mkColliders_Find("referee");
	unsigned long long seed = 2022;
	int below = 0;
	for (int trial = 0; trial < 160; ++trial) {
		int ell = trial % 2 == 0, deep = trial % 4 == 1;
		mkBody3 b1, b2;
		mk_draw(&seed, ell, deep, &b1, &b2);
		mkColliderScratch s;
		mkCollision3 ref, mine;
		ENSURE(mkCollider_Run(referee, b1, b2, &s, &ref) == MK_OK);
		ENSURE(mkCollider_Run(mkColliders_Find("minksum-normal"), b1, b2, &s, &mine) == MK_OK);
		/* Both are lower bounds of sd evaluated at their own normals, so the
		 * Newton answer is never below the referee's (beyond rounding); on
		 * separated pairs it also lies within the referee's certified
		 * bracket [bound, bound + gap]; and the referee's search does not
		 * stop short of it (it did, on nearly kinked superquadrics, when
		 * the referee was a pattern search). */
		ENSURE_LE(ref.distance - mine.distance, 1e-12 * mine.scale);
		if (ref.distance > 0.0) {
			ENSURE(ref.residual <= 1e-10);
			ENSURE_LE(mine.distance, ref.bound + ref.gap + 1e-12 * mine.scale);
		}
		if (mine.distance - ref.distance > 1e-10 * mine.scale)
			++below;
		char what[64];
		snprintf(what, sizeof what, "random %s pair %d", ell ? "ellipsoid" : "superquadric", trial);
		for (size_t k = 0; k < sizeof fast / sizeof fast[0]; ++k) {
			const mkCollider *c = mkColliders_Find(fast[k]);
			if (mkCollider_Accepts(c, b1, b2, NULL, 0))
				mk_check_entry(c, b1, b2, mine.distance, what);
		}
	}
	printf("random pairs: the referee's search stopped short of the Newton answer on %d of 160\n", below);
	ENSURE(below == 0);
}

static void test_near_touching(void)
{
	unsigned long long seed = 99;
	const double seps[] = { 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6 };
	const char *exact[] = { "minksum-normal", "minksum-ray", "asc", "asc-eigen", "ccd-gjk", "fcl" };
	for (int trial = 0; trial < 24; ++trial) {
		int ell = trial % 2 == 0;
		mkBody3 b1, b2;
		mk_draw(&seed, ell, 0, &b1, &b2);
		mkCollision3 c;
		ENSURE(mkCollide3_Normal(b1, b2, &c) == MK_OK);
		for (size_t k = 0; k < sizeof seps / sizeof seps[0]; ++k) {
			mkBody3 b3 = b2;
			double want = seps[k] * c.scale;
			b3.t = mkVec3_Add(b2.t, mkVec3_Scale(c.normal, want - c.distance));
			char what[64];
			snprintf(what, sizeof what, "near-touching pair %d at %g", trial, seps[k]);
			for (size_t e = 0; e < sizeof exact / sizeof exact[0]; ++e) {
				const mkCollider *col = mkColliders_Find(exact[e]);
				if (mkCollider_Accepts(col, b1, b3, NULL, 0))
					mk_check_entry(col, b1, b3, want, what);
			}
		}
	}
}

int main(void)
{
	test_registry();
	test_fcl_cases();
	test_random_pairs();
	test_near_touching();
	printf("%-18s %6s %8s %6s\n", "entry", "runs", "no-verdict", "wrong");
	for (int i = 0; i < mkColliders_Count(); ++i)
		printf("%-18s %6d %8d %6d\n", mkColliders_At(i)->name, mkRuns[i], mkFails[i], mkWrong[i]);
	/* The core's queries, the closed-form ASC and the referee never fail. */
	for (int i = 0; i < mkColliders_Count(); ++i) {
		const char *n = mkColliders_At(i)->name;
		if (strncmp(n, "minksum-normal", 15) == 0 || strcmp(n, "minksum-ray") == 0 || strcmp(n, "asc") == 0
			|| strcmp(n, "referee") == 0)
			ENSURE(mkFails[i] == 0);
	}
	return mk_summary("test_colliders");
}
