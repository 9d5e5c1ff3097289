/* table.c - reading a CSV result file back. */
#include "mink_exp/table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <zlib.h>

/* Split buf (RFC 4180: fields may be quoted, "" is a quote) into fields in
 * place; *out_cells (allocated) receives them row by row and *out_cols the
 * fields per row. Returns the number of fields, or -1 when the rows are
 * ragged or memory runs out. */
static long mkCsvSplit(char *buf, char ***out_cells, int *out_cols)
{
	long cap = 1024, count = 0;
	char **cells = malloc((size_t)cap * sizeof *cells);
	if (!cells)
		return -1;
	int cols = -1, col = 0;
	char *r = buf, *w = buf;
	while (*r) {
		char *start = w;
		if (*r == '"') {
			++r;
			while (*r) {
				if (*r == '"' && r[1] == '"') {
					*w++ = '"';
					r += 2;
				} else if (*r == '"') {
					++r;
					break;
				} else {
					*w++ = *r++;
				}
			}
		}
		while (*r && *r != ',' && *r != '\n' && *r != '\r')
			*w++ = *r++;
		char end = *r;
		if (*r == '\r')
			++r;
		if (*r)
			++r;
		if (end == '\r' && *r == '\n')
			++r;
		*w++ = '\0';
		if (count == cap) {
			cap *= 2;
			char **grown = realloc(cells, (size_t)cap * sizeof *cells);
			if (!grown) {
				free(cells);
				return -1;
			}
			cells = grown;
		}
		cells[count++] = start;
		++col;
		if (end != ',') {
			if (cols < 0)
				cols = col;
			else if (col != cols) {
				free(cells);
				return -1;
			}
			col = 0;
		}
	}
	if (col != 0 || cols <= 0) {
		free(cells);
		return -1;
	}
	*out_cells = cells;
	*out_cols = cols;
	return count;
}

void mkPath_Stored(const char *path, char *buf, size_t len)
{
	struct stat st;
	char gz[4096];
	snprintf(gz, sizeof gz, "%s.gz", path);
	int use_gz = stat(path, &st) != 0 && stat(gz, &st) == 0;
	snprintf(buf, len, "%s", use_gz ? gz : path);
}

/* The whole file into a NUL-terminated buffer, gunzipped when it is gzip
 * (zlib reads any other file as it is); NULL when missing, unreadable or
 * out of memory (the last two reported). */
static char *mkReadAll(const char *path)
{
	char stored[4096];
	mkPath_Stored(path, stored, sizeof stored);
	gzFile in = gzopen(stored, "rb");
	if (!in)
		return NULL;
	gzbuffer(in, 1 << 17);
	size_t cap = 1 << 20, len = 0;
	char *buf = malloc(cap + 1);
	int bad = 0;
	while (buf) {
		int got = gzread(in, buf + len, (unsigned)(cap - len));
		if (got < 0) {
			bad = 1;
			break;
		}
		len += (size_t)got;
		if (len < cap)
			break;
		cap *= 2;
		char *grown = realloc(buf, cap + 1);
		if (!grown)
			free(buf);
		buf = grown;
	}
	int errnum = 0;
	const char *why = bad ? gzerror(in, &errnum) : NULL;
	if (bad)
		fprintf(stderr, "%s: %s\n", stored, why ? why : "read error");
	gzclose(in);
	if (!buf || bad) {
		if (!buf)
			fprintf(stderr, "%s: out of memory\n", stored);
		free(buf);
		return NULL;
	}
	buf[len] = '\0';
	return buf;
}

/* Drop the blank lines ("\n" or "\r\n" alone) of buf in place; those after
 * the first line are counted. */
static long mkDropBlankLines(char *buf)
{
	long blank = 0;
	int first = 1;
	char *r = buf, *w = buf;
	while (*r) {
		if (*r == '\n' || (*r == '\r' && r[1] == '\n')) {
			r += *r == '\r' ? 2 : 1;
			blank += !first;
			continue;
		}
		while (*r && *r != '\n')
			*w++ = *r++;
		if (*r)
			*w++ = *r++;
		first = 0;
	}
	*w = '\0';
	return blank;
}

static void mkTable_Parse(mkTable *t, const char *path, char *buf)
{
	char **cells = NULL;
	int cols = 0;
	long count = mkCsvSplit(buf, &cells, &cols);
	if (count < 0) {
		fprintf(stderr, "%s: not a rectangular CSV file; treated as missing\n", path);
		free(buf);
		return;
	}
	t->buf = buf;
	t->cols = cols;
	t->names = cells;
	t->cells = cells + cols;
	t->rows = count / cols - 1;
	t->present = 1;
}

void mkTable_FromText(mkTable *t, char *buf, const char *name, long *blank)
{
	memset(t, 0, sizeof *t);
	if (blank)
		*blank = mkDropBlankLines(buf);
	mkTable_Parse(t, name, buf);
}

/* Load path into t. A missing file leaves t->present = 0; a malformed one
 * is reported and treated as missing. */
void mkTable_Load(mkTable *t, const char *path)
{
	memset(t, 0, sizeof *t);
	char *buf = mkReadAll(path);
	if (buf)
		mkTable_FromText(t, buf, path, NULL);
}

void mkTable_LoadBlocks(mkTable *t, const char *path, long *blank)
{
	memset(t, 0, sizeof *t);
	*blank = 0;
	char *buf = mkReadAll(path);
	if (buf)
		mkTable_FromText(t, buf, path, blank);
}

void mkTable_Free(mkTable *t)
{
	free(t->names);
	free(t->buf);
	memset(t, 0, sizeof *t);
}

int mkTable_Col(const mkTable *t, const char *name)
{
	for (int c = 0; t->present && c < t->cols; ++c)
		if (strcmp(t->names[c], name) == 0)
			return c;
	return -1;
}

const char *mkTable_Str(const mkTable *t, long r, int c)
{
	return c >= 0 ? t->cells[r * t->cols + c] : "";
}

/* A number, NaN when empty or not a number ("nan" reads as NaN). */
double mkTable_Num(const mkTable *t, long r, int c)
{
	const char *s = mkTable_Str(t, r, c);
	char *end = NULL;
	double v = strtod(s, &end);
	return (s[0] && end && *end == '\0') ? v : NAN;
}

