/* test_batch_lanes.c - the vector lanes of the batched queries
 * (collide/batch_x86.h) against the scalar reference:
 *  - each build's support points of eight superquadrics at eight directions
 *    against mkBody3_Support (the shape module's closed form, other code),
 *    within 1e-13 of the body's size, for exponents over the whole range
 *    (1e-6 ... 2 - 1e-6, and U(0.1, 1.9)) and directions along the axes;
 *  - mkCollide3_BatchImpl with each build against the scalar lanes
 *    (MK_IMPL_SCALAR) on the paper's pairs, near-touching pairs and
 *    box-like pairs: the same status on every pair, lower bounds within
 *    1e-12 of the scale.
 * A build the processor lacks is reported on stdout as not tested. */
#include <math.h>
#include <stdio.h>

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
			ENSURE(mkCollide3_BatchImpl(use[v], &pairs, (mkBatchMode)mode, 0.5, &o, NULL) == MK_OK);
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

int main(void)
{
	static const mkImpl impls[2] = { MK_IMPL_AVX2, MK_IMPL_AVX512 };
	static const char *const names[2] = { "avx2", "avx512" };
	mkLanesFn fns[2] = { mkBatch_SupportLanesAvx2, mkBatch_SupportLanesAvx512 };
	static mkBody3 b1[MK_N], b2[MK_N];
	for (int v = 0; v < 2; ++v) {
		if (!mkImpl_Available(impls[v])) {
			printf("test_batch_lanes: %s is not available on this processor: NOT TESTED\n", names[v]);
			continue;
		}
		unsigned long long seed = 2028;
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
	return mk_summary("test_batch_lanes");
}
