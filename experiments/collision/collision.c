/* collision.c - the collision-detection benchmark: draws, the timed
 * queries, rows and sidecar (what is measured is in collision.h), and its
 * section of the tables. */
#include "collision.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MK_GJK_GRID 10
#define MK_REFEREE_GRID 24
#define MK_CELL_MAX 256

const char *const mkCollision_Columns[] = {
	"pair", "trial", "algorithm", "seconds", "collide", "residual", "iterations", "success",
	"referee_min_g", "agrees", NULL
};
const char *const mkCollision_PairNames[2] = { "ellipsoids", "superquadrics" };

enum { MK_ALG_GJK, MK_ALG_ASC, MK_ALG_IMPLICIT, MK_ALG_COMMON, MK_ALG_RAY, MK_ALG_NORMAL, MK_ALG_COUNT };
static const char *const mkAlgNames[MK_ALG_COUNT] = {
	"GJK", "ASC", "Implicit", "Common Normal", "MinkSum (Ray)", "MinkSum (Normal)"
};

/* Ipopt's tolerance on its scaled NLP error: the paper's success level. */
#define MK_IMPLICIT_TOL MK_COLLIDE_SUCCESS_RESIDUAL

void mkCollision_Meta(mkMeta *meta, const mkCollisionOptions *o, int ellipsoids, int superquadrics)
{
	mkMeta_Set(meta, "pairs", ellipsoids && superquadrics ? "ellipsoids,superquadrics"
		: ellipsoids ? "ellipsoids" : "superquadrics");
	mkMeta_Set(meta, "rotation_draw", mkRotDraw_Names[o->rotations]);
	mkMeta_SetDouble(meta, "referee_margin", o->margin);
	mkMeta_SetInt(meta, "referee_grid", MK_REFEREE_GRID);
	mkMeta_Set(meta, "rng", "xoshiro256** seeded by splitmix64, one stream per trial: (pair << 32) | trial, pair 0 ellipsoids 1 superquadrics");
	mkMeta_Set(meta, "draw", "B1 a,b,c~U(1,11) c~U(-5,5)^3; B2 a,b,c~U(1,6) c~U(5,15)^3; eps1,eps2~U(0.1,1.9) (ellipsoids 1,1)");
	mkMeta_SetInt(meta, "lm_max_iterations", MK_COLLIDE_LM_MAX_ITER);
	static const char *const fixed[][2] = {
		{ "lm", "cminpack lmder, central-difference Jacobian (step 1e-6 rad), ftol=xtol=1e-15, gtol=0" },
		{ "implicit", "Ipopt, limited-memory BFGS Hessian, tol=1e-10, max_iter=1000, constraints Psi^eps1<=1, collide iff distance<=1e-3" },
		{ "gjk", "libccd ccdGJKIntersect on 10x10 grid vertex sets, max 100 iterations; vertex sets built outside the timer" },
		{ "asc", "Eigen EigenSolver on A^-1 B (4x4), separated iff two distinct positive roots of det(lambda A + B)" },
		{ "success", "LM: residual norm < 1e-10; Implicit: Ipopt Solve_Succeeded at tol 1e-10" },
		{ "timer", "CLOCK_MONOTONIC around the query call only, one thread" },
	};
	mkMeta_SetPairs(meta, fixed, MK_COUNT(fixed));
	mkMeta_Set(meta, "ipopt_version", mkCollide_IpoptVersion());
	mkMeta_Set(meta, "libccd_version", mkCollide_CcdVersion());
	mkMeta_Set(meta, "cminpack_version", mkCollide_CminpackVersion());
	mkMeta_Set(meta, "eigen_version", mkCollide_EigenVersion());
}

/* ---- draws ------------------------------------------------------------------ */

static int mkDrawBody(mkRng *r, double amax, double clo, double chi, int ellipsoid, mkRotDraw rot,
	mkBody3 *body)
{
	double elo = ellipsoid ? 1.0 : 0.1, ehi = ellipsoid ? 1.0 : 1.9;
	mkShapeRange3 range = { { 1.0, amax }, { 1.0, amax }, { 1.0, amax }, { elo, ehi }, { elo, ehi } };
	mkShape3 s = mkDraw_Shape3(r, &range);
	mkVec3 t;
	t.x = mkRng_Uniform(r, clo, chi);
	t.y = mkRng_Uniform(r, clo, chi);
	t.z = mkRng_Uniform(r, clo, chi);
	mkMat3 R = mkDraw_Rotation3(r, rot);
	if (!mkMat3_IsFinite(R))
		return 0;
	*body = mkBody3_Make(s, R, t);
	return mkBody3_IsValid(*body, "body", NULL, 0);
}

