/* main.c - the `fitting` driver: the fitting errors of paper Sec. 6.2.
 *
 * Writes one CSV row per trial and model (and per level in case 2) with a
 * metadata sidecar, then prints the means beside the published figures. */
#define _POSIX_C_SOURCE 200809L
#include "cases.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <libqhull_r/libqhull_r.h>
#include <mink_exp/exp.h>

#define DEFAULT_SEED 2022u
#define DEFAULT_TRIALS 100
#define MAX_TRIALS 1000000
#define SCHEMA_VERSION 1

static const char *const COLUMNS[] = {
	"case", "trial", "truth", "model", "sampling", "level", "vertices",
	"volume_true", "volume_model", "e_volume", "e_implicit",
	"a", "b", "c", "eps1", "eps2", "qw", "qx", "qy", "qz", "tx", "ty", "tz",
	"size_x", "size_y", "size_z", "cost", "iterations", "nfev", "status",
};
enum { NCOLUMNS = sizeof COLUMNS / sizeof COLUMNS[0] };

static void usage(FILE *f)
{
	fprintf(f,
		"usage: fitting [options]\n"
		"Fitting errors between superquadrics and convex polyhedra (paper Sec. 6.2).\n"
		"  --case 1|2|3|all   which case to run (default all)\n"
		"                     1: superquadric fitted to a random polyhedron (LM)\n"
		"                     2: polyhedra from n x n superquadric grids, n = %d..%d\n"
		"                     3: cube, ellipsoid, cylinder, both models\n"
		"  --trials N         trials per case and level, 1..%d (default %d)\n"
		"  --seed S           run seed, 0..2^64-1, decimal or 0x.. (default %u)\n"
		"  --out PATH         results CSV (default results/fitting.csv, or\n"
		"                     results/fitting-case<K>.csv for one case; a shard\n"
		"                     adds .shard-I-of-N before .csv); PATH.meta is the sidecar\n"
		"  --shard I/N        run only block I of N (0 <= I < N) of the run's\n"
		"                     (case, trial) units; the shards' rows, concatenated\n"
		"                     in shard order, are the whole run's\n"
		"  --force            overwrite an existing result (otherwise the run is skipped)\n"
		"  --help             this text\n",
		MK_FIT_CASE2_NMIN, MK_FIT_CASE2_NMAX, MAX_TRIALS, DEFAULT_TRIALS, DEFAULT_SEED);
}

