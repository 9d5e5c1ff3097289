/* planning.h - the experiment `planning`: OMPL's planners on mink scenes
 * with two checkers, mink's certified checks (mkPlan_Solve) and FCL 0.7
 * with OMPL's default discrete motion check (mkPlanFcl_Solve); every
 * returned path is then certified segment by segment for the declared
 * shapes with mkSceneQuery_Motion (what `mink plan --check` runs). */
#ifndef MINK_EXP_PLANNING_H
#define MINK_EXP_PLANNING_H

#include <mink_exp/exp.h>
#include <mink/cspace.h>

extern const char *const mkPlanning_Columns[];

typedef enum mkPlanningChecker { MK_PLANNING_MINK = 0, MK_PLANNING_FCL = 1 } mkPlanningChecker;

/* "mink" or "fcl". */
const char *mkPlanningChecker_Name(mkPlanningChecker c);

typedef struct mkPlanningScene {
	char name[64];       /* the file's name without folder and .txt */
	mkScene scene;
	mkSceneQuery *query; /* the certified checks, default options */
} mkPlanningScene;

/* Read and prepare a scene file with planning queries; 0, or -1 with a
 * message naming the file (and line). */
int mkPlanningScene_Load(mkPlanningScene *s, const char *path, char *msg, size_t msglen);
void mkPlanningScene_Free(mkPlanningScene *s);

typedef struct mkPlanningSetup {
	const char *planner;
	mkPlanningChecker checker;
	double time;          /* the budget, seconds */
	int res;              /* FCL's mesh resolution */
	unsigned long seed;   /* OMPL's seed, nonzero */
} mkPlanningSetup;

typedef enum mkPlanningStatus {
	MK_PLANNING_PATH = 0,  /* a path was returned */
	MK_PLANNING_NONE = 1,  /* none in the budget */
	MK_PLANNING_BAD = 2,   /* the checker rejected the problem (start or goal) */
	MK_PLANNING_CRASH = 3  /* the planning process died (FCL's assertions abort) */
} mkPlanningStatus;

typedef struct mkPlanningResult {
	mkPlanningStatus status;
	double seconds;             /* planning wall time (without simplification) */
	long states, motions;       /* the checker's state and motion checks */
	int waypoints;
	double length;              /* the path's length in position (sum of |dx|) */
	int segments, free, colliding, uncertain;   /* mkSceneQuery_Motion's verdicts */
	int first_contact;          /* the first colliding segment, -1: none */
	int contact_obstacle;       /* its obstacle, -1: none */
	char message[200];
} mkPlanningResult;

/* Plan query k of the scene with one setup, in a child process (OMPL takes
 * one seed per process; an abort inside FCL ends only the child), and
 * certify the path. 0, or -1 when the child could not be run. */
int mkPlanning_Run(const mkPlanningScene *s, int k, const mkPlanningSetup *setup, mkPlanningResult *out);

/* The row of one run. */
void mkPlanning_Row(mkCsv *csv, long trial, const mkPlanningScene *s, int k, const mkPlanningSetup *setup,
	const mkPlanningResult *r);

#endif