/* ---- the queries ------------------------------------------------------------- */

/* One timed query (GJK on the grid vertex sets, built outside the timer).
 * Returns 0, or -1 when the vertex sets fail. */
static int mkQuery(int alg, mkBody3 b1, mkBody3 b2, mkCollide *c, double *seconds)
{
	enum { NV = MK_GJK_GRID * MK_GJK_GRID };
	double ux[NV], uy[NV], uz[NV], x1[NV], y1[NV], z1[NV], x2[NV], y2[NV], z2[NV];
	mkVertices3 v1 = { x1, y1, z1, NV }, v2 = { x2, y2, z2, NV };
	if (alg == MK_ALG_GJK && (mkCollide_GridVertices(b1, MK_GJK_GRID, ux, uy, uz, x1, y1, z1) != MK_OK
			|| mkCollide_GridVertices(b2, MK_GJK_GRID, ux, uy, uz, x2, y2, z2) != MK_OK))
		return -1;
	double t0 = mkClock_Wall();
	switch (alg) {
	case MK_ALG_GJK: *c = mkCollide_GJK(v1, v2, MK_COLLIDE_LM_MAX_ITER); break;
	case MK_ALG_ASC: *c = mkCollide_ASC(b1, b2); break;
	case MK_ALG_IMPLICIT: *c = mkCollide_Implicit(b1, b2, MK_IMPLICIT_TOL); break;
	case MK_ALG_COMMON: *c = mkCollide_CommonNormal(b1, b2, MK_COLLIDE_LM_MAX_ITER); break;
	case MK_ALG_RAY: *c = mkCollide_MinkRay(b1, b2, MK_COLLIDE_LM_MAX_ITER); break;
	default: *c = mkCollide_MinkNormal(b1, b2, MK_COLLIDE_LM_MAX_ITER); break;
	}
	*seconds = mkClock_Wall() - t0;
	return 0;
}

/* The row of one query; decided: the referee's answer (truth) counts. */
static void mkWriteRow(mkCsv *csv, int pair, long trial, int alg, double seconds, const mkCollide *c, double g,
	int decided, int truth)
{
	int solver = alg == MK_ALG_IMPLICIT || alg == MK_ALG_COMMON || alg == MK_ALG_RAY || alg == MK_ALG_NORMAL;
	mkCsv_Str(csv, mkCollision_PairNames[pair]);
	mkCsv_Int(csv, trial);
	mkCsv_Str(csv, mkAlgNames[alg]);
	mkCsv_Double(csv, seconds);
	mkCsv_Int(csv, c->collide);
	if (solver) {
		mkCsv_Double(csv, c->residual);
		mkCsv_Int(csv, c->iterations);
		/* LM: the paper's criterion on the residual norm; Implicit: Ipopt
		 * reports Solve_Succeeded at tol = 1e-10. */
		mkCsv_Int(csv, alg == MK_ALG_IMPLICIT ? c->status == 0 : c->residual < MK_COLLIDE_SUCCESS_RESIDUAL);
	} else {
		mkCsv_Empty(csv);
		mkCsv_Empty(csv);
		mkCsv_Empty(csv);
	}
	mkCsv_Double(csv, g);
	if (decided)
		mkCsv_Int(csv, c->collide == truth);
	else
		mkCsv_Empty(csv);
	mkCsv_EndRow(csv);
}

int mkCollision_Trial(const mkCollisionOptions *o, int pair, long trial, mkCsv *csv)
{
	mkRng rng;
	mkRng_Seed(&rng, o->seed, ((uint64_t)pair << 32) | (uint64_t)trial);
	int ellipsoid = pair == 0;
	mkBody3 b1, b2;
	int ok = mkDrawBody(&rng, 11.0, -5.0, 5.0, ellipsoid, o->rotations, &b1);
	ok = mkDrawBody(&rng, 6.0, 5.0, 15.0, ellipsoid, o->rotations, &b2) && ok;
	if (!ok) {
		/* The ranges above keep every draw valid; a failure is a bug. */
		fprintf(stderr, "collision: %s trial %ld: invalid body drawn\n", mkCollision_PairNames[pair], trial);
		return -1;
	}
	double g = mkCollide_Referee(b1, b2, MK_REFEREE_GRID, NULL);
	int decided = fabs(g) > o->margin, truth = g >= 0.0;
	for (int alg = 0; alg < MK_ALG_COUNT; ++alg) {
		if (alg == MK_ALG_ASC && !ellipsoid)
			continue;
		mkCollide c;
		double seconds = 0.0;
		if (mkQuery(alg, b1, b2, &c, &seconds) != 0) {
			fprintf(stderr, "collision: the GJK vertex sets failed\n");
			return -1;
		}
		mkWriteRow(csv, pair, trial, alg, seconds, &c, g, decided, truth);
	}
	return 0;
}

