/* cmd_bench.c - `mink bench`: ns per boundary point of the closed forms.
 *
 * One measurement times `calls` back-to-back batch calls on the same inputs
 * (the parameter vectors are sampled once, outside the clock, as a C-obstacle
 * loop reuses them) with CLOCK_MONOTONIC, on the calling thread only; after
 * one untimed warm-up call, `reps` measurements are taken and the median is
 * reported. Bodies are random with a fixed seed: 2D with rotation and shear
 * (the paper's validation draw), 3D with rotations.
 *
 * Precision tiers (mkSumOptions.precision): each case and form is timed in
 * the double kernel and in every faster tier alternately, A B A B within
 * one repetition loop, so that both see the same machine state; a tier's
 * row names it in `form` (gradient-f32) and gives, in `speedup`, the median
 * over the repetitions of (double time / tier time) of the same repetition.
 * The double rows have speedup 1. The f32 tier is timed twice: on the same
 * double arrays as the double kernel (form gradient-f32), and on float
 * arrays holding the same parameter vectors rounded to float, through
 * mkSum2f_Batch/mkSum3f_Batch (form gradient-f32io), whose kernels read and
 * write floats. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/mink.h>
#include <mink_exp/clock.h>
#include <mink_exp/rng.h>

#include "cli.h"
#include "commands.h"

static void help(FILE *fp)
{
	fprintf(fp,
		"usage: mink bench [--n2 N] [--n3 N] [--reps R] [--impl auto|scalar|avx2|avx512]\n"
		"                  [--precision all|double|f32] [--seed S]\n"
		"\n"
		"Prints CSV  dim,case,form,n,ns_per_point,speedup  for 2D and 3D x EE (two\n"
		"ellipses/ellipsoids), ES (ellipse/ellipsoid and superellipse/superquadric), SQ (two\n"
		"super shapes) x the normal and gradient forms x the precision tiers: the median over\n"
		"R measurements of the time of one batch call divided by its number of points. A\n"
		"tier other than double is named in the form (gradient-f32) and timed alternately\n"
		"with the double kernel; speedup is the median of double time / tier time over the\n"
		"R pairs. The f32 tier has two rows: on double arrays (gradient-f32, mkSum2_Batch)\n"
		"and on float arrays (gradient-f32io, mkSum2f_Batch: half the memory traffic).\n"
		"Random bodies from a fixed seed: 2D rotated and sheared, 3D rotated. The\n"
		"kernel used is printed on standard error.\n"
		"\n");
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Enough calls that one measurement lasts about 2 ms. */
static int calls_for(long points) { long c = 2000000L / (points > 0 ? points : 1); return c < 1 ? 1 : (int)c; }

typedef struct Bench {
	int dim;
	long n, count;
	double *u[3], *o[6];
	float *fu[3], *fo[6]; /* the same parameter vectors in float, and float outputs */
	int reps;
	mkImpl impl;
} Bench;

/* fio: the float arrays (mkSum2f_Batch) instead of the double ones. */
static double call_s(Bench *b, mkBody2 *p2, mkBody3 *p3, const mkSumOptions *opt, int fio, int calls)
{
	double t0 = mkClock_Wall();
	for (int c = 0; c < calls; ++c) {
		if (b->dim == 2 && fio)
			mkSum2f_Batch(p2[0], p2[1], opt, b->fu[0], b->fu[1], (int)b->count, b->fo[0], b->fo[1], b->fo[2], b->fo[3]);
		else if (b->dim == 2)
			mkSum2_Batch(p2[0], p2[1], opt, b->u[0], b->u[1], (int)b->count, b->o[0], b->o[1], b->o[2], b->o[3]);
		else if (fio)
			mkSum3f_Batch(p3[0], p3[1], opt, b->fu[0], b->fu[1], b->fu[2], (int)b->count,
				b->fo[0], b->fo[1], b->fo[2], b->fo[3], b->fo[4], b->fo[5]);
		else
			mkSum3_Batch(p3[0], p3[1], opt, b->u[0], b->u[1], b->u[2], (int)b->count,
				b->o[0], b->o[1], b->o[2], b->o[3], b->o[4], b->o[5]);
	}
	return (mkClock_Wall() - t0) / calls / (double)b->count * 1e9;
}

