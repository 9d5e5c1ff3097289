/* newton.h - MinkSum (Normal)'s local solver: the maximum of
 *   f(n) = <n, d> - h1(n) - h2(-n)
 * over unit normals n near a start (d = c2 - c1; max f is the signed
 * distance of a separated pair, and on an overlap the largest local maximum
 * is minus the penetration depth). Plain Newton steps with backtracking
 * while they work, a trust region when they do not, an exact line search
 * where the quadratic model keeps failing; pairs of ellipsoids have a Newton
 * loop of their own in 3D with no transcendental function
 * (mkNormal_Ellipsoids). Static definitions, compiled into each build of
 * the solver (normal.h). */
#ifndef MINK_COLLIDE_NEWTON_H
#define MINK_COLLIDE_NEWTON_H

#include "collide/pair.h"
#include "collide/steps.h"

/* Plain Newton steps tried before the trust region takes over. */
#define MK_NEWTON_MAX 12
/* A plain Newton step at most this long (about radians) lands, on most
 * pairs, where the solve ends: there its tests need the residual and the
 * value only (the predicted gain of test (d) is bounded without the
 * Jacobian, see mkNormal_Newton). Such a point is evaluated without the
 * tangent Jacobian (a pass about a fifth cheaper); where it does not end the
 * solve, the Jacobian is formed from its records (mkNormal_Hessian), as for
 * pairs with an ellipsoid. */
#define MK_LIGHT_STEP 3e-4
/* Cuts of a plain Newton step before the trust region takes over. */
#define MK_BACKTRACK 4
/* The shortest cut of a rejected step, as a fraction of it (mkCross); a
 * rejected trust-region step shrinks the radius to between MK_TR_CUT_MIN
 * and 1/2 of its length. */
#define MK_CUT_MIN 0.05
#define MK_TR_CUT_MIN 0.1
/* The accuracy an answer is held to where no tighter test applies (times
 * the scale): the widest bracket the Gilbert fallback accepts, the branch
 * and bound's tolerance on an overlap no start converged on, and how far
 * above the best a centre of the branch and bound restarts Newton. */
#define MK_ANSWER_TOL 1e-10

/* The state at a unit normal n. */
typedef struct mkNormalState {
	mkVec3 n, t1, t2;
	mkPairAt e;      /* supports at n (s1 = e.a1.s) and -n (s2 = e.a2.s) */
	double f;        /* <n, d - x> */
	double g[2];     /* tangential components of d - x */
	double A[3];     /* with hasA: the tangent Jacobian (t1 J t1, t1 J t2, t2 J t2) */
	int hasA;
} mkNormalState;

/* The rest of the state at st->n once st->e and st->f are known: the
 * tangent basis and the tangential gradient. */
static void mkNormal_Complete(const mkPairCtx *c, mkNormalState *st)
{
	mkTangents(st->n, &st->t1, &st->t2);
	mkVec3 r = mkVec3_Sub(c->d, st->e.x);
	st->g[0] = mkVec3_Dot(st->t1, r);
	st->g[1] = mkVec3_Dot(st->t2, r);
	st->hasA = 0;
}

/* The state at the unit normal n = m / len (m the unnormalised trial point
 * of a step, len = |m|; len = 1 for a unit m); for two superquadrics with
 * the tangent Jacobian when hess (formed in the same pass from m itself,
 * mkSupBody_EvalHess2), without it otherwise (then hasA = 0). */
