/* cobstacle.c - certified inner/outer boundaries of C-obstacles from the
 * closed-form support points, adaptive or uniform, on POSIX threads. The
 * certificates are proved in docs/scene.md; each step below names the one
 * it implements. */
#define _POSIX_C_SOURCE 200809L
#include "mink/cobstacle.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/message.h"
#include <time.h>

#include "base/geom_inline.h"
#include "kernels/kernel.h"

#define ROUND_REL 1e-13   /* rounding allowance per unit of coordinate size */
#define MIN_ANGLE 1e-12   /* normals closer than this (radians) are not split */
#define MAX_SPLITS 10     /* uniform 3D: 8 * 4^10 triangles */

mkCSpaceOptions mkCSpaceOptions_Default(void)
{
	mkCSpaceOptions o;
	memset(&o, 0, sizeof o);
	o.tol = 1e-3;
	o.mode = MK_CSPACE_ADAPTIVE;
	o.uniform = 0;
	o.threads = 1;
	o.store = 1;
	o.max_points = 1000000;
	o.form = MK_FORM_GRADIENT;
	o.impl = MK_IMPL_AUTO;
	return o;
}

/* ---- growable arrays -------------------------------------------------------------- */

static int grow_d(double **p, int *cap, int need)
{
	if (need <= *cap) return 1;
	int nc = *cap > 0 ? *cap : 64;
	while (nc < need) nc *= 2;
	double *q = realloc(*p, (size_t)nc * sizeof **p);
	if (!q) return 0;
	*p = q;
	*cap = nc;
	return 1;
}

static int grow_i(int **p, int *cap, int need)
{
	if (need <= *cap) return 1;
	int nc = *cap > 0 ? *cap : 64;
	while (nc < need) nc *= 2;
	int *q = realloc(*p, (size_t)nc * sizeof **p);
	if (!q) return 0;
	*p = q;
	*cap = nc;
	return 1;
}

/* Open-addressing hash from 64-bit keys to non-negative ints. */
typedef struct Hash { uint64_t *key; int *val; int cap, count; } Hash;

/* The scratch space of one thread, reused from boundary to boundary. */
typedef struct Work {
	/* vertices: normal n and point p */
	double *n[3], *p[3];
	int vcap[6];
	int *next, ncap;           /* 2D walks: a node's counter-clockwise successor */
	double *m[3], *q[3];       /* batch normals and their points */
	int mcap[6];
	int *tri, tcap, *tri2, t2cap, *leaf, lcap; /* 3D triangles, 3 ints each */
	Hash edges;                /* 3D: undirected edge -> midpoint vertex */
	Hash dedges;               /* 3D: directed edge a -> b -> its triangle */
	int *poly, pcap;
	double *o[3]; int ocap[3]; /* 3D outer vertices */
	int *fin, fcap;            /* 3D final (conforming) triangles */
	double *pb; int pbcap;     /* paper mode: B1's half, the poses' directions, their points */
	double *err2; int ecap;    /* 2D: the error of the arc from node i to the next */
	double *cp; int cpcap;     /* 2D adaptive: the chosen walk's vertices */
} Work;

static void work_free(Work *w)
{
	for (int i = 0; i < 3; ++i) { free(w->n[i]); free(w->p[i]); free(w->m[i]); free(w->q[i]); }
	free(w->next); free(w->tri); free(w->tri2); free(w->leaf);
	free(w->edges.key); free(w->edges.val); free(w->dedges.key); free(w->dedges.val); free(w->poly);
	for (int i = 0; i < 3; ++i) free(w->o[i]);
	free(w->fin); free(w->pb); free(w->err2); free(w->cp);
	memset(w, 0, sizeof *w);
}

static int work_verts(Work *w, int need, int dim)
{
	for (int i = 0; i < dim; ++i)
		if (!grow_d(&w->n[i], &w->vcap[i], need) || !grow_d(&w->p[i], &w->vcap[3 + i], need)) return 0;
	return 1;
}

static int work_batch(Work *w, int need, int dim)
{
	for (int i = 0; i < dim; ++i)
		if (!grow_d(&w->m[i], &w->mcap[i], need) || !grow_d(&w->q[i], &w->mcap[3 + i], need)) return 0;
	return 1;
}

/* cos and sin, exact on the axes (as mkSample2_Angles). */
static void sincos_exact(double t, double *c, double *s)
{
	*c = cos(t);
	*s = sin(t);
	if (fabs(*c) < 1e-15) { *c = 0.0; *s = *s > 0 ? 1.0 : -1.0; }
	if (fabs(*s) < 1e-15) { *s = 0.0; *c = *c > 0 ? 1.0 : -1.0; }
}

static mkResult eval2(mkBody2 b1, mkBody2 b2, mkImpl impl, const double *ux, const double *uy, int n,
	double *x, double *y)
{
	mkSumOptions o = {MK_SET_CONTACT, MK_FORM_NORMAL, MK_PARAM_NORMAL, impl, MK_PRECISION_DOUBLE};
	return mkSum2_Batch(b1, b2, &o, ux, uy, n, x, y, NULL, NULL);
}

static mkResult eval3(mkBody3 b1, mkBody3 b2, mkImpl impl, const double *ux, const double *uy, const double *uz,
	int n, double *x, double *y, double *z)
{
	mkSumOptions o = {MK_SET_CONTACT, MK_FORM_NORMAL, MK_PARAM_NORMAL, impl, MK_PRECISION_DOUBLE};
	return mkSum3_Batch(b1, b2, &o, ux, uy, uz, n, x, y, z, NULL, NULL, NULL);
}

/* ---- 2D ------------------------------------------------------------------------------ */

static double dist_seg2(mkVec2 v, mkVec2 a, mkVec2 b)
{
	mkVec2 d = mkVec2_Sub(b, a), e = mkVec2_Sub(v, a);
	double dd = mkVec2_Dot(d, d), t = dd > 0.0 ? mkVec2_Dot(e, d) / dd : 0.0;
	if (t < 0.0) t = 0.0;
	if (t > 1.0) t = 1.0;
	return mkVec2_LengthInline(mkVec2_Sub(e, mkVec2_Scale(d, t)));
}

/* The vertex of the tangent lines at (ni, pi) and (nj, pj): pi + s tau_i with
 * tau_i = ni turned by +90 degrees (Proof 2 of docs/scene.md). */
static mkVec2 tangent_vertex(mkVec2 ni, mkVec2 pi, mkVec2 nj, mkVec2 pj)
{
	mkVec2 tau = {-ni.y, ni.x};
	double s = mkVec2_Dot(nj, mkVec2_Sub(pj, pi)) / mkVec2_Cross(ni, nj);
	return mkVec2_Add(pi, mkVec2_Scale(tau, s));
}

static double size2(mkVec2 a) { return fabs(a.x) + fabs(a.y); }

/* The normal at which the chord p_i p_j is split: the chord's outward
 * normal when it lies between the two normals (always, in exact
 * arithmetic), else the bisector. */
static mkVec2 split_normal2(mkVec2 ni, mkVec2 nj, mkVec2 pi, mkVec2 pj)
{
	mkVec2 d = mkVec2_Sub(pj, pi);
	mkVec2 m = mkVec2_NormalizeInline(mkVec2_Make(d.y, -d.x));
	if (!(mkVec2_Cross(ni, m) > 0.0 && mkVec2_Cross(m, nj) > 0.0))
		m = mkVec2_NormalizeInline(mkVec2_Add(ni, nj));
	return m;
}

/* The certified error of the arc between consecutive normals ni, nj (points
 * pi, pj), given the split normal m and its point xm = x(m). */
static double edge_err2(mkBound bound, mkVec2 ni, mkVec2 nj, mkVec2 pi, mkVec2 pj, mkVec2 m, mkVec2 xm)
{
	double rnd = ROUND_REL * (size2(pi) + size2(pj) + size2(xm));
	/* Proof 3: for normals u between ni and nj, h_K(u) minus the
	 * best of <u, pi>, <u, pj> is at most g3 = c / (4 cos(theta/2)) */
	double c = mkVec2_Dot(mkVec2_Sub(ni, nj), mkVec2_Sub(pi, pj));
	c = c > 0.0 ? c : 0.0;
	if (!(mkVec2_Cross(ni, nj) > 0.0)) return INFINITY + rnd; /* 180 degrees or more (or clockwise): nothing certified */
	double other = INFINITY; /* Proof 1 or 2, where it applies */
	if (!(mkVec2_Dot(ni, nj) >= 0.0)) {
		/* a step over 90 degrees: Proof 3 only */
	} else if (bound == MK_BOUND_INNER) {
		/* Proof 1: the chord gap h_K(m) - <m, p>, m the chord normal */
		mkVec2 d = mkVec2_Sub(pj, pi);
		mkVec2 chord = mkVec2_NormalizeInline(mkVec2_Make(d.y, -d.x));
		if (mkVec2_Dot(chord, m) == 1.0 || (chord.x == m.x && chord.y == m.y)) {
			double lo = fmin(mkVec2_Dot(m, pi), mkVec2_Dot(m, pj));
			other = mkVec2_Dot(m, xm) - lo;
			if (other < 0.0) other = 0.0;
		}
	} else {
		/* Proof 2: the tangent vertex's distance to conv{pi, x(m), pj} */
		mkVec2 v = tangent_vertex(ni, pi, nj, pj);
		other = fmin(dist_seg2(v, pi, xm), dist_seg2(v, xm, pj));
	}
	/* the smaller of the two; g3 >= c / (4 (1 + 1e-9)) for unit normals, so
	 * g3 is only formed when the other bound might exceed it */
	if (other * (4.0 * (1.0 + 1e-9)) < c) return other + rnd;
	double g3 = c / (4.0 * (0.5 * mkVec2_LengthInline(mkVec2_Add(ni, nj))));
	return (other < g3 ? other : g3) + rnd;
}

static mkVec2 wn2(const Work *w, int i) { return mkVec2_Make(w->n[0][i], w->n[1][i]); }
static mkVec2 wp2(const Work *w, int i) { return mkVec2_Make(w->p[0][i], w->p[1][i]); }

/* ---- 2D adaptive: the farthest-reach walk ---------------------------------------------- */

#define WALK_STARTS 2        /* walks from different start normals, in lockstep; the fewest vertices win */
#define WALK_K 8             /* candidate steps per walk and round (at most) */
#define WALK_KI 4            /* the same around an estimated reach */
#define WALK_REL 2e-2        /* the reach is bracketed to this relative width */
#define WALK_MAX (0.75 * MK_PI) /* the largest normal step (the proofs need less than 180 degrees) */
#define WALK_LAST 3          /* vertices kept for closing the cycle when max_points is reached */
#define WALK_FORCED (MK_PI / 64.0) /* the least step taken uncertified (no finite error down to MIN_ANGLE) */
#define WALK_RETRIES 8       /* walks restarted with a looser target when max_points would be exceeded */

