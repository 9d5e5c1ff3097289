/* test_batch.c - the batched queries of mink/batch.h, every mode, against
 *  - the one-pair query (mkCollide3_BatchReference: mkCollide3_Normal on
 *    every pair): the same status on every pair, distances within 1e-12 of
 *    the scale, the same clearance verdict outside the stated margin;
 *  - the referee of the collider registry (support maps only, not the
 *    solver): statuses where it is certain and |sd| > 1e-9 of the scale,
 *    distances inside its certified bracket within 1e-12 of the scale;
 *  - the certificates themselves, by code that shares nothing with the
 *    bounds: a separating direction's f(n) by mkCollide3_Bound
 *    (mkBody3_SupportValue), an overlap point inside both bodies by their
 *    implicit functions (mkBody3_Implicit < 1);
 * on the paper's pairs (ellipsoids, superquadrics), near-touching pairs
 * (moved along the normal to a signed distance 1e-1 ... 1e-6 of the
 * scale, both sides), box-like pairs (exponents U(0.05, 0.3)) and deep
 * pairs (centres within U(-2, 2)^3), and planar pairs as the scene query
 * makes of 2D bodies (superellipses, box-like ones among them, lifted to
 * superquadrics with eps1 = 1 whose z = 0 sections they are, rotated about
 * z, centres in z = 0, most overlapping: Gilbert's hull then lies in the
 * plane, and every overlap deeper than 1e-3 of the scale must be certified
 * by an overlap point in STATUS mode). Prints how many pairs each path
 * answered (the fallbacks to the one-pair query), and checks the
 * arguments' errors. */
#include <mink/colliders.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "draw3.h"
#include "draw_paper.h"
#include "ensure.h"

enum { MK_N = 300, MK_KINDS = 7, MK_PLANAR = 6 };
static const char *const mkKindNames[MK_KINDS] = { "ellipsoids", "superquadrics", "near-separated", "near-overlapping",
	"box-like", "deep", "planar" };

/* A 2D body (semi-axes U(0.3, 3), exponent 4e-4 as a box's model, or U(0.1,
 * 1.9)) lifted as the scene query lifts it, centred at (x, y, 0). */
static mkBody3 mkDrawPlanar(unsigned long long *seed, double x, double y)
{
	double a = mk_test_uniform(seed, 0.3, 3.0), b = mk_test_uniform(seed, 0.3, 3.0);
	double eps = mk_test_uniform(seed, 0.0, 1.0) < 0.5 ? 4e-4 : mk_test_uniform(seed, 0.1, 1.9);
	double th = mk_test_uniform(seed, -3.2, 3.2);
	mkShape3 s = { a, b, a > b ? a : b, 1.0, eps };
	mkMat3 M = { { { cos(th), -sin(th), 0.0 }, { sin(th), cos(th), 0.0 }, { 0.0, 0.0, 1.0 } } };
	return mkBody3_Make(s, M, mkVec3_Make(x, y, 0.0));
}

/* Pairs of kind k. */
static void mkDrawKind(int kind, unsigned long long *seed, mkBody3 *b1, mkBody3 *b2)
{
	for (int p = 0; p < MK_N && kind == MK_PLANAR; ++p) {
		b1[p] = mkDrawPlanar(seed, mk_test_uniform(seed, -1, 1), mk_test_uniform(seed, -1, 1));
		b2[p] = mkDrawPlanar(seed, mk_test_uniform(seed, -4, 4), mk_test_uniform(seed, -4, 4));
	}
	for (int p = 0; p < MK_N && kind != MK_PLANAR; ++p) {
		int ell = kind == 0 || ((kind == 2 || kind == 3 || kind == 5) && p % 2 == 0);
		mk_test_paper_pair3(seed, ell, kind == 5, &b1[p], &b2[p]);
		if (kind == 4) {
			b1[p].shape.eps1 = mk_test_uniform(seed, 0.05, 0.3);
			b1[p].shape.eps2 = mk_test_uniform(seed, 0.05, 0.3);
			b2[p].shape.eps1 = mk_test_uniform(seed, 0.05, 0.3);
			b2[p].shape.eps2 = mk_test_uniform(seed, 0.05, 0.3);
		}
		if (kind == 2 || kind == 3) {
			static const double s[6] = { 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6 };
			mkCollision3 c;
			if (mkCollide3_Normal(b1[p], b2[p], &c) == MK_OK && c.distance > 0.0) {
				double to = (kind == 2 ? 1.0 : -1.0) * s[p % 6] * c.scale;
				b2[p].t = mkVec3_Add(b2[p].t, mkVec3_Scale(c.normal, to - c.distance));
			}
		}
	}
}