MK_PAIR_INLINE void mkNormal_EvalAt(const mkPairCtx *c, mkVec3 m, double len, mkNormalState *st, int hess)
{
	mkVec3 n = len == 1.0 ? m : mkVec3_Scale(m, 1.0 / len);
	st->n = n;
	if (c->k1.ellipsoid || c->k2.ellipsoid) {
		st->f = mkVec3_Dot(n, c->d) - mkPair_Eval(c, n, &st->e);
		mkNormal_Complete(c, st);
		return;
	}
	mkTangents(n, &st->t1, &st->t2);
	if (hess)
		mkSupBody_EvalHess2(&c->k1, &c->k2, m, len, n, st->t1, st->t2, &st->e.a1, &st->e.a2, st->A, 1);
	else
		mkSupBody_EvalHess2(&c->k1, &c->k2, m, len, n, st->t1, st->t2, &st->e.a1, &st->e.a2, st->A, 0);
	st->hasA = hess;
	st->e.x = mkVec3_Sub(st->e.a1.s, st->e.a2.s);
	st->e.H = mkVec3_Dot(n, st->e.x);
	st->f = mkVec3_Dot(n, c->d) - st->e.H;
	mkVec3 r = mkVec3_Sub(c->d, st->e.x);
	st->g[0] = mkVec3_Dot(st->t1, r);
	st->g[1] = mkVec3_Dot(st->t2, r);
}

static void mkNormal_Eval(const mkPairCtx *c, mkVec3 n, mkNormalState *st)
{
	mkNormal_EvalAt(c, n, 1.0, st, 1);
}

/* Value only, for the trial points of the line searches and the scan. */
static double mkNormal_Value(const mkPairCtx *c, mkVec3 n)
{
	mkPairAt e;
	return mkVec3_Dot(n, c->d) - mkPair_Eval(c, n, &e);
}

/* f along the great circle from n towards the unit tangent e, at
 * m = normalize(n + t e): the value and its derivative in t,
 * <P_m e, d - x(m)> / |n + t e| (P_m the projection orthogonal to m). The
 * best probe's supports are kept, so that the search's answer needs no
 * evaluation of its own. */
typedef struct mkNormalLine {
	const mkPairCtx *c;
	mkVec3 n, e;
	double best;
	mkVec3 mbest;
	mkPairAt at;
} mkNormalLine;

static void mkNormal_LineAt(void *p, double t, double *v, double *dv)
{
	mkNormalLine *L = p;
	mkVec3 y = mkVec3_Add(L->n, mkVec3_Scale(L->e, t));
	double len = mkVec3_LengthInline(y);
	mkVec3 m = mkVec3_Scale(y, 1.0 / len);
	mkPairAt pe;
	double H = mkPair_Eval(L->c, m, &pe);
	mkVec3 r = mkVec3_Sub(L->c->d, pe.x);
	*v = mkVec3_Dot(m, L->c->d) - H;
	*dv = (mkVec3_Dot(L->e, r) - mkVec3_Dot(L->e, m) * mkVec3_Dot(m, r)) / len;
	if (*v > L->best) {
		L->best = *v;
		L->mbest = m;
		L->at = pe;
	}
}

/* Maximise f exactly along the great circle through st->n in the tangent
 * direction e (mkLine_Max): the safeguard where f is too far from quadratic
 * for Newton (near an axis of a body with an exponent well below 1, where
 * the support point crosses a nearly flat face within a tiny change of the
 * normal). st moves to the best point found. Returns 1 when the search
 * converged. */
static int mkNormal_LineSearch(const mkPairCtx *c, mkNormalState *st, mkVec3 e, double h)
{
	double slope = mkVec3_Dot(e, mkVec3_Sub(c->d, st->e.x));
	if (slope == 0.0)
		return 1;
	if (slope < 0.0) {
		e = mkVec3_Neg(e);
		slope = -slope;
	}
	mkNormalLine L;
	L.c = c;
	L.n = st->n;
	L.e = e;
	L.best = st->f;
	int done = mkLine_Max(mkNormal_LineAt, &L, h, st->f, slope, c->scale);
	if (L.best > st->f) {
		st->n = L.mbest;
		st->e = L.at;
		st->f = L.best;
		mkNormal_Complete(c, st);
	}
	return done;
}

static void mkNormal_Hessian(const mkPairCtx *c, mkNormalState *st, double A[2][2])
{
	/* Hessian of -f in the tangent plane: t^T J t + f I. */
	if (st->hasA) {
		A[0][0] = st->A[0];
		A[0][1] = A[1][0] = st->A[1];
		A[1][1] = st->A[2];
	} else
		mkPair_Tangent(c, &st->e, st->t1, st->t2, A);
	A[0][0] += st->f;
	A[1][1] += st->f;
}

