/* mink_exp/driver.h - the harness every experiment driver runs on.
 *
 * A driver declares what it is (an mkDriver: name, purpose, CSV columns,
 * which shared options it takes and their defaults) and its own options (an
 * array of mkFlag pointing into its options struct); the harness does the
 * rest: the option loop with one message style, --help (its options, the
 * shared ones and the CSV columns), the checks of --out (refused when it
 * exists unless --force; parent folders made), the default and shard-named
 * output paths, the sidecar's shared keys (seed, trials, shard, trial_range),
 * the CSV opened under a temporary name and committed or discarded at the
 * end, and progress on stderr.
 *
 *   static const char *const columns[] = { "dim", "trial", ... };
 *   static const mkDriver driver = { "validation", "The numerical ...",
 *       2, columns, MK_SHARED_TRIALS | MK_SHARED_SEED | MK_SHARED_SHARD, 100, 10000000, 2022, NULL };
 *   int main(int argc, char **argv) {
 *       MyOptions o = defaults;
 *       mkFlag flags[] = { MK_FLAG_LONG("--n", "N", "points on B1", &o.n, 1, 10000000), ... };
 *       mkRun run;
 *       MK_RUN_BEGIN(&run, &driver, flags, argc, argv);   // returns from main on --help or a bad flag
 *       mkMeta_Set(&run.meta, "my_key", "...");        // the driver's own sidecar keys
 *       if (mkRun_OpenCsv(&run, run.end - run.begin) != 0) return mkRun_End(&run, 1);
 *       for (long t = run.begin; t < run.end; ++t) { ...rows into run.csv...; mkRun_Step(&run, 1); }
 *       return mkRun_End(&run, failed);
 *   }
 *
 * Messages: every bad option gives one line "<driver>: <flag> = '<value>'
 * is <what>: must be <allowed>" (the style of the core's SPEC messages), e.g.
 *   validation: --trials = '0' is out of range: must be an integer in [1, 10000000]
 * and exit status 2; a failure to write gives "<driver>: <why>" and 1. */
#ifndef MINK_EXP_DRIVER_H
#define MINK_EXP_DRIVER_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "args.h"
#include "csv.h"
#include "meta.h"
#include "outfile.h"
#include "progress.h"
#include "shard.h"

/* ---- options ------------------------------------------------------------- */

typedef enum mkFlagKind {
	MK_FLAG_SWITCH,  /* no value; *(int *)value = 1 */
	MK_FLAG_LONG,    /* an integer in [lo, hi]; long * */
	MK_FLAG_DOUBLE,  /* a finite number in [lo, hi]; double * */
	MK_FLAG_U64,     /* any unsigned 64-bit integer, decimal or 0x; uint64_t * */
	MK_FLAG_CHOICE,  /* one of choices[]; int * receives its index */
	MK_FLAG_PATH,    /* a non-empty path; const char ** */
	MK_FLAG_IMPL,    /* a kernel this CPU runs (auto|scalar|avx2|avx512); int * (mkImpl) */
	MK_FLAG_TEXT,    /* any text, checked by parse (when not NULL); const char ** */
	MK_FLAG_REPEAT   /* any text, may be given many times: parse is called for each */
} mkFlagKind;

typedef struct mkFlag {
	const char *name;   /* "--trials" */
	const char *arg;    /* its value's name in --help ("T"); NULL for a switch */
	const char *help;   /* what it does, with its range and default; "\n" breaks lines */
	mkFlagKind kind;
	void *value;
	double lo, hi;                 /* MK_FLAG_LONG, MK_FLAG_DOUBLE */
	const char *const *choices;    /* MK_FLAG_CHOICE */
	int choice_count;
	/* MK_FLAG_TEXT / MK_FLAG_REPEAT: check (and store) one value; returns 0,
	 * or -1 with a message of the form "is <what>: must be <allowed>" (the
	 * harness puts "<flag> = '<value>' " in front). `context` is the flag's
	 * value pointer. */
	int (*parse)(void *context, const char *text, char *msg, size_t msglen);
	int given;                     /* set by the harness: how often it appeared */
} mkFlag;

#define MK_FLAG_SWITCH(name, help, ptr) { name, NULL, help, MK_FLAG_SWITCH, ptr, 0, 0, NULL, 0, NULL, 0 }
#define MK_FLAG_LONG(name, arg, help, ptr, lo, hi) { name, arg, help, MK_FLAG_LONG, ptr, lo, hi, NULL, 0, NULL, 0 }
#define MK_FLAG_DOUBLE(name, arg, help, ptr, lo, hi) { name, arg, help, MK_FLAG_DOUBLE, ptr, lo, hi, NULL, 0, NULL, 0 }
#define MK_FLAG_U64(name, arg, help, ptr) { name, arg, help, MK_FLAG_U64, ptr, 0, 0, NULL, 0, NULL, 0 }
#define MK_FLAG_CHOICE(name, arg, help, ptr, names) \
	{ name, arg, help, MK_FLAG_CHOICE, ptr, 0, 0, names, MK_COUNT(names), NULL, 0 }
/* A "--set contact|plus" choice: *ptr (an int) gets the mkSet value
 * (MK_SET_CONTACT 0, MK_SET_PLUS 1). */
extern const char *const mkFlag_SetNames[2];
#define MK_FLAG_SET(name, help, ptr) \
	{ name, "contact|plus", help, MK_FLAG_CHOICE, ptr, 0, 0, mkFlag_SetNames, MK_COUNT(mkFlag_SetNames), NULL, 0 }
