/* planning.c - one planning run of the experiment `planning` (planning.h). */
#include "planning.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <mink_plan/plan.h>
#include <mink_plan/plan_fcl.h>

#define MK_PLANNING_MAX_POSES 1000000L   /* poses per certified segment at most, as mink plan --check */

const char *const mkPlanning_Columns[] = { "trial", "seed", "scene", "query", "planner", "checker", "budget_s",
	"mesh_res", "status", "success", "seconds", "states_checked", "motions_checked", "waypoints", "length",
	"segments", "segments_free", "segments_colliding", "segments_uncertain", "path_true_free",
	"first_contact_segment", "first_contact_obstacle", NULL };

static const char *const mkPlanningStatusNames[] = { "path", "none", "bad", "crash" };

const char *mkPlanningChecker_Name(mkPlanningChecker c) { return c == MK_PLANNING_FCL ? "fcl" : "mink"; }

int mkPlanningScene_Load(mkPlanningScene *s, const char *path, char *msg, size_t msglen)
{
	memset(s, 0, sizeof *s);
	FILE *fp = fopen(path, "rb");
	if (!fp) {
		snprintf(msg, msglen, "%s: cannot be read", path);
		return -1;
	}
	char *text = NULL;
	size_t len = 0, cap = 0, got;
	char buf[4096];
	while ((got = fread(buf, 1, sizeof buf, fp)) > 0) {
		if (len + got + 1 > cap) {
			cap = 2 * (len + got + 1);
			char *t = realloc(text, cap);
			if (!t) break;
			text = t;
		}
		memcpy(text + len, buf, got);
		len += got;
	}
	fclose(fp);
	if (!text || len + 1 > cap) {
		free(text);
		snprintf(msg, msglen, "%s: empty or out of memory", path);
		return -1;
	}
	text[len] = 0;
	char why[512];
	mkResult rc = mkScene_Parse(text, &s->scene, why, sizeof why);
	free(text);
	if (rc == MK_OK && s->scene.query_count == 0) {
		snprintf(why, sizeof why, "no planning query (a 'start' and a 'goal' line)");
		rc = MK_ERR_ARGUMENT;
	}
	if (rc == MK_OK) {
		mkSceneQueryOptions qo = mkSceneQueryOptions_Default();
		qo.clearance_rel = MK_PLAN_CLEARANCE_REL;
		rc = mkSceneQuery_Create(&s->scene, &qo, &s->query, why, sizeof why);
	}
	if (rc != MK_OK) {
		snprintf(msg, msglen, "%s: %s", path, why);
		mkPlanningScene_Free(s);
		return -1;
	}
	const char *base = strrchr(path, '/');
	snprintf(s->name, sizeof s->name, "%s", base ? base + 1 : path);
	char *dot = strrchr(s->name, '.');
	if (dot) *dot = 0;
	return 0;
}

void mkPlanningScene_Free(mkPlanningScene *s)
{
	if (s->query) mkSceneQuery_Destroy(s->query);
	mkScene_Free(&s->scene);
	memset(s, 0, sizeof *s);
}

/* Certify the path segment by segment and measure it. */
static void mkPlanning_Certify(const mkPlanningScene *s, const mkPlanPath *p, mkPlanningResult *r)
{
	int ps = p->pose_size, dim = s->scene.dim;
	r->waypoints = p->count;
	r->segments = p->count > 0 ? p->count - 1 : 0;
	for (int i = 0; i + 1 < p->count; ++i) {
		const double *a = p->poses + (size_t)i * ps, *b = a + ps;
		double d = 0.0;
		for (int j = 0; j < dim; ++j) d += (b[j] - a[j]) * (b[j] - a[j]);
		r->length += sqrt(d);
		mkMotionAnswer m;
		mkSceneQuery_Motion(s->query, a, b, 0.0, MK_PLANNING_MAX_POSES, &m);
		if (m.status == MK_POSE_FREE) ++r->free;
		else if (m.status == MK_POSE_UNCERTAIN) ++r->uncertain;
		else {
			++r->colliding;
			if (r->first_contact < 0) {
				r->first_contact = i;
				r->contact_obstacle = m.obstacle;
			}
		}
	}
}