/* The slope of f along the great circle normalize(n + u v) at the
 * evaluated point st (st->n = normalize(n + u v), len = |n + u v|): the
 * tangential part of d - x along v, per unit of u. */
static double mkNormal_SlopeAlong(const mkPairCtx *c, const mkNormalState *st, mkVec3 v, double len)
{
	mkVec3 r = mkVec3_Sub(c->d, st->e.x);
	return (mkVec3_Dot(v, r) - mkVec3_Dot(v, st->n) * st->f) / len;
}

/* Where to try next along a step that was rejected at u = t: the point,
 * as a fraction of t, where the tangent lines of f at u = 0 (slope d0 > 0)
 * and at u = t (gain over u = 0, slope dt) cross, kept within
 * [lo, 1/2]; 1/2 when the slope at t is not negative (no crossing ahead of
 * it). Where f is far from quadratic (the support function of a body with
 * a nearly flat face is nearly kinked, and Newton's step overshoots its
 * maximum many times over) the crossing lands near the kink, where
 * halving would need several more trials. */
static double mkCross(double gain, double d0, double dt, double t, double lo)
{
	if (!(dt < 0.0 && d0 > 0.0))
		return 0.5;
	double u = (gain - dt * t) / ((d0 - dt) * t);
	return u < lo ? lo : u > 0.5 ? 0.5 : u;
}

/* Convergence test (d) of a Newton step with predicted gain pred at a
 * point with value f and residual res (|g|): the step cannot be verified,
 * since its gain is below the noise of f (the level under which the
 * step acceptance tests treat gains as rounding), and the witness points'
 * certificate gap |p2 - p1| - |f|, about res^2 / (2 |f|) there, is at most
 * 1e-13 of the scale. The gradient may then be above the tolerance (up
 * to about 1e-7 of the scale): f is converged, evaluating the step would
 * only confirm it. */
static int mkNormal_Settled(double pred, double res, double f, double scale)
{
	return pred <= 64.0 * DBL_EPSILON * (fabs(f) + scale) && res * res <= 2e-13 * scale * fabs(f);
}

/* Solves (C + (beta - f) n n^T) z = g for the tangent-plane Newton step of a
 * pair of ellipsoids in 3D form: C = J1 + J2 + f I has n as an eigenvector
 * (eigenvalue f), so the shifted matrix keeps the tangent plane invariant and
 * is positive definite iff the tangent Hessian is. Returns 0 when it is not
 * (Sylvester's criterion on the shifted matrix). */
static int mkSolveSym3(double C[3][3], mkVec3 g, mkVec3 *z)
{
	double c00 = C[1][1] * C[2][2] - C[1][2] * C[1][2];
	double c01 = C[0][2] * C[1][2] - C[0][1] * C[2][2];
	double c02 = C[0][1] * C[1][2] - C[0][2] * C[1][1];
	double c11 = C[0][0] * C[2][2] - C[0][2] * C[0][2];
	double c12 = C[0][2] * C[0][1] - C[0][0] * C[1][2];
	double c22 = C[0][0] * C[1][1] - C[0][1] * C[0][1];
	double det = C[0][0] * c00 + C[0][1] * c01 + C[0][2] * c02;
	double tr = C[0][0] + C[1][1] + C[2][2];
	if (!(C[0][0] > 0.0 && c22 > 0.0 && det > 1e-12 * tr * tr * tr))
		return 0;
	double inv = 1.0 / det;
	*z = mkVec3_Make((c00 * g.x + c01 * g.y + c02 * g.z) * inv,
		(c01 * g.x + c11 * g.y + c12 * g.z) * inv,
		(c02 * g.x + c12 * g.y + c22 * g.z) * inv);
	return 1;
}

/* Plain Newton for a pair of ellipsoids, all in 3D and in registers: per
 * step two products Q n, two square roots, a 3 x 3 solve. The same tests
 * as mkNormal_Newton (the residual, or an interior step that cannot gain
 * more than 1e-17 of the scale); the first step that fails them (Hessian
 * not positive definite, a step beyond MK_TR_MAX or gaining less than a
 * quarter of its prediction) hands over. Fills st at the last accepted
 * point either way; returns 1 when converged, 0 to hand over (then *radius
 * is the trust radius to continue with). */
