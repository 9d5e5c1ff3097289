/* test_cspace_prep.c - the scene query's poses prepared side by side
 * (cspace/sceneprep.h) against the one-pose path's operations: every build
 * the CPU runs (portable, AVX2, AVX-512F) gives, to the bit, the rotation of
 * mkMat3_FromQuatInline, the part centres c + R t (mkVec3_Add,
 * mkMat3_MulVecInline) and the float query boxes mkSw_Down(centre - half),
 * mkSw_Up(centre + half) of every lane, on random poses and on poses with
 * quaternions of tiny (a subnormal squared norm) and huge norms and
 * positions up to 1e150 (what the scene query's answers being the same
 * bits as one pose at a time rests on). A build that differs in one lane is
 * caught (a lane swapped). The exact boxes of ellipsoid parts (every
 * subset of the parts, random matrices and semi-axes) against the one-pose
 * path's product and square root, to the bit; the masks of the spheres
 * near the parts (1 to 128 spheres, every other block) against the test of
 * two spheres written out at the one-pose centre. And the poses' test (mkSqPrep_FirstBad) of every
 * build against the test pose by pose, with NaN, infinite and too large
 * values and zero quaternions placed at random; and the test of the
 * spheres near a part (mkSqPrep_Near's builds on squared radii from
 * mkSqPrep_Radius2, as bit masks, full chunks of 8 and tails)
 * against the scene query's test of two spheres written out. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/geom_inline.h"
#include "cspace/sceneprep.h"
#include "cspace/scenewide.h"
#include "ensure.h"

static unsigned long long seed = 31;

static double uni(double lo, double hi) { return mk_test_uniform(&seed, lo, hi); }

static int same(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }
static int samef(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* The lanes of x against the one-pose operations; returns the lanes that differ. */
static int check(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *sp, const mkSqPrep *x)
{
	int bad = 0;
	for (int k = 0; k < n; ++k) {
		const double *p = poses + 7 * k;
		mkMat3 R = mkMat3_FromQuatInline(p[3], p[4], p[5], p[6]);
		int ok = 1;
		for (int i = 0; i < 9; ++i) ok &= same(x->R[i][k], R.m[i / 3][i % 3]);
		for (int j = 0; j < parts && j < MK_SQ_PREP_PARTS; ++j) {
			mkVec3 c = mkVec3_Add(mkVec3_Make(p[0], p[1], p[2]), mkMat3_MulVecInline(R, t[j]));
			double v[3] = {c.x, c.y, c.z};
			for (int i = 0; i < 3; ++i) {
				ok &= same(x->pc[3 * j + i][k], v[i]);
				if (!half) continue;
				ok &= samef(x->lo[3 * j + i][k], mkSw_Down(v[i] - half[j]));
				ok &= samef(x->hi[3 * j + i][k], mkSw_Up(v[i] + half[j]));
			}
			/* the spheres near the part: the test of two spheres written out */
			for (int i = 0; sp && i < sp->n; ++i) {
				double dx = v[0] - sp->x[i], dy = v[1] - sp->y[i], dz = v[2] - sp->z[i];
				int want = !(dx * dx + dy * dy + dz * dz > sp->rr[j * sp->stride + i]);
				ok &= (int)(x->near[j][i / 32][k] >> (i % 32) & 1u) == want;
			}
			for (int w = 0; sp && w < (sp->n + 31) / 32; ++w) /* (no bits past the spheres) */
				ok &= sp->n - 32 * w >= 32 || x->near[j][w][k] >> (sp->n - 32 * w) == 0;
			if (!(ell >> j & 1u)) continue;
			/* an ellipsoid part's exact box, as the scene query's one-pose path forms it */
			mkMat3 RM = mkMat3_MulInline(R, M[j]);
			for (int i = 0; i < 3; ++i) {
				double a = RM.m[i][0] * abc[j][0], b = RM.m[i][1] * abc[j][1], c3 = RM.m[i][2] * abc[j][2];
				ok &= same(x->eh[3 * j + i][k], sqrt(a * a + b * b + c3 * c3) * (1.0 + 1e-13));
			}
		}
		bad += !ok;
	}
	return bad;
}

