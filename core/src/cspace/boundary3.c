/* boundary3.c - 3D C-obstacle boundaries: refinement of the octahedron of
 * normals (adaptive until Proof 4's bound meets the tolerance, or uniform),
 * the conforming triangulation, one boundary (inner or outer) and the
 * single-boundary 3D functions of mink/cobstacle.h, Certify included. */
#include "cspace/work.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int mkBoundary3_NewNormal(mkCSpaceWork *w, mkVec3 u, int *nv)
{
	if (!mkCSpaceWork_Verts(w, *nv + 1, 3)) return -1;
	int m = (*nv)++;
	w->n[0][m] = u.x; w->n[1][m] = u.y; w->n[2][m] = u.z;
	return m;
}

/* The midpoint normal of edge (a, b), created on first use; -1 on memory. */
static int mkBoundary3_Midpoint(mkCSpaceWork *w, int a, int b, int *nv)
{
	int m = mkEdgeHash_Find(&w->edges, mkEdgeHash_Undirected(a, b));
	if (m >= 0) return m;
	m = mkBoundary3_NewNormal(w, mkVec3_Normalize(mkVec3_Add(mkWork_Normal3(w, a), mkWork_Normal3(w, b))), nv);
	if (m < 0 || !mkEdgeHash_Put(&w->edges, mkEdgeHash_Undirected(a, b), m)) return -1;
	return m;
}

/* Proof 4 of docs/scene.md: for normals u in the spherical triangle (a, b, c),
 * both h_K(u) - h_P(u) and h_Q(u) - h_K(u) are at most
 *   max over pairs of <n_k - n_j, p_k - p_j> / (3 d0),
 * d0 the distance from the origin to the plane through the three normals. */
static double mkBoundary3_TriangleD0(const mkCSpaceWork *w, int a, int b, int c)
{
	mkVec3 na = mkWork_Normal3(w, a);
	mkVec3 nu = mkVec3_Normalize(mkVec3_Cross(mkVec3_Sub(mkWork_Normal3(w, b), na), mkVec3_Sub(mkWork_Normal3(w, c), na)));
	return fabs(mkVec3_Dot(na, nu));
}

double mkBoundary3_TriangleBound(const mkCSpaceWork *w, int a, int b, int c)
{
	int v[3] = {a, b, c};
	double C = 0.0, sz = 0.0;
	for (int i = 0; i < 3; ++i) {
		int k = v[i], j = v[(i + 1) % 3];
		double t = mkVec3_Dot(mkVec3_Sub(mkWork_Normal3(w, k), mkWork_Normal3(w, j)), mkVec3_Sub(mkWork_Point3(w, k), mkWork_Point3(w, j)));
		if (t > C) C = t;
		sz += mkVec3_Size1(mkWork_Point3(w, k));
	}
	return C / (3.0 * mkBoundary3_TriangleD0(w, a, b, c)) + MK_CSPACE_ROUND_REL * sz;
}

static double mkVec3_Angle(mkVec3 a, mkVec3 b) { return atan2(mkVec3_Length(mkVec3_Cross(a, b)), mkVec3_Dot(a, b)); }

static mkResult mkBoundary3_EvalPending(mkCSpaceWork *w, mkBody3 b1, mkBody3 b2, mkImpl impl, int *neval, int nv)
{
	if (nv <= *neval) return MK_OK;
	mkResult r = mkContact3_Points(b1, b2, impl, w->n[0] + *neval, w->n[1] + *neval, w->n[2] + *neval, nv - *neval,
		w->p[0] + *neval, w->p[1] + *neval, w->p[2] + *neval);
	*neval = nv;
	return r;
}

/* The vertices on edge a -> b strictly between them (midpoints made by
 * finer neighbours), in order, appended to w->poly. */
static int mkBoundary3_Chain(mkCSpaceWork *w, int a, int b, int *len)
{
	int m = mkEdgeHash_Find(&w->edges, mkEdgeHash_Undirected(a, b));
	if (m < 0) return 1;
	if (!mkBoundary3_Chain(w, a, m, len)) return 0;
	if (!mkGrow_Ints(&w->poly, &w->pcap, *len + 1)) return 0;
	w->poly[(*len)++] = m;
	return mkBoundary3_Chain(w, m, b, len);
}