static int mkNormal_Ellipsoids(const mkPairCtx *c, mkVec3 n, mkNormalState *st, int *iters, double *res,
	double *radius)
{
	const double (*Q1)[3] = c->k1.Q, (*Q2)[3] = c->k2.Q;
	const mkVec3 d = c->d;
	double tol = MK_COLLIDE3_RESIDUAL_TOL * c->scale;
	mkVec3 v1, v2, s1, s2, gr;
	double h1, h2, f;
	int done = 0;
#define MK_ELL_EVAL(N, V1, V2, S1, S2, H1, H2, F, G) do { \
		V1 = mkVec3_Make(Q1[0][0] * N.x + Q1[0][1] * N.y + Q1[0][2] * N.z, \
			Q1[1][0] * N.x + Q1[1][1] * N.y + Q1[1][2] * N.z, Q1[2][0] * N.x + Q1[2][1] * N.y + Q1[2][2] * N.z); \
		V2 = mkVec3_Make(Q2[0][0] * N.x + Q2[0][1] * N.y + Q2[0][2] * N.z, \
			Q2[1][0] * N.x + Q2[1][1] * N.y + Q2[1][2] * N.z, Q2[2][0] * N.x + Q2[2][1] * N.y + Q2[2][2] * N.z); \
		S1 = mkVec3_Scale(V1, 1.0 / sqrt(mkVec3_Dot(N, V1))); \
		S2 = mkVec3_Scale(V2, -1.0 / sqrt(mkVec3_Dot(N, V2))); \
		H1 = mkVec3_Dot(N, S1); \
		H2 = -mkVec3_Dot(N, S2); \
		mkVec3 r_ = mkVec3_Sub(d, mkVec3_Sub(S1, S2)); \
		F = mkVec3_Dot(N, d) - mkVec3_Dot(N, mkVec3_Sub(S1, S2)); \
		G = mkVec3_Sub(r_, mkVec3_Scale(N, mkVec3_Dot(N, r_))); \
	} while (0)
	MK_ELL_EVAL(n, v1, v2, s1, s2, h1, h2, f, gr);
	for (int it = 0; it < MK_NEWTON_MAX; ++it) {
		*res = sqrt(mkVec3_Dot(gr, gr));
		if (*res <= tol) {
			done = 1;
			break;
		}
		double i1 = 1.0 / h1, i2 = 1.0 / h2, C[3][3];
		double w = h1 + h2 - f; /* the shift: n's eigenvalue becomes h1 + h2 > 0 */
		C[0][0] = (Q1[0][0] - s1.x * s1.x) * i1 + (Q2[0][0] - s2.x * s2.x) * i2 + f + w * n.x * n.x;
		C[1][1] = (Q1[1][1] - s1.y * s1.y) * i1 + (Q2[1][1] - s2.y * s2.y) * i2 + f + w * n.y * n.y;
		C[2][2] = (Q1[2][2] - s1.z * s1.z) * i1 + (Q2[2][2] - s2.z * s2.z) * i2 + f + w * n.z * n.z;
		C[0][1] = C[1][0] = (Q1[0][1] - s1.x * s1.y) * i1 + (Q2[0][1] - s2.x * s2.y) * i2 + w * n.x * n.y;
		C[0][2] = C[2][0] = (Q1[0][2] - s1.x * s1.z) * i1 + (Q2[0][2] - s2.x * s2.z) * i2 + w * n.x * n.z;
		C[1][2] = C[2][1] = (Q1[1][2] - s1.y * s1.z) * i1 + (Q2[1][2] - s2.y * s2.z) * i2 + w * n.y * n.z;
		mkVec3 z;
		if (!mkSolveSym3(C, gr, &z))
			break;
		z = mkVec3_Sub(z, mkVec3_Scale(n, mkVec3_Dot(n, z)));
		double zlen = sqrt(mkVec3_Dot(z, z));
		if (!(zlen <= MK_TR_MAX))
			break;
		*iters += 1;
		double pred = 0.5 * mkVec3_Dot(gr, z);
		if (zlen <= 1e-14 || pred <= 1e-17 * c->scale) {
			/* (test (d) of mkNormal_Settled is not used here: an
			 * ellipsoid evaluation costs little, and the distances stay
			 * within a few ulps of the scale) */
			done = 1;
			break;
		}
		mkVec3 m = mkVec3_Add(n, z);
		m = mkVec3_Scale(m, 1.0 / sqrt(mkVec3_Dot(m, m)));
		mkVec3 w1, w2, q1, q2, gq;
		double k1, k2, fq;
		MK_ELL_EVAL(m, w1, w2, q1, q2, k1, k2, fq, gq);
		double gain = fq - f;
		double noise = 64.0 * DBL_EPSILON * (fabs(f) + c->scale);
		if (!(pred > noise ? gain >= 0.25 * pred : gain >= -noise)) {
			*radius = 0.25 * zlen;
			break;
		}
		n = m; v1 = w1; v2 = w2; s1 = q1; s2 = q2; h1 = k1; h2 = k2; f = fq; gr = gq;
	}
