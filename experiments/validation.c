/* validation.c - the numerical validation of the paper (Sec. 6.1).
 *
 * For each trial, two random bodies are drawn; the contact space
 * B1 (+) (-B2) (or, with --set plus, B1 (+) B2) is computed by the closed
 * form at B1's surface parameters (MK_PARAM_SURFACE), in every form: the
 * normal form (Theorem 1), the gradient form (Theorem 2, stable evaluation)
 * and the paper's printed formulas (MK_FORM_PAPER, the reference of what the
 * published code computes). Each boundary point x with its kissing point k
 * on B1 is checked by mkCheck2_Normal/mkCheck3_Normal (e_implicit,
 * e_gradient, the normal angle, and e_support with B1's normal taken from
 * its parameter), and one raw row per trial and form is written.
 *
 * Draws (paper Sec. 6.1, with the reference code's distributions):
 *  2D: a, b ~ U(0,10), eps ~ U(0.1,1.9), M = rot(2 pi U(0,1)) [1 s; 0 1],
 *      s ~ U(-2,2), for both bodies; N points on B1 (default 1000).
 *  3D: B1 semi-axes ~ U(1,10)^3, B2 ~ U(1,6)^3, eps1, eps2 ~ U(0.1,1.9),
 *      pure rotations; a G x G grid on B1 (default 50). Rotations as the
 *      reference code draws them (--rotations paper: a quaternion with four
 *      U(0,1) entries, normalised; not uniform on SO(3)) or uniform on SO(3)
 *      (--rotations uniform: Shoemake's subgroup algorithm).
 *  Both bodies are centred at the origin (the contact space does not depend
 *  on B2's centre, and B1's only shifts it).
 * Each trial draws from its own random stream (dim << 32 | trial) of the
 * run's seed, in the order body 1 then body 2 as listed above. A draw that
 * the core rejects as invalid (a semi-axis below MK_AXIS_MIN, reachable only
 * through U(0,10) with probability about 1e-10) is drawn again from the same
 * stream and counted in the row's `redraws` column.
 *
 * Aggregates per row: means and maxima over the points whose metrics are all
 * finite; the other points are counted in nonfinite_count (never dropped
 * silently; the reference code's 'omitnan' drops them). */
#include <mink/mink.h>
#include <mink_exp/exp.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MK_SCHEMA_VERSION 2 /* 2: e_support_mean, e_support_max */
#define MK_MAX_REDRAWS 1000

typedef enum mkRotDraw { MK_ROT_PAPER = 0, MK_ROT_UNIFORM = 1 } mkRotDraw;

/* What a row records about one body: enough to rebuild it. */
typedef struct mkBodyRecord {
	int dim;
	double a, b, c, eps1, eps2;
	double angle, shear;        /* 2D pose */
	double qw, qx, qy, qz;      /* 3D pose, unit quaternion */
} mkBodyRecord;

typedef struct mkOptions {
	long trials;
	uint64_t seed;
	int dim2, dim3;
	long n2;      /* points in 2D */
	long grid3;   /* grid side in 3D */
	mkRotDraw rotations;
	mkSet set;
	mkImpl impl;
	const char *out;
	int out_given;
	mkShard shard;
	int force;
} mkOptions;

static const char *const mkRotNames[] = { "paper", "uniform" };
static const char *const mkDimNames[] = { "2", "3", "both" };
static const char *const mkSetNames[] = { "contact", "plus" };
static const mkForm mkForms[] = { MK_FORM_NORMAL, MK_FORM_GRADIENT, MK_FORM_PAPER };
#define MK_FORM_COUNT 3

