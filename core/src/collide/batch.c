/* batch.c - many pairs per call (mink/batch.h): certificates first, the
 * one-pair query where they do not settle a pair.
 *
 * Before any search, at the centre line: bounds of the support functions
 * and, for two ellipsoids, a few direct steps (batch_quick.h). Then
 * Gilbert's iteration on W = B2 - B1 (mkGilbert_Step) looks for both: a
 * separating direction (f(m) = <m, d> - h1(m) - h2(-m) <= sd, the support
 * values through mkPair_Eval as the solver evaluates them), or a
 * tetrahedron of points of W holding a ball about the origin; where it
 * gives up on an overlap, a point on the centre segment
 * (mkBatch_OverlapPoint). Separated pairs of ellipsoids in the distance
 * mode run Newton's iteration in vector lanes (batch_newton.h). */
#include <mink/batch.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "collide/collision_impl.h"
#include "collide/batch_quick.h"
#include "collide/hull.h"
#include "collide/pair.h"

static const char *const mkBatchModeNames[4] = { "status", "clearance", "distance", "full" };

/* mkCollide3_BatchBracket's mode (no name: not one of mkBatchMode's). */
#define MK_BATCH_BRACKET ((mkBatchMode)4)

const char *mkBatchMode_Name(mkBatchMode mode)
{
	return (int)mode >= 0 && (int)mode < 4 ? mkBatchModeNames[mode] : NULL;
}

int mkBatchMode_FromName(const char *name)
{
	for (int i = 0; name && i < 4; ++i)
		if (strcmp(name, mkBatchModeNames[i]) == 0)
			return i;
	return -1;
}

/* A tetrahedron w[0..4): when it holds the origin, its barycentric weights
 * lam and the radius of the ball about the origin inside it (the least
 * distance to its faces' planes, lam_i times the height over face i);
 * -1 when the origin is outside or the tetrahedron is flat. */
static double mkBatch_Volume(mkVec3 p0, mkVec3 p1, mkVec3 p2, mkVec3 p3)
{
	return mkVec3_Dot(mkVec3_Sub(p1, p0), mkVec3_Cross(mkVec3_Sub(p2, p0), mkVec3_Sub(p3, p0)));
}

static double mkBatch_Inside(const mkVec3 w[4], double lam[4])
{
	double vol = mkBatch_Volume(w[0], w[1], w[2], w[3]);
	if (!(fabs(vol) > 0.0))
		return -1.0;
	double r = INFINITY;
	for (int i = 0; i < 4; ++i) {
		mkVec3 v[4] = { w[0], w[1], w[2], w[3] };
		v[i] = mkVec3_Make(0.0, 0.0, 0.0);
		lam[i] = mkBatch_Volume(v[0], v[1], v[2], v[3]) / vol;
		/* face i: the other three points; its height over w_i is |vol| / (2 area) */
		mkVec3 p = w[(i + 1) & 3], q = w[(i + 2) & 3], t = w[(i + 3) & 3];
		double area2 = mkVec3_LengthInline(mkVec3_Cross(mkVec3_Sub(q, p), mkVec3_Sub(t, p)));
		if (!(lam[i] >= 0.0) || !(area2 > 0.0))
			return -1.0;
		r = fmin(r, lam[i] * fabs(vol) / area2);
	}
	return r;
}

/* Gilbert's iteration on W = B2 - B1 for a certificate (at most
 * MK_BATCH_EVALS pair evaluations from the centre line): the support point
 * of W towards the origin from the least-norm point z of the hull kept,
 * w(m) = c2 + s2(-m) - c1 - s1(m) at m = z / |z|, gives f(m) = <m, w(m)>
 * <= sd; |z| >= sd. It ends in MK_PATH_SEPARATING when f(m) > need (r's n,
 * f, the support points p1, p2 at n and upper, the least |w| met), or when
 * f(m) > margin and |z| < below (a clearance certainly missed);
 * MK_PATH_OVERLAP_POINT when a tetrahedron of W holds the ball of radius
 * depth > margin about the origin (x = sum lam_i a_i = sum lam_i b_i, a
 * point of both bodies); MK_PATH_ONE_PAIR when neither was reached. A
 * state that steps on the pair evaluations it is given, so that several
 * pairs can be evaluated in lock-step (mkBatch_Run). */
