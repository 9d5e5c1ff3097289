/* collision.c - the collision-detection benchmark of the paper (Sec. 7.2,
 * Table 3).
 *
 * One trial is one random pair of bodies; every applicable query of
 * mink/collide.h runs on it, each timed alone (CLOCK_MONOTONIC around the
 * query call only, one thread), and one raw row per trial and algorithm is
 * written. A referee independent of all six (the minimum over unit n of
 * h1(n) + h2(-n), support functions only) decides the true answer; trials
 * whose |min g| is within --margin are too close to call and get an empty
 * `agrees` (they are kept and counted, never dropped).
 *
 * Draws (paper Sec. 7.2, the reference code's distributions):
 *  B1: semi-axes ~ U(1,11)^3, eps1, eps2 ~ U(0.1,1.9), centre ~ U(-5,5)^3;
 *  B2: semi-axes ~ U(1,6)^3, same exponents, centre ~ U(5,15)^3;
 *  ellipsoid pairs have eps = (1,1) and draw no exponents. Rotations as
 *  the reference code draws them (--rotations paper: four U(0,1), normalised)
 *  or uniform on SO(3) (Shoemake's subgroup algorithm).
 * Each trial draws from its own stream (pair << 32) | trial of the run's
 * seed (pair 0 ellipsoids, 1 superquadrics), body 1 then body 2, each in
 * the order semi-axes, exponents, centre, rotation.
 *
 * GJK runs on the 10 x 10 grid vertex sets of both bodies (100 vertices
 * each); the vertex sets are built before its timer starts, as the
 * reference code builds its surfaces outside the timed call. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <mink/collide.h>
#include <mink/mink.h>
#include <mink_exp/exp.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MK_SCHEMA_VERSION 1
#define MK_GJK_GRID 10
#define MK_REFEREE_GRID 24


typedef struct mkOptions {
	long trials;
	uint64_t seed;
	int ell, sq;
	mkRotDraw rotations;
	double margin;
	const char *out;
	int out_given;
	mkShard shard;
	int force;
} mkOptions;

static const char *const mkRotNames[] = { "paper", "uniform" };
static const char *const mkPairNames[] = { "ellipsoids", "superquadrics", "both" };

static void mkUsage(FILE *fp)
{
	fputs(
		"usage: collision [options]\n"
		"The collision-detection benchmark of the paper (Sec. 7.2, Table 3): per trial\n"
		"one random pair of bodies, queried by GJK, ASC (ellipsoids only), Implicit,\n"
		"Common Normal, MinkSum (Ray) and MinkSum (Normal), each timed alone, and\n"
		"judged against a support-function referee. One CSV row per trial and\n"
		"algorithm, plus a metadata sidecar <out>.meta.\n"
		"\n"
		"  --pair ellipsoids|superquadrics|both\n"
		"                      which pairs (default both)\n"
		"  --trials T          trials per pair kind, 1..10000000 (default 10000)\n"
		"  --rotations paper|uniform\n"
		"                      rotation draw: the reference code's normalised positive\n"
		"                      quaternion, or uniform on SO(3) (default paper)\n"
		"  --margin M          referee margin: |min g| <= M is too close to call,\n"
		"                      0..1 (default 0.001)\n"
		"  --seed S            run seed, 0..2^64-1, decimal or 0x.. (default 2022)\n"
		"  --out PATH          output CSV (default results/collision.csv, or\n"
		"                      results/collision.shard-I-of-N.csv with --shard)\n"
		"  --shard I/N         run only block I (0-based) of N of the trials\n"
		"  --force             replace an existing output file\n"
		"  --help              this text\n"
		"Progress goes to stderr when it is a terminal (MINK_PROGRESS=always|never).\n",
		fp);
}

static const mkOption mkOptionTable[] = {
	{ "--pair", 1 }, { "--trials", 1 }, { "--rotations", 1 }, { "--margin", 1 }, { "--seed", 1 },
	{ "--out", 1 }, { "--shard", 1 }, { "--force", 0 },
};

/* Parse argv into o. Returns 0 to run, 1 when --help was printed, 2 on a
 * usage error (message printed). */
