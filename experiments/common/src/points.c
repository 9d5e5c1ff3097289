/* points.c - a CSV of points read from text (mink_exp/points.h). */
#include "mink_exp/points.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MK_POINTS_FIELDS 64

/* Split a line at commas in place; returns the field count (the first
 * max of them in f). */
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

/* The header's columns x, y[, z] into col; 0, or -1 with a message. */
static int mkPoints_Header(char **f, int nf, int dim, int lineno, int *col, char *msg, size_t msglen)
{
	static const char *const names[3] = {"x", "y", "z"};
	for (int c = 0; c < dim; ++c) {
		col[c] = -1;
		for (int i = 0; i < nf; ++i)
			if (strcmp(f[i], names[c]) == 0) col[c] = i;
		if (col[c] < 0) {
			snprintf(msg, msglen, "line %d: the header has no column '%s'", lineno, names[c]);
			return -1;
		}
	}
	return 0;
}

static int mkPoints_Append(mkPoints *p, const double *v)
{
	if (p->count == p->cap) {
		int cap = p->cap ? 2 * p->cap : 1024;
		if (cap < p->cap) return -1;
		for (int c = 0; c < p->dim; ++c) {
			double **a = c == 0 ? &p->x : c == 1 ? &p->y : &p->z;
			double *g = realloc(*a, (size_t)cap * sizeof **a);
			if (!g) return -1;
			*a = g;
		}
		p->cap = cap;
	}
	p->x[p->count] = v[0];
	p->y[p->count] = v[1];
	if (p->dim == 3) p->z[p->count] = v[2];
	++p->count;
	return 0;
}

int mkPoints_Parse(char *text, int dim, mkPoints *out, char *msg, size_t msglen)
{
	memset(out, 0, sizeof *out);
	out->dim = dim;
	int col[3] = {0, 1, 2}, header_seen = 0, lineno = 0;
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
		char *f[MK_POINTS_FIELDS], *end;
		int nf = mkPoints_Split(p, f, MK_POINTS_FIELDS);
		if (nf > MK_POINTS_FIELDS) nf = MK_POINTS_FIELDS;
		strtod(f[0], &end);
		if (!header_seen && (end == f[0] || *end)) {
			header_seen = 1;
			if (mkPoints_Header(f, nf, dim, lineno, col, msg, msglen)) return -1;
			continue;
		}
		header_seen = 1;
		double v[3] = {0, 0, 0};
		for (int c = 0; c < dim; ++c) {
			if (col[c] >= nf) {
				snprintf(msg, msglen, "line %d, column %d: missing (the line has %d fields)", lineno, col[c] + 1, nf);
				return -1;
			}
			v[c] = strtod(f[col[c]], &end);
			if (end == f[col[c]] || *end) {
				snprintf(msg, msglen, "line %d, column %d: '%.40s' is not a number", lineno, col[c] + 1, f[col[c]]);
				return -1;
			}
		}
		if (mkPoints_Append(out, v)) {
			snprintf(msg, msglen, "out of memory reading the points");
			return -1;
		}
	}
	if (!out->count) {
		snprintf(msg, msglen, "holds no points");
		return -1;
	}
	return 0;
}

void mkPoints_Free(mkPoints *p)
{
	free(p->x);
	free(p->y);
	free(p->z);
	memset(p, 0, sizeof *p);
}
