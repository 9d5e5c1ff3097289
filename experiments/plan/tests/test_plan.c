/* test_plan.c - every path mink_plan returns (several planners,
 * 2D and 3D robots of several parts) is certified free segment by segment
 * by the motion check, and passes an independent dense check: at 401 poses
 * per segment, every robot part against every obstacle by the registry's
 * referee (collider_referee.c, Gilbert's iteration on the support maps: a
 * certified lower bound of each pair's signed distance), each bound
 * positive and at least the segment's reported clearance. The bodies of
 * the dense check are placed here from the scene's declared shapes, 2D
 * ones as the superquadric whose z = 0 section they are (docs/scene.md).
 * The same for one path per query of the experiment's maze, home and
 * passage scenes (boxes and cylinders by their models). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <mink/cspace.h>
#include <mink/colliders.h>
#include <mink_plan/plan.h>

#include "ensure.h"

static const char *scene2 =
	"dim 2\npart superellipse a=1 b=0.3 eps=0.1\npart circle a=0.4 at=1.2,0\n"
	"object walls\nobstacle superellipse a=10 b=0.5 eps=0.05 at=0,-10\nobstacle superellipse a=10 b=0.5 eps=0.05 at=0,10\n"
	"obstacle superellipse a=0.5 b=10 eps=0.05 at=-10,0\nobstacle superellipse a=0.5 b=10 eps=0.05 at=10,0\n"
	"object divider\nobstacle superellipse a=7 b=0.5 eps=0.1 at=-3,0\nobstacle ellipse a=1 b=2 rot=0.3 at=5,5\n"
	"bounds -9,9,-9,9\nstart -6,-6,0\ngoal -6,6,1.57\ngoal 6,-6,0\n";

static const char *scene3 =
	"dim 3\npart superquadric a=0.8 b=0.4 c=0.3 eps1=0.2 eps2=0.2\npart sphere a=0.35 at=1.0,0,0.2\n"
	"obstacle superquadric a=4 b=4 c=0.3 eps1=0.1 eps2=0.1 at=0,0,0\nobstacle ellipsoid a=1 b=1.5 c=2 at=-3,-3,3\n"
	"obstacle sphere a=1.2 at=3,-3,-2\nobstacle superquadric a=1 b=1 c=3 eps1=0.5 eps2=1.5 at=-2,3,2\n"
	"bounds -6,6,-6,6,-6,6\nstart -2,-2,-3,1,0,0,0\ngoal 2,2,3,0.7,0.7,0,0\n";

/* A scene body in 3D form: a smooth body as declared; a box or cylinder
 * by its model on the side (inner: inside it; outer: enclosing it) at the
 * scene query's default tolerance (1e-4 of |M|_F times the half diagonal). */
static mkBody3 lift(const mkSceneBody *b, mkBound side)
{
	char msg[256];
	double err, f = 0.0, s2 = 0.0;
	int n = b->dim;
	for (int i = 0; i < n * n; ++i) {
		double m = n == 2 ? b->spec.body2.M.m[i / 2][i % 2] : b->spec.body3.M.m[i / 3][i % 3];
		f += m * m;
	}
	if (b->kind == MK_SCENE_BOX) for (int i = 0; i < n; ++i) s2 += 0.25 * b->size[i] * b->size[i];
	if (b->kind == MK_SCENE_CYLINDER) s2 = b->size[0] * b->size[0] + 0.25 * b->size[1] * b->size[1];
	if (n == 3) {
		mkBody3 out = b->spec.body3;
		double delta = 1e-4 * sqrt(f * s2);
		if (b->kind != MK_SCENE_SMOOTH && mkSceneBody3_Model(b, delta, side, &out, &err, msg, sizeof msg) != MK_OK)
			ENSURE(!"the model of a box or cylinder");
		return out;
	}
	mkBody2 c = b->spec.body2;
	if (b->kind != MK_SCENE_SMOOTH && mkSceneBody2_Model(b, 1e-4 * sqrt(f * s2), side, &c, &err, msg, sizeof msg) != MK_OK)
		ENSURE(!"the model of a box");
	mkShape3 s = {c.shape.a, c.shape.b, 1.0, 1.0, c.shape.eps};
	mkMat3 M = {{{c.M.m[0][0], c.M.m[0][1], 0}, {c.M.m[1][0], c.M.m[1][1], 0}, {0, 0, 1}}};
	return mkBody3_Make(s, M, mkVec3_Make(c.t.x, c.t.y, 0));
}