/* the first round's ladder: the previous step times 2^((k - 3) / 2) */
static const double walk_ladder_ratio[WALK_K] = {
	0.35355339059327373, 0.5, 0.70710678118654757, 1.0, 1.4142135623730951, 2.0, 2.8284271247461903, 4.0};

/* One walk around the circle of normals: its start, where it is, and the
 * search for its next step: tol its target, lo the largest step certified
 * within it (its error, normal, point), hi the smallest uncertified step
 * above it, width the bracket's width before the last round, d[0 .. nc) the
 * next candidates. */
typedef struct Walk {
	double phi0, phi, guess, maxerr, tol;
	int first, cur, count, done, force; /* force: take the one candidate, certified or not */
	double lo, hi, lo_e, hi_e, width;
	mkVec2 lo_n, lo_p;
	int nc;
	double d[WALK_K];
} Walk;

/* The rest of the circle from the walk's vertex, and the largest step. */
static double walk_cap(const Walk *a, int max_points, double *rem)
{
	*rem = a->phi0 + 2.0 * MK_PI - a->phi;
	double cap = *rem < WALK_MAX ? *rem : WALK_MAX;
	if (a->count >= max_points - WALK_LAST && cap > 0.5 * MK_PI) cap = 0.5 * MK_PI;
	return cap;
}

/* The first round of a step towards target tol: a ladder around the
 * previous step, up to the cap. Past max_points - WALK_LAST vertices the
 * walk closes the cycle in at most WALK_LAST + 1 steps of at most 90
 * degrees, certified or not. */
static void walk_ladder(Walk *a, double tol, int max_points)
{
	double rem, cap = walk_cap(a, max_points, &rem);
	a->tol = tol;
	a->lo = 0.0; a->hi = INFINITY; a->lo_e = a->hi_e = INFINITY; a->width = INFINITY;
	a->nc = 0;
	a->force = a->count >= max_points - WALK_LAST;
	if (a->force) { a->d[a->nc++] = cap; return; }
	for (int k = 0; k < WALK_K; ++k) {
		double t = a->guess * walk_ladder_ratio[k];
		if (t >= cap) { a->d[a->nc++] = cap; break; }
		a->d[a->nc++] = t;
	}
}

/* After a round: 1 when the step lo is decided, else the next round's
 * candidates in d. */
static int walk_next(Walk *a, int max_points)
{
	double rem, cap = walk_cap(a, max_points, &rem);
	if (a->lo == cap) return 1;
	a->nc = 0;
	if (a->lo == 0.0) { /* nothing certified: steps down to MIN_ANGLE */
		if (a->hi <= MIN_ANGLE) {
			if (isfinite(a->hi_e)) {
				/* tol is below the rounding allowance here: the step
				 * starts over with twice the error of the least step
				 * as its target */
				walk_ladder(a, 2.0 * a->hi_e, max_points);
				return 0;
			}
			/* no finite error at all (NaN points): the previous step
			 * (at least WALK_FORCED), uncertified */
			double t = a->guess > WALK_FORCED ? a->guess : WALK_FORCED;
			a->d[a->nc++] = t < cap ? t : cap;
			a->force = 1;
			return 0;
		}
		for (int k = 0; k < WALK_K; ++k) {
			double t = a->hi * exp2(-2.0 * (k + 1));
			if (t <= MIN_ANGLE) { a->d[a->nc++] = MIN_ANGLE; break; }
			a->d[a->nc++] = t;
		}
		return 0;
	}
	if (a->hi == INFINITY) { /* everything certified: longer steps */
		for (int k = 0; k < WALK_K; ++k) {
			double t = a->lo * exp2(0.5 * (k + 1));
			if (t >= cap) { a->d[a->nc++] = cap; break; }
			a->d[a->nc++] = t;
		}
		return 0;
	}
	double width = a->hi - a->lo;
	if (width <= WALK_REL * a->lo) return 1;
	/* The error as a power of the step through the bracket's ends estimates
	 * the reach; when the bracket at least halved in the last round, the
	 * candidates sit 0.9 WALK_REL lo apart around the estimate, else they
	 * divide the bracket evenly. */
	double est = NAN, h = 0.9 * WALK_REL * a->lo;
	if (a->lo_e > 0.0 && a->hi_e > a->lo_e && isfinite(a->hi_e)) {
		double p = log(a->hi_e / a->lo_e) / log(a->hi / a->lo);
		est = a->lo * pow(a->tol / a->lo_e, 1.0 / p);
	}
	if (est > a->lo && est < a->hi && 2.0 * width <= a->width && WALK_KI * h < width) {
		double t0 = est - 0.5 * (WALK_KI - 1) * h;
		if (t0 <= a->lo) t0 = a->lo + h;
		if (t0 + (WALK_KI - 1) * h >= a->hi) t0 = a->hi - WALK_KI * h;
		for (int k = 0; k < WALK_KI; ++k) a->d[a->nc++] = t0 + k * h;
	} else {
		for (int k = 0; k < WALK_K; ++k) a->d[a->nc++] = a->lo + width * (k + 1) / (WALK_K + 1);
	}
	a->width = width;
	return 0;
}

/* Append a vertex to the node pool; -1 on memory. */
static int walk_node(Work *w, int *nv, mkVec2 n, mkVec2 p)
{
	if (!work_verts(w, *nv + 1, 2) || !grow_i(&w->next, &w->ncap, *nv + 1) || !grow_d(&w->err2, &w->ecap, *nv + 1))
		return -1;
	int k = (*nv)++;
	w->n[0][k] = n.x; w->n[1][k] = n.y;
	w->p[0][k] = p.x; w->p[1][k] = p.y;
	w->next[k] = k;
	w->err2[k] = NAN;
	return k;
}

/* Start a walk at normal angle phi with first guess `guess` towards target tol. */
static mkResult walk_start(Work *w, Walk *a, mkBody2 b1, mkBody2 b2, mkImpl impl, double phi, double guess,
	double tol, int max_points, int *nv)
{
	double nx, ny, px, py;
	sincos_exact(phi, &nx, &ny);
	mkResult r = eval2(b1, b2, impl, &nx, &ny, 1, &px, &py);
	if (r != MK_OK) return r;
	memset(a, 0, sizeof *a);
	a->first = a->cur = walk_node(w, nv, mkVec2_Make(nx, ny), mkVec2_Make(px, py));
	if (a->first < 0) return MK_ERR_MEMORY;
	a->phi0 = a->phi = phi;
	a->guess = guess;
	a->count = 1;
	walk_ladder(a, tol, max_points);
	return MK_OK;
}

/* The adaptive 2D boundary (docs/scene.md, "2D adaptive sampling"): greedy
 * walks around the circle of normals. From each vertex the next is placed
 * at (about) the largest normal step whose arc edge_err2 certifies within
 * tol (Proofs 1-3, exactly the check of a fixed sampling), found in rounds
 * of WALK_K candidate steps: a ladder around the previous step, then
 * candidates inside the bracket [largest certified, smallest uncertified)
 * until it is WALK_REL wide. Only a candidate whose own certificate is
 * within tol is taken, so the result never relies on the error growing
 * with the step, which the search assumes. The last arc ends at the walk's
 * first vertex. Walk 0 starts at normal angle 0; once its first step s is
 * known, walk j starts at s j / WALK_STARTS (a greedy walk ends with a
 * short arc; another start may save a vertex); the walks share each round's
 * two batch calls. The walk with the fewest vertices wins (the first to
 * finish among equals; a walk is dropped as soon as it cannot beat a
 * finished one), and its vertices move to nodes 0 .. count - 1.
 * Where tol cannot be met (the errors then exceed tol and are reported):
 * when no step down to MIN_ANGLE is certified, the step starts over with
 * twice the error at MIN_ANGLE as its target (tol below the rounding
 * allowance), or, if that error is not finite (NaN points), takes the
 * previous step (at least WALK_FORCED) uncertified; when a walk reaches
 * max_points - WALK_LAST vertices, all walks start over with a target
 * looser by (1.1 / the fraction of the circle covered)^2, at least 2, up to
 * WALK_RETRIES times, and after that close the cycle in steps of at most 90
 * degrees. Results as for fixed normals: nodes 0 .. count - 1 in
 * counter-clockwise order, w->err2[i] the error of the arc from node i to
 * node i + 1 (mod count). Deterministic: the same rounds whatever the
 * thread. */