/* ---- the summary -------------------------------------------------------------- */

/* Letters and digits only, lower case: "MinkSum (Ray)" -> "minksumray", so
 * that spellings of one algorithm meet. */
static void mkSquash(const char *s, char *out, size_t len)
{
	size_t n = 0;
	for (; *s && n + 1 < len; ++s)
		if (isalnum((unsigned char)*s))
			out[n++] = (char)tolower((unsigned char)*s);
	out[n] = '\0';
}

static int mkCompareDouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* What one (pair, algorithm) did: its times (ms) and verdict counts. */
typedef struct mkAlgStat {
	long n, ns, ok, nd, ag, close;
	double sum;
} mkAlgStat;

/* The rows of pair kind `pair` whose algorithm squashes to `want`. */
static void mkAlgStat_Load(mkAlgStat *st, double *ms, const mkTable *t, const char *pair, const char *want)
{
	int cpair = mkTable_Col(t, "pair"), calg = mkTable_Col(t, "algorithm"), csec = mkTable_Col(t, "seconds");
	int csucc = mkTable_Col(t, "success"), cagree = mkTable_Col(t, "agrees");
	memset(st, 0, sizeof *st);
	for (long r = 0; r < t->rows; ++r) {
		char alg[64];
		mkSquash(mkTable_Str(t, r, calg), alg, sizeof alg);
		if (strcmp(mkTable_Str(t, r, cpair), pair) != 0 || strcmp(alg, want) != 0)
			continue;
		double v = 1e3 * mkTable_Num(t, r, csec);
		ms[st->n++] = v;
		st->sum += v;
		double sv = mkTable_Num(t, r, csucc), av = mkTable_Num(t, r, cagree);
		if (!isnan(sv)) {
			st->ns += 1;
			st->ok += sv == 1.0;
		}
		if (!isnan(av)) {
			st->nd += 1;
			st->ag += av == 1.0;
		} else {
			st->close += 1;
		}
	}
}

/* One row of the details: queries, mean and median time, success rate,
 * agreement, too close. */
static void mkAlgStat_Row(mkDoc *d, const mkAlgStat *st, double *ms, const char *pair, const char *alg)
{
	qsort(ms, (size_t)st->n, sizeof(double), mkCompareDouble);
	double med = st->n % 2 ? ms[st->n / 2] : 0.5 * (ms[st->n / 2 - 1] + ms[st->n / 2]);
	char c[6][MK_CELL_MAX];
	snprintf(c[0], MK_CELL_MAX, "%ld", st->n);
	snprintf(c[1], MK_CELL_MAX, "%.3g", st->sum / (double)st->n);
	snprintf(c[2], MK_CELL_MAX, "%.3g", med);
	if (st->ns)
		snprintf(c[3], MK_CELL_MAX, "%.4f", (double)st->ok / (double)st->ns);
	else
		snprintf(c[3], MK_CELL_MAX, "—");
	if (st->nd)
		snprintf(c[4], MK_CELL_MAX, "%.4f (%ld/%ld)", (double)st->ag / (double)st->nd, st->ag, st->nd);
	else
		snprintf(c[4], MK_CELL_MAX, "—");
	snprintf(c[5], MK_CELL_MAX, "%ld", st->close);
	const char *row[8] = { pair, alg, c[0], c[1], c[2], c[3], c[4], c[5] };
	mkDoc_Row(d, row);
}

/* The first row whose algorithm squashes to `want`, or -1. */
static long mkFirstRow(const mkTable *t, int calg, const char *want)
{
	for (long r = 0; r < t->rows; ++r) {
		char alg[64];
		mkSquash(mkTable_Str(t, r, calg), alg, sizeof alg);
		if (strcmp(alg, want) == 0)
			return r;
	}
	return -1;
}

/* The reproduction's own figures per pair and algorithm (nothing published
 * to compare with). The algorithms are those of the data, in order of first
 * appearance (one per squashed name). */
