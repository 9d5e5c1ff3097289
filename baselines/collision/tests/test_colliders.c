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
 *  - box-like pairs (every exponent U(0.05, 0.3)) against the referee: the
 *    core queries' status and distance, and witness points that are the
 *    nearest points;
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

#include "draw3.h"
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
 *    up to 2e-2 of the scale here, with tolerances tightened as well (the
 *    ccd-gjk-epa-1e-* entries: their depth errors on deep superquadric
 *    overlaps stop near 2e-7 of the scale at the median and keep EPA's
 *    rare wrong faces, up to 0.1); GJK's intersection
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
	{ "ccd-gjk-epa-1e-6", 1e-5, 0, 5e-2 },
	{ "ccd-gjk-epa-1e-8", 1e-5, 0, 5e-2 },
	{ "ccd-gjk-epa-1e-10", 1e-5, 0, 5e-2 },
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
		mkMat3 R = rot == 0 ? mkMat3_Identity() : mk_test_rotation(&seed);
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
	*b1 = mkBody3_Make(s1, mk_test_rotation(seed), c1);
	*b2 = mkBody3_Make(s2, mk_test_rotation(seed), c2);
}

/* Random pairs against the referee, for the fast entries (the slow LM and
 * Ipopt peers run on FCL's cases above and in the benchmark). */
