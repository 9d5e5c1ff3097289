/* sampled.c - the sampled baselines: the convex hull of all pairwise sums
 * of boundary samples (the paper's "definition" method, a family of
 * registry entries, one per hull library, bound in registry.c) and edge
 * sorting (2D). */
#include <stdlib.h>

#include <mink/baselines.h>
#include <mink/registry.h>

#include "registry_internal.h"

mkResult mkHullSums2_Run(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out, mkHullFn hull)
{
	if (!out) return MK_ERR_ARGUMENT;
	if (n < MK_SAMPLED_N_MIN || n > MK_HULL2_N_MAX) return MK_ERR_RANGE;
	size_t count = (size_t)n * (size_t)n;
	double *pq = malloc(4 * (size_t)n * sizeof *pq);
	double *s = malloc(2 * count * sizeof *s);
	mkResult r = pq && s ? MK_OK : MK_ERR_MEMORY;
	if (r == MK_OK) r = mkSampled2_Bodies(b1, b2, set, n, pq, pq + 2 * n);
	if (r == MK_OK) {
		mkSampled2_Sums(pq, n, pq + 2 * n, n, s);
		r = hull(s, (int)count, out);
	}
	free(pq);
	free(s);
	return r;
}

mkResult mkHullSums3_Run(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out, mkHullFn hull)
{
	if (!out) return MK_ERR_ARGUMENT;
	if (n < MK_SAMPLED_N_MIN || n > MK_HULL3_N_MAX) return MK_ERR_RANGE;
	int per = n * n;
	size_t count = (size_t)per * (size_t)per;
	double *pq = malloc(6 * (size_t)per * sizeof *pq);
	double *s = malloc(3 * count * sizeof *s);
	mkResult r = pq && s ? MK_OK : MK_ERR_MEMORY;
	if (r == MK_OK) r = mkSampled3_Bodies(b1, b2, set, n, pq, pq + 3 * (size_t)per);
	if (r == MK_OK) {
		mkSampled3_Sums(pq, per, pq + 3 * (size_t)per, per, s);
		r = hull(s, (int)count, out);
	}
	free(pq);
	free(s);
	return r;
}

/* Edge sorting: each body's samples as a convex polygon (rounding can make
 * samples of nearly flat or nearly pointed bodies collinear or reflex; such
 * samples are dropped, exactly), the O(m + n) merge, and the same exact
 * cleanup of the merged vertices, whose sums are rounded. */
mkResult mkEdgeSort2_Run(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	if (!out) return MK_ERR_ARGUMENT;
	if (n < MK_SAMPLED_N_MIN || n > MK_EDGESORT_N_MAX) return MK_ERR_RANGE;
	double *pq = malloc(4 * (size_t)n * sizeof *pq);
	double *poly = malloc(4 * (size_t)n * sizeof *poly);
	mkResult r = pq && poly ? MK_OK : MK_ERR_MEMORY;
	if (r == MK_OK) r = mkSampled2_Bodies(b1, b2, set, n, pq, pq + 2 * n);
	if (r == MK_OK) {
		int m1 = mkPolygon2_Convex(pq, n, poly);
		int m2 = mkPolygon2_Convex(pq + 2 * n, n, poly + 2 * n);
		if (m1 < 0 || m2 < 0) r = MK_ERR_MEMORY;
		else r = mkEdgeSort2_Merge(poly, m1, poly + 2 * n, m2, out);
	}
	if (r == MK_OK) {
		/* Interleave the merged polygon (at most 2n vertices) into pq and
		 * make it strictly convex. */
		int h = out->count;
		for (int k = 0; k < h; ++k) {
			pq[2 * k] = out->x[k];
			pq[2 * k + 1] = out->y[k];
		}
		int c = mkPolygon2_Convex(pq, h, poly);
		if (c < 0) r = MK_ERR_MEMORY;
		else if (c < 3) r = MK_ERR_ARGUMENT; /* no area */
		else {
			out->count = c;
			for (int k = 0; k < c; ++k) {
				out->x[k] = poly[2 * k];
				out->y[k] = poly[2 * k + 1];
			}
		}
	}
	free(pq);
	free(poly);
	return r;
}
