/* bench_scene.c - scene checks: a robot of two ellipsoid parts at random
 * poses among N ellipsoid obstacles, mink's scene query (mink/scenequery.h,
 * 1 and 2 threads) against FCL 0.7's DynamicAABBTreeCollisionManager with
 * its ellipsoid narrow phase (mink/scene_fcl.h). The entries run
 * interleaved, round by round (mink-1t, fcl, mink-2t, mink-yn, ...), on the same
 * poses; the rows give the median time of a round as poses per second and
 * the ratios. mink-yn is the query asked for free / colliding only
 * (max_clearance 1e-9), the question FCL answers. FCL's verdicts are compared with mink's certified ones (free /
 * colliding; uncertain poses are counted apart): every disagreement is
 * listed with mink's clearance bound.
 *
 * usage: bench_scene [POSES [MAX_OBSTACLES [ROUNDS [SEED]]]]
 * (defaults 2000 1000 5 2029; scenes of 10, 100, 1000, 10000 obstacles up
 * to MAX_OBSTACLES). Exit 1 when some certified verdict of FCL disagrees
 * with mink's by more than the contact band (|clearance bound| > 1e-6 of the
 * robot's size); timings never decide the exit status. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <mink/cspace.h>
#include <mink/scene_fcl.h>

static unsigned long long mkBs_seed = 2029;

static double mkBs_Uni(double lo, double hi)
{
	mkBs_seed = mkBs_seed * 6364136223846793005ULL + 1442695040888963407ULL;
	return lo + (hi - lo) * (double)(mkBs_seed >> 11) * (1.0 / 9007199254740992.0);
}

static double mkBs_Now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int mkBs_CompareDouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The scene text: n ellipsoids, random axes in [0.3, 1.5] and orientations,
 * in a cube whose side keeps about 1 obstacle per 80 unit volumes. */
static char *mkBs_SceneText(int n)
{
	size_t len = (size_t)n * 160 + 512, k;
	char *t = malloc(len);
	if (!t) return NULL;
	double half = 0.5 * cbrt(80.0 * n);
	k = (size_t)snprintf(t, len, "dim 3\npart ellipsoid a=1 b=0.5 c=0.3\n"
		"part ellipsoid a=0.5 b=0.3 c=0.3 quat=0.9,0.2,0.3,0 at=1.2,0.3,0.2\nobject clutter\n");
	for (int i = 0; i < n; ++i)
		k += (size_t)snprintf(t + k, len - k, "obstacle ellipsoid a=%.6f b=%.6f c=%.6f quat=%.5f,%.5f,%.5f,%.5f "
			"at=%.5f,%.5f,%.5f\n", mkBs_Uni(0.3, 1.5), mkBs_Uni(0.3, 1.5), mkBs_Uni(0.3, 1.5), mkBs_Uni(-1, 1),
			mkBs_Uni(-1, 1), mkBs_Uni(-1, 1), mkBs_Uni(-1, 1), mkBs_Uni(-half, half), mkBs_Uni(-half, half),
			mkBs_Uni(-half, half));
	snprintf(t + k, len - k, "quaternions 1,0,0,0\n");
	return t;
}

static void mkBs_Place(mkBody3 b, double *R, double *p)
{
	for (int i = 0; i < 9; ++i) R[i] = b.M.m[i / 3][i % 3];
	p[0] = b.t.x; p[1] = b.t.y; p[2] = b.t.z;
}

/* FCL's scene of the query's bodies (every body of the generated scenes is
 * an ellipsoid placed by a rotation, so its model is the body itself). */
static mkFclScene *mkBs_FclScene(const mkSceneQuery *q, int n)
{
	double *ax = malloc(sizeof(double) * 3 * (size_t)n), *R = malloc(sizeof(double) * 9 * (size_t)n);
	double *p = malloc(sizeof(double) * 3 * (size_t)n), pax[6], pose[7] = {0, 0, 0, 1, 0, 0, 0};
	mkFclScene *s = NULL;
	if (ax && R && p) {
		mkBody3 b;
		for (int i = 0; i < n; ++i) {
			mkSceneQuery_ObstacleBody(q, i, 0, &b);
			ax[3 * i] = b.shape.a; ax[3 * i + 1] = b.shape.b; ax[3 * i + 2] = b.shape.c;
			mkBs_Place(b, R + 9 * i, p + 3 * i);
		}
		for (int j = 0; j < 2; ++j) {
			mkSceneQuery_PartBody(q, pose, j, 0, &b);
			pax[3 * j] = b.shape.a; pax[3 * j + 1] = b.shape.b; pax[3 * j + 2] = b.shape.c;
		}
		s = mkFclScene_Create(n, ax, R, p, 2, pax);
	}
	free(ax); free(R); free(p);
	return s;
}