int main(void)
{
	const mkImpl impls[3] = {MK_IMPL_SCALAR, MK_IMPL_AVX2, MK_IMPL_AVX512};
	const char *names[3] = {"portable", "AVX2", "AVX-512F"};
	int ran = 0;
	for (int b = 0; b < 3; ++b) {
		mkSqPrepFn f = mkSqPrep_Pick(impls[b]);
		if (!f) {
			printf("test_cspace_prep: the %s build is not run here (the CPU or the build lacks it)\n", names[b]);
			continue;
		}
		++ran;
		int bad = 0, blocks = 200, lanes = 0;
		static double poses[7 * MK_SQ_PREP];
		static mkSqPrep x;
		double sx[32 * MK_SQ_PREP_WORDS], sy[32 * MK_SQ_PREP_WORDS], sz[32 * MK_SQ_PREP_WORDS];
		double srr[MK_SQ_PREP_PARTS * (32 * MK_SQ_PREP_WORDS + 1)];
		int near_lanes = 0;
		for (int r = 0; r < blocks; ++r) {
			double half[MK_SQ_PREP_PARTS];
			int n = r % 3 == 0 ? MK_SQ_PREP : 1 + (int)uni(0, MK_SQ_PREP - 1);   /* full and short tasks */
			mkVec3 t[MK_SQ_PREP_PARTS];
			mkMat3 M[MK_SQ_PREP_PARTS];
			double abc[MK_SQ_PREP_PARTS][3];
			int parts = 1 + r % MK_SQ_PREP_PARTS;
			unsigned ell = (unsigned)r & 15u;   /* every subset of the parts with exact boxes */
			for (int j = 0; j < MK_SQ_PREP_PARTS; ++j) {
				t[j] = mkVec3_Make(uni(-2, 2), uni(-2, 2), uni(-2, 2));
				half[j] = uni(0.01, 3) * (1.0 + 1e-12);
				for (int i = 0; i < 9; ++i) M[j].m[i / 3][i % 3] = uni(-1.5, 1.5);   /* (rotation and shear) */
				for (int i = 0; i < 3; ++i) abc[j][i] = uni(0.01, 5);
			}
			for (int k = 0; k < n; ++k) {
				double *p = poses + 7 * k, pos = r % 4 == 3 ? 1e150 : r % 4 == 2 ? 1e6 : 10.0;
				double qs = r % 10 == 9 ? 1e-160 : r % 5 == 4 ? 1e-150 : r % 5 == 3 ? 1e140 : 1.0;   /* (1e-160: a subnormal squared norm) */
				for (int d = 0; d < 3; ++d) p[d] = uni(-pos, pos);
				for (int d = 3; d < 7; ++d) p[d] = qs * uni(-1, 1);
			}
			/* every other block, the masks of 1 to 128 spheres near the parts (positions of lane 0's
			 * scale; a sphere's edge at lane 0's first part's centre up to rounding) */
			mkSqPrepSpheres sp = {sx, sy, sz, srr, 1 + r % (32 * MK_SQ_PREP_WORDS), 32 * MK_SQ_PREP_WORDS + 1};
			double span = fabs(poses[0]) + fabs(poses[1]) + fabs(poses[2]) + 2.0, bound = r % 3 == 0 ? 1e-9 : uni(0, 1);
			for (int i = 0; i < sp.n; ++i) {
				sx[i] = uni(-span, span); sy[i] = uni(-span, span); sz[i] = uni(-span, span);
				double rad = uni(0.1, span);
				for (int j = 0; j < MK_SQ_PREP_PARTS; ++j) srr[j * sp.stride + i] = mkSqPrep_Radius2(0.5 * (j + 1), rad, bound);
				if (i == 0 && r % 4 == 1) {
					mkMat3 R0 = mkMat3_FromQuatInline(poses[3], poses[4], poses[5], poses[6]);
					mkVec3 c0 = mkVec3_Add(mkVec3_Make(poses[0], poses[1], poses[2]), mkMat3_MulVecInline(R0, t[0]));
					sx[0] = c0.x + (0.5 + rad + bound) * (1.0 + 1e-12); sy[0] = c0.y; sz[0] = c0.z;
				}
			}
			const mkSqPrepSpheres *use = r % 2 ? &sp : NULL;
			const double *hv = r % 5 == 4 ? NULL : half;   /* (no query boxes: the rest the same) */
			f(poses, n, parts, t, hv, M, (const double (*)[3])abc, ell, use, &x);
			bad += check(poses, n, parts, t, hv, M, (const double (*)[3])abc, ell, use, &x);
			lanes += n;
			near_lanes += use ? n : 0;
			if (r == 0 || r == 1) { /* a lane swapped is caught; so is a mask's bit */
				double keep = x.R[4][3];
				x.R[4][3] = x.R[4][5];
				ENSURE(check(poses, n, parts, t, half, M, (const double (*)[3])abc, ell, use, &x) > 0);
				x.R[4][3] = keep;
			}
			if (r == 1) {
				x.near[0][0][0] ^= 1u;
				ENSURE(check(poses, n, parts, t, half, M, (const double (*)[3])abc, ell, use, &x) > 0);
				x.near[0][0][0] ^= 1u;
			}
		}
		printf("test_cspace_prep: %s build, %d blocks of 1 to %d poses (%d in all, %d with the masks of spheres near the "
			"parts): %d differ from the one-pose operations\n", names[b], blocks, MK_SQ_PREP, lanes, near_lanes, bad);
		ENSURE(bad == 0);
	}
	/* the poses' test: the first bad pose of every build, against the test pose by pose */
	static double many[7 * 3000];
	int wrong = 0, cases = 0;
	for (int r = 0; r < 400; ++r) {
		long n = 1 + (long)uni(0, 2999);
		for (long k = 0; k < 7 * n; ++k) many[k] = uni(-5, 5);
		long at = r % 4 == 0 ? n : (long)uni(0, (double)n);   /* a quarter without a bad pose */
		if (at >= n) at = r % 4 == 0 ? n : n - 1;
		if (at < n) {
			int kind = r % 7, d = (int)uni(0, 7) % 7;
			double bad[5] = {NAN, INFINITY, -INFINITY, 1.0000001e150, 0.0};
			if (kind == 4 || kind == 5) for (int m = 3; m < 7; ++m) many[7 * at + m] = 0.0;   /* a zero quaternion */
			else many[7 * at + d] = bad[kind % 4];
		}
		if (r % 5 == 1) many[7 * (n - 1)] = 1e150;   /* the bound itself is allowed */
		long want = n;
		for (long k = 0; k < n && want == n; ++k) {
			const double *q = many + 7 * k;
			int ok = 1;
			for (int m = 0; m < 7; ++m) ok &= isfinite(q[m]) && fabs(q[m]) <= 1e150;
			if (!ok || !(q[3] * q[3] + q[4] * q[4] + q[5] * q[5] + q[6] * q[6] > 0.0)) want = k;
		}
		for (int b = 0; b < 3; ++b) {
			mkSqFirstBadFn f = mkSqPrep_PickFirstBad(impls[b]);
			if (!f) continue;
			++cases;
			wrong += f(many, n) != want;
		}
		wrong += mkSqPrep_PickFirstBad(MK_IMPL_AUTO)(many, n) != want;
	}
	printf("test_cspace_prep: the poses' test on %d cases of 1 to 3,000 poses: %d wrong\n", cases, wrong);
	ENSURE(wrong == 0);
	/* the spheres near a part against the scene query's test of two spheres, written out */
	int near_wrong = 0, near_cases = 0;
	for (int r = 0; r < 2000; ++r) {
		double x[24], y[24], z[24], rad[24], c[3] = {uni(-5, 5), uni(-5, 5), uni(-5, 5)}, prad = uni(0.1, 2);
		double b = r % 3 == 0 ? 1e-9 : r % 3 == 1 ? uni(0, 1) : -uni(0, 0.5);
		int n = 1 + r % 24;
		for (int i = 0; i < n; ++i) {
			x[i] = uni(-5, 5); y[i] = uni(-5, 5); z[i] = uni(-5, 5); rad[i] = uni(0.1, 2);
			if (i == 0 && r % 4 == 0) { /* exactly at the bound's edge, up to rounding */
				double dd = (prad + rad[i] + b) * (1.0 + 1e-12);
				x[i] = c[0] + dd; y[i] = c[1]; z[i] = c[2];
			}
		}
		double rr2[24];
		for (int i = 0; i < n; ++i) rr2[i] = mkSqPrep_Radius2(prad, rad[i], b);
		for (int v = 0; v < 3; ++v) { /* each build the CPU runs, against the test written out below */
			mkSqNearFn f = mkSqPrep_PickNear(impls[v]);
			if (!f) continue;
			uint32_t near = f(x, y, z, rr2, n, c);
			++near_cases;
			near_wrong += n < 32 && near >> n != 0;
			for (int i = 0; i < n; ++i) {
				double dx = c[0] - x[i], dy = c[1] - y[i], dz = c[2] - z[i], rr = (prad + rad[i] + b) * (1.0 + 1e-12);
				int want = !(dx * dx + dy * dy + dz * dz > rr * rr);
				near_wrong += (int)(near >> i & 1u) != want;
				near_wrong += (!mkSqPrep_Apart(dx, dy, dz, prad, rad[i], b)) != want;   /* (the pair test the query shares) */
			}
		}
	}
	printf("test_cspace_prep: the spheres near a part, %d cases of 1 to 24 obstacles (each build): %d wrong\n", near_cases,
		near_wrong);
	ENSURE(near_wrong == 0);
	ENSURE(ran >= 1);
	ENSURE(mkSqPrep_Pick(MK_IMPL_AUTO) != NULL);
	return mk_summary("test_cspace_prep");
}
