/* hull3.c - the inner 3D boundary's faces: the convex hull of its points,
 * built incrementally in index order (so deterministic), with an edge hash
 * from each directed edge to its face. */
#include "cspace/work.h"

#include <math.h>
#include <stdlib.h>

/* The hull under construction: faces F (3 vertices each), their planes P
 * (unit normal, offset), alive (1 on the hull, 2 visible and being
 * removed, 0 removed), and the scratch of one insertion. */
typedef struct mkHull3 {
	mkCSpaceWork *w;
	int *F;
	double *P;
	char *alive;
	int cap, nf;
	int *stack, scap, *vis, vcap, *hor, hcap;
	mkVec3 inside;
	double eps;
} mkHull3;

static void mkHull3_Free(mkHull3 *h)
{
	free(h->F); free(h->P); free(h->alive); free(h->stack); free(h->vis); free(h->hor);
}

/* The signed distance of p above face f's plane. */
static double mkHull3_Height(const mkHull3 *h, int f, mkVec3 p)
{
	const double *P = h->P;
	return P[4 * f] * p.x + P[4 * f + 1] * p.y + P[4 * f + 2] * p.z - P[4 * f + 3];
}

/* A face (a, b, c), turned to face away from the inside point; 0 on memory. */
static int mkHull3_AddFace(mkHull3 *h, int a, int b, int c)
{
	if (h->nf == h->cap) {
		h->cap *= 2;
		int *nF = realloc(h->F, (size_t)h->cap * 3 * sizeof *h->F);
		if (!nF) return 0;
		h->F = nF;
		double *nP = realloc(h->P, (size_t)h->cap * 4 * sizeof *h->P);
		if (!nP) return 0;
		h->P = nP;
		char *nA = realloc(h->alive, (size_t)h->cap);
		if (!nA) return 0;
		h->alive = nA;
	}
	const mkCSpaceWork *w = h->w;
	mkVec3 pa = mkWork_Point3(w, a);
	mkVec3 nn = mkVec3_Normalize(mkVec3_Cross(mkVec3_Sub(mkWork_Point3(w, b), pa), mkVec3_Sub(mkWork_Point3(w, c), pa)));
	if (mkVec3_Dot(nn, mkVec3_Sub(h->inside, pa)) > 0.0) { int t = b; b = c; c = t; nn = mkVec3_Neg(nn); }
	int f = h->nf;
	h->F[3 * f] = a; h->F[3 * f + 1] = b; h->F[3 * f + 2] = c;
	h->P[4 * f] = nn.x; h->P[4 * f + 1] = nn.y; h->P[4 * f + 2] = nn.z; h->P[4 * f + 3] = mkVec3_Dot(nn, pa);
	h->alive[f] = 1;
	mkEdgeHash *e = &h->w->dedges;
	if (!mkEdgeHash_Put(e, mkEdgeHash_Directed(a, b), f) || !mkEdgeHash_Put(e, mkEdgeHash_Directed(b, c), f)
		|| !mkEdgeHash_Put(e, mkEdgeHash_Directed(c, a), f))
		return 0;
	++h->nf;
	return 1;
}

/* A first tetrahedron of far-apart points into v; 0 when the points are
 * degenerate (flat within eps). */
static int mkHull3_Tetrahedron(const mkCSpaceWork *w, int n, double eps, int v[4])
{
	int i0 = 0;
	for (int k = 1; k < n; ++k) if (w->p[0][k] < w->p[0][i0]) i0 = k;
	int i1 = -1, i2 = -1, i3 = -1;
	double best = 0.0;
	for (int k = 0; k < n; ++k) {
		double d = mkVec3_Length(mkVec3_Sub(mkWork_Point3(w, k), mkWork_Point3(w, i0)));
		if (d > best) { best = d; i1 = k; }
	}
	if (i1 < 0) return 0;
	best = 0.0;
	mkVec3 e01 = mkVec3_Sub(mkWork_Point3(w, i1), mkWork_Point3(w, i0));
	for (int k = 0; k < n; ++k) {
		double d = mkVec3_Length(mkVec3_Cross(e01, mkVec3_Sub(mkWork_Point3(w, k), mkWork_Point3(w, i0))));
		if (d > best) { best = d; i2 = k; }
	}
	if (i2 < 0) return 0;
	mkVec3 nrm = mkVec3_Cross(e01, mkVec3_Sub(mkWork_Point3(w, i2), mkWork_Point3(w, i0)));
	best = 0.0;
	for (int k = 0; k < n; ++k) {
		double d = fabs(mkVec3_Dot(nrm, mkVec3_Sub(mkWork_Point3(w, k), mkWork_Point3(w, i0))));
		if (d > best) { best = d; i3 = k; }
	}
	if (i3 < 0 || best <= eps * mkVec3_Length(nrm)) return 0;
	v[0] = i0; v[1] = i1; v[2] = i2; v[3] = i3;
	return 1;
}

/* A face that sees p (height above eps), or -1: first by walking from face
 * `last` to neighbours that see p better, else by looking at every face. */
static int mkHull3_Visible(const mkHull3 *h, mkVec3 p, int last)
{
	const int *F = h->F;
	int cur = last;
	double dcur = mkHull3_Height(h, cur, p);
	for (int steps = 0; steps < h->nf && dcur <= h->eps; ++steps) {
		int next = -1;
		double dn = dcur;
		for (int e = 0; e < 3; ++e) {
			int g = mkEdgeHash_Find(&h->w->dedges, mkEdgeHash_Directed(F[3 * cur + (e + 1) % 3], F[3 * cur + e]));
			if (g < 0 || h->alive[g] != 1) continue;
			double d = mkHull3_Height(h, g, p);
			if (d > dn) { dn = d; next = g; }
		}
		if (next < 0) break;
		cur = next;
		dcur = dn;
	}
	if (dcur > h->eps) return cur;
	int f0 = -1;
	double dmax = h->eps;
	for (int f = 0; f < h->nf; ++f) {
		if (h->alive[f] != 1) continue;
		double d = mkHull3_Height(h, f, p);
		if (d > dmax) { dmax = d; f0 = f; }
	}
	return f0;
}

