/* main.c - the `cobstacle` driver: C-obstacle timings (paper Sec. 7.1,
 * Table 2) and the geometry of Fig. 9; what it computes is in cobstacle.h. */
#include "cobstacle.h"

#include <stdlib.h>
#include <string.h>

static const char *const mkDimNames[] = { "2", "3", "both" };
static const char *const mkFormNames[] = { "normal", "gradient" };

static const mkDriver mkCObstacleDriver = {
	"cobstacle",
	"Configuration-space obstacles (paper Sec. 7.1, Table 2 and Fig. 9): for every\n"
	"robot orientation and obstacle, the contact space obstacle (+) (-robot) by one\n"
	"closed-form batch call, timed on one thread. One CSV row per dimension,\n"
	"obstacle count and trial, plus a metadata sidecar <out>.meta, and the geometry\n"
	"of Fig. 9 in the directory <out without .csv>/.",
	MK_COBSTACLE_SCHEMA, mkCObstacle_Columns,
	MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 3, MK_COBSTACLE_TRIALS_MAX, 2022,
	"--trials counts the timed trials per obstacle count; --shard splits the run's\n"
	"(dimension, obstacle count, trial) units, and only shard 0 writes the figure.",
};

/* Run the units [begin, end) into the open CSV; returns failed. */
static int mkRunUnits(mkRun *run, const mkCObstacleOptions *o, const mkCObstacleUnit *units, long begin, long end,
	const mkRotations *rot, mkCObstacleWork *w2, mkCObstacleWork *w3)
{
	int failed = 0;
	for (long i = begin; i < end && !failed; ++i) {
		mkCObstacleResult res;
		const mkCObstacleUnit *u = &units[i];
		failed = mkCObstacle_Level(o, u, rot, u->dim == 2 ? w2 : w3, &run->progress, &res) != 0;
		if (!failed)
			mkCObstacle_WriteRow(&run->csv, o, u, u->dim == 2 ? w2->n : w3->n,
				u->dim == 2 ? o->headings : rot->count, &res);
		if (!failed && res.nonfinite > 0)
			mkRun_Fail(run, "%dD, %ld obstacles, trial %ld: %ld non-finite points "
				"(counted in the row's 'nonfinite' column)", u->dim, u->obstacles, u->trial, res.nonfinite);
	}
	return failed;
}

