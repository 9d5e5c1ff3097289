/* cmd_plan.c - `mink plan`: paths for a scene file's planning queries with
 * OMPL's planners on mink's certified checks (mink_plan/plan.h), and
 * `mink plan --check PATH SCENE`: certify any path against a scene,
 * segment by segment (mkSceneQuery_Motion). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/cspace.h>
#include <mink_exp/outfile.h>
#include <mink_plan/plan.h>

#include "cli.h"
#include "commands.h"
#include "scenefile.h"

#define PLAN_MAX_POSES 1000000L  /* poses per certified segment at most */

static void mkPlanCmd_Help(FILE *fp)
{
	fprintf(fp,
		"usage: mink plan SCENE --out PATH [--planner NAME] [--time S] [--seed S] [--clearance D]\n"
		"       mink plan --check PATH SCENE [--out PATH] [--clearance D] [--threads K]\n"
		"\n"
		"Plans every query of SCENE (lines 'bounds', 'start POSE', 'goal POSE'; docs/scene.md)\n"
		"with an OMPL planner whose state validity checker is mink's certified scene query and\n"
		"whose motion validator certifies each motion free from certified clearances against a\n"
		"bound on how far any robot point moves (intervals covered by bisection), never by\n"
		"sampling it at a resolution. The path is simplified under the same checks and written\n"
		"as CSV query,k,x,y,theta (3D: x,y,z,qw,qx,qy,qz),clearance: clearance is the certified\n"
		"minimum clearance of the segment from waypoint k to k+1 (empty on the last).\n"
		"Exit status: 0 paths for all queries; 1 no path for some query in the time (nothing\n"
		"written); 2 bad input (a start or goal in collision or out of bounds, with its line).\n"
		"\n"
		"--check PATH certifies a path CSV (columns x,y,theta or x,y,z,qw,qx,qy,qz, an optional\n"
		"query column separating paths) against SCENE: per segment free, colliding or\n"
		"uncertain, how far it is certified free, the first contact found (time in [0,1] along\n"
		"the segment, obstacle, object, robot part), as CSV to --out or standard output. Exit\n"
		"status 0 when every segment is free, 1 otherwise, 2 on bad input.\n\n");
}

/* ---- planning ---- */

static int mkPlanCmd_Write(const char *out, const mkScene *s, const mkPlanPath *paths, int n)
{
	char msg[1024];
	mkOutFile f;
	memset(&f, 0, sizeof f);
	f.slot = -1;
	if (mkOutFile_Open(&f, out, msg, sizeof msg)) { fprintf(stderr, "mink plan: %s: %s\n", out, msg); return 1; }
	fprintf(f.fp, "query,k,%s,clearance\n", s->dim == 2 ? "x,y,theta" : "x,y,z,qw,qx,qy,qz");
	for (int qi = 0; qi < n; ++qi) {
		const mkPlanPath *p = &paths[qi];
		for (int k = 0; k < p->count; ++k) {
			fprintf(f.fp, "%d,%d", qi, k);
			for (int d = 0; d < p->pose_size; ++d) fprintf(f.fp, ",%.17g", p->poses[(long)k * p->pose_size + d]);
			if (k + 1 < p->count) fprintf(f.fp, ",%.17g\n", p->clearance[k]);
			else fprintf(f.fp, ",\n");
		}
	}
	if (mkOutFile_Commit(&f, msg, sizeof msg)) { fprintf(stderr, "mink plan: %s\n", msg); return 1; }
	return 0;
}

