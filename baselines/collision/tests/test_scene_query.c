/* test_scene_query.c - the scene query (mink/scenequery.h) against brute
 * force over all (part, obstacle) pairs, with references that share nothing
 * with its broad or narrow phase:
 *  - 3D (superquadrics and ellipsoids): the registry's referee
 *    (collider_referee.c: Gilbert's iteration on the support maps, a
 *    certified bracket [distance, distance + gap] of each pair's signed
 *    distance, overlaps certified by a tetrahedron around the origin);
 *  - 2D (boxes among smooth bodies): the support-function bound
 *    max over directions n of <n, t_P - t_O> - h_O(n) - h_P(-n), with the
 *    textbook support functions (dual norms by pow(), a box's
 *    sum s_i |v_i|), on 20000 directions and three zooms of 2000 around the
 *    best: below the signed distance, and within 1e-9 of the pair's
 *    size of it (steps of 2e-12 rad at the end, kinks included).
 * Checked per pose: the status, the clearance (a lower bound of the true
 * minimum, and tight: within the models' and the references' tolerances of
 * it), the nearest obstacle, the cap max_clearance, and the answers of 1, 2
 * and 3 threads byte for byte.
 * Against the one-pair narrow phase (test_3d_onepair: mkCollide3_Normal on
 * every pair, by the header's rules): the same status, and for free poses
 * the same clearance to the last bit and the same nearest pair, uncapped
 * and capped at 1e-9 (the yes/no question); colliding poses: the reported
 * pair overlaps (referee) and the clearance is an upper bound of its
 * signed distance. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/cspace.h>
#include <mink/colliders.h>

#include "ensure.h"

static unsigned long long seed = 2029;
static double spread = 10.0;   /* obstacles' and poses' positions in [-spread, spread] */

static double uni(double lo, double hi) { return lo + (hi - lo) * mk_test_unit(&seed); }

/* ---- 3D: smooth bodies, the referee ---- */

static void scene3_text(char *buf, size_t len, int nob)
{
	size_t n = (size_t)snprintf(buf, len, "dim 3\npart superquadric a=1 b=0.6 c=0.4 eps1=0.4 eps2=0.7\n"
		"part ellipsoid a=0.5 b=0.3 c=0.3 quat=0.9,0.2,0.3,0 at=1.2,0.3,0.2\nobject clutter\n");
	for (int i = 0; i < nob; ++i) {
		double a = uni(0.3, 1.5), b = uni(0.3, 1.5), c = uni(0.3, 1.5);
		double x = uni(-spread, spread), y = uni(-spread, spread), z = uni(-spread, spread);
		if (i % 2)
			n += (size_t)snprintf(buf + n, len - n, "obstacle superquadric a=%.6f b=%.6f c=%.6f eps1=%.4f eps2=%.4f "
				"quat=%.4f,%.4f,%.4f,%.4f at=%.5f,%.5f,%.5f\n", a, b, c, uni(0.2, 1.8), uni(0.2, 1.8), uni(-1, 1),
				uni(-1, 1), uni(-1, 1), uni(-1, 1), x, y, z);
		else
			n += (size_t)snprintf(buf + n, len - n, "obstacle ellipsoid a=%.6f b=%.6f c=%.6f at=%.5f,%.5f,%.5f\n", a, b, c,
				x, y, z);
	}
	snprintf(buf + n, len - n, "quaternions 1,0,0,0\n");
}

static void random_poses(int dim, double *p, int n)
{
	int ps = dim == 2 ? 3 : 7;
	for (int k = 0; k < n; ++k) {
		double *q = p + k * ps;
		for (int d = 0; d < dim; ++d) q[d] = uni(-spread, spread);
		if (dim == 2) q[2] = uni(-4, 4);
		else for (int d = 3; d < 7; ++d) q[d] = uni(-1, 1);
	}
}

