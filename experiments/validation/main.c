/* main.c - the `validation` driver: the numerical validation of the paper
 * (Sec. 6.1); what it computes is in validation.h. */
#include "validation.h"

static const char *const mkDimNames[] = { "2", "3", "both" };

static const mkDriver mkValidationDriver = {
	"validation",
	"The numerical validation of the paper (Sec. 6.1): per trial, two random\n"
	"bodies, the closed-form contact space in the normal, gradient and paper\n"
	"forms, and e_implicit / e_gradient / normal angle per boundary point.\n"
	"One CSV row per trial and form, plus a metadata sidecar <out>.meta.",
	MK_VALIDATION_SCHEMA, mkValidation_Columns,
	MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 100, 10000000, 2022, NULL,
};

int main(int argc, char **argv)
{
	mkValidationOptions o = { 0, 1000, 50, MK_ROT_PAPER, MK_SET_CONTACT, MK_IMPL_AUTO };
	int dims = 2, rotations = MK_ROT_PAPER, set = 0, impl = MK_IMPL_AUTO;
	mkFlag flags[] = {
		MK_FLAG_CHOICE("--dim", "2|3|both", "which experiments (default both)", &dims, mkDimNames),
		MK_FLAG_LONG("--n", "N", "2D: points on B1, 1..10000000 (default 1000)", &o.n2, 1, 10000000),
		MK_FLAG_LONG("--grid", "G", "3D: G x G grid on B1, 2..3000 (default 50)", &o.grid3, 2, 3000),
		MK_FLAG_ROTATIONS(&rotations),
		MK_FLAG_SET("--set", "B1 (+) (-B2) or B1 (+) B2 (default contact)", &set),
		MK_FLAG_IMPL("--impl", "kernel for the normal and gradient forms (default auto;\n"
			"the paper form always runs the scalar reference)", &impl),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkValidationDriver, flags, argc, argv);
	o.seed = run.seed;
	o.rotations = (mkRotDraw)rotations;
	o.set = set == 0 ? MK_SET_CONTACT : MK_SET_PLUS;
	o.impl = (mkImpl)impl;
	int dim2 = dims != 1, dim3 = dims != 0;

	mkMeta *meta = &run.meta;
	mkMeta_Set(meta, "dims", dim2 && dim3 ? "2,3" : dim2 ? "2" : "3");
	mkMeta_SetInt(meta, "n_points_2d", o.n2);
	mkMeta_SetInt(meta, "grid_3d", o.grid3);
	mkMeta_Set(meta, "rotation_draw", mkRotDraw_Names[o.rotations]);
	mkMeta_Set(meta, "set", mkSet_Name(o.set));
	mkMeta_Set(meta, "param", mkParam_Name(MK_PARAM_SURFACE));
	mkMeta_Set(meta, "forms", "normal,gradient,paper");
	mkMeta_Set(meta, "impl_requested", mkImpl_Name(o.impl));
	mkMeta_Set(meta, "impl", mkImpl_Name(mkImpl_Resolve(o.impl)));
	mkMeta_Set(meta, "rng", "xoshiro256** seeded by splitmix64, one stream per trial: (dim << 32) | trial");
	mkMeta_Set(meta, "draw_2d", "a,b~U(0,10) eps~U(0.1,1.9) M=rot(2pi U)[1 s;0 1] s~U(-2,2), both bodies");
	mkMeta_Set(meta, "draw_3d", "B1 a,b,c~U(1,10) B2 a,b,c~U(1,6) eps1,eps2~U(0.1,1.9) rotation only");
	mkPaper_Record(meta, "validation");
	if (mkRun_OpenCsv(&run, (run.end - run.begin) * (dim2 + dim3)) != 0)
		return mkRun_End(&run, 1);

	mkValidationWork work;
	mkResult rc = mkValidationWork_Init(&work, &o, dim2, dim3);
	if (rc != MK_OK) {
		mkRun_Fail(&run, "preparing the parameters failed: %s", mkResult_Name(rc));
		mkValidationWork_Free(&work);
		return mkRun_End(&run, 1);
	}
	/* Trial-major order (trial 0 in 2D, then in 3D, then trial 1, ...), so
	 * that the shards' rows, concatenated in shard order, are the rows of the
	 * unsplit run. */
	int failed = 0;
	for (long trial = run.begin; trial < run.end && !failed; ++trial)
		for (int dim = 2; dim <= 3 && !failed; ++dim)
			if (dim == 2 ? dim2 : dim3) {
				failed = mkValidation_Trial(&o, dim, trial, &work, &run.csv) != 0;
				mkRun_Step(&run, 1);
			}
	mkValidationWork_Free(&work);
	return mkRun_End(&run, failed);
}