static int mkPlanCmd_Plan(const char *file, const mkScene *s, const mkSceneQuery *q, const mkPlanOptions *o,
	const char *out)
{
	char msg[1024];
	if (!s->query_count) {
		fprintf(stderr, "mink plan: the scene has no queries: add 'bounds ...', 'start POSE' and 'goal POSE' lines\n");
		return 2;
	}
	mkPlanPath *paths = calloc((size_t)s->query_count, sizeof *paths);
	if (!paths) { fprintf(stderr, "mink plan: out of memory\n"); return 1; }
	int rc = 0;
	for (int k = 0; k < s->query_count && rc == 0; ++k) {
		rc = mkPlan_Solve(s, q, k, o, &paths[k], msg, sizeof msg);
		if (rc) { fprintf(stderr, "mink plan: %s: %s\n", file, msg); rc = rc == 3 ? 1 : rc; break; }
		const mkPlanPath *p = &paths[k];
		double minc = INFINITY;
		for (int i = 0; i + 1 < p->count; ++i) minc = fmin(minc, p->clearance[i]);
		fprintf(stderr, "mink plan: query %d: %d waypoints, certified minimum clearance %.6g, planned in %.3f s (%ld "
			"state and %ld motion checks)\n", k, p->count, minc, p->seconds, p->states_checked, p->motions_checked);
	}
	if (rc == 0) rc = mkPlanCmd_Write(out, s, paths, s->query_count);
	for (int k = 0; k < s->query_count; ++k) mkPlanPath_Free(&paths[k]);
	free(paths);
	return rc;
}

/* ---- --check ---- */

typedef struct mkPlanCheck {
	const mkSceneQuery *q;
	double margin;
	int ps;
	long n;              /* waypoints */
	double *poses;       /* n * ps */
	long *query;         /* n: the path of each waypoint */
	mkMotionAnswer *seg; /* n: segment i from waypoint i to i + 1 (same path) */
	int threads, index;
	pthread_mutex_t lock;
	long next;
} mkPlanCheck;

/* The column of name in the header's fields, or -1. */
static int mkPlanCmd_Column(char **fields, int nf, const char *name)
{
	for (int k = 0; k < nf; ++k)
		if (strcmp(fields[k], name) == 0) return k;
	return -1;
}

/* Split a line at commas in place (at most max fields); the count. */
static int mkPlanCmd_Split(char *line, char **fields, int max)
{
	int n = 0;
	char *p = line;
	line[strcspn(line, "\r\n")] = 0;
	while (n < max) {
		fields[n++] = p;
		char *c = strchr(p, ',');
		if (!c) break;
		*c = 0;
		p = c + 1;
	}
	return n;
}

/* Read the path CSV into C. Returns 0, or 2 after printing. */
static int mkPlanCmd_ReadPath(const char *path, int dim, mkPlanCheck *C)
{
	static const char *const cols2[] = {"x", "y", "theta"}, *const cols3[] = {"x", "y", "z", "qw", "qx", "qy", "qz"};
	const char *const *cols = dim == 2 ? cols2 : cols3;
	FILE *f = fopen(path, "r");
	if (!f) { fprintf(stderr, "mink plan: %s: cannot open: %s\n", path, strerror(errno)); return 2; }
	char line[8192], *fields[64];
	int col[7], qcol = -1, lineno = 1, rc = 0;
	long cap = 0;
	if (!fgets(line, sizeof line, f)) { fprintf(stderr, "mink plan: %s: empty file\n", path); fclose(f); return 2; }
	int nf = mkPlanCmd_Split(line, fields, 64);
	for (int d = 0; d < C->ps && rc == 0; ++d)
		if ((col[d] = mkPlanCmd_Column(fields, nf, cols[d])) < 0) {
			fprintf(stderr, "mink plan: %s: line 1: no column '%s': a %dD path needs columns %s\n", path, cols[d], dim,
				dim == 2 ? "x,y,theta" : "x,y,z,qw,qx,qy,qz");
			rc = 2;
		}
	qcol = mkPlanCmd_Column(fields, nf, "query");
	while (rc == 0 && fgets(line, sizeof line, f)) {
		++lineno;
		if (line[strspn(line, " \t\r\n")] == 0) continue;
		int m = mkPlanCmd_Split(line, fields, 64);
		if (C->n >= cap) {
			cap = cap ? 2 * cap : 256;
			double *np = realloc(C->poses, (size_t)cap * C->ps * sizeof *np);
			long *nq = np ? realloc(C->query, (size_t)cap * sizeof *nq) : NULL;
			if (np) C->poses = np;
			if (nq) C->query = nq;
			if (!np || !nq) { fprintf(stderr, "mink plan: out of memory\n"); rc = 2; break; }
		}
		for (int d = 0; d <= C->ps && rc == 0; ++d) {
			int c = d < C->ps ? col[d] : qcol;
			if (c < 0) { C->query[C->n] = 0; continue; }
			char *end;
			double v = c < m ? strtod(fields[c], &end) : NAN;
			if (c >= m || end == fields[c] || *end || !isfinite(v)) {
				fprintf(stderr, "mink plan: %s: line %d: field '%s' = '%.40s' is not a finite number\n", path, lineno,
					d < C->ps ? cols[d] : "query", c < m ? fields[c] : "");
				rc = 2;
			} else if (d < C->ps) {
				C->poses[C->n * C->ps + d] = v;
			} else {
				C->query[C->n] = (long)v;
			}
		}
		if (rc == 0 && C->ps == 7) {
			const double *p = C->poses + C->n * 7;
			if (p[3] == 0.0 && p[4] == 0.0 && p[5] == 0.0 && p[6] == 0.0) {
				fprintf(stderr, "mink plan: %s: line %d: the quaternion qw,qx,qy,qz = 0,0,0,0 is out of range: must be "
					"nonzero\n", path, lineno);
				rc = 2;
			}
		}
		if (rc == 0) ++C->n;
	}
	fclose(f);
	return rc;
}

