/* error3.c - the error measure in 3D (mink/error.h): P as CGAL's hull in
 * canonical order, gap_in certified over the vertex cones, and
 * mkDeviation3_Measure, which puts them together with the volume and the
 * signed distances of error3_distance.c. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/error.h>

#include "error_internal.h"
#include "referee_cgal.h"

/* ---- gap_in in 3D ---------------------------------------------------------------------
 * The normal cone of vertex v of P is spanned by the unit normals of its
 * facets; h_K - h_P = h_{K-v} there. For a spherical triangle of that cone
 * with corners A, B, C, a unit direction in it is w / |w| with w in the flat
 * triangle ABC and |w| >= <w, c> >= min(<A,c>, <B,c>, <C,c>) =: mu for the
 * unit c along A + B + C; by convexity h_{K-v}(w) <= max of the corner values,
 * so the triangle's maximum is at most max(corners, 0) / mu. The whole cone
 * (corners in any order) has the same bound with c along the sum of its
 * facet normals. Cones whose bound is above the level are fanned from c into
 * triangles and subdivided four ways. */
typedef struct mkDevTri3 { double a[3], b[3], c[3], fa, fb, fc; int depth; } mkDevTri3;

static double tri_bound(const mkDevTri3 *t)
{
	double c[3] = {t->a[0] + t->b[0] + t->c[0], t->a[1] + t->b[1] + t->c[1], t->a[2] + t->b[2] + t->c[2]};
	if (!mkDev_Unit3(c)) return HUGE_VAL;
	double mu = fmin(mkDev_Dot3(t->a, c), fmin(mkDev_Dot3(t->b, c), mkDev_Dot3(t->c, c)));
	if (!(mu > 0)) return HUGE_VAL;
	return fmax(fmax(t->fa, t->fb), fmax(t->fc, 0.0)) / mu;
}

static double phi3(const mkDevProb3 *P, const double *n, const double *v)
{
	double x[3];
	return mkDev_Hk3(P, n, x) - mkDev_Dot3(n, v);
}

/* Refine the cone of vertex v (facet normals nf[0..k-1], in any order):
 * returns the largest bound left, raises *best with the values found. */
static double refine_cone(const mkDevProb3 *P, const double *v, const double *nrm, const double *H, const int *fs, int k,
	double gap_out, double tol, double *best, long *evals, mkDevTri3 *stack, int scap)
{
	double c[3] = {0, 0, 0};
	for (int i = 0; i < k; ++i)
		for (int j = 0; j < 3; ++j) c[j] += nrm[3 * fs[i] + j];
	if (!mkDev_Unit3(c)) return HUGE_VAL;
	/* Order the facet normals by angle around c. */
	double e1[3], e2[3];
	mkDev_Frame3(c, e1, e2);
	int order_s[64], *order = k <= 64 ? order_s : malloc((size_t)k * sizeof *order);
	double ang_s[64], *ang = k <= 64 ? ang_s : malloc((size_t)k * sizeof *ang);
	if (!order || !ang) {
		if (order != order_s) free(order);
		if (ang != ang_s) free(ang);
		return HUGE_VAL;
	}
	for (int i = 0; i < k; ++i) {
		const double *f = nrm + 3 * fs[i];
		ang[i] = atan2(mkDev_Dot3(f, e2), mkDev_Dot3(f, e1));
		order[i] = i;
	}
	for (int i = 1; i < k; ++i) /* insertion sort: k is small */
		for (int j = i; j > 0 && ang[order[j]] < ang[order[j - 1]]; --j) {
			int t = order[j];
			order[j] = order[j - 1];
			order[j - 1] = t;
		}
	double fc = phi3(P, c, v);
	++*evals;
	*best = fmax(*best, fc);
	double top = -HUGE_VAL;
	for (int i = 0; i < k; ++i) {
		int fa = fs[order[i]], fb = fs[order[(i + 1) % k]];
		int sp = 0;
		mkDevTri3 t;
		memcpy(t.a, c, sizeof t.a);
		memcpy(t.b, nrm + 3 * fa, sizeof t.b);
		memcpy(t.c, nrm + 3 * fb, sizeof t.c);
		t.fa = fc;
		t.fb = H[fa] - mkDev_Dot3(nrm + 3 * fa, v);
		t.fc = H[fb] - mkDev_Dot3(nrm + 3 * fb, v);
		t.depth = 0;
		stack[sp++] = t;
		while (sp > 0) {
			mkDevTri3 q = stack[--sp];
			double level = fmax(*best, gap_out);
			double ub = tri_bound(&q), need = level + tol * fabs(level) + P->round;
			if (ub <= need || *evals >= EVAL_BUDGET || q.depth >= 40 || sp + 4 > scap) {
				top = fmax(top, ub);
				continue;
			}
			double ab[3], bc[3], ca[3];
			for (int j = 0; j < 3; ++j) {
				ab[j] = q.a[j] + q.b[j];
				bc[j] = q.b[j] + q.c[j];
				ca[j] = q.c[j] + q.a[j];
			}
			mkDev_Unit3(ab);
			mkDev_Unit3(bc);
			mkDev_Unit3(ca);
			double fab = phi3(P, ab, v), fbc = phi3(P, bc, v), fca = phi3(P, ca, v);
			*evals += 3;
			*best = fmax(*best, fmax(fab, fmax(fbc, fca)));
			mkDevTri3 s[4];
			memcpy(s[0].a, q.a, sizeof q.a), memcpy(s[0].b, ab, sizeof ab), memcpy(s[0].c, ca, sizeof ca);
			s[0].fa = q.fa, s[0].fb = fab, s[0].fc = fca;
			memcpy(s[1].a, ab, sizeof ab), memcpy(s[1].b, q.b, sizeof q.b), memcpy(s[1].c, bc, sizeof bc);
			s[1].fa = fab, s[1].fb = q.fb, s[1].fc = fbc;
			memcpy(s[2].a, ca, sizeof ca), memcpy(s[2].b, bc, sizeof bc), memcpy(s[2].c, q.c, sizeof q.c);
			s[2].fa = fca, s[2].fb = fbc, s[2].fc = q.fc;
			memcpy(s[3].a, ab, sizeof ab), memcpy(s[3].b, bc, sizeof bc), memcpy(s[3].c, ca, sizeof ca);
			s[3].fa = fab, s[3].fb = fbc, s[3].fc = fca;
			for (int j = 0; j < 4; ++j) {
				s[j].depth = q.depth + 1;
				stack[sp++] = s[j];
			}
		}
	}
	if (order != order_s) free(order);
	if (ang != ang_s) free(ang);
	return top;
}

