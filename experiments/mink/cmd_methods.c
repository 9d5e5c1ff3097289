/* cmd_methods.c - `mink methods`: the registered methods, as a table or CSV. */
#include <stdio.h>
#include <string.h>

#include <mink/registry.h>

#include "cli.h"
#include "commands.h"

static void help(FILE *fp)
{
	fprintf(fp, "usage: mink methods [--csv]\n"
		"\n"
		"List the registered ways of computing a Minkowski-sum boundary: the closed\n"
		"forms and the baselines of the paper's Table 1. Each runs with\n"
		"  mink sum --method NAME --dim 2|3 --body1 SPEC --body2 SPEC --n N\n"
		"and its output is checked with 'mink verify'.\n"
		"  exact    its points lie on the smooth boundary (to rounding); approx: within\n"
		"           the accuracy the method states (mkMethod_Tolerance)\n"
		"  sampled  N is samples per body (3D: an N x N grid per body) and the output\n"
		"           is the vertices of the hull of all pairwise sums\n"
		"With --csv, one row per method: name,dims,exact,sampled,n2,n3,summary,reference\n\n");
}

static const char *dims(const mkMethod *m)
{
	int two = !!(m->flags & MK_METHOD_2D), three = !!(m->flags & MK_METHOD_3D);
	return two && three ? "2D,3D" : two ? "2D" : three ? "3D" : "-";
}

/* The allowed n in a dimension, as "[lo, hi]", or "-". */
static void range(const mkMethod *m, int dim, char *buf, size_t len)
{
	char msg[256];
	if (!(m->flags & (dim == 2 ? MK_METHOD_2D : MK_METHOD_3D))) {
		snprintf(buf, len, "-");
		return;
	}
	/* The registry's message for an impossible n names the range. */
	mkMethod_CheckN(m, dim, -1, msg, sizeof msg);
	const char *open = strrchr(msg, '[');
	snprintf(buf, len, "%s", open ? open : "?");
}

static void csv_field(const char *s)
{
	if (!strpbrk(s, ",\"\n")) {
		fputs(s, stdout);
		return;
	}
	putchar('"');
	for (; *s; ++s) {
		if (*s == '"') putchar('"');
		putchar(*s);
	}
	putchar('"');
}

int mkCmd_Methods(int argc, char **argv)
{
	int csv = 0;
	mkFlag flags[] = { MK_FLAG_SWITCH("--csv", "the table as CSV", &csv) };
	int rc = mkCli_Parse("methods", flags, MK_COUNT(flags), argc, argv, help);
	if (rc != MK_CLI_GO)
		return rc;
	int count = mkRegistry_Count();
	if (csv) printf("name,dims,exact,sampled,n2,n3,summary,reference\n");
	else printf("%-19s %-6s %-6s %-7s %-16s %-11s %s\n", "name", "dims", "exact", "sampled", "n (2D)", "n (3D)", "summary");
	for (int i = 0; i < count; ++i) {
		const mkMethod *m = mkRegistry_At(i);
		char r2[64], r3[64];
		range(m, 2, r2, sizeof r2);
		range(m, 3, r3, sizeof r3);
		const char *exact = (m->flags & MK_METHOD_EXACT) ? "yes" : (m->flags & MK_METHOD_APPROX) ? "approx" : "no";
		const char *sampled = (m->flags & MK_METHOD_SAMPLED) ? "yes" : "no";
		if (csv) {
			csv_field(m->name);
			putchar(',');
			csv_field(dims(m));
			printf(",%s,%s,", exact, sampled);
			csv_field(r2);
			putchar(',');
			csv_field(r3);
			putchar(',');
			csv_field(m->summary);
			putchar(',');
			csv_field(m->reference);
			putchar('\n');
		} else
			printf("%-19s %-6s %-6s %-7s %-16s %-11s %s\n", m->name, dims(m), exact, sampled, r2, r3, m->summary);
	}
	if (!csv) {
		printf("\nreferences:\n");
		for (int i = 0; i < count; ++i) printf("  %-19s %s\n", mkRegistry_At(i)->name, mkRegistry_At(i)->reference);
	}
	if (fflush(stdout)) {
		fprintf(stderr, "mink methods: writing to standard output failed\n");
		return 1;
	}
	return 0;
}
