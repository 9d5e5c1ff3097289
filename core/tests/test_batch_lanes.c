/* test_batch_lanes.c - the vector lanes of the batched queries
 * (collide/batch_x86.h) against the scalar reference:
 *  - each build's support points of eight superquadrics at eight directions
 *    against mkBody3_Support (the shape module's closed form, other code),
 *    within 1e-13 of the body's size, for exponents over the whole range
 *    (1e-6 ... 2 - 1e-6, and U(0.1, 1.9)) and directions along the axes;
 *  - mkCollide3_BatchImpl with each build against the scalar lanes
 *    (MK_IMPL_SCALAR) on the paper's pairs, near-touching pairs and
 *    box-like pairs: the same status on every pair, lower bounds within
 *    1e-12 of the scale;
 *  - the ellipsoids' Newton lanes (collide/batch_newton.h): each vector
 *    build against the scalar build (every output the same bits, as both do
 *    the same correctly rounded operations; also when run on fewer
 *    lanes), and the scalar build's
 *    converged lanes by other code: f(n) against mkCollide3_Bound
 *    (mkBody3_SupportValue) and the support points against
 *    mkBody3_Support within 1e-13 of the scale, f against the one-pair
 *    query's distance within 1e-12 of the scale, the residual within
 *    MK_COLLIDE3_RESIDUAL_TOL of the scale; on separated pairs near and far
 *    (1e-1 ... 1e-6 of the scale apart, and as drawn) from starts up to
 *    about 0.6 rad off the centre line.
 *  - a pair's answer does not depend on the other pairs of its call (what
 *    the scene query's gathering of many poses' pairs into one call rests
 *    on): mkCollide3_Batch in every mode but FULL and mkCollide3_BatchBracket
 *    on the pairs all at once, in reverse order and one by one, every
 *    output the same bits, on the paper's, near-touching, box-like and
 *    ellipsoid pairs.
 * A build the processor lacks is reported on stdout as not tested. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "collide/collision_impl.h"
#include "draw3.h"
#include "ensure.h"

typedef void (*mkLanesFn)(const mkBatchLanesIn *in, double s[3][MK_BATCH_VLANES]);

/* Eight bodies and directions through fn, against mkBody3_Support. */
static void mkCheckSupport(mkLanesFn fn, unsigned long long *seed, double elo, double ehi, int axes)
{
	mkBody3 b[MK_BATCH_VLANES];
	mkVec3 y[MK_BATCH_VLANES];
	mkBatchLanesIn in;
	for (int l = 0; l < MK_BATCH_VLANES; ++l) {
		mkShape3 s = { mk_test_uniform(seed, 1, 11), mk_test_uniform(seed, 1, 11), mk_test_uniform(seed, 1, 11),
			mk_test_uniform(seed, elo, ehi), mk_test_uniform(seed, elo, ehi) };
		b[l] = mkBody3_Make(s, mk_test_rotation(seed), mkVec3_Make(0, 0, 0));
		y[l] = mkVec3_Normalize(mkVec3_Make(mk_test_uniform(seed, -1, 1), mk_test_uniform(seed, -1, 1),
			mk_test_uniform(seed, -1, 1)));
		if (axes) { /* exactly along an axis of an unrotated body: pair norms with zero components (near
		               an axis a box-like body's support point moves fast, so rounding would decide) */
			b[l].M = mkMat3_Identity();
			y[l] = mkVec3_Make(l % 3 == 0 ? -1.0 : 0.0, l % 3 == 1, l % 3 == 2);
		}
		for (int i = 0; i < 9; ++i)
			in.P[i][l] = b[l].M.m[i / 3][i % 3] * (i % 3 == 0 ? s.a : i % 3 == 1 ? s.b : s.c);
		in.q1[l] = 2.0 / (2.0 - s.eps1);
		in.q2[l] = 2.0 / (2.0 - s.eps2);
		in.iq1[l] = 1.0 - 0.5 * s.eps1;
		in.iq2[l] = 1.0 - 0.5 * s.eps2;
		in.y[0][l] = y[l].x;
		in.y[1][l] = y[l].y;
		in.y[2][l] = y[l].z;
	}
	double sv[3][MK_BATCH_VLANES];
	fn(&in, sv);
	for (int l = 0; l < MK_BATCH_VLANES; ++l) {
		mkVec3 want = mkBody3_Support(b[l], y[l]);
		double size = 11.0;
		ENSURE_NEAR(sv[0][l], want.x, 1e-13 * size);
		ENSURE_NEAR(sv[1][l], want.y, 1e-13 * size);
		ENSURE_NEAR(sv[2][l], want.z, 1e-13 * size);
	}
}

