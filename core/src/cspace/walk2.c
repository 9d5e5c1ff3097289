/* walk2.c - the adaptive 2D boundary: greedy walks around the circle of
 * normals, each vertex at about the farthest normal step whose arc the
 * certificate of boundary2.c bounds within the tolerance ("2D adaptive
 * sampling" in docs/scene.md). */
#include "cspace/work.h"

#include <math.h>
#include <string.h>

#include "base/geom_inline.h"

static mkVec2 mkWork_Normal2(const mkCSpaceWork *w, int i) { return mkVec2_Make(w->n[0][i], w->n[1][i]); }
static mkVec2 mkWork_Point2(const mkCSpaceWork *w, int i) { return mkVec2_Make(w->p[0][i], w->p[1][i]); }

#define MK_WALK_STARTS 2        /* walks from different start normals, in lockstep; the fewest vertices win */
#define MK_WALK_K 8             /* candidate steps per walk and round (at most) */
#define MK_WALK_KI 4            /* the same around an estimated reach */
#define MK_WALK_REL 2e-2        /* the reach is bracketed to this relative width */
#define MK_WALK_MAX (0.75 * MK_PI) /* the largest normal step (the proofs need less than 180 degrees) */
#define MK_WALK_LAST 3          /* vertices kept for closing the cycle when max_points is reached */
#define MK_WALK_FORCED (MK_PI / 64.0) /* the least step taken uncertified (no finite error down to MK_CSPACE_MIN_ANGLE) */
#define MK_WALK_RETRIES 8       /* walks restarted with a looser target when max_points would be exceeded */

/* the first round's ladder: the previous step times 2^((k - 3) / 2) */
static const double mkWalk_LadderRatio[MK_WALK_K] = {
	0.35355339059327373, 0.5, 0.70710678118654757, 1.0, 1.4142135623730951, 2.0, 2.8284271247461903, 4.0};

/* One walk around the circle of normals: its start, where it is, and the
 * search for its next step: tol its target, lo the largest step certified
 * within it (its error, normal, point), hi the smallest uncertified step
 * above it, width the bracket's width before the last round, d[0 .. nc) the
 * next candidates. */
typedef struct mkWalk {
	double phi0, phi, guess, maxerr, tol;
	int first, cur, count, done, force; /* force: take the one candidate, certified or not */
	double lo, hi, lo_e, hi_e, width;
	mkVec2 lo_n, lo_p;
	int nc;
	double d[MK_WALK_K];
} mkWalk;

/* The rest of the circle from the walk's vertex, and the largest step. */
static double mkWalk_Cap(const mkWalk *a, int max_points, double *rem)
{
	*rem = a->phi0 + 2.0 * MK_PI - a->phi;
	double cap = *rem < MK_WALK_MAX ? *rem : MK_WALK_MAX;
	if (a->count >= max_points - MK_WALK_LAST && cap > 0.5 * MK_PI) cap = 0.5 * MK_PI;
	return cap;
}

/* The first round of a step towards target tol: a ladder around the
 * previous step, up to the cap. Past max_points - MK_WALK_LAST vertices the
 * walk closes the cycle in at most MK_WALK_LAST + 1 steps of at most 90
 * degrees, certified or not. */
static void mkWalk_Ladder(mkWalk *a, double tol, int max_points)
{
	double rem, cap = mkWalk_Cap(a, max_points, &rem);
	a->tol = tol;
	a->lo = 0.0; a->hi = INFINITY; a->lo_e = a->hi_e = INFINITY; a->width = INFINITY;
	a->nc = 0;
	a->force = a->count >= max_points - MK_WALK_LAST;
	if (a->force) { a->d[a->nc++] = cap; return; }
	for (int k = 0; k < MK_WALK_K; ++k) {
		double t = a->guess * mkWalk_LadderRatio[k];
		if (t >= cap) { a->d[a->nc++] = cap; break; }
		a->d[a->nc++] = t;
	}
}