static int answers_equal(const mkPoseAnswer *a, const mkPoseAnswer *b, int n)
{
	for (int k = 0; k < n; ++k)
		if (a[k].status != b[k].status || a[k].obstacle != b[k].obstacle || a[k].part != b[k].part
			|| memcmp(&a[k].clearance, &b[k].clearance, sizeof a[k].clearance) || a[k].pairs != b[k].pairs)
			return 0;
	return 1;
}

/* Run the poses on 1, 2 and 3 threads; the answers must be the same bytes. */
static void run_threads(const mkScene *s, mkSceneQueryOptions o, const double *poses, int n, mkPoseAnswer *out)
{
	char msg[512];
	mkPoseAnswer *other = malloc((size_t)n * sizeof *other);
	for (int t = 1; t <= 3; ++t) {
		o.threads = t;
		mkSceneQuery *q = NULL;
		ENSURE(mkSceneQuery_Create(s, &o, &q, msg, sizeof msg) == MK_OK);
		ENSURE(mkSceneQuery_Run(q, poses, n, t == 1 ? out : other, msg, sizeof msg) == MK_OK);
		if (t > 1) ENSURE(answers_equal(out, other, n));
		mkSceneQuery_Destroy(q);
	}
	free(other);
}

/* Parse the scene, draw np poses and answer them on 1, 2 and 3 threads. */
static void prepare(const char *text, int dim, mkScene *s, double *poses, int np, mkPoseAnswer *ans)
{
	char msg[512];
	ENSURE(mkScene_Parse(text, s, msg, sizeof msg) == MK_OK);
	random_poses(dim, poses, np);
	run_threads(s, mkSceneQueryOptions_Default(), poses, np, ans);
}