typedef void (*mkEllFn)(const mkBatchEllIn *in, mkBatchEllOut *out);

/* MK_BATCH_NLANES separated pairs of ellipsoids through fn and through the scalar
 * build; returns the number of lanes that converged. */
static int mkCheckEllipsoids(mkEllFn fn, unsigned long long *seed, int rep)
{
	mkBody3 b1[MK_BATCH_NLANES], b2[MK_BATCH_NLANES];
	mkBatchEllIn in;
	for (int l = 0; l < MK_BATCH_NLANES; ++l) {
		mk_test_pair3(seed, 1.0, 1.0, &b1[l], &b2[l]);
		mkCollision3 c;
		ENSURE(mkCollide3_Normal(b1[l], b2[l], &c) == MK_OK);
		if (c.distance > 0.0 && (rep + l) % 2 == 0) /* moved to 1e-1 ... 1e-6 of the scale apart */
			b2[l].t = mkVec3_Add(b2[l].t, mkVec3_Scale(c.normal, pow(10.0, -1 - (rep + l) % 6) * c.scale - c.distance));
		else if (!(c.distance > 0.0))
			b2[l].t = mkVec3_Add(b2[l].t, mkVec3_Scale(c.normal, 0.1 * c.scale - c.distance));
		/* the start: the centre line where f > 0 there (as the batch's
		 * starts: separating directions), else and on every other lane the
		 * normal of the answer moved by up to 0.03 per component */
		mkVec3 d = mkVec3_Sub(b2[l].t, b1[l].t), n = mkVec3_Normalize(d);
		ENSURE(mkCollide3_Normal(b1[l], b2[l], &c) == MK_OK);
		if (l % 2 || !(mkCollide3_Bound(b1[l], b2[l], n) > 0.0))
			n = mkVec3_Normalize(mkVec3_Add(c.normal, mkVec3_Make(mk_test_uniform(seed, -0.03, 0.03),
				mk_test_uniform(seed, -0.03, 0.03), mk_test_uniform(seed, -0.03, 0.03))));
		const mkBody3 *b[2] = { &b1[l], &b2[l] };
		for (int k = 0; k < 2; ++k) {
			double P[3][3], Q[3][3];
			mkShape3 s = b[k]->shape;
			for (int i = 0; i < 3; ++i)
				for (int j = 0; j < 3; ++j)
					P[i][j] = b[k]->M.m[i][j] * (j == 0 ? s.a : j == 1 ? s.b : s.c);
			for (int i = 0; i < 3; ++i)
				for (int j = 0; j < 3; ++j)
					Q[i][j] = P[i][0] * P[j][0] + P[i][1] * P[j][1] + P[i][2] * P[j][2];
			const double q6[6] = { Q[0][0], Q[0][1], Q[0][2], Q[1][1], Q[1][2], Q[2][2] };
			for (int i = 0; i < 6; ++i)
				(k ? in.Q2 : in.Q1)[i][l] = q6[i];
		}
		const double dv[3] = { d.x, d.y, d.z }, nv[3] = { n.x, n.y, n.z };
		for (int i = 0; i < 3; ++i) {
			in.d[i][l] = dv[i];
			in.n[i][l] = nv[i];
		}
		in.scale[l] = mkCollide3_PairSize(b1[l], b2[l]);
	}
	in.count = MK_BATCH_NLANES;
	mkBatchEllOut want, got;
	mkBatch_EllipsoidLanesScalar(&in, &want);
	fn(&in, &got);
	ENSURE(memcmp(&want, &got, sizeof want) == 0);
	in.count = 1 + rep % MK_BATCH_NLANES; /* fewer lanes: the same bits on those */
	fn(&in, &got);
	for (int l = 0; l < in.count; ++l) {
		ENSURE(got.f[l] == want.f[l] && got.done[l] == want.done[l] && got.steps[l] == want.steps[l]);
		for (int i = 0; i < 3; ++i)
			ENSURE(got.n[i][l] == want.n[i][l] && got.s1[i][l] == want.s1[i][l] && got.s2[i][l] == want.s2[i][l]);
	}
	int conv = 0;
	for (int l = 0; l < MK_BATCH_NLANES; ++l) {
		if (want.done[l] != 1.0)
			continue;
		++conv;
		double scale = in.scale[l];
		mkVec3 n = mkVec3_Make(want.n[0][l], want.n[1][l], want.n[2][l]);
		mkVec3 s1 = mkVec3_Add(b1[l].t, mkVec3_Make(want.s1[0][l], want.s1[1][l], want.s1[2][l]));
		mkVec3 s2 = mkVec3_Add(b2[l].t, mkVec3_Make(want.s2[0][l], want.s2[1][l], want.s2[2][l]));
		mkVec3 r1 = mkBody3_Support(b1[l], n), r2 = mkBody3_Support(b2[l], mkVec3_Neg(n));
		ENSURE_NEAR(mkVec3_Length(mkVec3_Sub(s1, r1)), 0.0, 1e-13 * scale);
		ENSURE_NEAR(mkVec3_Length(mkVec3_Sub(s2, r2)), 0.0, 1e-13 * scale);
		ENSURE_NEAR(want.f[l], mkCollide3_Bound(b1[l], b2[l], n), 1e-13 * scale);
		ENSURE(mkVec3_Length(mkVec3_Sub(r2, r1)) - want.f[l] <= 1e-12 * scale);
		mkCollision3 c;
		ENSURE(mkCollide3_Normal(b1[l], b2[l], &c) == MK_OK);
		ENSURE_NEAR(want.f[l], c.distance, 1e-12 * scale);
	}
	return conv;
}

