/* hull_qhull.c - convex hulls with libqhull_r (reentrant Qhull), the
 * Quickhull that MATLAB's convhull runs, so that the paper's baseline is
 * measured as it was. Qhull decides in floating point; its default merging
 * keeps the output convex within its own roundoff estimate. */
#include <stdio.h>
#include <stdlib.h>

#include <libqhull_r/qhull_ra.h>

#include <mink/baselines.h>
#include <mink/registry.h>

static mkResult from_exitcode(int code)
{
	switch (code) {
	case qh_ERRnone: return MK_OK;
	case qh_ERRsingular: return MK_ERR_ARGUMENT; /* flat input */
	case qh_ERRmem: return MK_ERR_MEMORY;
	default: return MK_ERR_UNSUPPORTED;
	}
}

/* 2D: walk the hull's edges (qhull's facets) from neighbour to neighbour,
 * as qhull's own extreme-points output ('Fx') does, which gives the vertices
 * in counter-clockwise order. */
static mkResult collect2(qhT *qh, const double *xy, mkPointSet *out)
{
	int nf = qh->num_facets;
	mkResult r = mkPointSet_Resize(out, 2, nf);
	if (r != MK_OK) return r;
	facetT *start = qh->facet_list, *facet = start;
	int k = 0;
	do {
		vertexT *a;
		facetT *next;
		if (facet->toporient ^ qh_ORIENTclock) {
			a = SETfirstt_(facet->vertices, vertexT);
			next = SETfirstt_(facet->neighbors, facetT);
		} else {
			a = SETsecondt_(facet->vertices, vertexT);
			next = SETsecondt_(facet->neighbors, facetT);
		}
		if (k == nf) return MK_ERR_UNSUPPORTED; /* the walk did not close */
		int id = qh_pointid(qh, a->point);
		out->x[k] = xy[2 * id];
		out->y[k] = xy[2 * id + 1];
		++k;
		facet = next;
	} while (facet && facet != start);
	if (!facet) return MK_ERR_UNSUPPORTED;
	out->count = k;
	/* The walk's sense follows qh_ORIENTclock; make sure of it from the
	 * signed area (a hull's area is far from zero compared with its
	 * rounding) and reverse a clockwise walk. */
	double area = 0;
	for (int i = 0; i < k; ++i) {
		int j = (i + 1) % k;
		area += out->x[i] * out->y[j] - out->x[j] * out->y[i];
	}
	if (area < 0)
		for (int i = 0, j = k - 1; i < j; ++i, --j) {
			double tx = out->x[i], ty = out->y[i];
			out->x[i] = out->x[j];
			out->y[i] = out->y[j];
			out->x[j] = tx;
			out->y[j] = ty;
		}
	/* Start at the lowest-leftmost vertex, as the other hulls do. */
	int best = 0;
	for (int i = 1; i < k; ++i)
		if (out->y[i] < out->y[best] || (out->y[i] == out->y[best] && out->x[i] < out->x[best])) best = i;
	if (best) {
		double *tmp = malloc(2 * (size_t)k * sizeof *tmp);
		if (!tmp) return MK_ERR_MEMORY;
		for (int i = 0; i < k; ++i) {
			tmp[i] = out->x[(best + i) % k];
			tmp[k + i] = out->y[(best + i) % k];
		}
		for (int i = 0; i < k; ++i) {
			out->x[i] = tmp[i];
			out->y[i] = tmp[k + i];
		}
		free(tmp);
	}
	return MK_OK;
}

static mkResult collect3(qhT *qh, const double *xyz, mkPointSet *out)
{
	mkResult r = mkPointSet_Resize(out, 3, qh->num_vertices);
	if (r != MK_OK) return r;
	vertexT *vertex;
	int k = 0;
	FORALLvertices {
		if (k == qh->num_vertices) return MK_ERR_UNSUPPORTED;
		int id = qh_pointid(qh, vertex->point);
		out->x[k] = xyz[3 * id];
		out->y[k] = xyz[3 * id + 1];
		out->z[k] = xyz[3 * id + 2];
		++k;
	}
	out->count = k;
	return MK_OK;
}

static mkResult run(int dim, const double *pts, int count, mkPointSet *out)
{
	if (!pts || !out || count < dim + 1) return MK_ERR_ARGUMENT;
	/* qhull takes a non-const array but, without scaling options, does not
	 * write to it; a copy keeps the caller's array const all the same. */
	size_t bytes = (size_t)dim * (size_t)count * sizeof(coordT);
	coordT *coords = malloc(bytes);
	if (!coords) return MK_ERR_MEMORY;
	for (size_t i = 0; i < (size_t)dim * (size_t)count; ++i) coords[i] = pts[i];
	qhT qh_qh;
	qhT *qh = &qh_qh;
	char cmd2[] = "qhull", cmd3[] = "qhull Qt";
	qh_zero(qh, stderr);
	int code = qh_new_qhull(qh, dim, count, coords, False, dim == 2 ? cmd2 : cmd3, NULL, stderr);
	mkResult r = from_exitcode(code);
	if (r == MK_OK) r = dim == 2 ? collect2(qh, pts, out) : collect3(qh, pts, out);
	int curlong, totlong;
	qh_freeqhull(qh, !qh_ALL);
	qh_memfreeshort(qh, &curlong, &totlong);
	free(coords);
	return r;
}

mkResult mkHull2_Qhull(const double *xy, int count, mkPointSet *out)
{
	return run(2, xy, count, out);
}

mkResult mkHull3_Qhull(const double *xyz, int count, mkPointSet *out)
{
	return run(3, xyz, count, out);
}
