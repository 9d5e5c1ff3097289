/* cmd_pairs.c - `mink collide --pairs FILE`: the batched queries of
 * mink/batch.h on every pair of a CSV file, one CSV row per pair. The whole
 * file is read and checked before any query runs; the rows are written
 * after the last one (with --out: through a temporary file, renamed). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/mink.h>
#include <mink_exp/outfile.h>
#include <mink_exp/progress.h>

#include "cli.h"
#include "commands.h"

/* Longest line of a pairs file, in bytes. */
#define MK_PAIRS_LINE 8192
/* Pairs per batch call (and per progress step). */
#define MK_PAIRS_CHUNK 4096

static void help(FILE *out)
{
	fputs("usage: mink collide --pairs FILE [--mode status|clearance|distance|full] [--delta D] [--out FILE]\n"
		"\n"
		"Every pair of bodies in FILE, queried in one batch (mink/batch.h). FILE is CSV\n"
		"with the header 'body1,body2' and one pair of SPECs per line; a SPEC that holds\n"
		"a comma (at=x,y,z) is quoted: \"sphere a=10 at=40,0,0\". One CSV row per pair:\n"
		"  line          the pair's line in FILE\n"
		"  status        separated, touching or overlapping (certified), unknown on failure\n"
		"  distance      the signed distance (distance mode: separated and touching pairs;\n"
		"                full: every pair, negative the penetration depth)\n"
		"  lower,upper   a certified bracket of the signed distance (inf where unbounded)\n"
		"  clear         clearance mode: 1 when the distance is at least --delta, else 0\n"
		"  nx,ny,nz      the separating direction or the solver's normal\n"
		"  x1..z2        witness points on body1 and body2 (an overlap point: both the same)\n"
		"  path          separating, overlap-point (certificates) or one-pair (the solver)\n"
		"Absent values are empty. Exit status 1 when a pair got no verdict (its row says\n"
		"unknown), 2 on bad input (named by line and field).\n"
		"\n", out);
}

static const char *const mkModeNames[] = { "status", "clearance", "distance", "full" };
static const char *const mkPathNames[] = { "separating", "overlap-point", "one-pair", "failed" };

/* Splits one CSV line (RFC 4180 quoting, the line ending removed) into at
 * most max fields, in place. Returns the count, or -1 on an unclosed
 * quote. */
static int mkSplitCsv(char *line, char **fields, int max)
{
	int n = 0;
	char *r = line, *w = line;
	for (;;) {
		char *start = w;
		if (*r == '"') {
			for (++r;; ++r) {
				if (*r == '\0')
					return -1;
				if (*r == '"' && r[1] == '"') {
					*w++ = '"';
					++r;
				} else if (*r == '"') {
					++r;
					break;
				} else {
					*w++ = *r;
				}
			}
		}
		while (*r && *r != ',')
			*w++ = *r++;
		int more = *r == ',';
		*w++ = '\0';
		if (n < max)
			fields[n] = start;
		++n;
		if (!more)
			return n;
		++r;
	}
}

typedef struct mkPairsIn {
	mkBody3 *b1, *b2;
	int *line;
	int count, cap;
} mkPairsIn;

/* Reads the pairs file. Returns 0, or 2 after a message naming the line
 * and field. */
