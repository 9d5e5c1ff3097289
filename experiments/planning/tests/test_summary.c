/* test_summary.c - the planning section of the tables (mkPlanning_Summary)
 * on a hand-made result, the numbers worked by hand:
 *  - room2d / PRM, budget 1 s, four runs per checker. mink: paths after
 *    0.001, 0.003, 0.004 s and none; median of (0.001, 0.003, 0.004, inf)
 *    = (0.003 + 0.004) / 2 = 0.0035. fcl: 0.002, 0.010, 0.020, 0.030;
 *    median 0.015; ratio 0.0035 / 0.015 = 0.23. Within 2 ms: mink 1
 *    (0.001), fcl 1 (0.002); within 5 ms 3 / 1; within 20 ms 3 / 3 (0.020
 *    counts); within 1 s 3 / 4, so mink
 *    is below from the first budget at or above 0.030 s to 1 s: the
 *    budgets b_k = 10^(-3 + 3k/37) with b_k >= 0.03 are k >= 37 *
 *    log10(30) / 3 = 18.2, k = 19 .. 37: 19 budgets, each 1 run below.
 *    fcl's paths: one hitting the true shapes (0), one uncertain (-1).
 *    The one-sided Fisher test of 3 of 4 against 4 of 4: 0.50 (below).
 *  - maze2d / RRTConnect, budget 0.01 s, one run each: mink 0.004, fcl
 *    none: median ratio undefined; never below.
 * Without a result the section says it is not reproduced yet. */
#include "planning_summary.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ensure.h"
#include "summary_text.h"

static void mkWrite(const char *dir, const char *name, const char *text)
{
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/%s", dir, name);
	FILE *fp = fopen(path, "w");
	ENSURE(fp != NULL);
	fputs(text, fp);
	ENSURE(fclose(fp) == 0);
}

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	if (argc != 2) return mk_summary("planning.summary");
	const char *dir = argv[1];
	mkTally tally = { 0, 0, 0 };
	mkSummary_ExpectMissing(mkPlanning_Summary, dir, "planning", &tally);

	/* the budgets: 1 ms to the top, log-spaced, the last the top itself */
	ENSURE(fabs(mkPlanning_Budget(0, 1.0) - 1e-3) < 1e-18);
	ENSURE(mkPlanning_Budget(MK_PLANNING_BUDGETS - 1, 1.0) == 1.0);
	ENSURE(mkPlanning_Budget(18, 1.0) < 0.03 && mkPlanning_Budget(19, 1.0) > 0.03);
	/* Fisher's one-sided test by hand: 3 of 4 against 4 of 4 (7 successes
	 * in 8, the one failure in the first group with chance 4 / 8); 0 of 3
	 * against 3 of 3: 1 / C(6, 3) = 1 / 20; equal counts 2 of 4 and 2 of 4:
	 * P(X >= 2) for X ~ H(8, 4, 4) = (36 + 16 + 1) / 70. */
	ENSURE(fabs(mkPlanning_Fisher(3, 4, 4, 4) - 0.5) < 1e-12);
	ENSURE(fabs(mkPlanning_Fisher(0, 3, 3, 3) - 0.05) < 1e-12);
	ENSURE(fabs(mkPlanning_Fisher(2, 4, 2, 4) - 53.0 / 70.0) < 1e-12);

	mkWrite(dir, "planning.csv",
		"trial,seed,scene,query,planner,checker,budget_s,mesh_res,status,success,seconds,path_true_free\n"
		"0,1,room2d,0,PRM,mink,1,,path,1,0.001,1\n"
		"0,1,room2d,0,PRM,fcl,1,32,path,1,0.002,1\n"
		"1,2,room2d,0,PRM,fcl,1,32,path,1,0.010,0\n"
		"1,2,room2d,0,PRM,mink,1,,path,1,0.003,1\n"
		"2,3,room2d,0,PRM,mink,1,,path,1,0.004,1\n"
		"2,3,room2d,0,PRM,fcl,1,32,path,1,0.020,-1\n"
		"3,4,room2d,0,PRM,mink,1,,none,0,1.0,\n"
		"3,4,room2d,0,PRM,fcl,1,32,path,1,0.030,1\n"
		"0,1,maze2d,0,RRTConnect,mink,0.01,,path,1,0.004,1\n"
		"0,1,maze2d,0,RRTConnect,fcl,0.01,32,none,0,0.01,\n");
	mkWrite(dir, "planning.csv.meta", "experiment: planning\nseed: 1\ntrials: 4\n");
	char *md = mkSummary_Text(mkPlanning_Summary, dir, &tally);
	mkSummary_Expect(md, "| room2d | PRM | 4 | 3 / 4 | 0.0035 | 0.015 | 0.23 | 3 of 3 | 1 of 4 (1) |");
	mkSummary_Expect(md, "| maze2d | RRTConnect | 1 | 1 / 0 | 0.004 | no path | – | 1 of 1 | 0 of 0 (0) |");
	mkSummary_Expect(md, "| room2d | PRM | 1 / 1 | 3 / 1 | 3 / 3 | 3 / 4 | 3 / 4 | 19 of 38 | 1 runs at 0.035 s (p 0.50) |");
	mkSummary_Expect(md, "| maze2d | RRTConnect | 0 / 0 | 1 / 0 | – | – | – | 0 of 38 | – |");
	mkSummary_Expect(md, "Groups with some budget below: 1 of 2.");
	ENSURE(tally.published == 0 && tally.reproduced == 0 && tally.missing == 0);
	free(md);
	return mk_summary("planning.summary");
}