#undef MK_ELL_EVAL
	st->n = n;
	mkTangents(n, &st->t1, &st->t2);
	st->e.a1.s = s1;
	st->e.a1.h = h1;
	st->e.a1.v = v1;
	st->e.a2.s = s2;
	st->e.a2.h = h2;
	st->e.a2.v = mkVec3_Neg(v2);
	st->e.x = mkVec3_Sub(s1, s2);
	st->e.H = mkVec3_Dot(n, st->e.x);
	st->f = f;
	mkVec3 r = mkVec3_Sub(d, st->e.x);
	st->g[0] = mkVec3_Dot(st->t1, r);
	st->g[1] = mkVec3_Dot(st->t2, r);
	st->hasA = 0;
	return done;
}

/* Plain Newton from the evaluated state st, before the trust region: while the tangent Hessian is positive definite,
 * the full step is at most MK_TR_MAX and gains at least a quarter of
 * its prediction, no trust region is needed (the common case: every
 * separated pair of ellipsoids, where the Hessian is at least f I). The
 * first step that fails hands over to the trust region, with a radius
 * that excludes it. A rejected trial is followed by one at the crossing
 * of the tangent lines at its two ends (mkCross), and once a step has
 * been cut, the next one is first tried at the fraction that was
 * accepted (Newton's step keeps overshooting by about the same factor
 * on a nearly kinked support function), the fraction doubling back
 * towards 1 after each step taken as tried.
 * Returns 1 when converged; 0 to hand over, st then at the last accepted
 * point and *radius, after a rejected step, short enough to exclude it. */
