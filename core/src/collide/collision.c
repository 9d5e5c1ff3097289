/* collision.c - mink/collision.h: MinkSum (Normal) as a trust-region Newton
 * method on the closed-form support map (collision_pair.h), the global
 * certificate of an overlap, and the public helpers of the header; MinkSum
 * (Ray) is in collision_ray.c.
 *
 * MinkSum (Normal) runs plain Newton steps (with backtracking) while they
 * work and a trust region when they do not; ellipsoid pairs have a Newton
 * loop of their own in 3D with no transcendental function (see
 * mkNormal_Ellipsoids). docs/collide.md describes the method. */
#include "collide/collision_pair.h"
#include "collide/collision_impl.h"

/* This file is compiled twice where the processor family allows
 * (core/CMakeLists.txt): as itself, the portable build, and by
 * collision_fma.c with MK_COLLISION_FMA_UNIT defined, for processors with
 * the FMA instruction (-mavx2 -mfma, contraction on). The solver below
 * exists once in each, under its own name (MK_NORMAL_AT); the public
 * helpers at the end and the choice between the two only in the portable
 * one. */
#ifdef MK_COLLISION_FMA_UNIT
#define MK_NORMAL_AT mkCollide3_NormalAtFma
#else
#define MK_NORMAL_AT mkCollide3_NormalAtPortable
#endif

/* Plain Newton steps tried before the trust region takes over. */
#define MK_NEWTON_MAX 12
/* A plain Newton step at most this long (about radians) lands, on most
 * pairs, where the solve ends: there its tests need the residual and the
 * value only (the predicted gain of test (d) is bounded without the
 * Jacobian, see mkNormal_Solve). Such a point is evaluated without the
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
/* The golden ratio (the icosahedron of the overlap certificate). */
#define MK_GOLDEN 1.6180339887498949

/* ---- MinkSum (Normal) --------------------------------------------------- */

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
 * as mkNormal_Solve (the residual, or an interior step that cannot gain
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

/* Maximise f from n0. Returns 1 on convergence, 0 otherwise; *iters adds
 * the iterations used; *res receives the residual that decided (the
 * tangential gradient, or its smooth part after a line search). */
static int mkNormal_Solve(const mkPairCtx *c, mkVec3 n0, mkNormalState *st, int *iters, double *res)
{
	double radius = MK_TR_INIT;
	double tol = MK_COLLIDE3_RESIDUAL_TOL * c->scale;
	int first = *iters; /* the Newton phase's steps count against MK_COLLIDE3_MAX_ITER */
	if (c->k1.ellipsoid && c->k2.ellipsoid) {
		if (mkNormal_Ellipsoids(c, n0, st, iters, res, &radius))
			return 1;
	} else
		mkNormal_Eval(c, n0, st);
	/* Plain Newton first: while the tangent Hessian is positive definite,
	 * the full step is at most MK_TR_MAX and gains at least a quarter of
	 * its prediction, no trust region is needed (the common case: every
	 * separated pair of ellipsoids, where the Hessian is at least f I). The
	 * first step that fails hands over to the trust region, with a radius
	 * that excludes it. A rejected trial is followed by one at the crossing
	 * of the tangent lines at its two ends (mkCross), and once a step has
	 * been cut, the next one is first tried at the fraction that was
	 * accepted (Newton's step keeps overshooting by about the same factor
	 * on a nearly kinked support function), the fraction doubling back
	 * towards 1 after each step taken as tried. */
	{
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
				/* The convergence tests (b), (d) of the trust region below. */
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
				radius = t * zlen;
				break;
			}
			damp = t < tried ? t : fmin(1.0, 2.0 * t);
			mkNormalState *tmp = cur;
			cur = nxt;
			nxt = tmp;
		}
		if (cur != st)
			*st = *cur;
		if (done)
			return 1;
	}
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

/* The point where the segment from b's centre to x crosses b's boundary:
 * t + (x - t) / gauge(x), the gauge Psi^(eps1/2) (homogeneous of degree 1
 * in the body frame). x itself when x is the centre. */
