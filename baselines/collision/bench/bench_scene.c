/* bench_scene.c - scene checks: a robot of two ellipsoid parts at random
 * poses among N obstacles (ellipsoids, superquadrics with --kind sq, or
 * boxes with --kind box: FCL on their exact 12-triangle meshes, libccd's
 * GJK replaced by FCL's native box),
 * mink's scene query (mink/scenequery.h, 1 and 2 threads) against FCL
 * 0.7's DynamicAABBTreeCollisionManager with FCL's narrow phase (native
 * ellipsoids; superquadrics as convex meshes of --mesh N rings) and with
 * libccd's GJK on the exact bodies behind the same broad phase
 * (mink/scene_fcl.h).
 * The entries run interleaved, round by round (mink-1t, fcl, mink-2t,
 * mink-yn, ccd), on the same poses; the rows give the median time of a
 * round as poses per second and the ratios. mink-yn is the query asked for
 * free / colliding only (max_clearance 1e-9), the question FCL and libccd
 * answer. Their verdicts are compared with mink's certified ones (free /
 * colliding; uncertain poses are counted apart): the disagreements are
 * counted, and the first ones listed with mink's clearance bound.
 *
 * usage: bench_scene [--kind ellipsoid|sq|box] [--mesh N] [POSES [MAX_OBSTACLES [ROUNDS [SEED]]]]
 * (defaults ellipsoid, 16, 2000 1000 5 2029; scenes of 10, 100, 1000,
 * 10000 obstacles up to MAX_OBSTACLES). Exit 1 when a verdict of an exact
 * peer (FCL on ellipsoids and on boxes' exact meshes, libccd, FCL's
 * native box) disagrees with mink's by more than the contact band
 * (|clearance bound| > 1e-6 of the robot's size), or when mink's answers
 * differ between its entries; FCL's superquadric meshes are counted,
 * never judged; timings never decide the exit status. */
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