static int mkPairs_Read(const char *path, mkPairsIn *in)
{
	FILE *fp = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
	if (!fp) {
		fprintf(stderr, "mink collide: --pairs %s: cannot open the file\n", path);
		return 2;
	}
	static char buf[MK_PAIRS_LINE];
	char msg[512];
	int lineno = 0, rc = 0;
	while (rc == 0 && fgets(buf, sizeof buf, fp)) {
		++lineno;
		size_t len = strlen(buf);
		if (len + 1 == sizeof buf && buf[len - 1] != '\n') {
			fprintf(stderr, "mink collide: %s line %d: longer than %d bytes\n", path, lineno, MK_PAIRS_LINE - 2);
			rc = 2;
			break;
		}
		while (len > 0 && (buf[len - 1] == '\n' || buf[len - 1] == '\r'))
			buf[--len] = '\0';
		char *f[2];
		int nf = mkSplitCsv(buf, f, 2);
		if (lineno == 1) {
			if (nf != 2 || strcmp(f[0], "body1") != 0 || strcmp(f[1], "body2") != 0) {
				fprintf(stderr, "mink collide: %s line 1: the header must be 'body1,body2'\n", path);
				rc = 2;
			}
			continue;
		}
		if (len == 0)
			continue;
		if (nf != 2) {
			fprintf(stderr, "mink collide: %s line %d: %s; expected 2 fields (body1,body2), found %d (quote a SPEC "
				"that holds commas)\n", path, lineno, nf < 0 ? "unclosed quote" : "wrong field count", nf < 0 ? 0 : nf);
			rc = 2;
			break;
		}
		if (in->count == in->cap) {
			int cap = in->cap ? 2 * in->cap : 1024;
			mkBody3 *b1 = realloc(in->b1, sizeof *b1 * (size_t)cap), *b2 = b1 ? realloc(in->b2, sizeof *b2 * (size_t)cap) : NULL;
			int *ln = b2 ? realloc(in->line, sizeof *ln * (size_t)cap) : NULL;
			if (b1) in->b1 = b1;
			if (b2) in->b2 = b2;
			if (ln) in->line = ln;
			if (!ln) {
				fprintf(stderr, "mink collide: out of memory at %s line %d\n", path, lineno);
				rc = 1;
				break;
			}
			in->cap = cap;
		}
		const char *what[2] = { "body1", "body2" };
		mkBody3 *dst[2] = { &in->b1[in->count], &in->b2[in->count] };
		for (int j = 0; j < 2 && rc == 0; ++j) {
			mkSpec s;
			if (mkSpec_Parse(f[j], 3, what[j], &s, msg, sizeof msg) != MK_OK) {
				fprintf(stderr, "mink collide: %s line %d: %s\n", path, lineno, msg);
				rc = 2;
			}
			*dst[j] = s.body3;
		}
		in->line[in->count++] = lineno;
	}
	if (rc == 0 && ferror(fp)) {
		fprintf(stderr, "mink collide: --pairs %s: read error\n", path);
		rc = 2;
	}
	if (rc == 0 && lineno == 0) {
		fprintf(stderr, "mink collide: %s line 1: the header must be 'body1,body2' (the file is empty)\n", path);
		rc = 2;
	}
	if (fp != stdin)
		fclose(fp);
	return rc;
}

/* The answers of every pair (arrays of in->count). */
typedef struct mkPairsOut {
	mkContact *status;
	double *distance, *lower, *upper;
	mkVec3 *n, *p1, *p2;
	unsigned char *clear, *path;
} mkPairsOut;

static void mkNum(FILE *fp, double v)
{
	if (isnan(v))
		return;
	if (isinf(v))
		fputs(v > 0 ? "inf" : "-inf", fp);
	else
		fprintf(fp, "%.17g", v);
}

static void mkVecOut(FILE *fp, mkVec3 v)
{
	mkNum(fp, v.x);
	fputc(',', fp);
	mkNum(fp, v.y);
	fputc(',', fp);
	mkNum(fp, v.z);
}

static int mkPairs_Write(FILE *fp, const mkPairsIn *in, const mkPairsOut *o, int mode)
{
	fputs("line,status,distance,lower,upper,clear,nx,ny,nz,x1,y1,z1,x2,y2,z2,path\n", fp);
	for (int k = 0; k < in->count; ++k) {
		fprintf(fp, "%d,%s,", in->line[k], mkContact_Name(o->status[k]));
		mkNum(fp, o->distance[k]);
		fputc(',', fp);
		mkNum(fp, o->lower[k]);
		fputc(',', fp);
		mkNum(fp, o->upper[k]);
		fputc(',', fp);
		if (mode == MK_BATCH_CLEARANCE && o->status[k] != MK_CONTACT_UNKNOWN)
			fprintf(fp, "%d", o->clear[k]);
		fputc(',', fp);
		mkVecOut(fp, o->n[k]);
		fputc(',', fp);
		mkVecOut(fp, o->p1[k]);
		fputc(',', fp);
		mkVecOut(fp, o->p2[k]);
		fprintf(fp, ",%s\n", mkPathNames[o->path[k] < 4 ? o->path[k] : 3]);
	}
	return ferror(fp) ? -1 : 0;
}

/* Runs the batch in chunks (progress on long runs). Returns 0, or 1 when
 * some pair got no verdict. */
static int mkPairs_Run(const mkPairsIn *in, const mkPairsOut *o, int mode, double delta)
{
	mkProgress prog;
	mkProgress_Begin(&prog, "pairs", in->count);
	int failed = 0;
	for (int at = 0; at < in->count; at += MK_PAIRS_CHUNK) {
		int n = in->count - at < MK_PAIRS_CHUNK ? in->count - at : MK_PAIRS_CHUNK;
		mkBatchPairs3 pairs = { n, in->b1 + at, in->b2 + at, NULL, NULL };
		mkBatchOut3 out = { o->status + at, o->distance + at, o->lower + at, o->upper + at, o->n + at, o->p1 + at,
			o->p2 + at, o->clear + at, o->path + at };
		mkResult r = mkCollide3_Batch(&pairs, (mkBatchMode)mode, delta, &out, NULL);
		failed |= r != MK_OK;
		mkProgress_Add(&prog, n);
	}
	mkProgress_End(&prog);
	return failed;
}