static double median(double *t, int n)
{
	qsort(t, (size_t)n, sizeof *t, cmp_double);
	return t[n / 2];
}

/* ns per point of the double kernel (ns[0]) and of the tier `tier` (ns[1],
 * on the float arrays when fio, with the median ratio in *speedup), timed
 * alternately; tier == MK_PRECISION_DOUBLE times the double kernel alone. */
static int measure(Bench *b, mkBody2 *p2, mkBody3 *p3, mkForm form, mkPrecision tier, int fio, double ns[2],
	double *speedup)
{
	mkSumOptions opt[2] = {mkSumOptions_Default(), mkSumOptions_Default()};
	for (int k = 0; k < 2; ++k) {
		opt[k].form = form;
		opt[k].impl = b->impl;
	}
	opt[1].precision = tier;
	int pair = tier != MK_PRECISION_DOUBLE, calls = calls_for(b->count);
	double *t = malloc(3 * (size_t)b->reps * sizeof *t);
	if (!t) return 1;
	double *t1 = t + b->reps, *ratio = t + 2 * b->reps;
	for (int k = 0; k <= pair; ++k) call_s(b, p2, p3, &opt[k], k && fio, 1); /* warm-up */
	for (int r = 0; r < b->reps; ++r) {
		t[r] = call_s(b, p2, p3, &opt[0], 0, calls);
		if (pair) {
			t1[r] = call_s(b, p2, p3, &opt[1], fio, calls);
			ratio[r] = t[r] / t1[r];
		}
	}
	ns[0] = median(t, b->reps);
	ns[1] = pair ? median(t1, b->reps) : ns[0];
	*speedup = pair ? median(ratio, b->reps) : 1.0;
	free(t);
	return 0;
}