static mkVec3 mkRadial(mkBody3 b, mkVec3 x)
{
	double psi = mkBody3_Implicit(b, x);
	if (!(psi > 0.0))
		return x;
	double gauge = pow(psi, 0.5 * b.shape.eps1);
	return mkVec3_Add(b.t, mkVec3_Scale(mkVec3_Sub(x, b.t), 1.0 / gauge));
}

/* ---- witness points on nearly flat faces ---------------------------------- */

/* Pair evaluations the witness iteration (mkNormal_Hull) may spend. */
#define MK_HULL_EVALS 64
/* The same iteration as the fallback of a separated pair on which Newton
 * did not converge: its budget of pair evaluations and the bracket it aims
 * for (times the scale). */
#define MK_GILBERT_EVALS 2000
#define MK_GILBERT_TOL 1e-12
/* The accuracy an answer is held to where no tighter test applies (times
 * the scale; the 1e-10): the widest bracket the Gilbert fallback
 * accepts, the branch and bound's tolerance on an overlap no start
 * converged on, and how far above the best a centre of the branch and bound
 * restarts Newton. */
#define MK_ANSWER_TOL 1e-10

/* The least-norm point of the convex hull of w[0..k), k <= 4: every subset
 * of one, two or three points is tried (the nearest point of its affine hull
 * by the normal equations), those with nonnegative weights kept, the least
 * norm wins. lam receives the weights (0 outside the winning subset). */
static mkVec3 mkHull_Nearest(const mkVec3 *w, int k, double lam[4])
{
	double bestn = INFINITY;
	mkVec3 best = w[0];
	for (int i = 0; i < 4; ++i)
		lam[i] = i == 0 ? 1.0 : 0.0;
	for (int mask = 1; mask < (1 << k); ++mask) {
		int id[4], n = 0;
		for (int i = 0; i < k; ++i)
			if (mask & (1 << i))
				id[n++] = i;
		if (n > 3)
			continue;
		double mu[3] = { 1.0, 0.0, 0.0 };
		if (n == 2) {
			mkVec3 e = mkVec3_Sub(w[id[1]], w[id[0]]);
			double ee = mkVec3_Dot(e, e);
			if (!(ee > 0.0))
				continue;
			mu[1] = -mkVec3_Dot(e, w[id[0]]) / ee;
			mu[0] = 1.0 - mu[1];
		} else if (n == 3) {
			mkVec3 e1 = mkVec3_Sub(w[id[1]], w[id[0]]), e2 = mkVec3_Sub(w[id[2]], w[id[0]]);
			double a = mkVec3_Dot(e1, e1), b = mkVec3_Dot(e1, e2), c = mkVec3_Dot(e2, e2);
			double r1 = -mkVec3_Dot(e1, w[id[0]]), r2 = -mkVec3_Dot(e2, w[id[0]]);
			double det = a * c - b * b;
			if (!(det > 1e-300 && det > 1e-14 * a * c))
				continue;
			mu[1] = (c * r1 - b * r2) / det;
			mu[2] = (a * r2 - b * r1) / det;
			mu[0] = 1.0 - mu[1] - mu[2];
		}
		if (mu[0] < 0.0 || mu[1] < 0.0 || mu[2] < 0.0)
			continue;
		mkVec3 z = mkVec3_Make(0.0, 0.0, 0.0);
		for (int j = 0; j < n; ++j)
			z = mkVec3_Add(z, mkVec3_Scale(w[id[j]], mu[j]));
		double zn = mkVec3_Dot(z, z);
		if (zn < bestn) {
			bestn = zn;
			best = z;
			for (int i = 0; i < 4; ++i)
				lam[i] = 0.0;
			for (int j = 0; j < n; ++j)
				lam[id[j]] = mu[j];
		}
	}
	return best;
}