/* After a round: 1 when the step lo is decided, else the next round's
 * candidates in d. */
static int mkWalk_Next(mkWalk *a, int max_points)
{
	double rem, cap = mkWalk_Cap(a, max_points, &rem);
	if (a->lo == cap) return 1;
	a->nc = 0;
	if (a->lo == 0.0) { /* nothing certified: steps down to MK_CSPACE_MIN_ANGLE */
		if (a->hi <= MK_CSPACE_MIN_ANGLE) {
			if (isfinite(a->hi_e)) {
				/* tol is below the rounding allowance here: the step
				 * starts over with twice the error of the least step
				 * as its target */
				mkWalk_Ladder(a, 2.0 * a->hi_e, max_points);
				return 0;
			}
			/* no finite error at all (NaN points): the previous step
			 * (at least MK_WALK_FORCED), uncertified */
			double t = a->guess > MK_WALK_FORCED ? a->guess : MK_WALK_FORCED;
			a->d[a->nc++] = t < cap ? t : cap;
			a->force = 1;
			return 0;
		}
		for (int k = 0; k < MK_WALK_K; ++k) {
			double t = a->hi * exp2(-2.0 * (k + 1));
			if (t <= MK_CSPACE_MIN_ANGLE) { a->d[a->nc++] = MK_CSPACE_MIN_ANGLE; break; }
			a->d[a->nc++] = t;
		}
		return 0;
	}
	if (a->hi == INFINITY) { /* everything certified: longer steps */
		for (int k = 0; k < MK_WALK_K; ++k) {
			double t = a->lo * exp2(0.5 * (k + 1));
			if (t >= cap) { a->d[a->nc++] = cap; break; }
			a->d[a->nc++] = t;
		}
		return 0;
	}
	double width = a->hi - a->lo;
	if (width <= MK_WALK_REL * a->lo) return 1;
	/* The error as a power of the step through the bracket's ends estimates
	 * the reach; when the bracket at least halved in the last round, the
	 * candidates sit 0.9 MK_WALK_REL lo apart around the estimate, else they
	 * divide the bracket evenly. */
	double est = NAN, h = 0.9 * MK_WALK_REL * a->lo;
	if (a->lo_e > 0.0 && a->hi_e > a->lo_e && isfinite(a->hi_e)) {
		double p = log(a->hi_e / a->lo_e) / log(a->hi / a->lo);
		est = a->lo * pow(a->tol / a->lo_e, 1.0 / p);
	}
	if (est > a->lo && est < a->hi && 2.0 * width <= a->width && MK_WALK_KI * h < width) {
		double t0 = est - 0.5 * (MK_WALK_KI - 1) * h;
		if (t0 <= a->lo) t0 = a->lo + h;
		if (t0 + (MK_WALK_KI - 1) * h >= a->hi) t0 = a->hi - MK_WALK_KI * h;
		for (int k = 0; k < MK_WALK_KI; ++k) a->d[a->nc++] = t0 + k * h;
	} else {
		for (int k = 0; k < MK_WALK_K; ++k) a->d[a->nc++] = a->lo + width * (k + 1) / (MK_WALK_K + 1);
	}
	a->width = width;
	return 0;
}

/* Append a vertex to the node pool; -1 on memory. */
static int mkWalk_Node(mkCSpaceWork *w, int *nv, mkVec2 n, mkVec2 p)
{
	if (!mkCSpaceWork_Verts(w, *nv + 1, 2) || !mkGrow_Ints(&w->next, &w->ncap, *nv + 1) || !mkGrow_Doubles(&w->err2, &w->ecap, *nv + 1))
		return -1;
	int k = (*nv)++;
	w->n[0][k] = n.x; w->n[1][k] = n.y;
	w->p[0][k] = p.x; w->p[1][k] = p.y;
	w->next[k] = k;
	w->err2[k] = NAN;
	return k;
}