/* Points with their index, in lexicographic order (for matching the input
 * points to hull vertices; no global state, so the measure is reentrant). */
typedef struct Keyed { double c[3]; int i; } Keyed;

static int cmp_coords(const double *p, const double *q)
{
	for (int i = 0; i < 3; ++i)
		if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
	return 0;
}

static int cmp_keyed(const void *a, const void *b)
{
	return cmp_coords(((const Keyed *)a)->c, ((const Keyed *)b)->c);
}

static Keyed *sorted_points(const double *xyz, int n)
{
	Keyed *k = malloc((size_t)(n > 0 ? n : 1) * sizeof *k);
	if (!k) return NULL;
	for (int i = 0; i < n; ++i) {
		memcpy(k[i].c, xyz + 3 * i, sizeof k[i].c);
		k[i].i = i;
	}
	qsort(k, (size_t)n, sizeof *k, cmp_keyed);
	return k;
}

static int cmp_tri(const void *a, const void *b)
{
	const int *p = a, *q = b;
	for (int i = 0; i < 3; ++i)
		if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
	return 0;
}

/* Put the hull in an order that depends only on the point set. The hull
 * comes canonical already (mkCgalHull3_Mesh: sorted vertices, each planar
 * face fanned from its smallest corner, sorted triangles); this sorts it
 * once more, so that the measure does not rest on that alone, and drops
 * the vertices CGAL kept on an edge or inside a planar face: they belong to
 * no triangle, so their normal cones would be empty, and whether CGAL keeps
 * such a point can follow its build order. *nv is updated. */
static mkResult canonical_hull(double *V, int *nv, int *T, int nt)
{
	int n = *nv;
	Keyed *hs = sorted_points(V, n);
	int *to = malloc((size_t)(n > 0 ? n : 1) * sizeof *to);
	if (!hs || !to) {
		free(hs);
		free(to);
		return MK_ERR_MEMORY;
	}
	for (int v = 0; v < n; ++v) to[hs[v].i] = -1;
	for (int j = 0; j < 3 * nt; ++j) to[T[j]] = 0; /* used */
	int m = 0;
	for (int v = 0; v < n; ++v) /* in coordinate order */
		if (to[hs[v].i] == 0) {
			to[hs[v].i] = m;
			memcpy(V + 3 * m++, hs[v].c, sizeof hs[v].c);
		}
	for (int f = 0; f < nt; ++f) {
		int *t = T + 3 * f, a = to[t[0]], b = to[t[1]], c = to[t[2]];
		if (a < b && a < c) t[0] = a, t[1] = b, t[2] = c;
		else if (b < c) t[0] = b, t[1] = c, t[2] = a;
		else t[0] = c, t[1] = a, t[2] = b;
	}
	qsort(T, (size_t)nt, 3 * sizeof *T, cmp_tri);
	*nv = m;
	free(hs);
	free(to);
	return MK_OK;
}