static void test_3d(void)
{
	enum { NOB = 60, NP = 150 };
	static char text[NOB * 160 + 512];
	scene3_text(text, sizeof text, NOB);
	mkScene s;
	char msg[512];
	double poses[NP * 7];
	mkPoseAnswer ans[NP];
	prepare(text, 3, &s, poses, NP, ans);
	const mkCollider *ref = mkColliders_Find("referee");
	ENSURE(ref != NULL);
	mkColliderScratch scratch;
	mkSceneQuery *q = NULL;
	mkSceneQueryOptions o = mkSceneQueryOptions_Default();
	ENSURE(mkSceneQuery_Create(&s, &o, &q, msg, sizeof msg) == MK_OK);
	int counts[3] = {0, 0, 0}, bad_status = 0, bad_lower = 0, bad_tight = 0, bad_nearest = 0;
	long pairs = 0;
	double true_lo[NP], true_hi[NP], true_tol[NP];
	for (int k = 0; k < NP; ++k) {
		double lo = INFINITY, hi = INFINITY, lo_reported = NAN, scale = 0.0;
		int overlap = 0;
		for (int j = 0; j < s.part_count; ++j) {
			const double *P = poses + 7 * k;
			mkMat3 R = mkMat3_FromQuat(P[3], P[4], P[5], P[6]);
			mkBody3 part = s.parts[j].spec.body3;
			part.t = mkVec3_Add(mkVec3_Make(P[0], P[1], P[2]), mkMat3_MulVec(R, part.t));
			part.M = mkMat3_Mul(R, part.M);
			for (int i = 0; i < s.obstacle_count; ++i) {
				mkCollision3 c;
				ENSURE(mkCollider_Run(ref, s.obstacles[i].spec.body3, part, &scratch, &c) == MK_OK);
				if (c.residual == 0.0 && c.distance < 0.0) overlap = 1;
				lo = fmin(lo, c.distance);
				hi = fmin(hi, isnan(c.gap) ? c.distance : c.distance + c.gap);
				scale = fmax(scale, c.scale);
				if (i == ans[k].obstacle && j == ans[k].part) lo_reported = c.distance;
			}
		}
		double tol = 1e-9 * scale;
		true_lo[k] = lo;
		true_hi[k] = hi;
		true_tol[k] = tol;
		const mkPoseAnswer *a = &ans[k];
		++counts[a->status];
		pairs += a->pairs;
		if ((a->status == MK_POSE_FREE) != (lo > tol) || (a->status == MK_POSE_COLLIDING) != overlap) ++bad_status;
		if (a->status == MK_POSE_FREE) {
			if (!(a->clearance <= hi + tol)) ++bad_lower;      /* a lower bound of the true minimum */
			if (!(a->clearance >= lo - tol)) ++bad_tight;      /* and the minimum itself */
			if (!(fabs(lo_reported - lo) <= tol)) ++bad_nearest;
		}
	}
	ENSURE(bad_status == 0);
	ENSURE(bad_lower == 0);
	ENSURE(bad_tight == 0);
	ENSURE(bad_nearest == 0);
	ENSURE(counts[MK_POSE_UNCERTAIN] == 0);
	ENSURE(counts[MK_POSE_FREE] > 10 && counts[MK_POSE_COLLIDING] > 10);
	printf("3D, %d obstacles, 2 parts, %d poses: %d free, %d colliding, %d uncertain; %.1f narrow-phase pairs per pose "
		"(brute force %d); mismatches status %d lower %d tight %d nearest %d\n", NOB, NP, counts[0], counts[1], counts[2],
		(double)pairs / NP, NOB * 2, bad_status, bad_lower, bad_tight, bad_nearest);
	/* the cap: clearances beyond max_clearance are reported as it */
	o.max_clearance = 0.5;
	mkSceneQuery *qc = NULL;
	ENSURE(mkSceneQuery_Create(&s, &o, &qc, msg, sizeof msg) == MK_OK);
	for (int k = 0; k < NP; ++k) {
		mkPoseAnswer c;
		ENSURE(mkSceneQuery_Pose(qc, poses + 7 * k, &c) == MK_OK);
		ENSURE(c.status == ans[k].status);
		if (ans[k].status == MK_POSE_FREE) ENSURE(c.clearance == fmin(ans[k].clearance, 0.5));
		if (ans[k].status == MK_POSE_FREE && ans[k].clearance >= 0.5) ENSURE(c.obstacle == -1);
	}
	/* clearance_rel: the same statuses; a free pose's clearance a lower bound
	 * of the referee's minimum within that fraction of it */
	mkSceneQueryOptions orel = mkSceneQueryOptions_Default();
	orel.clearance_rel = 0.1;
	mkSceneQuery *qr = NULL;
	ENSURE(mkSceneQuery_Create(&s, &orel, &qr, msg, sizeof msg) == MK_OK);
	int rel_looser = 0;
	for (int k = 0; k < NP; ++k) {
		mkPoseAnswer c;
		ENSURE(mkSceneQuery_Pose(qr, poses + 7 * k, &c) == MK_OK);
		ENSURE(c.status == ans[k].status);
		if (c.status != MK_POSE_FREE) continue;
		ENSURE_LE(c.clearance, true_hi[k] + true_tol[k]);
		ENSURE_LE(0.9 * true_lo[k] - true_tol[k], c.clearance);
		rel_looser += c.clearance < ans[k].clearance;
	}
	printf("3D clearance_rel 0.1: the same statuses; %d of %d free poses got a looser lower bound\n", rel_looser,
		counts[MK_POSE_FREE]);
	mkSceneQuery_Destroy(qr);
	orel.clearance_rel = 0.6;
	ENSURE(mkSceneQuery_Create(&s, &orel, &qr, msg, sizeof msg) == MK_ERR_ARGUMENT);
	ENSURE(strstr(msg, "clearance_rel") != NULL);
	/* a bad pose is named */
	poses[7 * 3 + 3] = poses[7 * 3 + 4] = poses[7 * 3 + 5] = poses[7 * 3 + 6] = 0.0;
	ENSURE(mkSceneQuery_Run(q, poses, NP, ans, msg, sizeof msg) == MK_ERR_ARGUMENT);
	ENSURE(strstr(msg, "pose 3 is out of range") != NULL);
	mkSceneQuery_Destroy(qc);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
}

/* ---- 3D: the one-pair narrow phase on every pair ---- */

