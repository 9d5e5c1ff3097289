/* cli.h - small helpers shared by the subcommands of `mink`: option values
 * with range checks and messages that name the option, the value and the
 * allowed range. */
#ifndef MINK_CLI_H
#define MINK_CLI_H

#include <stdio.h>

/* The value after option argv[*i], advancing *i; NULL (with a message on
 * stderr) when it is missing. */
const char *mkCli_Value(int argc, char **argv, int *i);
/* Parse an integer in [lo, hi]; 0 on success, -1 with a message on stderr. */
int mkCli_Int(const char *opt, const char *s, long lo, long hi, long *out);
/* Parse one of the names of an enum via its parse function; -1 with a
 * message listing `choices` on failure. */
int mkCli_Choice(const char *opt, const char *s, int (*parse)(const char *), const char *choices, int *out);
/* 1 when argv[i] is -h or --help. */
int mkCli_IsHelp(const char *arg);
/* Report an unknown option and point at --help. Returns 2. */
int mkCli_Unknown(const char *cmd, const char *arg);

#endif
