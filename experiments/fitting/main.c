/* main.c - the `fitting` driver: the fitting errors of paper Sec. 6.2.
 *
 * Writes one CSV row per trial and model (and per level in case 2) with a
 * metadata sidecar, then prints the means beside the published figures. */
#define _POSIX_C_SOURCE 200809L
#include "cases.h"
#include "fitio.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define DEFAULT_SEED 20220622u
#define DEFAULT_TRIALS 100
#define MAX_TRIALS 1000000

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
		"  --seed S           run seed, 0..2^64-1 (default %u)\n"
		"  --out PATH         results CSV (default results/fitting.csv, or\n"
		"                     results/fitting-case<K>.csv for one case; a shard\n"
		"                     adds .shard-I-of-N before .csv); PATH.meta is the sidecar\n"
		"  --shard I/N        run only trials t with t mod N == I (0 <= I < N)\n"
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

static void writeRow(mkFitOut *out, const mkFitRow *r)
{
	mkFitOut_Int(out, r->caseId);
	mkFitOut_Int(out, r->trial);
	mkFitOut_Str(out, r->truth);
	mkFitOut_Str(out, r->model);
	mkFitOut_Str(out, r->sampling);
	mkFitOut_Int(out, r->level);
	mkFitOut_Int(out, r->vertices);
	mkFitOut_Double(out, r->volumeTrue);
	mkFitOut_Double(out, r->volumeModel);
	mkFitOut_Double(out, r->eVolume);
	mkFitOut_Double(out, r->eImplicit);
	mkFitOut_Double(out, r->shape.a);
	mkFitOut_Double(out, r->shape.b);
	mkFitOut_Double(out, r->shape.c);
	mkFitOut_Double(out, r->shape.eps1);
	mkFitOut_Double(out, r->shape.eps2);
	for (int i = 0; i < 4; ++i) {
		mkFitOut_Double(out, r->q[i]);
	}
	mkFitOut_Double(out, r->t.x);
	mkFitOut_Double(out, r->t.y);
	mkFitOut_Double(out, r->t.z);
	for (int i = 0; i < 3; ++i) {
		mkFitOut_Double(out, r->size[i]);
	}
	mkFitOut_Double(out, r->cost);
	mkFitOut_Int(out, r->iterations);
	mkFitOut_Int(out, r->nfev);
	mkFitOut_Str(out, r->status);
	mkFitOut_EndRow(out);
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

int main(int argc, char **argv)
{
	const char *caseText = "all";
	const char *out = NULL;
	int trials = DEFAULT_TRIALS;
	uint64_t seed = DEFAULT_SEED;
	int shardIndex = 0, shardCount = 1, force = 0;

	for (int i = 1; i < argc; ++i) {
		const char *a = argv[i];
		const char *v = i + 1 < argc ? argv[i + 1] : NULL;
		char msg[256];
		if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
			usage(stdout);
			return 0;
		} else if (strcmp(a, "--force") == 0) {
			force = 1;
			continue;
		}
		if (strcmp(a, "--case") != 0 && strcmp(a, "--trials") != 0 && strcmp(a, "--seed") != 0
			&& strcmp(a, "--out") != 0 && strcmp(a, "--shard") != 0) {
			fprintf(stderr, "fitting: unknown option '%s' (see --help)\n", a);
			return 2;
		}
		if (v == NULL) {
			fprintf(stderr, "fitting: %s needs a value (see --help)\n", a);
			return 2;
		}
		++i;
		if (strcmp(a, "--case") == 0) {
			if (strcmp(v, "1") != 0 && strcmp(v, "2") != 0 && strcmp(v, "3") != 0 && strcmp(v, "all") != 0) {
				fprintf(stderr, "fitting: --case: expected 1, 2, 3 or all, got '%s'\n", v);
				return 2;
			}
			caseText = v;
		} else if (strcmp(a, "--trials") == 0) {
			char *end;
			errno = 0;
			long t = strtol(v, &end, 10);
			if (errno != 0 || end == v || *end != '\0' || t < 1 || t > MAX_TRIALS) {
				fprintf(stderr, "fitting: --trials: expected an integer in 1..%d, got '%s'\n", MAX_TRIALS, v);
				return 2;
			}
			trials = (int)t;
		} else if (strcmp(a, "--seed") == 0) {
			char *end;
			errno = 0;
			unsigned long long s = strtoull(v, &end, 10);
			if (errno != 0 || end == v || *end != '\0' || v[0] == '-') {
				fprintf(stderr, "fitting: --seed: expected an integer in 0..18446744073709551615, got '%s'\n", v);
				return 2;
			}
			seed = (uint64_t)s;
		} else if (strcmp(a, "--out") == 0) {
			if (v[0] == '\0') {
				fprintf(stderr, "fitting: --out: expected a file path, got ''\n");
				return 2;
			}
			out = v;
		} else {
			if (mkFitShard_Parse(v, &shardIndex, &shardCount, msg, sizeof msg) != 0) {
				fprintf(stderr, "fitting: %s\n", msg);
				return 2;
			}
		}
	}

	char defaultOut[256];
	if (out == NULL) {
		char shardPart[64] = "";
		if (shardCount > 1) {
			snprintf(shardPart, sizeof shardPart, ".shard-%d-of-%d", shardIndex, shardCount);
		}
		if (strcmp(caseText, "all") == 0) {
			snprintf(defaultOut, sizeof defaultOut, "results/fitting%s.csv", shardPart);
		} else {
			snprintf(defaultOut, sizeof defaultOut, "results/fitting-case%s%s.csv", caseText, shardPart);
		}
		out = defaultOut;
	}
	if (!force && mkFitOut_Exists(out)) {
		printf("fitting: %s exists; skipped (use --force to run again)\n", out);
		return 0;
	}

	char msg[512];
	mkFitOut *csv = mkFitOut_Open(out, COLUMNS, NCOLUMNS, msg, sizeof msg);
	if (csv == NULL) {
		fprintf(stderr, "fitting: %s\n", msg);
		return 1;
	}

	static Summary summary;
	static mkFitRow rows[MK_FIT_MAX_ROWS];
	int (*const trialFn[3])(uint64_t, int, mkFitRow *) = { mkFitCase1_Trial, mkFitCase2_Trial, mkFitCase3_Trial };
	double seconds[3] = { 0.0, 0.0, 0.0 };
	for (int c = 1; c <= 3; ++c) {
		if (strcmp(caseText, "all") != 0 && caseText[0] - '0' != c) {
			continue;
		}
		double t0 = nowSeconds();
		for (int t = 0; t < trials; ++t) {
			if (!mkFitShard_Owns(shardIndex, shardCount, t)) {
				continue;
			}
			int n = trialFn[c - 1](seed, t, rows);
			if (n < 0) {
				fprintf(stderr, "fitting: out of memory in case %d, trial %d\n", c, t);
				mkFitOut_Discard(csv);
				return 1;
			}
			for (int k = 0; k < n; ++k) {
				writeRow(csv, &rows[k]);
				summaryAdd(&summary, &rows[k]);
			}
		}
		seconds[c - 1] = nowSeconds() - t0;
	}

	size_t cmdLen = 1;
	for (int i = 0; i < argc; ++i) {
		cmdLen += strlen(argv[i]) + 1;
	}
	char *cmd = malloc(cmdLen);
	if (cmd == NULL) {
		mkFitOut_Discard(csv);
		fprintf(stderr, "fitting: out of memory\n");
		return 1;
	}
	cmd[0] = '\0';
	for (int i = 0; i < argc; ++i) {
		strcat(cmd, i ? " " : "");
		strcat(cmd, argv[i]);
	}
	mkFitRunInfo info = { cmd, seed, trials, caseText, shardIndex, shardCount };
	int rc = mkFitOut_Commit(csv, &info, msg, sizeof msg);
	free(cmd);
	if (rc != 0) {
		fprintf(stderr, "fitting: %s\n", msg);
		return 1;
	}

	printf("fitting: wrote %s (seed %" PRIu64 ", %d trials, shard %d/%d)\n", out, seed, trials,
		shardIndex, shardCount);
	summaryPrint(&summary);
	for (int c = 0; c < 3; ++c) {
		if (seconds[c] > 0.0) {
			printf("case %d: %.3f s\n", c + 1, seconds[c]);
		}
	}
	return 0;
}
