/* certify.h - MinkSum (Normal)'s certificate of an overlap: a branch and
 * bound over the sphere of normals that proves no normal has f more than a
 * tolerance above the depth found (else climbs the higher maximum it meets,
 * by Newton from there), and gives an upper bound of the signed distance.
 * Static definitions, compiled into each build of the solver (normal.h). */
#ifndef MINK_COLLIDE_CERTIFY_H
#define MINK_COLLIDE_CERTIFY_H

#include "collide/newton.h"

/* The golden ratio (the icosahedron the subdivision starts from). */
#define MK_GOLDEN 1.6180339887498949

/* The depth is min over unit n of h(n) = h_{K-d}(n) = -f(n), the support
 * function of the shifted contact space K - d (which holds the origin in
 * its interior when the bodies overlap). Every evaluated direction c gives
 * a point x = x(c) - d of K - d, and h(n) >= <n, x> for every n.
 *
 * Lipschitz bound: |h(n) - h(m)| <= L |n - m| with L = max |x| over K - d
 * <= R1 + R2 + |d| (R the bodies' radii about their centres; |d| from the
 * shift by the centre line), so over a patch of chord radius rho about c,
 * f <= f(c) + L rho: first order in rho, and L is of the size of the
 * scale. The bound used is the plane <n, x> itself over the patch, a
 * spherical triangle T with unit vertices v0, v1, v2: every n in T is
 * m / |m| with m = sum lambda_i v_i (lambda in the simplex), so
 *     <n, x> = <m, x> / |m| >= min_i <v_i, x> =: b    when b >= 0 (|m| <= 1),
 *     <n, x> >= b / dmin                              when b < 0,
 * dmin the distance of the plane of v0, v1, v2 from the origin (<= |m|).
 * Hence max over T of f <= -(that bound), for any point x of K - d at hand:
 * the triangle's centre's, its parent's centre's, its three siblings'
 * centres' and the best normal's (the largest b wins, the map b -> bound
 * being increasing). Against the true maximum over T it loses about the
 * curvature radius of K at the optimum times the squared size of T, so
 * near the optimum triangles are split down to about sqrt(2 tol /
 * curvature). (A bound from the three vertices' points, second order
 * without a gradient term, was tried: its loss is the largest curvature
 * over T, unbounded near the nearly flat faces of superquadrics with
 * exponents below 1, and it needed more evaluations.)
 * Where a kink of h (a nearly flat face of a body) crosses T, every single
 * plane is below h by a first-order amount on one side of it, and T was
 * split down to edges of about tol / (the jump of the gradient), 2e-7 rad
 * and below. A mixture of two of the planes, w x_k + (1 - w) x_l (w in
 * [0, 1]), is again a lower bound of h (h >= <n, x_k> and >= <n, x_l>),
 * and a mixture of the planes on both sides of a kink follows it; so when
 * no single plane prunes T, the best mixture of each pair that could is
 * tried (mkMix2). (Mixtures of three planes were tried as well: on 500 deep
 * superquadric overlaps they pruned nothing that pairs did not.) */

/* The 12 vertices (unnormalised) and 20 faces of an icosahedron: the
 * first subdivision of the sphere of normals. */
static const double mkIcoV[12][3] = {
	{ -1, MK_GOLDEN, 0 }, { 1, MK_GOLDEN, 0 }, { -1, -MK_GOLDEN, 0 }, { 1, -MK_GOLDEN, 0 },
	{ 0, -1, MK_GOLDEN }, { 0, 1, MK_GOLDEN }, { 0, -1, -MK_GOLDEN }, { 0, 1, -MK_GOLDEN },
	{ MK_GOLDEN, 0, -1 }, { MK_GOLDEN, 0, 1 }, { -MK_GOLDEN, 0, -1 }, { -MK_GOLDEN, 0, 1 }
};
static const unsigned char mkIcoF[20][3] = {
	{ 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 },
	{ 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 },
	{ 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 }
};