/* Gilbert's distance iteration on B2 - B1 from the state st of a
 * separated pair: the support point of B2 - B1 towards the origin from the
 * current least-norm point z (c2 + s2(-m) - c1 - s1(m), m = z / |z|: one
 * pair evaluation) joins the points kept, and the least-norm point of their
 * hull keeps at most three of them. Every z is a point of B2 - B1 (a convex
 * combination of differences of points of the bodies), so |z| >= sd, and
 * every f(m) <= sd. At most budget evaluations; it stops when |z| is within
 * tol of f(m) (improve = 0) or of the largest f met (improve = 1, which then
 * also moves st to the evaluated state of largest f). The weights give a
 * point of each body (their difference is z), each then moved radially onto
 * its boundary; *p1, *p2 are replaced when that pair is closer. Returns the
 * least |z| (the upper bound of sd); *evals receives the evaluations made.
 *
 * Two uses. Witness points of a separated answer whose support points leave
 * a gap (improve = 0): near a nearly flat face the normal does not resolve
 * where on the face the nearest points lie (the support point crosses the
 * face within a rounding change of n); the distance and the normal are left
 * as the solver found them. And the fallback of a separated pair on which
 * Newton did not converge (improve = 1): on a ridge of a nearly kinked
 * support function, where no smooth model fits, the primal iteration still
 * brackets sd (mkCollide3_NormalAt). */
static double mkNormal_Hull(const mkPairCtx *c, mkNormalState *st, int budget, double tol, int improve, mkVec3 *p1,
	mkVec3 *p2, int *evals)
{
	const mkVec3 c1 = c->b1->t, c2 = c->b2->t;
	mkVec3 a[4], b[4], w[4];
	double lam[4] = { 1.0, 0.0, 0.0, 0.0 };
	int k = 1;
	a[0] = mkVec3_Add(c1, st->e.a1.s);
	b[0] = mkVec3_Add(c2, st->e.a2.s);
	w[0] = mkVec3_Sub(b[0], a[0]);
	mkVec3 z = w[0];
	double upper = INFINITY;
	*evals = 0;
	for (int it = 0; it < budget; ++it) {
		double zl = mkVec3_LengthInline(z);
		if (!(zl > 0.0))
			break;
		upper = fmin(upper, zl);
		mkVec3 m = mkVec3_Scale(z, 1.0 / zl);
		mkPairAt e;
		double f = mkVec3_Dot(m, c->d) - mkPair_Eval(c, m, &e); /* <m, wn> up to rounding */
		*evals += 1;
		if (improve && f > st->f) {
			st->n = m;
			st->e = e;
			st->f = f;
			mkNormal_Complete(c, st);
		}
		mkVec3 an = mkVec3_Add(c1, e.a1.s), bn = mkVec3_Add(c2, e.a2.s), wn = mkVec3_Sub(bn, an);
		if (!(zl - (improve ? st->f : f) > tol))
			break;
		a[k] = an;
		b[k] = bn;
		w[k] = wn;
		++k;
		z = mkHull_Nearest(w, k, lam);
		/* keep the points that carry weight */
		int j = 0;
		for (int i = 0; i < k; ++i)
			if (lam[i] > 0.0) {
				a[j] = a[i];
				b[j] = b[i];
				w[j] = w[i];
				lam[j] = lam[i];
				++j;
			}
		k = j;
	}
	mkVec3 q1 = mkVec3_Make(0.0, 0.0, 0.0), q2 = q1;
	for (int i = 0; i < k; ++i) {
		q1 = mkVec3_Add(q1, mkVec3_Scale(a[i], lam[i]));
		q2 = mkVec3_Add(q2, mkVec3_Scale(b[i], lam[i]));
	}
	q1 = mkRadial(*c->b1, q1);
	q2 = mkRadial(*c->b2, q2);
	if (mkIsFinite3(q1) && mkIsFinite3(q2)
		&& mkVec3_LengthInline(mkVec3_Sub(q2, q1)) < mkVec3_LengthInline(mkVec3_Sub(*p2, *p1))) {
		*p1 = q1;
		*p2 = q2;
	}
	return fmin(upper, mkVec3_LengthInline(z));
}