typedef struct mkOut {
	mkContact status[MK_N];
	double distance[MK_N], lower[MK_N], upper[MK_N];
	mkVec3 normal[MK_N], p1[MK_N], p2[MK_N];
	unsigned char clear[MK_N], path[MK_N];
} mkOut;

static mkBatchOut3 mkOut_View(mkOut *o)
{
	mkBatchOut3 v = { o->status, o->distance, o->lower, o->upper, o->normal, o->p1, o->p2, o->clear, o->path };
	return v;
}

/* The certificates of the bounds' answers, by independent code. */
static void mkCheckCertificates(const mkBody3 *b1, const mkBody3 *b2, const mkOut *o, int p)
{
	if (o->path[p] == MK_PATH_SEPARATING) {
		/* lower: f(n) where the search evaluated it, else a bound below it
		 * from bounds of the support functions; the witnesses are points
		 * of the bodies at most upper apart */
		double f = mkCollide3_Bound(b1[p], b2[p], o->normal[p]), size = mkCollide3_PairSize(b1[p], b2[p]);
		ENSURE(f > 0.0 && o->lower[p] > 0.0);
		ENSURE_LE(o->lower[p], f + 1e-13 * size);
		ENSURE_LE(mkBody3_Implicit(b1[p], o->p1[p]), 1.0 + 1e-9);
		ENSURE_LE(mkBody3_Implicit(b2[p], o->p2[p]), 1.0 + 1e-9);
		ENSURE_LE(o->upper[p], mkVec3_Length(mkVec3_Sub(o->p2[p], o->p1[p])) + 1e-13 * size);
		ENSURE(o->status[p] == MK_CONTACT_SEPARATED);
		if (isfinite(o->distance[p])) {
			/* a distance of the Newton lanes: the witnesses on the bodies,
			 * the bracket [lower, upper] = [f(n), |p2 - p1|] closed */
			double scale = mkCollide3_PairSize(b1[p], b2[p]), span = mkVec3_Length(mkVec3_Sub(o->p2[p], o->p1[p]));
			ENSURE_NEAR(mkBody3_Implicit(b1[p], o->p1[p]), 1.0, 1e-9);
			ENSURE_NEAR(mkBody3_Implicit(b2[p], o->p2[p]), 1.0, 1e-9);
			ENSURE_NEAR(o->upper[p], span, 1e-15 * scale);
			ENSURE(o->distance[p] == o->lower[p] && o->upper[p] - o->lower[p] <= MK_BATCH_DISTANCE_GAP * scale);
		}
	}
	if (o->path[p] == MK_PATH_OVERLAP_POINT) {
		ENSURE(mkBody3_Implicit(b1[p], o->p1[p]) < 1.0);
		ENSURE(mkBody3_Implicit(b2[p], o->p1[p]) < 1.0);
		ENSURE(o->status[p] == MK_CONTACT_OVERLAPPING && o->upper[p] < 0.0);
	}
}