static double nowSeconds(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void writeRow(mkCsv *out, const mkFitRow *r)
{
	mkCsv_Int(out, r->caseId);
	mkCsv_Int(out, r->trial);
	mkCsv_Str(out, r->truth);
	mkCsv_Str(out, r->model);
	mkCsv_Str(out, r->sampling);
	mkCsv_Int(out, r->level);
	mkCsv_Int(out, r->vertices);
	mkCsv_Double(out, r->volumeTrue);
	mkCsv_Double(out, r->volumeModel);
	mkCsv_Double(out, r->eVolume);
	mkCsv_Double(out, r->eImplicit);
	mkCsv_Double(out, r->shape.a);
	mkCsv_Double(out, r->shape.b);
	mkCsv_Double(out, r->shape.c);
	mkCsv_Double(out, r->shape.eps1);
	mkCsv_Double(out, r->shape.eps2);
	for (int i = 0; i < 4; ++i) {
		mkCsv_Double(out, r->q[i]);
	}
	mkCsv_Double(out, r->t.x);
	mkCsv_Double(out, r->t.y);
	mkCsv_Double(out, r->t.z);
	for (int i = 0; i < 3; ++i) {
		mkCsv_Double(out, r->size[i]);
	}
	mkCsv_Double(out, r->cost);
	mkCsv_Int(out, r->iterations);
	mkCsv_Int(out, r->nfev);
	mkCsv_Str(out, r->status);
	mkCsv_EndRow(out);
}

/* ---- the summary printed at the end: means by group ----------------------- */

typedef struct Group {
	int caseId, level;
	const char *truth, *model, *sampling;
	int rows, valid;
	double sumVolume, sumImplicit;
	int implicitRows;
} Group;

enum { MAX_GROUPS = 64 };

typedef struct Summary {
	Group g[MAX_GROUPS];
	int count;
} Summary;

static void summaryAdd(Summary *s, const mkFitRow *r)
{
	Group *g = NULL;
	for (int i = 0; i < s->count; ++i) {
		Group *h = &s->g[i];
		if (h->caseId == r->caseId && h->level == r->level && strcmp(h->truth, r->truth) == 0
			&& strcmp(h->model, r->model) == 0 && strcmp(h->sampling, r->sampling) == 0) {
			g = h;
			break;
		}
	}
	if (g == NULL) {
		if (s->count == MAX_GROUPS) {
			return;
		}
		g = &s->g[s->count++];
		memset(g, 0, sizeof *g);
		g->caseId = r->caseId;
		g->level = r->level;
		g->truth = r->truth;
		g->model = r->model;
		g->sampling = r->sampling;
	}
	g->rows += 1;
	if (isfinite(r->eVolume)) {
		g->valid += 1;
		g->sumVolume += r->eVolume;
	}
	if (isfinite(r->eImplicit)) {
		g->implicitRows += 1;
		g->sumImplicit += r->eImplicit;
	}
}

/* The published means (paper Sec. 6.2), where the paper gives one. */
static double published(const Group *g, double *publishedImplicit)
{
	*publishedImplicit = NAN;
	if (g->caseId == 1) {
		*publishedImplicit = 0.5808;
		return 0.2095;
	}
	int paper = strcmp(g->sampling, "paper") == 0;
	if (g->caseId == 2 && paper) {
		return g->level == 16 ? 0.6573 : g->level == 81 ? 0.094 : g->level == 400 ? 0.0171 : NAN;
	}
	if (g->caseId == 3) {
		int sq = strcmp(g->model, "superquadric") == 0;
		if (strcmp(g->truth, "cube") == 0 && sq) {
			return 0.0112;
		}
		if (strcmp(g->truth, "ellipsoid") == 0 && !sq && paper) {
			return 0.1340;
		}
		if (strcmp(g->truth, "cylinder") == 0) {
			return sq ? 0.0074 : paper ? 0.0078 : NAN;
		}
	}
	return NAN;
}

/* A published figure, or "-" where the paper gives none. */
static void printPublished(double v)
{
	if (isnan(v)) {
		printf(" %10s", "-");
	} else {
		printf(" %10.4g", v);
	}
}

static void summaryPrint(const Summary *s)
{
	printf("%-4s %-12s %-12s %-9s %5s %5s %12s %10s %12s %10s\n", "case", "truth", "model",
		"sampling", "level", "rows", "e_volume", "published", "e_implicit", "published");
	for (int i = 0; i < s->count; ++i) {
		const Group *g = &s->g[i];
		double pubI;
		double pubV = published(g, &pubI);
		printf("%-4d %-12s %-12s %-9s %5d %5d %12.4e", g->caseId, g->truth, g->model, g->sampling,
			g->level, g->rows, g->valid ? g->sumVolume / g->valid : NAN);
		printPublished(pubV);
		printf(" %12.4e", g->implicitRows ? g->sumImplicit / g->implicitRows : NAN);
		printPublished(pubI);
		printf("\n");
		if (g->valid != g->rows) {
			printf("     (%d of %d rows without a volume: see their status)\n", g->rows - g->valid, g->rows);
		}
	}
}

static const mkOption OPTIONS[] = {
	{ "--case", 1 }, { "--trials", 1 }, { "--seed", 1 }, { "--out", 1 }, { "--shard", 1 }, { "--force", 0 },
};

static int usageError(const char *msg)
{
	fprintf(stderr, "fitting: %s\n", msg);
	return 2;
}

int main(int argc, char **argv)
{
	static const char *const CASE_NAMES[] = { "1", "2", "3", "all" };
	int caseChoice = 3;
	const char *out = NULL;
	long trials = DEFAULT_TRIALS;
	uint64_t seed = DEFAULT_SEED;
	mkShard shard = mkShard_All();
	int force = 0;
	char msg[512];

	mkArgs args;
	mkArgs_Begin(&args, argc, argv); /* starts after argv[0] */
	const char *name, *value;
	mkArgsStep step;
	while ((step = mkArgs_Step(&args, OPTIONS, MK_COUNT(OPTIONS), &name, &value, msg, sizeof msg))
		!= MK_ARGS_END) {
		if (step == MK_ARGS_HELP) {
			usage(stdout);
			return 0;
		}
		if (step == MK_ARGS_ERROR) {
			return usageError(msg);
		}
		if (strcmp(name, "--force") == 0) {
			force = 1;
			continue;
		}
		int bad = 0;
		if (strcmp(name, "--case") == 0) {
			bad = mkArg_Choice(name, value, CASE_NAMES, 4, &caseChoice, msg, sizeof msg);
		} else if (strcmp(name, "--trials") == 0) {
			bad = mkArg_Long(name, value, 1, MAX_TRIALS, &trials, msg, sizeof msg);
		} else if (strcmp(name, "--seed") == 0) {
			bad = mkArg_U64(name, value, &seed, msg, sizeof msg);
		} else if (strcmp(name, "--shard") == 0) {
			bad = mkShard_Parse(value, name, &shard, msg, sizeof msg);
		} else {
			bad = mkArg_Path(name, value, &out, msg, sizeof msg);
		}
		if (bad) {
			return usageError(msg);
		}
	}
	const char *caseText = CASE_NAMES[caseChoice];

	char defaultOut[256];
	if (out == NULL) {
		char shardPart[64] = "";
		if (shard.count > 1) {
			snprintf(shardPart, sizeof shardPart, ".shard-%d-of-%d", shard.index, shard.count);
		}
		if (caseChoice == 3) {
			snprintf(defaultOut, sizeof defaultOut, "results/fitting%s.csv", shardPart);
		} else {
			snprintf(defaultOut, sizeof defaultOut, "results/fitting-case%s%s.csv", caseText, shardPart);
		}
		out = defaultOut;
	}
	if (!force && mkPath_Exists(out)) {
		printf("fitting: %s exists; skipped (use --force to run again)\n", out);
		return 0;
	}
	if (mkPath_MakeParents(out, msg, sizeof msg) != 0) {
		fprintf(stderr, "fitting: %s\n", msg);
		return 1;
	}

	mkMeta meta;
	mkMeta_Init(&meta, "fitting", SCHEMA_VERSION, argc, argv);
	mkMeta_SetU64(&meta, "seed", seed);
	mkMeta_SetInt(&meta, "trials", trials);
	mkMeta_Set(&meta, "cases", caseText);
	snprintf(msg, sizeof msg, "%d/%d", shard.index, shard.count);
	mkMeta_Set(&meta, "shard", msg);
	mkMeta_Set(&meta, "qhull_version", qh_version);
	mkMeta_Set(&meta, "cminpack_version", MK_FIT_CMINPACK_VERSION);
	mkMeta_Set(&meta, "case1_draw", "100 points [20,15,10].*U(-1,1)^3; LM fit to the hull vertices");
	mkMeta_Set(&meta, "case2_draw", "a=[20,15,10].*U(0,1)^3, eps=U(0,2)^2, quaternion U(0,1)^4; n=4..20");
	mkMeta_Set(&meta, "case3_draw", "size=[50,36,20].*U(0,1)^3+1");

	mkCsv csv;
	if (mkCsv_Open(&csv, out, COLUMNS, NCOLUMNS, msg, sizeof msg) != 0) {
		fprintf(stderr, "fitting: %s\n", msg);
		mkMeta_Free(&meta);
		return 1;
	}

	/* The run's units are (case, trial) pairs, case by case; a shard takes
	 * a contiguous block of them. */
	int cases[3], ncases = 0;
	for (int c = 1; c <= 3; ++c) {
		if (caseChoice == 3 || caseChoice == c - 1) {
			cases[ncases++] = c;
		}
	}
	long begin, end;
	mkShard_Range(shard, (long)ncases * trials, &begin, &end);

	static Summary summary;
	static mkFitRow rows[MK_FIT_MAX_ROWS];
	int (*const trialFn[3])(uint64_t, int, mkFitRow *) = { mkFitCase1_Trial, mkFitCase2_Trial, mkFitCase3_Trial };
	double seconds[3] = { 0.0, 0.0, 0.0 };
	mkProgress progress;
	mkProgress_Begin(&progress, "fitting", end - begin);
	for (long u = begin; u < end; ++u) {
		int c = cases[u / trials];
		int t = (int)(u % trials);
		double t0 = nowSeconds();
		int n = trialFn[c - 1](seed, t, rows);
		seconds[c - 1] += nowSeconds() - t0;
		if (n < 0) {
			fprintf(stderr, "fitting: out of memory in case %d, trial %d\n", c, t);
			mkCsv_Discard(&csv);
			mkMeta_Free(&meta);
			return 1;
		}
		for (int k = 0; k < n; ++k) {
			writeRow(&csv, &rows[k]);
			summaryAdd(&summary, &rows[k]);
		}
		mkProgress_Add(&progress, 1);
	}
	mkProgress_End(&progress);

	for (int c = 0; c < 3; ++c) {
		char key[32];
		snprintf(key, sizeof key, "case%d_seconds", c + 1);
		mkMeta_SetDouble(&meta, key, seconds[c]);
	}
	int rc = mkCsv_Commit(&csv, &meta, msg, sizeof msg);
	mkMeta_Free(&meta);
	if (rc != 0) {
		fprintf(stderr, "fitting: %s\n", msg);
		return 1;
	}

	printf("fitting: wrote %s (seed %" PRIu64 ", %ld trials, shard %d/%d)\n", out, seed, trials,
		shard.index, shard.count);
	summaryPrint(&summary);
	for (int c = 0; c < 3; ++c) {
		if (seconds[c] > 0.0) {
			printf("case %d: %.3f s\n", c + 1, seconds[c]);
		}
	}
	return 0;
}
