/* outer3.c - the outer 3D boundary (Proof 5 of docs/scene.md): the
 * polytope cut out by the tangent planes at the normals of the final
 * triangulation, made locally convex by Lawson flips, with the excess that
 * enters its certificate where a flip is blocked. */
#include "cspace/work.h"

#include <math.h>
#include <stdlib.h>

static mkVec3 mkBoundary3_TangentPoint(const mkCSpaceWork *w, int a, int b, int c)
{
	mkVec3 na = mkWork_Normal3(w, a), nb = mkWork_Normal3(w, b), nc = mkWork_Normal3(w, c), pa = mkWork_Point3(w, a);
	double rb = mkVec3_Dot(nb, mkVec3_Sub(mkWork_Point3(w, b), pa)), rc = mkVec3_Dot(nc, mkVec3_Sub(mkWork_Point3(w, c), pa));
	double det = mkVec3_Dot(na, mkVec3_Cross(nb, nc));
	mkVec3 y = mkVec3_Scale(mkVec3_Add(mkVec3_Scale(mkVec3_Cross(nc, na), rb), mkVec3_Scale(mkVec3_Cross(na, nb), rc)),
		1.0 / det);
	return mkVec3_Add(pa, y);
}

/* 1 when the edge a -> b of triangle (a, b, c), whose other side is
 * (b, a, d), should be flipped: inner, when p_d lies outside the plane of
 * p_a, p_b, p_c (the surface is not convex there); outer, when the tangent
 * vertex of (a, b, c) lies outside the tangent plane of d (the planes'
 * polytope has another face structure there). */
static int mkBoundary3_WantsFlip(const mkCSpaceWork *w, mkBound bound, int a, int b, int c, int d)
{
	if (bound == MK_BOUND_INNER) {
		mkVec3 pa = mkWork_Point3(w, a);
		mkVec3 nrm = mkVec3_Cross(mkVec3_Sub(mkWork_Point3(w, b), pa), mkVec3_Sub(mkWork_Point3(w, c), pa));
		mkVec3 e = mkVec3_Sub(mkWork_Point3(w, d), pa);
		double sc = mkVec3_Length(nrm) * mkVec3_Length(e);
		return mkVec3_Dot(nrm, e) > 1e-12 * sc;
	}
	mkVec3 v = mkBoundary3_TangentPoint(w, a, b, c), pd = mkWork_Point3(w, d);
	double ex = mkVec3_Dot(mkWork_Normal3(w, d), mkVec3_Sub(v, pd));
	return ex > 1e-12 * (mkVec3_Size1(v) + mkVec3_Size1(pd));
}


/* Lawson flips of the final triangulation (w->fin) until every edge is
 * locally convex for `bound` or can no longer be flipped (the quadrilateral
 * of normals is not convex, or a pass limit). Every flip keeps a partition
 * of the sphere of normals into proper spherical triangles. Where a flip is
 * blocked the outer polytope's excess enters its certificate. Used for the
 * outer polytope; the inner one takes its faces from hull3. The certificates do not
 * depend on the faces (Proofs 4 and 5 use the normals' leaf triangles and,
 * for the outer polytope, the measured excess), only the output's face
 * structure does. */
static int mkBoundary3_FlipAll(mkCSpaceWork *w, int nfin, mkBound bound)
{
	mkEdgeHash_Clear(&w->dedges);
	for (int t = 0; t < nfin; ++t)
		for (int e = 0; e < 3; ++e)
			if (!mkEdgeHash_Put(&w->dedges, mkEdgeHash_Directed(w->fin[3 * t + e], w->fin[3 * t + (e + 1) % 3]), t)) return 0;
	for (int pass = 0; pass < 64; ++pass) {
		int flips = 0;
		for (int t = 0; t < nfin; ++t)
			for (int e = 0; e < 3; ++e) {
				int *T = w->fin + 3 * t;
				int a = T[e], b = T[(e + 1) % 3], c = T[(e + 2) % 3];
				int u = mkEdgeHash_Find(&w->dedges, mkEdgeHash_Directed(b, a));
				if (u < 0) continue;
				int *U = w->fin + 3 * u, f = 0;
				while (U[f] != b) ++f;
				int d = U[(f + 2) % 3];
				if (d == c || !mkBoundary3_WantsFlip(w, bound, a, b, c, d)) continue;
				/* new triangles (a, d, c) and (d, b, c): both must be proper
				 * spherical triangles of normals, so that the triangulation
				 * stays a partition of the sphere of normals */
				mkVec3 na = mkWork_Normal3(w, a), nb = mkWork_Normal3(w, b), nc = mkWork_Normal3(w, c), nd = mkWork_Normal3(w, d);
				if (!(mkVec3_Det(na, nd, nc) > 0.0 && mkVec3_Det(nd, nb, nc) > 0.0)) continue;
				if (mkEdgeHash_Find(&w->dedges, mkEdgeHash_Directed(d, c)) >= 0) continue; /* edge exists already */
				int ks[6][2] = {{a, b}, {b, c}, {c, a}, {b, a}, {a, d}, {d, b}};
				for (int k = 0; k < 6; ++k) mkEdgeHash_Remove(&w->dedges, mkEdgeHash_Directed(ks[k][0], ks[k][1]));
				T[0] = a; T[1] = d; T[2] = c;
				U[0] = d; U[1] = b; U[2] = c;
				int ok = mkEdgeHash_Put(&w->dedges, mkEdgeHash_Directed(a, d), t) && mkEdgeHash_Put(&w->dedges, mkEdgeHash_Directed(d, c), t)
					&& mkEdgeHash_Put(&w->dedges, mkEdgeHash_Directed(c, a), t) && mkEdgeHash_Put(&w->dedges, mkEdgeHash_Directed(d, b), u)
					&& mkEdgeHash_Put(&w->dedges, mkEdgeHash_Directed(b, c), u) && mkEdgeHash_Put(&w->dedges, mkEdgeHash_Directed(c, d), u);
				if (!ok) return 0;
				++flips;
				break; /* triangle t changed: its edges are looked at on the next pass */
			}
		if (!flips) break;
	}
	return 1;
}