/* One kind in one mode: the batch against the reference and the referee. */
static void mkCheckMode(int kind, mkBatchMode mode, const mkBody3 *b1, const mkBody3 *b2, const mkCollision3 *ref)
{
	static mkOut got, want;
	mkBatchPairs3 pairs = { MK_N, b1, b2, NULL, NULL };
	mkBatchOut3 vg = mkOut_View(&got), vw = mkOut_View(&want);
	mkBatchStats3 st, stw;
	double delta = 0.05 * mkCollide3_PairSize(b1[0], b2[0]);
	ENSURE(mkCollide3_Batch(&pairs, mode, delta, &vg, &st) == MK_OK);
	ENSURE(mkCollide3_BatchReference(&pairs, mode, delta, &vw, &stw) == MK_OK);
	ENSURE(stw.one_pair == MK_N);
	ENSURE(st.separating + st.overlap_point + st.one_pair + st.failed == MK_N && st.failed == 0);
	ENSURE(st.newton <= st.separating && st.newton_left <= st.one_pair);
	ENSURE(mode == MK_BATCH_DISTANCE || st.newton + st.newton_left == 0);
	ENSURE(st.quick <= st.separating + st.overlap_point && stw.quick == 0);
	printf("  %-17s %-9s bounds: %3d separating, %3d overlap point (%3d before any search); one-pair query: %3d; "
		"Newton lanes: %3d answered, %d left\n", mkKindNames[kind], mkBatchMode_Name(mode), st.separating,
		st.overlap_point, st.quick, st.one_pair, st.newton, st.newton_left);
	for (int p = 0; p < MK_N; ++p) {
		double scale = mkCollide3_PairSize(b1[p], b2[p]);
		ENSURE(got.status[p] == want.status[p]);
		mkCheckCertificates(b1, b2, &got, p);
		if (mode == MK_BATCH_DISTANCE || mode == MK_BATCH_FULL) {
			if (want.status[p] == MK_CONTACT_OVERLAPPING && mode == MK_BATCH_DISTANCE)
				ENSURE(isnan(got.distance[p]));
			else
				ENSURE_NEAR(got.distance[p], want.distance[p], 1e-12 * scale);
		}
		if (mode == MK_BATCH_CLEARANCE) {
			double sd = ref[p].distance;
			if (fabs(sd - delta) > 1e-9 * scale)
				ENSURE(got.clear[p] == (sd >= delta));
			if (fabs(want.distance[p] - delta) > MK_BATCH_MARGIN * scale)
				ENSURE(got.clear[p] == want.clear[p]);
		}
		/* the referee: certain when its bracket is within 1e-10 of the scale */
		if (ref[p].residual <= 1e-10 && fabs(ref[p].distance) > 1e-9 * scale)
			ENSURE((got.status[p] == MK_CONTACT_SEPARATED) == (ref[p].distance > 0.0));
		/* an overlap point's depth is at most the referee's */
		if (got.path[p] == MK_PATH_OVERLAP_POINT && ref[p].residual <= 1e-10)
			ENSURE_LE(ref[p].bound - 1e-12 * scale, got.upper[p]);
		/* planar overlaps: the hull's common point certifies them */
		if (kind == MK_PLANAR && mode == MK_BATCH_STATUS && ref[p].residual <= 1e-10 && ref[p].distance < -1e-3 * scale)
			ENSURE(got.path[p] == MK_PATH_OVERLAP_POINT);
		/* a separated pair's bracket [lower, upper] holds the referee's */
		if (got.path[p] == MK_PATH_SEPARATING && ref[p].residual <= 1e-10) {
			ENSURE_LE(got.lower[p], ref[p].distance + ref[p].gap + 1e-12 * scale);
			ENSURE_LE(ref[p].bound - 1e-12 * scale, got.upper[p]);
		}
		if (isfinite(got.distance[p]) && ref[p].distance > 0.0) {
			ENSURE_LE(ref[p].bound - 1e-12 * scale, got.distance[p]);
			ENSURE_LE(got.distance[p], ref[p].distance + ref[p].gap + 1e-12 * scale);
		}
	}
}

/* The bounds before any search, through the public call: two bodies far
 * apart along a direction u (random, or an axis or a diagonal of a body's
 * frame), exponents over the whole range (1e-6, 1, 2 - 1e-6, U(0, 2)), are
 * separated by the bounds at the centre line, and lower = |d| - H1(u) -
 * H2(-u): H1 + H2 must hold h1 + h2 (mkBody3_SupportValue, the closed form)
 * and exceed it by at most 16 % (each level's bound is within 15.3 % of its
 * pair norm; exact on the axes and the diagonals). */