static int mkParseOptions(int argc, char **argv, mkOptions *o, char *outbuf, size_t outlen)
{
	o->trials = 10000;
	o->seed = 2022;
	o->ell = o->sq = 1;
	o->rotations = MK_ROT_PAPER;
	o->margin = 1e-3;
	o->out = "results/collision.csv";
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
		} else if (strcmp(name, "--pair") == 0) {
			bad = mkArg_Choice(name, value, mkPairNames, 3, &choice, msg, sizeof msg) != 0;
			o->ell = choice != 1;
			o->sq = choice != 0;
		} else if (strcmp(name, "--rotations") == 0) {
			bad = mkArg_Choice(name, value, mkRotNames, 2, &choice, msg, sizeof msg) != 0;
			o->rotations = (mkRotDraw)choice;
		} else if (strcmp(name, "--margin") == 0) {
			bad = mkArg_Double(name, value, 0.0, 1.0, "a number", &o->margin, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--out") == 0) {
			bad = mkArg_Path(name, value, &o->out, msg, sizeof msg) != 0;
			o->out_given = 1;
		} else if (strcmp(name, "--shard") == 0) {
			bad = mkShard_Parse(value, name, &o->shard, msg, sizeof msg) != 0;
		}
	}
	if (bad) {
		fprintf(stderr, "collision: %s\n", msg);
		return 2;
	}
	if (!o->out_given && o->shard.count > 1) {
		snprintf(outbuf, outlen, "results/collision.shard-%d-of-%d.csv", o->shard.index, o->shard.count);
		o->out = outbuf;
	}
	return 0;
}

/* ---- draws --------------------------------------------------------------- */

static int mkDrawBody(mkRng *r, double amax, double clo, double chi, int ellipsoid, mkRotDraw rot,
	mkBody3 *body)
{
	mkShape3 s;
	s.a = mkRng_Uniform(r, 1.0, amax);
	s.b = mkRng_Uniform(r, 1.0, amax);
	s.c = mkRng_Uniform(r, 1.0, amax);
	s.eps1 = ellipsoid ? 1.0 : mkRng_Uniform(r, 0.1, 1.9);
	s.eps2 = ellipsoid ? 1.0 : mkRng_Uniform(r, 0.1, 1.9);
	mkVec3 t;
	t.x = mkRng_Uniform(r, clo, chi);
	t.y = mkRng_Uniform(r, clo, chi);
	t.z = mkRng_Uniform(r, clo, chi);
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
	int ok = 0;
	mkMat3 R = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
	ok = mkMat3_IsFinite(R);
	if (!ok)
		return 0;
	*body = mkBody3_Make(s, R, t);
	return mkBody3_IsValid(*body, "body", NULL, 0);
}

/* ---- rows ---------------------------------------------------------------- */

static const char *const mkColumns[] = {
	"pair", "trial", "algorithm", "seconds", "collide", "residual", "iterations", "success",
	"referee_min_g", "agrees"
};
#define MK_COLUMN_COUNT ((int)(sizeof mkColumns / sizeof mkColumns[0]))

enum { MK_ALG_GJK, MK_ALG_ASC, MK_ALG_IMPLICIT, MK_ALG_COMMON, MK_ALG_RAY, MK_ALG_NORMAL, MK_ALG_COUNT };
static const char *const mkAlgNames[MK_ALG_COUNT] = {
	"GJK", "ASC", "Implicit", "Common Normal", "MinkSum (Ray)", "MinkSum (Normal)"
};