static void mkUsage(FILE *fp)
{
	fputs(
		"usage: validation [options]\n"
		"The numerical validation of the paper (Sec. 6.1): per trial, two random\n"
		"bodies, the closed-form contact space in the normal, gradient and paper\n"
		"forms, and e_implicit / e_gradient / normal angle per boundary point.\n"
		"One CSV row per trial and form, plus a metadata sidecar <out>.meta.\n"
		"\n"
		"  --trials T          trials per dimension, 1..10000000 (default 100)\n"
		"  --seed S            run seed, 0..2^64-1, decimal or 0x.. (default 2022)\n"
		"  --dim 2|3|both      which experiments (default both)\n"
		"  --n N               2D: points on B1, 1..10000000 (default 1000)\n"
		"  --grid G            3D: G x G grid on B1, 2..3000 (default 50)\n"
		"  --rotations paper|uniform\n"
		"                      3D rotation draw: the reference code's normalised\n"
		"                      positive quaternion, or uniform on SO(3) (default paper)\n"
		"  --set contact|plus  B1 (+) (-B2) or B1 (+) B2 (default contact)\n"
		"  --impl auto|scalar|avx2|avx512\n"
		"                      kernel for the normal and gradient forms (default auto;\n"
		"                      the paper form always runs the scalar reference)\n"
		"  --out PATH          output CSV (default results/validation.csv, or\n"
		"                      results/validation.shard-I-of-N.csv with --shard)\n"
		"  --shard I/N         run only block I (0-based) of N of each dimension's trials\n"
		"  --force             replace an existing output file\n"
		"  --help              this text\n"
		"Progress goes to stderr when it is a terminal (MINK_PROGRESS=always|never).\n",
		fp);
}

static const mkOption mkOptionTable[] = {
	{ "--trials", 1 }, { "--seed", 1 }, { "--dim", 1 }, { "--n", 1 }, { "--grid", 1 },
	{ "--rotations", 1 }, { "--set", 1 }, { "--impl", 1 }, { "--out", 1 }, { "--shard", 1 },
	{ "--force", 0 },
};

/* Parse argv into o. Returns 0 to run, 1 when --help was printed, 2 on a
 * usage error (message printed). */