/* Part j at the pose P. */
static mkBody3 placed_part(const mkScene *s, const double *P, int j)
{
	mkMat3 R = mkMat3_FromQuat(P[3], P[4], P[5], P[6]);
	mkBody3 part = s->parts[j].spec.body3;
	part.t = mkVec3_Add(mkVec3_Make(P[0], P[1], P[2]), mkMat3_MulVec(R, part.t));
	part.M = mkMat3_Mul(R, part.M);
	return part;
}

/* The one-pair narrow phase on pair (obstacle i, part j at the pose): free
 * with the value bound - 1e-12 scale when that is positive, colliding when
 * the solver finds the (smooth) pair overlapping, else uncertain. */
static mkPoseStatus onepair_pair(const mkScene *s, const double *P, int j, int i, double *value)
{
	mkCollision3 c;
	if (mkCollide3_Normal(s->obstacles[i].spec.body3, placed_part(s, P, j), &c) != MK_OK) return MK_POSE_UNCERTAIN;
	*value = c.bound - 1e-12 * c.scale;
	if (*value > 0.0) return MK_POSE_FREE;
	return c.status == MK_CONTACT_OVERLAPPING && c.distance < -1e-9 * c.scale ? MK_POSE_COLLIDING : MK_POSE_UNCERTAIN;
}

/* One pose of the query (capped at cap) against the one-pair narrow phase
 * on every pair, and a colliding pose's pair against the referee. Returns
 * 1 when they differ. */
static int onepair_pose(const mkScene *s, const double *P, const mkPoseAnswer *a, double cap)
{
	double best = cap, v;
	int coll = 0, unc = 0, ob = -1, pt = -1;
	for (int j = 0; j < s->part_count; ++j)
		for (int i = 0; i < s->obstacle_count; ++i) {
			mkPoseStatus st = onepair_pair(s, P, j, i, &v);
			coll |= st == MK_POSE_COLLIDING;
			unc |= st == MK_POSE_UNCERTAIN;
			if (st == MK_POSE_FREE && v < best) { best = v; ob = i; pt = j; }
		}
	mkPoseStatus want = coll ? MK_POSE_COLLIDING : unc ? MK_POSE_UNCERTAIN : MK_POSE_FREE;
	int bad = a->status != want || (want == MK_POSE_FREE && (a->clearance != best || a->obstacle != ob || a->part != pt));
	if (a->status == MK_POSE_COLLIDING) {
		const mkCollider *ref = mkColliders_Find("referee");
		mkColliderScratch scratch;
		mkCollision3 c;
		ENSURE(ref && a->obstacle >= 0 && a->part >= 0);
		ENSURE(mkCollider_Run(ref, s->obstacles[a->obstacle].spec.body3, placed_part(s, P, a->part), &scratch, &c) == MK_OK);
		double tol = 1e-9 * c.scale, hi = isnan(c.gap) ? c.distance : c.distance + c.gap;
		bad |= !(hi < -tol && a->clearance <= 0.0 && a->clearance >= c.distance - tol);
	}
	if (bad)
		fprintf(stderr, "  one-pair, cap %g: %s %.17g (%d, %d); one-pair %s %.17g (%d, %d)\n", cap,
			mkPoseStatus_Name(a->status), a->clearance, a->obstacle, a->part, mkPoseStatus_Name(want), best, ob, pt);
	return bad;
}

