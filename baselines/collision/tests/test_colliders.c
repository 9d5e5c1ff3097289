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
 *    nearest points; six box-like pairs written exactly on which Newton
 *    alone did not converge, and pairs with every exponent 1e-6 or
 *    1.999999, against the referee;
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
#include "draw_paper.h"
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
	double scale = mkCollide3_PairSize(b1, b2);
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
	const double *xs = mkFclCaseX;
	unsigned long long seed = 17;
	for (int rot = 0; rot < 3; ++rot) {
		mkMat3 R = rot == 0 ? mkMat3_Identity() : mk_test_rotation(&seed);
		for (size_t k = 0; k < sizeof mkFclCaseX / sizeof mkFclCaseX[0]; ++k) {
			mkBody3 A, B;
			mk_test_fcl_case(R, mkVec3_Make(0, 0, 0), xs[k], &A, &B);
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
		mk_test_paper_pair3(&seed, ell, deep, &b1, &b2);
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

/* The referee's and minksum-normal's answers on a pair written exactly;
 * both must give one. */
static void mk_hex_answers(const mkHexBody *h1, const mkHexBody *h2, mkCollision3 *ref, mkCollision3 *mine)
{
	mkBody3 b1 = mk_hex_body(h1), b2 = mk_hex_body(h2);
	mkColliderScratch s;
	ENSURE(mkCollider_Run(mkColliders_Find("referee"), b1, b2, &s, ref) == MK_OK);
	ENSURE(mkCollide3_Normal(b1, b2, mine) == MK_OK);
}

static void test_deep_pairs(void)
{
	for (size_t k = 0; k < sizeof mkDeepPairs / sizeof mkDeepPairs[0]; ++k) {
		mkCollision3 ref, mine;
		mk_hex_answers(&mkDeepPairs[k].b1, &mkDeepPairs[k].b2, &ref, &mine);
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

/* Pairs on which no Newton start of minksum-normal converged before the
 * fallbacks: box-like pairs of
 * mink_bench_colliders (KIND 4; its seed and pair index), bodies written
 * exactly. The first four are separated (Newton stalls on a ridge of a nearly
 * kinked support function, and Gilbert's iteration brackets sd); the last
 * two overlap (where no Newton start converges, the branch and bound at
 * 1e-10 of the scale certifies the depth; since the cut backtracking of
 * the Newton phase a start converges on both, and the ordinary certificate
 * holds at MK_COLLIDE3_GLOBAL_TOL). Reference: the referee, certain on all
 * six. The code before the fallbacks returned MK_ERR_CONVERGENCE on every
 * one. */
static const struct { unsigned long long seed; int trial; mkHexBody b1, b2; } mkRidgePairs[] = {
	{ 2022, 294,
	  { { 0x1.495a79e4235c6p+1, 0x1.351de0032c528p+3, 0x1.33c377fc39c7ep+3, 0x1.2d096421343d8p-2, 0x1.4395eef1806aap-3 },
	    { -0x1.9fa011afc47dp-1, -0x1.e9e51c1383202p+0, 0x1.6b45f7d9afc4p-1 },
	    { -0x1.c5173219d9f96p-1, 0x1.58023ce63f40cp-2, 0x1.4a41c11392f5cp-2,
	      0x1.b05a76d02d0bp-2, 0x1.bdefcfd4c6f83p-1, 0x1.014f39a9efdbcp-2,
	      -0x1.926751778c09p-3, 0x1.6f252b4f1e3f6p-2, -0x1.d3408c315eb7ap-1 } },
	  { { 0x1.049b7119b4ecap+1, 0x1.32f698e5f760cp+2, 0x1.0601d88d17cdp+2, 0x1.0e6f279584a16p-2, 0x1.b524d0005991cp-3 },
	    { 0x1.388c5dd6e4be8p+3, 0x1.28cc0260c5d5cp+3, 0x1.169187de4b9b6p+3 },
	    { -0x1.6399dc578b00ep-1, 0x1.357d87c4c086ep-2, 0x1.4e48b975db22ep-1,
	      0x1.4b50b70f94b6ap-1, -0x1.12e1d0d9639dp-3, 0x1.8041334e84d7dp-1,
	      0x1.4201bc8f4ab49p-2, 0x1.e33164b4539d5p-1, -0x1.a3416bff72aep-4 } } },
	{ 2022, 370,
	  { { 0x1.44256a08a2dfcp+3, 0x1.03c7813259515p+3, 0x1.4afae100f14c8p+3, 0x1.b71b0407c05c2p-5, 0x1.ff09d882202d2p-3 },
	    { -0x1.5f25d9482238p+1, -0x1.0cd4e885e926p+2, 0x1.eb34557001eb8p+0 },
	    { 0x1.4a1323fdea95p-1, 0x1.5cc318b5d8006p-2, 0x1.5e687ef5e320cp-1,
	      0x1.869a6297851dfp-1, -0x1.d606d1b53c96p-3, -0x1.3575bbf25341bp-1,
	      -0x1.8fa52afe207dp-5, 0x1.d2d3b55fdd271p-1, -0x1.a193c16414d68p-2 } },
	  { { 0x1.f23c6fd76d1c5p+0, 0x1.60f2b3aad614cp+1, 0x1.a168f65e314d2p+1, 0x1.d01ec672a906cp-3, 0x1.c6f828a976fd6p-5 },
	    { 0x1.0d3c2345c66dfp+3, 0x1.8b75468abc20cp+2, 0x1.7031a169d707ap+3 },
	    { 0x1.49109a5a3c18p-8, 0x1.6774ca8f975p-8, 0x1.fffc6048444c5p-1,
	      0x1.4b8045cae9d84p-1, -0x1.86317ca3ae6aep-1, 0x1.e713b00608cp-11,
	      0x1.862f649bc40f7p-1, 0x1.4b7d509b3c92cp-1, -0x1.e38382eae45p-8 } } },
	{ 2022, 1308,
	  { { 0x1.eabff6a1a379dp+2, 0x1.d85b78e85de5ep+1, 0x1.0d6991b6243dcp+2, 0x1.670f91697fb35p-4, 0x1.1d3cc7fded6fap-3 },
	    { -0x1.1a3f746d5177ap+1, -0x1.6cf4ed3d68084p+1, 0x1.463769a53b668p+0 },
	    { 0x1.2b5c2f5519327p-1, -0x1.a361b8d5e6132p-4, 0x1.9c0afea4ee955p-1,
	      0x1.104fdf6f7554ep-2, 0x1.ec3a49ef9033fp-1, -0x1.225f743437d2ep-4,
	      -0x1.886a174baafdbp-1, 0x1.0597e0613f7c6p-2, 0x1.2dbd7f9479a2dp-1 } },
	  { { 0x1.56fa4b7047008p+2, 0x1.e5212153e03fbp+1, 0x1.08bd50b11872dp+0, 0x1.e10e39786032p-3, 0x1.d2896f26b2a96p-5 },
	    { 0x1.8673b883d1d56p+2, 0x1.7af082c5fc5d1p+3, 0x1.b597a750996a1p+3 },
	    { 0x1.b6eb839ee57fp-3, 0x1.4b73c8ee0555bp-1, 0x1.767d6c5f4a748p-1,
	      0x1.7844d3bc50a53p-1, -0x1.3345aefdd513cp-1, 0x1.436a995d128bap-2,
	      0x1.496e73221481p-1, 0x1.e11ca8c88f05ep-2, -0x1.3570130cc5616p-1 } } },
	{ 2022, 1454,
	  { { 0x1.2ce59e7b27775p+3, 0x1.a28991bbdfb09p+2, 0x1.643cb4e9c28fdp+2, 0x1.ff61c6b2da4cap-5, 0x1.d237f34cff5bfp-4 },
	    { -0x1.9185a81009848p+1, 0x1.31e896cad931p+2, 0x1.53a992a0de7d4p+1 },
	    { 0x1.5dacb6b404adcp-3, 0x1.7c7eb638b5b7ap-1, 0x1.4b3f9c750267ap-1,
	      0x1.e16e7c0b8fabp-1, 0x1.2c4e5450fdde8p-4, -0x1.545811e85e3b6p-2,
	      -0x1.2d8014d26daf9p-2, 0x1.5486d84f28b26p-1, -0x1.5f5e60091cd12p-1 } },
	  { { 0x1.50e3163af268bp+2, 0x1.32b54efe386dap+0, 0x1.f7577b0be258p+0, 0x1.514d8e70b031ap-3, 0x1.b1c0101c5153ep-5 },
	    { 0x1.319d1bede6c7cp+3, 0x1.dc16b4239ce12p+3, 0x1.173442c055718p+3 },
	    { -0x1.694e2536976b4p-2, -0x1.18c5860ef04e8p-1, 0x1.842b85317f989p-1,
	      0x1.deded47ffab14p-1, -0x1.d74a6a6a7659p-3, 0x1.1347fa23f73cap-2,
	      0x1.bb1a9ee387cep-6, 0x1.9b9e2248e3cfdp-1, 0x1.302d1728f7c0ep-1 } } },
	{ 7, 3757,
	  { { 0x1.303997ea57acap+2, 0x1.929c4e425a238p+2, 0x1.4a35e42b853a9p+3, 0x1.aa5fea86ada43p-4, 0x1.ce300a9db31p-3 },
	    { 0x1.220b3dd155a9p+0, 0x1.c95e6dc50dp-8, 0x1.27ee20b2034bcp+1 },
	    { -0x1.5454937a53be4p-2, 0x1.cbe3e657aba54p-2, 0x1.a8a20210367c7p-1,
	      0x1.4000a9912e9f6p-1, -0x1.1b7b3e73ada58p-1, 0x1.19bee4d13b165p-1,
	      0x1.69a4c85d85df5p-1, 0x1.6709752211b27p-1, -0x1.8c0173b4fd1ap-4 } },
	  { { 0x1.2231d93863fccp+1, 0x1.7517fe2ec5774p+2, 0x1.7d12ded1610dp+1, 0x1.78b89ca180c68p-3, 0x1.434de01f40ad1p-4 },
	    { 0x1.0e9d8f806130bp+3, 0x1.4352c302db55cp+3, 0x1.5d542d3f1d838p+2 },
	    { -0x1.2e8abe6ac0308p-2, -0x1.30e65a87599bap-1, 0x1.7e7cf7d2dde64p-1,
	      0x1.dc7aa24d9d83ep-1, -0x1.56b78e4f6f2p-9, 0x1.76c0bdbe537c6p-2,
	      -0x1.ba55fc9c4fefep-3, 0x1.9b501abc218dbp-1, 0x1.1c2471467289fp-1 } } },
	{ 7, 8568,
	  { { 0x1.3d06fa36c8cecp+3, 0x1.5a39a72cb6bdcp+3, 0x1.e42af5508efaap+1, 0x1.5792283fa0e43p-4, 0x1.11e91e314fa79p-4 },
	    { 0x1.32df6b4f51538p-1, 0x1.ce28ce6c6f9fp+1, 0x1.4938961cbf09p+1 },
	    { 0x1.b8e4a0b275f5fp-1, 0x1.6e2911b68c7f7p-2, 0x1.72134639ef4cp-2,
	      0x1.037955a6e2334p-1, -0x1.1818c5a7b20ep-1, -0x1.551ecc7710307p-1,
	      -0x1.4bff76083ae94p-5, 0x1.8385043c82337p-1, -0x1.4dfaa30359b92p-1 } },
	  { { 0x1.92a68be332419p+1, 0x1.1cd80b8835a44p+2, 0x1.885149f4328e8p+1, 0x1.f0b3b9ac2f806p-5, 0x1.bc58918a04696p-5 },
	    { 0x1.6baa769d3bf75p+3, 0x1.69e1a39a4d71cp+3, 0x1.791f2545e7aacp+2 },
	    { 0x1.8990cb4d8272cp-3, 0x1.a4f891bf42e7cp-1, 0x1.124fa3460d3ecp-1,
	      0x1.e3b0c298356a8p-1, -0x1.3612317ab23ep-2, 0x1.01ba9c6b7b7cdp-3,
	      0x1.101411334ace8p-2, 0x1.ed8614547d6eep-2, -0x1.ab7ce7d654424p-1 } } },
};

static void test_ridge_pairs(void)
{
	for (size_t k = 0; k < sizeof mkRidgePairs / sizeof mkRidgePairs[0]; ++k) {
		mkCollision3 ref, mine;
		mk_hex_answers(&mkRidgePairs[k].b1, &mkRidgePairs[k].b2, &ref, &mine);
		ENSURE(ref.residual <= 1e-10);
		ENSURE(mine.status == ref.status);
		ENSURE_NEAR(mine.distance, ref.distance, 1e-10 * mine.scale);
		ENSURE(mine.certified == 1);
		/* the width each path certifies: 1e-10 of the scale for a
		 * separation (Newton or Gilbert's bracket), the global tolerance
		 * for an overlap */
		ENSURE_LE(mine.gap, (ref.status == MK_CONTACT_SEPARATED ? 1e-10 : MK_COLLIDE3_GLOBAL_TOL) * mine.scale);
		ENSURE_LE(ref.distance, mine.bound + mine.gap + 1e-13 * mine.scale);
		if (ref.status == MK_CONTACT_SEPARATED)
			ENSURE_LE(mine.bound, ref.distance + ref.gap + 1e-13 * mine.scale);
		printf("ridge pair (seed %llu, %d): sd %.17g, referee %.17g (difference %.2g of the scale), gap %.2g, "
			"%d iterations\n", mkRidgePairs[k].seed, mkRidgePairs[k].trial, mine.distance, ref.distance,
			fabs(mine.distance - ref.distance) / mine.scale, mine.gap / mine.scale, mine.iterations);
	}
}

/* Pairs at the ends of the exponent range: every exponent 1e-6 or 1.999999
 * (box-like and needle-like faces, nearly kinked support functions), the
 * paper's sizes, B2's centre drawn as usual or pulled towards B1's (then
 * mostly overlapping). Against the referee where it is certain: no failure,
 * the same status outside the margin, the distance within 1e-10 of the
 * scale on separated pairs, and within the answer's certified gap (at most
 * MK_COLLIDE3_GLOBAL_TOL of the scale) on overlaps. The code before the
 * fallbacks failed 26 of 600 such pairs and was off by up to 7.9e-3 of the
 * scale (measured). */
static void test_extreme_pairs(void)
{
	const mkCollider *referee = mkColliders_Find("referee");
	unsigned long long seed = 57;
	int certain = 0, overlaps = 0;
	double worst = 0.0;
	for (int trial = 0; trial < 60; ++trial) {
		mkBody3 p1, p2;
		mk_test_pair3(&seed, 0.5, 0.5, &p1, &p2);
		mkShape3 s1 = p1.shape, s2 = p2.shape;
		double *e[4] = { &s1.eps1, &s1.eps2, &s2.eps1, &s2.eps2 };
		for (int i = 0; i < 4; ++i)
			*e[i] = mk_test_unit(&seed) < 0.5 ? 1e-6 : 1.999999;
		mkVec3 c2 = trial % 2 ? mkVec3_Add(p1.t, mkVec3_Scale(mkVec3_Sub(p2.t, p1.t), 0.3)) : p2.t;
		mkBody3 b1 = mkBody3_Make(s1, p1.M, p1.t), b2 = mkBody3_Make(s2, p2.M, c2);
		mkColliderScratch s;
		mkCollision3 ref, mine;
		ENSURE(mkCollider_Run(referee, b1, b2, &s, &ref) == MK_OK);
		ENSURE(mkCollide3_Normal(b1, b2, &mine) == MK_OK);
		if (!(ref.residual <= 1e-10) || fabs(ref.distance) <= 1e-9 * ref.scale)
			continue;
		++certain;
		ENSURE(mine.status == ref.status);
		ENSURE(mine.certified == 1);
		double err = fabs(mine.distance - ref.distance) / mine.scale;
		if (ref.status == MK_CONTACT_SEPARATED)
			ENSURE_LE(err, 1e-10);
		else {
			++overlaps;
			ENSURE_LE(mine.gap, (MK_COLLIDE3_GLOBAL_TOL + 1e-14) * mine.scale);
			ENSURE_LE(err * mine.scale, mine.gap + 1e-13 * mine.scale);
		}
		worst = err > worst ? err : worst;
	}
	printf("extreme exponents: %d pairs certain (%d overlapping), largest difference %.2g of the scale\n", certain,
		overlaps, worst);
	ENSURE(certain >= 40 && overlaps >= 10);
}

static void test_near_touching(void)
{
	unsigned long long seed = 99;
	const double seps[] = { 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6 };
	const char *exact[] = { "minksum-normal", "minksum-ray", "asc", "asc-eigen", "ccd-gjk", "fcl" };
	for (int trial = 0; trial < 24; ++trial) {
		int ell = trial % 2 == 0;
		mkBody3 b1, b2;
		mk_test_paper_pair3(&seed, ell, 0, &b1, &b2);
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
	test_ridge_pairs();
	test_extreme_pairs();
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
