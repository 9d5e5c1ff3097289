/* cli.c - option parsing of the mink subcommands. */
#include "cli.h"

int mkCli_Parse(const char *cmd, mkFlag *flags, int count, int argc, char **argv, void (*help)(FILE *))
{
	char msg[1024];
	int rc = mkFlags_Parse(flags, count, argc, argv, msg, sizeof msg);
	if (rc == 1) {
		help(stdout);
		mkFlags_Print(stdout, flags, count);
		return 0;
	}
	if (rc != 0) {
		fprintf(stderr, "mink %s: %s\n", cmd, msg);
		return 2;
	}
	return MK_CLI_GO;
}

int mkCli_Require(const char *cmd, const mkFlag *flag)
{
	if (flag->given)
		return MK_CLI_GO;
	fprintf(stderr, "mink %s: %s is required (see --help)\n", cmd, flag->name);
	return 2;
}