static int mkBs_FclRun(mkFclScene *f, const mkSceneQuery *q, const double *poses, int np, unsigned char *hit)
{
	double R[18], p[6];
	for (int k = 0; k < np; ++k) {
		mkBody3 b;
		for (int j = 0; j < 2; ++j) {
			if (!mkSceneQuery_PartBody(q, poses + 7 * k, j, 0, &b)) return 0;
			mkBs_Place(b, R + 9 * j, p + 3 * j);
		}
		hit[k] = (unsigned char)mkFclScene_Check(f, R, p);
	}
	return 1;
}

/* One scene of n obstacles: the rows. Returns the disagreements beyond the band. */
static int mkBs_Scene(int n, int np, int rounds)
{
	char msg[512], *text = mkBs_SceneText(n);
	mkScene s;
	memset(&s, 0, sizeof s);
	mkSceneQuery *q1 = NULL, *q2 = NULL, *qy = NULL;
	mkSceneQueryOptions o = mkSceneQueryOptions_Default();
	if (!text || mkScene_Parse(text, &s, msg, sizeof msg) != MK_OK || mkSceneQuery_Create(&s, &o, &q1, msg, sizeof msg) != MK_OK
		|| (o.threads = 2, mkSceneQuery_Create(&s, &o, &q2, msg, sizeof msg)) != MK_OK
		|| (o.threads = 1, o.max_clearance = 1e-9, mkSceneQuery_Create(&s, &o, &qy, msg, sizeof msg)) != MK_OK) {
		fprintf(stderr, "bench_scene: scene of %d obstacles: %s\n", n, text ? msg : "out of memory");
		exit(1);
	}
	double half = 0.5 * cbrt(80.0 * n), *poses = malloc(sizeof(double) * 7 * (size_t)np);
	mkPoseAnswer *a1 = malloc(sizeof *a1 * (size_t)np), *a2 = malloc(sizeof *a2 * (size_t)np);
	mkPoseAnswer *ay = malloc(sizeof *ay * (size_t)np);
	unsigned char *hit = malloc((size_t)np);
	double *t = malloc(sizeof(double) * 4 * (size_t)rounds);
	mkFclScene *f = mkBs_FclScene(q1, n);
	if (!poses || !a1 || !a2 || !ay || !hit || !t || !f) { fprintf(stderr, "bench_scene: out of memory\n"); exit(1); }
	for (int k = 0; k < np; ++k) {
		for (int d = 0; d < 3; ++d) poses[7 * k + d] = mkBs_Uni(-half, half);
		for (int d = 3; d < 7; ++d) poses[7 * k + d] = mkBs_Uni(-1, 1);
	}
	for (int r = 0; r < rounds; ++r) {
		double t0 = mkBs_Now();
		mkSceneQuery_Run(q1, poses, np, a1, msg, sizeof msg);
		double t1 = mkBs_Now();
		mkBs_FclRun(f, q1, poses, np, hit);
		double t2 = mkBs_Now();
		mkSceneQuery_Run(q2, poses, np, a2, msg, sizeof msg);
		double t3 = mkBs_Now();
		mkSceneQuery_Run(qy, poses, np, ay, msg, sizeof msg);
		double t4 = mkBs_Now();
		t[r] = t1 - t0; t[rounds + r] = t2 - t1; t[2 * rounds + r] = t3 - t2; t[3 * rounds + r] = t4 - t3;
	}
	int counts[3] = {0, 0, 0}, dis = 0, far = 0, same = 1;
	long pairs = 0;
	for (int k = 0; k < np; ++k) {
		++counts[a1[k].status];
		pairs += a1[k].pairs;
		same &= a1[k].status == a2[k].status && a1[k].clearance == a2[k].clearance && a1[k].obstacle == a2[k].obstacle;
		same &= a1[k].status == ay[k].status;
		if (a1[k].status == MK_POSE_UNCERTAIN || (a1[k].status == MK_POSE_COLLIDING) == (hit[k] != 0)) continue;
		++dis;
		int beyond = fabs(a1[k].clearance) > 1e-6 * 1.5;
		far += beyond;
		printf("  disagreement: pose %d mink %s (clearance bound %.3g), fcl %s%s\n", k, mkPoseStatus_Name(a1[k].status),
			a1[k].clearance, hit[k] ? "colliding" : "free", beyond ? "  BEYOND THE CONTACT BAND" : "");
	}
	double med[4];
	for (int e = 0; e < 4; ++e) {
		qsort(t + e * rounds, (size_t)rounds, sizeof *t, mkBs_CompareDouble);
		med[e] = t[e * rounds + rounds / 2];
	}
	printf("%-9s %6d %6d %11.0f %11.0f %11.0f %11.0f %7.2f %7.2f %7.2f %6.2f %5d %5d %5d %5d %s\n", "ellipsoid", n, np,
		np / med[0], np / med[2], np / med[3], np / med[1], med[1] / med[0], med[1] / med[2], med[1] / med[3],
		med[0] / med[2], counts[0], counts[1], counts[2], dis, same ? "" : "ANSWERS DIFFER");
	fflush(stdout);
	(void)pairs;
	mkFclScene_Destroy(f);
	mkSceneQuery_Destroy(q1); mkSceneQuery_Destroy(q2); mkSceneQuery_Destroy(qy);
	mkScene_Free(&s);
	free(text); free(poses); free(a1); free(a2); free(ay); free(hit); free(t);
	return far + !same;
}

