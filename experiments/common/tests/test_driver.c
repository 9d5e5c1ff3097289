/* test_driver.c - the harness of the drivers (mink_exp/driver.h), tested
 * once for every driver: the shared options, their messages, --help, the
 * default and shard-named output paths, the sidecar's shared keys and the
 * commit-or-discard ending. The expected texts are written out here by hand. */
#define _POSIX_C_SOURCE 200809L
#include <mink_exp/exp.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "ensure.h"

static const char *const mkColumns[] = { "trial", "value", NULL };
static const mkDriver mkTestDriver = {
	"demo", "A driver for the tests.", 1, mkColumns,
	MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 10, 1000, 7, "A note.",
};
static const char *const mkFruit[] = { "apple", "pear" };

typedef struct mkOpts { long n; double x; int fruit, flag; const char *path; } mkOpts;

/* Parse argv (a NULL-ended list after the program name) with the test
 * flags; msg receives the message. */
static int mkParse(mkOpts *o, char *msg, size_t len, const char *const *args)
{
	char *argv[32] = { "demo" };
	int argc = 1;
	while (args[argc - 1])
		argv[argc] = (char *)args[argc - 1], ++argc;
	mkFlag flags[] = {
		MK_FLAG_LONG("--n", "N", "count", &o->n, 1, 100),
		MK_FLAG_DOUBLE("--x", "X", "a number", &o->x, 0.0, 1.0),
		MK_FLAG_CHOICE("--fruit", "F", "kind", &o->fruit, mkFruit),
		MK_FLAG_SWITCH("--flag", "on", &o->flag),
		MK_FLAG_PATH("--path", "P", "file", &o->path),
	};
	msg[0] = '\0';
	return mkFlags_Parse(flags, MK_COUNT(flags), argc, argv, msg, len);
}

#define MK_ARGS(...) ((const char *const[]){ __VA_ARGS__, NULL })

static void mkTestFlags(void)
{
	mkOpts o = { 5, 0.5, 0, 0, NULL };
	char msg[512];
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--n", "7", "--x=0.25", "--fruit", "pear", "--flag")) == 0);
	ENSURE(o.n == 7 && o.x == 0.25 && o.fruit == 1 && o.flag == 1);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--n", "0")) == -1);
	ENSURE(strcmp(msg, "--n = '0' is out of range: must be an integer in [1, 100]") == 0);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--x", "2")) == -1);
	ENSURE(strcmp(msg, "--x = '2' is out of range: must be a number in [0, 1]") == 0);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--fruit", "plum")) == -1);
	ENSURE(strcmp(msg, "--fruit = 'plum' is not allowed: must be one of apple, pear") == 0);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--bogus", "1")) == -1);
	ENSURE(strcmp(msg, "unknown option '--bogus' (see --help)") == 0);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--n")) == -1);
	ENSURE(strcmp(msg, "option --n needs a value (see --help)") == 0);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--flag=1")) == -1);
	ENSURE(strcmp(msg, "option --flag takes no value") == 0);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--n", "3", "--n", "4")) == -1);
	ENSURE(strcmp(msg, "option --n is given twice") == 0);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--path", "")) == -1);
	ENSURE(strcmp(msg, "--path = '' is not allowed: must be a file path") == 0);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("--help")) == 1);
	ENSURE(mkParse(&o, msg, sizeof msg, MK_ARGS("-h")) == 1);
}

/* mkRun_Begin with stderr captured into err. */
static int mkBegin(mkRun *run, char *err, size_t len, const char *const *args)
{
	char *argv[32] = { "demo" };
	int argc = 1;
	while (args[argc - 1])
		argv[argc] = (char *)args[argc - 1], ++argc;
	fflush(stderr);
	int saved = dup(2);
	FILE *cap = tmpfile();
	dup2(fileno(cap), 2);
	long n = 1;
	mkFlag flags[] = { MK_FLAG_LONG("--n", "N", "count", &n, 1, 100) };
	int status = mkRun_Begin(run, &mkTestDriver, flags, MK_COUNT(flags), argc, argv);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	rewind(cap);
	size_t got = fread(err, 1, len - 1, cap);
	err[got] = '\0';
	fclose(cap);
	return status;
}