static mkResult walk2(Work *w, mkBody2 b1, mkBody2 b2, mkImpl impl, mkBound bound, double tol, int max_points,
	int *count, double *error)
{
	enum { LANES = WALK_STARTS * WALK_K };
	Walk wk[WALK_STARTS];
	double nx[LANES], ny[LANES], px[LANES], py[LANES], mx[LANES], my[LANES], qx[LANES], qy[LANES];
	int nv = 0, nwalk = 1, best = -1, retries = 0;
	double target = tol;
	mkResult r = walk_start(w, &wk[0], b1, b2, impl, 0.0, MK_PI / 8.0, target, max_points, &nv);
	if (r != MK_OK) return r;
	for (;;) {
		/* one round: every live walk's candidates, in two batch calls */
		int nl = 0;
		for (int j = 0; j < nwalk; ++j)
			if (!wk[j].done)
				for (int k = 0; k < wk[j].nc; ++k, ++nl) sincos_exact(wk[j].phi + wk[j].d[k], &nx[nl], &ny[nl]);
		if (nl == 0) break;
		r = eval2(b1, b2, impl, nx, ny, nl, px, py);
		if (r != MK_OK) return r;
		nl = 0;
		for (int j = 0; j < nwalk; ++j) {
			Walk *a = &wk[j];
			if (a->done) continue;
			double rem = a->phi0 + 2.0 * MK_PI - a->phi;
			mkVec2 ni = wn2(w, a->cur), pi = wp2(w, a->cur);
			for (int k = 0; k < a->nc; ++k, ++nl) {
				if (a->d[k] == rem) { /* the closing arc ends at the first vertex itself */
					nx[nl] = w->n[0][a->first]; ny[nl] = w->n[1][a->first];
					px[nl] = w->p[0][a->first]; py[nl] = w->p[1][a->first];
				}
				mkVec2 m = split_normal2(ni, mkVec2_Make(nx[nl], ny[nl]), pi, mkVec2_Make(px[nl], py[nl]));
				mx[nl] = m.x; my[nl] = m.y;
			}
		}
		r = eval2(b1, b2, impl, mx, my, nl, qx, qy);
		if (r != MK_OK) return r;
		nl = 0;
		int live = nwalk;
		for (int j = 0; j < live; ++j) {
			Walk *a = &wk[j];
			if (a->done) continue;
			mkVec2 ni = wn2(w, a->cur), pi = wp2(w, a->cur);
			int first_lane = nl;
			for (int k = 0; k < a->nc; ++k, ++nl) {
				double e = edge_err2(bound, ni, mkVec2_Make(nx[nl], ny[nl]), pi, mkVec2_Make(px[nl], py[nl]),
					mkVec2_Make(mx[nl], my[nl]), mkVec2_Make(qx[nl], qy[nl]));
				qx[nl] = e; /* the lane's error from here on */
				if (e <= a->tol && a->d[k] > a->lo) {
					a->lo = a->d[k]; a->lo_e = e;
					a->lo_n = mkVec2_Make(nx[nl], ny[nl]); a->lo_p = mkVec2_Make(px[nl], py[nl]);
				}
			}
			if (!(a->hi > a->lo)) a->hi = INFINITY;
			for (int k = 0, l = first_lane; k < a->nc; ++k, ++l)
				if (!(qx[l] <= a->tol) && a->d[k] > a->lo && a->d[k] < a->hi) { a->hi = a->d[k]; a->hi_e = qx[l]; }
			if (a->force) { /* the one candidate, certified or not */
				int l = first_lane;
				a->lo = a->d[0]; a->lo_e = qx[l];
				a->lo_n = mkVec2_Make(nx[l], ny[l]); a->lo_p = mkVec2_Make(px[l], py[l]);
			} else if (!walk_next(a, max_points)) {
				continue;
			}
			/* the step lo is decided */
			double rem = a->phi0 + 2.0 * MK_PI - a->phi;
			w->err2[a->cur] = a->lo_e;
			if (a->lo_e > a->maxerr || a->lo_e != a->lo_e) a->maxerr = a->lo_e;
			if (a->lo == rem) {
				w->next[a->cur] = a->first;
				a->done = 1;
				if (best < 0 || a->count < wk[best].count) best = j;
				continue;
			}
			int k = walk_node(w, &nv, a->lo_n, a->lo_p);
			if (k < 0) return MK_ERR_MEMORY;
			w->next[a->cur] = k;
			a->cur = k;
			a->phi += a->lo;
			a->guess = a->lo;
			a->count++;
			if (a->count >= max_points - WALK_LAST && retries < WALK_RETRIES) {
				/* too many vertices: all walks start over, looser */
				double f = (a->phi - a->phi0) / (2.0 * MK_PI), grow = 1.1 / f;
				target *= grow * grow > 2.0 ? grow * grow : 2.0;
				++retries;
				nv = 0; nwalk = 1; best = -1;
				r = walk_start(w, &wk[0], b1, b2, impl, 0.0, MK_PI / 8.0, target, max_points, &nv);
				if (r != MK_OK) return r;
				break;
			}
			walk_ladder(a, target, max_points);
			if (j == 0 && a->count == 2) /* walk 0's first step is known: the other starts inside it */
				for (; nwalk < WALK_STARTS; ++nwalk) {
					r = walk_start(w, &wk[nwalk], b1, b2, impl, a->phi * nwalk / WALK_STARTS, a->guess, target,
						max_points, &nv);
					if (r != MK_OK) return r;
				}
		}
		for (int j = 0; j < nwalk; ++j) /* drop the walks that cannot beat a finished one */
			if (best >= 0 && !wk[j].done && wk[j].count >= wk[best].count) wk[j].done = 1;
	}
	/* the winner's vertices to nodes 0 .. count - 1, in order */
	const Walk *a = &wk[best];
	int cnt = a->count;
	if (!grow_d(&w->cp, &w->cpcap, 5 * cnt)) return MK_ERR_MEMORY;
	for (int k = 0, i = a->first; k < cnt; ++k, i = w->next[i]) {
		w->cp[5 * k] = w->n[0][i]; w->cp[5 * k + 1] = w->n[1][i];
		w->cp[5 * k + 2] = w->p[0][i]; w->cp[5 * k + 3] = w->p[1][i];
		w->cp[5 * k + 4] = w->err2[i];
	}
	for (int k = 0; k < cnt; ++k) {
		w->n[0][k] = w->cp[5 * k]; w->n[1][k] = w->cp[5 * k + 1];
		w->p[0][k] = w->cp[5 * k + 2]; w->p[1][k] = w->cp[5 * k + 3];
		w->err2[k] = w->cp[5 * k + 4];
	}
	*count = cnt;
	*error = a->maxerr;
	return MK_OK;
}

/* Adaptive (uniform_n == 0 and no given normals: walk2) or fixed normals
 * (uniform_n normals 2 pi k / n, or the given ones), each arc certified
 * by edge_err2. Results in w: *count nodes 0 .. count - 1 in
 * counter-clockwise order, w->err2[i] the error of the arc from node i to
 * node i + 1 (mod count). */
static mkResult run2(Work *w, mkBody2 b1, mkBody2 b2, mkImpl impl, mkBound bound, double tol, int max_points,
	int uniform_n, const double *given_x, const double *given_y, int *count, double *error)
{
	if (uniform_n == 0 && !given_x) return walk2(w, b1, b2, impl, bound, tol, max_points, count, error);
	int K = uniform_n;
	if (!work_verts(w, K, 2) || !grow_d(&w->err2, &w->ecap, K) || !work_batch(w, K, 2))
		return MK_ERR_MEMORY;
	for (int k = 0; k < K; ++k) {
		if (given_x) {
			mkVec2 u = mkVec2_NormalizeInline(mkVec2_Make(given_x[k], given_y[k]));
			w->n[0][k] = u.x; w->n[1][k] = u.y;
		} else {
			sincos_exact(2.0 * MK_PI * k / K, &w->n[0][k], &w->n[1][k]);
		}
	}
	mkResult r = eval2(b1, b2, impl, w->n[0], w->n[1], K, w->p[0], w->p[1]);
	if (r != MK_OK) return r;
	/* split normals: the chord's outward normal when it lies between the
	 * two normals (always, in exact arithmetic), else the bisector */
	for (int i = 0; i < K; ++i) {
		int j = (i + 1) % K;
		mkVec2 m = split_normal2(wn2(w, i), wn2(w, j), wp2(w, i), wp2(w, j));
		w->m[0][i] = m.x; w->m[1][i] = m.y;
	}
	r = eval2(b1, b2, impl, w->m[0], w->m[1], K, w->q[0], w->q[1]);
	if (r != MK_OK) return r;
	double maxerr = 0.0;
	for (int i = 0; i < K; ++i) {
		int j = (i + 1) % K;
		double err = edge_err2(bound, wn2(w, i), wn2(w, j), wp2(w, i), wp2(w, j), mkVec2_Make(w->m[0][i], w->m[1][i]),
			mkVec2_Make(w->q[0][i], w->q[1][i]));
		if (err > maxerr || err != err) maxerr = err;
		w->err2[i] = err;
	}
	*count = K;
	*error = maxerr;
	return MK_OK;
}

/* Write the boundary of run2 (inner: the points; outer: the tangent
 * vertices) counter-clockwise from node 0 into out (2 arrays). */
static void emit2(const Work *w, mkBound bound, int count, double *ox, double *oy)
{
	for (int i = 0; i < count; ++i) {
		int j = (i + 1) % count;
		if (bound == MK_BOUND_INNER) {
			ox[i] = w->p[0][i]; oy[i] = w->p[1][i];
		} else {
			mkVec2 v = tangent_vertex(mkVec2_Make(w->n[0][i], w->n[1][i]), mkVec2_Make(w->p[0][i], w->p[1][i]),
				mkVec2_Make(w->n[0][j], w->n[1][j]), mkVec2_Make(w->p[0][j], w->p[1][j]));
			ox[i] = v.x; oy[i] = v.y;
		}
	}
}

static mkResult single2(mkBody2 b1, mkBody2 b2, mkBound bound, double tol, int max_points, int uniform_n,
	const double *given_x, const double *given_y, mkImpl impl, double **x, double **y, int *cap, int *count, double *error)
{
	if (!x || !y || !cap || !count || !error || (bound != MK_BOUND_INNER && bound != MK_BOUND_OUTER))
		return MK_ERR_ARGUMENT;
	Work w;
	memset(&w, 0, sizeof w);
	int n = 0;
	double e = 0.0;
	mkResult r = run2(&w, b1, b2, impl, bound, tol, max_points, uniform_n, given_x, given_y, &n, &e);
	if (r == MK_OK) {
		int c1 = *cap, c2 = *cap;
		if (!grow_d(x, &c1, n) || !grow_d(y, &c2, n)) r = MK_ERR_MEMORY;
		else {
			*cap = c1 < c2 ? c1 : c2;
			emit2(&w, bound, n, *x, *y);
			*count = n;
			*error = e;
		}
	}
	work_free(&w);
	return r;
}

mkResult mkCObstacle2_Adaptive(mkBody2 b1, mkBody2 b2, mkBound bound, double tol, int max_points,
	mkImpl impl, double **x, double **y, int *cap, int *count, double *error)
{
	if (!(tol > 0.0) || !isfinite(tol) || max_points < 8) return MK_ERR_ARGUMENT;
	return single2(b1, b2, bound, tol, max_points, 0, NULL, NULL, impl, x, y, cap, count, error);
}

mkResult mkCObstacle2_Uniform(mkBody2 b1, mkBody2 b2, mkBound bound, int n, mkImpl impl,
	double **x, double **y, int *cap, int *count, double *error)
{
	if (n < 4) return MK_ERR_ARGUMENT;
	return single2(b1, b2, bound, 1.0, n, n, NULL, NULL, impl, x, y, cap, count, error);
}

mkResult mkCObstacle2_Certify(mkBody2 b1, mkBody2 b2, mkBound bound, const double *nx, const double *ny, int n,
	mkImpl impl, double **x, double **y, int *cap, int *count, double *error)
{
	if (n < 3 || !nx || !ny) return MK_ERR_ARGUMENT;
	for (int k = 0; k < n; ++k)
		if (!isfinite(nx[k]) || !isfinite(ny[k]) || (nx[k] == 0.0 && ny[k] == 0.0)) return MK_ERR_ARGUMENT;
	return single2(b1, b2, bound, 1.0, n, n, nx, ny, impl, x, y, cap, count, error);
}

/* ---- 3D ------------------------------------------------------------------------------ */

static uint64_t edge_key(int a, int b)
{
	uint32_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
	return (uint64_t)lo << 32 | hi;
}

