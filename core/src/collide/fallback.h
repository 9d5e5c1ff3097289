/* fallback.h - what MinkSum (Normal) does where one Newton solve from the
 * centre line does not give the answer: Gilbert's iteration on a separated
 * pair whose support function is nearly kinked (a bracket of the distance,
 * and witness points on nearly flat faces), and restarts from candidate
 * normals on an overlap, where f may have several local maxima. Static
 * definitions, compiled into each build of the solver (normal.h). */
#ifndef MINK_COLLIDE_FALLBACK_H
#define MINK_COLLIDE_FALLBACK_H

#include "collide/hull.h"
#include "collide/newton.h"

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

/* ---- Gilbert's iteration on the hull of support points -------------------- */

/* Pair evaluations the witness iteration (mkNormal_Hull) may spend. */
#define MK_HULL_EVALS 64
/* The same iteration as the fallback of a separated pair on which Newton
 * did not converge: its budget of pair evaluations and the bracket it aims
 * for (times the scale). */
#define MK_GILBERT_EVALS 2000
#define MK_GILBERT_TOL 1e-12

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
 * brackets sd (mkNormal_Gilbert). */
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

/* ---- the best answer of a query ------------------------------------------- */

/* The best state a query has met, with how it was reached. */
typedef struct mkNormalBest {
	mkNormalState st;
	double res;  /* its residual (mkNormal_Solve's *res) */
	int ok;      /* mkNormal_Solve's answer for it: 1 converged, 2 stalled, 0 not */
	int stalled; /* ok == 2 */
} mkNormalBest;

/* Newton from n (a restart, counted in out->restarts); the state found
 * replaces the best when it converged and is higher, or nothing converged
 * before. */
static void mkNormal_Restart(const mkPairCtx *c, mkVec3 n, mkNormalBest *b, int *iters, mkCollision3 *out)
{
	mkNormalState st;
	double res = NAN;
	int ok = mkNormal_Solve(c, n, &st, iters, &res);
	out->restarts += 1;
	if (ok && (!b->ok || st.f > b->st.f)) {
		b->st = st;
		b->res = res;
		b->ok = 1;
		b->stalled = ok == 2;
	}
}

/* ---- a separated pair Newton did not settle ------------------------------- */

/* A separated pair (f > 0 bounds sd from below) on which Newton did not
 * converge, or stopped on a stalled value, on a ridge of a nearly kinked
 * support function: Gilbert's iteration brackets sd between the largest f
 * it meets and the least |z| (mkNormal_Hull), and the answer stands when
 * the bracket is within MK_ANSWER_TOL of the scale; the residual reported
 * is then the bracket's width. Returns 1 when it stands; *gp1, *gp2
 * receive the iteration's witness points (NaN when it did not run). */
static int mkNormal_Gilbert(const mkPairCtx *c, mkNormalBest *b, int *iters, mkVec3 *gp1, mkVec3 *gp2)
{
	*gp1 = mkVec3_Make(NAN, NAN, NAN);
	*gp2 = *gp1;
	if (!((!b->ok || b->stalled) && isfinite(b->st.f) && b->st.f > 0.0))
		return 0;
	*gp1 = mkVec3_Add(c->b1->t, b->st.e.a1.s);
	*gp2 = mkVec3_Add(c->b2->t, b->st.e.a2.s);
	int evals;
	double up = mkNormal_Hull(c, &b->st, MK_GILBERT_EVALS, MK_GILBERT_TOL * c->scale, 1, gp1, gp2, &evals);
	*iters += evals;
	if (up - b->st.f <= MK_ANSWER_TOL * c->scale) {
		b->ok = 1;
		b->res = up - b->st.f;
		return 1;
	}
	return 0;
}

/* ---- restarts on an overlap ----------------------------------------------- */

/* Extra starts for an overlap: the reversed centre line, the bodies' axis
 * directions (both signs), the diagonals of their frames and a lattice over
 * the sphere; Newton restarts from the best MK_RESTARTS of them by f that
 * are not close (within about 18 degrees) to the answer or to each other.
 * One restart, since the branch and bound (certify.h) climbs any maximum it
 * meets more than MK_ANSWER_TOL of the scale above the best: on 2 x 10^4
 * deep overlaps (seeds 99 and 7) no answer was lower than with four
 * restarts, and the evaluations per query fell by about a tenth
 * (superquadrics: median 632 -> 572). Without any, two of 10^4 answers
 * stayed on a lower maximum within the certificate's 1e-8 (by 4e-10 and
 * 4.4e-9 of the scale). */
enum { MK_FIB = 64, MK_CAND = 29 + MK_FIB, MK_RESTARTS = 1, MK_SCAN_EXACT = 16 };

