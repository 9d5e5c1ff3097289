/* support.h - one superquadric's support map for the collision queries: its
 * support point at a direction, with the Jacobian (the support function's
 * Hessian) in the forms the solvers want. Static definitions, included by
 * every unit of collide/ (pair.h builds the pair of bodies on them).
 *
 * The support function of the canonical superquadric is the nested dual norm
 *   h(y) = N(p),  p = (a y1, b y2, c y3),
 *   N(p) = | ( |(p1, p2)|_q2 , p3 ) |_q1,   q = 2 / (2 - eps)
 * (the inner l_q2 norm over the first two components, the outer l_q1 norm of
 * that and the third; eps = 1 gives q = 2, the ellipsoid). For an l_q norm
 * of a pair, with r_i = |v_i| / |v|_q and w_i = r_i^(q-1):
 *   d|v|_q / dv_i = sign(v_i) w_i,
 *   d2|v|_q / dv_i dv_j = (q - 1) / |v|_q (delta_ij r_i^(q-2) - s_i s_j w_i w_j)
 * and the chain rule through the inner norm gives the 3 x 3 Hessian of N;
 * the support point is D grad N and its Jacobian D Hess N D (D = diag(a, b, c)),
 * mapped to the placed body by s = M sigma(M^T n), J = M Hess M^T.
 *
 * The pair norms are evaluated from the ratio k/m of the smaller to the larger
 * component: t = (k/m)^q, |v|_q = m (1 + t)^(1/q), r_m = (1 + t)^(-1/q),
 * r_k = (k/m) r_m, w_m = 1 / ((1 + t) r_m), w_k = t / ((1 + t) r_k): two
 * log and two exp per pair (log(1 + t) as one function in the Newton
 * solver's pass, mkSupBody_EvalHess2), no overflow for any finite input. With
 * P = M diag(a, b, c) formed once per query, p = P^T n and s = P grad N(p).
 */
#ifndef MINK_COLLIDE_SUPPORT_H
#define MINK_COLLIDE_SUPPORT_H

#include <mink/collision.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "base/base2.h"
#include "base/geom_inline.h"

/* MK_PAIR_FN: a function of these headers that is static in each unit that
 * includes them; a unit that does not use it leaves it out without a
 * warning. MK_PAIR_INLINE marks the few that Newton's loop calls at every
 * step: inlined there even where the compiler would not (left to itself it
 * kept the pair pass, called with its flag hess from two places, out of
 * line; inlined with the state's evaluation and the tangent basis, the
 * loop is about 2 % faster). */
#if defined(__GNUC__)
#define MK_PAIR_FN static __attribute__((unused))
#define MK_PAIR_INLINE static inline __attribute__((always_inline))
#else
#define MK_PAIR_FN static
#define MK_PAIR_INLINE static inline
#endif

/* Curvature terms r^(q-2) are clamped to this (q < 2 and r -> 0: the support
 * function is not twice differentiable on a body axis). */
#define MK_CURV_MAX 1e12

/* The l_q norm of a pair (u, v), u, v >= 0, not both 0: the norm, the ratios
 * r and the gradient weights w (the curvature terms r^(q-2) follow from them
 * when the Hessian is wanted, mkCurv). */
typedef struct mkPairNorm { double norm, r[2], w[2]; } mkPairNorm;

/* A curvature term r^(q-2) clamped to MK_CURV_MAX (NaN to it too). */
static inline double mkCurvClamp(double c)
{
	return c < MK_CURV_MAX ? c : MK_CURV_MAX;
}

/* r^(q-2) at r = 0: 0 for q > 2, 1 for q = 2, clamped for q < 2 (one value
 * per exponent, kept in mkSupBody). */
static inline double mkCurvAtZero(double q)
{
	return q > 2.0 ? 0.0 : q == 2.0 ? 1.0 : MK_CURV_MAX;
}

/* r^(q-2) = w / r, or at0 = mkCurvAtZero(q) on r = 0. */
MK_PAIR_FN double mkCurv(double w, double r, double at0)
{
	return r > 0.0 ? mkCurvClamp(w / r) : at0;
}