/* ---- the global certificate of an overlap --------------------------------- */

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
static int mkNormal_Certify(const mkPairCtx *c, mkNormalState *best, double *res, int *iters, double tol,
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

/* Extra starts for an overlap: the reversed centre line, the bodies' axis
 * directions (both signs), the diagonals of their frames and a lattice over
 * the sphere; Newton restarts from the best MK_RESTARTS of them by f that
 * are not close (within about 18 degrees) to the answer or to each other.
 * One restart, since the branch and bound below climbs any maximum it meets
 * more than 1e-10 of the scale above the best: on 2 x 10^4 deep overlaps
 * (seeds 99 and 7) no answer was lower than with four restarts, and the
 * evaluations per query fell by about a tenth (superquadrics: median 632 ->
 * 572). Without any, two of 10^4 answers stayed on a lower maximum within
 * the certificate's 1e-8 (by 4e-10 and 4.4e-9 of the scale).
 * For superquadrics f is evaluated at the structured candidates and at
 * the MK_SCAN_EXACT lattice points that rank best on the ellipsoids of the
 * same axes. */
enum { MK_FIB = 64, MK_CAND = 29 + MK_FIB, MK_RESTARTS = 1, MK_SCAN_EXACT = 16 };

/* The query from the centre line (start NULL) or from a given start. */
mkResult MK_NORMAL_AT(mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out)
{
	mkCollision3_Clear(out);
	mkPairCtx c;
	if (mkPairCtx_Begin(&c, &b1, &b2, out) != MK_OK)
		return MK_ERR_UNSUPPORTED;
	double dl = mkVec3_LengthInline(c.d);
	mkVec3 n0 = dl > 0.0 ? mkVec3_Scale(c.d, 1.0 / dl) : mkVec3_Make(0.0, 0.0, 1.0);
	mkNormalState best;
	int iters = 0;
	double res = NAN, res2 = NAN;
	int ok = mkNormal_Solve(&c, start ? *start : n0, &best, &iters, &res);
	int stalled = ok == 2;
	out->restarts = 0;
	if (start && !(ok && best.f > 0.0)) {
		/* The given start did not end at a separation (an overlap, or a start
		 * that did not converge): the centre line as without one, counted as
		 * a restart. */
		mkNormalState st;
		int ok2 = mkNormal_Solve(&c, n0, &st, &iters, &res2);
		out->restarts += 1;
		if (ok2 && (!ok || st.f > best.f)) {
			best = st;
			res = res2;
			ok = 1;
			stalled = ok2 == 2;
		}
	}
	/* A separated pair (f > 0 bounds sd from below) on which Newton did not
	 * converge, or stopped on a stalled value, on a ridge of a nearly kinked
	 * support function: Gilbert's iteration brackets sd between the largest
	 * f it meets and the least |z| (mkNormal_Hull), and the answer stands
	 * when the bracket is within MK_ANSWER_TOL of the scale; the
	 * residual reported is then the bracket's width. */
	int gilbert = 0;
	mkVec3 gp1 = mkVec3_Make(NAN, NAN, NAN), gp2 = gp1;
	if ((!ok || stalled) && isfinite(best.f) && best.f > 0.0) {
		gp1 = mkVec3_Add(b1.t, best.e.a1.s);
		gp2 = mkVec3_Add(b2.t, best.e.a2.s);
		int evals;
		double up = mkNormal_Hull(&c, &best, MK_GILBERT_EVALS, MK_GILBERT_TOL * c.scale, 1, &gp1, &gp2, &evals);
		iters += evals;
		if (up - best.f <= MK_ANSWER_TOL * c.scale) {
			ok = 1;
			gilbert = 1;
			res = up - best.f;
		}
	}
	if (!(ok && best.f > 0.0)) {
		/* Overlap (or a failed start): f may have several local maxima on the
		 * sphere. Evaluate f at the candidate directions, restart from the
		 * best few not already near the answer, keep the best converged. */
		mkVec3 cand[MK_CAND];
		double val[MK_CAND];
		int nc = 0;
		cand[nc++] = mkVec3_Neg(n0);
		for (int k = 0; k < 2; ++k) {
			mkMat3 M = k == 0 ? b1.M : b2.M;
			mkVec3 col[3];
			for (int j = 0; j < 3; ++j) {
				col[j] = mkVec3_NormalizeInline(mkVec3_Make(M.m[0][j], M.m[1][j], M.m[2][j]));
				cand[nc++] = col[j];
				cand[nc++] = mkVec3_Neg(col[j]);
			}
			/* and the eight diagonals of the body's frame */
			for (int q = 0; q < 8; ++q)
				cand[nc++] = mkVec3_NormalizeInline(mkVec3_Add(mkVec3_Scale(col[0], q & 1 ? -1.0 : 1.0),
					mkVec3_Add(mkVec3_Scale(col[1], q & 2 ? -1.0 : 1.0), mkVec3_Scale(col[2], q & 4 ? -1.0 : 1.0))));
		}
		/* and a Fibonacci lattice of MK_FIB directions over the sphere */
		/* (the angle q times the golden angle by rotation, not 64 sincos) */
		double cg = cos(2.399963229728653), sg = sin(2.399963229728653), ca = 1.0, sa = 0.0;
		for (int q = 0; q < MK_FIB; ++q) {
			double z = 1.0 - (2.0 * q + 1.0) / MK_FIB, r = sqrt(1.0 - z * z);
			cand[nc++] = mkVec3_Make(r * ca, r * sa, z);
			double cn = ca * cg - sa * sg;
			sa = sa * cg + ca * sg;
			ca = cn;
		}
		if (c.k1.ellipsoid && c.k2.ellipsoid) {
			for (int i = 0; i < nc; ++i)
				val[i] = mkIsFinite3(cand[i]) ? mkNormal_Value(&c, cand[i]) : -INFINITY;
		} else {
			/* Superquadrics: f exactly at the structured candidates (the
			 * reversed centre line, axes and diagonals: where box-like
			 * bodies have their optima), and at the MK_SCAN_EXACT lattice
			 * points that rank best by f of the ellipsoids with the same
			 * axes and maps (a square root per body instead of eight
			 * transcendental functions). */
			mkPairCtx e = c;
			mkBody3 p1 = b1, p2 = b2;
			p1.shape.eps1 = p1.shape.eps2 = p2.shape.eps1 = p2.shape.eps2 = 1.0;
			mkSupBody_Init(&e.k1, &p1);
			mkSupBody_Init(&e.k2, &p2);
			double proxy[MK_CAND], sorted[MK_CAND];
			for (int i = 0; i < nc; ++i)
				sorted[i] = proxy[i] = mkIsFinite3(cand[i]) ? mkNormal_Value(&e, cand[i]) : -INFINITY;
			/* the MK_SCAN_EXACT-th largest proxy value (partial selection) */
			for (int a = 0; a < MK_SCAN_EXACT; ++a) {
				int bi = a;
				for (int j = a + 1; j < nc; ++j)
					if (sorted[j] > sorted[bi])
						bi = j;
				double x = sorted[a];
				sorted[a] = sorted[bi];
				sorted[bi] = x;
			}
			double cut = sorted[MK_SCAN_EXACT - 1];
			for (int i = 0; i < nc; ++i)
				val[i] = (i < MK_CAND - MK_FIB || proxy[i] >= cut) && proxy[i] > -INFINITY ? mkNormal_Value(&c, cand[i])
					: -INFINITY;
		}
		mkVec3 picked[MK_RESTARTS];
		int npicked = 0;
		for (int r = 0; r < MK_RESTARTS; ++r) {
			int pick = -1;
			for (int i = 0; i < nc; ++i) {
				if (!(val[i] > -INFINITY))
					continue;
				if (ok && mkVec3_Dot(cand[i], best.n) > 0.99)
					continue;
				int near = 0;
				for (int q = 0; q < npicked; ++q)
					near |= mkVec3_Dot(cand[i], picked[q]) > 0.95;
				if (near)
					continue;
				if (pick < 0 || val[i] > val[pick])
					pick = i;
			}
			if (pick < 0)
				break;
			val[pick] = -INFINITY;
			picked[npicked++] = cand[pick];
			mkNormalState st;
			int ok2 = mkNormal_Solve(&c, cand[pick], &st, &iters, &res2);
			out->restarts += 1;
			if (ok2 && (!ok || st.f > best.f)) {
				best = st;
				res = res2;
				ok = 1;
				stalled = ok2 == 2;
			}
		}
	}
	double upper = NAN;
	int certified = 1;
	if (isfinite(best.f) && best.f <= 0.0 && mkIsFinite3(best.n)) {
		/* Overlap (or touching): the depth certified global, or said not to
		 * be. When no start converged (a ridge of a nearly kinked support
		 * function), the branch and bound runs from the best state met at
		 * the tighter MK_ANSWER_TOL (its restarts climb the ridge), and
		 * the answer stands only when it completes; the residual reported
		 * is then the width of its bracket. */
		int evals = 0;
		int done = mkNormal_Certify(&c, &best, &res, &iters,
			(ok ? MK_COLLIDE3_GLOBAL_TOL : MK_ANSWER_TOL) * c.scale, &upper, &evals) == 1;
		out->cert_evals = evals;
		if (ok)
			certified = done;
		else if (done) {
			ok = 1;
			res = upper - best.f;
		}
	}
	out->iterations = iters;
	out->normal = best.n;
	out->bound = best.f;
	out->p1 = mkVec3_Add(b1.t, best.e.a1.s);
	out->p2 = mkVec3_Add(b2.t, best.e.a2.s);
	if (gilbert && mkIsFinite3(gp1) && mkIsFinite3(gp2)
		&& mkVec3_LengthInline(mkVec3_Sub(gp2, gp1)) < mkVec3_LengthInline(mkVec3_Sub(out->p2, out->p1))) {
		/* the fallback's hull already placed them on the faces */
		out->p1 = gp1;
		out->p2 = gp2;
	}
	out->residual = res / c.scale;
	if (!ok || !isfinite(best.f) || !mkIsFinite3(out->p1) || !mkIsFinite3(out->p2))
		return MK_ERR_CONVERGENCE;
	out->distance = best.f;
	double span = mkVec3_LengthInline(mkVec3_Sub(out->p2, out->p1));
	if (best.f > 0.0 && span - best.f > MK_COLLIDE3_TOUCH_TOL * c.scale) {
		/* Near a kink the support points are not resolved by the normal
		 * (a nearly flat face is crossed within rounding of n). Tighter
		 * witnesses: each support point moved by -/+ f n to the other
		 * body's supporting plane, then radially onto that body. */
		mkVec3 q1 = mkRadial(b1, mkVec3_Sub(out->p2, mkVec3_Scale(best.n, best.f)));
		mkVec3 q2 = mkRadial(b2, mkVec3_Add(out->p1, mkVec3_Scale(best.n, best.f)));
		double s1 = mkVec3_LengthInline(mkVec3_Sub(out->p2, q1)), s2 = mkVec3_LengthInline(mkVec3_Sub(q2, out->p1));
		if (s1 < span && s1 <= s2) {
			out->p1 = q1;
			span = s1;
		} else if (s2 < span) {
			out->p2 = q2;
			span = s2;
		}
		if (span - best.f > MK_COLLIDE3_TOUCH_TOL * c.scale) {
			/* still apart: where on the face, by the hull of support points */
			int evals;
			mkNormal_Hull(&c, &best, MK_HULL_EVALS, 1e-13 * c.scale, 0, &out->p1, &out->p2, &evals);
			span = mkVec3_LengthInline(mkVec3_Sub(out->p2, out->p1));
		}
	}
	if (best.f > 0.0) {
		out->gap = span - best.f;
		out->certified = 1;
	} else {
		out->gap = upper - best.f;
		out->certified = certified;
	}
	out->status = mkContact_FromDistance(best.f, c.scale);
	return MK_OK;
}

/* ---- the public helpers and the choice of build -------------------------- */

#ifndef MK_COLLISION_FMA_UNIT

const char *mkContact_Name(mkContact c)
{
	switch (c) {
	case MK_CONTACT_SEPARATED: return "separated";
	case MK_CONTACT_TOUCHING: return "touching";
	case MK_CONTACT_OVERLAPPING: return "overlapping";
	case MK_CONTACT_UNKNOWN: break;
	}
	return "unknown";
}

mkVec3 mkBody3_SupportJacobian(mkBody3 b, mkVec3 n, mkMat3 *J)
{
	if (!(mkVec3_Dot(n, n) > 0.0)) {
		if (J)
			for (int i = 0; i < 3; ++i)
				for (int j = 0; j < 3; ++j)
					J->m[i][j] = NAN;
		return mkVec3_Make(NAN, NAN, NAN);
	}
	mkSupBody k;
	mkSupBody_Init(&k, &b);
	mkSupAt a;
	mkSupBody_Eval(&k, n, &a);
	if (J)
		mkSupAt_Jacobian(&k, &a, J->m);
	return a.s;
}

double mkCollide3_PairSize(mkBody3 b1, mkBody3 b2)
{
	return mkScale(&b1, &b2);
}

double mkCollide3_Bound(mkBody3 b1, mkBody3 b2, mkVec3 n)
{
	mkVec3 u = mkVec3_NormalizeInline(n);
	mkBody3 c1 = b1, c2 = b2;
	c1.t = c2.t = mkVec3_Make(0.0, 0.0, 0.0);
	return mkVec3_Dot(u, mkVec3_Sub(b2.t, b1.t)) - mkBody3_SupportValue(c1, u)
		- mkBody3_SupportValue(c2, mkVec3_Neg(u));
}

void mkCollision3_Clear(mkCollision3 *out)
{
	mkVec3 nan3 = mkVec3_Make(NAN, NAN, NAN);
	out->status = MK_CONTACT_UNKNOWN;
	out->distance = out->directional = out->bound = out->gap = out->residual = NAN;
	out->normal = out->p1 = out->p2 = nan3;
	out->scale = NAN;
	out->iterations = -1;
	out->restarts = -1;
	out->certified = -1;
	out->cert_evals = -1;
}
mkContact mkContact_FromDistance(double sd, double scale)
{
	if (isnan(sd))
		return MK_CONTACT_UNKNOWN;
	if (sd > MK_COLLIDE3_TOUCH_TOL * scale)
		return MK_CONTACT_SEPARATED;
	if (sd < -MK_COLLIDE3_TOUCH_TOL * scale)
		return MK_CONTACT_OVERLAPPING;
	return MK_CONTACT_TOUCHING;
}

/* The solver in the build impl names (collision_impl.h). */
mkResult mkCollide3_NormalImpl(mkImpl impl, mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out)
{
#if defined(MINK_HAVE_FMA_SOLVER)
	if (impl == MK_IMPL_AVX2 || impl == MK_IMPL_AVX512)
		return mkCollide3_NormalAtFma(b1, b2, start, out);
#endif
	(void)impl;
	return mkCollide3_NormalAtPortable(b1, b2, start, out);
}

/* The solver's build for this processor: the FMA build where it was
 * compiled and the processor has AVX2 and FMA (the kernels' AVX2 tier;
 * mkImpl_Available reads the CPU features libgcc resolved at start-up),
 * the portable one otherwise. */
static mkImpl mkCollide3_Impl(void)
{
#if defined(MINK_HAVE_FMA_SOLVER)
	if (mkImpl_Available(MK_IMPL_AVX2))
		return MK_IMPL_AVX2;
#endif
	return MK_IMPL_SCALAR;
}

const char *mkCollide3_Build(void)
{
	return mkCollide3_Impl() == MK_IMPL_SCALAR ? "portable" : "fma";
}

mkResult mkCollide3_Normal(mkBody3 b1, mkBody3 b2, mkCollision3 *out)
{
	return mkCollide3_NormalImpl(mkCollide3_Impl(), b1, b2, NULL, out);
}

mkResult mkCollide3_NormalFrom(mkBody3 b1, mkBody3 b2, mkVec3 start, mkCollision3 *out)
{
	/* scaled by its largest component first, so that no length of a finite
	 * nonzero vector overflows or underflows */
	double m = fmax(fabs(start.x), fmax(fabs(start.y), fabs(start.z)));
	if (!mkIsFinite3(start) || !(m > 0.0)) {
		mkCollision3_Clear(out);
		return MK_ERR_ARGUMENT;
	}
	mkVec3 n = mkVec3_NormalizeInline(mkVec3_Make(start.x / m, start.y / m, start.z / m));
	return mkCollide3_NormalImpl(mkCollide3_Impl(), b1, b2, &n, out);
}

#endif /* MK_COLLISION_FMA_UNIT */