#define TABLE3 2048

/* The working state of one 3D measure: the finite points (relative to o,
 * in coordinate order, with their indices in the input), P's hull, its
 * facets' unit normals and h_K there, the facets of each vertex, the
 * hull vertex of each point (-1 if none) and a table of directions. */
typedef struct mkDevWork3 {
	double *xyz;
	int *idx, nf;
	double *V;
	int *T, nv, nt, flat;
	double *nrm, *H;
	int *vstart, *vfac, *vi, *pv;
	double *tab;
	mkDevTri3 *stack;
} mkDevWork3;

static void mkDevWork3_Free(mkDevWork3 *w)
{
	void *all[] = { w->xyz, w->idx, w->V, w->T, w->nrm, w->H, w->tab, w->vstart, w->vfac, w->vi, w->pv, w->stack };
	for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
		free(all[i]);
}

/* The finite points relative to o, counted out->nonfinite otherwise, then
 * in coordinate order: the hull (and with it every figure, to the last
 * bit) is then a function of the point set, not of the order the method
 * returned it in. */
static mkResult mkDevWork3_Points(mkDevWork3 *w, const mkDevProb3 *P, const mkPointSet *pts, mkDeviation *out)
{
	int n = pts->count;
	size_t n1 = (size_t)(n > 0 ? n : 1);
	w->xyz = malloc(3 * n1 * sizeof *w->xyz);
	w->idx = malloc(n1 * sizeof *w->idx);
	if (!w->xyz || !w->idx) return MK_ERR_MEMORY;
	for (int k = 0; k < n; ++k) {
		double p[3] = {pts->x[k] - P->o[0], pts->y[k] - P->o[1], pts->z[k] - P->o[2]};
		if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) {
			++out->nonfinite;
			continue;
		}
		memcpy(w->xyz + 3 * w->nf, p, sizeof p);
		w->idx[w->nf++] = k;
	}
	if (w->nf <= 1) return MK_OK;
	mkResult r = MK_OK;
	Keyed *ks = sorted_points(w->xyz, w->nf);
	int *was = malloc(n1 * sizeof *was);
	if (!ks || !was) r = MK_ERR_MEMORY;
	else {
		memcpy(was, w->idx, (size_t)w->nf * sizeof *w->idx);
		for (int k = 0; k < w->nf; ++k) {
			memcpy(w->xyz + 3 * k, ks[k].c, sizeof ks[k].c);
			w->idx[k] = was[ks[k].i];
		}
	}
	free(ks);
	free(was);
	return r;
}

/* P's hull in canonical order (w->flat when the points span no volume),
 * and a table of directions (Fibonacci sphere): starts for points that are
 * not hull vertices, and gap_in when the points span no volume. */
static mkResult mkDevWork3_Hull(mkDevWork3 *w, const mkDevProb3 *P)
{
	mkResult r = MK_OK;
	int hc = mkCgalHull3_Mesh(w->xyz, w->nf, &w->V, &w->nv, &w->T, &w->nt);
	if (hc == -1) r = MK_ERR_MEMORY;
	else if (hc == -2) w->flat = 1;
	else if (hc != 0) r = MK_ERR_UNSUPPORTED;
	if (r == MK_OK && !w->flat) r = canonical_hull(w->V, &w->nv, w->T, w->nt);
	if (r != MK_OK) return r;
	w->tab = malloc(7 * (size_t)TABLE3 * sizeof *w->tab);
	w->pv = malloc((size_t)(w->nf > 0 ? w->nf : 1) * sizeof *w->pv);
	if (!w->tab || !w->pv) return MK_ERR_MEMORY;
	for (int j = 0; j < TABLE3; ++j) {
		double *d = w->tab + 7 * j, z = 1.0 - (2.0 * j + 1.0) / TABLE3, rho = sqrt(1.0 - z * z);
		double a = MK_PI * (3.0 - sqrt(5.0)) * j;
		d[0] = rho * cos(a), d[1] = rho * sin(a), d[2] = z;
		d[6] = mkDev_Hk3(P, d, d + 3);
	}
	return MK_OK;
}

/* Facets: unit outward normals and h_K there, |P| (out->area_p), the
 * largest h_K - h_P over the facet normals (out->gap_in), vertex ->
 * facets, and each point's hull vertex. */
