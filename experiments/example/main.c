/* main.c - the `example` driver: declare the options, let the harness run. */
#include "example.h"

static const mkDriver mkExampleDriver = {
	"example", "The closed form's roundoff (max e_implicit) on random superellipse pairs.",
	1, mkExample_Columns, MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 10, 1000000, 2022, NULL,
};

int main(int argc, char **argv)
{
	long n = 100;
	mkFlag flags[] = { MK_FLAG_LONG("--n", "N", "points per trial, 3..100000 (default 100)", &n, 3, 100000) };
	mkRun run;
	MK_RUN_BEGIN(&run, &mkExampleDriver, flags, argc, argv);
	mkMeta_SetInt(&run.meta, "n", n);
	if (mkRun_OpenCsv(&run, run.end - run.begin) != 0)
		return mkRun_End(&run, 1);
	int failed = 0;
	for (long t = run.begin; t < run.end && !failed; ++t, mkRun_Step(&run, 1))
		failed = mkExample_Trial(run.seed, t, n, &run.csv) != MK_OK;
	return mkRun_End(&run, failed);
}
