/* batch.c - many pairs per call (mink/batch.h): cheap certificates first (a
 * separating direction from support values, an overlap point from the
 * bodies' gauges), the one-pair query where they do not settle a pair.
 *
 * Separating direction: f(n) = <n, d> - h1(n) - h2(-n) is a lower bound of
 * sd at every unit n (the support functions through mkSupBody_Eval, as the
 * solver evaluates them). The centre line is tried first, then the step
 * n <- (d - x(n)) / |d - x(n)| towards d from the contact-space point
 * x(n) = s1(n) - s2(-n) (at the optimum d - x(n) is parallel to n).
 *
 * Overlap point: the gauge g(y) = |(|(y1/a, y2/b)|_p2, y3/c)|_p1 of the
 * canonical body (p = 2/eps: the nested norm whose unit ball it is; pair
 * norms from the ratio of the smaller to the larger component, no
 * overflow) at y = M^-1 (x - t). With u = g < 1, x + (1 - u)(B - t) lies in
 * B, and B - t holds the ball of radius rho = sigma_min(M) / |(1/a, 1/b,
 * 1/c)| (the body holds its cross-polytope, since every p >= 1 norm is at
 * most the l1 norm; sigma_min(M) >= 1 / |M^-1|_F). Balls of radii r1, r2
 * about one point x inside B1 and B2 put the ball of radius r1 + r2 about
 * the origin inside B1 - B2: the depth is at least r1 + r2. The point is on
 * the centre segment, where the two bodies' gauges are linear in the
 * segment's parameter: the end of the common interval that maximises the
 * bound, and the gauges evaluated again at the point itself. */
#include <mink/batch.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "collide/pair.h"

static const char *const mkBatchModeNames[4] = { "status", "clearance", "distance", "full" };

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

/* |(u, v)|_p of u, v >= 0, from the ratio of the smaller to the larger. */
static double mkBatch_PairNorm(double u, double v, double p)
{
	double m = u > v ? u : v, k = u > v ? v : u;
	if (!(m > 0.0))
		return 0.0;
	return m * pow(1.0 + pow(k / m, p), 1.0 / p);
}

/* One body's data for the overlap test. */
typedef struct mkBatchGauge {
	mkMat3 Mi;
	double slack; /* a bound on the relative rounding of g */
	double rho;   /* inradius about the centre */
} mkBatchGauge;

static void mkBatchGauge_Init(mkBatchGauge *g, const mkBody3 *b)
{
	g->Mi = mkMat3_Inverse(b->M);
	double fm = 0.0, fi = 0.0;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			fm += b->M.m[i][j] * b->M.m[i][j];
			fi += g->Mi.m[i][j] * g->Mi.m[i][j];
		}
	const mkShape3 *s = &b->shape;
	double inv = sqrt(1.0 / (s->a * s->a) + 1.0 / (s->b * s->b) + 1.0 / (s->c * s->c));
	g->rho = 1.0 / (sqrt(fi) * inv);
	g->slack = 64.0 * DBL_EPSILON * (1.0 + sqrt(fm * fi));
}

/* The gauge of body b at the point x (rounding slack added). */
static double mkBatchGauge_At(const mkBatchGauge *g, const mkBody3 *b, mkVec3 x)
{
	mkVec3 y = mkMat3_MulVec(g->Mi, mkVec3_Sub(x, b->t));
	const mkShape3 *s = &b->shape;
	double in = mkBatch_PairNorm(fabs(y.x) / s->a, fabs(y.y) / s->b, 2.0 / s->eps2);
	return mkBatch_PairNorm(in, fabs(y.z) / s->c, 2.0 / s->eps1) * (1.0 + g->slack) + g->slack;
}

/* A point of both bodies on the centre segment whose balls inside them add
 * to more than need: 1 and *x, *depth (the certified lower bound of the
 * depth), else 0. */
static int mkBatch_OverlapPoint(const mkBody3 *b1, const mkBody3 *b2, mkVec3 d, double need, mkVec3 *x,
	double *depth)
{
	mkBatchGauge g1, g2;
	mkBatchGauge_Init(&g1, b1);
	mkBatchGauge_Init(&g2, b2);
	double t;
	if (mkVec3_LengthInline(d) == 0.0) {
		t = 0.0;
	} else {
		double u1 = mkBatchGauge_At(&g1, b1, b2->t);   /* g1 at t = 1 */
		double u2 = mkBatchGauge_At(&g2, b2, b1->t);   /* g2 at t = 0 */
		double lo = u2 > 0.0 ? fmax(0.0, 1.0 - 1.0 / u2) : 0.0, hi = u1 > 0.0 ? fmin(1.0, 1.0 / u1) : 1.0;
		if (!(lo < hi))
			return 0;
		/* (1 - t u1) rho1 + (1 - (1 - t) u2) rho2: slope u2 rho2 - u1 rho1 */
		t = u2 * g2.rho - u1 * g1.rho > 0.0 ? hi : lo;
	}
	*x = mkVec3_Add(b1->t, mkVec3_Scale(d, t));
	double v1 = mkBatchGauge_At(&g1, b1, *x), v2 = mkBatchGauge_At(&g2, b2, *x);
	if (!(v1 < 1.0 && v2 < 1.0))
		return 0;
	*depth = (1.0 - v1) * g1.rho + (1.0 - v2) * g2.rho;
	return *depth > need;
}

/* The separating-direction search: at most MK_BATCH_STEPS directions from
 * the centre line. Returns 1 when f(n) > need at the last one; *n, *f, the
 * witnesses *p1, *p2 (support points at n) are those of the best
 * direction met. */