/* Start a walk at normal angle phi with first guess `guess` towards target tol. */
static mkResult mkWalk_Start(mkCSpaceWork *w, mkWalk *a, mkBody2 b1, mkBody2 b2, mkImpl impl, double phi, double guess,
	double tol, int max_points, int *nv)
{
	double nx, ny, px, py;
	mkSinCosExact(phi, &nx, &ny);
	mkResult r = mkContact2_Points(b1, b2, impl, &nx, &ny, 1, &px, &py);
	if (r != MK_OK) return r;
	memset(a, 0, sizeof *a);
	a->first = a->cur = mkWalk_Node(w, nv, mkVec2_Make(nx, ny), mkVec2_Make(px, py));
	if (a->first < 0) return MK_ERR_MEMORY;
	a->phi0 = a->phi = phi;
	a->guess = guess;
	a->count = 1;
	mkWalk_Ladder(a, tol, max_points);
	return MK_OK;
}

enum { MK_WALK_LANES = MK_WALK_STARTS * MK_WALK_K };

/* The walks of one boundary and the lanes of a round: every live walk's
 * candidates (normal n, point p), their split normals m and points q (qx
 * holds a lane's error once judged). */
typedef struct mkWalkSet {
	mkWalk wk[MK_WALK_STARTS];
	int nv, nwalk, best, retries, max_points;
	double target;
	mkBody2 b1, b2;
	mkImpl impl;
	mkBound bound;
	double nx[MK_WALK_LANES], ny[MK_WALK_LANES], px[MK_WALK_LANES], py[MK_WALK_LANES];
	double mx[MK_WALK_LANES], my[MK_WALK_LANES], qx[MK_WALK_LANES], qy[MK_WALK_LANES];
} mkWalkSet;

/* One round's two batch calls: the live walks' candidates, then the split
 * normals of their arcs. *nl: the lanes (0: every walk is done). */
static mkResult mkWalkSet_Evaluate(mkCSpaceWork *w, mkWalkSet *s, int *nl)
{
	int n = 0;
	for (int j = 0; j < s->nwalk; ++j)
		if (!s->wk[j].done)
			for (int k = 0; k < s->wk[j].nc; ++k, ++n) mkSinCosExact(s->wk[j].phi + s->wk[j].d[k], &s->nx[n], &s->ny[n]);
	*nl = n;
	if (n == 0) return MK_OK;
	mkResult r = mkContact2_Points(s->b1, s->b2, s->impl, s->nx, s->ny, n, s->px, s->py);
	if (r != MK_OK) return r;
	n = 0;
	for (int j = 0; j < s->nwalk; ++j) {
		mkWalk *a = &s->wk[j];
		if (a->done) continue;
		double rem = a->phi0 + 2.0 * MK_PI - a->phi;
		mkVec2 ni = mkWork_Normal2(w, a->cur), pi = mkWork_Point2(w, a->cur);
		for (int k = 0; k < a->nc; ++k, ++n) {
			if (a->d[k] == rem) { /* the closing arc ends at the first vertex itself */
				s->nx[n] = w->n[0][a->first]; s->ny[n] = w->n[1][a->first];
				s->px[n] = w->p[0][a->first]; s->py[n] = w->p[1][a->first];
			}
			mkVec2 m = mkBoundary2_SplitNormal(ni, mkVec2_Make(s->nx[n], s->ny[n]), pi, mkVec2_Make(s->px[n], s->py[n]));
			s->mx[n] = m.x; s->my[n] = m.y;
		}
	}
	return mkContact2_Points(s->b1, s->b2, s->impl, s->mx, s->my, n, s->qx, s->qy);
}

/* Certify walk a's candidates in lanes l0 .. l0 + nc - 1 and move its
 * bracket; 1 when its step (lo) is decided. */