typedef struct mkBatchCert {
	mkVec3 n, p1, p2, x;
	double f, upper, depth;
} mkBatchCert;

typedef struct mkGilbert {
	mkPairCtx c;
	mkBatchCert r;
	mkVec3 a[4], b[4], w[4], m;
	double need, below, margin;
	double rel; /* MK_BATCH_BRACKET: the bracket's largest relative width, else 0 */
	int k, evals, pair;
	int common; /* the hull's common point was tried as an overlap point */
} mkGilbert;

static void mkGilbert_Begin(mkGilbert *g, double need, double below)
{
	double dl = mkVec3_LengthInline(g->c.d);
	g->m = dl > 0.0 ? mkVec3_Scale(g->c.d, 1.0 / dl) : mkVec3_Make(0.0, 0.0, 1.0);
	g->k = g->evals = g->common = 0;
	g->need = need;
	g->below = below;
	g->rel = 0.0;
	g->margin = MK_BATCH_MARGIN * g->c.scale;
	g->r.f = -INFINITY;
	g->r.upper = INFINITY;
}

/* Takes the support data of B1 at m (s1) and of B2 at -m (s2). Returns the
 * path when the search is over, else -1 (g->m is the next direction). */
static int mkGilbert_Step(mkGilbert *g, const mkSupAt *s1, const mkSupAt *s2)
{
	mkBatchCert *r = &g->r;
	int k = g->k;
	double lam[4];
	double f = mkVec3_Dot(g->m, g->c.d) - mkVec3_Dot(g->m, mkVec3_Sub(s1->s, s2->s));
	g->a[k] = mkVec3_Add(g->c.b1->t, s1->s);
	g->b[k] = mkVec3_Add(g->c.b2->t, s2->s);
	g->w[k] = mkVec3_Sub(g->b[k], g->a[k]);
	r->upper = fmin(r->upper, mkVec3_LengthInline(g->w[k]));
	if (f > r->f) {
		r->f = f;
		r->n = g->m;
		r->p1 = g->a[k];
		r->p2 = g->b[k];
	}
	if (f > g->need)
		return MK_PATH_SEPARATING;
	if (++k == 4 && (r->depth = mkBatch_Inside(g->w, lam)) >= 0.0) {
		if (!(r->depth > g->margin))
			return MK_PATH_ONE_PAIR;
		r->x = mkVec3_Make(0.0, 0.0, 0.0);
		for (int i = 0; i < 4; ++i)
			r->x = mkVec3_Add(r->x, mkVec3_Scale(mkVec3_Add(g->a[i], g->b[i]), 0.5 * lam[i]));
		return MK_PATH_OVERLAP_POINT;
	}
	mkVec3 z = mkHull_Nearest(g->w, k, lam);
	double zl = mkVec3_LengthInline(z);
	if (zl <= g->margin && !g->common) {
		/* no separation can be certified now (f <= sd <= |z|); sum lam_i a_i and
		 * sum lam_i b_i, points of the two bodies |z| apart, give their mean as
		 * an overlap point (for bodies in a plane the hull may never become a
		 * tetrahedron about the origin) */
		g->common = 1;
		mkVec3 x = mkVec3_Make(0.0, 0.0, 0.0);
		for (int i = 0; i < k; ++i)
			x = mkVec3_Add(x, mkVec3_Scale(mkVec3_Add(g->a[i], g->b[i]), 0.5 * lam[i]));
		if (mkBatch_OverlapAt(g->c.b1, g->c.b2, x, g->margin, &r->depth)) {
			r->x = x;
			return MK_PATH_OVERLAP_POINT;
		}
	}
	int j = 0;
	for (int i = 0; i < k; ++i)
		if (lam[i] > 0.0) {
			g->a[j] = g->a[i];
			g->b[j] = g->b[i];
			g->w[j++] = g->w[i];
		}
	g->k = j;
	r->upper = fmin(r->upper, zl);
	if (r->f > g->margin && (zl < g->below || r->upper - r->f <= g->rel * r->upper))
		return MK_PATH_SEPARATING;
	/* converged (within rounding) short of a certificate, degenerate, or
	 * out of evaluations */
	if (!(zl > 0.0) || !isfinite(zl) || zl - r->f <= 1e-14 * g->c.scale || ++g->evals >= MK_BATCH_EVALS)
		return MK_PATH_ONE_PAIR;
	g->m = mkVec3_Scale(z, 1.0 / zl);
	return -1;
}

