/* cli.c - option parsing helpers for the mink subcommands. */
#include "cli.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

const char *mkCli_Value(int argc, char **argv, int *i)
{
	if (*i + 1 >= argc) {
		fprintf(stderr, "mink: option %s needs a value\n", argv[*i]);
		return NULL;
	}
	return argv[++*i];
}

int mkCli_Int(const char *opt, const char *s, long lo, long hi, long *out)
{
	char *end;
	errno = 0;
	long v = strtol(s, &end, 10);
	if (end == s || *end) {
		fprintf(stderr, "mink: %s = '%s' is not an integer: must be an integer in [%ld, %ld]\n", opt, s, lo, hi);
		return -1;
	}
	if (errno == ERANGE || v < lo || v > hi) {
		fprintf(stderr, "mink: %s = '%s' is out of range: must be an integer in [%ld, %ld]\n", opt, s, lo, hi);
		return -1;
	}
	*out = v;
	return 0;
}

int mkCli_Choice(const char *opt, const char *s, int (*parse)(const char *), const char *choices, int *out)
{
	int v = parse(s);
	if (v < 0) {
		fprintf(stderr, "mink: %s = '%s' is not allowed: must be one of %s\n", opt, s, choices);
		return -1;
	}
	*out = v;
	return 0;
}

int mkCli_IsHelp(const char *arg)
{
	return strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0;
}

int mkCli_Unknown(const char *cmd, const char *arg)
{
	fprintf(stderr, "mink %s: unknown option '%s' (see 'mink %s --help')\n", cmd, arg, cmd);
	return 2;
}
