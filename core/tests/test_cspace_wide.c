/* test_cspace_wide.c - the scene query's eight-way box hierarchy
 * (cspace/scenewide.h) against brute force: for random and degenerate
 * sets of boxes and random query boxes, the walk returns every box that
 * meets the query box exactly once (compared in double precision, box by
 * box, with no hierarchy), nothing else but boxes whose float rounding
 * meets the query's, in chunks of any size and when the query box shrinks
 * during the walk; the walk's portable (SSE) and AVX2 builds return the
 * same positions in the same order (where the CPU runs AVX2); and the
 * float rounding keeps the order of any two numbers (a <= b implies
 * down(a) <= up(b)), over the finite doubles. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cspace/scenewide.h"
#include "ensure.h"
#include "mink/sum.h"

static unsigned long long seed = 17;

static double uni(double lo, double hi) { return mk_test_uniform(&seed, lo, hi); }

/* a meets b (closed boxes), in double. */
static int meets(const mkSwBox *a, const double lo[3], const double hi[3])
{
	for (int i = 0; i < 3; ++i)
		if (a->lo[i] > hi[i] || a->hi[i] < lo[i]) return 0;
	return 1;
}

/* One walk of the query [lo, hi] in chunks of at most max (1 .. 8); when
 * shrink, the query box is replaced by [lo2, hi2] (inside it) after the
 * first chunk. Checks against brute force; returns the boxes returned. */
static int check_walk(const mkSwTree *t, const mkSwBox *box, int n, const double lo[3], const double hi[3],
	const double lo2[3], const double hi2[3], int max, int shrink)
{
	float flo[3], fhi[3];
	for (int i = 0; i < 3; ++i) { flo[i] = mkSw_Down(lo[i]); fhi[i] = mkSw_Up(hi[i]); }
	int *seen = calloc((size_t)n + 1, sizeof *seen), pos[8], got, total = 0, chunk = 0, bad_pos = 0, bad_far = 0;
	mkSwWalk w;
	mkSwWalk_Begin(t, &w, flo, fhi);
	while ((got = mkSwWalk_Next(t, &w, flo, fhi, pos, max)) > 0) {
		ENSURE(got <= max);
		for (int k = 0; k < got; ++k) {
			if (pos[k] < 0 || pos[k] >= n) { ++bad_pos; continue; }
			int id = t->order[pos[k]];
			++seen[id];
			++total;
			/* the box at its position is the obstacle's, and its rounding meets the rounded query box */
			if (memcmp(&t->box[pos[k]], &box[id], sizeof box[id]) != 0) ++bad_pos;
			mkSwBox r;
			for (int i = 0; i < 3; ++i) { r.lo[i] = mkSw_Down(box[id].lo[i]); r.hi[i] = mkSw_Up(box[id].hi[i]); }
			double rlo[3] = {flo[0], flo[1], flo[2]}, rhi[3] = {fhi[0], fhi[1], fhi[2]};
			if (!meets(&r, rlo, rhi) && !shrink) ++bad_far;
		}
		if (shrink && chunk++ == 0)
			for (int i = 0; i < 3; ++i) { flo[i] = mkSw_Down(lo2[i]); fhi[i] = mkSw_Up(hi2[i]); }
	}
	int missed = 0, twice = 0;
	for (int i = 0; i < n; ++i) {
		twice += seen[i] > 1;
		if (!seen[i] && meets(&box[i], shrink ? lo2 : lo, shrink ? hi2 : hi)) ++missed;
	}
	ENSURE(bad_pos == 0);
	ENSURE(bad_far == 0);
	ENSURE(missed == 0);
	ENSURE(twice == 0);
	if (missed || twice || bad_far || bad_pos)
		fprintf(stderr, "  n %d, max %d, shrink %d: missed %d, twice %d, outside %d, bad positions %d\n", n, max, shrink,
			missed, twice, bad_far, bad_pos);
	free(seen);
	return total;
}

/* The walk's positions for the query, in order, by the build avx (0: the
 * portable one); returns their number (at most cap). */