/* Writes entry k of out (each array that is not NULL). */
static void mkBatch_Put(const mkBatchOut3 *out, int k, mkContact status, double dist, double lo, double hi, mkVec3 n,
	mkVec3 p1, mkVec3 p2, int clear, mkBatchPath path)
{
	out->status[k] = status;
	if (out->distance)
		out->distance[k] = dist;
	if (out->lower)
		out->lower[k] = lo;
	if (out->upper)
		out->upper[k] = hi;
	if (out->normal)
		out->normal[k] = n;
	if (out->p1)
		out->p1[k] = p1;
	if (out->p2)
		out->p2[k] = p2;
	if (out->clear)
		out->clear[k] = (unsigned char)(clear > 0);
	if (out->path)
		out->path[k] = (unsigned char)path;
}

static void mkBatchStats_Count(mkBatchStats3 *s, mkBatchPath path)
{
	if (!s)
		return;
	s->separating += path == MK_PATH_SEPARATING;
	s->overlap_point += path == MK_PATH_OVERLAP_POINT;
	s->one_pair += path == MK_PATH_ONE_PAIR;
	s->failed += path == MK_PATH_FAILED;
}

/* Pair k answered by the one-pair query (the reference path,
 * mkCollide3_Normal). Returns the path taken. */
static mkBatchPath mkBatch_OnePair(const mkBody3 *b1, const mkBody3 *b2, mkBatchMode mode, double delta,
	const mkBatchOut3 *out, int k)
{
	mkCollision3 c;
	mkResult r = mkCollide3_Normal(*b1, *b2, &c);
	if (r != MK_OK) {
		mkBatch_Put(out, k, MK_CONTACT_UNKNOWN, NAN, NAN, NAN, c.normal, c.p1, c.p2, 0, MK_PATH_FAILED);
		return MK_PATH_FAILED;
	}
	double lo = c.certified == 1 ? c.bound : -INFINITY, hi = c.certified == 1 ? c.bound + c.gap : INFINITY;
	double dist = mode == MK_BATCH_FULL || (mode == MK_BATCH_DISTANCE && c.status != MK_CONTACT_OVERLAPPING)
		? c.distance : NAN;
	mkBatch_Put(out, k, c.status, dist, lo, hi, c.normal, c.p1, c.p2, mode == MK_BATCH_CLEARANCE && c.distance >= delta,
		MK_PATH_ONE_PAIR);
	return MK_PATH_ONE_PAIR;
}

/* The Newton lanes of pairs of ellipsoids in the distance mode
 * (batch_newton.h): pairs wait in the queue until MK_BATCH_NLANES are there
 * (or the searches are over), then run together. A pair first enters from
 * the centre line, before any search (second 0); a lane that does not
 * answer it sends it on to the search (q->retry: the lock-step searches
 * take these first, so that at most one queue's worth waits), and when
 * that finds it separated it enters again from the search's best
 * direction (second 1); leaving then, it goes to the one-pair query. */
typedef void (*mkBatchEllFn)(const mkBatchEllIn *in, mkBatchEllOut *out);
/* Queues of at most this many pairs run on the scalar build (measured: one
 * pair alone took about twice the one-pair query's time in the AVX-512
 * build's sixteen lanes). */
#define MK_BATCH_NEWTON_FEW 4

typedef struct mkBatchEllQueue {
	mkBatchEllIn in;
	const mkBody3 *b1[MK_BATCH_NLANES], *b2[MK_BATCH_NLANES];
	int pair[MK_BATCH_NLANES], second[MK_BATCH_NLANES], count;
	int retry[MK_BATCH_NLANES], nretry; /* pairs sent on to the search */
	mkBatchEllFn fn;
	mkBatchStats3 *stats;
	int *failed;
} mkBatchEllQueue;

static void mkBatchEll_Flush(mkBatchEllQueue *q, mkBatchMode mode, double delta, const mkBatchOut3 *out);

/* Queues pair k of ellipsoids b1, b2 (Q_i = P_i P_i^T, the centre line d,
 * the scale) from the unit start n (second: from a search's direction);
 * runs the queue when it is full. */
