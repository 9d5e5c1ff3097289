/* summary_text.h - for the tests of the experiments' summaries: run one
 * summary (mink_exp/doc.h) into temporary files and check its Markdown.
 * Header-only; include after ensure.h. */
#ifndef MINK_EXP_SUMMARY_TEXT_H
#define MINK_EXP_SUMMARY_TEXT_H

#include <mink_exp/doc.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef void (*mkSummaryFn)(mkDoc *d, const char *dir, mkTally *tally);

/* The Markdown that summary writes for the results in dir, in a malloc'd
 * string (the LaTeX side is written and dropped). */
static char *mkSummary_Text(mkSummaryFn summary, const char *dir, mkTally *tally)
{
	mkDoc d = { tmpfile(), tmpfile(), 0 };
	ENSURE(d.md != NULL && d.tex != NULL);
	summary(&d, dir, tally);
	long n = ftell(d.md);
	char *text = calloc((size_t)n + 1, 1);
	ENSURE(text != NULL);
	rewind(d.md);
	ENSURE(fread(text, 1, (size_t)n, d.md) == (size_t)n);
	fclose(d.md);
	fclose(d.tex);
	return text;
}

/* ENSURE that text holds want, printing the text when it does not. */
static void mkSummary_Expect(const char *text, const char *want)
{
	if (!strstr(text, want))
		fprintf(stderr, "the summary lacks '%s':\n%s\n", want, text);
	ENSURE(strstr(text, want) != NULL);
}

/* The section of `name` with no result in <root>/none: it must say so
 * ("<name>.csv` does not exist (run the `<name>` driver)"); tally is passed
 * through for the caller to check. */
static inline void mkSummary_ExpectMissing(mkSummaryFn summary, const char *root, const char *name, mkTally *tally)
{
	char dir[4096], want[256];
	snprintf(dir, sizeof dir, "%s/none", root);
	snprintf(want, sizeof want, "%s.csv` does not exist (run the `%s` driver)", name, name);
	char *md = mkSummary_Text(summary, dir, tally);
	mkSummary_Expect(md, "**NOT REPRODUCED YET**: `");
	mkSummary_Expect(md, want);
	free(md);
}

#endif