/* A spherical triangle of the subdivision and its depth. */
typedef struct mkPatch {
	mkVec3 v[3];     /* unit vertices */
	mkVec3 x;        /* the point x(c) - d of K - d of its centre c */
	double lower;    /* the largest plane value min_i <v_i, x> (the bound of
	                    <n, x> over the triangle when >= 0, else to be
	                    divided by dmin: mkPatch_Lower) of the points of its
	                    centre, its parent's centre and its siblings' centres */
	double a[5][3];  /* <v_i, x_k> of those np points x_k (the mixtures) */
	int np;
	int level;
} mkPatch;

/* min(a0, a1, a2) */
static double mkMin3(const double a[3])
{
	double m = a[1] < a[0] ? a[1] : a[0];
	return a[2] < m ? a[2] : m;
}

/* The best plane value of a mixture of two points: the largest over w in
 * [0, 1] of min_i (w a_i + (1 - w) b_i), a_i, b_i their values <v_i, x> at
 * the three vertices. The minimum of three lines in w is concave, so its
 * largest value is at an end of [0, 1] or where two of the lines cross. */
static double mkMix2(const double a[3], const double b[3])
{
	double best = mkMin3(a), mb = mkMin3(b);
	best = mb > best ? mb : best;
	double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
	for (int i = 0; i < 3; ++i)
		for (int j = i + 1; j < 3; ++j) {
			double den = d[i] - d[j];
			double w = den != 0.0 ? (b[j] - b[i]) / den : -1.0;
			if (!(w > 0.0 && w < 1.0))
				continue;
			double v = INFINITY;
			for (int k = 0; k < 3; ++k) {
				double t = b[k] + w * d[k];
				v = t < v ? t : v;
			}
			best = v > best ? v : best;
		}
	return best;
}

/* A mixture of the points with plane values a and b can reach at most
 * min_i max(a_i, b_i); 1 when that is above need. */
static int mkMix_Could(const double a[3], const double b[3], double need)
{
	return (a[0] > b[0] ? a[0] : b[0]) > need && (a[1] > b[1] ? a[1] : b[1]) > need && (a[2] > b[2] ? a[2] : b[2]) > need;
}

/* The deepest subdivision (edges of about 1.1 / 2^40 radians). */
#define MK_CERT_LEVELS 40

/* The state of a branch and bound. */
typedef struct mkCertRun {
	const mkPairCtx *c;
	mkNormalState *best;
	double *res, tol;
	int *iters, used;
	mkVec3 xs;       /* the best normal's point of K - d */
} mkCertRun;

/* The lower bound of h over the triangle from the largest plane value b
 * min_i <v_i, x> of its points: b when b >= 0, else b / dmin, dmin the
 * distance of the triangle's plane from the origin (a monotone map of b,
 * so the best point gives the best bound). */
static double mkPatch_Lower(const mkPatch *p, double b)
{
	if (b >= 0.0)
		return b;
	mkVec3 nr = mkVec3_Cross(mkVec3_Sub(p->v[1], p->v[0]), mkVec3_Sub(p->v[2], p->v[0]));
	double dmin = fabs(mkVec3_Dot(nr, p->v[0])) / mkVec3_LengthInline(nr);
	return dmin > 0.0 ? b / dmin : -INFINITY;
}

/* Evaluates the centre of each of the n patches (their x) and their lower
 * bounds from those points and xp, then restarts Newton from the best
 * centre when it is more than min(tol, MK_ANSWER_TOL * scale) above
 * the best. Returns 0 on a
 * non-finite evaluation. */