/* Each pair norm (iq = 1 / q): with the ratio k/m of the smaller to the
 * larger component and t = (k/m)^q: |v|_q = m (1 + t)^(1/q),
 * r_m = (1 + t)^(-1/q), r_k = (k/m) r_m, w_m = r_m^(q-1) = (1 + t)^(1/q) / (1 + t),
 * w_k = (t / (k/m)) w_m. log(1 + t) (t in [0, 1]) carries an absolute error
 * of an ulp of 1, which is all the exponential that follows needs, so
 * log1p is not called. A pair (0, 0) (a direction along the other axis)
 * gets the norm 0 and the unit pair r = w = (1, 0): the outer weight
 * multiplies its gradient by 0. */

/* A placed body's constants for the loop: P = M diag(a, b, c), so that the
 * canonical argument is p = P^T y and the support point P grad N(p); for an
 * ellipsoid Q = P P^T, h(y) = sqrt(y^T Q y), s = Q y / h, J = (Q - s s^T) / h:
 * no transcendental function beyond one square root. */
typedef struct mkSupBody {
	double P[3][3], Q[3][3];
	double q1, q2, iq1, iq2;
	double c1, c2; /* mkCurvAtZero(q1), mkCurvAtZero(q2) */
	int ellipsoid;
} mkSupBody;

/* P = M diag(a, b, c) of body b and, when Q is not NULL, Q = P P^T. */
static inline void mkSupBody_PQ(const mkBody3 *b, double P[3][3], double Q[3][3])
{
	double D[3] = { b->shape.a, b->shape.b, b->shape.c }, p[3][3];
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			P[i][j] = p[i][j] = b->M.m[i][j] * D[j];
	if (Q)
		for (int i = 0; i < 3; ++i)
			for (int j = i; j < 3; ++j)
				Q[i][j] = Q[j][i] = p[i][0] * p[j][0] + p[i][1] * p[j][1] + p[i][2] * p[j][2];
}

MK_PAIR_FN void mkSupBody_Init(mkSupBody *k, const mkBody3 *b)
{
	k->ellipsoid = b->shape.eps1 == 1.0 && b->shape.eps2 == 1.0; /* mkShape3_IsEllipsoid, inline */
	mkSupBody_PQ(b, k->P, k->ellipsoid ? k->Q : NULL);
	if (k->ellipsoid) {
		k->q1 = k->q2 = 2.0;
		k->iq1 = k->iq2 = 0.5;
	} else {
		k->q1 = 2.0 / (2.0 - b->shape.eps1);
		k->q2 = 2.0 / (2.0 - b->shape.eps2);
		k->iq1 = 1.0 - 0.5 * b->shape.eps1;
		k->iq2 = 1.0 - 0.5 * b->shape.eps2;
	}
	k->c1 = mkCurvAtZero(k->q1);
	k->c2 = mkCurvAtZero(k->q2);
}

/* Bodies evaluated in lock-step at most (mkNested): the two of a pair, or
 * the pairs at four directions of the overlap certificate. */
#define MK_LANES 8

/* The nested norms |(|(u, v)|_q2, w)|_q1 of nl <= MK_LANES bodies, each pair
 * norm as described above (mkPairNorm), the bodies in lock-step (the libm calls of one body form
 * dependency chains; interleaving two bodies' lets the processor
 * overlap them, which halved a pair evaluation) and, within a body, the inner and outer chains
 * overlapped: the outer pair's log ratio is
 *   log(N_in / w) = log(m_in / w) + log(1 + t_in) / q2
 * (N_in = m_in (1 + t_in)^(1/q2)), so the outer exponential need not wait
 * for the inner norm's. The longest chain per body is six libm calls
 * instead of eight, the count unchanged (log(m_in / w) replaces
 * log(k_out / m_out)). Both terms of the sum are small logarithms of
 * quantities carrying a few ulps, as the ratio k/m of mkPair does, so
 * t_out is as accurate as there. The outputs are those of mkPair for
 * (u, v) and for (N_in, w) (in the order of the arguments), the larger of
 * the outer pair chosen by the sign of log(N_in / w). The logarithms and
 * exponentials are glibc's log2 and exp2 (cheaper than log and exp, and
 * the formulas hold in any base used for both). */