/* The candidate starts of an overlap (n0 the centre line's direction) in
 * cand, the structured ones first and the MK_FIB lattice points last; returns
 * their number. */
static int mkNormal_Candidates(const mkPairCtx *c, mkVec3 n0, mkVec3 cand[MK_CAND])
{
	int nc = 0;
	cand[nc++] = mkVec3_Neg(n0);
	for (int k = 0; k < 2; ++k) {
		mkMat3 M = k == 0 ? c->b1->M : c->b2->M;
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
	return nc;
}

/* f at the nc candidates, -inf where it is not evaluated. Two ellipsoids:
 * at every candidate. Superquadrics: exactly at the structured candidates
 * (the reversed centre line, axes and diagonals: where box-like bodies have
 * their optima), and at the MK_SCAN_EXACT lattice points that rank best by
 * f of the ellipsoids with the same axes and maps (a square root per body
 * instead of eight transcendental functions). */
static void mkNormal_Scan(const mkPairCtx *c, const mkVec3 cand[MK_CAND], int nc, double val[MK_CAND])
{
	if (c->k1.ellipsoid && c->k2.ellipsoid) {
		for (int i = 0; i < nc; ++i)
			val[i] = mkIsFinite3(cand[i]) ? mkNormal_Value(c, cand[i]) : -INFINITY;
		return;
	}
	mkPairCtx e = *c;
	mkBody3 p1 = *c->b1, p2 = *c->b2;
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
		val[i] = (i < MK_CAND - MK_FIB || proxy[i] >= cut) && proxy[i] > -INFINITY ? mkNormal_Value(c, cand[i])
			: -INFINITY;
}

/* Overlap (or a failed start): f may have several local maxima on the
 * sphere. Evaluates f at the candidate directions, restarts Newton from the
 * best MK_RESTARTS not already near the answer (nor near each other) and
 * keeps the best converged state in b. */
static void mkNormal_Restarts(const mkPairCtx *c, mkVec3 n0, mkNormalBest *b, int *iters, mkCollision3 *out)
{
	mkVec3 cand[MK_CAND];
	double val[MK_CAND];
	int nc = mkNormal_Candidates(c, n0, cand);
	mkNormal_Scan(c, cand, nc, val);
	mkVec3 picked[MK_RESTARTS];
	int npicked = 0;
	for (int r = 0; r < MK_RESTARTS; ++r) {
		int pick = -1;
		for (int i = 0; i < nc; ++i) {
			if (!(val[i] > -INFINITY))
				continue;
			if (b->ok && mkVec3_Dot(cand[i], b->st.n) > 0.99)
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
		mkNormal_Restart(c, cand[pick], b, iters, out);
	}
}

/* ---- witness points of a separated answer --------------------------------- */

/* Near a kink the support points are not resolved by the normal (a nearly
 * flat face is crossed within rounding of n): where out's witnesses are
 * further apart than the distance f by more than MK_COLLIDE3_TOUCH_TOL of
 * the scale, tighter ones. Each support point moved by -/+ f n to the other
 * body's supporting plane, then radially onto that body; if they are still
 * apart, where on the face by the hull of support points (mkNormal_Hull).
 * Returns the witnesses' distance. */
static double mkNormal_Witnesses(const mkPairCtx *c, mkNormalState *best, mkCollision3 *out)
{
	double span = mkVec3_LengthInline(mkVec3_Sub(out->p2, out->p1));
	if (!(best->f > 0.0 && span - best->f > MK_COLLIDE3_TOUCH_TOL * c->scale))
		return span;
	mkVec3 q1 = mkRadial(*c->b1, mkVec3_Sub(out->p2, mkVec3_Scale(best->n, best->f)));
	mkVec3 q2 = mkRadial(*c->b2, mkVec3_Add(out->p1, mkVec3_Scale(best->n, best->f)));
	double s1 = mkVec3_LengthInline(mkVec3_Sub(out->p2, q1)), s2 = mkVec3_LengthInline(mkVec3_Sub(q2, out->p1));
	if (s1 < span && s1 <= s2) {
		out->p1 = q1;
		span = s1;
	} else if (s2 < span) {
		out->p2 = q2;
		span = s2;
	}
	if (span - best->f > MK_COLLIDE3_TOUCH_TOL * c->scale) {
		int evals;
		mkNormal_Hull(c, best, MK_HULL_EVALS, 1e-13 * c->scale, 0, &out->p1, &out->p2, &evals);
		span = mkVec3_LengthInline(mkVec3_Sub(out->p2, out->p1));
	}
	return span;
}

#endif