static void mkTestShared(const char *dir)
{
	mkRun run;
	char err[1024], path[512];
	ENSURE(mkBegin(&run, err, sizeof err, MK_ARGS("--trials", "0")) == MK_RUN_USAGE);
	ENSURE(strcmp(err, "demo: --trials = '0' is out of range: must be an integer in [1, 1000]\n") == 0);
	ENSURE(mkBegin(&run, err, sizeof err, MK_ARGS("--seed", "x")) == MK_RUN_USAGE);
	ENSURE(strcmp(err, "demo: --seed = 'x' is not allowed: must be an integer in [0, 2^64-1] (decimal or 0x...)\n") == 0);
	ENSURE(mkBegin(&run, err, sizeof err, MK_ARGS("--shard", "2/2")) == MK_RUN_USAGE);
	ENSURE(strcmp(err, "demo: --shard = '2/2' is not allowed: must be I/N with 1 <= N <= 1000000 and 0 <= I < N\n") == 0);
	ENSURE(mkBegin(&run, err, sizeof err, MK_ARGS("--force=1")) == MK_RUN_USAGE);
	ENSURE(strcmp(err, "demo: option --force takes no value\n") == 0);
	ENSURE(mkRun_Status(MK_RUN_USAGE) == 2 && mkRun_Status(MK_RUN_HELP) == 0 && mkRun_Status(MK_RUN_FAILED) == 1);

	/* a run: shared keys in the sidecar, the CSV committed */
	snprintf(path, sizeof path, "%s/sub/run.csv", dir);
	char side[600];
	snprintf(side, sizeof side, "%s.meta", path);
	remove(path);
	remove(side);
	ENSURE(mkBegin(&run, err, sizeof err, MK_ARGS("--trials", "5", "--seed", "9", "--shard", "1/2", "--out", path))
		== MK_RUN_GO);
	ENSURE(run.begin == 2 && run.end == 5 && run.seed == 9 && strcmp(run.out, path) == 0);
	ENSURE(strcmp(mkMeta_Get(&run.meta, "shard"), "1/2") == 0);
	ENSURE(strcmp(mkMeta_Get(&run.meta, "trial_range"), "2..4") == 0);
	ENSURE(strcmp(mkMeta_Get(&run.meta, "seed"), "9") == 0);
	ENSURE(mkRun_OpenCsv(&run, 3) == 0);
	for (long t = run.begin; t < run.end; ++t) {
		mkCsv_Int(&run.csv, t);
		mkCsv_Double(&run.csv, 0.5 * (double)t);
		mkCsv_EndRow(&run.csv);
	}
	ENSURE(mkRun_End(&run, 0) == 0);
	mkTable t;
	mkTable_Load(&t, path);
	ENSURE(t.present && t.rows == 3 && t.cols == 2 && mkTable_Num(&t, 2, mkTable_Col(&t, "value")) == 2.0);
	mkTable_Free(&t);

	/* an existing result is refused without --force, kept as it was */
	ENSURE(mkBegin(&run, err, sizeof err, MK_ARGS("--out", path)) == MK_RUN_FAILED);
	ENSURE(strstr(err, "exists") != NULL);
	/* a failed run leaves the previous result */
	ENSURE(mkBegin(&run, err, sizeof err, MK_ARGS("--out", path, "--force")) == MK_RUN_GO);
	ENSURE(mkRun_OpenCsv(&run, 1) == 0);
	ENSURE(mkRun_End(&run, 1) == 1);
	mkTable_Load(&t, path);
	ENSURE(t.present && t.rows == 3);
	mkTable_Free(&t);

	/* the shard-named default path */
	ENSURE(mkBegin(&run, err, sizeof err, MK_ARGS("--shard", "3/8")) == MK_RUN_GO);
	ENSURE(strcmp(run.out, "results/demo.shard-3-of-8.csv") == 0);
	mkMeta_Free(&run.meta);

	char sib[256];
	mkPath_Sibling("results/demos.csv", "fig3.csv", sib, sizeof sib);
	ENSURE(strcmp(sib, "results/demos/fig3.csv") == 0);
}

/* --help names the options, the shared ones and every column. */
static void mkTestHelp(void)
{
	fflush(stdout);
	int saved = dup(1);
	FILE *cap = tmpfile();
	dup2(fileno(cap), 1);
	mkRun run;
	char err[256];
	int status = mkBegin(&run, err, sizeof err, MK_ARGS("--help"));
	fflush(stdout);
	dup2(saved, 1);
	close(saved);
	rewind(cap);
	char text[4096];
	size_t got = fread(text, 1, sizeof text - 1, cap);
	text[got] = '\0';
	fclose(cap);
	ENSURE(status == MK_RUN_HELP);
	ENSURE(strstr(text, "usage: demo [options]") != NULL);
	ENSURE(strstr(text, "--n N") != NULL && strstr(text, "--trials T") != NULL);
	ENSURE(strstr(text, "--shard I/N") != NULL && strstr(text, "--force") != NULL);
	ENSURE(strstr(text, "trial, value") != NULL);
	ENSURE(strstr(text, "A note.") != NULL);
}

int main(int argc, char **argv)
{
	const char *dir = argc > 1 ? argv[1] : ".";
	mkTestFlags();
	mkTestShared(dir);
	mkTestHelp();
	return mk_summary("mink_exp.driver");
}