static mkResult mkDevWork3_Facets(mkDevWork3 *w, const mkDevProb3 *P, mkDeviation *out)
{
	int nv = w->nv, nt = w->nt, nf = w->nf;
	const double *V = w->V;
	const int *T = w->T;
	w->nrm = malloc(3 * (size_t)nt * sizeof *w->nrm);
	w->H = malloc((size_t)nt * sizeof *w->H);
	w->vstart = calloc((size_t)nv + 1, sizeof *w->vstart);
	w->vfac = malloc(3 * (size_t)nt * sizeof *w->vfac);
	w->vi = malloc((size_t)nv * sizeof *w->vi);
	if (!w->nrm || !w->H || !w->vstart || !w->vfac || !w->vi) return MK_ERR_MEMORY;
	double best = -HUGE_VAL;
	mkDevSum vol = {0, 0};
	for (int f = 0; f < nt; ++f) {
		const double *a = V + 3 * T[3 * f], *b = V + 3 * T[3 * f + 1], *c = V + 3 * T[3 * f + 2];
		double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
		double *nn = w->nrm + 3 * f, bc[3];
		mkDev_Cross3(ab, ac, nn);
		mkDev_Unit3(nn);
		mkDev_Cross3(b, c, bc);
		mkDevSum_Add(&vol, mkDev_Dot3(a, bc) / 6.0);
		double x[3];
		w->H[f] = mkDev_Hk3(P, nn, x);
		double hp = fmax(mkDev_Dot3(nn, a), fmax(mkDev_Dot3(nn, b), mkDev_Dot3(nn, c)));
		best = fmax(best, w->H[f] - hp);
		for (int j = 0; j < 3; ++j) ++w->vstart[T[3 * f + j] + 1];
	}
	out->area_p = mkDevSum_Get(&vol);
	for (int v = 0; v < nv; ++v) w->vstart[v + 1] += w->vstart[v];
	for (int v = 0; v < nv; ++v) w->vi[v] = w->vstart[v];
	for (int f = 0; f < nt; ++f)
		for (int j = 0; j < 3; ++j) w->vfac[w->vi[T[3 * f + j]]++] = f;
	out->gap_in = best;
	out->vertices = nv;
	/* Match the points to hull vertices (CGAL keeps input coordinates):
	 * both lists are in coordinate order already (mkDevWork3_Points and
	 * canonical_hull), so one merge pass does it. */
	for (int k = 0; k < nf; ++k) w->pv[k] = -1;
	for (int i = 0, j = 0; i < nf && j < nv;) {
		int c = cmp_coords(w->xyz + 3 * i, V + 3 * j);
		if (c == 0) w->pv[i++] = j;
		else if (c < 0) ++i;
		else ++j;
	}
	return MK_OK;
}

/* Signed distances of every point: gap_out, off_boundary and its bound.
 * A hull vertex starts from the mean of its facets' normals, any other
 * point from the table direction that puts it farthest out. */
static void mkDevWork3_Distances(const mkDevWork3 *w, const mkDevProb3 *P, mkDeviation *out)
{
	double left = 0;
	for (int k = 0; k < w->nf; ++k) {
		const double *p = w->xyz + 3 * k;
		double start[3] = {0, 0, 0};
		int v = w->pv[k];
		if (v >= 0) {
			for (int i = w->vstart[v]; i < w->vstart[v + 1]; ++i)
				for (int j = 0; j < 3; ++j) start[j] += w->nrm[3 * w->vfac[i] + j];
		}
		if (v < 0 || !mkDev_Unit3(start)) {
			int bj = 0;
			double bf = -HUGE_VAL;
			for (int j = 0; j < TABLE3; ++j) {
				const double *d = w->tab + 7 * j;
				double f = mkDev_Dot3(d, p) - d[6];
				if (f > bf) bf = f, bj = j;
			}
			memcpy(start, w->tab + 7 * bj, sizeof start);
		}
		double sd, lf;
		mkDev_SignedDistance3(P, start, p, &sd, &lf);
		out->gap_out = fmax(out->gap_out, sd);
		if (fabs(sd) > out->off_boundary_max || out->worst < 0) {
			out->off_boundary_max = fabs(sd);
			out->worst = w->idx[k];
		}
		left = fmax(left, lf);
	}
	out->off_boundary_bound = left + P->round;
}

/* gap_in certified over every vertex cone (out->gap_in raised); *hi gets
 * the largest bound left. */
