/* main.c - the `extremes` driver: the numerical-stability map of every
 * registry method over the extremes grid (extremes.h). */
#include "extremes.h"

#include <stdio.h>
#include <stdlib.h>

static const char *const mkGridNames[] = { "quick", "full" };
static const char *const mkDimNames[] = { "2", "3", "both" };
static const char *const mkSetNames[] = { "contact", "plus", "both" };

static const mkDriver mkExtremesDriver = {
	"extremes",
	"Numerical stability at the extremes: every registry method that accepts the\n"
	"pair, on every cell of the extremes grid (exponents towards both ends of their\n"
	"range, semi-axis ratios 1..1e6, shears 0..100, size ratios 1e-6..1e6,\n"
	"translations up to 1e9), scored by the 256-bit MPFR reference: the largest\n"
	"distance of an output point from the exact boundary, beside the problem's\n"
	"condition. One row per (cell, set, method).",
	MK_EXTREMES_SCHEMA, mkExtremes_Columns, MK_SHARED_SHARD, 1, 1, 0,
	"A run's units are the (dim, cell) pairs, 2D first: --shard splits them.\n"
	"Methods that do not accept a pair (geometric off ellipses, edge-sort in 3D)\n"
	"have no row; the sidecar counts them (rejected_pairs).",
};

static void mkExtremes_Step(void *run)
{
	mkRun_Step(run, 1);
}

int main(int argc, char **argv)
{
	mkExtremesOptions o;
	mkExtremesOptions_Default(&o);
	int grid = 0, dims = 2, sets = 2;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--grid", "quick|full", "the grid: 33 cells per dimension or 241 (default quick)", &grid,
			mkGridNames),
		MK_FLAG_CHOICE("--dim", "2|3|both", "which dimensions (default both)", &dims, mkDimNames),
		MK_FLAG_CHOICE("--set", "contact|plus|both", "which sets (default both)", &sets, mkSetNames),
		MK_FLAG_TEXT("--methods", "LIST", "comma-separated registry names, exec:NAME=COMMAND\n"
			"(external methods), @FILE (a methods file: docs/compare.md), or all\n"
			"(default all)", o.method_on,
			mkExtremes_ParseMethods),
		MK_FLAG_LONG("--n2", "N", "closed forms in 2D: parameters on body 1, 1..100000 (default 64)", &o.n2, 1,
			100000),
		MK_FLAG_LONG("--n3", "N", "closed forms in 3D: grid side on body 1, 2..1000 (default 5)", &o.n3, 2, 1000),
		MK_FLAG_LONG("--s2", "N", "sampled methods in 2D: samples per body, 3..4096 (default 64)", &o.s2, 3, 4096),
		MK_FLAG_LONG("--s3", "N", "sampled methods in 3D: grid side per body, 3..64 (default 5)", &o.s3, 3, 64),
		MK_FLAG_LONG("--cells", "C", "only the first C cells of each dimension, 1..100000 (default all)", &o.cells,
			1, 100000),
		MK_FLAG_LONG("--threads", "K", "cells run at once, 1..64 (default 2); the rows do not depend on it", &o.threads,
			1, 64),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkExtremesDriver, flags, argc, argv);
	o.grid = grid ? REF_GRID_FULL : REF_GRID_QUICK;
	o.dim_on[2] = dims != 1;
	o.dim_on[3] = dims != 0;
	o.set_on[0] = sets != 1;
	o.set_on[1] = sets != 0;
	char msg[256];
	if (mkExtremes_Check(&o, msg, sizeof msg) != 0) {
		mkRun_Fail(&run, "%s", msg);
		return mkRun_End(&run, 1);
	}
	long total = mkExtremes_Units(&o, NULL, NULL), begin, end;
	int *dim = malloc((size_t)(total > 0 ? total : 1) * 2 * sizeof *dim);
	if (!dim) {
		mkRun_Fail(&run, "out of memory");
		return mkRun_End(&run, 1);
	}
	mkExtremes_Units(&o, dim, dim + total);
	mkShard_Range(run.shard, total, &begin, &end);
	char range[64];
	snprintf(range, sizeof range, "%ld..%ld of %ld (dim, cell) units", begin, end - 1, total);
	mkMeta_Set(&run.meta, "trial_range", end > begin ? range : "none");
	/* Nothing is random but the condition's one-ulp draws: seed 1000 + cell. */
	mkMeta_SetU64(&run.meta, "seed", 1000);
	mkMeta_SetInt(&run.meta, "trials", total);
	mkMeta_Set(&run.meta, "condition_draws", "3 draws per (cell, set), generator seed 1000 + cell index");
	mkMeta_Set(&run.meta, "grid", mkGridNames[grid]);
	mkMeta_SetInt(&run.meta, "n2", o.n2);
	mkMeta_SetInt(&run.meta, "n3", o.n3);
	mkMeta_SetInt(&run.meta, "s2", o.s2);
	mkMeta_SetInt(&run.meta, "s3", o.s3);
	mkMeta_SetDouble(&run.meta, "keep_threshold", MK_EXTREMES_KEEP);
	mkExtremesTally tally = { 0, 0, 0, 0, 0, 0 };
	mkMeta_SetInt(&run.meta, "threads", o.threads);
	int failed = mkRun_OpenCsv(&run, end - begin) != 0;
	if (!failed)
		failed = mkExtremes_RunUnits(&o, dim + begin, dim + total + begin, end - begin, &run.csv, &tally,
			mkExtremes_Step, &run) != 0;
	mkMeta_SetInt(&run.meta, "error_rows", tally.failed);
	mkMeta_SetInt(&run.meta, "nonfinite_points", tally.nonfinite);
	mkMeta_SetInt(&run.meta, "rejected_pairs", tally.rejected);
	mkMeta_SetInt(&run.meta, "score_searches", tally.searches);
	mkMeta_SetInt(&run.meta, "score_searches_reused", tally.reused);
	free(dim);
	return mkRun_End(&run, failed);
}