/* Writes to standard output, or to --out through a temporary file. */
static int mkPairs_Emit(const char *outpath, const mkPairsIn *in, const mkPairsOut *o, int mode)
{
	char msg[512];
	if (!outpath) {
		if (mkPairs_Write(stdout, in, o, mode) || fflush(stdout)) {
			fprintf(stderr, "mink collide: writing to standard output failed\n");
			return 1;
		}
		return 0;
	}
	mkOutFile f;
	if (mkOutFile_Open(&f, outpath, msg, sizeof msg)) {
		fprintf(stderr, "mink collide: --out %s: %s\n", outpath, msg);
		return 1;
	}
	if (mkPairs_Write(f.fp, in, o, mode)) {
		mkOutFile_Discard(&f);
		fprintf(stderr, "mink collide: --out %s: write failed\n", outpath);
		return 1;
	}
	if (mkOutFile_Commit(&f, msg, sizeof msg)) {
		fprintf(stderr, "mink collide: --out %s: %s\n", outpath, msg);
		return 1;
	}
	return 0;
}

int mkCmd_CollidePairs(int argc, char **argv)
{
	const char *file = NULL, *outpath = NULL;
	int mode = MK_BATCH_STATUS;
	double delta = 0.0;
	mkFlag flags[] = {
		MK_FLAG_PATH("--pairs", "FILE", "the pairs: CSV, header 'body1,body2', one pair of SPECs per\nline ('-': "
			"standard input)", &file),
		MK_FLAG_CHOICE("--mode", "status|clearance|distance|full", "what to answer (default status); see\n"
			"docs/collide.md#batches", &mode, mkModeNames),
		MK_FLAG_DOUBLE("--delta", "D", "clearance mode: the clearance asked, a number in [0, 1e300]", &delta, 0.0,
			1e300),
		MK_FLAG_PATH("--out", "FILE", "write to FILE (atomically: complete or not at all);\n"
			"default standard output", &outpath),
	};
	/* --help wins wherever it stands (also as the argument of --pairs) */
	char *helpv[2] = { argv[0], "--help" };
	for (int i = 1; i < argc; ++i)
		if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
			return mkCli_Parse("collide", flags, MK_COUNT(flags), 2, helpv, help);
	int rc = mkCli_Parse("collide", flags, MK_COUNT(flags), argc, argv, help);
	if (rc != MK_CLI_GO)
		return rc;
	if ((rc = mkCli_Require("collide", &flags[0])) != MK_CLI_GO)
		return rc;
	if (flags[2].given && mode != MK_BATCH_CLEARANCE) {
		fprintf(stderr, "mink collide: --delta is for --mode clearance only\n");
		return 2;
	}
	if (mode == MK_BATCH_CLEARANCE && !flags[2].given) {
		fprintf(stderr, "mink collide: --mode clearance needs --delta D (the clearance asked, in [0, 1e300])\n");
		return 2;
	}
	mkPairsIn in = { 0 };
	mkPairsOut o = { 0 };
	rc = mkPairs_Read(file, &in);
	size_t n = (size_t)(in.count > 0 ? in.count : 1);
	if (rc == 0) {
		o.status = malloc(n * sizeof *o.status);
		o.distance = malloc(n * sizeof(double));
		o.lower = malloc(n * sizeof(double));
		o.upper = malloc(n * sizeof(double));
		o.n = malloc(n * sizeof(mkVec3));
		o.p1 = malloc(n * sizeof(mkVec3));
		o.p2 = malloc(n * sizeof(mkVec3));
		o.clear = malloc(n);
		o.path = malloc(n);
		if (!o.status || !o.distance || !o.lower || !o.upper || !o.n || !o.p1 || !o.p2 || !o.clear || !o.path) {
			fprintf(stderr, "mink collide: out of memory for %d pairs\n", in.count);
			rc = 1;
		}
	}
	if (rc == 0) {
		int failed = mkPairs_Run(&in, &o, mode, delta);
		rc = mkPairs_Emit(outpath, &in, &o, mode);
		if (failed) {
			fprintf(stderr, "mink collide: some pairs got no verdict (status unknown): the solver did not converge\n");
			rc = 1;
		}
	}
	free(in.b1); free(in.b2); free(in.line);
	free(o.status); free(o.distance); free(o.lower); free(o.upper);
	free(o.n); free(o.p1); free(o.p2); free(o.clear); free(o.path);
	return rc;
}
