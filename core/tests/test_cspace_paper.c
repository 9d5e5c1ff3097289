/* test_cspace_paper.c - mkCSpace_Run's paper mode (Table 2's workload) is,
 * bit for bit, one mkSum2_Batch/mkSum3_Batch call per obstacle and
 * orientation.
 *
 * The paper mode computes each obstacle's half of the batch once and the
 * robot's half over many orientations per kernel call (kernel.h, mkKOne*);
 * it claims the very same points. The reference here is the public batch
 * call per (obstacle, orientation), as the paper's driver makes it: the
 * obstacle with the robot at map R_o M. Every coordinate must be equal
 * (tolerance 0: the same operations on the same operands), and every
 * boundary's checksum must be the sum of its coordinates in order. Cases:
 * both dimensions, every available kernel, both forms (normal, gradient),
 * superquadric/superellipse and ellipsoid/ellipse bodies (the kernels'
 * special forms), point counts that make whole and partial kernel groups
 * and tasks (2D 1, 7, 50, 600 angles; 3D grids 2, 3, 10, 23), 150
 * orientations (several tasks per obstacle), 1 and 2 threads; and the
 * orientations run in two pieces (as shards are) equal the whole run. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/cspace.h>

#include "ensure.h"

#define NOB 3
#define NOR 150

static mkSceneBody body2(double a, double b, double eps, double angle, double tx, double ty)
{
	mkSceneBody s;
	memset(&s, 0, sizeof s);
	s.dim = s.spec.dim = 2;
	s.kind = MK_SCENE_SMOOTH;
	s.spec.kind = eps == 1.0 ? MK_KIND_ELLIPSE : MK_KIND_SUPERELLIPSE;
	s.spec.body2 = mkBody2_Make((mkShape2){a, b, eps}, mkMat2_Rotation(angle), (mkVec2){tx, ty});
	return s;
}

static mkSceneBody body3(double a, double b, double c, double e1, double e2, mkMat3 R, mkVec3 t)
{
	mkSceneBody s;
	memset(&s, 0, sizeof s);
	s.dim = s.spec.dim = 3;
	s.kind = MK_SCENE_SMOOTH;
	s.spec.kind = e1 == 1.0 && e2 == 1.0 ? MK_KIND_ELLIPSOID : MK_KIND_SUPERQUADRIC;
	s.spec.body3 = mkBody3_Make((mkShape3){a, b, c, e1, e2}, R, t);
	return s;
}

/* Run the scene in paper mode and compare every boundary with the batch. */
static void check(const mkScene *s, int side, mkImpl impl, mkForm form, int threads, int robot_ellipse)
{
	int dim = s->dim, n = dim == 2 ? side : side * side;
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.mode = MK_CSPACE_PAPER;
	o.uniform = side;
	o.threads = threads;
	o.store = 1;
	o.form = form;
	o.impl = impl;
	o.interleaved = threads > 1; /* both layouts */
	mkCSpaceResult r;
	char msg[512];
	mkCSpace *cs = NULL;
	ENSURE(mkCSpace_Create(s, &o, &cs, msg, sizeof msg) == MK_OK);
	ENSURE(mkCSpace_Run(cs, 0, s->orientation_count, &r, msg, sizeof msg) == MK_OK);
	double *u[3], *q[3];
	for (int d = 0; d < 3; ++d) {
		u[d] = malloc((size_t)n * sizeof(double));
		q[d] = malloc((size_t)n * sizeof(double));
	}
	if (dim == 2) mkSample2_Angles(n, u[0], u[1]);
	else mkSample3_Grid(side, u[0], u[1], u[2]);
	mkSumOptions so = {MK_SET_CONTACT, form, MK_PARAM_SURFACE, impl, MK_PRECISION_DOUBLE};
	long bad = 0, badsum = 0;
	for (int or = 0; or < s->orientation_count; ++or)
		for (int i = 0; i < s->obstacle_count; ++i) {
			long b = (long)or * s->obstacle_count + i;
			if (dim == 2) {
				mkBody2 rob = s->robot.spec.body2;
				rob.M = mkMat2_Mul(mkScene2_Orientation(s, or), rob.M);
				rob.t = mkVec2_Make(0.0, 0.0);
				ENSURE(mkSum2_Batch(s->obstacles[i].spec.body2, rob, &so, u[0], u[1], n, q[0], q[1], NULL, NULL)
					== MK_OK);
			} else {
				mkBody3 rob = s->robot.spec.body3;
				rob.M = mkMat3_Mul(mkScene3_Orientation(s, or), rob.M);
				rob.t = mkVec3_Make(0.0, 0.0, 0.0);
				ENSURE(mkSum3_Batch(s->obstacles[i].spec.body3, rob, &so, u[0], u[1], u[2], n, q[0], q[1], q[2],
					NULL, NULL, NULL) == MK_OK);
			}
			double sum = 0.0;
			mkCSpaceBoundary v = mkCSpaceResult_Boundary(&r, or, i, MK_BOUND_INNER);
			int same = v.count == n;
			for (int j = 0; j < n && same; ++j) {
				long k = (long)j * v.stride;
				same = v.x[k] == q[0][j] && v.y[k] == q[1][j] && (dim == 2 || v.z[k] == q[2][j]);
				sum += q[0][j] + q[1][j] + (dim == 3 ? q[2][j] : 0.0);
			}
			bad += !same;
			badsum += same && r.checksum[b] != sum;
		}
	if (bad || badsum)
		printf("%dD side %d, %s kernel, %s form, %d threads, robot %s: %ld boundaries differ from the batch, "
			"%ld checksums differ\n", dim, side, mkImpl_Name(impl), mkForm_Name(form), threads,
			robot_ellipse ? "ellipse" : "super", bad, badsum);
	ENSURE(bad == 0);
	ENSURE(badsum == 0);
	/* two pieces of the orientations (as --shard runs them) equal the whole */
	int cut = s->orientation_count * 2 / 5;
	long diff = 0;
	for (int piece = 0; piece < 2; ++piece) {
		mkCSpaceResult h;
		int b0 = piece ? cut : 0, b1 = piece ? s->orientation_count : cut;
		ENSURE(mkCSpace_Run(cs, b0, b1, &h, msg, sizeof msg) == MK_OK);
		for (int or = b0; or < b1; ++or)
			for (int i = 0; i < s->obstacle_count; ++i) {
				mkCSpaceBoundary vh = mkCSpaceResult_Boundary(&h, or, i, MK_BOUND_INNER);
				mkCSpaceBoundary vr = mkCSpaceResult_Boundary(&r, or, i, MK_BOUND_INNER);
				diff += vh.count != vr.count || vh.checksum != vr.checksum;
				for (long j = 0; j < vh.count && j < vr.count; ++j) {
					long k = j * vh.stride, kr = j * vr.stride;
					diff += vh.x[k] != vr.x[kr] || vh.y[k] != vr.y[kr] || (dim == 3 && vh.z[k] != vr.z[kr]);
				}
			}
		mkCSpaceResult_Free(&h);
	}
	mkCSpace_Destroy(cs);
	ENSURE(diff == 0);
	for (int d = 0; d < 3; ++d) { free(u[d]); free(q[d]); }
	mkCSpaceResult_Free(&r);
}

