/* args.c - command-line values. */
#include "mink_exp/args.h"

#include <mink/sum.h>

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int mkArg_Long(const char *flag, const char *text, long lo, long hi, long *out,
	char *msg, size_t msglen)
{
	char *end = NULL;
	errno = 0;
	long v = text ? strtol(text, &end, 10) : 0;
	int number = text && text[0] && *end == '\0';
	if (!number || errno != 0 || v < lo || v > hi) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "%s = '%s' is %s: must be an integer in [%ld, %ld]", flag,
				text ? text : "", number ? "out of range" : "not an integer", lo, hi);
		return -1;
	}
	*out = v;
	return 0;
}

int mkArg_Double(const char *flag, const char *text, double lo, double hi, const char *what,
	double *out, char *msg, size_t msglen)
{
	char *end = NULL;
	errno = 0;
	double v = text ? strtod(text, &end) : 0.0;
	int number = text && text[0] && *end == '\0';
	if (!number || errno == ERANGE || !(v >= lo && v <= hi)) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "%s = '%s' is %s: must be %s in [%g, %g]", flag, text ? text : "",
				number ? "out of range" : "not a number", what, lo, hi);
		return -1;
	}
	*out = v;
	return 0;
}

int mkArg_U64(const char *flag, const char *text, uint64_t *out, char *msg, size_t msglen)
{
	char *end = NULL;
	errno = 0;
	int ok = text && text[0] >= '0' && text[0] <= '9';
	uintmax_t v = ok ? strtoumax(text, &end, 0) : 0;
	ok = ok && *end == '\0' && errno == 0 && v <= UINT64_MAX;
	if (!ok) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "%s = '%s' is not allowed: must be an integer in [0, 2^64-1] "
				"(decimal or 0x...)", flag, text ? text : "");
		return -1;
	}
	*out = (uint64_t)v;
	return 0;
}

int mkArg_Choice(const char *flag, const char *text, const char *const *names, int count,
	int *out, char *msg, size_t msglen)
{
	for (int i = 0; text && i < count; ++i) {
		if (strcmp(text, names[i]) == 0) {
			*out = i;
			return 0;
		}
	}
	if (msg && msglen > 0) {
		int n = snprintf(msg, msglen, "%s = '%s' is not allowed: must be one of ", flag, text ? text : "");
		for (int i = 0; i < count && n >= 0 && (size_t)n < msglen; ++i)
			n += snprintf(msg + n, msglen - (size_t)n, "%s%s", i ? ", " : "", names[i]);
	}
	return -1;
}

void mkArgs_Begin(mkArgs *a, int argc, char **argv)
{
	a->argc = argc;
	a->argv = argv;
	a->i = 1;
	a->name[0] = '\0';
}

/* Consumes the next argument: its name (up to any '=') into a->name;
 * returns the '=' of "--name=value", or NULL. */
static const char *mkArgs_Take(mkArgs *a)
{
	const char *arg = a->argv[a->i++];
	const char *eq = strncmp(arg, "--", 2) == 0 ? strchr(arg, '=') : NULL;
	size_t n = eq ? (size_t)(eq - arg) : strlen(arg);
	if (n >= sizeof a->name)
		n = sizeof a->name - 1;
	memcpy(a->name, arg, n);
	a->name[n] = '\0';
	return eq;
}

int mkArg_Impl(const char *flag, const char *text, int *out, char *msg, size_t msglen)
{
	static const char *const names[] = { "auto", "scalar", "avx2", "avx512" };
	int choice = 0;
	if (mkArg_Choice(flag, text, names, 4, &choice, msg, msglen) != 0)
		return -1;
	int impl = mkImpl_Parse(text);
	if (impl < 0 || !mkImpl_Available((mkImpl)impl)) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "%s = '%s' is not available on this CPU or build: must be one of "
				"auto, scalar%s%s", flag, text,
				mkImpl_Available(MK_IMPL_AVX2) ? ", avx2" : "",
				mkImpl_Available(MK_IMPL_AVX512) ? ", avx512" : "");
		return -1;
	}
	*out = impl;
	return 0;
}

int mkArg_Path(const char *flag, const char *text, const char **out, char *msg, size_t msglen)
{
	if (!text || !text[0]) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "%s = '' is not allowed: must be a file path", flag);
		return -1;
	}
	*out = text;
	return 0;
}

/* The table entry of name, or NULL. */
static const mkOption *mkOption_Find(const mkOption *opts, int count, const char *name)
{
	for (int i = 0; i < count; ++i)
		if (strcmp(opts[i].name, name) == 0)
			return &opts[i];
	return NULL;
}

mkArgsStep mkArgs_Step(mkArgs *a, const mkOption *opts, int count, const char **name,
	const char **value, char *msg, size_t msglen)
{
	*name = NULL;
	*value = NULL;
	if (a->i >= a->argc)
		return MK_ARGS_END;
	const char *eq = mkArgs_Take(a);
	*name = a->name;
	int help = strcmp(a->name, "--help") == 0 || strcmp(a->name, "-h") == 0;
	const mkOption *opt = help ? NULL : mkOption_Find(opts, count, a->name);
	if (!help && !opt) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "unknown option '%s' (see --help)", a->name);
		return MK_ARGS_ERROR;
	}
	if (help || !opt->takes_value) {
		if (eq) {
			if (msg && msglen > 0)
				snprintf(msg, msglen, "option %s takes no value", a->name);
			return MK_ARGS_ERROR;
		}
		if (help)
			return MK_ARGS_HELP;
		*name = opt->name;
		return MK_ARGS_OPTION;
	}
	if (eq) {
		*value = eq + 1;
	} else if (a->i < a->argc) {
		*value = a->argv[a->i++];
	} else {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "option %s needs a value (see --help)", a->name);
		return MK_ARGS_ERROR;
	}
	*name = opt->name;
	return MK_ARGS_OPTION;
}

int mkArg_NameList(const char *text, const char *const *names, int count, int *on, char *msg,
	size_t msglen)
{
	int seen[MK_NAMELIST_MAX] = { 0 };
	if (count > MK_NAMELIST_MAX)
		count = MK_NAMELIST_MAX;
	int all = strcmp(text, "all") == 0;
	for (const char *s = text; !all;) {
		size_t len = strcspn(s, ",");
		int found = -1;
		for (int i = 0; i < count; ++i)
			if (strlen(names[i]) == len && strncmp(names[i], s, len) == 0)
				found = i;
		if (found < 0) {
			int n = snprintf(msg, msglen, "is not allowed: must be a comma-separated list of ");
			for (int i = 0; i < count && n >= 0 && (size_t)n < msglen; ++i)
				n += snprintf(msg + n, msglen - (size_t)n, "%s, ", names[i]);
			if (n >= 0 && (size_t)n < msglen)
				snprintf(msg + n, msglen - (size_t)n, "or all");
			return -1;
		}
		seen[found] = 1;
		if (s[len] == '\0')
			break;
		s += len + 1;
	}
	for (int i = 0; i < count; ++i)
		on[i] = all || seen[i];
	return 0;
}