MK_PAIR_INLINE int mkNormal_Newton(const mkPairCtx *c, mkNormalState *st, int *iters, double *res, double *radius)
{
	double tol = MK_COLLIDE3_RESIDUAL_TOL * c->scale;
	mkNormalState buf, *cur = st, *nxt = &buf;
	int done = 0;
	double damp = 1.0;
	for (int it = 0; it < MK_NEWTON_MAX; ++it) {
		*res = mkLen2(cur->g[0], cur->g[1]);
		if (*res <= tol) {
			done = 1;
			break;
		}
		if (!cur->hasA && cur->f > 0.0 && mkNormal_Settled(0.5 * *res * *res / cur->f, *res, cur->f, c->scale)) {
			/* A point evaluated without the Jacobian: test (d) with
			 * Newton's predicted gain bounded by |g|^2 / (2 f), since
			 * the Hessian of -f is J + f I with J positive
			 * semidefinite (a separated pair, f > 0). The bound is
			 * above the gain, so the test passes only where the exact
			 * one would (and counts the step as it does). */
			*iters += 1;
			done = 1;
			break;
		}
		double A[2][2];
		mkNormal_Hessian(c, cur, A); /* (formed from the records where the pass did not) */
		double a = A[0][0], b = A[0][1], cc = A[1][1], det = a * cc - b * b;
		if (!(a > 0.0 && det > 1e-12 * (a * cc)))
			break;
		double z0 = (cc * cur->g[0] - b * cur->g[1]) / det, z1 = (a * cur->g[1] - b * cur->g[0]) / det;
		double zlen = mkLen2(z0, z1);
		if (!(zlen <= 1e300))
			break;
		*iters += 1;
		double slope = cur->g[0] * z0 + cur->g[1] * z1; /* g.z > 0: an ascent direction */
		double pred = 0.5 * slope;
		if (zlen <= 1e-14 || pred <= 1e-17 * c->scale || mkNormal_Settled(pred, *res, cur->f, c->scale)) {
			/* The convergence tests (b), (d) of the trust region (mkNormal_Trust). */
			done = 1;
			break;
		}
		/* Backtracking (Armijo) along the Newton direction, the step
		 * first cut to MK_TR_MAX and to the last accepted fraction. */
		double t = zlen > MK_TR_MAX ? MK_TR_MAX / zlen : 1.0;
		t = t < damp ? t : damp;
		double tried = t;
		double noise = 64.0 * DBL_EPSILON * (fabs(cur->f) + c->scale);
		mkVec3 zv = mkVec3_Add(mkVec3_Scale(cur->t1, z0), mkVec3_Scale(cur->t2, z1));
		int taken = 0;
		int hess = zlen > MK_LIGHT_STEP;
		for (int k = 0; k < MK_BACKTRACK; ++k) {
			mkVec3 m = mkVec3_Add(cur->n, mkVec3_Scale(zv, t));
			double len = mkVec3_LengthInline(m);
			mkNormal_EvalAt(c, m, len, nxt, hess);
			double gain = nxt->f - cur->f;
			if (t * slope > noise ? gain >= 1e-4 * t * slope : gain >= -noise) {
				taken = 1;
				break;
			}
			t *= mkCross(gain, slope, mkNormal_SlopeAlong(c, nxt, zv, len), t, MK_CUT_MIN);
		}
		if (!taken) {
			*radius = t * zlen;
			break;
		}
		damp = t < tried ? t : fmin(1.0, 2.0 * t);
		mkNormalState *tmp = cur;
		cur = nxt;
		nxt = tmp;
	}
	if (cur != st)
		*st = *cur;
	return done;
}

/* The trust region from st, until convergence or MK_COLLIDE3_MAX_ITER
 * iterations since *iters was first (the Newton phase's steps count
 * against it), starting with the given radius. Returns 1 on convergence,
 * 2 when stalled in value at a kink (f converged, see below), 0 otherwise;
 * *iters and *res as for mkNormal_Solve. */