static double mkBs_Clock(clockid_t c)
{
	struct timespec t;
	clock_gettime(c, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double mkBs_Now(void) { return mkBs_Clock(CLOCK_MONOTONIC); }
static double mkBs_Cpu(void) { return mkBs_Clock(CLOCK_THREAD_CPUTIME_ID); }

static int mkBs_CompareDouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static int mkBs_sq = 0;   /* --kind sq: superquadric obstacles */
static int mkBs_box = 0;  /* --kind box: box obstacles */
static int mkBs_mesh = 16; /* --mesh: rings of FCL's meshes */

/* The scene text: n obstacles (ellipsoids, superquadrics with exponents
 * in [0.3, 1.7], or boxes), random semi-axes (half sides) in [0.3, 1.5]
 * and orientations, in a cube whose side keeps about 1 obstacle per 80 unit
 * volumes. */
static char *mkBs_SceneText(int n)
{
	size_t len = (size_t)n * 200 + 512, k;
	char *t = malloc(len);
	if (!t) return NULL;
	double half = 0.5 * cbrt(80.0 * n);
	k = (size_t)snprintf(t, len, "dim 3\npart ellipsoid a=1 b=0.5 c=0.3\n"
		"part ellipsoid a=0.5 b=0.3 c=0.3 quat=0.9,0.2,0.3,0 at=1.2,0.3,0.2\nobject clutter\n");
	for (int i = 0; i < n; ++i) {
		double a = mkBs_Uni(0.3, 1.5), b = mkBs_Uni(0.3, 1.5), c = mkBs_Uni(0.3, 1.5);
		if (mkBs_box)
			k += (size_t)snprintf(t + k, len - k, "obstacle box size=%.6f,%.6f,%.6f", 2 * a, 2 * b, 2 * c);
		else if (mkBs_sq)
			k += (size_t)snprintf(t + k, len - k, "obstacle superquadric a=%.6f b=%.6f c=%.6f eps1=%.4f eps2=%.4f", a, b, c,
				mkBs_Uni(0.3, 1.7), mkBs_Uni(0.3, 1.7));
		else
			k += (size_t)snprintf(t + k, len - k, "obstacle ellipsoid a=%.6f b=%.6f c=%.6f", a, b, c);
		k += (size_t)snprintf(t + k, len - k, " quat=%.5f,%.5f,%.5f,%.5f at=%.5f,%.5f,%.5f\n", mkBs_Uni(-1, 1),
			mkBs_Uni(-1, 1), mkBs_Uni(-1, 1), mkBs_Uni(-1, 1), mkBs_Uni(-half, half), mkBs_Uni(-half, half),
			mkBs_Uni(-half, half));
	}
	snprintf(t + k, len - k, "quaternions 1,0,0,0\n");
	return t;
}

/* A peer's scene of the query's bodies (smooth bodies are their own
 * models; a box obstacle goes to the peer as the exact box of the scene). */
static mkFclScene *mkBs_Peer(const mkScene *sc, const mkSceneQuery *q, int n, int narrow)
{
	mkBody3 *obs = malloc(sizeof *obs * (size_t)n + 1), robot[2];
	double pose[7] = {0, 0, 0, 1, 0, 0, 0}, *half = calloc(3 * (size_t)n + 1, sizeof *half);
	mkFclScene *s = NULL;
	if (obs && half) {
		for (int i = 0; i < n; ++i) {
			mkSceneQuery_ObstacleBody(q, i, 0, &obs[i]);
			const mkSceneBody *b = &sc->obstacles[i];
			if (b->kind != MK_SCENE_BOX) continue;
			if (mkVec3_Length(mkVec3_Sub(obs[i].t, b->spec.body3.t)) > 1e-12 * (1.0 + mkVec3_Length(obs[i].t))) {
				fprintf(stderr, "bench_scene: the query's obstacle %d is not the scene's obstacle %d\n", i, i);
				exit(1);
			}
			obs[i].M = b->spec.body3.M;
			for (int d = 0; d < 3; ++d) half[3 * i + d] = 0.5 * b->size[d];
		}
		for (int j = 0; j < 2; ++j) mkSceneQuery_PartBody(q, pose, j, 0, &robot[j]);
		s = mkFclScene_CreateBoxes(n, obs, half, 2, robot, mkBs_mesh, narrow);
	}
	free(obs);
	free(half);
	return s;
}

static void mkBs_PeerRun(mkFclScene *f, const double *poses, int np, unsigned char *hit)
{
	for (int k = 0; k < np; ++k) {
		const double *p = poses + 7 * k;
		mkMat3 R = mkMat3_FromQuat(p[3], p[4], p[5], p[6]);
		hit[k] = (unsigned char)mkFclScene_Check(f, &R.m[0][0], p);
	}
}

/* A peer's verdicts against mink's certified ones: the disagreements (the
 * first 5 listed), *beyond those beyond the contact band (flagged loudly
 * when the peer is exact: judged). */
static int mkBs_Disagree(const char *peer, int judged, const mkPoseAnswer *a, const unsigned char *hit, int np,
	int *beyond)
{
	int dis = 0;
	*beyond = 0;
	for (int k = 0; k < np; ++k) {
		if (a[k].status == MK_POSE_UNCERTAIN || (a[k].status == MK_POSE_COLLIDING) == (hit[k] != 0)) continue;
		int far = fabs(a[k].clearance) > 1e-6 * 1.5;
		*beyond += far;
		if (dis++ < 5)
			printf("  disagreement: pose %d mink %s (clearance bound %.3g), %s %s%s\n", k, mkPoseStatus_Name(a[k].status),
				a[k].clearance, peer, hit[k] ? "colliding" : "free",
				!far ? "" : judged ? "  BEYOND THE CONTACT BAND" : "  (a mesh: beyond the contact band)");
	}
	return dis;
}

/* The rounds, interleaved: t[e * rounds + r] is entry e's time in round r
 * (mink-1t, fcl, mink-2t, mink-yn, ccd), by the wall clock, and
 * t[(5 + e) * rounds + r] by the calling thread's CPU clock (which the
 * 1-thread entries run on; mink-2t's is not its time). */
static void mkBs_Rounds(mkSceneQuery *const q[3], mkFclScene *const f[2], const double *poses, int np, int rounds,
	mkPoseAnswer *const a[3], unsigned char *const hit[2], double *t)
{
	char msg[512];
	for (int r = 0; r < rounds; ++r)
		for (int e = 0; e < 5; ++e) {
			double w = mkBs_Now(), c = mkBs_Cpu();
			if (e == 0 || e == 2 || e == 3) mkSceneQuery_Run(q[e == 0 ? 0 : e - 1], poses, np, a[e == 0 ? 0 : e - 1], msg, sizeof msg);
			else mkBs_PeerRun(f[e == 1 ? 0 : 1], poses, np, hit[e == 1 ? 0 : 1]);
			t[e * rounds + r] = mkBs_Now() - w;
			t[(5 + e) * rounds + r] = mkBs_Cpu() - c;
		}
}

/* One scene of n obstacles: the row. Returns the failures (exact peers'
 * disagreements beyond the band, mink's entries differing). */
static int mkBs_Scene(int n, int np, int rounds)
{
	char msg[512], *text = mkBs_SceneText(n);
	mkScene s;
	memset(&s, 0, sizeof s);
	mkSceneQuery *q[3] = {NULL, NULL, NULL};
	mkSceneQueryOptions o = mkSceneQueryOptions_Default();
	if (!text || mkScene_Parse(text, &s, msg, sizeof msg) != MK_OK || mkSceneQuery_Create(&s, &o, &q[0], msg, sizeof msg) != MK_OK
		|| (o.threads = 2, mkSceneQuery_Create(&s, &o, &q[1], msg, sizeof msg)) != MK_OK
		|| (o.threads = 1, o.max_clearance = 1e-9, mkSceneQuery_Create(&s, &o, &q[2], msg, sizeof msg)) != MK_OK) {
		fprintf(stderr, "bench_scene: scene of %d obstacles: %s\n", n, text ? msg : "out of memory");
		exit(1);
	}
	double half = 0.5 * cbrt(80.0 * n), *poses = malloc(sizeof(double) * 7 * (size_t)np);
	mkPoseAnswer *a[3];
	unsigned char *hit[2] = {malloc((size_t)np), malloc((size_t)np)};
	for (int e = 0; e < 3; ++e) a[e] = malloc(sizeof *a[e] * (size_t)np);
	double *t = malloc(sizeof(double) * 10 * (size_t)rounds);
	mkFclScene *f[2] = {mkBs_Peer(&s, q[0], n, MK_FCL_NARROW_FCL), mkBs_Peer(&s, q[0], n, MK_FCL_NARROW_CCD)};
	if (!poses || !a[0] || !a[1] || !a[2] || !hit[0] || !hit[1] || !t || !f[0] || !f[1]) {
		fprintf(stderr, "bench_scene: out of memory\n");
		exit(1);
	}
	for (int k = 0; k < np; ++k) {
		for (int d = 0; d < 3; ++d) poses[7 * k + d] = mkBs_Uni(-half, half);
		for (int d = 3; d < 7; ++d) poses[7 * k + d] = mkBs_Uni(-1, 1);
	}
	mkBs_Rounds(q, f, poses, np, rounds, a, hit, t);
	int counts[3] = {0, 0, 0}, same = 1, beyond[2];
	for (int k = 0; k < np; ++k) {
		++counts[a[0][k].status];
		same &= a[0][k].status == a[1][k].status && a[0][k].clearance == a[1][k].clearance && a[0][k].obstacle == a[1][k].obstacle;
		/* the yes/no query may decide a pose the clearance query leaves
		 * uncertain (it needs only a positive bound), or the reverse: only
		 * free against colliding is a contradiction */
		same &= a[0][k].status == MK_POSE_UNCERTAIN || a[2][k].status == MK_POSE_UNCERTAIN
			|| a[0][k].status == a[2][k].status;
	}
	int dis[2] = {mkBs_Disagree("fcl", !mkBs_sq, a[0], hit[0], np, &beyond[0]),
		mkBs_Disagree("ccd", 1, a[0], hit[1], np, &beyond[1])};
	double med[10];
	for (int e = 0; e < 10; ++e) {
		qsort(t + e * rounds, (size_t)rounds, sizeof *t, mkBs_CompareDouble);
		med[e] = t[e * rounds + rounds / 2];
	}
	printf("%-9s %6d %6d %10.0f %10.0f %10.0f %10.0f %10.0f %7.2f %7.2f %7.2f %7.2f %6.2f %5d %5d %4d %5d %5d %s\n",
		mkBs_box ? "box" : mkBs_sq ? "sq" : "ellipsoid", n, np, np / med[0], np / med[2], np / med[3], np / med[1], np / med[4],
		med[1] / med[0], med[1] / med[2], med[1] / med[3], med[4] / med[3], med[0] / med[2], counts[0], counts[1],
		counts[2], dis[0], dis[1], same ? "" : "ANSWERS DIFFER");
	printf("  cpu time (1 thread): yn/fcl %.2f, yn/ccd %.2f, 1t/fcl %.2f; mink-yn %.3f us per pose, fcl %.3f, ccd %.3f\n",
		med[6] / med[8], med[9] / med[8], med[6] / med[5], 1e6 * med[8] / np, 1e6 * med[6] / np, 1e6 * med[9] / np);
	if (mkFclScene_Triangles(f[0]) > 0) printf("  fcl meshes: %ld triangles\n", mkFclScene_Triangles(f[0]));
	fflush(stdout);
	for (int e = 0; e < 3; ++e) { mkSceneQuery_Destroy(q[e]); free(a[e]); }
	for (int e = 0; e < 2; ++e) { mkFclScene_Destroy(f[e]); free(hit[e]); }
	mkScene_Free(&s);
	free(text); free(poses); free(t);
	return (mkBs_sq ? 0 : beyond[0]) + beyond[1] + !same;
}

static long mkBs_Arg(const char *arg, const char *name, long lo, long hi)
{
	char *end;
	long v = strtol(arg, &end, 10);
	if (*end || end == arg || v < lo || v > hi) {
		fprintf(stderr, "bench_scene: %s = '%s' is out of range: must be an integer in [%ld, %ld]\n", name, arg, lo, hi);
		exit(2);
	}
	return v;
}

int main(int argc, char **argv)
{
	const char *pos[4] = {NULL, NULL, NULL, NULL};
	int npos = 0;
	for (int i = 1; i < argc; ++i) {
		if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
			printf("usage: bench_scene [--kind ellipsoid|sq|box] [--mesh N] [POSES [MAX_OBSTACLES [ROUNDS [SEED]]]]\n"
				"  a robot of 2 ellipsoids at POSES random poses (default 2000) among 10, 100, 1000, 10000 obstacles\n"
				"  (up to MAX_OBSTACLES, default 1000): ellipsoids, superquadrics (--kind sq) or boxes (--kind box).\n"
				"  mink's scene query on 1 and 2 threads against FCL 0.7's DynamicAABBTreeCollisionManager with FCL's narrow phase\n"
				"  (superquadrics as convex meshes of N rings of 2N vertices, default 16; boxes as exact 12-triangle\n"
				"  meshes) and with libccd's GJK behind it (on boxes FCL's native box),\n"
				"  interleaved for ROUNDS rounds (default 5), SEED (default 2029).\n");
			return 0;
		}
		if (!strcmp(argv[i], "--kind") && i + 1 < argc) {
			++i;
			if (strcmp(argv[i], "ellipsoid") && strcmp(argv[i], "sq") && strcmp(argv[i], "box")) {
				fprintf(stderr, "bench_scene: --kind = '%s' is not known: must be ellipsoid, sq or box\n", argv[i]);
				return 2;
			}
			mkBs_sq = !strcmp(argv[i], "sq");
			mkBs_box = !strcmp(argv[i], "box");
		} else if (!strcmp(argv[i], "--mesh") && i + 1 < argc) {
			mkBs_mesh = (int)mkBs_Arg(argv[++i], "--mesh", 2, 1000);
		} else if (argv[i][0] == '-' && argv[i][1] == '-') {
			fprintf(stderr, "bench_scene: option '%s' is not known (or has no value): see --help\n", argv[i]);
			return 2;
		} else if (npos < 4) {
			pos[npos++] = argv[i];
		} else {
			fprintf(stderr, "bench_scene: too many arguments: see --help\n");
			return 2;
		}
	}
	int np = pos[0] ? (int)mkBs_Arg(pos[0], "POSES", 1, 10000000) : 2000;
	int maxn = pos[1] ? (int)mkBs_Arg(pos[1], "MAX_OBSTACLES", 10, 1000000) : 1000;
	int rounds = pos[2] ? (int)mkBs_Arg(pos[2], "ROUNDS", 1, 1000) : 5;
	mkBs_seed = pos[3] ? (unsigned long long)mkBs_Arg(pos[3], "SEED", 0, 2147483647L) : 2029;
	printf("# bench_scene: %d poses, %d rounds interleaved (mink-1t, fcl, mink-2t, mink-yn, ccd), median round; poses per second\n"
		"# mink-1t, -2t: certified free/colliding and the nearest obstacle's clearance per pose (1, 2 threads);\n"
		"# mink-yn: certified free/colliding only (max_clearance 1e-9, 1 thread);\n"
		"# fcl: DynamicAABBTreeCollisionManager + fcl::collide (ellipsoids native, superquadrics as convex meshes of %d rings,\n"
		"#   boxes as exact 12-triangle convex meshes)\n"
		"# ccd: the same broad phase + libccd's GJK on the exact bodies (boxes: FCL's native box); both yes/no, first contact\n"
		"%-9s %6s %6s %10s %10s %10s %10s %10s %7s %7s %7s %7s %6s %5s %5s %4s %5s %5s\n", np, rounds, mkBs_mesh, "kind",
		"obst", "poses", "mink-1t/s", "mink-2t/s", "mink-yn/s", "fcl/s", "ccd/s", "1t/fcl", "2t/fcl", "yn/fcl", "yn/ccd",
		"2t/1t", "free", "coll", "unc", "d-fcl", "d-ccd");
	int bad = 0;
	for (int n = 10; n <= maxn; n *= 10) bad += mkBs_Scene(n, np, rounds);
	if (bad) fprintf(stderr, "bench_scene: %d disagreement(s) of an exact peer beyond the contact band or answers that differ\n", bad);
	return bad ? 1 : 0;
}