static uint64_t dedge_key(int a, int b) { return (uint64_t)(uint32_t)a << 32 | (uint32_t)b; }

static uint64_t hash64(uint64_t z)
{
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	return z ^ (z >> 31);
}

static void hash_clear(Hash *h)
{
	h->count = 0;
	for (int i = 0; i < h->cap; ++i) h->val[i] = -1;
}

/* Values: -1 marks an empty slot, -2 a removed entry (probing goes on). */
static int hash_slot(const Hash *h, uint64_t k)
{
	if (!h->cap) return -1;
	for (uint64_t i = hash64(k) & (uint64_t)(h->cap - 1);; i = (i + 1) & (uint64_t)(h->cap - 1)) {
		if (h->val[i] == -1) return -1;
		if (h->val[i] >= 0 && h->key[i] == k) return (int)i;
	}
}

static int hash_find(const Hash *h, uint64_t k)
{
	int i = hash_slot(h, k);
	return i < 0 ? -1 : h->val[i];
}

static int hash_put(Hash *h, uint64_t k, int v)
{
	if (2 * (h->count + 1) > h->cap) {
		int nc = h->cap ? 2 * h->cap : 1024;
		uint64_t *nk = malloc((size_t)nc * sizeof *nk);
		int *nv = malloc((size_t)nc * sizeof *nv);
		if (!nk || !nv) { free(nk); free(nv); return 0; }
		for (int i = 0; i < nc; ++i) nv[i] = -1;
		for (int i = 0; i < h->cap; ++i) {
			if (h->val[i] < 0) continue; /* removed entries are dropped */
			uint64_t j = hash64(h->key[i]) & (uint64_t)(nc - 1);
			while (nv[j] >= 0) j = (j + 1) & (uint64_t)(nc - 1);
			nk[j] = h->key[i];
			nv[j] = h->val[i];
		}
		free(h->key); free(h->val);
		h->key = nk; h->val = nv; h->cap = nc;
	}
	uint64_t j = hash64(k) & (uint64_t)(h->cap - 1);
	while (h->val[j] != -1) j = (j + 1) & (uint64_t)(h->cap - 1);
	h->key[j] = k;
	h->val[j] = v;
	++h->count;
	return 1;
}

static mkVec3 vn(const Work *w, int i) { return mkVec3_Make(w->n[0][i], w->n[1][i], w->n[2][i]); }
static mkVec3 vp(const Work *w, int i) { return mkVec3_Make(w->p[0][i], w->p[1][i], w->p[2][i]); }
static double size3(mkVec3 a) { return fabs(a.x) + fabs(a.y) + fabs(a.z); }

static int new_normal(Work *w, mkVec3 u, int *nv)
{
	if (!work_verts(w, *nv + 1, 3)) return -1;
	int m = (*nv)++;
	w->n[0][m] = u.x; w->n[1][m] = u.y; w->n[2][m] = u.z;
	return m;
}

/* The midpoint normal of edge (a, b), created on first use; -1 on memory. */
static int midpoint(Work *w, int a, int b, int *nv)
{
	int m = hash_find(&w->edges, edge_key(a, b));
	if (m >= 0) return m;
	m = new_normal(w, mkVec3_Normalize(mkVec3_Add(vn(w, a), vn(w, b))), nv);
	if (m < 0 || !hash_put(&w->edges, edge_key(a, b), m)) return -1;
	return m;
}

/* Proof 4 of docs/scene.md: for normals u in the spherical triangle (a, b, c),
 * both h_K(u) - h_P(u) and h_Q(u) - h_K(u) are at most
 *   max over pairs of <n_k - n_j, p_k - p_j> / (3 d0),
 * d0 the distance from the origin to the plane through the three normals. */
static double tri_d0(const Work *w, int a, int b, int c)
{
	mkVec3 na = vn(w, a);
	mkVec3 nu = mkVec3_Normalize(mkVec3_Cross(mkVec3_Sub(vn(w, b), na), mkVec3_Sub(vn(w, c), na)));
	return fabs(mkVec3_Dot(na, nu));
}

static double tri_bound(const Work *w, int a, int b, int c)
{
	int v[3] = {a, b, c};
	double C = 0.0, sz = 0.0;
	for (int i = 0; i < 3; ++i) {
		int k = v[i], j = v[(i + 1) % 3];
		double t = mkVec3_Dot(mkVec3_Sub(vn(w, k), vn(w, j)), mkVec3_Sub(vp(w, k), vp(w, j)));
		if (t > C) C = t;
		sz += size3(vp(w, k));
	}
	return C / (3.0 * tri_d0(w, a, b, c)) + ROUND_REL * sz;
}

static double vangle(mkVec3 a, mkVec3 b) { return atan2(mkVec3_Length(mkVec3_Cross(a, b)), mkVec3_Dot(a, b)); }

static mkResult eval_pending(Work *w, mkBody3 b1, mkBody3 b2, mkImpl impl, int *neval, int nv)
{
	if (nv <= *neval) return MK_OK;
	mkResult r = eval3(b1, b2, impl, w->n[0] + *neval, w->n[1] + *neval, w->n[2] + *neval, nv - *neval,
		w->p[0] + *neval, w->p[1] + *neval, w->p[2] + *neval);
	*neval = nv;
	return r;
}

/* The vertices on edge a -> b strictly between them (midpoints made by
 * finer neighbours), in order, appended to w->poly. */
static int chain(Work *w, int a, int b, int *len)
{
	int m = hash_find(&w->edges, edge_key(a, b));
	if (m < 0) return 1;
	if (!chain(w, a, m, len)) return 0;
	if (!grow_i(&w->poly, &w->pcap, *len + 1)) return 0;
	w->poly[(*len)++] = m;
	return chain(w, m, b, len);
}

/* Adaptive (splits < 0) or uniform refinement of the octahedron of normals,
 * then (conform = 1) the conforming closed triangulation: a leaf whose
 * edges carry vertices of finer neighbours gets a new normal at its
 * centroid and is fanned from it. Vertices 0..*count-1 (w->n, w->p), final triangles in
 * w->fin (*nfin, counter-clockwise from outside). *error: the largest leaf
 * bound (which holds on the final triangulation too: Proof 4 needs only the
 * leaf's corners). *d0min: the smallest d0 of the leaves. */
static mkResult run3(Work *w, mkBody3 b1, mkBody3 b2, mkImpl impl, double tol, int max_points, int splits,
	int conform, int *count, int *nfin, double *error, double *d0min)
{
	static const double oct[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
	hash_clear(&w->edges);
	if (!work_verts(w, 6, 3) || !grow_i(&w->tri, &w->tcap, 24)) return MK_ERR_MEMORY;
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
		if (!work_verts(w, nv, 3)) return MK_ERR_MEMORY;
		if ((r = eval_pending(w, b1, b2, impl, &neval, nv)) != MK_OK) return r;
		int nn = 0;
		for (int t = 0; t < na; ++t) {
			int a = w->tri[3 * t], b = w->tri[3 * t + 1], c = w->tri[3 * t + 2];
			int split;
			double err = 0.0;
			if (splits >= 0) {
				split = level < splits;
				if (!split) err = tri_bound(w, a, b, c);
			} else {
				err = tri_bound(w, a, b, c);
				double ang = vangle(vn(w, a), vn(w, b));
				split = err > tol && ang > MIN_ANGLE && nv + 3 <= max_points;
			}
			if (!split) {
				if (err > maxerr || err != err) maxerr = err;
				double d0 = tri_d0(w, a, b, c);
				if (d0 < dmin) dmin = d0;
				if (!grow_i(&w->leaf, &w->lcap, 3 * (nl + 1))) return MK_ERR_MEMORY;
				w->leaf[3 * nl] = a; w->leaf[3 * nl + 1] = b; w->leaf[3 * nl + 2] = c;
				++nl;
				continue;
			}
			int ab = midpoint(w, a, b, &nv), bc = midpoint(w, b, c, &nv), ca = midpoint(w, c, a, &nv);
			if (ab < 0 || bc < 0 || ca < 0 || !grow_i(&w->tri2, &w->t2cap, 3 * (nn + 4))) return MK_ERR_MEMORY;
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
			if (!grow_i(&w->poly, &w->pcap, len + 1)) return MK_ERR_MEMORY;
			w->poly[len++] = v[e];
			if (!chain(w, v[e], v[(e + 1) % 3], &len)) return MK_ERR_MEMORY;
		}
		if (!grow_i(&w->fin, &w->fcap, 3 * (nf + len))) return MK_ERR_MEMORY;
		if (len == 3) {
			for (int d = 0; d < 3; ++d) w->fin[3 * nf + d] = v[d];
			++nf;
			continue;
		}
		mkVec3 cen = mkVec3_Normalize(mkVec3_Add(mkVec3_Add(vn(w, v[0]), vn(w, v[1])), vn(w, v[2])));
		int c = new_normal(w, cen, &nv);
		if (c < 0) return MK_ERR_MEMORY;
		for (int k = 0; k < len; ++k) {
			w->fin[3 * nf] = c;
			w->fin[3 * nf + 1] = w->poly[k];
			w->fin[3 * nf + 2] = w->poly[(k + 1) % len];
			++nf;
		}
	}
	if ((r = eval_pending(w, b1, b2, impl, &neval, nv)) != MK_OK) return r;
	*count = nv;
	*nfin = nf;
	*error = maxerr;
	*d0min = dmin;
	return MK_OK;
}

/* The vertex where the tangent planes of triangle t's normals meet, solved
 * relative to its first corner's point. */
