/* main.c - the `collision` driver: the collision-detection benchmark of the
 * paper (Sec. 7.2, Table 3); what it measures is in collision.h. */
#include "collision.h"

static const char *const mkPairChoices[] = { "ellipsoids", "superquadrics", "both" };

static const mkDriver mkCollisionDriver = {
	"collision",
	"The collision-detection benchmark of the paper (Sec. 7.2, Table 3): per trial\n"
	"one random pair of bodies, queried by GJK, ASC (ellipsoids only), Implicit,\n"
	"Common Normal, MinkSum (Ray) and MinkSum (Normal), each timed alone, and\n"
	"judged against a support-function referee. One CSV row per trial and\n"
	"algorithm, plus a metadata sidecar <out>.meta.",
	MK_COLLISION_SCHEMA, mkCollision_Columns,
	MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 10000, 10000000, 2022, NULL,
};

int main(int argc, char **argv)
{
	mkCollisionOptions o = { 0, MK_ROT_PAPER, 1e-3 };
	int pairs = 2, rotations = MK_ROT_PAPER;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--pair", "ellipsoids|superquadrics|both", "which pairs (default both)", &pairs,
			mkPairChoices),
		MK_FLAG_CHOICE("--rotations", "paper|uniform", "rotation draw: the reference code's normalised\n"
			"positive quaternion, or uniform on SO(3) (default paper)", &rotations, mkRotDraw_Names),
		MK_FLAG_DOUBLE("--margin", "M", "referee margin: |min g| <= M is too close to call,\n"
			"0..1 (default 0.001)", &o.margin, 0.0, 1.0),
	};
	mkRun run;
	int status = mkRun_Begin(&run, &mkCollisionDriver, flags, MK_COUNT(flags), argc, argv);
	if (status != MK_RUN_GO)
		return mkRun_Status(status);
	o.seed = run.seed;
	o.rotations = (mkRotDraw)rotations;
	int on[2] = { pairs != 1, pairs != 0 };
	mkCollision_Meta(&run.meta, &o, on[0], on[1]);
	if (mkRun_OpenCsv(&run, (run.end - run.begin) * (on[0] + on[1])) != 0)
		return mkRun_End(&run, 1);

	/* Trial-major order (trial 0's ellipsoids, then its superquadrics, then
	 * trial 1, ...), so that shards concatenate to the unsplit run. */
	int failed = 0;
	for (long trial = run.begin; trial < run.end && !failed; ++trial)
		for (int pair = 0; pair < 2 && !failed; ++pair)
			if (on[pair]) {
				failed = mkCollision_Trial(&o, pair, trial, &run.csv) != 0;
				mkRun_Step(&run, 1);
			}
	return mkRun_End(&run, failed);
}
