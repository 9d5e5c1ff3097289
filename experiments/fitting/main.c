/* main.c - the `fitting` driver: the fitting errors of paper Sec. 6.2
 * (cases.h). One CSV row per trial and model (and per level in case 2). */
#include "fitting.h"

#include <libqhull_r/libqhull_r.h>

#define MAX_TRIALS 1000000

static const char *const mkCaseNames[] = { "1", "2", "3", "all" };

static const mkDriver mkFittingDriver = {
	"fitting",
	"Fitting errors between superquadrics and convex polyhedra (paper Sec. 6.2).\n"
	"A run's units are (case, trial) pairs, case by case; --shard splits them.",
	MK_FIT_SCHEMA, mkFitting_Columns,
	MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 100, MAX_TRIALS, 2022, NULL,
};

int main(int argc, char **argv)
{
	int caseChoice = 3;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--case", "1|2|3|all", "which case to run (default all)\n"
			"1: superquadric fitted to a random polyhedron (LM)\n"
			"2: polyhedra from n x n superquadric grids, n = 4..20\n"
			"3: cube, ellipsoid, cylinder, both models", &caseChoice, mkCaseNames),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkFittingDriver, flags, argc, argv);

	/* The run's units are (case, trial) pairs, case by case; a shard takes a
	 * contiguous block of them. */
	int cases[3], ncases = 0;
	for (int c = 1; c <= 3; ++c)
		if (caseChoice == 3 || caseChoice == c - 1)
			cases[ncases++] = c;
	long begin, end;
	mkShard_Range(run.shard, (long)ncases * run.trials, &begin, &end);
	char text[64];
	snprintf(text, sizeof text, "%ld..%ld", begin, end - 1);
	mkMeta_Set(&run.meta, "trial_range", end > begin ? text : "none");
	mkMeta_Set(&run.meta, "cases", mkCaseNames[caseChoice]);
	mkMeta_Set(&run.meta, "qhull_version", qh_version);
	mkMeta_Set(&run.meta, "cminpack_version", MK_FIT_CMINPACK_VERSION);
	mkMeta_Set(&run.meta, "case1_draw", "100 points [20,15,10].*U(-1,1)^3; LM fit to the hull vertices");
	mkMeta_Set(&run.meta, "case2_draw", "a=[20,15,10].*U(0,1)^3, eps=U(0,2)^2, quaternion U(0,1)^4; n=4..20");
	mkMeta_Set(&run.meta, "case3_draw", "size=[50,36,20].*U(0,1)^3+1");
	mkPaper_Record(&run.meta, "fitting");
	if (mkRun_OpenCsv(&run, end - begin) != 0)
		return mkRun_End(&run, 1);

	static mkFitRow rows[MK_FIT_MAX_ROWS];
	int (*const trialFn[3])(uint64_t, int, mkFitRow *) = { mkFitCase1_Trial, mkFitCase2_Trial, mkFitCase3_Trial };
	double seconds[3] = { 0.0, 0.0, 0.0 };
	int failed = 0;
	for (long u = begin; u < end && !failed; ++u) {
		int c = cases[u / run.trials];
		int t = (int)(u % run.trials);
		double t0 = mkClock_Wall();
		int n = trialFn[c - 1](run.seed, t, rows);
		seconds[c - 1] += mkClock_Wall() - t0;
		if (n < 0) {
			mkRun_Fail(&run, "out of memory in case %d, trial %d", c, t);
			failed = 1;
		}
		for (int k = 0; k < n; ++k)
			mkFitting_WriteRow(&run.csv, &rows[k]);
		mkRun_Step(&run, 1);
	}
	for (int c = 0; c < 3; ++c) {
		char key[32];
		snprintf(key, sizeof key, "case%d_seconds", c + 1);
		mkMeta_SetDouble(&run.meta, key, seconds[c]);
	}
	return mkRun_End(&run, failed);
}