static int mkWalkSet_Judge(const mkCSpaceWork *w, mkWalkSet *s, mkWalk *a, int l0)
{
	mkVec2 ni = mkWork_Normal2(w, a->cur), pi = mkWork_Point2(w, a->cur);
	for (int k = 0, l = l0; k < a->nc; ++k, ++l) {
		double e = mkBoundary2_EdgeError(s->bound, ni, mkVec2_Make(s->nx[l], s->ny[l]), pi,
			mkVec2_Make(s->px[l], s->py[l]), mkVec2_Make(s->mx[l], s->my[l]), mkVec2_Make(s->qx[l], s->qy[l]));
		s->qx[l] = e; /* the lane's error from here on */
		if (e <= a->tol && a->d[k] > a->lo) {
			a->lo = a->d[k]; a->lo_e = e;
			a->lo_n = mkVec2_Make(s->nx[l], s->ny[l]); a->lo_p = mkVec2_Make(s->px[l], s->py[l]);
		}
	}
	if (!(a->hi > a->lo)) a->hi = INFINITY;
	for (int k = 0, l = l0; k < a->nc; ++k, ++l)
		if (!(s->qx[l] <= a->tol) && a->d[k] > a->lo && a->d[k] < a->hi) { a->hi = a->d[k]; a->hi_e = s->qx[l]; }
	if (a->force) { /* the one candidate, certified or not */
		a->lo = a->d[0]; a->lo_e = s->qx[l0];
		a->lo_n = mkVec2_Make(s->nx[l0], s->ny[l0]); a->lo_p = mkVec2_Make(s->px[l0], s->py[l0]);
		return 1;
	}
	return mkWalk_Next(a, s->max_points);
}

/* Walk j takes its decided step: it closes the cycle, or gets a new vertex
 * (and walk 0's first step starts the other walks inside it). *restart:
 * the walk reached max_points - MK_WALK_LAST vertices and every walk
 * started over with a looser target. */
static mkResult mkWalkSet_Step(mkCSpaceWork *w, mkWalkSet *s, int j, int *restart)
{
	mkWalk *a = &s->wk[j];
	double rem = a->phi0 + 2.0 * MK_PI - a->phi;
	w->err2[a->cur] = a->lo_e;
	if (a->lo_e > a->maxerr || a->lo_e != a->lo_e) a->maxerr = a->lo_e;
	if (a->lo == rem) {
		w->next[a->cur] = a->first;
		a->done = 1;
		if (s->best < 0 || a->count < s->wk[s->best].count) s->best = j;
		return MK_OK;
	}
	int k = mkWalk_Node(w, &s->nv, a->lo_n, a->lo_p);
	if (k < 0) return MK_ERR_MEMORY;
	w->next[a->cur] = k;
	a->cur = k;
	a->phi += a->lo;
	a->guess = a->lo;
	a->count++;
	if (a->count >= s->max_points - MK_WALK_LAST && s->retries < MK_WALK_RETRIES) {
		/* too many vertices: all walks start over, looser */
		double f = (a->phi - a->phi0) / (2.0 * MK_PI), grow = 1.1 / f;
		s->target *= grow * grow > 2.0 ? grow * grow : 2.0;
		++s->retries;
		s->nv = 0; s->nwalk = 1; s->best = -1;
		*restart = 1;
		return mkWalk_Start(w, &s->wk[0], s->b1, s->b2, s->impl, 0.0, MK_PI / 8.0, s->target, s->max_points, &s->nv);
	}
	mkWalk_Ladder(a, s->target, s->max_points);
	if (j == 0 && a->count == 2) /* walk 0's first step is known: the other starts inside it */
		for (; s->nwalk < MK_WALK_STARTS; ++s->nwalk) {
			mkResult r = mkWalk_Start(w, &s->wk[s->nwalk], s->b1, s->b2, s->impl, a->phi * s->nwalk / MK_WALK_STARTS,
				a->guess, s->target, s->max_points, &s->nv);
			if (r != MK_OK) return r;
		}
	return MK_OK;
}

