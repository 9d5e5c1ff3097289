/* main.c - the `tradeoff` driver: every method's error against its time
 * (what it measures is in tradeoff.h). */
#include "tradeoff.h"

static const char *const mkDimNames[] = { "2", "3", "both" };

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
	mkTradeoffOptions o;
	mkTradeoffOptions_Default(&o);
	int dims = 2;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--dim", "2|3|both", "which dimensions (default both)", &dims, mkDimNames),
		MK_FLAG_REPEAT("--levels", "2d=LIST|3d=LIST", "the --n of each level, rising, comma-separated:\n"
			"2D points 3..1000000, 3D grid side 2..4096 (default\n"
			"2d=8,32,128,512,2048,8192,32768,65536 and 3d=4,8,16,32,64,128,256)", o.levels,
			mkTradeoff_ParseLevels),
		MK_FLAG_DOUBLE("--budget", "SECONDS", "a method's higher levels are not run once the median call\n"
			"of a level takes longer, 0..1e6; 0: no cut (default 1)", &o.budget, 0.0, 1e6),
		MK_FLAG_LONG("--repeats", "R", "timed calls per row (median), 1..64; a call over 50 ms\n"
			"is timed once (default 5)", &o.repeats, 1, 64),
	};
	mkRun run;
	int status = mkRun_Begin(&run, &mkTradeoffDriver, flags, MK_COUNT(flags), argc, argv);
	if (status != MK_RUN_GO)
		return mkRun_Status(status);
	o.trials = run.trials;
	o.seed = run.seed;
	o.dim_on[2] = dims != 1;
	o.dim_on[3] = dims != 0;
	char text[1024];
	for (int dim = 2; dim <= 3; ++dim) {
		size_t len = 0;
		for (int l = 0; l < o.levels[dim].count && len < sizeof text; ++l)
			len += (size_t)snprintf(text + len, sizeof text - len, "%s%d", l ? "," : "", o.levels[dim].v[l]);
		mkMeta_Set(&run.meta, dim == 2 ? "levels_2d" : "levels_3d", o.dim_on[dim] ? text : "off");
	}
	mkMeta_SetDouble(&run.meta, "budget_seconds", o.budget);
	mkMeta_SetInt(&run.meta, "repeats", o.repeats);
	mkMeta_Set(&run.meta, "set", "contact");
	mkMeta_Set(&run.meta, "clock", "CLOCK_MONOTONIC wall time, median of the repeats; one thread");
	mkMeta_Set(&run.meta, "error_measure", "mink/error.h, true area/volume once per pair");
	mkMeta_Set(&run.meta, "draw_2d", "a,b~U(0,10) (redrawn below 1e-3) eps~U(0.1,1.9) M=rot(2pi U)[1 s;0 1] s~U(-2,2)");
	mkMeta_Set(&run.meta, "draw_3d", "B1 axes U(1,10)^3, B2 U(1,6)^3, eps1,eps2~U(0.1,1.9), paper quaternion");
	long units = 0;
	for (int dim = 2; dim <= 3; ++dim)
		units += o.dim_on[dim] ? MK_TRADEOFF_CASES : 0;
	if (mkRun_OpenCsv(&run, units) != 0)
		return mkRun_End(&run, 1);
	int failed = mkTradeoff_Run(&o, &run.csv, &run.meta) != 0;
	mkRun_Step(&run, units);
	return mkRun_End(&run, failed);
}