static void mkCheckQuickBound(void)
{
	enum { N = 256 };
	static const double eps[4] = { 1e-6, 1.0, 2.0 - 1e-6, -1.0 };
	static mkBody3 b1[N], b2[N];
	static mkContact st[N];
	static double lower[N];
	unsigned char path[N];
	unsigned long long seed = 31;
	for (int p = 0; p < N; ++p) {
		mkShape3 s[2];
		for (int j = 0; j < 2; ++j) {
			s[j] = (mkShape3){ mk_test_uniform(&seed, 1, 6), mk_test_uniform(&seed, 1, 6), mk_test_uniform(&seed, 1, 6), 1, 1 };
			double e1 = eps[(p + j) % 4], e2 = eps[(p / 4 + j) % 4];
			s[j].eps1 = e1 < 0.0 ? mk_test_uniform(&seed, 1e-3, 2.0 - 1e-3) : e1;
			s[j].eps2 = e2 < 0.0 ? mk_test_uniform(&seed, 1e-3, 2.0 - 1e-3) : e2;
		}
		b1[p] = mkBody3_Make(s[0], mk_test_rotation(&seed), mkVec3_Make(0, 0, 0));
		mkVec3 u = mkVec3_Normalize(mkVec3_Make(mk_test_uniform(&seed, -1, 1), mk_test_uniform(&seed, -1, 1),
			mk_test_uniform(&seed, -1, 1)));
		if (p % 3 == 1) /* an axis, or a diagonal, of B1's frame */
			u = mkMat3_MulVec(b1[p].M, p % 2 ? mkVec3_Make(1, 0, 0) : mkVec3_Normalize(mkVec3_Make(1, 1, 1)));
		b2[p] = mkBody3_Make(s[1], mk_test_rotation(&seed), mkVec3_Scale(u, 1e3));
	}
	mkBatchPairs3 pairs = { N, b1, b2, NULL, NULL };
	mkBatchOut3 out = { .status = st, .lower = lower, .path = path };
	mkBatchStats3 stats;
	ENSURE(mkCollide3_Batch(&pairs, MK_BATCH_STATUS, 0.0, &out, &stats) == MK_OK);
	ENSURE(stats.quick == N);
	double worst = 1.0;
	for (int p = 0; p < N; ++p) {
		mkVec3 d = mkVec3_Sub(b2[p].t, b1[p].t), u = mkVec3_Normalize(d);
		/* (the support values about the origin, less the centres' parts) */
		double h = mkBody3_SupportValue(b1[p], u) - mkVec3_Dot(u, b1[p].t) + mkBody3_SupportValue(b2[p], mkVec3_Scale(u, -1.0))
			+ mkVec3_Dot(u, b2[p].t);
		double H = mkVec3_Length(d) - lower[p];
		ENSURE(st[p] == MK_CONTACT_SEPARATED && path[p] == MK_PATH_SEPARATING);
		ENSURE_LE(h, H + 1e-12 * mkVec3_Length(d));
		ENSURE_LE(H, 1.16 * h);
		worst = fmax(worst, H / h);
	}
	printf("  bounds before any search: %d pairs far apart, H / h at most %.4f\n", N, worst);
}

/* mkCollide3_BatchBracket: the reference's statuses; every separated pair's
 * bracket holds the referee's distance and, where the search gave it, is at
 * most rel of its upper end wide. */
static void mkCheckBracket(int kind, const mkBody3 *b1, const mkBody3 *b2, const mkCollision3 *ref)
{
	static mkOut got, want;
	const double rel = 0.1;
	mkBatchPairs3 pairs = { MK_N, b1, b2, NULL, NULL };
	mkBatchOut3 vg = mkOut_View(&got), vw = mkOut_View(&want);
	mkBatchStats3 st;
	ENSURE(mkCollide3_BatchBracket(&pairs, rel, &vg, &st) == MK_OK);
	ENSURE(mkCollide3_BatchReference(&pairs, MK_BATCH_STATUS, 0.0, &vw, NULL) == MK_OK);
	printf("  %-17s bracket   bounds: %3d separating, %3d overlap point; one-pair query: %3d\n", mkKindNames[kind],
		st.separating, st.overlap_point, st.one_pair);
	for (int p = 0; p < MK_N; ++p) {
		double scale = mkCollide3_PairSize(b1[p], b2[p]);
		ENSURE(got.status[p] == want.status[p]);
		if (got.path[p] == MK_PATH_OVERLAP_POINT)
			ENSURE(mkBody3_Implicit(b1[p], got.p1[p]) < 1.0 && mkBody3_Implicit(b2[p], got.p1[p]) < 1.0);
		if (got.status[p] != MK_CONTACT_SEPARATED)
			continue;
		if (got.path[p] == MK_PATH_SEPARATING) {
			ENSURE(got.lower[p] > 0.0 && got.upper[p] - got.lower[p] <= rel * got.upper[p]);
			ENSURE(mkCollide3_Bound(b1[p], b2[p], got.normal[p]) >= got.lower[p] - 1e-13 * scale);
		}
		if (ref[p].residual <= 1e-10) {
			ENSURE_LE(got.lower[p], ref[p].distance + ref[p].gap + 1e-12 * scale);
			ENSURE_LE(ref[p].bound - 1e-12 * scale, got.upper[p]);
		}
	}
	mkBatchOut3 none = { got.status, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL };
	ENSURE(mkCollide3_BatchBracket(&pairs, 0.0, &none, NULL) == MK_ERR_ARGUMENT);
	ENSURE(mkCollide3_BatchBracket(&pairs, 1.0, &none, NULL) == MK_ERR_ARGUMENT);
}