static void mkBatchEll_Push(mkBatchEllQueue *q, const mkBody3 *b1, const mkBody3 *b2, double Q1[3][3],
	double Q2[3][3], mkVec3 dv, double scale, int k, mkVec3 n0, int second, mkBatchMode mode, double delta,
	const mkBatchOut3 *out)
{
	int l = q->count++;
	mkBatchEllIn *in = &q->in;
	static const int ix[6][2] = { { 0, 0 }, { 0, 1 }, { 0, 2 }, { 1, 1 }, { 1, 2 }, { 2, 2 } };
	for (int i = 0; i < 6; ++i) {
		in->Q1[i][l] = Q1[ix[i][0]][ix[i][1]];
		in->Q2[i][l] = Q2[ix[i][0]][ix[i][1]];
	}
	const double d[3] = { dv.x, dv.y, dv.z }, n[3] = { n0.x, n0.y, n0.z };
	for (int i = 0; i < 3; ++i) {
		in->d[i][l] = d[i];
		in->n[i][l] = n[i];
	}
	in->scale[l] = scale;
	q->b1[l] = b1;
	q->b2[l] = b2;
	q->pair[l] = k;
	q->second[l] = second;
	if (q->count == MK_BATCH_NLANES)
		mkBatchEll_Flush(q, mode, delta, out);
}

/* Sets up pair k's search (its bodies b1, b2) in g. Returns 1, or 0 when
 * the pair was answered before any search (use_quick: mkBatchQuick_Bound,
 * mkBatchQuick_Ellipsoids; counted in stats->quick) or went to the one-pair query
 * at once (FULL, a scale that is not finite, or DISTANCE on a pair the
 * bounds found separated), *path saying which, or -1 when it went to the
 * Newton lanes q instead (DISTANCE, two ellipsoids, q not NULL). */
static int mkBatch_Begin(mkGilbert *g, const mkBody3 *b1, const mkBody3 *b2, mkBatchMode mode, double delta,
	const mkBatchOut3 *out, int k, mkBatchPath *path, mkBatchEllQueue *q, mkBatchStats3 *stats, int use_quick)
{
	double scale = mkScale(b1, b2);
	if (mode == MK_BATCH_FULL || !isfinite(scale)) {
		*path = mkBatch_OnePair(b1, b2, mode, delta, out, k);
		return 0;
	}
	int ellipsoids = b1->shape.eps1 == 1.0 && b1->shape.eps2 == 1.0 && b2->shape.eps1 == 1.0 && b2->shape.eps2 == 1.0;
	int clearance = mode == MK_BATCH_CLEARANCE, distance = mode == MK_BATCH_DISTANCE, bracket = mode == MK_BATCH_BRACKET;
	double margin = MK_BATCH_MARGIN * scale;
	/* (a bracket: never the first separating direction, only a narrow bracket) */
	double need = clearance ? delta + margin : bracket ? INFINITY : margin;
	double below = clearance ? delta - margin : -INFINITY;
	mkBatchQuick r;
	/* (two ellipsoids in the distance mode only when the Newton lanes sent them on: q NULL) */
	int quick = !use_quick ? -1
		: !ellipsoids ? mkBatchQuick_Bound(b1, b2, need, below, margin, distance, out->p1 || out->p2 || out->upper, &r)
		: !q || !distance ? mkBatchQuick_Ellipsoids(b1, b2, need, below, margin, distance, &r) : -1;
	if (quick >= 0 && distance && r.status == MK_CONTACT_SEPARATED) {
		*path = mkBatch_OnePair(b1, b2, mode, delta, out, k); /* (the search would only have found it separated) */
		return 0;
	}
	if (quick >= 0) {
		mkBatch_Put(out, k, r.status, NAN, r.lower, r.upper, r.n, r.p1, r.p2, r.clear, (mkBatchPath)quick);
		*path = (mkBatchPath)quick;
		if (stats)
			stats->quick += 1;
		return 0;
	}
	if (q && distance && ellipsoids) {
		mkVec3 d = mkVec3_Sub(b2->t, b1->t);
		double dl = mkVec3_LengthInline(d), P[3][3], Q1[3][3], Q2[3][3];
		if (dl > 0.0) {
			mkSupBody_PQ(b1, P, Q1);
			mkSupBody_PQ(b2, P, Q2);
			mkBatchEll_Push(q, b1, b2, Q1, Q2, d, scale, k, mkVec3_Scale(d, 1.0 / dl), 0, mode, delta, out);
			return -1;
		}
	}
	mkPairCtx_InitScaled(&g->c, b1, b2, scale);
	g->pair = k;
	mkGilbert_Begin(g, need, below);
	if (bracket)
		g->rel = delta;
	return 1;
}

