/* mink_exp/args.h - command-line values with ranges, for the drivers.
 *
 * Each parser takes the flag name (for the message), the text and the
 * allowed range; on failure it returns -1 and writes one line such as
 *   --trials = '0' is out of range: must be an integer in [1, 10000000]
 * (the style of the core's SPEC messages: "<field> = <value> is <what>:
 * must be <allowed>")
 * and on success returns 0. */
#ifndef MINK_EXP_ARGS_H
#define MINK_EXP_ARGS_H

#include <stddef.h>
#include <stdint.h>

int mkArg_Long(const char *flag, const char *text, long lo, long hi, long *out,
	char *msg, size_t msglen);
/* A finite real number in [lo, hi]; `what` names it in the message
 * ("a number", "a number of seconds"). */
int mkArg_Double(const char *flag, const char *text, double lo, double hi, const char *what,
	double *out, char *msg, size_t msglen);

/* Any unsigned 64-bit integer, decimal or 0x hexadecimal. */
int mkArg_U64(const char *flag, const char *text, uint64_t *out, char *msg, size_t msglen);
/* One of `count` names; *out is its index. */
int mkArg_Choice(const char *flag, const char *text, const char *const *names, int count,
	int *out, char *msg, size_t msglen);

/* "all" or a comma-separated list of names out of `names` (a MK_FLAG_TEXT
 * parse step): on[i] = 1 for the names given (all of them for "all"),
 * else 0. Returns 0, or -1 with "is not allowed: must be a comma-separated
 * list of a, b, ..., or all". At most MK_NAMELIST_MAX names are known. */
#define MK_NAMELIST_MAX 64
int mkArg_NameList(const char *text, const char *const *names, int count, int *on, char *msg, size_t msglen);

/* A kernel name (auto, scalar, avx2, avx512) that this CPU and build can
 * run (mkImpl_Available); *out is an mkImpl value. */
int mkArg_Impl(const char *flag, const char *text, int *out, char *msg, size_t msglen);
/* A non-empty file path; *out points into text. */
int mkArg_Path(const char *flag, const char *text, const char **out, char *msg, size_t msglen);

/* The state of a walk over argv in the usual long-option forms
 * "--name value" and "--name=value" (see mkArgs_Step). */
typedef struct mkArgs {
	int argc;
	char **argv;
	int i;
	char name[64];
} mkArgs;

void mkArgs_Begin(mkArgs *a, int argc, char **argv);

/* One option a command accepts: its name with dashes, and whether it takes a
 * value ("--trials" 1) or is a flag ("--force" 0). */
/* Entries of a static array. */
#define MK_COUNT(table) ((int)(sizeof(table) / sizeof((table)[0])))

typedef struct mkOption {
	const char *name;
	int takes_value;
} mkOption;

typedef enum mkArgsStep {
	MK_ARGS_END,    /* no more arguments */
	MK_ARGS_HELP,   /* --help or -h (always accepted) */
	MK_ARGS_OPTION, /* *name is one of the table's names; *value its value (NULL for a flag) */
	MK_ARGS_ERROR   /* msg says which: an unknown option, a missing value, or a value given to a flag */
} mkArgsStep;

/* The next option of argv checked against the table of `count` options: the
 * whole loop of a command is
 *   while ((step = mkArgs_Step(&a, opts, n, &name, &value, msg, len)) == MK_ARGS_OPTION)
 *       ... one branch per name, each parsing value with an mkArg_ parser ...
 * followed by the handling of MK_ARGS_HELP and MK_ARGS_ERROR. */
mkArgsStep mkArgs_Step(mkArgs *a, const mkOption *opts, int count, const char **name,
	const char **value, char *msg, size_t msglen);

#endif