/* The winner's vertices to nodes 0 .. count - 1, in order. */
static mkResult mkWalkSet_Collect(mkCSpaceWork *w, const mkWalk *a, int *count, double *error)
{
	int cnt = a->count;
	if (!mkGrow_Doubles(&w->cp, &w->cpcap, 5 * cnt)) return MK_ERR_MEMORY;
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

/* The adaptive 2D boundary (docs/scene.md, "2D adaptive sampling"): greedy
 * walks around the circle of normals. From each vertex the next is placed
 * at (about) the largest normal step whose arc mkBoundary2_EdgeError certifies within
 * tol (Proofs 1-3, exactly the check of a fixed sampling), found in rounds
 * of MK_WALK_K candidate steps: a ladder around the previous step, then
 * candidates inside the bracket [largest certified, smallest uncertified)
 * until it is MK_WALK_REL wide. Only a candidate whose own certificate is
 * within tol is taken, so the result never relies on the error growing
 * with the step, which the search assumes. The last arc ends at the walk's
 * first vertex. Walk 0 starts at normal angle 0; once its first step s is
 * known, walk j starts at s j / MK_WALK_STARTS (a greedy walk ends with a
 * short arc; another start may save a vertex); the walks share each round's
 * two batch calls. The walk with the fewest vertices wins (the first to
 * finish among equals; a walk is dropped as soon as it cannot beat a
 * finished one), and its vertices move to nodes 0 .. count - 1.
 * Where tol cannot be met (the errors then exceed tol and are reported):
 * when no step down to MK_CSPACE_MIN_ANGLE is certified, the step starts over with
 * twice the error at MK_CSPACE_MIN_ANGLE as its target (tol below the rounding
 * allowance), or, if that error is not finite (NaN points), takes the
 * previous step (at least MK_WALK_FORCED) uncertified; when a walk reaches
 * max_points - MK_WALK_LAST vertices, all walks start over with a target
 * looser by (1.1 / the fraction of the circle covered)^2, at least 2, up to
 * MK_WALK_RETRIES times, and after that close the cycle in steps of at most 90
 * degrees. Results as for fixed normals: nodes 0 .. count - 1 in
 * counter-clockwise order, w->err2[i] the error of the arc from node i to
 * node i + 1 (mod count). Deterministic: the same rounds whatever the
 * thread. */
mkResult mkBoundary2_Walk(mkCSpaceWork *w, mkBody2 b1, mkBody2 b2, mkImpl impl, mkBound bound, double tol,
	int max_points, int *count, double *error)
{
	mkWalkSet s;
	memset(&s, 0, sizeof s);
	s.nwalk = 1; s.best = -1; s.max_points = max_points; s.target = tol;
	s.b1 = b1; s.b2 = b2; s.impl = impl; s.bound = bound;
	mkResult r = mkWalk_Start(w, &s.wk[0], b1, b2, impl, 0.0, MK_PI / 8.0, s.target, max_points, &s.nv);
	if (r != MK_OK) return r;
	for (;;) {
		int nl = 0;
		if ((r = mkWalkSet_Evaluate(w, &s, &nl)) != MK_OK) return r;
		if (nl == 0) break;
		nl = 0;
		int live = s.nwalk, restart = 0;
		for (int j = 0; j < live && !restart; ++j) {
			mkWalk *a = &s.wk[j];
			if (a->done) continue;
			int l0 = nl;
			nl += a->nc;
			if (mkWalkSet_Judge(w, &s, a, l0) && (r = mkWalkSet_Step(w, &s, j, &restart)) != MK_OK) return r;
		}
		for (int j = 0; j < s.nwalk; ++j) /* drop the walks that cannot beat a finished one */
			if (s.best >= 0 && !s.wk[j].done && s.wk[j].count >= s.wk[s.best].count) s.wk[j].done = 1;
	}
	return mkWalkSet_Collect(w, &s.wk[s.best], count, error);
}