#define MK_FLAG_PATH(name, arg, help, ptr) { name, arg, help, MK_FLAG_PATH, ptr, 0, 0, NULL, 0, NULL, 0 }
#define MK_FLAG_IMPL(name, help, ptr) \
	{ name, "auto|scalar|avx2|avx512", help, MK_FLAG_IMPL, ptr, 0, 0, NULL, 0, NULL, 0 }
#define MK_FLAG_TEXT(name, arg, help, ptr, fn) { name, arg, help, MK_FLAG_TEXT, ptr, 0, 0, NULL, 0, fn, 0 }
#define MK_FLAG_REPEAT(name, arg, help, ptr, fn) { name, arg, help, MK_FLAG_REPEAT, ptr, 0, 0, NULL, 0, fn, 0 }

/* The parse function of a MK_FLAG_TEXT flag "I/N" that splits a run
 * (mink_exp/shard.h); context is an mkShard *. */
int mkShard_ParseFlag(void *context, const char *text, char *msg, size_t msglen);

/* Parse argv against `flags` (and --help). Returns 0 to go on, 1 when --help
 * was asked for, -1 on an error (msg holds "<flag>: <why>"). Exposed for the
 * `mink` subcommands, which have no CSV of their own. */
int mkFlags_Parse(mkFlag *flags, int count, int argc, char **argv, char *msg, size_t msglen);
/* The options part of --help: one entry per flag. */
void mkFlags_Print(FILE *fp, const mkFlag *flags, int count);

/* ---- drivers ------------------------------------------------------------- */

/* The options the harness owns; a driver takes those it names. */
typedef enum mkShared {
	MK_SHARED_TRIALS = 1,  /* --trials T (default mkDriver.trials) */
	MK_SHARED_SEED = 2,    /* --seed S (default mkDriver.seed) */
	MK_SHARED_SHARD = 4    /* --shard I/N: the trials [begin, end) of block I of N */
} mkShared;
/* Every driver takes --out PATH (default results/<name>.csv, or
 * results/<name>.shard-I-of-N.csv with --shard), --force and --help. */

typedef struct mkDriver {
	const char *name;        /* program, experiment and default file name */
	const char *purpose;     /* a few lines for --help */
	int schema_version;      /* of its CSV (sidecar key schema_version) */
	const char *const *columns;  /* the CSV's header, ended by NULL */
	unsigned shared;         /* mkShared bits */
	long trials;             /* default --trials (MK_SHARED_TRIALS) */
	long trials_max;         /* its upper bound (the lower is 1) */
	uint64_t seed;           /* default --seed (MK_SHARED_SEED) */
	const char *notes;       /* lines after the options in --help, or NULL */
} mkDriver;

/* The number of columns (before the NULL). */
int mkDriver_ColumnCount(const mkDriver *d);

/* A run in progress: the parsed shared options and the open result. */
typedef struct mkRun {
	const mkDriver *driver;
	long trials;
	uint64_t seed;
	mkShard shard;
	long begin, end;         /* the trials of this shard: [begin, end) */
	int force;
	const char *out;         /* the result's path */
	mkMeta meta;             /* the sidecar; shared keys set by mkRun_Begin */
	mkCsv csv;
	int csv_open;
	mkProgress progress;
	char outbuf[MK_PATH_MAX];
} mkRun;

#define MK_RUN_GO 0          /* mkRun_Begin: go on */
#define MK_RUN_HELP 1        /* --help was printed: exit 0 */
#define MK_RUN_USAGE 2       /* a bad option, message printed: exit 2 */
#define MK_RUN_FAILED 3      /* --out refused or not creatable, message printed: exit 1 */

/* Parse argv (the driver's flags and the shared ones), print --help or the
 * error, check --out and start the sidecar (mkMeta_Init plus seed, trials,
 * shard and trial_range when the driver takes them). Returns one of
 * MK_RUN_*; only on MK_RUN_GO is the run live (end it with mkRun_End). */
int mkRun_Begin(mkRun *run, const mkDriver *d, mkFlag *flags, int count, int argc, char **argv);
/* The process exit status for a status of mkRun_Begin other than MK_RUN_GO. */
int mkRun_Status(int begin_status);
/* In a driver's main: mkRun_Begin over the array `flags`, returning the
 * exit status from main unless the run goes on. */
#define MK_RUN_BEGIN(run, driver, flags, argc, argv) \
	do { \
		int mk_begin = mkRun_Begin(run, driver, flags, MK_COUNT(flags), argc, argv); \
		if (mk_begin != MK_RUN_GO) \
			return mkRun_Status(mk_begin); \
	} while (0)

/* Open the CSV (temporary file, header of the driver's columns) and start
 * the progress line over `units` steps. Returns 0, or -1 after printing why. */
int mkRun_OpenCsv(mkRun *run, long units);
/* Count `steps` more units done on the progress line. */
void mkRun_Step(mkRun *run, long steps);
/* Print "<driver>: <message>" on stderr (printf-style). */
void mkRun_Fail(const mkRun *run, const char *fmt, ...);

/* The end: when `failed` the CSV is discarded, else it is committed with the
 * sidecar. Frees everything. Returns the exit status (0 written, 1 not). */
int mkRun_End(mkRun *run, int failed);

/* The path of a further file of a driver that writes more than one:
 * "<out without .csv or .csv.gz>/<name>" (results/demos.csv, "fig3.csv" ->
 * results/demos/fig3.csv; name it "*.csv.gz" to store it compressed). */
void mkPath_Sibling(const char *out, const char *name, char *buf, size_t len);
/* Open such a file as CSV (its folder made first). Returns 0, or -1 after
 * printing "<driver>: <why>". */
int mkRun_OpenSibling(const mkRun *run, const char *name, const char *const *columns, int count, mkCsv *csv);

#endif