static inline void mkNested(int nl, const double u[MK_LANES], const double v[MK_LANES], const double w[MK_LANES],
	const mkSupBody *const b[MK_LANES], mkPairNorm in[MK_LANES], mkPairNorm out[MK_LANES])
{
	double m[MK_LANES], ratio[MK_LANES], L[MK_LANES], Lc[MK_LANES], t[MK_LANES], opt[MK_LANES], irm[MK_LANES],
		lr[MK_LANES], to[MK_LANES], opto[MK_LANES], irmo[MK_LANES];
	int big[MK_LANES];
	for (int l = 0; l < nl; ++l) {
		big[l] = u[l] >= v[l] ? 0 : 1;
		m[l] = big[l] == 0 ? u[l] : v[l];
		double k = big[l] == 0 ? v[l] : u[l];
		ratio[l] = m[l] > 0.0 ? k / m[l] : 0.0;
	}
	for (int l = 0; l < nl; ++l) {
		L[l] = ratio[l] > 0.0 ? log2(ratio[l]) : 0.0;
		/* log2(m_in / w); +-inf when one of them is 0 (or the quotient
		 * leaves the double range: t_out is then 0 either way) */
		Lc[l] = m[l] > 0.0 && w[l] > 0.0 ? log2(m[l] / w[l]) : m[l] > 0.0 ? INFINITY : -INFINITY;
	}
	for (int l = 0; l < nl; ++l)
		t[l] = ratio[l] > 0.0 ? exp2(b[l]->q2 * L[l]) : 0.0;
	for (int l = 0; l < nl; ++l) {
		opt[l] = 1.0 + t[l];
		L[l] = log2(opt[l]);
	}
	for (int l = 0; l < nl; ++l) {
		irm[l] = exp2(b[l]->iq2 * L[l]);
		lr[l] = Lc[l] + b[l]->iq2 * L[l]; /* log2(N_in / w) */
		to[l] = isfinite(lr[l]) ? exp2(-b[l]->q1 * fabs(lr[l])) : 0.0;
	}
	for (int l = 0; l < nl; ++l) {
		opto[l] = 1.0 + to[l];
		irmo[l] = exp2(b[l]->iq1 * log2(opto[l]));
	}
	for (int l = 0; l < nl; ++l) {
		mkPairNorm *p = &in[l];
		if (m[l] == 0.0) {
			/* as mkPair: any unit pair, the outer weight multiplies it by 0 */
			p->norm = 0.0;
			p->r[0] = 1.0; p->r[1] = 0.0;
			p->w[0] = 1.0; p->w[1] = 0.0;
		} else {
			double rm = 1.0 / irm[l], wm = irm[l] / opt[l];
			p->norm = m[l] * irm[l];
			p->r[big[l]] = rm;
			p->r[1 - big[l]] = ratio[l] * rm;
			p->w[big[l]] = wm;
			p->w[1 - big[l]] = ratio[l] > 0.0 ? t[l] / ratio[l] * wm : 0.0;
		}
		p = &out[l];
		int bo = lr[l] >= 0.0 ? 0 : 1; /* N_in >= w: the first is the larger */
		double mo = bo == 0 ? in[l].norm : w[l], ko = bo == 0 ? w[l] : in[l].norm;
		if (mo == 0.0) {
			p->norm = 0.0;
			p->r[0] = 1.0; p->r[1] = 0.0;
			p->w[0] = 1.0; p->w[1] = 0.0;
			continue;
		}
		double ro = ko / mo;
		double rm = 1.0 / irmo[l], wm = irmo[l] / opto[l];
		p->norm = mo * irmo[l];
		p->r[bo] = rm;
		p->r[1 - bo] = ro * rm;
		p->w[bo] = wm;
		p->w[1 - bo] = ro > 0.0 ? to[l] / ro * wm : 0.0;
	}
}

/* One body's support at a direction y, with what its Hessian needs. */
typedef struct mkSupAt {
	mkVec3 s;          /* support point about the centre */
	double h;          /* <y, s> */
	mkVec3 v;          /* ellipsoid: Q y */
	double sg[3];      /* superquadric: signs of p = P^T y */
	mkPairNorm in, out;
} mkSupAt;