static int walk_sequence(mkSwTree *t, int avx, const double lo[3], const double hi[3], int *seq, int cap)
{
	float flo[3], fhi[3];
	for (int i = 0; i < 3; ++i) { flo[i] = mkSw_Down(lo[i]); fhi[i] = mkSw_Up(hi[i]); }
	int keep = t->avx, n = 0, pos[3], got;
	t->avx = avx;
	mkSwWalk w;
	mkSwWalk_Begin(t, &w, flo, fhi);
	while ((got = mkSwWalk_Next(t, &w, flo, fhi, pos, 3)) > 0)
		for (int k = 0; k < got; ++k) if (n < cap) seq[n++] = pos[k];
	t->avx = keep;
	return n;
}

/* n random boxes of half sides in [r0, r1] in a cube of half side half
 * about c (same: all the same box), then random queries. */
static void check_set(int n, double c, double half, double r0, double r1, int same, int queries)
{
	mkSwBox *box = malloc(((size_t)n + 1) * sizeof *box);
	for (int i = 0; i < n; ++i)
		for (int d = 0; d < 3; ++d) {
			double m = same && i > 0 ? 0.5 * (box[0].lo[d] + box[0].hi[d]) : c + uni(-half, half);
			double r = same && i > 0 ? 0.5 * (box[0].hi[d] - box[0].lo[d]) : uni(r0, r1);
			box[i].lo[d] = m - r;
			box[i].hi[d] = m + r;
		}
	mkSwTree t;
	ENSURE(mkSwTree_Build(&t, box, n) == MK_OK);
	ENSURE(t.n == n);
	long hits = 0;
	for (int k = 0; k < queries; ++k) {
		double lo[3], hi[3], lo2[3], hi2[3];
		for (int d = 0; d < 3; ++d) {
			double m = c + uni(-1.2 * half, 1.2 * half), r = uni(0.0, 2.0 * r1 + 1e-300);
			lo[d] = m - r;
			hi[d] = m + r;
		}
		if (k % 5 == 0 && n > 0) { /* a query that touches a box: sharing one face's plane */
			int i = k % n, d = k % 3;
			for (int e = 0; e < 3; ++e) { lo[e] = box[i].lo[e]; hi[e] = box[i].hi[e]; }
			double w = hi[d] - lo[d];
			lo[d] = box[i].hi[d];
			hi[d] = box[i].hi[d] + w;
		}
		for (int d = 0; d < 3; ++d) { /* the shrunk query: half as wide about the same centre */
			double m = 0.5 * (lo[d] + hi[d]), r = 0.25 * (hi[d] - lo[d]);
			lo2[d] = m - r;
			hi2[d] = m + r;
		}
		int max = 1 + k % 8;
		hits += check_walk(&t, box, n, lo, hi, lo2, hi2, max, 0);
		check_walk(&t, box, n, lo, hi, lo2, hi2, max, 1);
		if (mkImpl_Available(MK_IMPL_AVX2) && k % 4 == 0) { /* the two builds: the same walk */
			int *a = malloc(((size_t)n + 1) * sizeof *a), *b = malloc(((size_t)n + 1) * sizeof *b);
			int na = walk_sequence(&t, 0, lo, hi, a, n), nb = walk_sequence(&t, 1, lo, hi, b, n);
			ENSURE(na == nb && memcmp(a, b, (size_t)na * sizeof *a) == 0);
			free(a);
			free(b);
		}
	}
	printf("%6d boxes about %-8g half side %-8g: %d queries, %.2f boxes returned per query, %d nodes\n", n, c, half,
		queries, (double)hits / queries, t.nnode);
	mkSwTree_Free(&t);
	free(box);
}

/* Cells of spheres (mkSwCells) against the test of two spheres written
 * out in double: n spheres of radii in [r0, r1] about random centres in
 * a cube of half side half about c; at random points x (inside the
 * spheres' reach, on the edge of one's, and outside every cell) and radii
 * pr + b <= r, every sphere within (pr + r_i + b)(1 + 1e-12) of x is in
 * x's cell and passes the float test there, and the positions that pass
 * come in the walk's order. Returns the spheres passing per point. */