/* The answer of a search that ended in p: the certificate's, or the
 * one-pair query's (DISTANCE on a separated pair of superquadrics: the same
 * call as the reference, so the same distance; a separated pair of
 * ellipsoids goes to the Newton lanes, q; an overlap the search did not
 * certify may still have a point on the centre segment). Returns the path
 * taken, or -1 for a pair queued in q (counted when q runs). */
static int mkBatch_Finish(mkGilbert *g, mkBatchPath p, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchEllQueue *q)
{
	const mkBody3 *b1 = g->c.b1, *b2 = g->c.b2;
	mkBatchCert *r = &g->r;
	int k = g->pair;
	double margin = MK_BATCH_MARGIN * g->c.scale;
	if (p == MK_PATH_SEPARATING && mode != MK_BATCH_DISTANCE) {
		mkBatch_Put(out, k, MK_CONTACT_SEPARATED, NAN, r->f, r->upper, r->n, r->p1, r->p2,
			mode == MK_BATCH_CLEARANCE ? r->f > delta + margin : 1, p);
		return p;
	}
	if (p == MK_PATH_SEPARATING && g->c.k1.ellipsoid && g->c.k2.ellipsoid) {
		mkBatchEll_Push(q, b1, b2, g->c.k1.Q, g->c.k2.Q, g->c.d, g->c.scale, k, r->n, 1, mode, delta, out);
		return -1;
	}
	if (p == MK_PATH_SEPARATING) /* started from r->n it was no faster (measured) */
		return mkBatch_OnePair(b1, b2, mode, delta, out, k);
	if (p == MK_PATH_ONE_PAIR && !(r->f > 0.0) && mkBatch_OverlapPoint(b1, b2, g->c.d, margin, &r->x, &r->depth))
		p = MK_PATH_OVERLAP_POINT;
	if (p == MK_PATH_OVERLAP_POINT) {
		mkBatch_Put(out, k, MK_CONTACT_OVERLAPPING, NAN, -INFINITY, -r->depth, mkVec3_Make(NAN, NAN, NAN), r->x, r->x,
			0, p);
		return p;
	}
	return mkBatch_OnePair(b1, b2, mode, delta, out, k);
}

/* Runs the queued pairs and answers each: a lane that converged is
 * answered when f(n) > MK_BATCH_MARGIN * scale (separated) and its
 * certificate closes, lower = f(n) at its normal n (every unit n has
 * f(n) <= sd) and upper = |p2 - p1| for the support points p1 (B1 at n),
 * p2 (B2 at -n), points of the bodies: upper - lower at most
 * MK_BATCH_DISTANCE_GAP of the scale; the distance is f(n), as the one-pair
 * query's. Every other lane leaves: a first entry for the search
 * (q->retry), a second for the one-pair query. */