static int mkParseOptions(int argc, char **argv, mkOptions *o, char *outbuf, size_t outlen)
{
	o->trials = 100;
	o->seed = 2022;
	o->dim2 = o->dim3 = 1;
	o->n2 = 1000;
	o->grid3 = 50;
	o->rotations = MK_ROT_PAPER;
	o->set = MK_SET_CONTACT;
	o->impl = MK_IMPL_AUTO;
	o->out = "results/validation.csv";
	o->out_given = 0;
	o->shard = mkShard_All();
	o->force = 0;

	char msg[512] = "";
	mkArgs args;
	mkArgs_Begin(&args, argc, argv);
	const char *name, *value;
	int choice = 0, bad = 0;
	mkArgsStep step;
	while (!bad && (step = mkArgs_Step(&args, mkOptionTable, MK_COUNT(mkOptionTable), &name, &value,
			msg, sizeof msg)) != MK_ARGS_END) {
		if (step == MK_ARGS_HELP) {
			mkUsage(stdout);
			return 1;
		}
		if (step == MK_ARGS_ERROR) {
			bad = 1;
		} else if (strcmp(name, "--force") == 0) {
			o->force = 1;
		} else if (strcmp(name, "--trials") == 0) {
			bad = mkArg_Long(name, value, 1, 10000000, &o->trials, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--seed") == 0) {
			bad = mkArg_U64(name, value, &o->seed, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--dim") == 0) {
			bad = mkArg_Choice(name, value, mkDimNames, 3, &choice, msg, sizeof msg) != 0;
			o->dim2 = choice != 1;
			o->dim3 = choice != 0;
		} else if (strcmp(name, "--n") == 0) {
			bad = mkArg_Long(name, value, 1, 10000000, &o->n2, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--grid") == 0) {
			bad = mkArg_Long(name, value, 2, 3000, &o->grid3, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--rotations") == 0) {
			bad = mkArg_Choice(name, value, mkRotNames, 2, &choice, msg, sizeof msg) != 0;
			o->rotations = (mkRotDraw)choice;
		} else if (strcmp(name, "--set") == 0) {
			bad = mkArg_Choice(name, value, mkSetNames, 2, &choice, msg, sizeof msg) != 0;
			o->set = choice == 0 ? MK_SET_CONTACT : MK_SET_PLUS;
		} else if (strcmp(name, "--impl") == 0) {
			bad = mkArg_Impl(name, value, &choice, msg, sizeof msg) != 0;
			if (!bad)
				o->impl = (mkImpl)choice;
		} else if (strcmp(name, "--out") == 0) {
			bad = mkArg_Path(name, value, &o->out, msg, sizeof msg) != 0;
			o->out_given = 1;
		} else if (strcmp(name, "--shard") == 0) {
			bad = mkShard_Parse(value, name, &o->shard, msg, sizeof msg) != 0;
		}
	}
	if (bad) {
		fprintf(stderr, "validation: %s\n", msg);
		return 2;
	}
	if (!o->out_given && o->shard.count > 1) {
		snprintf(outbuf, outlen, "results/validation.shard-%d-of-%d.csv", o->shard.index, o->shard.count);
		o->out = outbuf;
	}
	return 0;
}

/* ---- draws --------------------------------------------------------------- */

static int mkDrawBody2(mkRng *r, mkBody2 *body, mkBodyRecord *rec)
{
	memset(rec, 0, sizeof *rec);
	rec->dim = 2;
	rec->a = mkRng_Uniform(r, 0.0, 10.0);
	rec->b = mkRng_Uniform(r, 0.0, 10.0);
	rec->eps1 = mkRng_Uniform(r, 0.1, 1.9);
	rec->angle = 2.0 * MK_PI * mkRng_Unit(r);
	rec->shear = mkRng_Uniform(r, -2.0, 2.0);
	mkShape2 s = { rec->a, rec->b, rec->eps1 };
	mkMat2 M = mkMat2_Mul(mkMat2_Rotation(rec->angle), mkMat2_Shear(rec->shear));
	mkVec2 t = { 0.0, 0.0 };
	*body = mkBody2_Make(s, M, t);
	return mkBody2_IsValid(*body, "body", NULL, 0);
}

static int mkDrawBody3(mkRng *r, double amax, mkRotDraw rot, mkBody3 *body, mkBodyRecord *rec)
{
	memset(rec, 0, sizeof *rec);
	rec->dim = 3;
	rec->a = mkRng_Uniform(r, 1.0, amax);
	rec->b = mkRng_Uniform(r, 1.0, amax);
	rec->c = mkRng_Uniform(r, 1.0, amax);
	rec->eps1 = mkRng_Uniform(r, 0.1, 1.9);
	rec->eps2 = mkRng_Uniform(r, 0.1, 1.9);
	double q[4];
	if (rot == MK_ROT_PAPER) {
		for (int i = 0; i < 4; ++i)
			q[i] = mkRng_Unit(r);
	} else {
		/* Shoemake (1992): uniform on the unit 3-sphere, hence on SO(3). */
		double u1 = mkRng_Unit(r), u2 = mkRng_Unit(r), u3 = mkRng_Unit(r);
		double r1 = sqrt(1.0 - u1), r2 = sqrt(u1);
		q[0] = r2 * cos(2.0 * MK_PI * u3);
		q[1] = r1 * sin(2.0 * MK_PI * u2);
		q[2] = r1 * cos(2.0 * MK_PI * u2);
		q[3] = r2 * sin(2.0 * MK_PI * u3);
	}
	double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
	int ok = 0;
	mkMat3 R = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
	ok = mkMat3_IsFinite(R);
	if (!ok || !(norm > 0.0))
		return 0;
	rec->qw = q[0] / norm;
	rec->qx = q[1] / norm;
	rec->qy = q[2] / norm;
	rec->qz = q[3] / norm;
	mkShape3 s = { rec->a, rec->b, rec->c, rec->eps1, rec->eps2 };
	mkVec3 t = { 0.0, 0.0, 0.0 };
	*body = mkBody3_Make(s, R, t);
	return mkBody3_IsValid(*body, "body", NULL, 0);
}

/* ---- metrics ------------------------------------------------------------- */

typedef struct mkAgg {
	double sum_i, max_i, sum_g, max_g, sum_a, max_a, max_i1, sum_s, max_s;
	long finite, nonfinite;
} mkAgg;

static void mkAgg_Add(mkAgg *g, mkCheck c, int point_finite)
{
	if (!point_finite || !isfinite(c.e_implicit) || !isfinite(c.e_gradient)
		|| !isfinite(c.angle) || !isfinite(c.e_implicit1) || !isfinite(c.e_support)) {
		g->nonfinite += 1;
		return;
	}
	g->finite += 1;
	g->sum_i += c.e_implicit;
	g->sum_g += c.e_gradient;
	g->sum_a += c.angle;
	g->max_i = fmax(g->max_i, c.e_implicit);
	g->max_g = fmax(g->max_g, c.e_gradient);
	g->max_a = fmax(g->max_a, c.angle);
	g->max_i1 = fmax(g->max_i1, c.e_implicit1);
	g->sum_s += fabs(c.e_support);
	g->max_s = fmax(g->max_s, fabs(c.e_support));
}

/* ---- rows ---------------------------------------------------------------- */

static const char *const mkColumns[] = {
	"dim", "trial", "form", "impl", "set", "n_points",
	"e_implicit_mean", "e_implicit_max", "e_gradient_mean", "e_gradient_max",
	"angle_mean", "angle_max", "e_implicit1_max", "e_support_mean", "e_support_max",
	"nonfinite_count", "redraws",
	"b1_a", "b1_b", "b1_c", "b1_eps1", "b1_eps2", "b1_angle", "b1_shear",
	"b1_qw", "b1_qx", "b1_qy", "b1_qz",
	"b2_a", "b2_b", "b2_c", "b2_eps1", "b2_eps2", "b2_angle", "b2_shear",
	"b2_qw", "b2_qx", "b2_qy", "b2_qz"
};
#define MK_COLUMN_COUNT ((int)(sizeof mkColumns / sizeof mkColumns[0]))

static void mkWriteBody(mkCsv *csv, const mkBodyRecord *r)
{
	mkCsv_Double(csv, r->a);
	mkCsv_Double(csv, r->b);
	if (r->dim == 3) mkCsv_Double(csv, r->c); else mkCsv_Empty(csv);
	mkCsv_Double(csv, r->eps1);
	if (r->dim == 3) mkCsv_Double(csv, r->eps2); else mkCsv_Empty(csv);
	if (r->dim == 2) {
		mkCsv_Double(csv, r->angle);
		mkCsv_Double(csv, r->shear);
		for (int i = 0; i < 4; ++i)
			mkCsv_Empty(csv);
	} else {
		mkCsv_Empty(csv);
		mkCsv_Empty(csv);
		mkCsv_Double(csv, r->qw);
		mkCsv_Double(csv, r->qx);
		mkCsv_Double(csv, r->qy);
		mkCsv_Double(csv, r->qz);
	}
}

static void mkWriteRow(mkCsv *csv, int dim, long trial, mkForm form, mkImpl impl, mkSet set,
	long n_points, const mkAgg *g, int redraws, const mkBodyRecord *r1, const mkBodyRecord *r2)
{
	double nf = (double)g->finite;
	mkCsv_Int(csv, dim);
	mkCsv_Int(csv, trial);
	mkCsv_Str(csv, mkForm_Name(form));
	mkCsv_Str(csv, mkImpl_Name(impl));
	mkCsv_Str(csv, mkSet_Name(set));
	mkCsv_Int(csv, n_points);
	/* Means over no finite point are NaN, written "nan". */
	mkCsv_Double(csv, g->finite ? g->sum_i / nf : NAN);
	mkCsv_Double(csv, g->finite ? g->max_i : NAN);
	mkCsv_Double(csv, g->finite ? g->sum_g / nf : NAN);
	mkCsv_Double(csv, g->finite ? g->max_g : NAN);
	mkCsv_Double(csv, g->finite ? g->sum_a / nf : NAN);
	mkCsv_Double(csv, g->finite ? g->max_a : NAN);
	mkCsv_Double(csv, g->finite ? g->max_i1 : NAN);
	mkCsv_Double(csv, g->finite ? g->sum_s / nf : NAN);
	mkCsv_Double(csv, g->finite ? g->max_s : NAN);
	mkCsv_Int(csv, g->nonfinite);
	mkCsv_Int(csv, redraws);
	mkWriteBody(csv, r1);
	mkWriteBody(csv, r2);
	mkCsv_EndRow(csv);
}

/* ---- the experiment ------------------------------------------------------ */

typedef struct mkBuffers {
	double *u2x, *u2y;          /* 2D parameters */
	double *u3x, *u3y, *u3z;    /* 3D parameters */
	double *x, *y, *z, *kx, *ky, *kz;
} mkBuffers;

static double *mkAllocDoubles(long n, int *ok)
{
	double *p = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
	*ok = *ok && p != NULL;
	return p;
}

/* Parameters for both dimensions, outputs for the larger of the two. */
static int mkBuffers_Alloc(mkBuffers *b, long n2, long n3)
{
	int ok = 1;
	long most = n2 > n3 ? n2 : n3;
	b->u2x = mkAllocDoubles(n2, &ok);
	b->u2y = mkAllocDoubles(n2, &ok);
	b->u3x = mkAllocDoubles(n3, &ok);
	b->u3y = mkAllocDoubles(n3, &ok);
	b->u3z = mkAllocDoubles(n3, &ok);
	b->x = mkAllocDoubles(most, &ok);
	b->y = mkAllocDoubles(most, &ok);
	b->z = mkAllocDoubles(most, &ok);
	b->kx = mkAllocDoubles(most, &ok);
	b->ky = mkAllocDoubles(most, &ok);
	b->kz = mkAllocDoubles(most, &ok);
	return ok;
}

static void mkBuffers_Free(mkBuffers *b)
{
	double *all[] = { b->u2x, b->u2y, b->u3x, b->u3y, b->u3z, b->x, b->y, b->z, b->kx, b->ky, b->kz };
	for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
		free(all[i]);
}

static mkImpl mkFormImpl(mkForm form, mkImpl requested)
{
	return form == MK_FORM_PAPER ? MK_IMPL_SCALAR : mkImpl_Resolve(requested);
}

/* One trial of one dimension: draw, compute every form, write its rows.
 * Returns 0, or -1 after printing an error. */
static int mkRunTrial(int dim, long trial, const mkOptions *o, mkCsv *csv, mkBuffers *buf)
{
	long n = dim == 2 ? o->n2 : o->grid3 * o->grid3;
	const double *ux = dim == 2 ? buf->u2x : buf->u3x;
	const double *uy = dim == 2 ? buf->u2y : buf->u3y;
	mkRng rng;
	mkRng_Seed(&rng, o->seed, ((uint64_t)dim << 32) | (uint64_t)trial);
	mkBody2 p1, p2;
	mkBody3 q1, q2;
	memset(&p1, 0, sizeof p1);
	memset(&p2, 0, sizeof p2);
	memset(&q1, 0, sizeof q1);
	memset(&q2, 0, sizeof q2);
	mkBodyRecord r1, r2;
	int redraws = 0;
	for (;;) {
		int ok;
		if (dim == 2) {
			ok = mkDrawBody2(&rng, &p1, &r1);
			ok = mkDrawBody2(&rng, &p2, &r2) && ok;
		} else {
			ok = mkDrawBody3(&rng, 10.0, o->rotations, &q1, &r1);
			ok = mkDrawBody3(&rng, 6.0, o->rotations, &q2, &r2) && ok;
		}
		if (ok)
			break;
		if (++redraws > MK_MAX_REDRAWS) {
			fprintf(stderr, "validation: %dD trial %ld: no valid body pair in %d draws\n",
				dim, trial, MK_MAX_REDRAWS);
			return -1;
		}
	}
	for (int f = 0; f < MK_FORM_COUNT; ++f) {
		mkSumOptions opt = mkSumOptions_Default();
		opt.set = o->set;
		opt.form = mkForms[f];
		opt.param = MK_PARAM_SURFACE;
		opt.impl = mkFormImpl(mkForms[f], o->impl);
		mkResult rc = dim == 2
			? mkSum2_Batch(p1, p2, &opt, ux, uy, (int)n, buf->x, buf->y, buf->kx, buf->ky)
			: mkSum3_Batch(q1, q2, &opt, ux, uy, buf->u3z, (int)n,
				buf->x, buf->y, buf->z, buf->kx, buf->ky, buf->kz);
		if (rc != MK_OK) {
			fprintf(stderr, "validation: %dD trial %ld, form %s: the closed form failed: %s\n",
				dim, trial, mkForm_Name(mkForms[f]), mkResult_Name(rc));
			return -1;
		}
		mkAgg agg;
		memset(&agg, 0, sizeof agg);
		mkMat2 M1i2 = dim == 2 ? mkMat2_Inverse(p1.M) : mkMat2_Identity();
		mkMat3 M1i3 = dim == 3 ? mkMat3_Inverse(q1.M) : mkMat3_Identity();
		for (long i = 0; i < n; ++i) {
			mkCheck c;
			int finite;
			if (dim == 2) {
				mkVec2 x = { buf->x[i], buf->y[i] }, k = { buf->kx[i], buf->ky[i] };
				finite = isfinite(x.x) && isfinite(x.y) && isfinite(k.x) && isfinite(k.y);
				/* B1's normal from its parameter, for e_support */
				mkVec2 n1 = mkMat2_MulTVec(M1i2, mkShape2_PointGradient(p1.shape, (mkVec2){ ux[i], uy[i] }));
				c = mkCheck2_Normal(p1, p2, o->set, x, k, n1);
			} else {
				mkVec3 x = { buf->x[i], buf->y[i], buf->z[i] };
				mkVec3 k = { buf->kx[i], buf->ky[i], buf->kz[i] };
				finite = isfinite(x.x) && isfinite(x.y) && isfinite(x.z)
					&& isfinite(k.x) && isfinite(k.y) && isfinite(k.z);
				mkVec3 n1 = mkMat3_MulTVec(M1i3,
					mkShape3_PointGradient(q1.shape, (mkVec3){ ux[i], uy[i], buf->u3z[i] }));
				c = mkCheck3_Normal(q1, q2, o->set, x, k, n1);
			}
			mkAgg_Add(&agg, c, finite);
		}
		mkWriteRow(csv, dim, trial, mkForms[f], opt.impl, o->set, n, &agg, redraws, &r1, &r2);
	}
	return 0;
}

int main(int argc, char **argv)
{
	mkOptions o;
	char outbuf[128];
	int parsed = mkParseOptions(argc, argv, &o, outbuf, sizeof outbuf);
	if (parsed == 1)
		return 0;
	if (parsed != 0)
		return 2;

	if (mkPath_PrepareOutput("validation", o.out, o.force) != 0)
		return 1;
	char msg[1024];

	mkMeta meta;
	mkMeta_Init(&meta, "validation", MK_SCHEMA_VERSION, argc, argv);
	char text[256];
	mkMeta_SetU64(&meta, "seed", o.seed);
	mkMeta_SetInt(&meta, "trials", o.trials);
	snprintf(text, sizeof text, "%d/%d", o.shard.index, o.shard.count);
	mkMeta_Set(&meta, "shard", text);
	long begin, end;
	mkShard_Range(o.shard, o.trials, &begin, &end);
	snprintf(text, sizeof text, "%ld..%ld", begin, end - 1);
	mkMeta_Set(&meta, "trial_range", end > begin ? text : "none");
	mkMeta_Set(&meta, "dims", o.dim2 && o.dim3 ? "2,3" : o.dim2 ? "2" : "3");
	mkMeta_SetInt(&meta, "n_points_2d", o.n2);
	mkMeta_SetInt(&meta, "grid_3d", o.grid3);
	mkMeta_Set(&meta, "rotation_draw", mkRotNames[o.rotations]);
	mkMeta_Set(&meta, "set", mkSet_Name(o.set));
	mkMeta_Set(&meta, "param", mkParam_Name(MK_PARAM_SURFACE));
	mkMeta_Set(&meta, "forms", "normal,gradient,paper");
	mkMeta_Set(&meta, "impl_requested", mkImpl_Name(o.impl));
	mkMeta_Set(&meta, "impl", mkImpl_Name(mkImpl_Resolve(o.impl)));
	mkMeta_Set(&meta, "rng", "xoshiro256** seeded by splitmix64, one stream per trial: (dim << 32) | trial");
	mkMeta_Set(&meta, "draw_2d", "a,b~U(0,10) eps~U(0.1,1.9) M=rot(2pi U)[1 s;0 1] s~U(-2,2), both bodies");
	mkMeta_Set(&meta, "draw_3d", "B1 a,b,c~U(1,10) B2 a,b,c~U(1,6) eps1,eps2~U(0.1,1.9) rotation only");

	mkCsv csv;
	if (mkCsv_Open(&csv, o.out, mkColumns, MK_COLUMN_COUNT, msg, sizeof msg) != 0) {
		fprintf(stderr, "validation: %s\n", msg);
		mkMeta_Free(&meta);
		return 1;
	}
	mkBuffers buf;
	memset(&buf, 0, sizeof buf);
	long n3 = o.grid3 * o.grid3;
	int ok = mkBuffers_Alloc(&buf, o.dim2 ? o.n2 : 0, o.dim3 ? n3 : 0);
	mkResult rc = MK_OK;
	if (ok && o.dim2)
		rc = mkSample2_Angles((int)o.n2, buf.u2x, buf.u2y);
	if (ok && rc == MK_OK && o.dim3)
		rc = mkSample3_Grid((int)o.grid3, buf.u3x, buf.u3y, buf.u3z);
	if (!ok || rc != MK_OK) {
		if (!ok)
			fprintf(stderr, "validation: out of memory for %ld points\n", o.n2 > n3 ? o.n2 : n3);
		else
			fprintf(stderr, "validation: sampling the parameters failed: %s\n", mkResult_Name(rc));
		mkBuffers_Free(&buf);
		mkCsv_Discard(&csv);
		mkMeta_Free(&meta);
		return 1;
	}

	/* Trial-major order (trial 0 in 2D, then in 3D, then trial 1, ...), so
	 * that the shards' rows, concatenated in shard order, are the rows of the
	 * unsplit run. */
	mkProgress prog;
	mkProgress_Begin(&prog, "validation", (end - begin) * (o.dim2 + o.dim3));
	int failed = 0;
	for (long trial = begin; trial < end && !failed; ++trial) {
		if (o.dim2) {
			failed = mkRunTrial(2, trial, &o, &csv, &buf) != 0;
			mkProgress_Add(&prog, 1);
		}
		if (!failed && o.dim3) {
			failed = mkRunTrial(3, trial, &o, &csv, &buf) != 0;
			mkProgress_Add(&prog, 1);
		}
	}
	mkProgress_End(&prog);
	mkBuffers_Free(&buf);

	return mkCsv_Finish(&csv, &meta, failed, "validation");
}
