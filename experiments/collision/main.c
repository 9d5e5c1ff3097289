/* main.c - the `collision` driver: every entry of the collider registry on
 * the paper's pairs (Sec. 7.2, Table 3) and on near-touching and deeply
 * overlapping ones; what it measures is in collision.h. */
#include "collision.h"

#include <stdio.h>
#include <stdlib.h>

static const char *const mkPairChoices[] = { "ellipsoids", "superquadrics", "near", "deep", "both", "all" };

static const mkDriver mkCollisionDriver = {
	"collision",
	"Collision and distance (paper Sec. 7.2, Table 3): per trial and pair kind one\n"
	"pair of bodies, queried by every entry of the collider registry that takes it\n"
	"(prepare untimed, run timed alone) and judged against the registry's referee.\n"
	"One CSV row per trial and entry, plus a metadata sidecar <out>.meta.",
	MK_COLLISION_SCHEMA, mkCollision_Columns,
	MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 10000, 10000000, 2022,
	"Pair kinds: ellipsoids and superquadrics (the paper's draws), near (B2 moved so\n"
	"that the referee's signed distance is +-1e-1 .. +-1e-6 of the size) and deep\n"
	"(overlapping centres); --pair both = the first two, all = all four.\n"
	"Status: separated|touching|overlapping|failed, or skipped past a --limit.\n"
	"The batch entries minksum-batch-<mode> answer each kind's pairs in chunks of\n"
	"64 trials, one mkCollide3_Batch call per mode; seconds is per pair (amortised).",
};

int main(int argc, char **argv)
{
	mkCollisionOptions o = { 0, MK_ROT_PAPER, 1e-9, 0, { NULL }, { 0 } };
	int pairs = 5, rotations = MK_ROT_PAPER;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--pair", "ellipsoids|superquadrics|near|deep|both|all",
			"which pair kinds (default all)", &pairs, mkPairChoices),
		MK_FLAG_ROTATIONS(&rotations),
		MK_FLAG_DOUBLE("--margin", "M", "statuses are compared where |referee sd| > M * scale,\n"
			"0..1 (default 1e-9)", &o.margin, 0.0, 1.0),
		MK_FLAG_REPEAT("--limit", "NAME=N", "run entry NAME on trials < N only (later trials: rows\n"
			"with status skipped); repeatable (default none)", &o, mkCollision_ParseLimit),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkCollisionDriver, flags, argc, argv);
	o.seed = run.seed;
	o.rotations = (mkRotDraw)rotations;
	int on[MK_COLLISION_KINDS], kinds = 0;
	for (int k = 0; k < MK_COLLISION_KINDS; ++k) {
		on[k] = pairs == k || pairs == 5 || (pairs == 4 && k < 2);
		kinds += on[k];
	}
	mkCollision_Meta(&run.meta, &o, on);
	if (mkRun_OpenCsv(&run, (run.end - run.begin) * kinds) != 0)
		return mkRun_End(&run, 1);

	/* Trial-major order (trial 0 of every kind, then trial 1, ...), so that
	 * shards concatenate to the unsplit run; each chunk of trials drawn and
	 * answered by the batch entries first (chunks aligned to trial numbers,
	 * so that a shard's pairs and answers are the unsplit run's). */
	mkCollisionChunk *chunk = malloc(sizeof *chunk);
	int failed = chunk == NULL;
	if (failed)
		fprintf(stderr, "collision: out of memory\n");
	for (long trial = run.begin; trial < run.end && !failed; ++trial) {
		if (trial == run.begin || trial % MK_COLLISION_CHUNK == 0) {
			long end = (trial / MK_COLLISION_CHUNK + 1) * MK_COLLISION_CHUNK;
			failed = mkCollision_Chunk(&o, on, trial, end < run.end ? end : run.end, chunk) != 0;
		}
		for (int k = 0; k < MK_COLLISION_KINDS && !failed; ++k)
			if (on[k]) {
				failed = mkCollision_Trial(&o, k, trial, chunk, &run.csv) != 0;
				mkRun_Step(&run, 1);
			}
	}
	free(chunk);
	return mkRun_End(&run, failed);
}