static void test_3d_onepair(int NOB, double half)
{
	enum { NP = 100 };
	static char text[200 * 160 + 512];
	spread = half;
	scene3_text(text, sizeof text, NOB);
	mkScene s;
	double poses[NP * 7], caps[2] = {INFINITY, 1e-9};
	mkPoseAnswer ans[NP];
	prepare(text, 3, &s, poses, NP, ans);
	int bad = 0, counts[3] = {0, 0, 0};
	for (int c = 0; c < 2; ++c) {
		char msg[512];
		mkSceneQueryOptions o = mkSceneQueryOptions_Default();
		o.max_clearance = caps[c];
		mkSceneQuery *q = NULL;
		ENSURE(mkSceneQuery_Create(&s, &o, &q, msg, sizeof msg) == MK_OK);
		for (int k = 0; k < NP; ++k) {
			mkPoseAnswer a;
			ENSURE(mkSceneQuery_Pose(q, poses + 7 * k, &a) == MK_OK);
			bad += onepair_pose(&s, poses + 7 * k, &a, caps[c]);
			++counts[a.status];
		}
		mkSceneQuery_Destroy(q);
	}
	ENSURE(bad == 0);
	ENSURE(counts[MK_POSE_FREE] > 20 && counts[MK_POSE_COLLIDING] > 10);
	printf("3D against the one-pair narrow phase, %d obstacles, %d poses, uncapped and capped at 1e-9: %d free, "
		"%d colliding, %d uncertain; %d differ\n", NOB, NP, counts[0], counts[1], counts[2], bad);
	spread = 10.0;
	mkScene_Free(&s);
}

/* ---- 3D: boxes, the referee on their models ---- */

/* Among rotated boxes, the query's answers hold for the boxes' models
 * (what its certificates rest on: a free pair is certified on the outer
 * model or a box that holds it, a colliding one on the inner models),
 * checked by the referee: a free pose's clearance at most every pair's
 * distance to the outer model (upper end of the referee's bracket), no free
 * pose where an inner model overlaps a part; a colliding pose's pair's inner
 * model overlapping with a signed distance at most the reported one (minus
 * a certified depth), no colliding pose where every outer model is apart;
 * an uncertain pose's value at most 0 and at most its pair's signed
 * distance to the declared box (the referee's on a model within 1e-5 that
 * holds the box, mkSceneBody3_Model, plus 1e-5).
 * Capped at 1e-9 (the yes/no question) and uncapped, with the default
 * models and coarse ones (model_rel 0.05, whose wide band the batch's
 * overlap points reach: a certificate on the wrong model is caught there),
 * at random poses and at poses within the band of a box's face. */
