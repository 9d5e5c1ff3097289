/* main.c - the `timing` driver: the running-time experiment of the paper
 * (Sec. 6.3, Table 1, Figs. 5-8); what it measures is in timing.h. */
#include "timing.h"

#include <stdlib.h>

static const char *const mkDimNames[] = { "2", "3", "both" };

static const mkDriver mkTimingDriver = {
	"timing",
	"The running-time experiment of the paper (Sec. 6.3, Table 1, Figs. 5-8): seconds\n"
	"per call of every registered method on random EE, ES and SQ pairs in 2D and 3D,\n"
	"one CSV row per (dim, case, method, level, trial), plus a metadata sidecar\n"
	"<out>.meta (clock, warm-up, threads, trial caps, skipped methods).",
	MK_TIMING_SCHEMA, mkTiming_Columns,
	MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 100, 1000000, 2022,
	"A run's units are its cells (dim, case, level, method), in that order: --shard\n"
	"splits the cells, every cell runs trials 0..T-1 (or its cap).",
};

int main(int argc, char **argv)
{
	mkTimingOptions o;
	mkTimingOptions_Default(&o);
	int dims = 2, rotations = MK_ROT_PAPER;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--dim", "2|3|both", "which dimensions (default both)", &dims, mkDimNames),
		MK_FLAG_TEXT("--cases", "LIST", "comma-separated EE, ES, SQ, or all (default all)", o.case_on,
			mkTiming_ParseCases),
		MK_FLAG_TEXT("--methods", "LIST", "comma-separated registry names, exec:NAME=COMMAND\n"
			"(external methods), @FILE (a methods file: docs/compare.md), or all\n"
			"(default all)", o.method_on,
			mkTiming_ParseMethods),
		MK_FLAG_REPEAT("--levels", "2d=LIST|3d=LIST", "2D levels: points per body, 3..100000;\n"
			"3D levels: grid side n (n x n points per body), 3..3000;\n"
			"LIST is comma-separated integers or START:STEP:STOP ranges\n"
			"(default 2d=20:10:500 and 3d=5:5:50, the paper's)", o.levels, mkTiming_ParseLevels),
		MK_FLAG_ROTATIONS(&rotations),
		MK_FLAG_DOUBLE("--budget", "SECONDS", "time budget per (dim, case, level, method) cell, 0..1e6\n"
			"(default 2): when T warm-up times exceed it, the cell runs\n"
			"max(K, floor(budget / warm-up)) trials instead of T", &o.budget, 0.0, 1e6),
		MK_FLAG_LONG("--min-trials", "K", "trials a capped cell still runs, 1..1000000 (default 3)",
			&o.min_trials, 1, 1000000),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkTimingDriver, flags, argc, argv);
	o.trials = run.trials;
	o.seed = run.seed;
	o.dim_on[2] = dims != 1;
	o.dim_on[3] = dims != 0;
	o.rotations = (mkRotDraw)rotations;

	long total = mkTiming_Cells(&o, NULL), begin, end;
	mkTimingCell *cells = malloc((size_t)(total > 0 ? total : 1) * sizeof *cells);
	mkTimingRun *tr = mkTimingRun_New();
	if (!cells || !tr) {
		mkRun_Fail(&run, "out of memory");
		free(cells);
		mkTimingRun_Free(tr);
		return mkRun_End(&run, 1);
	}
	mkTiming_Cells(&o, cells);
	mkShard_Range(run.shard, total, &begin, &end);
	/* The units are cells; every cell runs the trials from 0. */
	char text[64];
	snprintf(text, sizeof text, "0..%ld", o.trials - 1);
	mkMeta_Set(&run.meta, "trial_range", text);
	mkTiming_MetaBegin(&run.meta, &o, begin, end, total);

	int failed = mkRun_OpenCsv(&run, end - begin) != 0;
	for (long i = begin; i < end && !failed; ++i) {
		int first = i == begin || cells[i - 1].dim != cells[i].dim || cells[i - 1].c != cells[i].c
			|| cells[i - 1].level != cells[i].level;
		failed = mkTiming_RunCell(&o, cells[i], first, tr, &run.csv) != 0;
		mkRun_Step(&run, 1);
	}
	if (!failed)
		mkTiming_MetaEnd(&run.meta, tr, end - begin);
	free(cells);
	mkTimingRun_Free(tr);
	return mkRun_End(&run, failed);
}