static void mkBatchEll_Flush(mkBatchEllQueue *q, mkBatchMode mode, double delta, const mkBatchOut3 *out)
{
	int nl = q->count;
	if (nl == 0)
		return;
	mkBatchEllIn *in = &q->in;
	for (int l = nl; l < MK_BATCH_NLANES; ++l) { /* spare lanes: copies of lane 0 */
		for (int i = 0; i < 6; ++i) {
			in->Q1[i][l] = in->Q1[i][0];
			in->Q2[i][l] = in->Q2[i][0];
		}
		for (int i = 0; i < 3; ++i) {
			in->d[i][l] = in->d[i][0];
			in->n[i][l] = in->n[i][0];
		}
		in->scale[l] = in->scale[0];
	}
	mkBatchEllOut r;
	in->count = nl;
	/* a few pairs: the scalar build runs just their lanes (a vector build
	 * would pay for whole vectors; every build gives the same bits) */
	(nl <= MK_BATCH_NEWTON_FEW ? mkBatch_EllipsoidLanesScalar : q->fn)(in, &r);
	const mkBody3 *qb1[MK_BATCH_NLANES], *qb2[MK_BATCH_NLANES];
	int pair[MK_BATCH_NLANES], second[MK_BATCH_NLANES];
	double sc[MK_BATCH_NLANES];
	for (int l = 0; l < nl; ++l) {
		qb1[l] = q->b1[l];
		qb2[l] = q->b2[l];
		pair[l] = q->pair[l];
		second[l] = q->second[l];
		sc[l] = in->scale[l];
	}
	q->count = 0;
	for (int l = 0; l < nl; ++l) {
		const mkBody3 *b1 = qb1[l], *b2 = qb2[l];
		double f = r.f[l], scale = sc[l];
		mkVec3 n = mkVec3_Make(r.n[0][l], r.n[1][l], r.n[2][l]);
		mkVec3 p1 = mkVec3_Add(b1->t, mkVec3_Make(r.s1[0][l], r.s1[1][l], r.s1[2][l]));
		mkVec3 p2 = mkVec3_Add(b2->t, mkVec3_Make(r.s2[0][l], r.s2[1][l], r.s2[2][l]));
		double upper = mkVec3_LengthInline(mkVec3_Sub(p2, p1));
		int path = MK_PATH_SEPARATING;
		if (r.done[l] == 1.0 && f > MK_BATCH_MARGIN * scale && upper - f <= MK_BATCH_DISTANCE_GAP * scale) {
			mkBatch_Put(out, pair[l], mkContact_FromDistance(f, scale), f, f, upper, n, p1, p2, 0, MK_PATH_SEPARATING);
			if (q->stats)
				q->stats->newton += 1;
		} else if (second[l]) {
			path = mkBatch_OnePair(b1, b2, mode, delta, out, pair[l]);
			if (q->stats)
				q->stats->newton_left += 1;
		} else {
			q->retry[q->nretry++] = pair[l];
			continue;
		}
		mkBatchStats_Count(q->stats, (mkBatchPath)path);
		*q->failed += path == MK_PATH_FAILED;
	}
}

/* NULL pointers, negative counts, unknown modes, bad deltas. */
static int mkBatch_ArgsOk(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out)
{
	if (!pairs || !out || !out->status || pairs->count < 0 || (mkBatchMode_Name(mode) == NULL && mode != MK_BATCH_BRACKET))
		return 0;
	if (pairs->count > 0 && (!pairs->bodies1 || !pairs->bodies2))
		return 0;
	if (mode == MK_BATCH_BRACKET)
		return delta > 0.0 && delta < 1.0;
	return mode != MK_BATCH_CLEARANCE || (isfinite(delta) && delta >= 0.0);
}

/* A vector build of the support points (collision_impl.h), or NULL. */
typedef void (*mkBatchLanesFn)(const mkBatchLanesIn *in, double s[3][MK_BATCH_VLANES]);

/* nl <= MK_BATCH_VLANES superquadrics' support points at y[l] by vf (the
 * lanes beyond nl repeat lane 0); the searches use s only. */
static void mkBatch_EvalVector(int nl, const mkSupBody *const b[MK_LANES], const mkVec3 y[MK_LANES],
	mkSupAt *const a[MK_LANES], mkBatchLanesFn vf)
{
	mkBatchLanesIn in;
	double sv[3][MK_BATCH_VLANES];
	for (int l = 0; l < MK_BATCH_VLANES; ++l) {
		int f = l < nl ? l : 0;
		for (int i = 0; i < 9; ++i)
			in.P[i][l] = b[f]->P[i / 3][i % 3];
		in.q1[l] = b[f]->q1;
		in.q2[l] = b[f]->q2;
		in.iq1[l] = b[f]->iq1;
		in.iq2[l] = b[f]->iq2;
		in.y[0][l] = y[f].x;
		in.y[1][l] = y[f].y;
		in.y[2][l] = y[f].z;
	}
	vf(&in, sv);
	for (int l = 0; l < nl; ++l)
		a[l]->s = mkVec3_Make(sv[0][l], sv[1][l], sv[2][l]);
}

/* Searches in lock-step: the superquadric bodies of up to this many pairs'
 * searches are evaluated together (mkSupBody_EvalLanes: their chains of
 * libm calls interleaved, which the processor overlaps; the vector builds
 * MK_LANES at a time). Half as many where some pair has two superquadrics
 * (mkBatch_LockStep). */
