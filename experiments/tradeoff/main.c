/* main.c - the `tradeoff` driver: every method's error against its time
 * (what it measures is in tradeoff.h). */
#include "tradeoff.h"

static const mkDriver mkTradeoffDriver = {
	"tradeoff",
	"Speed against accuracy: every registry method (and two more samplings of the\n"
	"closed form) on T random EE, ES and SQ pairs in 2D and 3D over a range of\n"
	"resolutions; per row the median time of repeated calls and the error of the\n"
	"points against the true contact set (mink/error.h), with both bodies as SPEC\n"
	"text, so that `mink sum` can re-check a registry method's row alone.",
	MK_TRADEOFF_SCHEMA, mkTradeoff_Columns, MK_SHARED_TRIALS | MK_SHARED_SEED, 20, 100000, 2022,
	"The pairs of a (dim, case) are trials 0..T-1; every method and level runs on them.",
};

int main(int argc, char **argv)
{
	mkRun run;
	mkTradeoffOptions o;
	mkTradeoffOptions_Default(&o);
	static const char *const dim_names[] = { "2", "3", "both" };
	int dims = 2;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--dim", "2|3|both", "which dimensions (default both)", &dims, dim_names),
		MK_FLAG_REPEAT("--levels", "2d=LIST|3d=LIST", "the --n of each level, rising, comma-separated:\n"
			"2D points 3..1000000, 3D grid side 2..4096 (default\n"
			"2d=8,32,128,512,2048,8192,32768,65536 and 3d=4,8,16,32,64,128,256)", &o,
			mkTradeoff_ParseLevels),
		MK_FLAG_DOUBLE("--budget", "SECONDS", "one untimed call opens each level; when it takes longer,\n"
			"that level and the higher ones of the method are not run,\n"
			"0..1e6; 0: no cut and no such call (default 1)", &o.budget, 0.0, 1e6),
		MK_FLAG_LONG("--repeats", "R", "timed calls per row (median), 1..64; a call over 50 ms\n"
			"is timed once (default 5)", &o.repeats, 1, 64),
		MK_FLAG_TEXT("--methods", "LIST", "comma-separated registry names and closed-normal@normal-angles,\n"
			"closed-normal@spaced, exec:NAME=COMMAND (external methods), @FILE (a methods\n"
			"file: docs/compare.md), or all (default all)", o.curve_on, mkTradeoff_ParseMethods),
		MK_FLAG_LONG("--threads", "T", "threads for the error measure and the true areas/volumes,\n"
			"1..64; the timed calls always run alone (default 2)", &o.threads, 1, MK_TRADEOFF_THREADS_MAX),
	};
	MK_RUN_BEGIN(&run, &mkTradeoffDriver, flags, argc, argv);
	mkTradeoff_Start(&o, &run, dims, &run.meta);
	long units = MK_TRADEOFF_CASES * (o.dim_on[2] + o.dim_on[3]);
	if (mkRun_OpenCsv(&run, units) != 0)
		return mkRun_End(&run, 1);
	int failed = mkTradeoff_Run(&o, &run.csv, &run.meta) != 0;
	mkRun_Step(&run, units);
	return mkRun_End(&run, failed);
}