/* Adaptive (splits < 0) or uniform refinement of the octahedron of normals,
 * then (conform = 1) the conforming closed triangulation: a leaf whose
 * edges carry vertices of finer neighbours gets a new normal at its
 * centroid and is fanned from it. Vertices 0..*count-1 (w->n, w->p), final triangles in
 * w->fin (*nfin, counter-clockwise from outside). *error: the largest leaf
 * bound (which holds on the final triangulation too: Proof 4 needs only the
 * leaf's corners). *d0min: the smallest d0 of the leaves. */
static mkResult mkBoundary3_Refine(mkCSpaceWork *w, mkBody3 b1, mkBody3 b2, mkImpl impl, double tol, int max_points, int splits,
	int conform, int *count, int *nfin, double *error, double *d0min)
{
	static const double oct[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
	mkEdgeHash_Clear(&w->edges);
	if (!mkCSpaceWork_Verts(w, 6, 3) || !mkGrow_Ints(&w->tri, &w->tcap, 24)) return MK_ERR_MEMORY;
	for (int i = 0; i < 6; ++i)
		for (int d = 0; d < 3; ++d) w->n[d][i] = oct[i][d];
	int na = 0;
	for (int s = 0; s < 8; ++s) {
		int x = (s & 1) ? 1 : 0, y = (s & 2) ? 3 : 2, z = (s & 4) ? 5 : 4;
		int neg = ((s & 1) != 0) + ((s & 2) != 0) + ((s & 4) != 0);
		w->tri[3 * na] = x;
		w->tri[3 * na + 1] = neg % 2 ? z : y;
		w->tri[3 * na + 2] = neg % 2 ? y : z;
		++na;
	}
	int nv = 6, neval = 0, nl = 0, level = 0;
	double maxerr = 0.0, dmin = 1.0;
	mkResult r;
	while (na > 0) {
		if (!mkCSpaceWork_Verts(w, nv, 3)) return MK_ERR_MEMORY;
		if ((r = mkBoundary3_EvalPending(w, b1, b2, impl, &neval, nv)) != MK_OK) return r;
		int nn = 0;
		for (int t = 0; t < na; ++t) {
			int a = w->tri[3 * t], b = w->tri[3 * t + 1], c = w->tri[3 * t + 2];
			int split;
			double err = 0.0;
			if (splits >= 0) {
				split = level < splits;
				if (!split) err = mkBoundary3_TriangleBound(w, a, b, c);
			} else {
				err = mkBoundary3_TriangleBound(w, a, b, c);
				double ang = mkVec3_Angle(mkWork_Normal3(w, a), mkWork_Normal3(w, b));
				split = err > tol && ang > MK_CSPACE_MIN_ANGLE && nv + 3 <= max_points;
			}
			if (!split) {
				if (err > maxerr || err != err) maxerr = err;
				double d0 = mkBoundary3_TriangleD0(w, a, b, c);
				if (d0 < dmin) dmin = d0;
				if (!mkGrow_Ints(&w->leaf, &w->lcap, 3 * (nl + 1))) return MK_ERR_MEMORY;
				w->leaf[3 * nl] = a; w->leaf[3 * nl + 1] = b; w->leaf[3 * nl + 2] = c;
				++nl;
				continue;
			}
			int ab = mkBoundary3_Midpoint(w, a, b, &nv), bc = mkBoundary3_Midpoint(w, b, c, &nv), ca = mkBoundary3_Midpoint(w, c, a, &nv);
			if (ab < 0 || bc < 0 || ca < 0 || !mkGrow_Ints(&w->tri2, &w->t2cap, 3 * (nn + 4))) return MK_ERR_MEMORY;
			int ch[4][3] = {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}};
			for (int k = 0; k < 4; ++k) {
				for (int d = 0; d < 3; ++d) w->tri2[3 * nn + d] = ch[k][d];
				++nn;
			}
		}
		int *tt = w->tri; w->tri = w->tri2; w->tri2 = tt;
		int tc = w->tcap; w->tcap = w->t2cap; w->t2cap = tc;
		na = nn;
		++level;
	}
	/* the conforming triangulation (outer bounds only) */
	int nf = 0;
	for (int t = 0; t < nl && conform; ++t) {
		int v[3] = {w->leaf[3 * t], w->leaf[3 * t + 1], w->leaf[3 * t + 2]};
		int len = 0;
		for (int e = 0; e < 3; ++e) {
			if (!mkGrow_Ints(&w->poly, &w->pcap, len + 1)) return MK_ERR_MEMORY;
			w->poly[len++] = v[e];
			if (!mkBoundary3_Chain(w, v[e], v[(e + 1) % 3], &len)) return MK_ERR_MEMORY;
		}
		if (!mkGrow_Ints(&w->fin, &w->fcap, 3 * (nf + len))) return MK_ERR_MEMORY;
		if (len == 3) {
			for (int d = 0; d < 3; ++d) w->fin[3 * nf + d] = v[d];
			++nf;
			continue;
		}
		mkVec3 cen = mkVec3_Normalize(mkVec3_Add(mkVec3_Add(mkWork_Normal3(w, v[0]), mkWork_Normal3(w, v[1])), mkWork_Normal3(w, v[2])));
		int c = mkBoundary3_NewNormal(w, cen, &nv);
		if (c < 0) return MK_ERR_MEMORY;
		for (int k = 0; k < len; ++k) {
			w->fin[3 * nf] = c;
			w->fin[3 * nf + 1] = w->poly[k];
			w->fin[3 * nf + 2] = w->poly[(k + 1) % len];
			++nf;
		}
	}
	if ((r = mkBoundary3_EvalPending(w, b1, b2, impl, &neval, nv)) != MK_OK) return r;
	*count = nv;
	*nfin = nf;
	*error = maxerr;
	*d0min = dmin;
	return MK_OK;
}