/* Bad arguments: MK_ERR_ARGUMENT, nothing written. */
static void mkCheckArguments(const mkBody3 *b1, const mkBody3 *b2)
{
	mkContact status[2] = { MK_CONTACT_UNKNOWN, MK_CONTACT_UNKNOWN };
	mkBatchOut3 out = { status, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL };
	mkBatchPairs3 pairs = { 2, b1, b2, NULL, NULL };
	ENSURE(mkCollide3_Batch(&pairs, MK_BATCH_CLEARANCE, -1.0, &out, NULL) == MK_ERR_ARGUMENT);
	ENSURE(mkCollide3_Batch(&pairs, MK_BATCH_CLEARANCE, NAN, &out, NULL) == MK_ERR_ARGUMENT);
	ENSURE(mkCollide3_Batch(&pairs, (mkBatchMode)7, 0.0, &out, NULL) == MK_ERR_ARGUMENT);
	ENSURE(mkCollide3_Batch(NULL, MK_BATCH_STATUS, 0.0, &out, NULL) == MK_ERR_ARGUMENT);
	pairs.count = -1;
	ENSURE(mkCollide3_Batch(&pairs, MK_BATCH_STATUS, 0.0, &out, NULL) == MK_ERR_ARGUMENT);
	ENSURE(status[0] == MK_CONTACT_UNKNOWN);
	/* index arrays: pair k is bodies1[index1[k]], bodies2[index2[k]] */
	int i1[2] = { 1, 1 }, i2[2] = { 0, 1 };
	mkBatchPairs3 ix = { 2, b1, b2, i1, i2 };
	ENSURE(mkCollide3_Batch(&ix, MK_BATCH_STATUS, 0.0, &out, NULL) == MK_OK);
	mkCollision3 c;
	ENSURE(mkCollide3_Normal(b1[1], b2[0], &c) == MK_OK && status[0] == c.status);
	ENSURE(mkCollide3_Normal(b1[1], b2[1], &c) == MK_OK && status[1] == c.status);
	ENSURE(mkBatchMode_FromName("clearance") == MK_BATCH_CLEARANCE && mkBatchMode_FromName("x") == -1);
}

int main(void)
{
	static mkBody3 b1[MK_N], b2[MK_N];
	static mkCollision3 ref[MK_N];
	const mkCollider *referee = mkColliders_Find("referee");
	ENSURE(referee != NULL);
	if (!referee)
		return mk_summary("test_batch");
	mkColliderScratch scratch;
	unsigned long long seed = 28;
	for (int kind = 0; kind < MK_KINDS; ++kind) {
		mkDrawKind(kind, &seed, b1, b2);
		for (int p = 0; p < MK_N; ++p)
			ENSURE(mkCollider_Run(referee, b1[p], b2[p], &scratch, &ref[p]) == MK_OK);
		for (int mode = 0; mode < 4; ++mode)
			mkCheckMode(kind, (mkBatchMode)mode, b1, b2, ref);
		mkCheckBracket(kind, b1, b2, ref);
	}
	mkCheckArguments(b1, b2);
	mkCheckQuickBound();
	return mk_summary("test_batch");
}