/* Part j of the robot at pose p, placed from the scene's declared shape. */
static mkBody3 place_part(const mkScene *s, const double *p, int j, mkBound side)
{
	mkMat3 R;
	mkVec3 c;
	if (s->dim == 2) {
		mkMat3 r = {{{cos(p[2]), -sin(p[2]), 0}, {sin(p[2]), cos(p[2]), 0}, {0, 0, 1}}};
		R = r;
		c = mkVec3_Make(p[0], p[1], 0);
	} else {
		R = mkMat3_FromQuat(p[3], p[4], p[5], p[6]);
		c = mkVec3_Make(p[0], p[1], p[2]);
	}
	mkBody3 part = lift(&s->parts[j], side);
	part.t = mkVec3_Add(c, mkMat3_MulVec(R, part.t));
	part.M = mkMat3_Mul(R, part.M);
	return part;
}

/* The smallest referee bound over (part, obstacle) pairs at pose p. */
static double dense_pose(const mkScene *s, const double *p, mkColliderScratch *scratch)
{
	const mkCollider *ref = mkColliders_Find("referee");
	double lo = INFINITY;
	for (int j = 0; j < s->part_count; ++j)
		for (int i = 0; i < s->obstacle_count; ++i) {
			mkCollision3 col;
			mkBody3 ob = lift(&s->obstacles[i], MK_BOUND_OUTER);
			if (mkCollider_Run(ref, ob, place_part(s, p, j, MK_BOUND_OUTER), scratch, &col) != MK_OK) return -INFINITY;
			lo = fmin(lo, col.distance);
		}
	return lo;
}

/* A certified overlap of some (part, obstacle) pair at pose p by the
 * referee (origin enclosed in the Minkowski difference: residual 0). */
static int dense_overlap(const mkScene *s, const double *p, mkColliderScratch *scratch)
{
	const mkCollider *ref = mkColliders_Find("referee");
	for (int j = 0; j < s->part_count; ++j)
		for (int i = 0; i < s->obstacle_count; ++i) {
			mkCollision3 col;
			mkBody3 ob = lift(&s->obstacles[i], MK_BOUND_INNER);
			if (mkCollider_Run(ref, ob, place_part(s, p, j, MK_BOUND_INNER), scratch, &col) == MK_OK &&
				col.distance <= 0.0 && col.residual == 0.0)
				return 1;
		}
	return 0;
}

/* The scene of the text and its query (default options). */
static mkSceneQuery *make_query(const char *text, mkScene *s)
{
	char msg[1024];
	mkSceneQuery *q = NULL;
	ENSURE(mkScene_Parse(text, s, msg, sizeof msg) == MK_OK);
	mkSceneQueryOptions qo = mkSceneQueryOptions_Default();
	ENSURE(mkSceneQuery_Create(s, &qo, &q, msg, sizeof msg) == MK_OK);
	return q;
}

/* Random motions from free starts, each position coordinate moving up to
 * half the bounds' mean extent: every verdict of mkSceneQuery_MotionTest is
 * checked by the referee: free ones at 401 poses (every bound positive),
 * colliding ones at their contact time (a certified overlap); and it agrees
 * with mkSceneQuery_Motion wherever both decide. */
static void check_motions(const char *text, int n, int *count, int *bad)
{
	mkScene s;
	mkSceneQuery *q = make_query(text, &s);
	mkColliderScratch scratch;
	unsigned long long x = 29;
	int dim = s.dim, seen[3] = {0, 0, 0};
	double ext = 0.0;
	for (int d = 0; d < dim; ++d) ext += (s.bounds_hi[d] - s.bounds_lo[d]) * (s.bounds_hi[d] - s.bounds_lo[d]);
	for (int k = 0; k < n;) {
		double a[7], b[7], u[14];
		for (int i = 0; i < 14; ++i) { x = x * 6364136223846793005ULL + 1442695040888963407ULL; u[i] = (x >> 11) * 0x1p-53; }
		for (int d = 0; d < dim; ++d) {
			a[d] = s.bounds_lo[d] + u[d] * (s.bounds_hi[d] - s.bounds_lo[d]);
			b[d] = a[d] + 0.5 * sqrt(ext / dim) * (2.0 * u[7 + d] - 1.0);
		}
		if (dim == 2) { a[2] = MK_PI * (2.0 * u[3] - 1.0); b[2] = MK_PI * (2.0 * u[10] - 1.0); }
		else for (int i = 3; i < 7; ++i) { a[i] = 2.0 * u[i] - 1.0; b[i] = 2.0 * u[7 + i] - 1.0; }
		mkPoseAnswer pa;
		if (mkSceneQuery_Pose(q, a, &pa) != MK_OK || pa.status != MK_POSE_FREE) continue;
		++k;
		mkMotionAnswer m, full;
		ENSURE(mkSceneQuery_MotionTest(q, a, b, 0.0, 1000000, &m) == MK_OK);
		ENSURE(mkSceneQuery_Motion(q, a, b, 0.0, 1000000, &full) == MK_OK);
		++seen[m.status];
		int ok = m.status == MK_POSE_UNCERTAIN || full.status == MK_POSE_UNCERTAIN || m.status == full.status;
		double pose[7];
		if (m.status == MK_POSE_FREE)
			for (int t = 0; t <= 400 && ok; ++t) {
				mkSceneQuery_Interpolate(q, a, b, t / 400.0, pose);
				ok = dense_pose(&s, pose, &scratch) > 0.0;
			}
		if (m.status == MK_POSE_COLLIDING) {
			mkSceneQuery_Interpolate(q, a, b, m.contact_time, pose);
			ok = ok && dense_overlap(&s, pose, &scratch);
		}
		if (!ok) {
			++*bad;
			fprintf(stderr, "  motion %d: test %s, full %s, contact %.17g\n", k, mkPoseStatus_Name(m.status),
				mkPoseStatus_Name(full.status), m.contact_time);
		}
	}
	*count += n;
	printf("%dD: %d random motions: %d free, %d colliding, %d uncertain\n", dim, n, seen[0], seen[1], seen[2]);
	ENSURE(seen[0] > n / 10 && seen[1] > n / 10 && seen[2] <= n / 50);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
}