static int mkCert_Centres(mkCertRun *r, mkPatch *p, int n, mkVec3 xp)
{
	int top = -1;
	double ftop = -INFINITY;
	mkVec3 ctop = mkVec3_Make(0.0, 0.0, 0.0);
	for (int k0 = 0; k0 < n; k0 += MK_LANES / 2) {
		int g = n - k0 < MK_LANES / 2 ? n - k0 : MK_LANES / 2;
		mkVec3 cn[MK_LANES / 2];
		mkPairAt e[MK_LANES / 2];
		for (int k = 0; k < g; ++k)
			cn[k] = mkVec3_NormalizeInline(mkVec3_Add(p[k0 + k].v[0], mkVec3_Add(p[k0 + k].v[1], p[k0 + k].v[2])));
		mkPair_EvalN(r->c, g, cn, e);
		for (int k = 0; k < g; ++k) {
			p[k0 + k].x = mkVec3_Sub(e[k].x, r->c->d);
			double f = -mkVec3_Dot(cn[k], p[k0 + k].x);
			if (!(isfinite(f) && mkIsFinite3(p[k0 + k].x)))
				return 0;
			if (f > ftop) {
				ftop = f;
				top = k0 + k;
				ctop = cn[k];
			}
		}
	}
	r->used += n;
	/* each patch's plane values: its own centre's, its parent's centre's
	 * (or the best normal's, for the first patches) and, among four
	 * siblings, the siblings' */
	for (int k = 0; k < n; ++k) {
		mkPatch *q = &p[k];
		q->np = 0;
		for (int j = -1; j < n; ++j)
			if (j < 0 || j == k || n <= 4) {
				mkVec3 x = j < 0 ? xp : p[j].x;
				for (int i = 0; i < 3; ++i)
					q->a[q->np][i] = mkVec3_Dot(q->v[i], x);
				q->np += 1;
			}
		double b = -INFINITY;
		for (int j = 0; j < q->np; ++j) {
			double bj = mkMin3(q->a[j]);
			b = bj > b ? bj : b;
		}
		q->lower = b;
	}
	/* (restarting already at MK_ANSWER_TOL of the scale, below the
	 * certificate's tol: a maximum higher by more than that is climbed,
	 * so that the answer is the highest maximum to that accuracy) */
	if (top >= 0 && ftop > r->best->f + fmin(r->tol, MK_ANSWER_TOL * r->c->scale)) {
		mkNormalState st;
		double r2 = NAN;
		int before = *r->iters;
		mkNormal_Solve(r->c, ctop, &st, r->iters, &r2);
		r->used += *r->iters - before;
		if (st.f > r->best->f) {
			*r->best = st;
			*r->res = r2;
			r->xs = mkVec3_Sub(st.e.x, r->c->d);
		}
	}
	return 1;
}

/* The upper bound of f over a patch from a plane value b: minus the lower
 * bound of h, plus the rounding of the dot products and support points (a
 * few ulps of the scale; a mixture's value adds a few more ulps of the
 * same size). */
static double mkPatch_Bound(const mkPatch *p, double b, double scale)
{
	double B = mkPatch_Lower(p, b);
	return -B + 64.0 * DBL_EPSILON * (fabs(B) + scale);
}

/* The upper bound of f over a patch from its points and the best normal's
 * point xs: the best single plane value, and when that does not bring the
 * bound down to goal, the best mixture of two of the points (tried only
 * when one could: a mixture's value is at most the least over the
 * vertices of the largest plane value there). */
static double mkPatch_Upper(const mkPatch *p, mkVec3 xs, double goal, double scale)
{
	double as[3] = { mkVec3_Dot(p->v[0], xs), mkVec3_Dot(p->v[1], xs), mkVec3_Dot(p->v[2], xs) };
	double b = mkMin3(as);
	b = b > p->lower ? b : p->lower;
	double ub = mkPatch_Bound(p, b, scale);
	if (ub <= goal)
		return ub;
	double env = INFINITY;
	for (int i = 0; i < 3; ++i) {
		double top = as[i];
		for (int k = 0; k < p->np; ++k)
			top = p->a[k][i] > top ? p->a[k][i] : top;
		env = top < env ? top : env;
	}
	if (mkPatch_Bound(p, env, scale) > goal)
		return ub;
	for (int k = 0; k < p->np; ++k) {
		if (mkMix_Could(p->a[k], as, b)) {
			double v = mkMix2(p->a[k], as);
			b = v > b ? v : b;
		}
		for (int j = k + 1; j < p->np; ++j)
			if (mkMix_Could(p->a[k], p->a[j], b)) {
				double v = mkMix2(p->a[k], p->a[j]);
				b = v > b ? v : b;
			}
	}
	return mkPatch_Bound(p, b, scale);
}