static void test_3d_boxes(int NOB)
{
	enum { NP = 300, NB = 100 };
	static char text[150 * 160 + 512];
	double span = NOB > 30 ? 6.0 * cbrt(NOB / 30.0) : 6.0;   /* (larger scenes as dense as 30 boxes in [-6, 6]^3) */
	size_t n = (size_t)snprintf(text, sizeof text, "dim 3\npart ellipsoid a=1 b=0.5 c=0.3\n"
		"part superquadric a=0.5 b=0.3 c=0.3 eps1=0.6 eps2=1.3 quat=0.9,0.2,0.3,0 at=1.2,0.3,0.2\nobject clutter\n");
	for (int i = 0; i < NOB; ++i)
		n += (size_t)snprintf(text + n, sizeof text - n, "obstacle box size=%.5f,%.5f,%.5f quat=%.4f,%.4f,%.4f,%.4f "
			"at=%.5f,%.5f,%.5f\n", uni(0.2, 3), uni(0.2, 3), uni(0.2, 3), uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1),
			uni(-span, span), uni(-span, span), uni(-span, span));
	snprintf(text + n, sizeof text - n, "quaternions 1,0,0,0\n");
	mkScene s;
	char msg[512];
	ENSURE(mkScene_Parse(text, &s, msg, sizeof msg) == MK_OK);
	static double poses[NP * 7];
	for (int k = 0; k < NP; ++k) {
		for (int d = 0; d < 3; ++d) poses[7 * k + d] = uni(-span, span);
		for (int d = 3; d < 7; ++d) poses[7 * k + d] = uni(-1, 1);
	}
	/* the last NB poses put the first part (at the robot's origin) against a box's face centre, apart from the
	 * face by half the outer model's overhang there, inside or outside: within the band of the box's models */
	mkSceneQueryOptions o0 = mkSceneQueryOptions_Default();
	mkSceneQuery *q0 = NULL;
	ENSURE(mkSceneQuery_Create(&s, &o0, &q0, msg, sizeof msg) == MK_OK);
	for (int k = NP - NB; k < NP; ++k) {
		double *P = poses + 7 * k;
		int i = (int)uni(0, NOB), ax = (int)uni(0, 3);
		if (i >= NOB) i = NOB - 1;
		if (ax > 2) ax = 2;
		const mkSceneBody *b = &s.obstacles[i];
		mkBody3 outer;
		ENSURE(mkSceneQuery_ObstacleBody(q0, i, 1, &outer));
		double half = 0.5 * b->size[ax], over = ((&outer.shape.a)[ax] - half), side = k % 2 ? 1.0 : -1.0;
		mkVec3 e = {ax == 0, ax == 1, ax == 2}, nf = mkMat3_MulVec(b->spec.body3.M, e);   /* a rotation: the face's normal */
		nf = mkVec3_Scale(nf, (k / 2) % 2 ? 1.0 : -1.0);
		mkMat3 R = mkMat3_FromQuat(P[3], P[4], P[5], P[6]);
		mkBody3 part = s.parts[0].spec.body3;
		part.M = mkMat3_Mul(R, part.M);
		part.t = mkVec3_Make(0.0, 0.0, 0.0);
		mkVec3 c = mkVec3_Add(b->spec.body3.t, mkVec3_Scale(nf, half + mkBody3_SupportValue(part, nf) + side * 0.5 * over));
		P[0] = c.x;
		P[1] = c.y;
		P[2] = c.z;
	}
	mkSceneQuery_Destroy(q0);
	const mkCollider *ref = mkColliders_Find("referee");
	ENSURE(ref != NULL);
	mkColliderScratch scratch;
	double caps[2] = {1e-9, INFINITY};
	int counts[3] = {0, 0, 0}, bad_free = 0, bad_coll = 0, bad_depth = 0, band_unc = 0, fine_unc = 0, bad_unc = 0,
		capped_unc = 0;
	for (int c = 0; c < 4; ++c) {
		mkSceneQueryOptions o = mkSceneQueryOptions_Default();
		o.max_clearance = caps[c % 2];
		if (c >= 2) o.model_rel = 0.05;   /* coarse models: a wide band, where the batch finds points */
		mkSceneQuery *q = NULL;
		ENSURE(mkSceneQuery_Create(&s, &o, &q, msg, sizeof msg) == MK_OK);
		static mkPoseAnswer ans[NP];
		run_threads(&s, o, poses, NP, ans);
		for (int k = 0; k < NP; ++k) {
			const mkPoseAnswer *a = &ans[k];
			int inner_overlap = 0, outer_apart = 1;
			double outer_hi = INFINITY;
			for (int j = 0; j < s.part_count; ++j)
				for (int i = 0; i < s.obstacle_count; ++i) {
					mkBody3 part = placed_part(&s, poses + 7 * k, j), m[2];
					ENSURE(mkSceneQuery_ObstacleBody(q, i, 0, &m[0]) && mkSceneQuery_ObstacleBody(q, i, 1, &m[1]));
					mkCollision3 ci, co;
					ENSURE(mkCollider_Run(ref, m[0], part, &scratch, &ci) == MK_OK);
					ENSURE(mkCollider_Run(ref, m[1], part, &scratch, &co) == MK_OK);
					double ti = 1e-9 * ci.scale, to = 1e-9 * co.scale;
					double hi_i = isnan(ci.gap) ? ci.distance : ci.distance + ci.gap;
					double hi_o = isnan(co.gap) ? co.distance : co.distance + co.gap;
					if (ci.residual == 0.0 && hi_i < -ti) inner_overlap = 1;
					if (!(co.distance > to)) outer_apart = 0;
					outer_hi = fmin(outer_hi, hi_o + to);
					if (a->status == MK_POSE_COLLIDING && i == a->obstacle && j == a->part
						&& !(ci.residual == 0.0 && hi_i < -ti && ci.distance <= a->clearance + ti))
						++bad_depth;
				}
			++counts[a->status];
			band_unc += k >= NP - NB && a->status == MK_POSE_UNCERTAIN;
			fine_unc += c < 2 && k < NP - NB && a->status == MK_POSE_UNCERTAIN;
			if (a->status == MK_POSE_FREE && (inner_overlap || !(a->clearance <= outer_hi))) ++bad_free;
			if (a->status == MK_POSE_COLLIDING && outer_apart) ++bad_coll;
			/* an uncertain pose's value: at most 0 and at most its pair's declared signed distance, which is at most
			 * the referee's upper end on an outer model within et = 1e-5 of the declared box plus et */
			if (a->status == MK_POSE_UNCERTAIN) {
				capped_unc += c % 2 == 0;
				mkBody3 tight;
				double et;
				if (a->obstacle < 0 || a->part < 0 || !(a->clearance <= 0.0)
					|| mkSceneBody3_Model(&s.obstacles[a->obstacle], 1e-5, MK_BOUND_OUTER, &tight, &et, msg, sizeof msg)
						!= MK_OK) {
					++bad_unc;
					continue;
				}
				mkCollision3 ct;
				ENSURE(mkCollider_Run(ref, tight, placed_part(&s, poses + 7 * k, a->part), &scratch, &ct) == MK_OK);
				double hi_t = isnan(ct.gap) ? ct.distance : ct.distance + ct.gap;
				if (!(a->clearance <= hi_t + et + 1e-9 * ct.scale)) ++bad_unc;
			}
		}
		mkSceneQuery_Destroy(q);
	}
	printf("3D boxes, %d obstacles, %d poses (%d within the models' band), capped at 1e-9 and uncapped, model_rel "
		"1e-4 and 0.05: %d free, "
		"%d colliding, %d uncertain (%d in the band, %d capped); mismatches free %d colliding %d depth %d uncertain's "
		"value %d\n", NOB, NP, NB, counts[0], counts[1], counts[2], band_unc, capped_unc, bad_free, bad_coll, bad_depth,
		bad_unc);
	ENSURE(bad_free == 0);
	ENSURE(bad_coll == 0);
	ENSURE(bad_depth == 0);
	ENSURE(counts[MK_POSE_FREE] > 100 && counts[MK_POSE_COLLIDING] > 100);
	ENSURE(fine_unc <= 4);   /* random poses, model_rel 1e-4 */
	ENSURE(band_unc > 20);
	ENSURE(bad_unc == 0);
	ENSURE(capped_unc > 10);
	mkScene_Free(&s);
}