/* RRTConnect on query 0 of text with seed 7 in a fresh process (OMPL takes
 * a seed once per process), warm-up on or off: its counts and waypoints
 * into out[0 .. 3); 0 when the child failed. */
static int solve_fresh(const char *text, int warm, long out[3])
{
	int fd[2];
	if (pipe(fd) != 0) return 0;
	fflush(NULL);
	pid_t pid = fork();
	if (pid == 0) {
		close(fd[0]);
		mkScene s;
		mkSceneQuery *q = make_query(text, &s);
		char msg[1024];
		mkPlanOptions o = mkPlanOptions_Default();
		o.seed = 7;
		o.warm = warm;
		mkPlanPath p;
		long r[3] = {-1, -1, -1};
		if (mkPlan_Solve(&s, q, 0, &o, &p, msg, sizeof msg) == 0) {
			r[0] = p.states_checked;
			r[1] = p.motions_checked;
			r[2] = p.count;
		}
		_exit(write(fd[1], r, sizeof r) == (ssize_t)sizeof r ? 0 : 1);
	}
	close(fd[1]);
	ssize_t got = pid > 0 ? read(fd[0], out, 3 * sizeof *out) : -1;
	close(fd[0]);
	int status = 1;
	if (pid > 0) waitpid(pid, &status, 0);
	return got == (ssize_t)(3 * sizeof *out) && WIFEXITED(status) && WEXITSTATUS(status) == 0 && out[0] >= 0;
}

/* Plan every query of the scene with the planner; check each path. */
static void check_scene(const char *text, const char *planner, int *paths, int *bad)
{
	mkScene s;
	mkSceneQuery *q = make_query(text, &s);
	char msg[1024];
	mkPlanOptions o = mkPlanOptions_Default();
	o.planner = planner;
	o.time = 20.0;   /* these planners stop at their first path: the budget only bounds a loaded machine's wait */
	mkColliderScratch scratch;
	int ps = mkSceneQuery_PoseSize(q);
	for (int k = 0; k < s.query_count; ++k) {
		mkPlanPath p;
		int rc = mkPlan_Solve(&s, q, k, &o, &p, msg, sizeof msg);
		ENSURE(rc == 0);
		if (rc) { fprintf(stderr, "  %s query %d: %s\n", planner, k, msg); continue; }
		++*paths;
		for (int d = 0; d < s.dim; ++d) { /* from the start's position to the goal's */
			ENSURE(p.poses[d] == s.queries[k].start[d]);
			ENSURE(p.poses[(long)(p.count - 1) * ps + d] == s.queries[k].goal[d]);
		}
		for (int i = 0; i + 1 < p.count; ++i) {
			const double *a = p.poses + (long)i * ps, *b = a + ps;
			mkMotionAnswer m;
			ENSURE(mkSceneQuery_Motion(q, a, b, 0.0, 1000000, &m) == MK_OK);
			ENSURE(m.status == MK_POSE_FREE);
			double worst = INFINITY, pose[7];
			for (int t = 0; t <= 400; ++t) {
				mkSceneQuery_Interpolate(q, a, b, t / 400.0, pose);
				worst = fmin(worst, dense_pose(&s, pose, &scratch));
			}
			if (!(worst > 0.0) || !(worst >= p.clearance[i] - 1e-9)) {
				++*bad;
				fprintf(stderr, "  %s query %d segment %d: dense minimum %.17g, certified clearance %.17g\n", planner, k, i,
					worst, p.clearance[i]);
			}
		}
		mkPlanPath_Free(&p);
	}
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
}