static void test_random_pairs(void)
{
	const char *fast[] = { "minksum-normal", "minksum-ray", "ccd-gjk", "ccd-mpr", "ccd-gjk-epa", "ccd-gjk-epa-1e-10", "fcl", "asc",
		"asc-eigen" };
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
		if (ref.distance < 0.0) {
			/* overlaps: the core's depth is certified global, so its upper
			 * end bound + gap is not below the referee's lower bound */
			ENSURE(mine.certified == 1);
			ENSURE_LE(ref.distance, mine.bound + mine.gap + 1e-13 * mine.scale);
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

/* Box-like pairs (every exponent in [0.05, 0.3]; nearly flat faces) against
 * the referee: both core queries give its status, MinkSum (Normal) its
 * distance within 1e-10 of the scale, and witness points whose span is
 * within 1e-10 of the scale of the referee's distance (so they are the
 * nearest points, not just points of the right faces). */
static void test_boxlike_pairs(void)
{
	const mkCollider *referee = mkColliders_Find("referee");
	unsigned long long seed = 31;
	double worst = 0.0;
	int sep = 0;
	for (int trial = 0; trial < 30; ++trial) {
		mkBody3 b1, b2;
		mk_test_pair3(&seed, 0.05, 0.3, &b1, &b2);
		mkColliderScratch s;
		mkCollision3 ref, mine, ray;
		ENSURE(mkCollider_Run(referee, b1, b2, &s, &ref) == MK_OK);
		ENSURE(mkCollide3_Normal(b1, b2, &mine) == MK_OK);
		ENSURE(mkCollide3_Ray(b1, b2, &ray) == MK_OK);
		if (!(ref.gap <= 1e-10 * ref.scale) || fabs(ref.distance) <= 1e-9 * ref.scale)
			continue; /* the referee not certain, or within the status margin */
		ENSURE(mine.status == ref.status);
		ENSURE(ray.status == ref.status);
		ENSURE_NEAR(mine.distance, ref.distance, 1e-10 * mine.scale);
		if (ref.status != MK_CONTACT_SEPARATED)
			continue;
		++sep;
		double span = mkVec3_Length(mkVec3_Sub(mine.p2, mine.p1));
		ENSURE_NEAR(span, ref.distance, 1e-10 * mine.scale);
		if (fabs(span - ref.distance) > worst * mine.scale)
			worst = fabs(span - ref.distance) / mine.scale;
	}
	printf("box-like pairs: %d separated and certain, witness span within %.2g of the scale of the referee's distance\n", sep,
		worst);
	ENSURE(sep >= 20);
}

/* The three deep overlaps of the collision experiment (kind deep, seed
 * 2022: trials 935, 1251 and 6479) on which the Newton restarts alone ended
 * in a local optimum of the depth (errors 1.2e-3, 6.7e-3 and 6.5e-2 of the
 * scale against the referee). The bodies as the experiment draws them
 * (shape a, b, c, eps1, eps2; centre; matrix row by row), written exactly.
 * Reference: the referee, whose depth search (a 2000-direction sweep and
 * local ascents on the support maps) shares no code with the core's branch
 * and bound; its answer is a lower bound of sd evaluated at its own normal,
 * so both must agree to rounding: within 1e-10 of the scale (the target of
 * the experiment; measured 4e-13 at most, on 6479, a nearly kinked body).
 * The core's certified upper end bound + gap must not be below the
 * referee's lower bound either. */
typedef struct mkHexBody { double shape[5], t[3], m[9]; } mkHexBody;
static const struct { long trial; mkHexBody b1, b2; } mkDeepPairs[] = {
	{ 935,
	  { { 0x1.2631e6d9848fcp+2, 0x1.b68018c871c9ap+2, 0x1.3a02898898628p+3, 0x1.b7d6c8310aacap+0, 0x1.4ef2250d5a0dap-2 },
	    { 0x1.99d46797ace44p-2, -0x1.210947f63b9d8p-1, -0x1.089e865d1bd28p-3 },
	    { 0x1.51a8d4aa0dfbep-2, -0x1.86dbc475c65f2p-1, 0x1.1c60773ff41d3p-1,
	      0x1.bf336f4e48196p-1, 0x1.e1402398a9ea8p-2, 0x1.04ea76d3adad5p-3,
	      -0x1.6ee38b514b7d5p-2, 0x1.c5c0fbf3f2508p-2, 0x1.a4bc7bf8d00f5p-1 } },
	  { { 0x1.44442d340170dp+2, 0x1.8b4511e5f1f3cp+0, 0x1.4548ee15a02ebp+1, 0x1.c05a2694a66p-2, 0x1.8ed7e9e6b5a77p+0 },
	    { 0x1.05f462a32074ap+0, 0x1.0975b40337e7p-1, 0x1.5949ca28f4938p-1 },
	    { -0x1.7f9083f6e88fp-3, 0x1.8bc8f3588101cp-4, 0x1.f48044dd7ea04p-1,
	      0x1.f69e5385334ccp-1, -0x1.197f5cdea0fp-6, 0x1.84aa55aa17a3p-3,
	      0x1.1fcf6d5fc4658p-5, 0x1.fd873ab2099fcp-1, -0x1.775a468561b6p-4 } } },
	{ 1251,
	  { { 0x1.6fb2d148a28a7p+2, 0x1.94c8e387644bdp+2, 0x1.e5b7eecaedd1ep+1, 0x1.e2d36792c4e98p-2, 0x1.498211fb08f57p+0 },
	    { 0x1.50461e123ca66p-1, 0x1.cd22b5da2249p-4, 0x1.2d842b507b594p-2 },
	    { 0x1.e2d33e1a95cep-5, -0x1.f7fd7ccc75553p-1, 0x1.540da804dbd0ap-3,
	      0x1.fe4a1ed56170bp-1, 0x1.8e29afd6da6ap-5, -0x1.0cd7c8f0fd9b8p-4,
	      0x1.cf299cc30eb9fp-5, 0x1.5ad7054e470ecp-3, 0x1.f7c5eed19a8edp-1 } },
	  { { 0x1.5f161ae4d0decp+1, 0x1.6948e32a43f6dp+2, 0x1.23f07d509306ap+2, 0x1.5a8133f978275p-1, 0x1.b9bd9d77b450ep+0 },
	    { -0x1.e9aea5a57a074p+0, -0x1.1ad36b9e5d07p+0, 0x1.819ca2224a4b6p+0 },
	    { -0x1.7f28c05853432p-1, 0x1.4e29813292c36p-2, 0x1.27a9e0e25d9bp-1,
	      0x1.33b6db1a4b016p-1, 0x1.67655f15491ecp-1, 0x1.875be1a5fb218p-2,
	      -0x1.1f5df94bb6dap-2, 0x1.44222500a5698p-1, -0x1.715f8cec32492p-1 } } },
	{ 6479,
	  { { 0x1.4a063b6a47b58p+2, 0x1.2a09e38c60e81p+1, 0x1.a8a3b4a3877b3p+0, 0x1.cf32977cecedfp-4, 0x1.f649f63f1d785p-4 },
	    { 0x1.1a34bd3bccb92p-1, -0x1.401561fb009aap-1, -0x1.429aebf0d27e8p-2 },
	    { -0x1.97b32764d1fp-2, -0x1.8804b69c449p-3, 0x1.cb548da6f9ad2p-1,
	      0x1.c54e0ab6a030cp-1, -0x1.58290d815576cp-2, 0x1.48eb91c42fbecp-2,
	      0x1.eb9795bdad07p-3, 0x1.d826e954b6022p-1, 0x1.36907dc737174p-2 } },
	  { { 0x1.cec599828b3bcp+1, 0x1.354c937030d9cp+0, 0x1.4ff205a03d8cfp+2, 0x1.d5f90b3f38f75p-3, 0x1.437c61933faa8p+0 },
	    { 0x1.03887d98680dp-1, 0x1.7414ec9a8b0e2p+0, -0x1.106c1cb66a8ccp-1 },
	    { 0x1.806b29efec81p-2, 0x1.cd803e0232288p-3, 0x1.cc5026794740dp-1,
	      0x1.d3d616b427fc4p-1, 0x1.297e3ff9e0a1p-4, -0x1.9957bc408732bp-2,
	      -0x1.3e370308f0394p-3, 0x1.f17173a48235ep-1, -0x1.6dda3490deabp-3 } } },
};

static mkBody3 mk_hex_body(const mkHexBody *h)
{
	mkShape3 s = { h->shape[0], h->shape[1], h->shape[2], h->shape[3], h->shape[4] };
	mkMat3 M;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			M.m[i][j] = h->m[3 * i + j];
	return mkBody3_Make(s, M, mkVec3_Make(h->t[0], h->t[1], h->t[2]));
}

static void test_deep_pairs(void)
{
	const mkCollider *referee = mkColliders_Find("referee");
	for (size_t k = 0; k < sizeof mkDeepPairs / sizeof mkDeepPairs[0]; ++k) {
		mkBody3 b1 = mk_hex_body(&mkDeepPairs[k].b1), b2 = mk_hex_body(&mkDeepPairs[k].b2);
		mkColliderScratch s;
		mkCollision3 ref, mine;
		ENSURE(mkCollider_Run(referee, b1, b2, &s, &ref) == MK_OK);
		ENSURE(mkCollide3_Normal(b1, b2, &mine) == MK_OK);
		ENSURE(ref.status == MK_CONTACT_OVERLAPPING && ref.residual == 0.0);
		ENSURE_NEAR(mine.distance, ref.distance, 1e-10 * mine.scale);
		ENSURE(mine.certified == 1);
		ENSURE_LE(mine.gap, (MK_COLLIDE3_GLOBAL_TOL + 1e-14) * mine.scale);
		ENSURE_LE(ref.distance, mine.bound + mine.gap + 1e-13 * mine.scale);
		printf("deep trial %ld: sd %.17g, referee %.17g (difference %.2g of the scale), certified within %.2g, "
			"%d evaluations\n", mkDeepPairs[k].trial, mine.distance, ref.distance,
			fabs(mine.distance - ref.distance) / mine.scale, mine.gap / mine.scale, mine.cert_evals);
	}
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
	test_boxlike_pairs();
	test_deep_pairs();
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
