/* main.c - the `mink` command: closed-form Minkowski sums and their
 * baselines from the command line. */
#include <stdio.h>
#include <string.h>

#include <mink/mink.h>

#include "commands.h"

typedef struct mkCommand {
	const char *name;
	int (*run)(int argc, char **argv);
	const char *summary;
} mkCommand;

static const mkCommand commands[] = {
	{"sum", mkCmd_Sum, "boundary points of B1 (+) B2 or of the contact space B1 (+) (-B2), as CSV"},
	{"scene", mkCmd_Scene, "certified C-obstacles of a scene file, inner and outer, as CSV"},
	{"bench", mkCmd_Bench, "ns per boundary point of the closed forms, as CSV"},
#ifdef MINK_HAVE_REGISTRY
	{"methods", mkCmd_Methods, "list the registered methods (closed forms and baselines)"},
	{"verify", mkCmd_Verify, "put a method's output through the exact (CGAL) referee"},
	{"score", mkCmd_Score, "the error of any boundary point set against the true sum (mink/score.h)"},
#endif
#ifdef MINK_HAVE_COLLIDE
	{"collide", mkCmd_Collide, "collision status, distance or penetration and witnesses of two bodies"},
#endif
#ifdef MINK_HAVE_PLAN
	{"plan", mkCmd_Plan, "paths for a scene's planning queries (OMPL, certified checks), or --check a path"},
#endif
};

static void usage(FILE *f)
{
	fprintf(f, "usage: mink COMMAND [options]   (mink COMMAND --help for its options)\n\ncommands:\n");
	for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i)
		fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].summary);
	fprintf(f, "\nmink %s\n", mkVersion());
}

int main(int argc, char **argv)
{
	if (argc < 2) {
		usage(stderr);
		return 2;
	}
	if (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "help") == 0) {
		usage(stdout);
		return 0;
	}
	if (strcmp(argv[1], "--version") == 0) {
		printf("mink %s\n", mkVersion());
		return 0;
	}
	for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i)
		if (strcmp(argv[1], commands[i].name) == 0) return commands[i].run(argc - 1, argv + 1);
	fprintf(stderr, "mink: unknown command '%s'\n\n", argv[1]);
	usage(stderr);
	return 2;
}