#define MK_BATCH_LANES MK_LANES

/* Pair k's bodies. */
static const mkBody3 *mkBatch_Body(const mkBatchPairs3 *pairs, int which, int k)
{
	const int *ix = which ? pairs->index2 : pairs->index1;
	return &(which ? pairs->bodies2 : pairs->bodies1)[ix ? ix[k] : k];
}

/* The pairs searched in lock-step: MK_BATCH_LANES when every pair has an
 * ellipsoid (its support points are computed apart, so that each pair
 * brings one body to the vector lanes), else half as many (measured: on
 * pairs of two superquadrics the wider lock-step was no faster). */
static int mkBatch_LockStep(const mkBatchPairs3 *pairs)
{
	for (int k = 0; k < pairs->count; ++k) {
		mkShape3 s1 = mkBatch_Body(pairs, 0, k)->shape, s2 = mkBatch_Body(pairs, 1, k)->shape;
		if (!(s1.eps1 == 1.0 && s1.eps2 == 1.0) && !(s2.eps1 == 1.0 && s2.eps2 == 1.0))
			return MK_BATCH_LANES / 2;
	}
	return MK_BATCH_LANES;
}

/* The certificates' searches of every pair, mkBatch_LockStep at a time, each
 * lane taking the next pair as its search ends; then each answer
 * (mkBatch_Finish). */
static void mkBatch_Lanes(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchStats3 *stats, int *failed, mkBatchLanesFn vf, mkBatchEllFn ef, int use_quick)
{
	mkBatchEllQueue q;
	q.count = q.nretry = 0;
	q.fn = ef;
	q.stats = stats;
	q.failed = failed;
	mkGilbert g[MK_BATCH_LANES];
	int live[MK_BATCH_LANES] = { 0 }, next = 0, nlive = 0, lanes = mkBatch_LockStep(pairs);
	for (;;) {
		for (int l = 0; l < lanes; ++l)
			while (!live[l] && (q.nretry > 0 || next < pairs->count)) {
				int retry = q.nretry > 0, k = retry ? q.retry[--q.nretry] : next++;
				mkBatchPath p;
				int b = mkBatch_Begin(&g[l], mkBatch_Body(pairs, 0, k), mkBatch_Body(pairs, 1, k), mode, delta, out, k,
					&p, retry ? NULL : &q, stats, use_quick);
				if (b > 0) {
					live[l] = 1;
					++nlive;
				} else if (b == 0) {
					mkBatchStats_Count(stats, p);
					*failed += p == MK_PATH_FAILED;
				}
			}
		if (nlive == 0) { /* (every retry was taken) */
			if (q.count == 0)
				return;
			mkBatchEll_Flush(&q, mode, delta, out);
			continue;
		}
		const mkSupBody *bs[MK_LANES];   /* (at most MK_LANES superquadrics: mkBatch_LockStep) */
		mkVec3 ys[MK_LANES];
		mkSupAt *as[MK_LANES], s[MK_BATCH_LANES][2];
		int nl = 0;
		for (int l = 0; l < lanes; ++l)
			for (int j = 0; live[l] && j < 2; ++j) {
				const mkSupBody *kb = j ? &g[l].c.k2 : &g[l].c.k1;
				mkVec3 y = j ? mkVec3_Neg(g[l].m) : g[l].m;
				if (kb->ellipsoid) {
					mkSupBody_Eval(kb, y, &s[l][j]);
				} else {
					bs[nl] = kb;
					ys[nl] = y;
					as[nl++] = &s[l][j];
				}
			}
		if (nl > 0 && vf)
			mkBatch_EvalVector(nl, bs, ys, as, vf);
		else if (nl > 0)
			mkSupBody_EvalLanes(nl, bs, ys, as);
		for (int l = 0; l < lanes; ++l) {
			int p = live[l] ? mkGilbert_Step(&g[l], &s[l][0], &s[l][1]) : -1;
			if (p < 0)
				continue;
			int a = mkBatch_Finish(&g[l], (mkBatchPath)p, mode, delta, out, &q);
			if (a >= 0) {
				mkBatchStats_Count(stats, (mkBatchPath)a);
				*failed += a == MK_PATH_FAILED;
			}
			live[l] = 0;
			--nlive;
		}
	}
}

/* The vector build for impl (MK_IMPL_AUTO: the widest available); NULL for
 * the scalar support map. */