int mkCmd_Bench(int argc, char **argv)
{
	long n2 = 1000, n3 = 50, reps = 21, seed = 1;
	int impl = MK_IMPL_AUTO, precision = -1;
	static const char *const precisionNames[] = { "all", "double", "f32" };
	int tiers = 0;
	mkFlag flags[] = {
		MK_FLAG_LONG("--n2", "N", "2D points per call (default 1000, in [3, 1000000])", &n2, 3, 1000000),
		MK_FLAG_LONG("--n3", "N", "3D grid side, N x N points per call (default 50, in [3, 1000])", &n3, 3, 1000),
		MK_FLAG_LONG("--reps", "R", "measurements per row (default 21, in [1, 10000])", &reps, 1, 10000),
		MK_FLAG_IMPL("--impl", "kernel (default auto: the widest this CPU runs)", &impl),
		MK_FLAG_CHOICE("--precision", "all|double|f32", "tiers to time (default all: double and f32)", &tiers,
			precisionNames),
		MK_FLAG_LONG("--seed", "S", "seed of the random bodies (default 1)", &seed, 0, 2147483647L),
	};
	int rc = mkCli_Parse("bench", flags, MK_COUNT(flags), argc, argv, help);
	if (rc != MK_CLI_GO)
		return rc;
	if (tiers > 0)
		precision = mkPrecision_Parse(precisionNames[tiers]);
	fprintf(stderr, "mink bench: kernel %s\n", mkImpl_Name(mkImpl_Resolve((mkImpl)impl)));
	mkRng rng;
	mkRng_Seed(&rng, (uint64_t)seed, 0);
	printf("dim,case,form,n,ns_per_point,speedup\n");
	static const char *cases[3] = {"EE", "ES", "SQ"};
	for (int dim = 2; dim <= 3; ++dim) {
		Bench b = {0};
		b.dim = dim;
		b.n = dim == 2 ? n2 : n3;
		b.count = dim == 2 ? n2 : n3 * n3;
		b.reps = (int)reps;
		b.impl = (mkImpl)impl;
		int ok = 1;
		for (int k = 0; k < 3; ++k) ok &= (b.u[k] = malloc((size_t)b.count * sizeof(double))) != NULL;
		for (int k = 0; k < 6; ++k) ok &= (b.o[k] = malloc((size_t)b.count * sizeof(double))) != NULL;
		for (int k = 0; k < 3; ++k) ok &= (b.fu[k] = malloc((size_t)b.count * sizeof(float))) != NULL;
		for (int k = 0; k < 6; ++k) ok &= (b.fo[k] = malloc((size_t)b.count * sizeof(float))) != NULL;
		if (!ok) {
			fprintf(stderr, "mink bench: out of memory\n");
			return 1;
		}
		if (dim == 2) mkSample2_Angles((int)b.count, b.u[0], b.u[1]);
		else mkSample3_Grid((int)b.n, b.u[0], b.u[1], b.u[2]);
		for (int k = 0; k < dim; ++k)
			for (long i = 0; i < b.count; ++i) b.fu[k][i] = (float)b.u[k][i];
		for (int c = 0; c < 3; ++c) {
			mkBody2 p2[2];
			mkBody3 p3[2];
			for (int j = 0; j < 2; ++j) {
				int super = (c == 1 && j == 1) || c == 2;
				double e1 = super ? mkRng_Uniform(&rng, 0.1, 1.9) : 1.0;
				double e2 = super ? mkRng_Uniform(&rng, 0.1, 1.9) : 1.0;
				if (dim == 2) {
					mkShape2 s = {mkRng_Uniform(&rng, 1, 11), mkRng_Uniform(&rng, 1, 11), e1};
					mkMat2 M = mkMat2_Mul(mkMat2_Rotation(2 * MK_PI * mkRng_Unit(&rng)),
						mkMat2_Shear(mkRng_Uniform(&rng, -2, 2)));
					mkVec2 t = {0, 0};
					p2[j] = mkBody2_Make(s, M, t);
				} else {
					mkShape3 s = {mkRng_Uniform(&rng, 1, 10), mkRng_Uniform(&rng, 1, 10), mkRng_Uniform(&rng, 1, 10), e1, e2};
					mkMat3 M = mkMat3_FromQuat(mkRng_Uniform(&rng, -1, 1), mkRng_Uniform(&rng, -1, 1),
						mkRng_Uniform(&rng, -1, 1), mkRng_Uniform(&rng, -1, 1));
					mkVec3 t = {0, 0, 0};
					p3[j] = mkBody3_Make(s, M, t);
				}
			}
			for (int f = MK_FORM_NORMAL; f <= MK_FORM_GRADIENT; ++f) {
				/* The double row, then each faster tier timed against it. */
				for (int row = 0; row < 3; ++row) { /* double, f32, f32 on float arrays */
					int tier = row == 0 ? MK_PRECISION_DOUBLE : MK_PRECISION_F32, fio = row == 2;
					if (precision >= 0 && tier != precision) continue;
					double ns[2], speedup;
					if (measure(&b, p2, p3, (mkForm)f, (mkPrecision)tier, fio, ns, &speedup)) {
						fprintf(stderr, "mink bench: out of memory\n");
						return 1;
					}
					int holds = dim == 2 ? mkSum2_TierHolds(p2[0], p2[1], &(mkSumOptions){MK_SET_CONTACT,
						(mkForm)f, MK_PARAM_SURFACE, (mkImpl)impl, (mkPrecision)tier})
						: mkSum3_TierHolds(p3[0], p3[1], &(mkSumOptions){MK_SET_CONTACT,
						(mkForm)f, MK_PARAM_SURFACE, (mkImpl)impl, (mkPrecision)tier});
					if (!holds && !fio)
						fprintf(stderr, "mink bench: %dD %s %s: outside the %s tier's domain, the double kernel ran\n",
							dim, cases[c], mkForm_Name((mkForm)f), mkPrecision_Name((mkPrecision)tier));
					if (tier == MK_PRECISION_DOUBLE)
						printf("%d,%s,%s,%ld,%.3f,1\n", dim, cases[c], mkForm_Name((mkForm)f), b.count, ns[0]);
					else
						printf("%d,%s,%s-%s%s,%ld,%.3f,%.3f\n", dim, cases[c], mkForm_Name((mkForm)f),
							mkPrecision_Name((mkPrecision)tier), fio ? "io" : "", b.count, ns[1], speedup);
					fflush(stdout);
				}
			}
		}
		for (int k = 0; k < 3; ++k) free(b.u[k]);
		for (int k = 0; k < 6; ++k) free(b.o[k]);
		for (int k = 0; k < 3; ++k) free(b.fu[k]);
		for (int k = 0; k < 6; ++k) free(b.fo[k]);
	}
	return 0;
}