static void *mkPlanCmd_CheckWorker(void *arg)
{
	mkPlanCheck *C = arg;
	for (;;) {
		pthread_mutex_lock(&C->lock);
		long i = C->next++;
		pthread_mutex_unlock(&C->lock);
		if (i + 1 >= C->n) return NULL;
		if (C->query[i] != C->query[i + 1]) continue;
		mkSceneQuery_Motion(C->q, C->poses + i * C->ps, C->poses + (i + 1) * C->ps, C->margin, PLAN_MAX_POSES, &C->seg[i]);
	}
}

static int mkPlanCmd_Check(const mkScene *s, const mkSceneQuery *q, const char *path, const char *out, double margin,
	int threads)
{
	mkPlanCheck C;
	memset(&C, 0, sizeof C);
	C.q = q;
	C.margin = margin;
	C.ps = mkSceneQuery_PoseSize(q);
	int rc = mkPlanCmd_ReadPath(path, s->dim, &C);
	if (rc == 0 && !(C.seg = calloc((size_t)C.n + 1, sizeof *C.seg))) rc = 1;
	if (rc == 0) {
		pthread_t th[256];
		pthread_mutex_init(&C.lock, NULL);
		int started = 0;
		for (int t = 1; t < threads; ++t)
			if (pthread_create(&th[started], NULL, mkPlanCmd_CheckWorker, &C) == 0) ++started;
		mkPlanCmd_CheckWorker(&C);
		for (int t = 0; t < started; ++t) pthread_join(th[t], NULL);
		pthread_mutex_destroy(&C.lock);
	}
	long bad = 0;
	if (rc == 0) {
		char msg[1024];
		mkOutFile f;
		memset(&f, 0, sizeof f);
		f.slot = -1;
		FILE *fp = stdout;
		if (out && mkOutFile_Open(&f, out, msg, sizeof msg)) { fprintf(stderr, "mink plan: %s: %s\n", out, msg); rc = 1; }
		if (out && rc == 0) fp = f.fp;
		if (rc == 0) fprintf(fp, "query,segment,status,free_until,contact_time,obstacle,object,part,clearance\n");
		for (long i = 0, seg = 0; rc == 0 && i + 1 < C.n; ++i) {
			if (C.query[i] != C.query[i + 1]) { seg = 0; continue; }
			const mkMotionAnswer *m = &C.seg[i];
			bad += m->status != MK_POSE_FREE;
			int coll = m->status == MK_POSE_COLLIDING;
			const char *obj = coll && m->obstacle >= 0 ? s->objects[s->obstacle_object[m->obstacle]].name : "";
			fprintf(fp, "%ld,%ld,%s,%.17g,", C.query[i], seg++, mkPoseStatus_Name(m->status), m->free_until);
			if (coll) fprintf(fp, "%.17g,%d,%s,%d,", m->contact_time, m->obstacle, obj, m->part);
			else fprintf(fp, ",,,,");
			fprintf(fp, "%.17g\n", m->clearance);
		}
		if (out && rc == 0 && mkOutFile_Commit(&f, msg, sizeof msg)) { fprintf(stderr, "mink plan: %s\n", msg); rc = 1; }
		if (out && rc != 0) mkOutFile_Discard(&f);
	}
	if (rc == 0 && bad) {
		fprintf(stderr, "mink plan: %s: %ld segments are not certified free (see the status column)\n", path, bad);
		rc = 1;
	}
	free(C.poses); free(C.query); free(C.seg);
	return rc;
}

