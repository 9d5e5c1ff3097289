/* main.c - the `planning` driver: planners x checkers (mink certified, FCL
 * with OMPL's discrete motion check) on scenes with planning queries. */
#include "planning.h"

#include <stdio.h>
#include <string.h>

#include <mink_plan/plan.h>
#include <mink_plan/plan_fcl.h>

#define MK_PLANNING_LIST_MAX 8
#define MK_PLANNING_SCENES "experiments/plan/scenes/room2d.txt,experiments/plan/scenes/maze2d.txt," \
	"experiments/plan/scenes/plate3d.txt,experiments/plan/scenes/home3d.txt,experiments/plan/scenes/passage3d.txt"

typedef struct mkPlanningList {
	char given[1024];   /* as given */
	char text[1024];    /* split: the items point into it */
	const char *item[MK_PLANNING_LIST_MAX];
	int count;
} mkPlanningList;

/* Split a comma-separated list in place; -1 when empty or too long. */
static int mkPlanningList_Split(mkPlanningList *l, const char *text, char *msg, size_t msglen)
{
	if (strlen(text) >= sizeof l->text) {
		snprintf(msg, msglen, "is too long: must be under %zu characters", sizeof l->text);
		return -1;
	}
	strcpy(l->given, text);
	strcpy(l->text, text);
	l->count = 0;
	for (char *p = l->text, *next; p; p = next) {
		next = strchr(p, ',');
		if (next) *next++ = 0;
		if (!*p || l->count == MK_PLANNING_LIST_MAX) {
			snprintf(msg, msglen, "is not a list: must be 1 to %d non-empty names separated by commas",
				MK_PLANNING_LIST_MAX);
			return -1;
		}
		l->item[l->count++] = p;
	}
	return 0;
}

static int mkPlanning_ParseScenes(void *ctx, const char *text, char *msg, size_t msglen)
{
	return mkPlanningList_Split(ctx, text, msg, msglen);
}

static int mkPlanning_ParsePlanners(void *ctx, const char *text, char *msg, size_t msglen)
{
	mkPlanningList *l = ctx;
	if (mkPlanningList_Split(l, text, msg, msglen) != 0) return -1;
	for (int i = 0; i < l->count; ++i)
		if (!mkPlan_PlannerKnown(l->item[i])) {
			snprintf(msg, msglen, "names an unknown planner '%s': must be among %s", l->item[i], mkPlan_PlannerNames());
			return -1;
		}
	return 0;
}

static const mkDriver mkPlanningDriver = {
	"planning", "OMPL's planners on scenes with two checkers: mink's certified state and motion checks, and\n"
	"FCL 0.7 with OMPL's default discrete motion check; every returned path certified afterwards.",
	1, mkPlanning_Columns, MK_SHARED_TRIALS | MK_SHARED_SEED, 20, 100000, 29,
	"Trial t seeds OMPL with seed + t (in a process of its own per run) for every scene, planner\n"
	"and checker, the checkers alternating which runs first. Rows: one per trial, scene, query,\n"
	"planner and checker; status path|none|bad|crash.",
};

int main(int argc, char **argv)
{
	mkPlanningList scenes, planners;
	char msg[1024];
	mkPlanningList_Split(&scenes, MK_PLANNING_SCENES, msg, sizeof msg);
	mkPlanningList_Split(&planners, "RRTConnect", msg, sizeof msg);
	double budget = 2.0;
	long res = 32;
	mkFlag flags[] = {
		MK_FLAG_TEXT("--scenes", "LIST", "scene files with planning queries, comma-separated (default the five\n"
			"of experiments/plan/scenes: room2d, maze2d, plate3d, home3d, passage3d)", &scenes, mkPlanning_ParseScenes),
		MK_FLAG_TEXT("--planners", "LIST", "OMPL planners, comma-separated (default RRTConnect)", &planners,
			mkPlanning_ParsePlanners),
		MK_FLAG_DOUBLE("--time", "S", "planning budget per run in seconds, 0.01..600 (default 2)", &budget, 0.01, 600),
		MK_FLAG_LONG("--res", "N", "FCL's mesh resolution (points around a curved outline), 8..1024 (default 32)", &res,
			MK_PLAN_FCL_RES_MIN, MK_PLAN_FCL_RES_MAX),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkPlanningDriver, flags, argc, argv);
	mkPlanningScene loaded[MK_PLANNING_LIST_MAX];
	int nloaded = 0, failed = 0;
	for (int i = 0; i < scenes.count && !failed; ++i) {
		if (mkPlanningScene_Load(&loaded[i], scenes.item[i], msg, sizeof msg) != 0) {
			fprintf(stderr, "planning: --scenes: %s\n", msg);
			failed = 2;
		} else {
			++nloaded;
		}
	}
	if (failed) {
		for (int i = 0; i < nloaded; ++i) mkPlanningScene_Free(&loaded[i]);
		mkRun_End(&run, 1);
		return 2;
	}
	mkMeta_Set(&run.meta, "scenes", scenes.given);
	mkMeta_Set(&run.meta, "planners", planners.given);
	mkMeta_SetDouble(&run.meta, "budget_s", budget);
	mkMeta_SetInt(&run.meta, "mesh_res", res);
	mkMeta_Set(&run.meta, "fcl_version", mkPlanFcl_Version());
	mkMeta_Set(&run.meta, "fcl_motion_check", "OMPL DiscreteMotionValidator, default resolution 0.01 of the extent");
	if (mkRun_OpenCsv(&run, run.end - run.begin) != 0) failed = 1;
	for (long t = run.begin; t < run.end && !failed; ++t, mkRun_Step(&run, 1))
		for (int i = 0; i < nloaded && !failed; ++i)
			for (int k = 0; k < loaded[i].scene.query_count && !failed; ++k)
				for (int p = 0; p < planners.count && !failed; ++p)
					for (int c = 0; c < 2 && !failed; ++c) {
						mkPlanningSetup setup = { planners.item[p], (mkPlanningChecker)((c + t) % 2), budget, (int)res,
							(unsigned long)((run.seed + (uint64_t)t) % 4294967295u) + 1 };
						mkPlanningResult r;
						if (mkPlanning_Run(&loaded[i], k, &setup, &r) != 0) {
							mkRun_Fail(&run, "cannot start a planning process");
							failed = 1;
							break;
						}
						if (r.status == MK_PLANNING_CRASH || r.status == MK_PLANNING_BAD)
							fprintf(stderr, "planning: trial %ld, %s query %d, %s with %s: %s\n", t, loaded[i].name, k,
								setup.planner, mkPlanningChecker_Name(setup.checker), r.message);
						mkPlanning_Row(&run.csv, t, &loaded[i], k, &setup, &r);
					}
	for (int i = 0; i < nloaded; ++i) mkPlanningScene_Free(&loaded[i]);
	return mkRun_End(&run, failed);
}