MK_PAIR_INLINE int mkNormal_Trust(const mkPairCtx *c, mkNormalState *st, int *iters, double *res, double radius, int first)
{
	double tol = MK_COLLIDE3_RESIDUAL_TOL * c->scale;
	int rejects = 0;
	double hist[3] = { -INFINITY, -INFINITY, -INFINITY };
	for (int it = *iters - first; it < MK_COLLIDE3_MAX_ITER; ++it) {
		hist[it % 3] = st->f;
		*res = mkLen2(st->g[0], st->g[1]);
		if (*res <= tol)
			return 1;
		*iters += 1;
		double A[2][2];
		mkNormal_Hessian(c, st, A);
		double s[2];
		double pred = mkTrustStep(st->g, A, radius, s);
		double slen = mkLen2(s[0], s[1]);
		if (slen < radius && (slen <= 1e-14 || pred <= 1e-17 * c->scale || mkNormal_Settled(pred, *res, st->f, c->scale))) {
			/* (b) An interior Newton step that cannot move the normal by
			 * more than rounding, or gain more than 1e-17 of the scale: the
			 * gradient is at its rounding floor (|Hessian| eps); or (d)
			 * mkNormal_Settled. */
			return 1;
		}
		mkVec3 m = mkVec3_Add(st->n, mkVec3_Add(mkVec3_Scale(st->t1, s[0]), mkVec3_Scale(st->t2, s[1])));
		/* The trial point is evaluated in full: most steps are taken. */
		mkNormalState trial;
		mkNormal_Eval(c, mkVec3_NormalizeInline(m), &trial);
		double gain = trial.f - st->f;
		/* Within rounding of f the ratio means nothing: a step whose
		 * predicted gain is below it is taken when it does not lose. */
		double noise = 64.0 * DBL_EPSILON * (fabs(st->f) + c->scale);
		double rho = pred > noise ? gain / pred : (gain >= -noise ? 1.0 : -1.0);
		if (rho < 0.25) {
			/* to the tangent lines' crossing along the step (mkCross) */
			mkVec3 sv = mkVec3_Add(mkVec3_Scale(st->t1, s[0]), mkVec3_Scale(st->t2, s[1]));
			double d0 = st->g[0] * s[0] + st->g[1] * s[1];
			double d1 = mkNormal_SlopeAlong(c, &trial, sv, mkVec3_LengthInline(m));
			radius = (d1 < 0.0 && d0 > 0.0 ? mkCross(gain, d0, d1, 1.0, MK_TR_CUT_MIN) : 0.25) * slen;
		} else if (rho > 0.75 && slen > 0.99 * radius)
			radius = fmin(2.0 * radius, MK_TR_MAX);
		if (rho > 1e-4) {
			*st = trial;
			rejects = rho < 0.25 ? rejects + 1 : 0;
		} else {
			rejects += 1;
		}
		if (rejects >= 2 || radius < 1e-12 || (it >= MK_LINE_AFTER && rho < 0.75)) {
			/* The quadratic model keeps failing: solve exactly along the
			 * stiffest direction, then check the smooth direction. */
			double lam[2], v0[2], v1[2];
			mkNormal_Hessian(c, st, A);
			mkEig2(A, lam, v0, v1);
			mkVec3 e = mkVec3_Add(mkVec3_Scale(st->t1, v1[0]), mkVec3_Scale(st->t2, v1[1]));
			double before = st->f;
			int tight = mkNormal_LineSearch(c, st, e, fmax(radius, 1e-6));
			int moved = st->f > before;
			mkNormal_Hessian(c, st, A);
			mkEig2(A, lam, v0, v1);
			double flat = fabs(v0[0] * st->g[0] + v0[1] * st->g[1]);
			if (tight && flat <= tol) {
				*res = flat;
				return 1;
			}
			/* Stalled in value: no gain above rounding over the last three
			 * iterations and the exact line search is at its optimum. The
			 * normal is then within rounding of a kink of the support
			 * function; f is converged, the witness points are not
			 * resolved better than the normal (the certificate says how
			 * well). */
			double oldest = fmin(hist[0], fmin(hist[1], hist[2]));
			if (tight && st->f - oldest <= 1e-13 * c->scale && radius < 1e-10) {
				*res = mkLen2(st->g[0], st->g[1]);
				return 2;
			}
			rejects = 0;
			if (moved)
				radius = fmax(radius, 1e-3);
		}
	}
	*res = mkLen2(st->g[0], st->g[1]);
	return *res <= tol;
}

/* Maximise f from n0: Newton (mkNormal_Ellipsoids for two ellipsoids,
 * else mkNormal_Newton), then the trust region where it hands over
 * (mkNormal_Trust). Returns 1 on convergence, 2 when stalled in value at a
 * kink of the support function, 0 otherwise; *iters adds the iterations
 * used; *res receives the residual that decided (the tangential gradient,
 * or its smooth part after a line search). */
static int mkNormal_Solve(const mkPairCtx *c, mkVec3 n0, mkNormalState *st, int *iters, double *res)
{
	double radius = MK_TR_INIT;
	int first = *iters; /* the Newton phase's steps count against MK_COLLIDE3_MAX_ITER */
	if (c->k1.ellipsoid && c->k2.ellipsoid) {
		if (mkNormal_Ellipsoids(c, n0, st, iters, res, &radius))
			return 1;
	} else
		mkNormal_Eval(c, n0, st);
	if (mkNormal_Newton(c, st, iters, res, &radius))
		return 1;
	return mkNormal_Trust(c, st, iters, res, radius, first);
}

#endif