/* ---- 2D: boxes among smooth bodies, textbook support functions ---- */

static double ref_h2(const mkSceneBody *b, mkMat2 M, mkVec2 u)
{
	mkVec2 v = mkMat2_MulTVec(M, u);
	if (b->kind == MK_SCENE_BOX) return 0.5 * (b->size[0] * fabs(v.x) + b->size[1] * fabs(v.y));
	mkShape2 s = b->spec.body2.shape;
	double q = 2.0 / (2.0 - s.eps), x = fabs(s.a * v.x), y = fabs(s.b * v.y), m = fmax(x, y);
	return m == 0.0 ? 0.0 : m * pow(pow(x / m, q) + pow(y / m, q), 1.0 / q);
}

/* max over sampled directions of the signed-distance bound of part j at the
 * pose and obstacle i. */
static double ref_pair2(const mkScene *s, const double *pose, int j, int i)
{
	mkMat2 R = mkMat2_Rotation(pose[2]);
	const mkSceneBody *p = &s->parts[j], *o = &s->obstacles[i];
	mkVec2 tp = mkVec2_Add(mkVec2_Make(pose[0], pose[1]), mkMat2_MulVec(R, p->spec.body2.t));
	mkMat2 Mp = mkMat2_Mul(R, p->spec.body2.M);
	mkVec2 d = mkVec2_Sub(tp, o->spec.body2.t);
	/* 20000 directions, then three zooms of 2000 around the best (the
	 * bound is kinked at a box's face normals: sampling errs linearly) */
	double best = -INFINITY, tb = 0.0, lo = 0.0, step = 2.0 * MK_PI / 20000.0;
	for (int z = 0, n = 20000; z < 4; ++z, n = 2000) {
		for (int k = 0; k <= n; ++k) {
			double t = lo + step * k;
			mkVec2 u = {cos(t), sin(t)};
			double f = mkVec2_Dot(u, d) - ref_h2(o, o->spec.body2.M, u) - ref_h2(p, Mp, mkVec2_Neg(u));
			if (f > best) { best = f; tb = t; }
		}
		lo = tb - step;
		step *= 2.0 / 2000.0;
	}
	return best;
}