static void mkCollision_Details(mkDoc *d, const mkTable *t, const mkMeta *m)
{
	static const char *const head[] = { "pair", "algorithm", "queries", "mean (ms)", "median (ms)",
		"success", "agreement", "too close" };
	const char *margin = mkMeta_Get(m, "referee_margin");
	mkDoc_Para(d, "Per algorithm: success = residual below 1e-10 (LM) or Ipopt's Solve_Succeeded "
		"(Implicit); agreement = same verdict as the support-function referee, over the trials whose "
		"|min g| exceeds the margin (%s); the others are too close to call.", margin ? margin : "not recorded");
	mkDoc_TableBegin(d, "Collision detection: the reproduction's figures per algorithm.", 8, head);
	int calg = mkTable_Col(t, "algorithm");
	double *ms = malloc((size_t)(t->rows > 0 ? t->rows : 1) * sizeof(double));
	for (int p = 0; ms && p < 2; ++p)
		for (long r = 0; r < t->rows; ++r) {
			char want[64];
			mkSquash(mkTable_Str(t, r, calg), want, sizeof want);
			if (mkFirstRow(t, calg, want) < r)
				continue; /* an algorithm's first row names it */
			mkAlgStat st;
			mkAlgStat_Load(&st, ms, t, mkCollision_PairNames[p], want);
			if (st.n > 0)
				mkAlgStat_Row(d, &st, ms, mkCollision_PairNames[p], mkTable_Str(t, r, calg));
		}
	free(ms);
	mkDoc_TableEnd(d);
}

/* Table 3: the published mean times beside the reproduced ones. */
static void mkCollision_Table3(mkDoc *d, const mkTable *t, int usable, mkTally *tally)
{
	static const char *const head[] = { "algorithm", "published ellipsoids (ms)", "reproduced", "ratio",
		"published superquadrics (ms)", "reproduced", "ratio" };
	int cpair = mkTable_Col(t, "pair"), calg = mkTable_Col(t, "algorithm"), csec = mkTable_Col(t, "seconds");
	mkDoc_TableBegin(d, "Collision detection: mean time per query over 10⁴ random poses.", 7, head);
	for (int i = 0; i < mkPaper_Table3Count; ++i) {
		const mkPaperTable3 *pub = &mkPaper_Table3[i];
		char want[64], alg[64];
		mkSquash(pub->algorithm, want, sizeof want);
		mkMean e, s;
		memset(&e, 0, sizeof e);
		memset(&s, 0, sizeof s);
		for (long r = 0; usable && r < t->rows; ++r) {
			mkSquash(mkTable_Str(t, r, calg), alg, sizeof alg);
			if (strcmp(alg, want) != 0)
				continue;
			const char *pair = mkTable_Str(t, r, cpair);
			double ms = 1e3 * mkTable_Num(t, r, csec);
			if (strcmp(pair, "ellipsoids") == 0)
				mkMean_Add(&e, ms);
			else if (strcmp(pair, "superquadrics") == 0)
				mkMean_Add(&s, ms);
		}
		char a[4][MK_CELL_MAX];
		double ve = mkMean_Get(&e), vs = mkMean_Get(&s);
		if (isnan(ve))
			snprintf(a[0], MK_CELL_MAX, "%s", mkNotYet);
		else
			snprintf(a[0], MK_CELL_MAX, "%.3g", ve);
		mkFmt_Ratio(a[1], MK_CELL_MAX, ve, pub->ellipsoids_ms);
		if (isnan(pub->superquadrics_ms))
			snprintf(a[2], MK_CELL_MAX, "—");
		else if (isnan(vs))
			snprintf(a[2], MK_CELL_MAX, "%s", mkNotYet);
		else
			snprintf(a[2], MK_CELL_MAX, "%.3g", vs);
		mkFmt_Ratio(a[3], MK_CELL_MAX, vs, pub->superquadrics_ms);
		const char *row[7] = { pub->algorithm, pub->ellipsoids_text, a[0], a[1], pub->superquadrics_text, a[2], a[3] };
		mkDoc_Row(d, row);
		mkTally_Add(tally, !isnan(ve));
		if (!isnan(pub->superquadrics_ms))
			mkTally_Add(tally, !isnan(vs));
	}
	mkDoc_TableEnd(d);
}

void mkCollision_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	static const char *const columns[] = { "pair", "algorithm", "seconds", NULL };
	mkSection s;
	int usable = mkSection_Begin(&s, d, "Collision detection (paper §7.2, Table 3)", dir, "collision.csv",
		columns, "None of the 11 published mean times below has a counterpart.");
	if (usable) {
		const char *rot = mkMeta_Get(&s.m, "rotation_draw");
		mkDoc_Para(d, "Rotation draw: %s.", rot ? rot : "not recorded in the sidecar");
	}
	mkCollision_Table3(d, &s.t, usable, tally);
	if (usable)
		mkCollision_Details(d, &s.t, &s.m);
	mkSection_End(&s);
}