static double check_cells(int n, double c, double half, double r0, double r1, double rp, int points)
{
	double (*sp)[4] = malloc(((size_t)n + 1) * sizeof *sp);
	mkSwBox *box = malloc(((size_t)n + 1) * sizeof *box);
	for (int i = 0; i < n; ++i) {
		for (int d = 0; d < 3; ++d) sp[i][d] = c + uni(-half, half);
		sp[i][3] = uni(r0, r1);
		for (int d = 0; d < 3; ++d) { box[i].lo[d] = sp[i][d] - sp[i][3]; box[i].hi[d] = sp[i][d] + sp[i][3]; }
	}
	mkSwTree t;
	ENSURE(mkSwTree_Build(&t, box, n) == MK_OK);
	int *rank = malloc(((size_t)n + 1) * sizeof *rank), *seq = malloc(((size_t)n + 1) * sizeof *seq);
	double alo[3] = {-1e38, -1e38, -1e38}, ahi[3] = {1e38, 1e38, 1e38};   /* (the walk's order: a box that meets all) */
	int ns = walk_sequence(&t, t.avx, alo, ahi, seq, n);
	ENSURE(ns == n);
	for (int k = 0; k < ns; ++k) rank[seq[k]] = k;
	double r = rp * uni(0.2, 1.5);
	mkSwCells g;
	ENSURE(mkSwCells_Build(&g, &t, (const double (*)[4])sp, r, 4.0 * r, 1L << 26) == MK_OK);
	ENSURE(g.start != NULL);
	long missed = 0, disorder = 0, passed = 0;
	for (int k = 0; k < points; ++k) {
		double x[3], pr = r * uni(0.0, 1.0), b = r - pr;
		int i = (int)uni(0, n) % n;
		for (int d = 0; d < 3; ++d) x[d] = sp[i][d] + uni(-1.0, 1.0) * (sp[i][3] + r);
		if (k % 4 == 1) { /* on the edge of sphere i's test */
			double u[3] = {uni(-1, 1), uni(-1, 1), uni(-1, 1)}, l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) + 1e-300;
			double e = (pr + sp[i][3] + b) * (1.0 + 1e-12);
			for (int d = 0; d < 3; ++d) x[d] = sp[i][d] + e * u[d] / l;
		}
		if (k % 16 == 2) x[k % 3] = c + (k % 32 == 2 ? 3.0 : -3.0) * (half + r1 + r);   /* outside every cell */
		const mkSwCellBlock *bl = NULL;
		float xf[3];
		int nb = mkSwCells_Find(&g, x, &bl, xf);
		ENSURE(nb >= 0);
		char *in = calloc((size_t)n + 1, 1);
		int last = -1;
		for (int q = 0; q < nb; ++q) {
			unsigned m = mkSwCells_Near(&bl[q], xf);
			for (; m; m &= m - 1) {
				int at = bl[q].pos[mkSw_Low(m)];
				ENSURE(at >= 0 && at < n);
				in[t.order[at]] = 1;
				disorder += rank[at] <= last;
				last = rank[at];
				++passed;
			}
		}
		for (int j = 0; j < n; ++j) {
			double dx = x[0] - sp[j][0], dy = x[1] - sp[j][1], dz = x[2] - sp[j][2], e = (pr + sp[j][3] + b) * (1.0 + 1e-12);
			missed += dx * dx + dy * dy + dz * dz <= e * e && !in[j];
		}
		free(in);
	}
	ENSURE(missed == 0);
	ENSURE(disorder == 0);
	printf("cells: %5d spheres about %-8g half side %-8g: %d points, %.2f spheres pass per point, %ld missed, "
		"%ld out of order\n", n, c, half, points, (double)passed / points, missed, disorder);
	mkSwCells_Free(&g);
	/* a budget too small for any side up to 4 times the first: no cells, nothing held */
	ENSURE(mkSwCells_Build(&g, &t, (const double (*)[4])sp, r, 4.0 * r, 64) == MK_OK);
	ENSURE(g.start == NULL && g.block == NULL);
	mkSwTree_Free(&t);
	free(sp);
	free(box);
	free(rank);
	free(seq);
	return (double)passed / points;
}