/* Branch and bound over the sphere of normals: certifies that no unit n has
 * f(n) > best->f + tol, splitting a triangle in four (at its normalised
 * edge midpoints, depth first) until its bound is at most best->f + tol,
 * and restarting Newton from the best new centre when it is more than tol
 * above the best (replacing *best when it ends higher). *upper receives an
 * upper bound of sd (>= best->f): the largest bound of the pruned
 * triangles, and when the budget (MK_COLLIDE3_CERT_EVALS evaluations:
 * centres and Newton iterations) or the depth MK_CERT_LEVELS runs out
 * first, also of those left unsplit. Returns 1 when every triangle was
 * pruned (*upper <= best->f + tol), 0 when the budget or depth ran out,
 * -1 on a non-finite evaluation (*upper NaN). *evals receives the
 * evaluations used. The computed midpoints lie within a few ulps of their
 * great circles, so the children cover their parent but for slivers that
 * thin, over which f changes by less than the rounding margin added. */
MK_PAIR_INLINE int mkNormal_Certify(const mkPairCtx *c, mkNormalState *best, double *res, int *iters, double tol,
	double *upper, int *evals)
{
	mkPatch stack[20 + 3 * MK_CERT_LEVELS];
	mkCertRun r = { c, best, res, tol, iters, 0, mkVec3_Sub(best->e.x, c->d) };
	double up = -INFINITY;
	int top = 20, done = 1;
	*upper = NAN;
	for (int i = 0; i < 20; ++i) {
		mkPatch *p = &stack[19 - i];
		p->level = 0;
		for (int k = 0; k < 3; ++k) {
			const double *v = mkIcoV[mkIcoF[i][k]];
			p->v[k] = mkVec3_NormalizeInline(mkVec3_Make(v[0], v[1], v[2]));
		}
	}
	if (!mkCert_Centres(&r, stack, 20, r.xs)) {
		*evals = r.used;
		return -1;
	}
	while (top > 0) {
		mkPatch p = stack[--top];
		double ub = mkPatch_Upper(&p, r.xs, best->f + tol, c->scale);
		if (ub <= best->f + tol) {
			up = ub > up ? ub : up;
			continue;
		}
		if (p.level >= MK_CERT_LEVELS || r.used + 4 > MK_COLLIDE3_CERT_EVALS) {
			/* out of budget: the bounds of what is left */
			up = ub > up ? ub : up;
			for (int k = 0; k < top; ++k) {
				double u = mkPatch_Upper(&stack[k], r.xs, best->f + tol, c->scale);
				up = u > up ? u : up;
			}
			done = 0;
			break;
		}
		mkVec3 m01 = mkVec3_NormalizeInline(mkVec3_Add(p.v[0], p.v[1]));
		mkVec3 m12 = mkVec3_NormalizeInline(mkVec3_Add(p.v[1], p.v[2]));
		mkVec3 m20 = mkVec3_NormalizeInline(mkVec3_Add(p.v[2], p.v[0]));
		mkPatch *ch = &stack[top];
		mkVec3 tri[4][3] = { { p.v[0], m01, m20 }, { m01, p.v[1], m12 }, { m20, m12, p.v[2] }, { m01, m12, m20 } };
		for (int k = 0; k < 4; ++k) {
			for (int j = 0; j < 3; ++j)
				ch[k].v[j] = tri[k][j];
			ch[k].level = p.level + 1;
		}
		if (!mkCert_Centres(&r, ch, 4, p.x)) {
			*evals = r.used;
			return -1;
		}
		top += 4;
	}
	*evals = r.used;
	*upper = up > best->f ? up : best->f;
	return done;
}

#endif