static double mkNow(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Ipopt's tolerance on its scaled NLP error: the paper's success level. */
#define MK_IMPLICIT_TOL MK_COLLIDE_SUCCESS_RESIDUAL

/* One trial of one pair kind: draw, referee, every query, its rows.
 * Returns 0, or -1 after printing an error. */
static int mkRunTrial(int pair, long trial, const mkOptions *o, mkCsv *csv)
{
	mkRng rng;
	mkRng_Seed(&rng, o->seed, ((uint64_t)pair << 32) | (uint64_t)trial);
	int ellipsoid = pair == 0;
	mkBody3 b1, b2;
	int ok = mkDrawBody(&rng, 11.0, -5.0, 5.0, ellipsoid, o->rotations, &b1);
	ok = mkDrawBody(&rng, 6.0, 5.0, 15.0, ellipsoid, o->rotations, &b2) && ok;
	if (!ok) {
		/* The ranges above keep every draw valid; a failure is a bug. */
		fprintf(stderr, "collision: %s trial %ld: invalid body drawn\n", mkPairNames[pair], trial);
		return -1;
	}
	double g = mkCollide_Referee(b1, b2, MK_REFEREE_GRID, NULL);
	int decided = fabs(g) > o->margin, truth = g >= 0.0;

	enum { NV = MK_GJK_GRID * MK_GJK_GRID };
	double ux[NV], uy[NV], uz[NV], x1[NV], y1[NV], z1[NV], x2[NV], y2[NV], z2[NV];
	for (int alg = 0; alg < MK_ALG_COUNT; ++alg) {
		if (alg == MK_ALG_ASC && !ellipsoid)
			continue;
		mkCollide c;
		double t0 = 0.0, t1 = 0.0;
		if (alg == MK_ALG_GJK) {
			if (mkCollide_GridVertices(b1, MK_GJK_GRID, ux, uy, uz, x1, y1, z1) != MK_OK
				|| mkCollide_GridVertices(b2, MK_GJK_GRID, ux, uy, uz, x2, y2, z2) != MK_OK) {
				fprintf(stderr, "collision: the GJK vertex sets failed\n");
				return -1;
			}
			mkVertices3 v1 = { x1, y1, z1, NV }, v2 = { x2, y2, z2, NV };
			t0 = mkNow();
			c = mkCollide_GJK(v1, v2, MK_COLLIDE_LM_MAX_ITER);
			t1 = mkNow();
		} else {
			t0 = mkNow();
			switch (alg) {
			case MK_ALG_ASC: c = mkCollide_ASC(b1, b2); break;
			case MK_ALG_IMPLICIT: c = mkCollide_Implicit(b1, b2, MK_IMPLICIT_TOL); break;
			case MK_ALG_COMMON: c = mkCollide_CommonNormal(b1, b2, MK_COLLIDE_LM_MAX_ITER); break;
			case MK_ALG_RAY: c = mkCollide_MinkRay(b1, b2, MK_COLLIDE_LM_MAX_ITER); break;
			default: c = mkCollide_MinkNormal(b1, b2, MK_COLLIDE_LM_MAX_ITER); break;
			}
			t1 = mkNow();
		}
		int solver = alg == MK_ALG_IMPLICIT || alg == MK_ALG_COMMON || alg == MK_ALG_RAY || alg == MK_ALG_NORMAL;
		mkCsv_Str(csv, mkPairNames[pair]);
		mkCsv_Int(csv, trial);
		mkCsv_Str(csv, mkAlgNames[alg]);
		mkCsv_Double(csv, t1 - t0);
		mkCsv_Int(csv, c.collide);
		if (solver) {
			mkCsv_Double(csv, c.residual);
			mkCsv_Int(csv, c.iterations);
			/* LM: the paper's criterion on the residual norm; Implicit:
			 * Ipopt reports Solve_Succeeded at tol = 1e-10. */
			int success = alg == MK_ALG_IMPLICIT ? c.status == 0 : c.residual < MK_COLLIDE_SUCCESS_RESIDUAL;
			mkCsv_Int(csv, success);
		} else {
			mkCsv_Empty(csv);
			mkCsv_Empty(csv);
			mkCsv_Empty(csv);
		}
		mkCsv_Double(csv, g);
		if (decided)
			mkCsv_Int(csv, c.collide == truth);
		else
			mkCsv_Empty(csv);
		mkCsv_EndRow(csv);
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

	if (mkPath_PrepareOutput("collision", o.out, o.force) != 0)
		return 1;
	char msg[1024];

	mkMeta meta;
	mkMeta_Init(&meta, "collision", MK_SCHEMA_VERSION, argc, argv);
	char text[256];
	mkMeta_SetU64(&meta, "seed", o.seed);
	mkMeta_SetInt(&meta, "trials", o.trials);
	snprintf(text, sizeof text, "%d/%d", o.shard.index, o.shard.count);
	mkMeta_Set(&meta, "shard", text);
	long begin, end;
	mkShard_Range(o.shard, o.trials, &begin, &end);
	snprintf(text, sizeof text, "%ld..%ld", begin, end - 1);
	mkMeta_Set(&meta, "trial_range", end > begin ? text : "none");
	mkMeta_Set(&meta, "pairs", o.ell && o.sq ? "ellipsoids,superquadrics" : o.ell ? "ellipsoids" : "superquadrics");
	mkMeta_Set(&meta, "rotation_draw", mkRotNames[o.rotations]);
	mkMeta_SetDouble(&meta, "referee_margin", o.margin);
	mkMeta_SetInt(&meta, "referee_grid", MK_REFEREE_GRID);
	mkMeta_Set(&meta, "rng", "xoshiro256** seeded by splitmix64, one stream per trial: (pair << 32) | trial, pair 0 ellipsoids 1 superquadrics");
	mkMeta_Set(&meta, "draw", "B1 a,b,c~U(1,11) c~U(-5,5)^3; B2 a,b,c~U(1,6) c~U(5,15)^3; eps1,eps2~U(0.1,1.9) (ellipsoids 1,1)");
	mkMeta_SetInt(&meta, "lm_max_iterations", MK_COLLIDE_LM_MAX_ITER);
	mkMeta_Set(&meta, "lm", "cminpack lmder, central-difference Jacobian (step 1e-6 rad), ftol=xtol=1e-15, gtol=0");
	mkMeta_Set(&meta, "implicit", "Ipopt, limited-memory BFGS Hessian, tol=1e-10, max_iter=1000, constraints Psi^eps1<=1, collide iff distance<=1e-3");
	mkMeta_Set(&meta, "gjk", "libccd ccdGJKIntersect on 10x10 grid vertex sets, max 100 iterations; vertex sets built outside the timer");
	mkMeta_Set(&meta, "asc", "Eigen EigenSolver on A^-1 B (4x4), separated iff two distinct positive roots of det(lambda A + B)");
	mkMeta_Set(&meta, "success", "LM: residual norm < 1e-10; Implicit: Ipopt Solve_Succeeded at tol 1e-10");
	mkMeta_Set(&meta, "timer", "CLOCK_MONOTONIC around the query call only, one thread");
	mkMeta_Set(&meta, "ipopt_version", mkCollide_IpoptVersion());
	mkMeta_Set(&meta, "libccd_version", mkCollide_CcdVersion());
	mkMeta_Set(&meta, "cminpack_version", mkCollide_CminpackVersion());
	mkMeta_Set(&meta, "eigen_version", mkCollide_EigenVersion());

	mkCsv csv;
	if (mkCsv_Open(&csv, o.out, mkColumns, MK_COLUMN_COUNT, msg, sizeof msg) != 0) {
		fprintf(stderr, "collision: %s\n", msg);
		mkMeta_Free(&meta);
		return 1;
	}

	/* Trial-major order (trial 0's ellipsoids, then its superquadrics, then
	 * trial 1, ...), so that shards concatenate to the unsplit run. */
	mkProgress prog;
	mkProgress_Begin(&prog, "collision", (end - begin) * (o.ell + o.sq));
	int failed = 0;
	for (long trial = begin; trial < end && !failed; ++trial) {
		for (int pair = 0; pair < 2 && !failed; ++pair) {
			if ((pair == 0 && !o.ell) || (pair == 1 && !o.sq))
				continue;
			failed = mkRunTrial(pair, trial, &o, &csv) != 0;
			mkProgress_Add(&prog, 1);
		}
	}
	mkProgress_End(&prog);

	return mkCsv_Finish(&csv, &meta, failed, "collision");
}