/* down(a) <= up(b) for a <= b, and down(x) <= x <= up(x) within the
 * floats' range, over finite doubles of every magnitude and sign. */
static void check_rounding(void)
{
	int bad_order = 0, bad_bracket = 0;
	for (int k = 0; k < 200000; ++k) {
		double e = uni(-320.0, 307.0), x = (k % 2 ? -1.0 : 1.0) * pow(10.0, e) * uni(1.0, 10.0);
		double y = k % 3 == 0 ? x : k % 3 == 1 ? nextafter(x, INFINITY) : x + fabs(x) * uni(0.0, 1e-6);
		if (!(x <= y)) continue;
		if (!(mkSw_Down(x) <= mkSw_Up(y))) ++bad_order;
		if (fabs(x) <= FLT_MAX && !((double)mkSw_Down(x) <= x && x <= (double)mkSw_Up(x))) ++bad_bracket;
	}
	for (int k = -1; k <= 1; ++k) { /* zero and the smallest doubles */
		double x = k * 4.9406564584124654e-324;
		if (!((double)mkSw_Down(x) <= x && x <= (double)mkSw_Up(x))) ++bad_bracket;
		if (!((double)mkSw_Down(0.0) <= 0.0)) ++bad_bracket;
	}
	ENSURE(bad_order == 0);
	ENSURE(bad_bracket == 0);
	printf("float rounding: 200000 pairs over every magnitude: %d out of order, %d not bracketed\n", bad_order, bad_bracket);
}

int main(void)
{
	check_rounding();
	mkSwTree t;
	ENSURE(mkSwTree_Build(&t, NULL, 0) == MK_OK);
	float lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
	int pos[8];
	mkSwWalk w;
	mkSwWalk_Begin(&t, &w, lo, hi);
	ENSURE(mkSwWalk_Next(&t, &w, lo, hi, pos, 8) == 0);   /* no boxes: nothing */
	mkSwTree_Free(&t);
	int sizes[] = {1, 2, 3, 7, 8, 9, 16, 17, 64, 100, 1000, 5000};
	for (size_t s = 0; s < sizeof sizes / sizeof *sizes; ++s) check_set(sizes[s], 0.0, 0.5 * cbrt(80.0 * sizes[s]), 0.3, 1.5, 0, 300);
	check_set(300, 0.0, 10.0, 0.0, 0.0, 0, 300);          /* points */
	check_set(300, 0.0, 10.0, 0.3, 1.5, 1, 100);          /* all the same box */
	check_set(300, 1e30, 1e24, 1e20, 1e23, 0, 300);       /* far out, wide */
	check_set(300, 1e6, 1.0, 1e-6, 1e-3, 0, 300);         /* far out, small: float spacing 0.06 there */
	check_set(300, 0.0, 1e-30, 1e-33, 1e-31, 0, 300);     /* tiny */
	int csizes[] = {1, 2, 16, 100, 1000, 5000};
	for (size_t k = 0; k < sizeof csizes / sizeof *csizes; ++k)
		check_cells(csizes[k], 0.0, 0.5 * cbrt(80.0 * csizes[k]), 0.3, 1.5, 1.5, 400);
	check_cells(300, 1e6, 20.0, 0.3, 1.5, 1.5, 400);       /* far out: float spacing 0.06 there */
	check_cells(300, 1e12, 20.0, 0.3, 1.5, 1.5, 400);      /* farther: float spacing 6.6e4 */
	check_cells(300, 0.0, 1e-20, 1e-23, 1e-21, 1e-21, 400);   /* small: squared distances below the floats' range */
	check_cells(300, 0.0, 10.0, 0.0, 0.0, 0.5, 400);       /* points */
	return mk_summary("test_cspace_wide");
}
