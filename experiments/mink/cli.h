/* cli.h - the option parsing of the `mink` subcommands: the flag parser of
 * the experiment drivers (mink_exp/driver.h), with the messages prefixed by
 * "mink <command>: ". */
#ifndef MINK_EXP_CLI_H
#define MINK_EXP_CLI_H

#include <stdio.h>

#include <mink_exp/driver.h>

#define MK_CLI_GO (-1)

/* Parse argv (argv[0] is the subcommand) against flags. Returns MK_CLI_GO
 * to go on, 0 after printing --help (help(stdout) then the options), or 2
 * after printing "mink <cmd>: <message>" on a bad option. */
int mkCli_Parse(const char *cmd, mkFlag *flags, int count, int argc, char **argv, void (*help)(FILE *));

/* 2 after "mink <cmd>: <option> is required (see --help)" unless the flag
 * was given; MK_CLI_GO when it was. */
int mkCli_Require(const char *cmd, const mkFlag *flag);

#endif