enum { MK_N = 400 };

/* The batch through impl against the scalar lanes, every mode but FULL
 * (which runs the one-pair query alone): the same status, and each
 * build's certificates checked by other code (mkCollide3_Bound at a
 * separating direction, mkBody3_Implicit at an overlap point). */
static void mkCheckBatch(mkImpl impl, const mkBody3 *b1, const mkBody3 *b2)
{
	static mkContact st[2][MK_N];
	static double lo[2][MK_N];
	static mkVec3 n[2][MK_N], x[2][MK_N];
	static unsigned char path[2][MK_N];
	mkBatchPairs3 pairs = { MK_N, b1, b2, NULL, NULL };
	const mkImpl use[2] = { MK_IMPL_SCALAR, impl };
	for (int mode = 0; mode < 3; ++mode) {
		for (int v = 0; v < 2; ++v) {
			mkBatchOut3 o = { st[v], NULL, lo[v], NULL, n[v], x[v], NULL, NULL, path[v] };
			ENSURE(mkCollide3_BatchImpl(use[v], 0, &pairs, (mkBatchMode)mode, 0.5, &o, NULL) == MK_OK);
		}
		for (int p = 0; p < MK_N; ++p) {
			ENSURE(st[0][p] == st[1][p]);
			double scale = mkCollide3_PairSize(b1[p], b2[p]);
			for (int v = 0; v < 2; ++v) {
				if (path[v][p] == MK_PATH_SEPARATING)
					ENSURE_NEAR(mkCollide3_Bound(b1[p], b2[p], n[v][p]), lo[v][p], 1e-12 * scale);
				if (path[v][p] == MK_PATH_OVERLAP_POINT)
					ENSURE(mkBody3_Implicit(b1[p], x[v][p]) <= 1.0 && mkBody3_Implicit(b2[p], x[v][p]) <= 1.0);
			}
		}
	}
}

/* The answers of the pairs all at once, in reverse order and one by one
 * (mode < 0: mkCollide3_BatchBracket at rel 0.1), compared bit for bit. */
static void mkCheckAlone(const mkBody3 *b1, const mkBody3 *b2, int mode, double delta)
{
	enum { W = 3 };
	static mkContact st[W][MK_N];
	static double lo[W][MK_N], up[W][MK_N], dist[W][MK_N];
	static mkVec3 n[W][MK_N], x1[W][MK_N], x2[W][MK_N];
	static unsigned char clear[W][MK_N], path[W][MK_N];
	static int rev[MK_N];
	for (int p = 0; p < MK_N; ++p) rev[p] = MK_N - 1 - p;
	for (int w = 0; w < W; ++w) {
		int count = w == 2 ? 1 : MK_N;
		for (int at = 0; at < (w == 2 ? MK_N : 1); ++at) {
			int k = w == 2 ? at : 0;
			mkBatchPairs3 pairs = { count, b1, b2, w == 1 ? rev : w == 2 ? &rev[MK_N - 1 - k] : NULL,
				w == 1 ? rev : w == 2 ? &rev[MK_N - 1 - k] : NULL };
			mkBatchOut3 o = { st[w] + k, dist[w] + k, lo[w] + k, up[w] + k, n[w] + k, x1[w] + k, x2[w] + k,
				clear[w] + k, path[w] + k };
			mkResult r = mode < 0 ? mkCollide3_BatchBracket(&pairs, 0.1, &o, NULL)
				: mkCollide3_Batch(&pairs, (mkBatchMode)mode, delta, &o, NULL);
			ENSURE(r == MK_OK || r == MK_ERR_CONVERGENCE);
		}
	}
	for (int p = 0; p < MK_N; ++p)
		for (int w = 1; w < W; ++w) {
			int q = w == 1 ? MK_N - 1 - p : p;   /* pair p's answer in arrangement w */
			ENSURE(st[w][q] == st[0][p] && path[w][q] == path[0][p]);
			ENSURE(memcmp(&lo[w][q], &lo[0][p], sizeof(double)) == 0 && memcmp(&up[w][q], &up[0][p], sizeof(double)) == 0);
			ENSURE(memcmp(&n[w][q], &n[0][p], sizeof(mkVec3)) == 0 && memcmp(&x1[w][q], &x1[0][p], sizeof(mkVec3)) == 0
				&& memcmp(&x2[w][q], &x2[0][p], sizeof(mkVec3)) == 0);
			if (mode == MK_BATCH_CLEARANCE) ENSURE(clear[w][q] == clear[0][p]);
			if (mode == MK_BATCH_DISTANCE) ENSURE(memcmp(&dist[w][q], &dist[0][p], sizeof(double)) == 0);
		}
}