/* Point k, seen by face f0, joins the hull: the connected set of faces that
 * see it goes, and its horizon edges are joined to k. 0 on memory. */
static int mkHull3_Insert(mkHull3 *h, int k, int f0)
{
	mkCSpaceWork *w = h->w;
	const int *F = h->F;
	mkVec3 p = mkWork_Point3(w, k);
	int nvis = 0, ns = 0;
	if (!mkGrow_Ints(&h->stack, &h->scap, 1)) return 0;
	h->stack[ns++] = f0;
	h->alive[f0] = 2;
	while (ns) {
		int f = h->stack[--ns];
		if (!mkGrow_Ints(&h->vis, &h->vcap, nvis + 1)) return 0;
		h->vis[nvis++] = f;
		for (int e = 0; e < 3; ++e) {
			int g = mkEdgeHash_Find(&w->dedges, mkEdgeHash_Directed(F[3 * f + (e + 1) % 3], F[3 * f + e]));
			if (g < 0 || h->alive[g] != 1) continue;
			if (mkHull3_Height(h, g, p) > h->eps) {
				h->alive[g] = 2;
				if (!mkGrow_Ints(&h->stack, &h->scap, ns + 1)) return 0;
				h->stack[ns++] = g;
			}
		}
	}
	/* horizon: edges of visible faces whose other side stays */
	int nh = 0;
	for (int v = 0; v < nvis; ++v) {
		int f = h->vis[v];
		for (int e = 0; e < 3; ++e) {
			int a = F[3 * f + e], b = F[3 * f + (e + 1) % 3];
			int g = mkEdgeHash_Find(&w->dedges, mkEdgeHash_Directed(b, a));
			if (g >= 0 && h->alive[g] == 1) {
				if (!mkGrow_Ints(&h->hor, &h->hcap, 2 * (nh + 1))) return 0;
				h->hor[2 * nh] = a; h->hor[2 * nh + 1] = b;
				++nh;
			}
		}
	}
	for (int v = 0; v < nvis; ++v) {
		int f = h->vis[v];
		h->alive[f] = 0;
		for (int e = 0; e < 3; ++e)
			mkEdgeHash_Remove(&w->dedges, mkEdgeHash_Directed(F[3 * f + e], F[3 * f + (e + 1) % 3]));
	}
	for (int j = 0; j < nh; ++j)
		if (!mkHull3_AddFace(h, h->hor[2 * j], h->hor[2 * j + 1], k)) return 0;
	return 1;
}

/* The hull's faces into *faces; their count or -1 on memory. */
static int mkHull3_Output(const mkHull3 *h, int **faces, int *fcap)
{
	int out = 0;
	for (int f = 0; f < h->nf; ++f) out += h->alive[f] == 1;
	if (!mkGrow_Ints(faces, fcap, 3 * out + 3)) return -1;
	out = 0;
	for (int f = 0; f < h->nf; ++f) {
		if (h->alive[f] != 1) continue;
		for (int d = 0; d < 3; ++d) (*faces)[3 * out + d] = h->F[3 * f + d];
		++out;
	}
	return out;
}

/* Triangles counter-clockwise from outside into *faces; returns their
 * count, or -1 on memory or a degenerate point set. A point within 1e-11 of
 * the points' size of a face's plane counts as on the hull's side of it and
 * is left out of the faces (it lies in the hull). */
int mkHull3_Build(mkCSpaceWork *w, int n, int **faces, int *fcap)
{
	if (n < 4) return -1;
	double scale = 0.0;
	for (int k = 0; k < n; ++k) scale = fmax(scale, mkVec3_Size1(mkWork_Point3(w, k)));
	mkHull3 h = {0};
	h.w = w;
	h.eps = 1e-11 * (scale > 0.0 ? scale : 1.0);
	int v[4];
	if (!mkHull3_Tetrahedron(w, n, h.eps, v)) return -1;
	h.cap = 64;
	h.F = malloc((size_t)h.cap * 3 * sizeof *h.F);
	h.P = malloc((size_t)h.cap * 4 * sizeof *h.P);
	h.alive = malloc((size_t)h.cap);
	int out = -1;
	if (!h.F || !h.P || !h.alive) goto done;
	mkEdgeHash_Clear(&w->dedges);
	h.inside = mkVec3_Scale(mkVec3_Add(mkVec3_Add(mkWork_Point3(w, v[0]), mkWork_Point3(w, v[1])),
		mkVec3_Add(mkWork_Point3(w, v[2]), mkWork_Point3(w, v[3]))), 0.25);
	if (!mkHull3_AddFace(&h, v[0], v[1], v[2]) || !mkHull3_AddFace(&h, v[0], v[1], v[3])
		|| !mkHull3_AddFace(&h, v[0], v[2], v[3]) || !mkHull3_AddFace(&h, v[1], v[2], v[3]))
		goto done;
	int last = 3;
	for (int k = 0; k < n; ++k) {
		if (k == v[0] || k == v[1] || k == v[2] || k == v[3]) continue;
		int f0 = mkHull3_Visible(&h, mkWork_Point3(w, k), last);
		if (f0 < 0) continue; /* inside or on the hull */
		if (!mkHull3_Insert(&h, k, f0)) goto done;
		last = h.nf - 1;
	}
	out = mkHull3_Output(&h, faces, fcap);
done:
	mkHull3_Free(&h);
	return out;
}