/* ---- the command ---- */

int mkCmd_Plan(int argc, char **argv)
{
	const char *out = NULL, *check = NULL, *planner = "RRTConnect", *scene_file = NULL;
	double time = 1.0, clearance = 0.0;
	long threads = 1;
	uint64_t seed = 1;
	int no_simplify = 0;
	/* SCENE: the one argument that is neither an option nor an option's
	 * value (every option but --no-simplify and --help takes one); taken out
	 * of argv before the options are parsed */
	for (int k = 1; k < argc; ++k) {
		if (argv[k][0] == '-') {
			k += strcmp(argv[k], "--no-simplify") != 0 && strcmp(argv[k], "--help") != 0 && strcmp(argv[k], "-h") != 0
				&& !strchr(argv[k], '=');
			continue;
		}
		scene_file = argv[k];
		memmove(argv + k, argv + k + 1, (size_t)(argc - k - 1) * sizeof *argv);
		--argc;
		break;
	}
	mkFlag flags[] = {
		MK_FLAG_PATH("--out", "PATH", "the path CSV (planning, required) or the check's CSV (--check;\n"
			"default standard output), written atomically", &out),
		MK_FLAG_TEXT("--planner", "NAME", "OMPL planner (default RRTConnect): RRTConnect, RRT, RRTstar, PRM,\n"
			"PRMstar, LazyPRM, KPIECE1, BKPIECE1, BITstar", &planner, NULL),
		MK_FLAG_DOUBLE("--time", "S", "planning time per query in seconds (default 1)", &time, 1e-3, 1e6),
		MK_FLAG_U64("--seed", "S", "OMPL's random seed (default 1)", &seed),
		MK_FLAG_DOUBLE("--clearance", "D", "certified clearance every state and motion keeps (default 0)", &clearance,
			0.0, 1e12),
		MK_FLAG_LONG("--threads", "K", "threads of --check's segments (default 1; OMPL's planners here run on\n"
			"one thread); the output does not depend on K", &threads, 1, 256),
		MK_FLAG_PATH("--check", "PATH", "certify the path CSV PATH against SCENE instead of planning", &check),
		MK_FLAG_SWITCH("--no-simplify", "keep the planner's path as it is", &no_simplify),
	};
	int rc = mkCli_Parse("plan", flags, MK_COUNT(flags), argc, argv, mkPlanCmd_Help);
	if (rc != MK_CLI_GO) return rc;
	if (!scene_file) { fprintf(stderr, "mink plan: no SCENE given (usage: mink plan SCENE --out PATH)\n"); return 2; }
	if (!check && (rc = mkCli_Require("plan", &flags[0])) != MK_CLI_GO) return rc;
	if (!mkPlan_PlannerKnown(planner)) {
		fprintf(stderr, "mink plan: --planner = '%s' is not allowed: must be one of %s\n", planner, mkPlan_PlannerNames());
		return 2;
	}
	mkScene s;
	memset(&s, 0, sizeof s);
	if ((rc = mkSceneCmd_LoadFile("plan", scene_file, &s)) != 0) return rc;
	mkSceneQueryOptions qo = mkSceneQueryOptions_Default();
	qo.clearance_rel = MK_PLAN_CLEARANCE_REL;
	mkSceneQuery *q = NULL;
	char msg[1024];
	if (mkSceneQuery_Create(&s, &qo, &q, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "mink plan: %s: %s\n", scene_file, msg);
		mkScene_Free(&s);
		return 2;
	}
	if (check) {
		rc = mkPlanCmd_Check(&s, q, check, out, clearance, (int)threads);
	} else {
		mkPlanOptions o = mkPlanOptions_Default();
		o.planner = planner;
		o.time = time;
		o.seed = (unsigned long)seed;
		o.clearance = clearance;
		o.simplify = !no_simplify;
		rc = mkPlanCmd_Plan(scene_file, &s, q, &o, out);
	}
	mkSceneQuery_Destroy(q);
	mkScene_Free(&s);
	return rc;
}
