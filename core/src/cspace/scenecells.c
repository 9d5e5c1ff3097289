/* scenecells.c - the cells of the obstacles' spheres (scenewide.h,
 * mkSwCells): the scene query's test of the spheres near a part in place
 * of the hierarchy's walk, built from the hierarchy's order. */
#include "cspace/scenewide.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The positions in the order of the walk of any box: the walk of the
 * largest float box (an unused child's empty box meets none). */
static void mkSw_Sequence(const mkSwTree *t, int *seq)
{
	float lo[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX}, hi[3] = {FLT_MAX, FLT_MAX, FLT_MAX};
	mkSwWalk w;
	int n = 0, got;
	mkSwWalk_Begin(t, &w, lo, hi);
	while ((got = mkSwWalk_Next(t, &w, lo, hi, seq + n, t->n - n)) > 0) n += got;
}

/* The cells' index range [*a, *b] along axis i that may meet [x0, x1]. */
static void mkSw_Range(const mkSwCells *g, int i, double x0, double x1, long *a, long *b)
{
	double f0 = floor((x0 - g->lo[i]) * g->inv) - 1.0, f1 = floor((x1 - g->lo[i]) * g->inv) + 1.0;
	*a = f0 < 0.0 ? 0 : f0 > g->n[i] - 1 ? g->n[i] - 1 : (long)f0;
	*b = f1 < 0.0 ? 0 : f1 > g->n[i] - 1 ? g->n[i] - 1 : (long)f1;
}

/* One pass over the positions in the walk's order: each cell's count
 * (fill NULL), or its entries placed at fill[cell] (the running place). */
static void mkSw_Fill(const mkSwCells *g, const mkSwTree *t, const double (*sphere)[4], const int *seq, double r,
	double slack, long *count, mkSwCellBlock *fill)
{
	double side = 1.0 / g->inv;
	for (int k = 0; k < t->n; ++k) {
		int p = seq[k];
		const double *sp = sphere[t->order[p]];
		double reach = (r + sp[3]) * (1.0 + 1e-9) + slack;
		long a[3], b[3];
		for (int i = 0; i < 3; ++i) mkSw_Range(g, i, sp[i] - reach, sp[i] + reach, &a[i], &b[i]);
		double ur[3], rc = (r + sp[3]) * g->inv;   /* (the centre and the radius in cells) */
		for (int i = 0; i < 3; ++i) ur[i] = (sp[i] - g->lo[i]) * g->inv;
		for (long cz = a[2]; cz <= b[2]; ++cz)
			for (long cy = a[1]; cy <= b[1]; ++cy)
				for (long cx = a[0]; cx <= b[0]; ++cx) {
					long idx[3] = {cx, cy, cz};
					double d2 = 0.0;
					for (int i = 0; i < 3; ++i) {
						double lo = g->lo[i] + (double)idx[i] * side - slack, hi = g->lo[i] + (double)(idx[i] + 1) * side + slack;
						double gap = sp[i] < lo ? lo - sp[i] : sp[i] > hi ? sp[i] - hi : 0.0;
						d2 += gap * gap;
					}
					if (!(d2 <= reach * reach)) continue;
					long c = (cz * g->n[1] + cy) * g->n[0] + cx, at = count[c]++;
					if (!fill) continue;
					mkSwCellBlock *bl = &fill[at / MK_SW_CELL];
					int e = (int)(at % MK_SW_CELL);
					/* the centre in the cell's units and the radius grown beyond the floats' rounding of those
					 * and of the test's operations (relative 2^-22 of numbers up to top), and the doubles' of
					 * the units (2^-50 of the cells' indices) */
					float x = (float)(ur[0] - (double)cx), y = (float)(ur[1] - (double)cy), z = (float)(ur[2] - (double)cz);
					double top = fmax(fabs((double)x), fmax(fabs((double)y), fabs((double)z))) + 2.0;
					double fr = rc * (1.0 + 1e-6) + 1e-6 * top + 1e-12 * (g->n[0] + g->n[1] + g->n[2]);
					bl->x[e] = x;
					bl->y[e] = y;
					bl->z[e] = z;
					bl->rr[e] = (float)(fr * fr * (1.0 + 1e-6));
					bl->pos[e] = p;
				}
	}
}

/* The grid of cells of side `side` over [lo, hi] (g's lo, inv, n); 0 when
 * it would have more than `cells` cells. */
static int mkSw_Grid(mkSwCells *g, const double lo[3], const double hi[3], double side, long cells)
{
	double n[3];
	for (int i = 0; i < 3; ++i) n[i] = fmax(1.0, ceil((hi[i] - lo[i]) / side));
	if (!(n[0] * n[1] * n[2] <= (double)cells)) return 0;
	for (int i = 0; i < 3; ++i) { g->lo[i] = lo[i]; g->n[i] = (int)n[i]; }
	g->inv = 1.0 / side;
	return 1;
}

mkResult mkSwCells_Build(mkSwCells *g, const mkSwTree *t, const double (*sphere)[4], double r, double side, long bytes)
{
	g->start = NULL;
	g->block = NULL;
	g->inv = 0.0;
	for (int i = 0; i < 3; ++i) { g->lo[i] = 0.0; g->n[i] = 0; }
	if (t->n == 0 || !(r >= 0.0) || !isfinite(r) || !(side > 0.0) || !isfinite(side)) return MK_OK;
	double lo[3], hi[3], ext = 0.0;
	for (int i = 0; i < 3; ++i) { lo[i] = INFINITY; hi[i] = -INFINITY; }
	for (int k = 0; k < t->n; ++k) {
		if (!(sphere[k][3] <= 1e30)) return MK_OK;
		for (int i = 0; i < 3; ++i) {
			lo[i] = fmin(lo[i], sphere[k][i] - sphere[k][3] - r);
			hi[i] = fmax(hi[i], sphere[k][i] + sphere[k][3] + r);
		}
	}
	for (int i = 0; i < 3; ++i) {
		if (!(fabs(lo[i]) <= 1e30) || !(fabs(hi[i]) <= 1e30)) return MK_OK;
		ext = fmax(ext, fmax(fabs(lo[i]), fabs(hi[i])));
		side = fmax(side, 1e-6 * (hi[i] - lo[i]));
	}
	long cap = bytes / (long)sizeof(int);
	int *seq = malloc((size_t)t->n * sizeof *seq);
	long *count = calloc((size_t)cap + 1, sizeof *count);
	if (!seq || !count) {
		free(seq);
		free(count);
		return MK_ERR_MEMORY;
	}
	mkSw_Sequence(t, seq);
	/* the side from `side` up (by 1.25) until the blocks fit in bytes, at most 4 times it */
	long total = 0, blocks = 0;
	double slack = 0.0;
	int fits = 0;
	for (double s0 = side; !fits && side <= 4.0 * s0; side *= 1.25) {
		if (!mkSw_Grid(g, lo, hi, side, cap)) continue;
		slack = 1e-9 * (ext + side) + 1e-30;   /* (beyond the rounding of a point's cell index) */
		total = (long)g->n[0] * g->n[1] * g->n[2];
		memset(count, 0, (size_t)total * sizeof *count);
		mkSw_Fill(g, t, sphere, seq, r, slack, count, NULL);
		blocks = 0;
		for (long c = 0; c < total; ++c) blocks += (count[c] + MK_SW_CELL - 1) / MK_SW_CELL;
		fits = (double)blocks * sizeof(mkSwCellBlock) + (double)total * sizeof(int) <= (double)bytes;
	}
	mkResult res = MK_OK;
	if (fits) {
		g->start = malloc(((size_t)total + 1) * sizeof *g->start);
		g->block = aligned_alloc(64, ((size_t)blocks + 1) * sizeof *g->block);
		if (!g->start || !g->block) res = MK_ERR_MEMORY;
		else {
			long at = 0;
			for (long c = 0; c < total; ++c) {
				g->start[c] = (int)at;
				long k = (count[c] + MK_SW_CELL - 1) / MK_SW_CELL;
				count[c] = at * MK_SW_CELL;   /* (the running place of the cell's next entry) */
				at += k;
			}
			g->start[total] = (int)at;
			for (long b = 0; b < at; ++b) /* (unused places never pass) */
				for (int e = 0; e < MK_SW_CELL; ++e) {
					g->block[b].x[e] = g->block[b].y[e] = g->block[b].z[e] = 0.0f;
					g->block[b].rr[e] = -1.0f;
					g->block[b].pos[e] = -1;
				}
			mkSw_Fill(g, t, sphere, seq, r, slack, count, g->block);
		}
	}
	free(count);
	free(seq);
	if (res != MK_OK || !fits) mkSwCells_Free(g);
	return res;
}

void mkSwCells_Free(mkSwCells *g)
{
	free(g->start);
	free(g->block);
	g->start = NULL;
	g->block = NULL;
}