/* The text of scene file NAME.txt in directory dir (static buffer). */
static const char *read_scene(const char *dir, const char *name)
{
	static char text[1 << 16];
	char path[1024];
	snprintf(path, sizeof path, "%s/%s.txt", dir, name);
	FILE *fp = fopen(path, "r");
	size_t n = fp ? fread(text, 1, sizeof text - 1, fp) : 0;
	ENSURE(fp != NULL && n > 0);
	if (fp) fclose(fp);
	text[n] = 0;
	return text;
}

int main(int argc, char **argv)
{
	static const char *planners[] = {"RRTConnect", "PRM", "KPIECE1", "RRT"};
	int paths = 0, bad = 0;
	for (int d = 0; d < 2; ++d)
		for (int k = 0; k < 4; ++k) check_scene(d == 0 ? scene2 : scene3, planners[k], &paths, &bad);
	ENSURE(bad == 0);
	ENSURE(paths == 4 * 3);
	printf("%d paths of 4 planners (2D and 3D robots of 2 parts): %d segments fail the dense referee check\n", paths, bad);
	/* the experiment's scenes of several parts and obstacle kinds: each query solved by RRTConnect */
	static const char *files[] = {"maze2d", "home3d", "passage3d"};
	paths = bad = 0;
	const char *dir = argc > 1 ? argv[1] : "experiments/plan/scenes";
	for (int k = 0; k < 3; ++k) check_scene(read_scene(dir, files[k]), "RRTConnect", &paths, &bad);
	ENSURE(bad == 0);
	ENSURE(paths == 2 + 2 + 1);
	printf("%d paths in the maze, home and passage scenes: %d segments fail the dense referee check\n", paths, bad);
	int motions = 0;
	bad = 0;
	check_motions(scene2, 100, &motions, &bad);
	check_motions(scene3, 100, &motions, &bad);
	ENSURE(bad == 0);
	printf("%d random motions: %d verdicts of the motion test fail the referee's check\n", motions, bad);
	/* the warm-up (mkPlanOptions.warm) is off the counts and off the planner's random numbers: RRTConnect
	 * under one seed makes the same checks and returns the same waypoints with it as without it */
	for (int d = 0; d < 2; ++d) {
		long cold[3], warm[3];
		int ok = solve_fresh(d == 0 ? scene2 : scene3, 0, cold) && solve_fresh(d == 0 ? scene2 : scene3, 1, warm);
		ENSURE(ok);
		ENSURE(ok && cold[0] == warm[0] && cold[1] == warm[1] && cold[2] == warm[2]);
		printf("%dD, seed 7: %ld state and %ld motion checks, %ld waypoints without the warm-up; %ld, %ld, %ld with it\n",
			d + 2, cold[0], cold[1], cold[2], warm[0], warm[1], warm[2]);
	}
	/* bad input: a start in collision names its line */
	mkScene s;
	char msg[1024];
	ENSURE(mkScene_Parse("dim 2\nrobot circle a=1\nobstacle circle a=1\nbounds -5,5,-5,5\nstart 0.5,0,0\ngoal 3,3,0\n", &s,
		msg, sizeof msg) == MK_OK);
	mkSceneQueryOptions qo = mkSceneQueryOptions_Default();
	mkSceneQuery *q = NULL;
	ENSURE(mkSceneQuery_Create(&s, &qo, &q, msg, sizeof msg) == MK_OK);
	mkPlanOptions o = mkPlanOptions_Default();
	mkPlanPath p;
	ENSURE(mkPlan_Solve(&s, q, 0, &o, &p, msg, sizeof msg) == 2);
	ENSURE(strstr(msg, "line 5: start is in collision") != NULL);
	o.planner = "NoSuchPlanner";
	ENSURE(mkPlan_Solve(&s, q, 0, &o, &p, msg, sizeof msg) == 2);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	/* no path: the goal sealed in a ring of obstacles */
	ENSURE(mkScene_Parse("dim 2\nrobot circle a=0.5\nobstacle superellipse a=3 b=0.3 eps=0.1 at=0,2\nobstacle superellipse "
		"a=3 b=0.3 eps=0.1 at=0,-2\nobstacle superellipse a=0.3 b=3 eps=0.1 at=2,0\nobstacle superellipse a=0.3 b=3 eps=0.1 "
		"at=-2,0\nbounds -8,8,-8,8\nstart -6,-6,0\ngoal 0,0,0\n", &s, msg, sizeof msg) == MK_OK);
	ENSURE(mkSceneQuery_Create(&s, &qo, &q, msg, sizeof msg) == MK_OK);
	o = mkPlanOptions_Default();
	o.time = 0.2;
	ENSURE(mkPlan_Solve(&s, q, 0, &o, &p, msg, sizeof msg) == 1);
	ENSURE(strstr(msg, "no path found") != NULL);
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	return mk_summary("test_plan");
}