static int mkBatch_Separate(const mkPairCtx *c, double need, mkVec3 *n, double *f, mkVec3 *p1, mkVec3 *p2)
{
	double dl = mkVec3_LengthInline(c->d);
	mkVec3 m = dl > 0.0 ? mkVec3_Scale(c->d, 1.0 / dl) : mkVec3_Make(0.0, 0.0, 1.0);
	*f = -INFINITY;
	for (int k = 0; k < MK_BATCH_STEPS; ++k) {
		mkSupAt a1, a2;
		mkSupBody_Eval(&c->k1, m, &a1);
		mkSupBody_Eval(&c->k2, mkVec3_Neg(m), &a2);
		double fk = mkVec3_Dot(m, c->d) - a1.h - a2.h;
		if (fk > *f) {
			*f = fk;
			*n = m;
			*p1 = mkVec3_Add(c->b1->t, a1.s);
			*p2 = mkVec3_Add(c->b2->t, a2.s);
		}
		if (fk > need)
			return 1;
		mkVec3 z = mkVec3_Sub(c->d, mkVec3_Sub(a1.s, a2.s));
		double zl = mkVec3_LengthInline(z);
		if (!(zl > 0.0) || !isfinite(zl))
			return 0;
		m = mkVec3_Scale(z, 1.0 / zl);
	}
	return 0;
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

/* Pair k answered by the one-pair query (the reference path), from the
 * centre line or from *start (mkCollide3_NormalFrom). Returns the path
 * taken. */
static mkBatchPath mkBatch_OnePair(const mkBody3 *b1, const mkBody3 *b2, const mkVec3 *start, mkBatchMode mode,
	double delta, const mkBatchOut3 *out, int k)
{
	mkCollision3 c;
	mkResult r = start ? mkCollide3_NormalFrom(*b1, *b2, *start, &c) : mkCollide3_Normal(*b1, *b2, &c);
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

/* Pair k by the bounds where they settle it (STATUS, CLEARANCE, DISTANCE's
 * overlaps), else the one-pair query (DISTANCE on a separated pair: started
 * from the separating direction found). */
static mkBatchPath mkBatch_One(const mkBody3 *b1, const mkBody3 *b2, mkBatchMode mode, double delta,
	const mkBatchOut3 *out, int k)
{
	mkPairCtx c;
	mkPairCtx_Init(&c, b1, b2);
	if (mode == MK_BATCH_FULL || !isfinite(c.scale))
		return mkBatch_OnePair(b1, b2, NULL, mode, delta, out, k);
	double margin = MK_BATCH_MARGIN * c.scale, need = mode == MK_BATCH_CLEARANCE ? delta + margin : margin;
	mkVec3 n = mkVec3_Make(NAN, NAN, NAN), p1 = n, p2 = n, x;
	double f = NAN, depth;
	int sep = mkBatch_Separate(&c, need, &n, &f, &p1, &p2);
	double up = mkVec3_LengthInline(mkVec3_Sub(p2, p1));
	if ((mode == MK_BATCH_STATUS && sep) || (mode == MK_BATCH_CLEARANCE && (sep || (f > margin && up < delta - margin)))) {
		mkBatch_Put(out, k, MK_CONTACT_SEPARATED, NAN, f, up, n, p1, p2, sep, MK_PATH_SEPARATING);
		return MK_PATH_SEPARATING;
	}
	if (mode == MK_BATCH_DISTANCE && sep)
		return mkBatch_OnePair(b1, b2, &n, mode, delta, out, k);
	if (!(f > 0.0) && mkBatch_OverlapPoint(b1, b2, c.d, margin, &x, &depth)) {
		mkBatch_Put(out, k, MK_CONTACT_OVERLAPPING, NAN, -INFINITY, -depth, mkVec3_Make(NAN, NAN, NAN), x, x, 0,
			MK_PATH_OVERLAP_POINT);
		return MK_PATH_OVERLAP_POINT;
	}
	return mkBatch_OnePair(b1, b2, NULL, mode, delta, out, k);
}

/* NULL pointers, negative counts, unknown modes, bad deltas. */
static int mkBatch_ArgsOk(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out)
{
	if (!pairs || !out || !out->status || pairs->count < 0 || mkBatchMode_Name(mode) == NULL)
		return 0;
	if (pairs->count > 0 && (!pairs->bodies1 || !pairs->bodies2))
		return 0;
	return mode != MK_BATCH_CLEARANCE || (isfinite(delta) && delta >= 0.0);
}

/* Both entries: the bounds first (reference 0) or the one-pair query alone. */
static mkResult mkBatch_Run(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchStats3 *stats, int reference)
{
	if (!mkBatch_ArgsOk(pairs, mode, delta, out))
		return MK_ERR_ARGUMENT;
	if (stats)
		memset(stats, 0, sizeof *stats);
	int failed = 0;
	for (int k = 0; k < pairs->count; ++k) {
		const mkBody3 *b1 = &pairs->bodies1[pairs->index1 ? pairs->index1[k] : k];
		const mkBody3 *b2 = &pairs->bodies2[pairs->index2 ? pairs->index2[k] : k];
		mkBatchPath p = reference ? mkBatch_OnePair(b1, b2, NULL, mode, delta, out, k) : mkBatch_One(b1, b2, mode, delta, out, k);
		mkBatchStats_Count(stats, p);
		failed += p == MK_PATH_FAILED;
	}
	return failed ? MK_ERR_CONVERGENCE : MK_OK;
}

mkResult mkCollide3_Batch(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchStats3 *stats)
{
	return mkBatch_Run(pairs, mode, delta, out, stats, 0);
}

mkResult mkCollide3_BatchReference(const mkBatchPairs3 *pairs, mkBatchMode mode, double delta, const mkBatchOut3 *out,
	mkBatchStats3 *stats)
{
	return mkBatch_Run(pairs, mode, delta, out, stats, 1);
}