static long mkBs_Arg(int argc, char **argv, int i, const char *name, long def, long lo, long hi)
{
	if (argc <= i) return def;
	char *end;
	long v = strtol(argv[i], &end, 10);
	if (*end || end == argv[i] || v < lo || v > hi) {
		fprintf(stderr, "bench_scene: %s = '%s' is out of range: must be an integer in [%ld, %ld]\n", name, argv[i], lo, hi);
		exit(2);
	}
	return v;
}

int main(int argc, char **argv)
{
	if (argc > 1 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
		printf("usage: bench_scene [POSES [MAX_OBSTACLES [ROUNDS [SEED]]]]\n"
			"  a robot of 2 ellipsoids at POSES random poses (default 2000) among 10, 100, 1000, 10000 ellipsoid\n"
			"  obstacles (up to MAX_OBSTACLES, default 1000): mink's scene query on 1 and 2 threads against FCL 0.7's\n"
			"  DynamicAABBTreeCollisionManager, interleaved for ROUNDS rounds (default 5), SEED (default 2029).\n");
		return 0;
	}
	int np = (int)mkBs_Arg(argc, argv, 1, "POSES", 2000, 1, 10000000);
	int maxn = (int)mkBs_Arg(argc, argv, 2, "MAX_OBSTACLES", 1000, 10, 1000000);
	int rounds = (int)mkBs_Arg(argc, argv, 3, "ROUNDS", 5, 1, 1000);
	mkBs_seed = (unsigned long long)mkBs_Arg(argc, argv, 4, "SEED", 2029, 0, 2147483647L);
	printf("# bench_scene: %d poses, %d rounds interleaved (mink-1t, fcl, mink-2t, mink-yn), median round; poses per second\n"
		"# mink-1t, -2t: certified free/colliding and the nearest obstacle's clearance per pose (1, 2 threads);\n"
		"# mink-yn: certified free/colliding only (max_clearance 1e-9, 1 thread);\n"
		"# fcl: DynamicAABBTreeCollisionManager + fcl::collide on ellipsoids (yes/no, first contact)\n"
		"%-9s %6s %6s %11s %11s %11s %11s %7s %7s %7s %6s %5s %5s %5s %5s\n", np, rounds, "kind", "obst", "poses",
		"mink-1t/s", "mink-2t/s", "mink-yn/s", "fcl/s", "1t/fcl", "2t/fcl", "yn/fcl", "2t/1t", "free", "coll", "unc",
		"disag");
	int bad = 0;
	for (int n = 10; n <= maxn; n *= 10) bad += mkBs_Scene(n, np, rounds);
	if (bad) fprintf(stderr, "bench_scene: %d disagreement(s) beyond the contact band or thread differences\n", bad);
	return bad ? 1 : 0;
}
