/* mink_exp/doc.h - the summary tables: Markdown and LaTeX written side by
 * side, and the small helpers every experiment's summary shares.
 *
 * Each experiment owns the summary of its own results (its section of
 * results/tables.md and tables.tex): a function that reads its result file
 * with mkResult_Load and writes headings, paragraphs and tables to an mkDoc.
 * The `tables` program only opens the two files and calls the summaries in
 * the paper's order.
 *
 * Text given to the writer is Markdown-flavoured UTF-8: `code` and **bold**
 * are the only markup; the LaTeX side translates them and the few non-ASCII
 * symbols the summaries use (±, µ, ×, ≤, ≥, −, ε, π, ...). */
#ifndef MINK_EXP_DOC_H
#define MINK_EXP_DOC_H

#include <stddef.h>
#include <stdio.h>

#include "meta.h"
#include "outfile.h"
#include "table.h"

typedef struct mkDoc {
	FILE *md, *tex;
	int cols;
} mkDoc;

void mkDoc_Heading(mkDoc *d, int level, const char *text);
/* A paragraph (printf-style). */
void mkDoc_Para(mkDoc *d, const char *fmt, ...);
/* A bullet list item (consecutive items form one list in Markdown; each
 * is its own paragraph in LaTeX, led by a dash); end the list with
 * mkDoc_EndItems. */
void mkDoc_Item(mkDoc *d, const char *fmt, ...);
void mkDoc_EndItems(mkDoc *d);
void mkDoc_TableBegin(mkDoc *d, const char *caption, int cols, const char *const *head);
void mkDoc_Row(mkDoc *d, const char *const *cells);
void mkDoc_TableEnd(mkDoc *d);
/* One line on where a table's numbers come from (path, rows, the sidecar's
 * date, commit, seed and trials). */
void mkDoc_Source(mkDoc *d, const char *path, const mkTable *t, const mkMeta *m);

/* The mark of a published number whose result is missing. */
extern const char *const mkNotYet;

/* Numbers as text: "%.4e" or "—" for NaN; got / published to three digits
 * or "—"; "mean ± std unit" in µs, ms or s. */
void mkFmt_Sci(char *buf, size_t len, double v);
void mkFmt_Ratio(char *buf, size_t len, double got, double published);
void mkFmt_Time(char *buf, size_t len, double mean, double std);

/* How many published numbers a summary met: with a reproduced counterpart
 * or not. */
typedef struct mkTally {
	int published, reproduced, missing;
} mkTally;
void mkTally_Add(mkTally *t, int reproduced);

/* A mean over the finite values given, counting the others. */
typedef struct mkMean {
	double sum;
	long n, nan;
} mkMean;
void mkMean_Add(mkMean *m, double v);
double mkMean_Get(const mkMean *m);

/* An experiment's section of the tables, opened: its result and sidecar
 * loaded, its heading written, and either the source line (when the result
 * is there with every column the summary reads) or the NOT REPRODUCED YET
 * line that says what is missing and what follows from it. */
typedef struct mkSection {
	mkTable t;
	mkMeta m;
	char path[MK_PATH_MAX];
	int usable;
} mkSection;
/* Heading `heading` (level 2); loads <dir>/<file>; `columns` NULL-ended, the
 * columns the summary needs; `consequence` one sentence for the missing case
 * ("The four published means are listed without a counterpart."). The
 * missing text names the driver: the file's stem. Returns s->usable. */
int mkSection_Begin(mkSection *s, mkDoc *d, const char *heading, const char *dir, const char *file,
	const char *const *columns, const char *consequence);
void mkSection_End(mkSection *s);

/* Load <dir>/<file> and its sidecar <dir>/<file>.meta (m is initialised
 * here; free both with mkResult_Free). path receives "<dir>/<file>".
 * Returns 1 when the CSV is present, 0 when missing or malformed. */
int mkResult_Load(const char *dir, const char *file, mkTable *t, mkMeta *m, char *path, size_t pathlen);
void mkResult_Free(mkTable *t, mkMeta *m);

#endif
