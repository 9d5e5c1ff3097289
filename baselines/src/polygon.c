/* polygon.c - convex polygons from rings of samples, and edge sorting: the
 * O(m + n) Minkowski sum of two convex polygons by merging their edges in
 * slope order (de Berg et al., Computational Geometry, Sec. 13.3). Every
 * decision is an exact orientation test (predicates.c). */
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/registry.h>

/* Index of the lowest (then leftmost) point. */
static int lowest(const double *xy, int count)
{
	int best = 0;
	for (int k = 1; k < count; ++k) {
		const double *p = xy + 2 * k, *b = xy + 2 * best;
		if (p[1] < b[1] || (p[1] == b[1] && p[0] < b[0])) best = k;
	}
	return best;
}

/* Copy the ring starting at index `start`. */
static void rotate_copy(const double *xy, int count, int start, double *out)
{
	for (int k = 0; k < count; ++k) {
		int s = (start + k) % count;
		out[2 * k] = xy[2 * s];
		out[2 * k + 1] = xy[2 * s + 1];
	}
}

/* Which half-turn the direction of edge (dx, dy) lies in: 0 for angles in
 * [0, pi), 1 for [pi, 2 pi). Exact: the sign of a difference of doubles is
 * the sign of the exact difference. */
static int half(double dx, double dy)
{
	return !(dy > 0 || (dy == 0 && dx > 0));
}

/* 1 when the ring (cyclic, counter-clockwise as given) turns left at every
 * vertex and winds once around. */
static int is_strictly_convex_ccw(const double *xy, int count)
{
	if (count < 3) return 0;
	int wraps = 0;
	for (int k = 0; k < count; ++k) {
		const double *a = xy + 2 * ((k + count - 1) % count);
		const double *b = xy + 2 * k;
		const double *c = xy + 2 * ((k + 1) % count);
		if (mkOrient2(a, b, c) <= 0) return 0;
		/* With every turn left and below a half-turn, the edge direction
		 * passes angle 0 once per winding: count the passes. */
		if (half(b[0] - a[0], b[1] - a[1]) == 1 && half(c[0] - b[0], c[1] - b[1]) == 0) ++wraps;
	}
	return wraps == 1;
}

static int cmp_xy(const void *pa, const void *pb)
{
	const double *a = pa, *b = pb;
	if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
	if (a[1] != b[1]) return a[1] < b[1] ? -1 : 1;
	return 0;
}

/* Andrew's monotone chain with strict turns: the extreme points only. */
static int monotone_chain(const double *xy, int count, double *out)
{
	double *pts = malloc(2 * (size_t)count * sizeof *pts);
	double *h = malloc(2 * ((size_t)count + 1) * sizeof *h);
	if (!pts || !h) {
		free(pts);
		free(h);
		return -1;
	}
	memcpy(pts, xy, 2 * (size_t)count * sizeof *pts);
	qsort(pts, (size_t)count, 2 * sizeof *pts, cmp_xy);
	int m = 0; /* drop exact duplicates */
	for (int k = 0; k < count; ++k)
		if (m == 0 || cmp_xy(pts + 2 * (m - 1), pts + 2 * k) != 0) {
			pts[2 * m] = pts[2 * k];
			pts[2 * m + 1] = pts[2 * k + 1];
			++m;
		}
	int len = 0;
	if (m < 3) {
		memcpy(h, pts, 2 * (size_t)m * sizeof *h);
		len = m;
	} else {
		for (int k = 0; k < m; ++k) { /* lower chain, left to right */
			while (len >= 2 && mkOrient2(h + 2 * (len - 2), h + 2 * (len - 1), pts + 2 * k) <= 0) --len;
			h[2 * len] = pts[2 * k];
			h[2 * len + 1] = pts[2 * k + 1];
			++len;
		}
		int lower = len + 1;
		for (int k = m - 2; k >= 0; --k) { /* upper chain, right to left */
			while (len >= lower && mkOrient2(h + 2 * (len - 2), h + 2 * (len - 1), pts + 2 * k) <= 0) --len;
			h[2 * len] = pts[2 * k];
			h[2 * len + 1] = pts[2 * k + 1];
			++len;
		}
		--len; /* the first point closes the chain */
	}
	rotate_copy(h, len, lowest(h, len), out);
	free(pts);
	free(h);
	return len;
}

int mkPolygon2_Convex(const double *xy, int count, double *out)
{
	if (count < 1 || !xy || !out) return -1;
	if (count >= 3) {
		/* Counter-clockwise as given, or clockwise and reversed. */
		int start = lowest(xy, count);
		rotate_copy(xy, count, start, out);
		if (is_strictly_convex_ccw(out, count)) return count;
		for (int k = 0; k < count; ++k) {
			int s = (start - k + count) % count;
			out[2 * k] = xy[2 * s];
			out[2 * k + 1] = xy[2 * s + 1];
		}
		if (is_strictly_convex_ccw(out, count)) return count;
	}
	return monotone_chain(xy, count, out);
}

/* Order of the directions of edges e = (a -> b) and f = (c -> d) by angle in
 * [0, 2 pi): -1 when e comes first, +1 when f does, 0 when they point the
 * same way. */
static int edge_order(const double *a, const double *b, const double *c, const double *d)
{
	int he = half(b[0] - a[0], b[1] - a[1]);
	int hf = half(d[0] - c[0], d[1] - c[1]);
	if (he != hf) return he < hf ? -1 : 1;
	/* Same half-turn: the cross product decides (both angles differ by less
	 * than pi). */
	return -mkCross2_Sign(a, b, c, d);
}

mkResult mkEdgeSort2_Merge(const double *P, int m, const double *Q, int n, mkPointSet *out)
{
	if (!P || !Q || !out || m < 1 || n < 1) return MK_ERR_ARGUMENT;
	if (m > 0x3fffffff - n) return MK_ERR_ARGUMENT;
	mkResult r = mkPointSet_Resize(out, 2, m + n);
	if (r != MK_OK) return r;
	/* i, j count the edges taken; a single vertex has no edge to take. */
	int i = m == 1 ? m : 0, j = n == 1 ? n : 0, k = 0;
	do {
		const double *p = P + 2 * (i % m), *q = Q + 2 * (j % n);
		out->x[k] = p[0] + q[0];
		out->y[k] = p[1] + q[1];
		++k;
		if (i == m) ++j;
		else if (j == n) ++i;
		else {
			int o = edge_order(p, P + 2 * ((i + 1) % m), q, Q + 2 * ((j + 1) % n));
			if (o <= 0) ++i;
			if (o >= 0) ++j;
		}
	} while (i < m || j < n);
	out->count = k;
	return MK_OK;
}