int main(int argc, char **argv)
{
	mkCObstacleOptions o = { 0, 0, 1, 1, { { 50, 1000, 10000 }, 3 }, { { 50, 200, 1000 }, 3 }, 50, 50, 10,
		"experiments/data/so3_double_coset_3600.csv", 0, MK_FORM_GRADIENT, MK_IMPL_AUTO, 500, 10 };
	int dims = 2, form = 1, impl = MK_IMPL_AUTO;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--dim", "2|3|both", "which experiments (default both)", &dims, mkDimNames),
		MK_FLAG_TEXT("--obstacles2", "LIST", "2D obstacle counts, comma-separated, each 1..10000000\n"
			"(default 50,1000,10000)", &o.levels2, mkCObstacleLevels_Parse),
		MK_FLAG_TEXT("--obstacles3", "LIST", "3D obstacle counts (default 50,200,1000)", &o.levels3,
			mkCObstacleLevels_Parse),
		MK_FLAG_LONG("--headings", "H", "2D robot headings k pi / H, k = 0..H-1, 1..100000\n(default 50)",
			&o.headings, 1, 100000),
		MK_FLAG_LONG("--points", "N", "2D points per boundary, 3..100000 (default 50)", &o.points2, 3, 100000),
		MK_FLAG_LONG("--grid", "G", "3D G x G grid per boundary, 2..1000 (default 10)", &o.grid3, 2, 1000),
		MK_FLAG_PATH("--so3", "PATH", "3D robot orientations: CSV r11,...,r33 with a header, one\n"
			"rotation per line (default\nexperiments/data/so3_double_coset_3600.csv)", &o.so3),
		MK_FLAG_LONG("--orientations", "K", "use only the first K rotations of the file, 0 = all\n(default 0)",
			&o.orient3, 0, MK_COBSTACLE_SO3_MAX),
		MK_FLAG_CHOICE("--form", "normal|gradient", "closed form (default gradient, as the paper)", &form,
			mkFormNames),
		MK_FLAG_IMPL("--impl", "kernel (default auto)", &impl),
		MK_FLAG_LONG("--fig-obstacles", "N", "obstacles of the Fig. 9 scene, 0..100000, 0 = no figure\n"
			"geometry (default 500)", &o.fig_obstacles, 0, 100000),
		MK_FLAG_LONG("--fig-slices", "L", "C-slices drawn, every (H/L)-th heading, 1..H (default 10)",
			&o.fig_slices, 1, 100000),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkCObstacleDriver, flags, argc, argv);
	if (o.fig_obstacles > 0 && o.fig_slices > o.headings) {
		mkRun_Fail(&run, "--fig-slices = '%ld' is out of range: must be an integer in [1, %ld] (the headings)",
			o.fig_slices, o.headings);
		mkRun_End(&run, 1);
		return mkRun_Status(MK_RUN_USAGE);
	}
	o.seed = run.seed;
	o.trials = run.trials;
	o.dim2 = dims != 1;
	o.dim3 = dims != 0;
	o.form = form == 0 ? MK_FORM_NORMAL : MK_FORM_GRADIENT;
	o.impl = (mkImpl)impl;

	/* The shards split the (dim, obstacles, trial) units, not the trials:
	 * the sidecar says which in unit_range instead of trial_range. */
	mkCObstacleUnit *units = NULL;
	long nunits = mkCObstacle_Units(&o, &units), begin, end;
	if (nunits < 0) {
		mkRun_Fail(&run, "out of memory");
		return mkRun_End(&run, 1);
	}
	mkShard_Range(run.shard, nunits, &begin, &end);
	mkMeta_Remove(&run.meta, "trial_range");
	int need3 = 0;
	for (long i = begin; i < end; ++i)
		need3 = need3 || units[i].dim == 3;

	char msg[1024];
	mkRotations rot = { 0, NULL, 0.0 };
	mkCObstacleWork w2, w3;
	memset(&w2, 0, sizeof w2);
	memset(&w3, 0, sizeof w3);
	int failed = need3 && mkRotations_Read(&rot, o.so3, o.orient3, msg, sizeof msg) != 0;
	if (failed)
		mkRun_Fail(&run, "%s", msg);
	else if ((failed = mkCObstacleWork_Init(&w2, &w3, &o) != 0) != 0)
		mkRun_Fail(&run, "out of memory or bad sampling");
	if (!failed) {
		mkCObstacle_Describe(&run.meta, &o, begin, end, nunits, need3 ? &rot : NULL);
		/* Figure geometry first (shard 0 only), so that the main result,
		 * committed last, is never newer than a half-written figure. */
		if (o.fig_obstacles > 0 && run.shard.index == 0)
			failed = mkCObstacle_Figure9(&run, &o, &w2) != 0;
		mkMeta_Set(&run.meta, "content", "C-obstacle timings, one row per (dim, obstacles, trial)");
		if (o.fig_obstacles <= 0 || run.shard.index != 0)
			mkMeta_SetInt(&run.meta, "fig9_obstacles", 0);
	}
	long steps = 0;
	for (long i = begin; i < end; ++i)
		steps += units[i].dim == 2 ? o.headings : rot.count;
	if (!failed && mkRun_OpenCsv(&run, steps) == 0) {
		failed = mkRunUnits(&run, &o, units, begin, end, &rot, &w2, &w3);
		mkClock_LoadAverage(msg, sizeof msg);
		mkMeta_Set(&run.meta, "loadavg_end", msg);
	} else {
		failed = 1;
	}
	mkCObstacleWork_Free(&w2);
	mkCObstacleWork_Free(&w3);
	mkRotations_Free(&rot);
	free(units);
	return mkRun_End(&run, failed);
}