int main(void)
{
	static const mkImpl impls[] = {MK_IMPL_SCALAR, MK_IMPL_AVX2, MK_IMPL_AVX512};
	static const mkForm forms[] = {MK_FORM_NORMAL, MK_FORM_GRADIENT};
	mkSceneBody obs2[NOB] = {body2(3, 1.5, 0.3, 0.4, 10, -20), body2(2, 4, 1.0, 1.1, -50, 7),
		body2(5, 0.7, 1.7, 2.9, 0, 100)};
	mkSceneBody obs3[NOB] = {body3(3, 1.5, 2, 0.3, 0.6, mkMat3_FromQuat(0.9, 0.1, -0.3, 0.2), mkVec3_Make(10, -20, 5)),
		body3(2, 4, 1, 1.0, 1.0, mkMat3_FromQuat(0.2, 0.7, 0.1, -0.5), mkVec3_Make(-50, 7, 0)),
		body3(5, 0.7, 3, 1.7, 0.1, mkMat3_FromQuat(-0.4, 0.3, 0.8, 0.1), mkVec3_Make(0, 100, -30))};
	double headings[NOR];
	mkMat3 rots[NOR];
	unsigned long long rng = 12345;
	for (int k = 0; k < NOR; ++k) {
		headings[k] = 2.0 * MK_PI * k / NOR;
		rots[k] = mkMat3_FromQuat(mk_test_uniform(&rng, -1, 1), mk_test_uniform(&rng, -1, 1),
			mk_test_uniform(&rng, -1, 1), mk_test_uniform(&rng, -1, 1));
	}
	for (int re = 0; re < 2; ++re) {
		mkScene s2, s3;
		memset(&s2, 0, sizeof s2);
		memset(&s3, 0, sizeof s3);
		s2.dim = 2;
		s2.robot = re ? body2(1.5, 0.8, 1.0, 0.0, 0, 0) : body2(1.5, 0.8, 0.4, 0.0, 0, 0);
		s2.obstacles = obs2;
		s2.obstacle_count = NOB;
		s2.orientation_count = NOR;
		s2.headings = headings;
		s3.dim = 3;
		s3.robot = re ? body3(1.5, 0.8, 2.5, 1.0, 1.0, mkMat3_Identity(), mkVec3_Make(0, 0, 0))
			: body3(1.5, 0.8, 2.5, 0.5, 1.4, mkMat3_Identity(), mkVec3_Make(0, 0, 0));
		s3.obstacles = obs3;
		s3.obstacle_count = NOB;
		s3.orientation_count = NOR;
		s3.rotations = rots;
		for (size_t k = 0; k < sizeof impls / sizeof impls[0]; ++k) {
			if (!mkImpl_Available(impls[k])) {
				printf("kernel %s not available on this machine: not checked\n", mkImpl_Name(impls[k]));
				continue;
			}
			for (int f = 0; f < 2; ++f) {
				static const int sides2[] = {1, 7, 50, 600}, sides3[] = {2, 3, 10, 23};
				for (int j = 0; j < 4; ++j) {
					check(&s2, sides2[j], impls[k], forms[f], 1 + j % 2, re);
					check(&s3, sides3[j], impls[k], forms[f], 2 - j % 2, re);
				}
			}
		}
	}
	return mk_summary("core.test_cspace_paper");
}