/* The vertex where the tangent planes of triangle t's normals meet, solved
 * relative to its first corner's point. */

/* One 3D boundary into w: inner (points w->p, triangles w->fin) or outer
 * (points w->o, triangles in *faces). */
mkResult mkBoundary3_Compute(mkCSpaceWork *w, mkBody3 b1, mkBody3 b2, mkImpl impl, mkBound bound, double tol, int max_points,
	int splits, int want_faces, int *count, int *nfaces, int **faces, int *fcap, double *error)
{
	int nv = 0, nfin = 0;
	double err = 0.0, d0 = 1.0;
	mkResult r = mkBoundary3_Refine(w, b1, b2, impl, tol, max_points, splits, bound == MK_BOUND_OUTER, &nv, &nfin, &err, &d0);
	if (r != MK_OK) return r;
	if (bound == MK_BOUND_INNER) {
		int nf = want_faces ? mkHull3_Build(w, nv, faces, fcap) : 0;
		if (nf < 0) return MK_ERR_MEMORY;
		*count = nv;
		*nfaces = nf;
		*error = err;
		return MK_OK;
	}
	double ex = 0.0;
	int nf = mkBoundary3_Outer(w, nv, nfin, faces, fcap, &ex);
	if (nf < 0) return MK_ERR_MEMORY;
	*count = nfin;
	*nfaces = nf;
	*error = err + ex / d0;
	return MK_OK;
}

static mkResult mkBoundary3_Single(mkBody3 b1, mkBody3 b2, mkBound bound, double tol, int max_points, int splits, mkImpl impl,
	double **x, double **y, double **z, int *cap, int **faces, int *face_cap, int *count, int *face_count,
	double *error)
{
	if (!x || !y || !z || !cap || !count || !error || (bound != MK_BOUND_INNER && bound != MK_BOUND_OUTER)
		|| (faces && (!face_cap || !face_count)))
		return MK_ERR_ARGUMENT;
	mkCSpaceWork w;
	memset(&w, 0, sizeof w);
	int n = 0, nf = 0, *tmp = NULL, tcap = 0;
	double e = 0.0;
	mkResult r = mkBoundary3_Compute(&w, b1, b2, impl, bound, tol, max_points, splits, faces != NULL, &n, &nf,
		faces ? faces : &tmp, faces ? face_cap : &tcap, &e);
	free(tmp);
	if (r == MK_OK) {
		int c1 = *cap, c2 = *cap, c3 = *cap;
		if (!mkGrow_Doubles(x, &c1, n) || !mkGrow_Doubles(y, &c2, n) || !mkGrow_Doubles(z, &c3, n)) r = MK_ERR_MEMORY;
		else {
			*cap = c1 < c2 ? (c1 < c3 ? c1 : c3) : (c2 < c3 ? c2 : c3);
			double *const *src = bound == MK_BOUND_INNER ? w.p : w.o;
			memcpy(*x, src[0], (size_t)n * sizeof(double));
			memcpy(*y, src[1], (size_t)n * sizeof(double));
			memcpy(*z, src[2], (size_t)n * sizeof(double));
			*count = n;
			if (face_count) *face_count = faces ? nf : 0;
			*error = e;
		}
	}
	mkCSpaceWork_Free(&w);
	return r;
}

