/* main.c - the `demos` driver: the geometry of the paper's demonstration
 * figures 1-4; what it writes is in demos.h. */
#include "demos.h"

static const char *const mkFigureNames[] = { "1", "2", "3", "4", "all" };

static const mkDriver mkDemosDriver = {
	"demos",
	"The geometry of the paper's demonstration figures 1-4 (definition vs closed\n"
	"form, the two theorems, 2D superellipse pairs, 3D superquadrics and\n"
	"primitives) as CSV files in the directory <out without .csv>/, one index row\n"
	"per file in <out>, each file with a metadata sidecar.",
	MK_DEMOS_SCHEMA, mkDemos_Columns,
	MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 1, 1, 0,
	"--seed and --trials are accepted for the drivers' common interface: this\n"
	"driver draws nothing and runs each figure once. --shard splits the chosen\n"
	"figures into blocks.",
};

int main(int argc, char **argv)
{
	mkDemosOptions o = { { 0, 1, 1, 1, 1 }, MK_DEMOS_OUTLINE_DEFAULT, MK_IMPL_AUTO };
	int figure = 4, impl = MK_IMPL_AUTO;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--figure", "1|2|3|4|all", "which figures (default all)", &figure, mkFigureNames),
		MK_FLAG_LONG("--outline", "N", "samples per drawn body outline in 2D, 8..100000\n"
			"(default 400; the sums use the paper's N)", &o.outline, 8, 100000),
		MK_FLAG_IMPL("--impl", "closed-form kernel (default auto)", &impl),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkDemosDriver, flags, argc, argv);
	for (int f = 1; f <= 4; ++f)
		o.figure[f] = figure == 4 || figure == f - 1;
	o.impl = (mkImpl)impl;

	/* The chosen figures, in order, are the run's units: a shard is a block
	 * of figures, not of trials (so the sidecar has no trial_range). */
	int units[4], nunits = 0;
	for (int f = 1; f <= 4; ++f)
		if (o.figure[f])
			units[nunits++] = f;
	long begin, end;
	mkShard_Range(run.shard, nunits, &begin, &end);
	mkMeta_Remove(&run.meta, "trial_range");
	mkDemos_Describe(&run.meta, &o, units, begin, end);
	if (mkRun_OpenCsv(&run, end - begin) != 0)
		return mkRun_End(&run, 1);
	int failed = 0;
	for (long i = begin; i < end && !failed; ++i) {
		failed = mkDemos_Figure(&run, &o, units[i]) != 0;
		mkRun_Step(&run, 1);
	}
	/* The index's own sidecar describes the whole run. */
	mkDemos_DescribeIndex(&run.meta);
	return mkRun_End(&run, failed);
}
