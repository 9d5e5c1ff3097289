/* table.h - reading the drivers' CSV back in the demos and cobstacle tests.
 *
 * A whole file is read into memory: the header names the columns, every
 * other non-blank line is a row (RFC 4180 quoting; blank lines, which the
 * geometry files use to separate curves and grid rows, are skipped, and
 * counted in `blank`). Numbers are read with strtod, "nan" and an empty
 * field as NaN. */
#ifndef MK_DEMOS_TABLE_H
#define MK_DEMOS_TABLE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct mkTable {
	int columns;
	char **names;
	long rows;
	char ***cell;   /* cell[row][column], NUL-terminated */
	long blank;     /* blank lines seen */
} mkTable;

static char *mkTable_Field(const char **p)
{
	size_t cap = 32, n = 0;
	char *out = malloc(cap);
	const char *s = *p;
	int quoted = *s == '"';
	if (quoted)
		++s;
	for (;;) {
		char c = *s;
		if (c == '\0')
			break;
		if (quoted) {
			if (c == '"' && s[1] == '"') {
				s += 2;
				c = '"';
			} else if (c == '"') {
				++s;
				quoted = 0;
				continue;
			} else {
				++s;
			}
		} else {
			if (c == ',' || c == '\n' || c == '\r')
				break;
			++s;
		}
		if (n + 2 > cap) {
			cap *= 2;
			out = realloc(out, cap);
		}
		out[n++] = c;
	}
	out[n] = '\0';
	*p = s;
	return out;
}

/* Split one line (without its end) into fields; the count is returned. */
static int mkTable_Split(const char *line, char ***fields)
{
	int n = 0, cap = 8;
	*fields = malloc(sizeof(char *) * (size_t)cap);
	const char *p = line;
	for (;;) {
		if (n == cap) {
			cap *= 2;
			*fields = realloc(*fields, sizeof(char *) * (size_t)cap);
		}
		(*fields)[n++] = mkTable_Field(&p);
		if (*p != ',')
			break;
		++p;
	}
	return n;
}

/* Returns 0, or -1 when the file cannot be read or a row's field count
 * differs from the header's (a message is printed). */
static int mkTable_Read(mkTable *t, const char *path)
{
	memset(t, 0, sizeof *t);
	FILE *fp = fopen(path, "rb");
	if (!fp) {
		fprintf(stderr, "cannot open %s\n", path);
		return -1;
	}
	fseek(fp, 0, SEEK_END);
	long size = ftell(fp);
	fseek(fp, 0, SEEK_SET);
	char *text = malloc((size_t)size + 1);
	size_t got = fread(text, 1, (size_t)size, fp);
	text[got] = '\0';
	fclose(fp);
	long cap = 1024;
	t->cell = malloc(sizeof(char **) * (size_t)cap);
	int bad = 0;
	/* Lines end at a newline that is not inside quotes; no field of these
	 * files holds a line break, so a plain split is enough. */
	char *save = text;
	int first = 1;
	while (*save && !bad) {
		char *end = strchr(save, '\n');
		if (end)
			*end = '\0';
		char *line = save;
		save = end ? end + 1 : save + strlen(save);
		if (line[0] == '\0' || (line[0] == '\r' && line[1] == '\0')) {
			if (!first)
				t->blank += 1;
			continue;
		}
		char **fields;
		int n = mkTable_Split(line, &fields);
		if (first) {
			t->columns = n;
			t->names = fields;
			first = 0;
			continue;
		}
		if (n != t->columns) {
			fprintf(stderr, "%s: a row has %d fields, the header %d\n", path, n, t->columns);
			bad = 1;
		}
		if (t->rows == cap) {
			cap *= 2;
			t->cell = realloc(t->cell, sizeof(char **) * (size_t)cap);
		}
		t->cell[t->rows++] = fields;
	}
	free(text);
	return bad || first ? -1 : 0;
}

/* The column of a name, or -1 (and a message). */
static int mkTable_Col(const mkTable *t, const char *name)
{
	for (int i = 0; i < t->columns; ++i)
		if (strcmp(t->names[i], name) == 0)
			return i;
	fprintf(stderr, "no column '%s'\n", name);
	return -1;
}

static const char *mkTable_Str(const mkTable *t, long row, const char *name)
{
	int c = mkTable_Col(t, name);
	return c < 0 ? "" : t->cell[row][c];
}

static double mkTable_Num(const mkTable *t, long row, const char *name)
{
	const char *s = mkTable_Str(t, row, name);
	if (s[0] == '\0')
		return NAN;
	return strtod(s, NULL);
}

static void mkTable_Free(mkTable *t)
{
	for (long r = 0; r < t->rows; ++r) {
		for (int c = 0; c < t->columns; ++c)
			free(t->cell[r][c]);
		free(t->cell[r]);
	}
	for (int c = 0; c < t->columns; ++c)
		free(t->names[c]);
	free(t->names);
	free(t->cell);
	memset(t, 0, sizeof *t);
}

#endif