mkResult mkCSpace3_Adaptive(mkBody3 b1, mkBody3 b2, mkBound bound, double tol, int max_points, mkImpl impl,
	double **x, double **y, double **z, int *cap, int **faces, int *face_cap, int *count, int *face_count,
	double *error)
{
	if (!(tol > 0.0) || !isfinite(tol) || max_points < 6) return MK_ERR_ARGUMENT;
	return mkBoundary3_Single(b1, b2, bound, tol, max_points, -1, impl, x, y, z, cap, faces, face_cap, count, face_count, error);
}

mkResult mkCSpace3_Uniform(mkBody3 b1, mkBody3 b2, mkBound bound, int splits, mkImpl impl,
	double **x, double **y, double **z, int *cap, int **faces, int *face_cap, int *count, int *face_count,
	double *error)
{
	if (splits < 0 || splits > MK_CSPACE_MAX_SPLITS) return MK_ERR_ARGUMENT;
	return mkBoundary3_Single(b1, b2, bound, 1.0, 1 << 30, splits, impl, x, y, z, cap, faces, face_cap, count, face_count, error);
}

mkResult mkCSpace3_Certify(mkBody3 b1, mkBody3 b2, const double *nx, const double *ny, const double *nz, int n,
	const int *tris, int ntri, mkImpl impl, double *error)
{
	if (n < 4 || ntri < 4 || !nx || !ny || !nz || !tris || !error) return MK_ERR_ARGUMENT;
	for (int t = 0; t < 3 * ntri; ++t)
		if (tris[t] < 0 || tris[t] >= n) return MK_ERR_ARGUMENT;
	mkCSpaceWork w;
	memset(&w, 0, sizeof w);
	mkResult r = MK_OK;
	if (!mkCSpaceWork_Verts(&w, n, 3)) { r = MK_ERR_MEMORY; goto done; }
	for (int k = 0; k < n; ++k) {
		mkVec3 u = mkVec3_Normalize(mkVec3_Make(nx[k], ny[k], nz[k]));
		if (!(u.x == u.x && u.y == u.y && u.z == u.z)) { r = MK_ERR_ARGUMENT; goto done; }
		w.n[0][k] = u.x; w.n[1][k] = u.y; w.n[2][k] = u.z;
	}
	if ((r = mkContact3_Points(b1, b2, impl, w.n[0], w.n[1], w.n[2], n, w.p[0], w.p[1], w.p[2])) != MK_OK) goto done;
	/* Proof 4 needs the triangles to partition the sphere: every one
	 * positively oriented and their areas summing to 4 pi */
	double area = 0.0, err = 0.0;
	for (int t = 0; t < ntri; ++t) {
		int a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
		mkVec3 na = mkWork_Normal3(&w, a), nb = mkWork_Normal3(&w, b), nc = mkWork_Normal3(&w, c);
		double det = mkVec3_Det(na, nb, nc);
		if (!(det > 0.0)) { err = INFINITY; break; }
		area += 2.0 * atan2(det, 1.0 + mkVec3_Dot(na, nb) + mkVec3_Dot(nb, nc) + mkVec3_Dot(nc, na));
		double e = mkBoundary3_TriangleBound(&w, a, b, c);
		if (e > err || e != e) err = e;
	}
	if (!(fabs(area - 4.0 * MK_PI) <= 1e-9)) err = INFINITY;
	*error = err;
done:
	mkCSpaceWork_Free(&w);
	return r;
}