/* The run itself (in the child). */
static void mkPlanning_Solve(const mkPlanningScene *s, int k, const mkPlanningSetup *setup, mkPlanningResult *r)
{
	mkPlanOptions o = mkPlanOptions_Default();
	o.planner = setup->planner;
	o.time = setup->time;
	o.seed = setup->seed;
	o.warm = 1;   /* a fresh process per run: its page faults kept off the clock, alike for both checkers */
	mkPlanPath p;
	int rc = setup->checker == MK_PLANNING_FCL
		? mkPlanFcl_Solve(&s->scene, k, &o, setup->res, &p, r->message, sizeof r->message)
		: mkPlan_Solve(&s->scene, s->query, k, &o, &p, r->message, sizeof r->message);
	r->seconds = p.seconds;
	r->states = p.states_checked;
	r->motions = p.motions_checked;
	if (rc == 0) {
		r->status = MK_PLANNING_PATH;
		mkPlanning_Certify(s, &p, r);
		mkPlanPath_Free(&p);
	} else {
		r->status = rc == 1 ? MK_PLANNING_NONE : MK_PLANNING_BAD;
	}
}

int mkPlanning_Run(const mkPlanningScene *s, int k, const mkPlanningSetup *setup, mkPlanningResult *out)
{
	memset(out, 0, sizeof *out);
	out->first_contact = out->contact_obstacle = -1;
	out->seconds = NAN;
	int fd[2];
	if (pipe(fd) != 0) return -1;
	fflush(NULL);
	pid_t pid = fork();
	if (pid < 0) {
		close(fd[0]);
		close(fd[1]);
		return -1;
	}
	if (pid == 0) {
		close(fd[0]);
		mkPlanning_Solve(s, k, setup, out);
		ssize_t w = write(fd[1], out, sizeof *out);
		_exit(w == (ssize_t)sizeof *out ? 0 : 1);
	}
	close(fd[1]);
	mkPlanningResult r;
	size_t got = 0;
	ssize_t n;
	while (got < sizeof r && (n = read(fd[0], (char *)&r + got, sizeof r - got)) > 0) got += (size_t)n;
	close(fd[0]);
	int status = 0;
	waitpid(pid, &status, 0);
	if (got == sizeof r && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
		*out = r;
		return 0;
	}
	out->status = MK_PLANNING_CRASH;
	snprintf(out->message, sizeof out->message, "the planning process ended by %s %d",
		WIFSIGNALED(status) ? "signal" : "exit status", WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
	return 0;
}

void mkPlanning_Row(mkCsv *csv, long trial, const mkPlanningScene *s, int k, const mkPlanningSetup *setup,
	const mkPlanningResult *r)
{
	int path = r->status == MK_PLANNING_PATH;
	mkCsv_Int(csv, trial);
	mkCsv_Int(csv, (long long)setup->seed);
	mkCsv_Str(csv, s->name);
	mkCsv_Int(csv, k);
	mkCsv_Str(csv, setup->planner);
	mkCsv_Str(csv, mkPlanningChecker_Name(setup->checker));
	mkCsv_Double(csv, setup->time);
	if (setup->checker == MK_PLANNING_FCL) mkCsv_Int(csv, setup->res); else mkCsv_Empty(csv);
	mkCsv_Str(csv, mkPlanningStatusNames[r->status]);
	mkCsv_Int(csv, path);
	if (r->status == MK_PLANNING_CRASH) mkCsv_Empty(csv); else mkCsv_Double(csv, r->seconds);
	mkCsv_Int(csv, r->states);
	mkCsv_Int(csv, r->motions);
	if (path) {
		mkCsv_Int(csv, r->waypoints);
		mkCsv_Double(csv, r->length);
		mkCsv_Int(csv, r->segments);
		mkCsv_Int(csv, r->free);
		mkCsv_Int(csv, r->colliding);
		mkCsv_Int(csv, r->uncertain);
		mkCsv_Int(csv, r->colliding ? 0 : r->uncertain ? -1 : 1);
		mkCsv_Int(csv, r->first_contact);
		mkCsv_Int(csv, r->contact_obstacle);
	} else {
		for (int i = 0; i < 9; ++i) mkCsv_Empty(csv);
	}
	mkCsv_EndRow(csv);
}