MK_PAIR_FN void mkSupBody_Eval(const mkSupBody *b, mkVec3 y, mkSupAt *a)
{
	const double (*P)[3] = b->P;
	if (b->ellipsoid) {
		const double (*Q)[3] = b->Q;
		mkVec3 v = mkVec3_Make(Q[0][0] * y.x + Q[0][1] * y.y + Q[0][2] * y.z,
			Q[1][0] * y.x + Q[1][1] * y.y + Q[1][2] * y.z,
			Q[2][0] * y.x + Q[2][1] * y.y + Q[2][2] * y.z);
		double h = sqrt(y.x * v.x + y.y * v.y + y.z * v.z);
		double inv = 1.0 / h;
		a->v = v;
		a->s = mkVec3_Scale(v, inv);
		a->h = mkVec3_Dot(y, a->s);
		return;
	}
	double p0 = P[0][0] * y.x + P[1][0] * y.y + P[2][0] * y.z;
	double p1 = P[0][1] * y.x + P[1][1] * y.y + P[2][1] * y.z;
	double p2 = P[0][2] * y.x + P[1][2] * y.y + P[2][2] * y.z;
	a->sg[0] = p0 < 0.0 ? -1.0 : 1.0;
	a->sg[1] = p1 < 0.0 ? -1.0 : 1.0;
	a->sg[2] = p2 < 0.0 ? -1.0 : 1.0;
	const mkSupBody *bb[MK_LANES] = { b };
	double u[MK_LANES] = { fabs(p0) }, v[MK_LANES] = { fabs(p1) }, w[MK_LANES] = { fabs(p2) };
	mkPairNorm in[MK_LANES], out[MK_LANES];
	mkNested(1, u, v, w, bb, in, out);
	a->in = in[0];
	a->out = out[0];
	double g0 = a->out.w[0] * a->sg[0] * a->in.w[0];
	double g1 = a->out.w[0] * a->sg[1] * a->in.w[1];
	double g2 = a->sg[2] * a->out.w[1];
	a->s = mkVec3_Make(P[0][0] * g0 + P[0][1] * g1 + P[0][2] * g2,
		P[1][0] * g0 + P[1][1] * g1 + P[1][2] * g2,
		P[2][0] * g0 + P[2][1] * g1 + P[2][2] * g2);
	a->h = mkVec3_Dot(y, a->s);
}

/* The Hessian of the canonical support function N at p (superquadric), from
 * the pair norms of the evaluation: for an l_q norm of a pair
 * (q - 1) / |v|_q (diag r_i^(q-2) - s_i s_j w_i w_j), through the chain rule
 * of the nested norms. */
MK_PAIR_FN void mkSupAt_CanonHess(const mkSupBody *b, const mkSupAt *a, double Hp[3][3])
{
	double G[2] = { a->sg[0] * a->in.w[0], a->sg[1] * a->in.w[1] };
	double N = a->out.norm;
	double k1 = (b->q1 - 1.0) / N;
	double co0 = mkCurv(a->out.w[0], a->out.r[0], b->c1), co1 = mkCurv(a->out.w[1], a->out.r[1], b->c1);
	double ci[2] = { mkCurv(a->in.w[0], a->in.r[0], b->c2), mkCurv(a->in.w[1], a->in.r[1], b->c2) };
	/* Outer Hessian over (inner norm, p3). */
	double o00 = k1 * (co0 - a->out.w[0] * a->out.w[0]);
	double o01 = -k1 * a->out.w[0] * a->sg[2] * a->out.w[1];
	double o11 = k1 * (co1 - a->out.w[1] * a->out.w[1]);
	/* w_g * Hess(inner) = (q2 - 1) / N * r_g^(q1 - 2) * (...): the weight
	 * w_g = r_g^(q1-1) over the inner norm r_g N. */
	double k2 = (b->q2 - 1.0) / N * co0;
	for (int i = 0; i < 2; ++i)
		for (int j = 0; j < 2; ++j)
			Hp[i][j] = o00 * G[i] * G[j] + k2 * ((i == j ? ci[i] : 0.0) - G[i] * G[j]);
	Hp[0][2] = Hp[2][0] = o01 * G[0];
	Hp[1][2] = Hp[2][1] = o01 * G[1];
	Hp[2][2] = o11;
}

/* The Jacobian ds/dy (3 x 3) at the evaluated direction. */
MK_PAIR_FN void mkSupAt_Jacobian(const mkSupBody *b, const mkSupAt *a, double J[3][3])
{
	if (b->ellipsoid) {
		double inv = 1.0 / a->h;
		double s[3] = { a->s.x, a->s.y, a->s.z };
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				J[i][j] = (b->Q[i][j] - s[i] * s[j]) * inv;
		return;
	}
	double Hp[3][3], T[3][3];
	mkSupAt_CanonHess(b, a, Hp);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			T[i][j] = b->P[i][0] * Hp[0][j] + b->P[i][1] * Hp[1][j] + b->P[i][2] * Hp[2][j];
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			J[i][j] = T[i][0] * b->P[j][0] + T[i][1] * b->P[j][1] + T[i][2] * b->P[j][2];
}

