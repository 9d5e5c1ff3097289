/* points.c - reading a point set from a CSV file (points.h). */
#include "points.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct mkPointsText {
	char *data;
	size_t len;
} mkPointsText;

static int mkPoints_Slurp(const char *cmd, const char *path, mkPointsText *t)
{
	FILE *fp = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
	if (!fp) {
		fprintf(stderr, "mink %s: --points %s: %s\n", cmd, path, strerror(errno));
		return -1;
	}
	size_t cap = 1 << 16;
	t->data = malloc(cap);
	t->len = 0;
	for (;;) {
		if (!t->data) break;
		if (t->len + 1 >= cap) {
			char *bigger = realloc(t->data, cap *= 2);
			if (!bigger) {
				free(t->data);
				t->data = NULL;
				break;
			}
			t->data = bigger;
		}
		size_t got = fread(t->data + t->len, 1, cap - 1 - t->len, fp);
		t->len += got;
		if (got == 0) break;
	}
	int bad = ferror(fp);
	if (fp != stdin) fclose(fp);
	if (!t->data || bad) {
		fprintf(stderr, "mink %s: --points %s: %s\n", cmd, path, t->data ? "read error" : "out of memory");
		free(t->data);
		return -1;
	}
	t->data[t->len] = '\0';
	return 0;
}

/* Split a line at commas in place; returns the field count (at most max
 * are stored). */
static int mkPoints_Split(char *line, char **f, int max)
{
	int n = 0;
	char *s = line;
	for (;;) {
		while (*s == ' ' || *s == '\t') ++s;
		if (n < max) f[n] = s;
		++n;
		char *c = strchr(s, ',');
		char *end = c ? c : s + strlen(s);
		while (end > s && isspace((unsigned char)end[-1])) --end;
		*end = '\0';
		if (!c) break;
		s = c + 1;
	}
	return n;
}

/* The header's columns x, y (and z) into col[]; -1 after a message. */
static int mkPoints_Header(const char *cmd, const char *path, int lineno, char **f, int nf, int dim, int *col)
{
	static const char *const names[3] = {"x", "y", "z"};
	for (int c = 0; c < dim; ++c) {
		col[c] = -1;
		for (int i = 0; i < nf; ++i)
			if (strcmp(f[i], names[c]) == 0) col[c] = i;
		if (col[c] < 0) {
			fprintf(stderr, "mink %s: --points %s line %d: the header has no column '%s'\n", cmd, path, lineno,
				names[c]);
			return -1;
		}
	}
	return 0;
}

static int mkPoints_Parse(const char *cmd, const char *path, char *text, int dim, mkPointSet *out)
{
	enum { MAXF = 64 };
	int col[3] = {0, 1, 2}, header_seen = 0, lineno = 0, count = 0;
	char *next = text;
	while (next && *next) {
		char *line = next, *nl = strchr(line, '\n');
		if (nl) *nl = '\0';
		next = nl ? nl + 1 : NULL;
		++lineno;
		size_t l = strlen(line);
		if (l && line[l - 1] == '\r') line[l - 1] = '\0';
		char *p = line;
		while (isspace((unsigned char)*p)) ++p;
		if (!*p || *p == '#') continue;
		char *f[MAXF], *end;
		int nf = mkPoints_Split(p, f, MAXF);
		if (nf > MAXF) nf = MAXF;
		strtod(f[0], &end);
		if (!header_seen && (end == f[0] || *end)) {
			if (mkPoints_Header(cmd, path, lineno, f, nf, dim, col)) return -1;
			header_seen = 1;
			continue;
		}
		header_seen = 1;
		double v[3] = {0, 0, 0};
		for (int c = 0; c < dim; ++c) {
			if (col[c] >= nf) {
				fprintf(stderr, "mink %s: --points %s line %d, column %d: missing (the line has %d fields)\n", cmd,
					path, lineno, col[c] + 1, nf);
				return -1;
			}
			v[c] = strtod(f[col[c]], &end);
			if (end == f[col[c]] || *end) {
				fprintf(stderr, "mink %s: --points %s line %d, column %d: '%s' is not a number\n", cmd, path,
					lineno, col[c] + 1, f[col[c]]);
				return -1;
			}
		}
		if (count == out->count) {
			int cap = out->count ? 2 * out->count : 1024;
			if (mkPointSet_Resize(out, dim, cap) != MK_OK) {
				fprintf(stderr, "mink %s: out of memory reading the points\n", cmd);
				return -1;
			}
		}
		out->x[count] = v[0];
		out->y[count] = v[1];
		if (dim == 3) out->z[count] = v[2];
		++count;
	}
	out->count = count;
	if (!count) {
		fprintf(stderr, "mink %s: --points %s holds no points\n", cmd, path);
		return -1;
	}
	return 0;
}

int mkPoints_Read(const char *cmd, const char *path, int dim, mkPointSet *out)
{
	mkPointsText text;
	if (mkPoints_Slurp(cmd, path, &text)) return -1;
	int bad = mkPoints_Parse(cmd, path, text.data, dim, out);
	free(text.data);
	return bad;
}