static mkBatchLanesFn mkBatch_LanesFn(mkImpl impl)
{
#if defined(MINK_HAVE_X86_KERNELS)
	if (impl == MK_IMPL_AUTO)
		impl = mkImpl_Available(MK_IMPL_AVX512) ? MK_IMPL_AVX512 : mkImpl_Available(MK_IMPL_AVX2) ? MK_IMPL_AVX2
			: MK_IMPL_SCALAR;
	if (impl == MK_IMPL_AVX512)
		return mkBatch_SupportLanesAvx512;
	if (impl == MK_IMPL_AVX2)
		return mkBatch_SupportLanesAvx2;
#endif
	(void)impl;
	return NULL;
}

/* The ellipsoids' Newton lanes for impl (as mkBatch_LanesFn; the scalar
 * build where no vector build runs). */
static mkBatchEllFn mkBatch_EllFn(mkImpl impl)
{
#if defined(MINK_HAVE_X86_KERNELS)
	mkBatchLanesFn vf = mkBatch_LanesFn(impl);
	if (vf == mkBatch_SupportLanesAvx512)
		return mkBatch_EllipsoidLanesAvx512;
	if (vf == mkBatch_SupportLanesAvx2)
		return mkBatch_EllipsoidLanesAvx2;
#endif
	(void)impl;
	return mkBatch_EllipsoidLanesScalar;
}

/* Both entries: the certificates first (use_quick: those before any
 * search too), with the lanes of impl (reference = impl >= 0), or the
 * one-pair query alone (reference -1). */
static mkResult mkBatch_Run(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchStats3 *stats, int reference, int use_quick)
{
	if (!mkBatch_ArgsOk(pairs, mode, delta, out))
		return MK_ERR_ARGUMENT;
	if (stats)
		memset(stats, 0, sizeof *stats);
	int failed = 0;
	if (reference >= 0) {
		mkBatch_Lanes(pairs, mode, delta, out, stats, &failed, mkBatch_LanesFn((mkImpl)reference),
			mkBatch_EllFn((mkImpl)reference), use_quick);
		return failed ? MK_ERR_CONVERGENCE : MK_OK;
	}
	for (int k = 0; k < pairs->count; ++k) {
		mkBatchPath p = mkBatch_OnePair(mkBatch_Body(pairs, 0, k), mkBatch_Body(pairs, 1, k), mode, delta, out, k);
		mkBatchStats_Count(stats, p);
		failed += p == MK_PATH_FAILED;
	}
	return failed ? MK_ERR_CONVERGENCE : MK_OK;
}

mkResult mkCollide3_Batch(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchStats3 *stats)
{
	return mkBatch_Run(pairs, mode, delta, out, stats, MK_IMPL_AUTO, 1);
}

mkResult mkCollide3_BatchImpl(mkImpl impl, int quick, const mkBatchPairs3 *pairs, mkBatchMode mode, double delta,
	const mkBatchOut3 *out, mkBatchStats3 *stats)
{
	if ((int)impl < MK_IMPL_AUTO || (int)impl > MK_IMPL_AVX512)
		return MK_ERR_ARGUMENT;
	if (impl != MK_IMPL_AUTO && !mkImpl_Available(impl))
		return MK_ERR_UNSUPPORTED;
	return mkBatch_Run(pairs, mode, delta, out, stats, (int)impl, quick != 0);
}

const char *mkCollide3_BatchLanes(void)
{
	mkBatchLanesFn f = mkBatch_LanesFn(MK_IMPL_AUTO);
#if defined(MINK_HAVE_X86_KERNELS)
	if (f == mkBatch_SupportLanesAvx512)
		return "avx512";
	if (f == mkBatch_SupportLanesAvx2)
		return "avx2";
#endif
	return f ? "vector" : "scalar";
}

mkResult mkCollide3_BatchBracket(const mkBatchPairs3 *pairs, double rel, const mkBatchOut3 *out, mkBatchStats3 *stats)
{
	return mkBatch_Run(pairs, MK_BATCH_BRACKET, rel, out, stats, MK_IMPL_AUTO, 1);
}

mkResult mkCollide3_BatchReference(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchStats3 *stats)
{
	return mkBatch_Run(pairs, mode, delta, out, stats, -1, 0);
}
