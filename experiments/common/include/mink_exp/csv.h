/* mink_exp/csv.h - raw result rows as CSV (RFC 4180), written through a
 * temporary file (mink_exp/outfile.h) together with the metadata sidecar.
 *
 * Numbers: doubles as "%.17g" (they read back to the same double), NaN as
 * "nan", infinities as "inf" / "-inf"; an absent value is an empty field.
 * Text fields are quoted only when they hold a comma, a quote or a line
 * break. Rows end in "\n". The header row is written by mkCsv_Open.
 *
 *   mkCsv csv;
 *   if (mkCsv_Open(&csv, "results/x.csv", names, count, msg, sizeof msg)) fail;
 *   mkCsv_Int(&csv, trial); mkCsv_Double(&csv, err); mkCsv_EndRow(&csv);
 *   if (mkCsv_Commit(&csv, &meta, msg, sizeof msg)) fail;   // x.csv + x.csv.meta
 */
#ifndef MINK_EXP_CSV_H
#define MINK_EXP_CSV_H

#include <stddef.h>
#include <stdint.h>

#include "outfile.h"

struct mkMeta;

typedef struct mkCsv {
	mkOutFile file;
	int columns;   /* from the header */
	int field;     /* fields written in the current row */
	long rows;     /* complete rows written, header excluded */
	int misuse;    /* a row had the wrong number of fields */
} mkCsv;

/* Open `path` for writing (temporary file) and write the header. Returns 0,
 * or -1 with a message. */
int mkCsv_Open(mkCsv *csv, const char *path, const char *const *names, int count,
	char *msg, size_t msglen);

void mkCsv_Str(mkCsv *csv, const char *text);
void mkCsv_Int(mkCsv *csv, long long v);
void mkCsv_U64(mkCsv *csv, uint64_t v);
void mkCsv_Double(mkCsv *csv, double v);
/* An absent value. */
void mkCsv_Empty(mkCsv *csv);
/* End the row; a row whose field count differs from the header's is
 * recorded as misuse and makes the commit fail. */
void mkCsv_EndRow(mkCsv *csv);

/* Finish: write the sidecar "<path>.meta" from meta (when not NULL; see
 * mink_exp/meta.h; it fails when a required key is missing) and commit both,
 * the sidecar first, so that a final CSV always has its sidecar. Fails on a
 * write error or a misused row, and then leaves no final file. Returns 0,
 * or -1 with a message. */
int mkCsv_Commit(mkCsv *csv, struct mkMeta *meta, char *msg, size_t msglen);

/* Drop everything written; the final name is untouched. */
void mkCsv_Discard(mkCsv *csv);

/* The end of a driver's run: discard when `failed`, else commit with the
 * sidecar (printing "<prog>: <why>" on a failed commit); frees meta either
 * way. Returns the driver's exit status: 0 when the result was written,
 * 1 otherwise. */
int mkCsv_Finish(mkCsv *csv, struct mkMeta *meta, int failed, const char *prog);

#endif
