/* csv.c - CSV rows into a temporary file; commit writes the sidecar too. */
#define _POSIX_C_SOURCE 200809L

#include "mink_exp/csv.h"
#include "mink_exp/meta.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static void mkCsv_Separator(mkCsv *csv)
{
	if (csv->field > 0)
		fputc(',', csv->file.fp);
	csv->field += 1;
}

static void mkCsv_WriteText(FILE *fp, const char *text)
{
	if (strpbrk(text, ",\"\r\n") == NULL) {
		fputs(text, fp);
		return;
	}
	fputc('"', fp);
	for (const char *p = text; *p; ++p) {
		if (*p == '"')
			fputc('"', fp);
		fputc(*p, fp);
	}
	fputc('"', fp);
}

int mkCsv_Open(mkCsv *csv, const char *path, const char *const *names, int count,
	char *msg, size_t msglen)
{
	csv->columns = count;
	csv->field = 0;
	csv->rows = 0;
	csv->misuse = 0;
	if (count < 1) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "a CSV needs at least one column");
		return -1;
	}
	if (mkOutFile_Open(&csv->file, path, msg, msglen) != 0)
		return -1;
	for (int i = 0; i < count; ++i) {
		if (i > 0)
			fputc(',', csv->file.fp);
		mkCsv_WriteText(csv->file.fp, names[i]);
	}
	fputc('\n', csv->file.fp);
	return 0;
}

void mkCsv_Str(mkCsv *csv, const char *text)
{
	mkCsv_Separator(csv);
	mkCsv_WriteText(csv->file.fp, text ? text : "");
}

void mkCsv_Int(mkCsv *csv, long long v)
{
	mkCsv_Separator(csv);
	fprintf(csv->file.fp, "%lld", v);
}

void mkCsv_U64(mkCsv *csv, uint64_t v)
{
	mkCsv_Separator(csv);
	fprintf(csv->file.fp, "%" PRIu64, v);
}

void mkCsv_Double(mkCsv *csv, double v)
{
	mkCsv_Separator(csv);
	if (isnan(v))
		fputs("nan", csv->file.fp);
	else if (isinf(v))
		fputs(v > 0 ? "inf" : "-inf", csv->file.fp);
	else
		fprintf(csv->file.fp, "%.17g", v);
}

void mkCsv_Empty(mkCsv *csv)
{
	mkCsv_Separator(csv);
}

void mkCsv_EndRow(mkCsv *csv)
{
	if (csv->field != csv->columns)
		csv->misuse = 1;
	fputc('\n', csv->file.fp);
	csv->field = 0;
	csv->rows += 1;
}

int mkCsv_Commit(mkCsv *csv, struct mkMeta *meta, char *msg, size_t msglen)
{
	if (csv->misuse || csv->field != 0) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "%s: a row does not have the header's %d fields (program error)",
				csv->file.path, csv->columns);
		mkCsv_Discard(csv);
		return -1;
	}
	if (!meta)
		return mkOutFile_Commit(&csv->file, msg, msglen);

	char metapath[MK_PATH_MAX + 8];
	snprintf(metapath, sizeof metapath, "%s.meta", csv->file.path);
	mkMeta_SetInt(meta, "rows", csv->rows);
	mkOutFile mf;
	if (mkOutFile_Open(&mf, metapath, msg, msglen) != 0) {
		mkCsv_Discard(csv);
		return -1;
	}
	if (mkMeta_Write(meta, mf.fp, msg, msglen) != 0) {
		mkOutFile_Discard(&mf);
		mkCsv_Discard(csv);
		return -1;
	}
	/* Sidecar first: a final CSV always has the sidecar of its own run. */
	mkOutFile *both[2] = { &mf, &csv->file };
	return mkOutFile_CommitAll(both, 2, msg, msglen);
}

void mkCsv_Discard(mkCsv *csv)
{
	mkOutFile_Discard(&csv->file);
}

int mkCsv_Finish(mkCsv *csv, struct mkMeta *meta, int failed, const char *prog)
{
	int status = 0;
	char msg[1024];
	if (failed) {
		mkCsv_Discard(csv);
		status = 1;
	} else if (mkCsv_Commit(csv, meta, msg, sizeof msg) != 0) {
		fprintf(stderr, "%s: %s\n", prog, msg);
		status = 1;
	}
	if (meta)
		mkMeta_Free(meta);
	return status;
}