static mkVec3 tangent_point(const Work *w, int a, int b, int c)
{
	mkVec3 na = vn(w, a), nb = vn(w, b), nc = vn(w, c), pa = vp(w, a);
	double rb = mkVec3_Dot(nb, mkVec3_Sub(vp(w, b), pa)), rc = mkVec3_Dot(nc, mkVec3_Sub(vp(w, c), pa));
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
static int wants_flip(const Work *w, mkBound bound, int a, int b, int c, int d)
{
	if (bound == MK_BOUND_INNER) {
		mkVec3 pa = vp(w, a);
		mkVec3 nrm = mkVec3_Cross(mkVec3_Sub(vp(w, b), pa), mkVec3_Sub(vp(w, c), pa));
		mkVec3 e = mkVec3_Sub(vp(w, d), pa);
		double sc = mkVec3_Length(nrm) * mkVec3_Length(e);
		return mkVec3_Dot(nrm, e) > 1e-12 * sc;
	}
	mkVec3 v = tangent_point(w, a, b, c), pd = vp(w, d);
	double ex = mkVec3_Dot(vn(w, d), mkVec3_Sub(v, pd));
	return ex > 1e-12 * (size3(v) + size3(pd));
}

static double det3(mkVec3 a, mkVec3 b, mkVec3 c) { return mkVec3_Dot(a, mkVec3_Cross(b, c)); }

/* Lawson flips of the final triangulation (w->fin) until every edge is
 * locally convex for `bound` or can no longer be flipped (the quadrilateral
 * of normals is not convex, or a pass limit). Every flip keeps a partition
 * of the sphere of normals into proper spherical triangles. Where a flip is
 * blocked the outer polytope's excess enters its certificate. Used for the
 * outer polytope; the inner one takes its faces from hull3. The certificates do not
 * depend on the faces (Proofs 4 and 5 use the normals' leaf triangles and,
 * for the outer polytope, the measured excess), only the output's face
 * structure does. */
static int flip_all(Work *w, int nfin, mkBound bound)
{
	hash_clear(&w->dedges);
	for (int t = 0; t < nfin; ++t)
		for (int e = 0; e < 3; ++e)
			if (!hash_put(&w->dedges, dedge_key(w->fin[3 * t + e], w->fin[3 * t + (e + 1) % 3]), t)) return 0;
	for (int pass = 0; pass < 64; ++pass) {
		int flips = 0;
		for (int t = 0; t < nfin; ++t)
			for (int e = 0; e < 3; ++e) {
				int *T = w->fin + 3 * t;
				int a = T[e], b = T[(e + 1) % 3], c = T[(e + 2) % 3];
				int u = hash_find(&w->dedges, dedge_key(b, a));
				if (u < 0) continue;
				int *U = w->fin + 3 * u, f = 0;
				while (U[f] != b) ++f;
				int d = U[(f + 2) % 3];
				if (d == c || !wants_flip(w, bound, a, b, c, d)) continue;
				/* new triangles (a, d, c) and (d, b, c): both must be proper
				 * spherical triangles of normals, so that the triangulation
				 * stays a partition of the sphere of normals */
				mkVec3 na = vn(w, a), nb = vn(w, b), nc = vn(w, c), nd = vn(w, d);
				if (!(det3(na, nd, nc) > 0.0 && det3(nd, nb, nc) > 0.0)) continue;
				if (hash_find(&w->dedges, dedge_key(d, c)) >= 0) continue; /* edge exists already */
				int ks[6][2] = {{a, b}, {b, c}, {c, a}, {b, a}, {a, d}, {d, b}};
				for (int k = 0; k < 6; ++k) w->dedges.val[hash_slot(&w->dedges, dedge_key(ks[k][0], ks[k][1]))] = -2;
				T[0] = a; T[1] = d; T[2] = c;
				U[0] = d; U[1] = b; U[2] = c;
				int ok = hash_put(&w->dedges, dedge_key(a, d), t) && hash_put(&w->dedges, dedge_key(d, c), t)
					&& hash_put(&w->dedges, dedge_key(c, a), t) && hash_put(&w->dedges, dedge_key(d, b), u)
					&& hash_put(&w->dedges, dedge_key(b, c), u) && hash_put(&w->dedges, dedge_key(c, d), u);
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
static int outer3(Work *w, int nv, int nfin, int **faces, int *fcap, double *excess)
{
	for (int d = 0; d < 3; ++d)
		if (!grow_d(&w->o[d], &w->ocap[d], nfin)) return -1;
	if (!flip_all(w, nfin, MK_BOUND_OUTER)) return -1;
	for (int t = 0; t < nfin; ++t) {
		mkVec3 v = tangent_point(w, w->fin[3 * t], w->fin[3 * t + 1], w->fin[3 * t + 2]);
		w->o[0][t] = v.x; w->o[1][t] = v.y; w->o[2][t] = v.z;
	}
	double ex = 0.0;
	for (int k = 0; k < nv; ++k) {
		mkVec3 n = vn(w, k);
		double h = mkVec3_Dot(n, vp(w, k));
		for (int t = 0; t < nfin; ++t) {
			double e = n.x * w->o[0][t] + n.y * w->o[1][t] + n.z * w->o[2][t] - h;
			if (e > ex || e != e) ex = e;
		}
	}
	*excess = ex;
	hash_clear(&w->dedges);
	for (int t = 0; t < nfin; ++t)
		for (int e = 0; e < 3; ++e)
			if (!hash_put(&w->dedges, dedge_key(w->fin[3 * t + e], w->fin[3 * t + (e + 1) % 3]), t)) return -1;
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
			if (!grow_i(&w->poly, &w->pcap, len + 1)) { free(start); return -1; }
			w->poly[len++] = t;
			int e = 0;
			while (w->fin[3 * t + e] != k) ++e;
			int b = w->fin[3 * t + (e + 2) % 3];
			t = hash_find(&w->dedges, dedge_key(k, b));
		} while (t >= 0 && t != start[k] && len <= nfin);
		if (t < 0 || len > nfin) { free(start); return -1; } /* not a closed surface: cannot happen */
		if (!grow_i(faces, fcap, 3 * (nf + len))) { free(start); return -1; }
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

/* The convex hull of the points w->p[0..n) (incremental, in index order, so
 * deterministic): triangles counter-clockwise from outside into *faces;
 * returns their count, or -1 on memory or a degenerate point set. A point
 * within 1e-11 of the points' size of a face's plane counts as on the
 * hull's side of it and is left out of the faces (it lies in the hull). */
static int hull3(Work *w, int n, int **faces, int *fcap)
{
	if (n < 4) return -1;
	double scale = 0.0;
	for (int k = 0; k < n; ++k) scale = fmax(scale, size3(vp(w, k)));
	const double eps = 1e-11 * (scale > 0.0 ? scale : 1.0);
	/* a first tetrahedron of far-apart points */
	int i0 = 0;
	for (int k = 1; k < n; ++k) if (w->p[0][k] < w->p[0][i0]) i0 = k;
	int i1 = -1, i2 = -1, i3 = -1;
	double best = 0.0;
	for (int k = 0; k < n; ++k) {
		double d = mkVec3_Length(mkVec3_Sub(vp(w, k), vp(w, i0)));
		if (d > best) { best = d; i1 = k; }
	}
	if (i1 < 0) return -1;
	best = 0.0;
	mkVec3 e01 = mkVec3_Sub(vp(w, i1), vp(w, i0));
	for (int k = 0; k < n; ++k) {
		double d = mkVec3_Length(mkVec3_Cross(e01, mkVec3_Sub(vp(w, k), vp(w, i0))));
		if (d > best) { best = d; i2 = k; }
	}
	if (i2 < 0) return -1;
	mkVec3 nrm = mkVec3_Cross(e01, mkVec3_Sub(vp(w, i2), vp(w, i0)));
	best = 0.0;
	for (int k = 0; k < n; ++k) {
		double d = fabs(mkVec3_Dot(nrm, mkVec3_Sub(vp(w, k), vp(w, i0))));
		if (d > best) { best = d; i3 = k; }
	}
	if (i3 < 0 || best <= eps * mkVec3_Length(nrm)) return -1;
	int cap = 64, nf = 0;
	int *F = malloc((size_t)cap * 3 * sizeof *F);
	double *P = malloc((size_t)cap * 4 * sizeof *P);
	char *alive = malloc((size_t)cap);
	int *stack = NULL, scap = 0, *vis = NULL, vcap = 0, *hor = NULL, hcap = 0;
	if (!F || !P || !alive) goto fail;
	hash_clear(&w->dedges);
	mkVec3 inside = mkVec3_Scale(mkVec3_Add(mkVec3_Add(vp(w, i0), vp(w, i1)), mkVec3_Add(vp(w, i2), vp(w, i3))), 0.25);
#define ADD_FACE(A, B, C) do { \
		int a_ = (A), b_ = (B), c_ = (C); \
		if (nf == cap) { \
			cap *= 2; \
			int *nF = realloc(F, (size_t)cap * 3 * sizeof *F); if (!nF) goto fail; F = nF; \
			double *nP = realloc(P, (size_t)cap * 4 * sizeof *P); if (!nP) goto fail; P = nP; \
			char *nA = realloc(alive, (size_t)cap); if (!nA) goto fail; alive = nA; \
		} \
		mkVec3 pa_ = vp(w, a_); \
		mkVec3 nn_ = mkVec3_Normalize(mkVec3_Cross(mkVec3_Sub(vp(w, b_), pa_), mkVec3_Sub(vp(w, c_), pa_))); \
		if (mkVec3_Dot(nn_, mkVec3_Sub(inside, pa_)) > 0.0) { int t_ = b_; b_ = c_; c_ = t_; nn_ = mkVec3_Neg(nn_); } \
		F[3 * nf] = a_; F[3 * nf + 1] = b_; F[3 * nf + 2] = c_; \
		P[4 * nf] = nn_.x; P[4 * nf + 1] = nn_.y; P[4 * nf + 2] = nn_.z; P[4 * nf + 3] = mkVec3_Dot(nn_, pa_); \
		alive[nf] = 1; \
		if (!hash_put(&w->dedges, dedge_key(a_, b_), nf) || !hash_put(&w->dedges, dedge_key(b_, c_), nf) \
			|| !hash_put(&w->dedges, dedge_key(c_, a_), nf)) goto fail; \
		++nf; \
	} while (0)
	ADD_FACE(i0, i1, i2); ADD_FACE(i0, i1, i3); ADD_FACE(i0, i2, i3); ADD_FACE(i1, i2, i3);
	int last = 3;
	for (int k = 0; k < n; ++k) {
		if (k == i0 || k == i1 || k == i2 || k == i3) continue;
		mkVec3 p = vp(w, k);
		/* a face that sees p: first by walking from the newest face to
		 * neighbours that see p better, else by looking at every face */
		int f0 = -1, cur = last;
		double dcur = P[4 * cur] * p.x + P[4 * cur + 1] * p.y + P[4 * cur + 2] * p.z - P[4 * cur + 3];
		for (int steps = 0; steps < nf && dcur <= eps; ++steps) {
			int next = -1;
			double dn = dcur;
			for (int e = 0; e < 3; ++e) {
				int g = hash_find(&w->dedges, dedge_key(F[3 * cur + (e + 1) % 3], F[3 * cur + e]));
				if (g < 0 || alive[g] != 1) continue;
				double d = P[4 * g] * p.x + P[4 * g + 1] * p.y + P[4 * g + 2] * p.z - P[4 * g + 3];
				if (d > dn) { dn = d; next = g; }
			}
			if (next < 0) break;
			cur = next;
			dcur = dn;
		}
		if (dcur > eps) f0 = cur;
		else {
			double dmax = eps;
			for (int f = 0; f < nf; ++f) {
				if (alive[f] != 1) continue;
				double d = P[4 * f] * p.x + P[4 * f + 1] * p.y + P[4 * f + 2] * p.z - P[4 * f + 3];
				if (d > dmax) { dmax = d; f0 = f; }
			}
		}
		if (f0 < 0) continue; /* inside or on the hull */
		/* the connected set of faces that see p, from the one that sees it most */
		int nvis = 0, ns = 0;
		if (!grow_i(&stack, &scap, 1)) goto fail;
		stack[ns++] = f0;
		alive[f0] = 2; /* 2: visible, being removed */
		while (ns) {
			int f = stack[--ns];
			if (!grow_i(&vis, &vcap, nvis + 1)) goto fail;
			vis[nvis++] = f;
			for (int e = 0; e < 3; ++e) {
				int g = hash_find(&w->dedges, dedge_key(F[3 * f + (e + 1) % 3], F[3 * f + e]));
				if (g < 0 || alive[g] != 1) continue;
				double d = P[4 * g] * p.x + P[4 * g + 1] * p.y + P[4 * g + 2] * p.z - P[4 * g + 3];
				if (d > eps) {
					alive[g] = 2;
					if (!grow_i(&stack, &scap, ns + 1)) goto fail;
					stack[ns++] = g;
				}
			}
		}
		/* horizon: edges of visible faces whose other side stays */
		int nh = 0;
		for (int v = 0; v < nvis; ++v) {
			int f = vis[v];
			for (int e = 0; e < 3; ++e) {
				int a = F[3 * f + e], b = F[3 * f + (e + 1) % 3];
				int g = hash_find(&w->dedges, dedge_key(b, a));
				if (g >= 0 && alive[g] == 1) {
					if (!grow_i(&hor, &hcap, 2 * (nh + 1))) goto fail;
					hor[2 * nh] = a; hor[2 * nh + 1] = b;
					++nh;
				}
			}
		}
		for (int v = 0; v < nvis; ++v) {
			int f = vis[v];
			alive[f] = 0;
			for (int e = 0; e < 3; ++e)
				w->dedges.val[hash_slot(&w->dedges, dedge_key(F[3 * f + e], F[3 * f + (e + 1) % 3]))] = -2;
		}
		for (int h = 0; h < nh; ++h) ADD_FACE(hor[2 * h], hor[2 * h + 1], k);
		last = nf - 1;
	}
#undef ADD_FACE
	int out = 0;
	for (int f = 0; f < nf; ++f) out += alive[f] == 1;
	if (!grow_i(faces, fcap, 3 * out + 3)) goto fail;
	out = 0;
	for (int f = 0; f < nf; ++f) {
		if (alive[f] != 1) continue;
		for (int d = 0; d < 3; ++d) (*faces)[3 * out + d] = F[3 * f + d];
		++out;
	}
	free(F); free(P); free(alive); free(stack); free(vis); free(hor);
	return out;
fail:
	free(F); free(P); free(alive); free(stack); free(vis); free(hor);
	return -1;
}

/* One 3D boundary into w: inner (points w->p, triangles w->fin) or outer
 * (points w->o, triangles in *faces). */
static mkResult boundary3(Work *w, mkBody3 b1, mkBody3 b2, mkImpl impl, mkBound bound, double tol, int max_points,
	int splits, int want_faces, int *count, int *nfaces, int **faces, int *fcap, double *error)
{
	int nv = 0, nfin = 0;
	double err = 0.0, d0 = 1.0;
	mkResult r = run3(w, b1, b2, impl, tol, max_points, splits, bound == MK_BOUND_OUTER, &nv, &nfin, &err, &d0);
	if (r != MK_OK) return r;
	if (bound == MK_BOUND_INNER) {
		int nf = want_faces ? hull3(w, nv, faces, fcap) : 0;
		if (nf < 0) return MK_ERR_MEMORY;
		*count = nv;
		*nfaces = nf;
		*error = err;
		return MK_OK;
	}
	double ex = 0.0;
	int nf = outer3(w, nv, nfin, faces, fcap, &ex);
	if (nf < 0) return MK_ERR_MEMORY;
	*count = nfin;
	*nfaces = nf;
	*error = err + ex / d0;
	return MK_OK;
}

static mkResult single3(mkBody3 b1, mkBody3 b2, mkBound bound, double tol, int max_points, int splits, mkImpl impl,
	double **x, double **y, double **z, int *cap, int **faces, int *face_cap, int *count, int *face_count,
	double *error)
{
	if (!x || !y || !z || !cap || !count || !error || (bound != MK_BOUND_INNER && bound != MK_BOUND_OUTER)
		|| (faces && (!face_cap || !face_count)))
		return MK_ERR_ARGUMENT;
	Work w;
	memset(&w, 0, sizeof w);
	int n = 0, nf = 0, *tmp = NULL, tcap = 0;
	double e = 0.0;
	mkResult r = boundary3(&w, b1, b2, impl, bound, tol, max_points, splits, faces != NULL, &n, &nf,
		faces ? faces : &tmp, faces ? face_cap : &tcap, &e);
	free(tmp);
	if (r == MK_OK) {
		int c1 = *cap, c2 = *cap, c3 = *cap;
		if (!grow_d(x, &c1, n) || !grow_d(y, &c2, n) || !grow_d(z, &c3, n)) r = MK_ERR_MEMORY;
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
	work_free(&w);
	return r;
}

mkResult mkCObstacle3_Adaptive(mkBody3 b1, mkBody3 b2, mkBound bound, double tol, int max_points, mkImpl impl,
	double **x, double **y, double **z, int *cap, int **faces, int *face_cap, int *count, int *face_count,
	double *error)
{
	if (!(tol > 0.0) || !isfinite(tol) || max_points < 6) return MK_ERR_ARGUMENT;
	return single3(b1, b2, bound, tol, max_points, -1, impl, x, y, z, cap, faces, face_cap, count, face_count, error);
}

mkResult mkCObstacle3_Uniform(mkBody3 b1, mkBody3 b2, mkBound bound, int splits, mkImpl impl,
	double **x, double **y, double **z, int *cap, int **faces, int *face_cap, int *count, int *face_count,
	double *error)
{
	if (splits < 0 || splits > MAX_SPLITS) return MK_ERR_ARGUMENT;
	return single3(b1, b2, bound, 1.0, 1 << 30, splits, impl, x, y, z, cap, faces, face_cap, count, face_count, error);
}

mkResult mkCObstacle3_Certify(mkBody3 b1, mkBody3 b2, const double *nx, const double *ny, const double *nz, int n,
	const int *tris, int ntri, mkImpl impl, double *error)
{
	if (n < 4 || ntri < 4 || !nx || !ny || !nz || !tris || !error) return MK_ERR_ARGUMENT;
	for (int t = 0; t < 3 * ntri; ++t)
		if (tris[t] < 0 || tris[t] >= n) return MK_ERR_ARGUMENT;
	Work w;
	memset(&w, 0, sizeof w);
	mkResult r = MK_OK;
	if (!work_verts(&w, n, 3)) { r = MK_ERR_MEMORY; goto done; }
	for (int k = 0; k < n; ++k) {
		mkVec3 u = mkVec3_Normalize(mkVec3_Make(nx[k], ny[k], nz[k]));
		if (!(u.x == u.x && u.y == u.y && u.z == u.z)) { r = MK_ERR_ARGUMENT; goto done; }
		w.n[0][k] = u.x; w.n[1][k] = u.y; w.n[2][k] = u.z;
	}
	if ((r = eval3(b1, b2, impl, w.n[0], w.n[1], w.n[2], n, w.p[0], w.p[1], w.p[2])) != MK_OK) goto done;
	/* Proof 3 needs the triangles to partition the sphere: every one
	 * positively oriented and their areas summing to 4 pi */
	double area = 0.0, err = 0.0;
	for (int t = 0; t < ntri; ++t) {
		int a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
		mkVec3 na = vn(&w, a), nb = vn(&w, b), nc = vn(&w, c);
		double det = det3(na, nb, nc);
		if (!(det > 0.0)) { err = INFINITY; break; }
		area += 2.0 * atan2(det, 1.0 + mkVec3_Dot(na, nb) + mkVec3_Dot(nb, nc) + mkVec3_Dot(nc, na));
		double e = tri_bound(&w, a, b, c);
		if (e > err || e != e) err = e;
	}
	if (!(fabs(area - 4.0 * MK_PI) <= 1e-9)) err = INFINITY;
	*error = err;
done:
	work_free(&w);
	return r;
}

/* ---- scenes on threads ----------------------------------------------------------------- */

typedef struct TaskOut {     /* one boundary's stored output */
	double *xyz;             /* count * dim, interleaved */
	int *faces;
	int nfaces;
} TaskOut;

typedef struct Run {
	const mkScene *scene;
	const mkCSpaceOptions *opt;
	int begin, nor, nob, bounds, dim;
	/* models: [bound] for the robot, [i * 2 + bound] for obstacles */
	mkBody2 robot2[2], *obs2;
	mkBody3 robot3[2], *obs3;
	double robot_err[2], *obs_err;
	double *paper_u[3];      /* paper mode parameters */
	int paper_n;
	/* paper mode: a task is one obstacle and `chunk` orientations, whose
	 * robot maps R_o M are poses2/poses3 (relative o), computed once */
	int chunk, nchunks, group;
	mkMat2 *poses2;
	mkMat3 *poses3;
	mkCSpaceResult *res;
	TaskOut *outs;           /* per boundary, store = 1 */
	long ntasks;
	long next_task;          /* guarded by lock */
	pthread_mutex_t lock;
	int failed;              /* an mkResult, guarded by lock */
} Run;

static double now_s(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static mkResult do_task(Run *R, Work *w, long task)
{
	const mkCSpaceOptions *o = R->opt;
	int orel = (int)(task / R->nob), i = (int)(task % R->nob), ori = R->begin + orel;
	double t0 = now_s();
	for (int k = 0; k < R->bounds; ++k) {
		long b = task * R->bounds + k;
		int count = 0, nf = 0;
		double err = NAN, sum = 0.0;
		const double *px = NULL, *py = NULL, *pz = NULL;
		mkResult r;
		if (R->dim == 2) {
			mkBody2 rob = R->robot2[k];
			rob.M = mkMat2_Mul(mkScene2_Orientation(R->scene, ori), rob.M);
			rob.t = mkVec2_Make(0.0, 0.0);
			mkBody2 ob = R->obs2[2 * i + k];
			if (o->mode == MK_CSPACE_PAPER) {
				count = R->paper_n;
				if (!work_batch(w, count, 2)) return MK_ERR_MEMORY;
				mkSumOptions so = {MK_SET_CONTACT, o->form, MK_PARAM_SURFACE, o->impl, MK_PRECISION_DOUBLE};
				r = mkSum2_Batch(ob, rob, &so, R->paper_u[0], R->paper_u[1], count, w->q[0], w->q[1], NULL, NULL);
				if (r != MK_OK) return r;
				px = w->q[0]; py = w->q[1];
			} else {
				double tol = o->tol - R->obs_err[2 * i + k] - R->robot_err[k];
				r = run2(w, ob, rob, o->impl, (mkBound)k, tol, o->max_points,
					o->mode == MK_CSPACE_UNIFORM ? o->uniform : 0, NULL, NULL, &count, &err);
				if (r != MK_OK) return r;
				if (!work_batch(w, count, 2)) return MK_ERR_MEMORY;
				emit2(w, (mkBound)k, count, w->q[0], w->q[1]);
				px = w->q[0]; py = w->q[1];
			}
		} else {
			mkBody3 rob = R->robot3[k];
			rob.M = mkMat3_Mul(mkScene3_Orientation(R->scene, ori), rob.M);
			rob.t = mkVec3_Make(0.0, 0.0, 0.0);
			mkBody3 ob = R->obs3[2 * i + k];
			if (o->mode == MK_CSPACE_PAPER) {
				count = R->paper_n * R->paper_n;
				if (!work_batch(w, count, 3)) return MK_ERR_MEMORY;
				mkSumOptions so = {MK_SET_CONTACT, o->form, MK_PARAM_SURFACE, o->impl, MK_PRECISION_DOUBLE};
				r = mkSum3_Batch(ob, rob, &so, R->paper_u[0], R->paper_u[1], R->paper_u[2], count,
					w->q[0], w->q[1], w->q[2], NULL, NULL, NULL);
				if (r != MK_OK) return r;
				px = w->q[0]; py = w->q[1]; pz = w->q[2];
			} else {
				double tol = o->tol - R->obs_err[2 * i + k] - R->robot_err[k];
				r = boundary3(w, ob, rob, o->impl, (mkBound)k, tol, o->max_points,
					o->mode == MK_CSPACE_UNIFORM ? o->uniform : -1, o->store, &count, &nf, &w->tri2, &w->t2cap, &err);
				if (r != MK_OK) return r;
				double *const *src = k == MK_BOUND_INNER ? w->p : w->o;
				px = src[0]; py = src[1]; pz = src[2];
				if (o->store) {
					int *faces = malloc((size_t)nf * 3 * sizeof(int) + 1);
					if (!faces) return MK_ERR_MEMORY;
					memcpy(faces, w->tri2, (size_t)nf * 3 * sizeof(int));
					R->outs[b].faces = faces;
					R->outs[b].nfaces = nf;
				}
			}
		}
		for (int j = 0; j < count; ++j) sum += px[j] + py[j] + (pz ? pz[j] : 0.0);
		if (o->store) {
			double *xyz = malloc((size_t)count * (size_t)R->dim * sizeof(double) + 1);
			if (!xyz) return MK_ERR_MEMORY;
			for (int j = 0; j < count; ++j) {
				xyz[R->dim * j] = px[j];
				xyz[R->dim * j + 1] = py[j];
				if (R->dim == 3) xyz[3 * j + 2] = pz[j];
			}
			R->outs[b].xyz = xyz;
		}
		R->res->count[b] = count;
		R->res->model_error[b] = R->obs_err[2 * i + k] + R->robot_err[k];
		R->res->error[b] = o->mode == MK_CSPACE_PAPER ? NAN : err + R->res->model_error[b];
		R->res->checksum[b] = sum;
		R->res->seconds[b] = 0.0;
	}
	R->res->seconds[task * R->bounds] = now_s() - t0;
	return MK_OK;
}

/* Paper mode: obstacle i against the orientations of chunk c. The
 * obstacle's half of the batch is computed once (mkKOne*_Init) and the
 * robot's half over `group` orientations per kernel call (mkKOne*_Run);
 * the points are, bit for bit, those of one mkSum*_Batch call per
 * orientation (kernel.h). Each boundary's seconds are the task's wall time
 * shared equally among its orientations. */
static mkResult do_paper_task(Run *R, Work *w, long task)
{
	const mkCSpaceOptions *o = R->opt;
	int c = (int)(task / R->nob), i = (int)(task % R->nob), dim = R->dim;
	int ob = c * R->chunk, oe = ob + R->chunk < R->nor ? ob + R->chunk : R->nor;
	double t0 = now_s();
	int n = dim == 2 ? R->paper_n : R->paper_n * R->paper_n, G = R->group;
	long need = (long)dim * n * (2 + 2 * (long)G);
	if (need > 0x7fffffffL || !grow_d(&w->pb, &w->pbcap, (int)need)) return MK_ERR_MEMORY;
	double *scratch = w->pb + (long)2 * dim * n, *pts = scratch + (long)dim * n * G;
	double *px = pts, *py = pts + (long)n * G, *pz = pts + (long)2 * n * G;
	mkSumOptions so = {MK_SET_CONTACT, o->form, MK_PARAM_SURFACE, o->impl, MK_PRECISION_DOUBLE};
	mkKOne2 one2;
	mkKOne3 one3;
	mkResult r = dim == 2
		? mkKOne2_Init(&one2, R->obs2[2 * i], R->robot2[0].shape, &so, R->paper_u[0], R->paper_u[1], n, w->pb)
		: mkKOne3_Init(&one3, R->obs3[2 * i], R->robot3[0].shape, &so, R->paper_u[0], R->paper_u[1], R->paper_u[2],
			n, w->pb);
	if (r != MK_OK) return r;
	for (int o0 = ob; o0 < oe; o0 += G) {
		int m = oe - o0 < G ? oe - o0 : G;
		if (dim == 2) mkKOne2_Run(&one2, R->poses2 + o0, m, scratch, px, py);
		else mkKOne3_Run(&one3, R->poses3 + o0, m, scratch, px, py, pz);
		/* checksums: each boundary's coordinates summed in order, as do_task
		 * sums them; the m sums are independent chains, advanced together */
		double sums[MK_KONE_POSES];
		for (int k = 0; k < m; ++k) sums[k] = 0.0;
		for (int j = 0; j < n; ++j)
			for (int k = 0; k < m; ++k) {
				long q = (long)k * n + j;
				sums[k] += px[q] + py[q] + (dim == 3 ? pz[q] : 0.0);
			}
		for (int k = 0; k < m; ++k) {
			long b = (long)(o0 + k) * R->nob + i; /* one bound: the inner */
			const double *qx = px + (long)k * n, *qy = py + (long)k * n, *qz = dim == 3 ? pz + (long)k * n : NULL;
			double sum = sums[k];
			if (o->store) {
				double *xyz = malloc((size_t)n * (size_t)dim * sizeof(double) + 1);
				if (!xyz) return MK_ERR_MEMORY;
				for (int j = 0; j < n; ++j) {
					xyz[dim * j] = qx[j];
					xyz[dim * j + 1] = qy[j];
					if (dim == 3) xyz[3 * j + 2] = qz[j];
				}
				R->outs[b].xyz = xyz;
			}
			R->res->count[b] = n;
			R->res->model_error[b] = R->obs_err[2 * i] + R->robot_err[0];
			R->res->error[b] = NAN;
			R->res->checksum[b] = sum;
		}
	}
	double each = (now_s() - t0) / (double)(oe - ob);
	for (int k = ob; k < oe; ++k) R->res->seconds[(long)k * R->nob + i] = each;
	return MK_OK;
}

static void *worker(void *arg)
{
	Run *R = arg;
	Work w;
	memset(&w, 0, sizeof w);
	for (;;) {
		pthread_mutex_lock(&R->lock);
		long t = R->failed ? R->ntasks : R->next_task;
		/* tasks in small blocks: fewer lock round trips, same results */
		long blk = R->ntasks / 4096 > 0 ? 16 : 1;
		R->next_task = t + blk;
		pthread_mutex_unlock(&R->lock);
		if (t >= R->ntasks) break;
		long e = t + blk < R->ntasks ? t + blk : R->ntasks;
		for (; t < e; ++t) {
			mkResult r = R->opt->mode == MK_CSPACE_PAPER ? do_paper_task(R, &w, t) : do_task(R, &w, t);
			if (r != MK_OK) {
				pthread_mutex_lock(&R->lock);
				if (!R->failed) R->failed = r;
				pthread_mutex_unlock(&R->lock);
				break;
			}
		}
	}
	work_free(&w);
	return NULL;
}

void mkCSpaceResult_Free(mkCSpaceResult *r)
{
	if (!r) return;
	free(r->count); free(r->error); free(r->model_error); free(r->seconds); free(r->checksum);
	free(r->first); free(r->x); free(r->y); free(r->z); free(r->face_first); free(r->faces);
	free(r->model_name);
	memset(r, 0, sizeof *r);
}

double mkCSpaceResult_MaxError(const mkCSpaceResult *r)
{
	double m = 0.0;
	long nb = (long)r->obstacles * r->orientations * r->bounds;
	for (long b = 0; b < nb; ++b) {
		if (r->error[b] != r->error[b]) return NAN;
		if (r->error[b] > m) m = r->error[b];
	}
	return m;
}

static void describe2(char *buf, size_t len, const mkSceneBody *d, mkBody2 m)
{
	if (d->kind == MK_SCENE_SMOOTH) snprintf(buf, len, "%s", mkSceneBody_KindName(d));
	else snprintf(buf, len, "%s eps=%.6g", mkShape2_IsEllipse(m.shape) ? "ellipse" : "superellipse", m.shape.eps);
}

static void describe3(char *buf, size_t len, const mkSceneBody *d, mkBody3 m)
{
	if (d->kind == MK_SCENE_SMOOTH) snprintf(buf, len, "%s", mkSceneBody_KindName(d));
	else snprintf(buf, len, "%s eps1=%.6g eps2=%.6g", mkShape3_IsEllipsoid(m.shape) ? "ellipsoid" : "superquadric",
		m.shape.eps1, m.shape.eps2);
}

mkResult mkCSpace_Run(const mkScene *scene, const mkCSpaceOptions *opt, int begin, int end,
	mkCSpaceResult *out, char *msg, size_t msglen)
{
	if (!out) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no result");
	memset(out, 0, sizeof *out);
	if (!scene || !opt || (scene->dim != 2 && scene->dim != 3))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no scene or options");
	if (!(opt->tol > 0.0) || !isfinite(opt->tol))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "tolerance = %g is out of range: must be a positive finite number", opt->tol);
	if (opt->threads < 1 || opt->threads > 1024)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "threads = %d is out of range: must be in [1, 1024]", opt->threads);
	if (begin < 0 || end > scene->orientation_count || begin > end)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "orientations [%d, %d) are out of range: the scene has %d",
			begin, end, scene->orientation_count);
	if (opt->max_points < 8)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "max_points = %d is out of range: must be at least 8", opt->max_points);
	int dim = scene->dim;
	if (opt->mode == MK_CSPACE_UNIFORM
		&& (dim == 2 ? opt->uniform < 4 : (opt->uniform < 0 || opt->uniform > MAX_SPLITS)))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "uniform = %d is out of range: must be %s", opt->uniform,
			dim == 2 ? "at least 4 normals" : "0..10 splits");
	if (opt->mode == MK_CSPACE_PAPER) {
		if (dim == 2 ? opt->uniform < 1 : (opt->uniform < 2 || opt->uniform > 46340))
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "uniform = %d is out of range for the paper's sampling", opt->uniform);
		if (opt->outer) return mkFail(MK_ERR_UNSUPPORTED, msg, msglen, "the paper's sampling gives no outer bound");
		if (opt->form != MK_FORM_NORMAL && opt->form != MK_FORM_GRADIENT)
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "form must be normal or gradient");
	} else if (opt->mode != MK_CSPACE_ADAPTIVE && opt->mode != MK_CSPACE_UNIFORM) {
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "unknown mode %d", (int)opt->mode);
	}
	if (!mkImpl_Available(opt->impl)) return mkFail(MK_ERR_UNSUPPORTED, msg, msglen, "kernel %s is not available", mkImpl_Name(opt->impl));

	Run R;
	memset(&R, 0, sizeof R);
	R.scene = scene; R.opt = opt; R.begin = begin; R.nor = end - begin; R.nob = scene->obstacle_count;
	R.bounds = opt->outer ? 2 : 1; R.dim = dim;
	mkResult r = MK_OK;
	char sub[512];
	int nob = R.nob;
	R.obs_err = calloc((size_t)(2 * nob + 1), sizeof(double));
	if (dim == 2) R.obs2 = calloc((size_t)(2 * nob + 1), sizeof(mkBody2));
	else R.obs3 = calloc((size_t)(2 * nob + 1), sizeof(mkBody3));
	out->model_name = calloc((size_t)nob + 1, sizeof *out->model_name);
	if (!R.obs_err || (!R.obs2 && !R.obs3) || !out->model_name) { r = MK_ERR_MEMORY; goto done; }
	/* models: each box or cylinder gets a budget of T/4 (see the header) */
	double budget = 0.25 * opt->tol;
	for (int k = 0; k < R.bounds; ++k) {
		r = dim == 2 ? mkSceneBody2_Model(&scene->robot, budget, (mkBound)k, &R.robot2[k], &R.robot_err[k], sub, sizeof sub)
			: mkSceneBody3_Model(&scene->robot, budget, (mkBound)k, &R.robot3[k], &R.robot_err[k], sub, sizeof sub);
		if (r != MK_OK) { mkFail(r, msg, msglen, "robot: %s", sub); goto done; }
		for (int i = 0; i < nob; ++i) {
			r = dim == 2 ? mkSceneBody2_Model(&scene->obstacles[i], budget, (mkBound)k, &R.obs2[2 * i + k],
					&R.obs_err[2 * i + k], sub, sizeof sub)
				: mkSceneBody3_Model(&scene->obstacles[i], budget, (mkBound)k, &R.obs3[2 * i + k],
					&R.obs_err[2 * i + k], sub, sizeof sub);
			if (r != MK_OK) { mkFail(r, msg, msglen, "obstacle %d: %s", i, sub); goto done; }
		}
	}
	for (int i = 0; i < nob; ++i) {
		char a[56], b[56] = "";
		if (dim == 2) {
			describe2(a, sizeof a, &scene->obstacles[i], R.obs2[2 * i]);
			if (R.bounds == 2) describe2(b, sizeof b, &scene->obstacles[i], R.obs2[2 * i + 1]);
		} else {
			describe3(a, sizeof a, &scene->obstacles[i], R.obs3[2 * i]);
			if (R.bounds == 2) describe3(b, sizeof b, &scene->obstacles[i], R.obs3[2 * i + 1]);
		}
		if (R.bounds == 2 && scene->obstacles[i].kind != MK_SCENE_SMOOTH)
			snprintf(out->model_name[i], sizeof out->model_name[i], "inner %s; outer %s", a, b);
		else
			snprintf(out->model_name[i], sizeof out->model_name[i], "%s", a);
	}
	if (opt->mode == MK_CSPACE_PAPER) {
		R.paper_n = opt->uniform;
		long np = dim == 2 ? opt->uniform : (long)opt->uniform * opt->uniform;
		for (int d = 0; d < dim; ++d)
			if (!(R.paper_u[d] = malloc((size_t)np * sizeof(double)))) { r = MK_ERR_MEMORY; goto done; }
		if (dim == 2) mkSample2_Angles(opt->uniform, R.paper_u[0], R.paper_u[1]);
		else mkSample3_Grid(opt->uniform, R.paper_u[0], R.paper_u[1], R.paper_u[2]);
		/* the robot's maps, once per orientation (not per obstacle) */
		if (dim == 2) R.poses2 = malloc((size_t)R.nor * sizeof *R.poses2 + 1);
		else R.poses3 = malloc((size_t)R.nor * sizeof *R.poses3 + 1);
		if (dim == 2 ? !R.poses2 : !R.poses3) { r = MK_ERR_MEMORY; goto done; }
		for (int k = 0; k < R.nor; ++k) {
			if (dim == 2) R.poses2[k] = mkMat2_Mul(mkScene2_Orientation(scene, begin + k), R.robot2[0].M);
			else R.poses3[k] = mkMat3_Mul(mkScene3_Orientation(scene, begin + k), R.robot3[0].M);
		}
		/* group: orientations per kernel call, so that group * points is a
		 * multiple of 32 (the widest kernel's block: no padded lanes) and
		 * at least 512; chunk: 16 groups per task, so that the obstacle's
		 * half (once per task) is a small part of it */
		int g0 = 32;
		for (long m = np; g0 > 1 && m % 2 == 0; m /= 2) g0 /= 2;   /* 32 / gcd(np, 32) */
		R.group = np >= 512 ? 1 : g0 * (int)((512 + g0 * np - 1) / (g0 * np));
		if (R.group > MK_KONE_POSES) R.group = MK_KONE_POSES / g0 * g0;
		R.chunk = 16 * R.group < R.nor ? 16 * R.group : (R.nor > 0 ? R.nor : 1);
		R.nchunks = (R.nor + R.chunk - 1) / R.chunk;
	}

	long nb = (long)nob * R.nor * R.bounds;
	out->dim = dim; out->obstacles = nob; out->orientations = R.nor; out->bounds = R.bounds;
	out->orientation_begin = begin;
	out->count = calloc((size_t)nb + 1, sizeof(int));
	out->error = calloc((size_t)nb + 1, sizeof(double));
	out->model_error = calloc((size_t)nb + 1, sizeof(double));
	out->seconds = calloc((size_t)nb + 1, sizeof(double));
	out->checksum = calloc((size_t)nb + 1, sizeof(double));
	if (!out->count || !out->error || !out->model_error || !out->seconds || !out->checksum) { r = MK_ERR_MEMORY; goto done; }
	if (opt->store && !(R.outs = calloc((size_t)nb + 1, sizeof *R.outs))) { r = MK_ERR_MEMORY; goto done; }
	R.res = out;
	R.ntasks = opt->mode == MK_CSPACE_PAPER ? (long)nob * R.nchunks : (long)nob * R.nor;
	pthread_mutex_init(&R.lock, NULL);
	int nth = opt->threads;
	if (nth > R.ntasks) nth = R.ntasks > 0 ? (int)R.ntasks : 1;
	pthread_t th[1024];
	int started = 0;
	for (int t = 1; t < nth; ++t) {
		if (pthread_create(&th[started], NULL, worker, &R) != 0) break;
		++started;
	}
	worker(&R);
	for (int t = 0; t < started; ++t) pthread_join(th[t], NULL);
	pthread_mutex_destroy(&R.lock);
	if (R.failed) { r = (mkResult)R.failed; mkFail(r, msg, msglen, "%s while computing boundaries", mkResult_Name(r)); goto done; }
	if (opt->store) {
		long total = 0, ftotal = 0;
		out->first = malloc((size_t)(nb + 1) * sizeof(long));
		if (dim == 3) out->face_first = malloc((size_t)(nb + 1) * sizeof(long));
		if (!out->first || (dim == 3 && !out->face_first)) { r = MK_ERR_MEMORY; goto done; }
		for (long b = 0; b < nb; ++b) {
			out->first[b] = total;
			total += out->count[b];
			if (dim == 3) { out->face_first[b] = ftotal; ftotal += R.outs[b].nfaces; }
		}
		out->first[nb] = total;
		if (dim == 3) out->face_first[nb] = ftotal;
		out->x = malloc((size_t)total * sizeof(double) + 1);
		out->y = malloc((size_t)total * sizeof(double) + 1);
		if (dim == 3) {
			out->z = malloc((size_t)total * sizeof(double) + 1);
			out->faces = malloc((size_t)ftotal * 3 * sizeof(int) + 1);
		}
		if (!out->x || !out->y || (dim == 3 && (!out->z || !out->faces))) { r = MK_ERR_MEMORY; goto done; }
		for (long b = 0; b < nb; ++b) {
			const double *s = R.outs[b].xyz;
			for (int j = 0; j < out->count[b]; ++j) {
				long q = out->first[b] + j;
				out->x[q] = s[dim * j];
				out->y[q] = s[dim * j + 1];
				if (dim == 3) out->z[q] = s[3 * j + 2];
			}
			if (dim == 3 && R.outs[b].nfaces)
				memcpy(out->faces + 3 * out->face_first[b], R.outs[b].faces, (size_t)R.outs[b].nfaces * 3 * sizeof(int));
		}
	}
done:
	if (R.outs) {
		for (long b = 0; b < (long)nob * R.nor * R.bounds; ++b) { free(R.outs[b].xyz); free(R.outs[b].faces); }
		free(R.outs);
	}
	free(R.obs_err); free(R.obs2); free(R.obs3);
	for (int d = 0; d < 3; ++d) free(R.paper_u[d]);
	free(R.poses2); free(R.poses3);
	if (r != MK_OK) mkCSpaceResult_Free(out);
	return r;
}
