/* mink_plan/plan.h - motion planning on a mink scene with OMPL's planners
 * (C++17 inside, a C interface here): mink's scene query as the state
 * validity checker and its certified motion check (mkSceneQuery_MotionTest;
 * the returned path certified again by mkSceneQuery_Motion) as the motion
 * validator. OMPL stays
 * out of the core; this library is the only code that includes it. */
#ifndef MINK_PLAN_PLAN_H
#define MINK_PLAN_PLAN_H

#include <stddef.h>
#include <mink/cspace.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The scene query's clearance_rel for planning (mkSceneQueryOptions): the
 * certified motion checks need a lower bound of each pose's clearance
 * within 10 % of it, not its last digits (docs/planning.md). The segments'
 * clearances written are such bounds. */
#define MK_PLAN_CLEARANCE_REL 0.1

typedef struct mkPlanOptions {
	const char *planner;  /* an OMPL geometric planner by name (mkPlan_PlannerNames) */
	double time;          /* seconds of planning per query, > 0 */
	unsigned long seed;   /* OMPL's random seed (ompl::RNG::setSeed) */
	double clearance;     /* every state and motion keeps at least this certified clearance, >= 0 */
	int simplify;         /* 1: OMPL's simplifier under the same validator */
	int warm;             /* 1: before the clock starts, one untimed check of the start and of the motion start ->
	                       * goal, one thread started and joined and one exception thrown and caught, so that the
	                       * first solve in a fresh process does not pay its page faults on the clock (the counts
	                       * leave them out; OMPL's PRM ends its search for a path by an exception) */
} mkPlanOptions;

/* RRTConnect, 1 s, seed 1, clearance 0, simplify, no warm-up. */
mkPlanOptions mkPlanOptions_Default(void);

/* The planners' names, comma-separated. */
const char *mkPlan_PlannerNames(void);
/* 1 when name is one of them. */
int mkPlan_PlannerKnown(const char *name);

typedef struct mkPlanPath {
	int count;            /* waypoints */
	int pose_size;        /* 3 (2D) or 7 (3D) */
	double *poses;        /* count * pose_size */
	double *clearance;    /* count - 1: each segment's certified minimum clearance */
	double seconds;       /* planning wall time (without simplification) */
	long states_checked, motions_checked;
} mkPlanPath;

/* Plan query k of the scene (scene->queries[k]) with the prepared query q.
 * Returns 0 with a path, 1 when none was found in the time (message says
 * so), 2 on bad input (start or goal in collision, closer than the
 * clearance or out of bounds, the scene without bounds; the message names
 * the line), 3 on another failure. The path is allocated
 * (mkPlanPath_Free). */
int mkPlan_Solve(const mkScene *scene, const mkSceneQuery *q, int k, const mkPlanOptions *o, mkPlanPath *out,
	char *msg, size_t msglen);
void mkPlanPath_Free(mkPlanPath *p);

#ifdef __cplusplus
}
#endif

#endif