static mkResult mkDevWork3_GapIn(mkDevWork3 *w, const mkDevProb3 *P, double tol, mkDeviation *out, double *hi)
{
	int scap = 4 * 40 + 64;
	w->stack = malloc((size_t)scap * sizeof *w->stack);
	if (!w->stack) return MK_ERR_MEMORY;
	long evals = 0;
	double best = out->gap_in, top = best;
	for (int v = 0; v < w->nv; ++v) {
		const double *pt = w->V + 3 * v;
		int k = w->vstart[v + 1] - w->vstart[v];
		const int *fs = w->vfac + w->vstart[v];
		double c[3] = {0, 0, 0}, fmaxv = -HUGE_VAL;
		for (int i = 0; i < k; ++i) {
			for (int j = 0; j < 3; ++j) c[j] += w->nrm[3 * fs[i] + j];
			fmaxv = fmax(fmaxv, w->H[fs[i]] - mkDev_Dot3(w->nrm + 3 * fs[i], pt));
		}
		double ub = HUGE_VAL;
		if (mkDev_Unit3(c)) {
			double mu = HUGE_VAL;
			for (int i = 0; i < k; ++i) mu = fmin(mu, mkDev_Dot3(w->nrm + 3 * fs[i], c));
			if (mu > 0) ub = fmax(fmaxv, 0.0) / mu;
		}
		double level = fmax(best, out->gap_out);
		if (ub > level + tol * fabs(level) + P->round)
			ub = refine_cone(P, pt, w->nrm, w->H, fs, k, out->gap_out, tol, &best, &evals, w->stack, scap);
		top = fmax(top, ub);
	}
	out->gap_in = best;
	*hi = fmax(top, best);
	return MK_OK;
}

/* No volume: gap_in over the table directions only, h_P by brute force; no
 * certificate (*hi = +inf). */
static void mkDevWork3_GapInFlat(const mkDevWork3 *w, mkDeviation *out, double *hi)
{
	double best = -HUGE_VAL;
	for (int j = 0; j < TABLE3; ++j) {
		const double *d = w->tab + 7 * j;
		double hp = -HUGE_VAL;
		for (int k = 0; k < w->nf; ++k) hp = fmax(hp, mkDev_Dot3(d, w->xyz + 3 * k));
		best = fmax(best, d[6] - hp);
	}
	out->gap_in = best;
	out->vertices = 0;
	out->area_p = 0;
	*hi = HUGE_VAL;
}

mkResult mkDeviation3_Measure(mkBody3 b1, mkBody3 b2, mkSet set, const mkPointSet *pts, const mkDeviationOptions *opt,
	mkDeviation *out)
{
	mkDevProb3 P;
	if (!pts || !out || pts->dim != 3 || pts->count < 0 || (pts->count > 0 && (!pts->x || !pts->y || !pts->z)))
		return MK_ERR_ARGUMENT;
	if (!mkDev_Prob3Init(&P, b1, b2, set)) return MK_ERR_ARGUMENT;
	double tol = opt && opt->tol > 0 ? opt->tol : TOL_DEFAULT;
	mkDev_Init(out, pts->count, P.S);
	mkDevWork3 w;
	memset(&w, 0, sizeof w);
	mkResult r = mkDevWork3_Points(&w, &P, pts, out);
	if (r == MK_OK && !mkDev_TakeTruth(opt, out))
		r = mkDev_Volume3(&P, &out->area_k, &out->area_bound);
	if (r == MK_OK && w.nf == 0) {
		mkDev_NoPoints(out, "volume");
		mkDevWork3_Free(&w);
		return r;
	}
	if (r == MK_OK) r = mkDevWork3_Hull(&w, &P);
	if (r == MK_OK && !w.flat) r = mkDevWork3_Facets(&w, &P, out);
	else if (r == MK_OK)
		for (int k = 0; k < w.nf; ++k) w.pv[k] = -1;
	double hi = 0;
	if (r == MK_OK) {
		mkDevWork3_Distances(&w, &P, out);
		if (w.flat) mkDevWork3_GapInFlat(&w, out, &hi);
		else r = mkDevWork3_GapIn(&w, &P, tol, out, &hi);
	}
	if (r == MK_OK) {
		out->hausdorff_abs = fmax(out->gap_in, out->gap_out);
		out->hausdorff_bound = fmax(hi, out->gap_out + out->off_boundary_bound) - out->hausdorff_abs + P.round;
		out->area_rel = (out->area_p - out->area_k) / out->area_k;
		out->area_bound = (out->area_bound + 16.0 * UNIT_ROUND * out->area_p) / out->area_k
			+ 4.0 * UNIT_ROUND * fabs(out->area_rel);
		mkDev_Finish(out, "volume");
	}
	mkDevWork3_Free(&w);
	return r;
}