static void test_2d(void)
{
	enum { NP = 120 };
	const char *text = "dim 2\npart box size=2,0.6\npart circle a=0.4 at=1.2,0\npart superellipse a=0.5 b=0.3 eps=0.3 "
		"rot=0.5 at=-1,0.4\nobject room\nobstacle box size=20,1 at=0,-8\nobstacle box size=1,16 rot=0.1 at=-9,0\n"
		"obstacle box size=3,2 rot=0.7 shear=0.2 at=3,3\nobstacle ellipse a=2 b=1 rot=0.4 at=-3,4\n"
		"obstacle superellipse a=1.5 b=1 eps=0.1 at=5,-3\nobstacle circle a=1 at=-4,-3\nobstacle superellipse a=1 b=2 "
		"eps=1.7 at=7,6\nheadings 1\n";
	mkScene s;
	double poses[NP * 3];
	mkPoseAnswer ans[NP];
	prepare(text, 2, &s, poses, NP, ans);
	mkSceneQueryOptions o = mkSceneQueryOptions_Default();
	int counts[3] = {0, 0, 0}, bad = 0;
	double worst_gap = 0.0;
	for (int k = 0; k < NP; ++k) {
		double lo = INFINITY, lo_reported = NAN;
		for (int j = 0; j < s.part_count; ++j)
			for (int i = 0; i < s.obstacle_count; ++i) {
				double f = ref_pair2(&s, poses + 3 * k, j, i);
				lo = fmin(lo, f);
				if (i == ans[k].obstacle && j == ans[k].part) lo_reported = f;
			}
		/* tolerances: the reference's sampling, and the models (model_rel
		 * of reaches ~ 10, two bodies) */
		double tol = 1e-6 + 4.0 * o.model_rel * 10.0;
		const mkPoseAnswer *a = &ans[k];
		++counts[a->status];
		int fail = 0;
		if (a->status == MK_POSE_FREE)
			fail = !(a->clearance <= lo + 1e-9) || !(a->clearance >= lo - tol) || !(fabs(lo_reported - lo) <= tol);
		else if (a->status == MK_POSE_COLLIDING)
			fail = !(lo < 1e-6);
		else
			fail = !(fabs(lo) <= tol);
		if (a->status == MK_POSE_FREE) worst_gap = fmax(worst_gap, lo - a->clearance);
		if (fail) {
			fprintf(stderr, "  pose %d: %s clearance %.17g obstacle %d part %d; reference %.17g\n", k,
				mkPoseStatus_Name(a->status), a->clearance, a->obstacle, a->part, lo);
			++bad;
		}
	}
	ENSURE(bad == 0);
	ENSURE(counts[MK_POSE_FREE] > 10 && counts[MK_POSE_COLLIDING] > 10);
	printf("2D room, 7 obstacles, 3 parts, %d poses: %d free, %d colliding, %d uncertain; largest clearance below the "
		"reference %.3g\n", NP, counts[0], counts[1], counts[2], worst_gap);
	mkScene_Free(&s);
}

int main(void)
{
	test_3d();
	test_2d();
	test_3d_onepair(40, 10.0);
	test_3d_onepair(16, 5.0);
	test_3d_boxes(30);
	test_3d_boxes(16);
	/* (capped queries: scenes of at most 128 obstacles test their spheres side by side, larger ones walk the hierarchy) */
	test_3d_onepair(200, 17.0);
	test_3d_boxes(150);
	return mk_summary("test_scene_query");
}