/* Adds t_i^T J t_j (i, j in {1, 2}) to A = (A11, A12, A22): the Jacobian in
 * a plane, never formed in 3 x 3. */
MK_PAIR_FN void mkSupAt_Tangent(const mkSupBody *b, const mkSupAt *a, mkVec3 t1, mkVec3 t2, double A[3])
{
	if (b->ellipsoid) {
		const double (*Q)[3] = b->Q;
		mkVec3 w1 = mkVec3_Make(Q[0][0] * t1.x + Q[0][1] * t1.y + Q[0][2] * t1.z,
			Q[1][0] * t1.x + Q[1][1] * t1.y + Q[1][2] * t1.z,
			Q[2][0] * t1.x + Q[2][1] * t1.y + Q[2][2] * t1.z);
		mkVec3 w2 = mkVec3_Make(Q[0][0] * t2.x + Q[0][1] * t2.y + Q[0][2] * t2.z,
			Q[1][0] * t2.x + Q[1][1] * t2.y + Q[1][2] * t2.z,
			Q[2][0] * t2.x + Q[2][1] * t2.y + Q[2][2] * t2.z);
		double inv = 1.0 / a->h;
		double e1 = mkVec3_Dot(t1, a->s), e2 = mkVec3_Dot(t2, a->s);
		A[0] += (mkVec3_Dot(t1, w1) - e1 * e1) * inv;
		A[1] += (mkVec3_Dot(t1, w2) - e1 * e2) * inv;
		A[2] += (mkVec3_Dot(t2, w2) - e2 * e2) * inv;
		return;
	}
	/* u^T Hp w from the structure of the canonical Hessian (mkSupAt_CanonHess)
	 * without forming it: with G the inner gradient and u' = (u1, u2),
	 * u^T Hp w = o00 (G.u')(G.w') + k2 (sum ci u_i w_i - (G.u')(G.w'))
	 *          + o01 ((G.u') w3 + (G.w') u3) + o11 u3 w3. */
	const double (*P)[3] = b->P;
	double u[3], w[3];
	for (int j = 0; j < 3; ++j) {
		u[j] = P[0][j] * t1.x + P[1][j] * t1.y + P[2][j] * t1.z;
		w[j] = P[0][j] * t2.x + P[1][j] * t2.y + P[2][j] * t2.z;
	}
	double G0 = a->sg[0] * a->in.w[0], G1 = a->sg[1] * a->in.w[1];
	double N = a->out.norm;
	double k1 = (b->q1 - 1.0) / N;
	double co0 = mkCurv(a->out.w[0], a->out.r[0], b->c1), co1 = mkCurv(a->out.w[1], a->out.r[1], b->c1);
	double ci0 = mkCurv(a->in.w[0], a->in.r[0], b->c2), ci1 = mkCurv(a->in.w[1], a->in.r[1], b->c2);
	double o00 = k1 * (co0 - a->out.w[0] * a->out.w[0]);
	double o01 = -k1 * a->out.w[0] * a->sg[2] * a->out.w[1];
	double o11 = k1 * (co1 - a->out.w[1] * a->out.w[1]);
	double k2 = (b->q2 - 1.0) / N * co0;
	double gu = G0 * u[0] + G1 * u[1], gw = G0 * w[0] + G1 * w[1];
	double og = o00 - k2;
	A[0] += og * gu * gu + k2 * (ci0 * u[0] * u[0] + ci1 * u[1] * u[1]) + 2.0 * o01 * gu * u[2] + o11 * u[2] * u[2];
	A[1] += og * gu * gw + k2 * (ci0 * u[0] * w[0] + ci1 * u[1] * w[1]) + o01 * (gu * w[2] + gw * u[2]) + o11 * u[2] * w[2];
	A[2] += og * gw * gw + k2 * (ci0 * w[0] * w[0] + ci1 * w[1] * w[1]) + 2.0 * o01 * gw * w[2] + o11 * w[2] * w[2];
}

#endif
