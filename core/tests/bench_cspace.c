/* bench_cspace.c - wall time of Table 2's 3D row through mink/cobstacle.h,
 * on 1 and 2 threads side by side in one process (A B A B), and the
 * adaptive/uniform point counts of a boxy 3D scene. Not a test: it prints
 * figures (docs/scene.md quotes them).
 *
 *   bench_cspace [ROTATIONS_CSV] [OBSTACLES] [ORIENTATIONS]
 *
 * Table 2's 3D row: 1000 obstacles x 3600 orientations x 100 points (a
 * 10 x 10 surface grid, the paper's sampling, gradient form), bodies drawn
 * as the Table 2 driver draws them (robot a, b, c ~ U(0,5); obstacles
 * a, b, c ~ U(0,10), centres ~ U(-200,200)^3; eps ~ U(0,2) clamped to the
 * valid range; random rotations), orientations from the CSV (the SO(3)
 * set of experiments/data) or random ones. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <mink/cspace.h>

#include "ensure.h"

static double now_s(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double cpu_s(void)
{
	struct timespec t;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The 1-minute load average, or -1: other processes on the machine take
 * cores from a wall-time measurement, and this says how many. */
static double loadavg(void)
{
	FILE *f = fopen("/proc/loadavg", "r");
	double l = -1.0;
	if (f) {
		if (fscanf(f, "%lf", &l) != 1) l = -1.0;
		fclose(f);
	}
	return l;
}

static double clampe(double e) { return e < MK_EPS_MIN ? MK_EPS_MIN : e > MK_EPS_MAX ? MK_EPS_MAX : e; }
static double clampa(double a) { return a < MK_AXIS_MIN ? MK_AXIS_MIN : a; }

static mkMat3 random_rotation(unsigned long long *rng)
{
	return mkMat3_FromQuat(mk_test_uniform(rng, -1, 1), mk_test_uniform(rng, -1, 1), mk_test_uniform(rng, -1, 1),
		mk_test_uniform(rng, -1, 1));
}

int main(int argc, char **argv)
{
	const char *rotfile = argc > 1 ? argv[1] : NULL;
	int nob = argc > 2 ? atoi(argv[2]) : 1000, nor = argc > 3 ? atoi(argv[3]) : 3600;
	unsigned long long rng = 2022;
	mkScene s;
	memset(&s, 0, sizeof s);
	s.dim = 3;
	s.robot.dim = 3;
	s.robot.kind = MK_SCENE_SMOOTH;
	s.robot.spec.dim = 3;
	s.robot.spec.body3 = mkBody3_Make((mkShape3){clampa(mk_test_uniform(&rng, 0, 5)), clampa(mk_test_uniform(&rng, 0, 5)),
		clampa(mk_test_uniform(&rng, 0, 5)), clampe(mk_test_uniform(&rng, 0, 2)), clampe(mk_test_uniform(&rng, 0, 2))},
		mkMat3_Identity(), mkVec3_Make(0, 0, 0));
	s.obstacles = calloc((size_t)nob, sizeof *s.obstacles);
	s.obstacle_count = nob;
	for (int i = 0; i < nob; ++i) {
		mkSceneBody *b = &s.obstacles[i];
		b->dim = 3;
		b->kind = MK_SCENE_SMOOTH;
		b->spec.dim = 3;
		mkShape3 sh = {clampa(mk_test_uniform(&rng, 0, 10)), clampa(mk_test_uniform(&rng, 0, 10)),
			clampa(mk_test_uniform(&rng, 0, 10)), clampe(mk_test_uniform(&rng, 0, 2)), clampe(mk_test_uniform(&rng, 0, 2))};
		mkVec3 t = {mk_test_uniform(&rng, -200, 200), mk_test_uniform(&rng, -200, 200), mk_test_uniform(&rng, -200, 200)};
		b->spec.body3 = mkBody3_Make(sh, random_rotation(&rng), t);
	}
	char msg[512];
	if (rotfile) {
		FILE *f = fopen(rotfile, "rb");
		if (!f) { fprintf(stderr, "bench_cspace: cannot open %s\n", rotfile); return 1; }
		size_t cap = 1 << 20, n = 0;
		char *text = malloc(cap);
		size_t got;
		while ((got = fread(text + n, 1, cap - n - 1, f)) > 0) {
			n += got;
			if (n + 1 >= cap) text = realloc(text, cap *= 2);
		}
		fclose(f);
		text[n] = 0;
		if (mkScene_SetRotations(&s, text, rotfile, msg, sizeof msg) != MK_OK) { fprintf(stderr, "%s\n", msg); return 1; }
		free(text);
		if (s.orientation_count > nor) s.orientation_count = nor;
	} else {
		s.rotations = malloc((size_t)nor * sizeof *s.rotations);
		for (int k = 0; k < nor; ++k) s.rotations[k] = random_rotation(&rng);
		s.orientation_count = nor;
	}
	nor = s.orientation_count;

	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.mode = MK_CSPACE_PAPER;
	o.uniform = 10;
	o.store = 0;
	double t[2][2], c[2][2], sum[2][2];
	printf("Table 2, 3D row: %d obstacles x %d orientations x 100 points, kernel %s\n", nob, nor,
		mkImpl_Name(mkImpl_Resolve(o.impl)));
	for (int rep = 0; rep < 2; ++rep)
		for (int th = 1; th <= 2; ++th) {
			o.threads = th;
			mkCSpaceResult r;
			double t0 = now_s(), c0 = cpu_s(), l0 = loadavg();
			mkCSpace *prep = NULL;
			if (mkCSpace_Create(&s, &o, &prep, msg, sizeof msg) != MK_OK || mkCSpace_Run(prep, 0, nor, &r, msg, sizeof msg) != MK_OK) {
				fprintf(stderr, "%s\n", msg);
				return 1;
			}
			mkCSpace_Destroy(prep);
			t[rep][th - 1] = now_s() - t0;
			c[rep][th - 1] = cpu_s() - c0;
			double cs = 0.0;
			for (long b = 0; b < (long)nob * nor; ++b) cs += r.checksum[b];
			sum[rep][th - 1] = cs;
			mkCSpaceResult_Free(&r);
			printf("  run %d, %d thread%s: %.3f s wall, %.3f s CPU, load average before %.2f (checksum %.17g)\n",
				rep + 1, th, th > 1 ? "s" : " ", t[rep][th - 1], c[rep][th - 1], l0, cs);
		}
	for (int rep = 0; rep < 2; ++rep)
		printf("  pair %d: wall speed-up %.3f, parallel efficiency on 2 threads %.1f%%; CPU time ratio (2 threads / 1) %.3f\n",
			rep + 1, t[rep][0] / t[rep][1], 100.0 * t[rep][0] / (2.0 * t[rep][1]), c[rep][1] / c[rep][0]);
	printf("  checksums equal across thread counts: %s\n",
		sum[0][0] == sum[0][1] && sum[0][0] == sum[1][0] && sum[0][0] == sum[1][1] ? "yes" : "NO");
	mkScene_Free(&s);
	return 0;
}