int main(void)
{
	static const mkImpl impls[2] = { MK_IMPL_AVX2, MK_IMPL_AVX512 };
	static const char *const names[2] = { "avx2", "avx512" };
	mkLanesFn fns[2] = { mkBatch_SupportLanesAvx2, mkBatch_SupportLanesAvx512 };
	static mkBody3 b1[MK_N], b2[MK_N];
	mkEllFn efns[2] = { mkBatch_EllipsoidLanesAvx2, mkBatch_EllipsoidLanesAvx512 };
	{
		/* the scalar build by other code (against itself for the bits) */
		unsigned long long seed = 2029;
		int conv = 0;
		for (int rep = 0; rep < 40; ++rep)
			conv += mkCheckEllipsoids(mkBatch_EllipsoidLanesScalar, &seed, rep);
		printf("test_batch_lanes: ellipsoids' Newton lanes, scalar: %d of %d lanes converged\n", conv,
			40 * MK_BATCH_NLANES);
		ENSURE(conv >= 38 * MK_BATCH_NLANES);
	}
	for (int v = 0; v < 2; ++v) {
		if (!mkImpl_Available(impls[v])) {
			printf("test_batch_lanes: %s is not available on this processor: NOT TESTED\n", names[v]);
			continue;
		}
		unsigned long long seed = 2028;
		for (int rep = 0; rep < 40; ++rep)
			mkCheckEllipsoids(efns[v], &seed, rep);
		for (int rep = 0; rep < 50; ++rep) {
			mkCheckSupport(fns[v], &seed, 0.1, 1.9, 0);
			mkCheckSupport(fns[v], &seed, 1e-6, 2.0 - 1e-6, 0);
			mkCheckSupport(fns[v], &seed, 0.1, 1.9, 1);
		}
		for (int kind = 0; kind < 3; ++kind) {
			for (int p = 0; p < MK_N; ++p) {
				mk_test_pair3(&seed, kind == 2 ? 0.05 : 0.1, kind == 2 ? 0.3 : 1.9, &b1[p], &b2[p]);
				mkCollision3 c;
				if (kind == 1 && mkCollide3_Normal(b1[p], b2[p], &c) == MK_OK && c.distance > 0.0)
					b2[p].t = mkVec3_Add(b2[p].t, mkVec3_Scale(c.normal, pow(10.0, -1 - p % 6) * c.scale - c.distance));
			}
			mkCheckBatch(impls[v], b1, b2);
		}
		printf("test_batch_lanes: %s checked\n", names[v]);
	}
	{
		/* every pair's answer alone, on whichever lanes this processor runs */
		unsigned long long seed = 2030;
		for (int kind = 0; kind < 4; ++kind) {
			for (int p = 0; p < MK_N; ++p) {
				double elo = kind == 2 ? 0.05 : kind == 3 ? 1.0 : 0.1, ehi = kind == 2 ? 0.3 : kind == 3 ? 1.0 : 1.9;
				mk_test_pair3(&seed, elo, ehi, &b1[p], &b2[p]);
				mkCollision3 c;
				if (kind == 1 && mkCollide3_Normal(b1[p], b2[p], &c) == MK_OK && c.distance > 0.0)
					b2[p].t = mkVec3_Add(b2[p].t, mkVec3_Scale(c.normal, pow(10.0, -1 - p % 6) * c.scale - c.distance));
			}
			mkCheckAlone(b1, b2, MK_BATCH_STATUS, 0.0);
			mkCheckAlone(b1, b2, MK_BATCH_CLEARANCE, kind == 1 ? 1e-3 : 0.5);
			mkCheckAlone(b1, b2, MK_BATCH_DISTANCE, 0.0);
			mkCheckAlone(b1, b2, -1, 0.0);
		}
		printf("test_batch_lanes: answers alone and in company the same bits\n");
	}
	return mk_summary("test_batch_lanes");
}
