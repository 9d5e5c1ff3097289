/* faces.c - reading and checking the triangles of `mink score --faces`. */
#include "faces.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct mkFaces_List {
	int *idx; /* 3 per face */
	int *line; /* the file line of each face */
	int count, cap;
} mkFaces_List;

/* Split line into at most max fields at commas or blanks. */
static int mkFaces_Split(char *line, char **field, int max)
{
	int n = 0;
	for (char *p = strtok(line, ", \t\r\n"); p && n < max; p = strtok(NULL, ", \t\r\n")) field[n++] = p;
	return n;
}

static int mkFaces_Push(mkFaces_List *f, const int v[3], int line)
{
	if (f->count == f->cap) {
		int cap = f->cap ? 2 * f->cap : 1024;
		int *idx = realloc(f->idx, (size_t)cap * 3 * sizeof(int));
		if (idx) f->idx = idx;
		int *ln = idx ? realloc(f->line, (size_t)cap * sizeof(int)) : NULL;
		if (!ln) return -1;
		f->line = ln;
		f->cap = cap;
	}
	memcpy(f->idx + 3 * f->count, v, 3 * sizeof(int));
	f->line[f->count++] = line;
	return 0;
}

/* The faces of path into f; -1 after a message. */
static int mkFaces_Read(const char *path, int npts, mkFaces_List *f)
{
	FILE *fp = fopen(path, "r");
	if (!fp) {
		fprintf(stderr, "mink score: --faces %s cannot be opened\n", path);
		return -1;
	}
	char buf[4096], *field[64];
	int col[3] = {0, 1, 2}, lineno = 0, rc = 0, data = 0;
	while (rc == 0 && fgets(buf, sizeof buf, fp)) {
		++lineno;
		int n = mkFaces_Split(buf, field, 64);
		if (n == 0 || field[0][0] == '#') continue;
		if (!data && isalpha((unsigned char)field[0][0])) { /* a header */
			for (int c = 0; c < n; ++c)
				for (int k = 0; k < 3; ++k)
					if (strcmp(field[c], (const char *[]){"i", "j", "k"}[k]) == 0) col[k] = c;
			data = 1;
			continue;
		}
		data = 1;
		int v[3];
		for (int k = 0; k < 3 && rc == 0; ++k) {
			char *end = NULL;
			long x = col[k] < n ? strtol(field[col[k]], &end, 10) : -1;
			if (col[k] >= n) {
				fprintf(stderr, "mink score: --faces %s line %d, column %d: missing\n", path, lineno, col[k] + 1);
				rc = -1;
			} else if (*end || end == field[col[k]] || x < 0 || x >= npts) {
				fprintf(stderr, "mink score: --faces %s line %d, column %d: index '%s' is out of range: "
					"must be an integer in [0, %d] (0-based into the %d points)\n", path, lineno, col[k] + 1,
					field[col[k]], npts - 1, npts);
				rc = -1;
			} else {
				v[k] = (int)x;
			}
		}
		if (rc == 0 && mkFaces_Push(f, v, lineno)) {
			fprintf(stderr, "mink score: out of memory reading --faces\n");
			rc = -1;
		}
	}
	if (rc == 0 && f->count < 4) {
		fprintf(stderr, "mink score: --faces %s holds %d triangles: a closed surface needs at least 4\n", path,
			f->count);
		rc = -1;
	}
	fclose(fp);
	return rc;
}

static int mkFaces_EdgeCompare(const void *a, const void *b)
{
	const long long *x = a, *y = b;
	return *x < *y ? -1 : *x > *y;
}

/* Every directed edge once and its reverse once: -1 after a message. */
static int mkFaces_Closed(const char *path, const mkFaces_List *f)
{
	size_t m = 3 * (size_t)f->count;
	long long *e = malloc(m * sizeof *e);
	if (!e) return fprintf(stderr, "mink score: out of memory checking --faces\n"), -1;
	for (int t = 0; t < f->count; ++t)
		for (int k = 0; k < 3; ++k)
			e[3 * t + k] = (long long)f->idx[3 * t + k] << 32 | (unsigned)f->idx[3 * t + (k + 1) % 3];
	qsort(e, m, sizeof *e, mkFaces_EdgeCompare);
	int rc = 0;
	for (size_t q = 0; q < m && rc == 0; ++q) {
		long long rev = (e[q] & 0xffffffffLL) << 32 | (e[q] >> 32);
		int twice = q + 1 < m && e[q + 1] == e[q];
		if (twice || !bsearch(&rev, e, m, sizeof *e, mkFaces_EdgeCompare)) {
			fprintf(stderr, "mink score: --faces %s: edge %lld -> %lld %s: the triangles do not close a "
				"consistently oriented surface\n", path, e[q] >> 32, e[q] & 0xffffffffLL,
				twice ? "is used twice in one direction" : "has no triangle on its other side");
			rc = -1;
		}
	}
	free(e);
	return rc;
}

int mkFaces_Check3(const char *path, const mkPointSet *pts, mkFaces_Check *out)
{
	mkFaces_List f = {0};
	int rc = mkFaces_Read(path, pts->count, &f);
	if (rc == 0) rc = mkFaces_Closed(path, &f);
	double vol = 0.0, extent = 0.0;
	for (int i = 0; i < pts->count; ++i)
		extent = fmax(extent, fmax(fabs(pts->x[i]), fmax(fabs(pts->y[i]), fabs(pts->z[i]))));
	for (int t = 0; rc == 0 && t < f.count; ++t) {
		double a[3][3];
		for (int k = 0; k < 3; ++k) {
			int v = f.idx[3 * t + k];
			a[k][0] = pts->x[v], a[k][1] = pts->y[v], a[k][2] = pts->z[v];
		}
		vol += a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
			+ a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
	}
	double sign = vol < 0 ? -1.0 : 1.0, tol = 1e-9 * extent;
	for (int t = 0; rc == 0 && t < f.count; ++t) {
		const int *v = f.idx + 3 * t;
		double u[3] = {pts->x[v[1]] - pts->x[v[0]], pts->y[v[1]] - pts->y[v[0]], pts->z[v[1]] - pts->z[v[0]]};
		double w[3] = {pts->x[v[2]] - pts->x[v[0]], pts->y[v[2]] - pts->y[v[0]], pts->z[v[2]] - pts->z[v[0]]};
		double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
		double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		if (!(len > 0)) {
			fprintf(stderr, "mink score: --faces %s line %d: the triangle %d,%d,%d has zero area\n", path, f.line[t],
				v[0], v[1], v[2]);
			rc = -1;
		}
		for (int i = 0; rc == 0 && i < pts->count; ++i) {
			double d = sign * (n[0] * (pts->x[i] - pts->x[v[0]]) + n[1] * (pts->y[i] - pts->y[v[0]])
				+ n[2] * (pts->z[i] - pts->z[v[0]])) / len;
			if (d > tol) {
				fprintf(stderr, "mink score: --faces %s line %d: point %d lies %.3g outside the plane of the "
					"triangle %d,%d,%d: the faces do not close a convex surface over the points (tolerance %.3g)\n",
					path, f.line[t], i, d, v[0], v[1], v[2], tol);
				rc = -1;
			}
		}
	}
	out->faces = f.count;
	out->volume = fabs(vol) / 6.0;
	free(f.idx);
	free(f.line);
	return rc;
}
