/* test_args.c - command-line values: ranges, one-line messages naming the
 * flag, and the two long-option forms. */
#include "ensure.h"

#include <mink_exp/args.h>

#include <string.h>

int main(void)
{
	char msg[256];
	long v = 0;
	ENSURE(mkArg_Long("--trials", "100", 1, 1000, &v, msg, sizeof msg) == 0 && v == 100);
	ENSURE(mkArg_Long("--trials", "1000", 1, 1000, &v, msg, sizeof msg) == 0 && v == 1000);
	ENSURE(mkArg_Long("--trials", "0", 1, 1000, &v, msg, sizeof msg) != 0);
	ENSURE(strcmp(msg, "--trials = '0' is out of range: must be an integer in [1, 1000]") == 0);
	ENSURE(mkArg_Long("--trials", "12x", 1, 1000, &v, msg, sizeof msg) != 0);
	ENSURE(mkArg_Long("--trials", "", 1, 1000, &v, msg, sizeof msg) != 0);
	ENSURE(mkArg_Long("--trials", NULL, 1, 1000, &v, msg, sizeof msg) != 0);
	ENSURE(mkArg_Long("--trials", "99999999999999999999999", 1, 1000, &v, msg, sizeof msg) != 0);

	double d = 0.0;
	ENSURE(mkArg_Double("--margin", "0.25", 0.0, 1.0, "a number", &d, msg, sizeof msg) == 0 && d == 0.25);
	ENSURE(mkArg_Double("--margin", "1", 0.0, 1.0, "a number", &d, msg, sizeof msg) == 0 && d == 1.0);
	ENSURE(mkArg_Double("--margin", "1.5", 0.0, 1.0, "a number", &d, msg, sizeof msg) != 0 && d == 1.0);
	ENSURE(strcmp(msg, "--margin = '1.5' is out of range: must be a number in [0, 1]") == 0);
	ENSURE(mkArg_Double("--budget", "2s", 0.0, 10.0, "a number of seconds", &d, msg, sizeof msg) != 0);
	ENSURE(strcmp(msg, "--budget = '2s' is not a number: must be a number of seconds in [0, 10]") == 0);
	ENSURE(mkArg_Double("--margin", "nan", 0.0, 1.0, "a number", &d, msg, sizeof msg) != 0);
	ENSURE(mkArg_Double("--margin", "", 0.0, 1.0, "a number", &d, msg, sizeof msg) != 0);
	ENSURE(mkArg_Double("--margin", NULL, 0.0, 1.0, "a number", &d, msg, sizeof msg) != 0);
	ENSURE(mkArg_Double("--margin", "1e999", 0.0, 1e300, "a number", &d, msg, sizeof msg) != 0);

	uint64_t u = 0;
	ENSURE(mkArg_U64("--seed", "18446744073709551615", &u, msg, sizeof msg) == 0 && u == UINT64_MAX);
	ENSURE(mkArg_U64("--seed", "0x10", &u, msg, sizeof msg) == 0 && u == 16);
	ENSURE(mkArg_U64("--seed", "18446744073709551616", &u, msg, sizeof msg) != 0);
	ENSURE(mkArg_U64("--seed", "-1", &u, msg, sizeof msg) != 0);
	ENSURE(strncmp(msg, "--seed = '", 10) == 0);

	static const char *const dims[] = { "2", "3", "both" };
	int c = -1;
	ENSURE(mkArg_Choice("--dim", "both", dims, 3, &c, msg, sizeof msg) == 0 && c == 2);
	ENSURE(mkArg_Choice("--dim", "4", dims, 3, &c, msg, sizeof msg) != 0);
	ENSURE(strcmp(msg, "--dim = '4' is not allowed: must be one of 2, 3, both") == 0);

	mkArgs a;
	const char *name, *value;
	/* mkArgs_Step: the table decides which options take values. */
	static const mkOption opts[] = { { "--n", 1 }, { "--seed", 1 }, { "--force", 0 } };
	char *argv2[] = { "prog", "--n", "5", "--seed=9", "--force", "-h", "--force=1", "--bogus", "--n" };
	mkArgs_Begin(&a, 9, argv2);
	ENSURE(mkArgs_Step(&a, opts, 3, &name, &value, msg, sizeof msg) == MK_ARGS_OPTION);
	ENSURE(strcmp(name, "--n") == 0 && value && strcmp(value, "5") == 0);
	ENSURE(mkArgs_Step(&a, opts, 3, &name, &value, msg, sizeof msg) == MK_ARGS_OPTION);
	ENSURE(strcmp(name, "--seed") == 0 && value && strcmp(value, "9") == 0);
	ENSURE(mkArgs_Step(&a, opts, 3, &name, &value, msg, sizeof msg) == MK_ARGS_OPTION);
	ENSURE(strcmp(name, "--force") == 0 && value == NULL);
	ENSURE(mkArgs_Step(&a, opts, 3, &name, &value, msg, sizeof msg) == MK_ARGS_HELP);
	ENSURE(mkArgs_Step(&a, opts, 3, &name, &value, msg, sizeof msg) == MK_ARGS_ERROR);
	ENSURE(strcmp(msg, "option --force takes no value") == 0);
	ENSURE(mkArgs_Step(&a, opts, 3, &name, &value, msg, sizeof msg) == MK_ARGS_ERROR);
	ENSURE(strcmp(msg, "unknown option '--bogus' (see --help)") == 0);
	ENSURE(mkArgs_Step(&a, opts, 3, &name, &value, msg, sizeof msg) == MK_ARGS_ERROR);
	ENSURE(strcmp(msg, "option --n needs a value (see --help)") == 0);
	ENSURE(mkArgs_Step(&a, opts, 3, &name, &value, msg, sizeof msg) == MK_ARGS_END);
	/* name lists: "all", a subset in any order, an unknown name */
	{
		static const char *const names[] = { "EE", "ES", "SQ" };
		int on[3] = { 0, 0, 0 };
		ENSURE(mkArg_NameList("all", names, 3, on, msg, sizeof msg) == 0 && on[0] && on[1] && on[2]);
		ENSURE(mkArg_NameList("SQ,EE", names, 3, on, msg, sizeof msg) == 0 && on[0] && !on[1] && on[2]);
		ENSURE(mkArg_NameList("EE,XY", names, 3, on, msg, sizeof msg) == -1);
		ENSURE(strcmp(msg, "is not allowed: must be a comma-separated list of EE, ES, SQ, or all") == 0);
	}
	return mk_summary("common.test_args");
}