/* The outer polytope (Proof 5 of docs/scene.md): one vertex per final
 * triangle, where the tangent planes of its three normals meet (solved
 * relative to the first corner's point), and for each normal the face of
 * the vertices of its triangles in turn around it. Returns the faces
 * count (triangles in *faces) or -1; *excess: the largest amount by which a
 * vertex lies outside some tangent plane (0 for a regular triangulation,
 * up to rounding). */
int mkBoundary3_Outer(mkCSpaceWork *w, int nv, int nfin, int **faces, int *fcap, double *excess)
{
	for (int d = 0; d < 3; ++d)
		if (!mkGrow_Doubles(&w->o[d], &w->ocap[d], nfin)) return -1;
	if (!mkBoundary3_FlipAll(w, nfin, MK_BOUND_OUTER)) return -1;
	for (int t = 0; t < nfin; ++t) {
		mkVec3 v = mkBoundary3_TangentPoint(w, w->fin[3 * t], w->fin[3 * t + 1], w->fin[3 * t + 2]);
		w->o[0][t] = v.x; w->o[1][t] = v.y; w->o[2][t] = v.z;
	}
	double ex = 0.0;
	for (int k = 0; k < nv; ++k) {
		mkVec3 n = mkWork_Normal3(w, k);
		double h = mkVec3_Dot(n, mkWork_Point3(w, k));
		for (int t = 0; t < nfin; ++t) {
			double e = n.x * w->o[0][t] + n.y * w->o[1][t] + n.z * w->o[2][t] - h;
			if (e > ex || e != e) ex = e;
		}
	}
	*excess = ex;
	mkEdgeHash_Clear(&w->dedges);
	for (int t = 0; t < nfin; ++t)
		for (int e = 0; e < 3; ++e)
			if (!mkEdgeHash_Put(&w->dedges, mkEdgeHash_Directed(w->fin[3 * t + e], w->fin[3 * t + (e + 1) % 3]), t)) return -1;
	/* each normal's face: from a triangle (k, a, b) on to the one holding k -> b */
	int *start = malloc((size_t)nv * sizeof *start);
	if (!start) return -1;
	for (int k = 0; k < nv; ++k) start[k] = -1;
	for (int t = 0; t < nfin; ++t)
		for (int e = 0; e < 3; ++e)
			if (start[w->fin[3 * t + e]] < 0) start[w->fin[3 * t + e]] = t;
	int nf = 0;
	for (int k = 0; k < nv; ++k) {
		if (start[k] < 0) continue;
		int len = 0, t = start[k];
		do {
			if (!mkGrow_Ints(&w->poly, &w->pcap, len + 1)) { free(start); return -1; }
			w->poly[len++] = t;
			int e = 0;
			while (w->fin[3 * t + e] != k) ++e;
			int b = w->fin[3 * t + (e + 2) % 3];
			t = mkEdgeHash_Find(&w->dedges, mkEdgeHash_Directed(k, b));
		} while (t >= 0 && t != start[k] && len <= nfin);
		if (t < 0 || len > nfin) { free(start); return -1; } /* not a closed surface: cannot happen */
		if (!mkGrow_Ints(faces, fcap, 3 * (nf + len))) { free(start); return -1; }
		for (int j = 1; j + 1 < len; ++j) {
			(*faces)[3 * nf] = w->poly[0];
			(*faces)[3 * nf + 1] = w->poly[j];
			(*faces)[3 * nf + 2] = w->poly[j + 1];
			++nf;
		}
	}
	free(start);
	return nf;
}
