/* collision_pair.h - what the two closed-form collision queries share
 * (collision.c: MinkSum (Normal), its certificate and the public helpers;
 * collision_ray.c: MinkSum (Ray)): the support map of a placed body with its
 * Jacobian, a pair of bodies evaluated at a normal, the trust-region step and
 * the exact line search. Everything here is static to each unit that
 * includes it (internal to the library): the small loops static inline,
 * the rest as they were when both queries shared one file (MK_PAIR_FN).
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
#ifndef MINK_COLLISION_PAIR_H
#define MINK_COLLISION_PAIR_H

#include <mink/collision.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "base/base2.h"
#include "base/geom_inline.h"

/* The functions below that are not marked inline: static in each unit that
 * includes this header, the ones a unit does not use left out without a
 * warning. MK_PAIR_INLINE marks the few that Newton's loop calls at every
 * step: inlined there even where the compiler would not (measured: the
 * pass called with its flag hess from two places was left out of line, and
 * inlining it with the state's evaluation and the tangent basis made the
 * loop 2 % faster). */
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
/* The initial and largest trust-region radius (a step in the tangent plane
 * of the unit normal, so roughly radians). */
#define MK_TR_INIT 0.25
#define MK_TR_MAX 1.0
/* From this iteration on, a step whose model was poor (ratio below 0.75) is
 * followed by an exact line search along the stiffest direction. */
#define MK_LINE_AFTER 6

/* |(a, b)| for the well-scaled 2-vectors of the solver (gradients and steps
 * far from the double range's ends): libm's hypot guards against overflow
 * at a cost that dominated the whole query. */
MK_PAIR_FN double mkLen2(double a, double b)
{
	return sqrt(a * a + b * b);
}

/* ---- the support map with its Jacobian ------------------------------------ */

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

MK_PAIR_FN void mkSupBody_Init(mkSupBody *k, const mkBody3 *b)
{
	double D[3] = { b->shape.a, b->shape.b, b->shape.c };
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			k->P[i][j] = b->M.m[i][j] * D[j];
	k->ellipsoid = mkShape3_IsEllipsoid(b->shape);
	if (k->ellipsoid) {
		for (int i = 0; i < 3; ++i)
			for (int j = i; j < 3; ++j)
				k->Q[i][j] = k->Q[j][i] = k->P[i][0] * k->P[j][0] + k->P[i][1] * k->P[j][1] + k->P[i][2] * k->P[j][2];
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

/* ---- the pair ----------------------------------------------------------- */

typedef struct mkPairCtx {
	const mkBody3 *b1, *b2;
	mkSupBody k1, k2;
	mkVec3 d;
	double scale;
} mkPairCtx;

/* Everything at one (possibly unnormalised) direction m: both bodies'
 * support data (s1 = a1.s at m, s2 = a2.s at -m, about the centres), the
 * contact-space point x = s1 - s2 and H = <m, x> (= h1(m) + h2(-m)). The
 * Hessians are formed only on demand (mkPair_Tangent). */
typedef struct mkPairAt {
	mkSupAt a1, a2;
	mkVec3 x;
	double H;
} mkPairAt;

/* nl <= MK_LANES superquadrics' support at y[l] (mkNested). */
static inline void mkSupBody_EvalLanes(int nl, const mkSupBody *const b[MK_LANES], const mkVec3 y[MK_LANES],
	mkSupAt *const a[MK_LANES])
{
	double p[MK_LANES][3], u[MK_LANES], v[MK_LANES], w[MK_LANES];
	mkPairNorm in[MK_LANES], out[MK_LANES];
	for (int l = 0; l < nl; ++l) {
		const double (*P)[3] = b[l]->P;
		for (int j = 0; j < 3; ++j) {
			p[l][j] = P[0][j] * y[l].x + P[1][j] * y[l].y + P[2][j] * y[l].z;
			a[l]->sg[j] = p[l][j] < 0.0 ? -1.0 : 1.0;
		}
		u[l] = fabs(p[l][0]);
		v[l] = fabs(p[l][1]);
		w[l] = fabs(p[l][2]);
	}
	mkNested(nl, u, v, w, b, in, out);
	for (int l = 0; l < nl; ++l) {
		const double (*P)[3] = b[l]->P;
		mkSupAt *A = a[l];
		A->in = in[l];
		A->out = out[l];
		double g0 = out[l].w[0] * A->sg[0] * in[l].w[0];
		double g1 = out[l].w[0] * A->sg[1] * in[l].w[1];
		double g2 = A->sg[2] * out[l].w[1];
		A->s = mkVec3_Make(P[0][0] * g0 + P[0][1] * g1 + P[0][2] * g2,
			P[1][0] * g0 + P[1][1] * g1 + P[1][2] * g2,
			P[2][0] * g0 + P[2][1] * g1 + P[2][2] * g2);
		A->h = mkVec3_Dot(y[l], A->s);
	}
}

/* Both superquadrics of a pair at y1 = n and y2 = -n with the pair's tangent
 * Jacobian A = (t1^T J t1, t1^T J t2, t2^T J t2), J = J1(n) + J2(-n), in one
 * pass for Newton's loop: the quantities of mkNested and mkSupAt_Tangent.
 * Measured, the arithmetic around a pair evaluation's libm calls weighs
 * about as much as the calls (a dependent loop of evaluations kept 3/5 of
 * its time with them replaced by a multiply-add), so this pass does what
 * the two did with less of it:
 *  - the tangent Jacobian is formed as soon as the weights are known, from
 *    projections P^T t of the tangents that do not wait for the evaluation;
 *  - the reciprocals 1/m, 1/k, 1/w of the components, 1/(1 + t) and
 *    1/R (R = (1 + t)^(1/q2)) are formed once, so that every ratio, weight
 *    and curvature term after them is a product: with r = m / k,
 *      N_in = m R,  1/N_in = (1/m) / R,  w_m = R / (1 + t),  w_k = t r w_m,
 *      r_m^(q-2) = R w_m,  r_k^(q-2) = t r^2 r_m^(q-2),
 *    and the same for the outer pair (N_in, |p3|), 1/N = (1/m_out) / R_out;
 *  - the maps start from y = len n, the unnormalised trial point of a step
 *    (n = y / len the unit normal): s is homogeneous of degree 0 in the
 *    direction, the norms of degree 1 and J of degree -1, so only the norms
 *    and 1 / N are rescaled, and the normalisation runs beside the chain.
 * Logarithms and exponentials are to base 2 here and in mkNested (the same
 * formulas: only the pairs log/exp must share a base), as glibc's exp2 is
 * cheaper than its exp. Here the two stages log2(1 + 2^x) of the nested norm
 * are one call each (mkSoftplus2) and 2^x is inline (mkExp2), both of
 * base2.h; the logarithms of the ratios stay glibc's log2 (an inline one
 * measured no faster). The values agree with mkNested's and
 * mkSupAt_Tangent's to a few ulps; the mkSupAt records are filled as there.
 * With hess = 0 (a constant at each call, so that the compiler drops the
 * dead part) the tangent Jacobian is not formed and A is not written: the
 * support points, values and weights are the same to the last bit. */
MK_PAIR_INLINE void mkSupBody_EvalHess2(const mkSupBody *b1, const mkSupBody *b2, mkVec3 y, double len, mkVec3 n,
	mkVec3 t1, mkVec3 t2, mkSupAt *a1, mkSupAt *a2, double A[3], int hess)
{
	const mkSupBody *B[2] = { b1, b2 };
	mkSupAt *S[2] = { a1, a2 };
	double pu[2][3], pw[2][3];
	double u[2], v[2], w[2], m[2], kk[2], im[2], ik[2], iw[2], ratio[2], L[2], Lc[2];
	int big[2];
	for (int k = 0; k < 2; ++k) {
		const double (*P)[3] = B[k]->P;
		double sy = k == 0 ? 1.0 : -1.0, pr[3];
		for (int j = 0; j < 3; ++j) {
			pr[j] = sy * (P[0][j] * y.x + P[1][j] * y.y + P[2][j] * y.z);
			if (hess) {
				pu[k][j] = P[0][j] * t1.x + P[1][j] * t1.y + P[2][j] * t1.z;
				pw[k][j] = P[0][j] * t2.x + P[1][j] * t2.y + P[2][j] * t2.z;
			}
			S[k]->sg[j] = pr[j] < 0.0 ? -1.0 : 1.0;
		}
		u[k] = fabs(pr[0]);
		v[k] = fabs(pr[1]);
		w[k] = fabs(pr[2]);
		big[k] = u[k] >= v[k] ? 0 : 1;
		m[k] = u[k] >= v[k] ? u[k] : v[k];
		kk[k] = u[k] >= v[k] ? v[k] : u[k];
	}
	for (int k = 0; k < 2; ++k) {
		ratio[k] = m[k] > 0.0 ? kk[k] / m[k] : 0.0;
		im[k] = 1.0 / m[k];
		ik[k] = 1.0 / kk[k];
		iw[k] = 1.0 / w[k];
	}
	for (int k = 0; k < 2; ++k) {
		L[k] = ratio[k] > 0.0 ? log2(ratio[k]) : 0.0;
		Lc[k] = m[k] > 0.0 && w[k] > 0.0 ? log2(m[k] / w[k]) : m[k] > 0.0 ? INFINITY : -INFINITY;
	}
	double t[2], opt[2], iopt[2], Lp[2], R[2], iR[2], lr[2], to[2], opto[2], iopto[2], Lo[2], Ro[2], iRo[2];
	/* Lp = log2(1 + t) and Lo = log2(1 + t_out) straight from the exponents
	 * (mkSoftplus2), t and t_out beside them */
	for (int k = 0; k < 2; ++k) {
		double x = B[k]->q2 * L[k];
		t[k] = ratio[k] > 0.0 ? mkExp2(x) : 0.0;
		Lp[k] = ratio[k] > 0.0 ? mkSoftplus2(x, t[k]) : 0.0;
	}
	for (int k = 0; k < 2; ++k) {
		opt[k] = 1.0 + t[k];
		iopt[k] = 1.0 / opt[k];
		R[k] = mkExp2(B[k]->iq2 * Lp[k]);
		iR[k] = 1.0 / R[k];
		lr[k] = Lc[k] + B[k]->iq2 * Lp[k]; /* log2(N_in / w) */
		double x = -B[k]->q1 * fabs(lr[k]);
		to[k] = isfinite(lr[k]) ? mkExp2(x) : 0.0;
		Lo[k] = isfinite(lr[k]) ? mkSoftplus2(x, to[k]) : 0.0;
	}
	for (int k = 0; k < 2; ++k) {
		opto[k] = 1.0 + to[k];
		iopto[k] = 1.0 / opto[k];
		Ro[k] = mkExp2(B[k]->iq1 * Lo[k]);
		iRo[k] = 1.0 / Ro[k];
	}
	double Aq[3] = { 0.0, 0.0, 0.0 };
	for (int k = 0; k < 2; ++k) {
		const mkSupBody *b = B[k];
		mkSupAt *a = S[k];
		mkPairNorm *in = &a->in, *out = &a->out;
		double ci[2], co[2];
		double Nin, iNin;
		if (m[k] == 0.0) {
			Nin = 0.0;
			iNin = INFINITY;
			in->r[0] = 1.0; in->r[1] = 0.0;
			in->w[0] = 1.0; in->w[1] = 0.0;
			ci[0] = 1.0;
			ci[1] = b->c2;
		} else {
			int bg = big[k];
			double wm = R[k] * iopt[k], r = m[k] * ik[k];
			Nin = m[k] * R[k];
			iNin = im[k] * iR[k];
			in->r[bg] = iR[k];
			in->r[1 - bg] = ratio[k] * iR[k];
			in->w[bg] = wm;
			in->w[1 - bg] = ratio[k] > 0.0 ? t[k] * r * wm : 0.0;
			double cm = R[k] * wm;
			ci[bg] = mkCurvClamp(cm);
			ci[1 - bg] = ratio[k] > 0.0 ? mkCurvClamp(t[k] * r * r * cm) : b->c2;
		}
		in->norm = Nin / len;
		int bo = lr[k] >= 0.0 ? 0 : 1; /* N_in >= w: the inner norm is the larger */
		double mo = bo == 0 ? Nin : w[k];
		double iN;
		if (mo == 0.0) {
			out->norm = 0.0;
			out->r[0] = 1.0; out->r[1] = 0.0;
			out->w[0] = 1.0; out->w[1] = 0.0;
			co[0] = 1.0;
			co[1] = b->c1;
			iN = INFINITY;
		} else {
			/* ro = k_out / m_out and its reciprocal, by the reciprocals */
			double ro = bo == 0 ? w[k] * iNin : Nin * iw[k];
			double iro = bo == 0 ? Nin * iw[k] : w[k] * iNin;
			double imo = bo == 0 ? iNin : iw[k];
			double wm = Ro[k] * iopto[k];
			out->norm = mo * Ro[k] / len;
			out->r[bo] = iRo[k];
			out->r[1 - bo] = ro * iRo[k];
			out->w[bo] = wm;
			double tro = ro > 0.0 ? to[k] * iro : 0.0;
			out->w[1 - bo] = tro * wm;
			double cm = Ro[k] * wm;
			co[bo] = mkCurvClamp(cm);
			co[1 - bo] = ro > 0.0 ? mkCurvClamp(tro * iro * cm) : b->c1;
			iN = imo * iRo[k] * len;
		}
		/* the support point */
		const double (*P)[3] = b->P;
		double g0 = out->w[0] * a->sg[0] * in->w[0];
		double g1 = out->w[0] * a->sg[1] * in->w[1];
		double g2 = a->sg[2] * out->w[1];
		mkVec3 sp = mkVec3_Make(P[0][0] * g0 + P[0][1] * g1 + P[0][2] * g2,
			P[1][0] * g0 + P[1][1] * g1 + P[1][2] * g2,
			P[2][0] * g0 + P[2][1] * g1 + P[2][2] * g2);
		a->s = sp;
		a->h = k == 0 ? mkVec3_Dot(n, sp) : -mkVec3_Dot(n, sp);
		if (!hess)
			continue;
		/* the tangent forms, as mkSupAt_Tangent */
		double G0 = a->sg[0] * in->w[0], G1 = a->sg[1] * in->w[1];
		double k1 = (b->q1 - 1.0) * iN;
		double o00 = k1 * (co[0] - out->w[0] * out->w[0]);
		double o01 = -k1 * out->w[0] * a->sg[2] * out->w[1];
		double o11 = k1 * (co[1] - out->w[1] * out->w[1]);
		double k2 = (b->q2 - 1.0) * iN * co[0];
		const double *x = pu[k], *z = pw[k];
		double gu = G0 * x[0] + G1 * x[1], gw = G0 * z[0] + G1 * z[1];
		double og = o00 - k2;
		Aq[0] += og * gu * gu + k2 * (ci[0] * x[0] * x[0] + ci[1] * x[1] * x[1]) + 2.0 * o01 * gu * x[2] + o11 * x[2] * x[2];
		Aq[1] += og * gu * gw + k2 * (ci[0] * x[0] * z[0] + ci[1] * x[1] * z[1]) + o01 * (gu * z[2] + gw * x[2]) + o11 * x[2] * z[2];
		Aq[2] += og * gw * gw + k2 * (ci[0] * z[0] * z[0] + ci[1] * z[1] * z[1]) + 2.0 * o01 * gw * z[2] + o11 * z[2] * z[2];
	}
	if (hess) {
		A[0] = Aq[0];
		A[1] = Aq[1];
		A[2] = Aq[2];
	}
}

/* Both superquadrics' support at y1 and y2. */
MK_PAIR_FN void mkSupBody_Eval2(const mkSupBody *b1, mkVec3 y1, mkSupAt *a1, const mkSupBody *b2, mkVec3 y2, mkSupAt *a2)
{
	const mkSupBody *b[MK_LANES] = { b1, b2 };
	mkSupAt *a[MK_LANES] = { a1, a2 };
	mkVec3 y[MK_LANES] = { y1, y2 };
	mkSupBody_EvalLanes(2, b, y, a);
}

MK_PAIR_FN double mkPair_Eval(const mkPairCtx *c, mkVec3 m, mkPairAt *e)
{
	if (!c->k1.ellipsoid && !c->k2.ellipsoid) {
		mkSupBody_Eval2(&c->k1, m, &e->a1, &c->k2, mkVec3_Neg(m), &e->a2);
	} else {
		mkSupBody_Eval(&c->k1, m, &e->a1);
		mkSupBody_Eval(&c->k2, mkVec3_Neg(m), &e->a2);
	}
	e->x = mkVec3_Sub(e->a1.s, e->a2.s);
	e->H = mkVec3_Dot(m, e->x);
	return e->H;
}

/* mkPair_Eval at n <= MK_LANES / 2 directions; a pair of superquadrics in
 * lock-step (the same arithmetic per direction, so the same results):
 * independent directions fill the processor where one waits on its chains
 * of libm calls. */
MK_PAIR_FN void mkPair_EvalN(const mkPairCtx *c, int n, const mkVec3 m[], mkPairAt e[])
{
	if (c->k1.ellipsoid || c->k2.ellipsoid || n < 2) {
		for (int k = 0; k < n; ++k)
			mkPair_Eval(c, m[k], &e[k]);
		return;
	}
	const mkSupBody *b[MK_LANES];
	mkVec3 y[MK_LANES];
	mkSupAt *a[MK_LANES];
	for (int k = 0; k < n; ++k) {
		b[2 * k] = &c->k1;
		b[2 * k + 1] = &c->k2;
		y[2 * k] = m[k];
		y[2 * k + 1] = mkVec3_Neg(m[k]);
		a[2 * k] = &e[k].a1;
		a[2 * k + 1] = &e[k].a2;
	}
	mkSupBody_EvalLanes(2 * n, b, y, a);
	for (int k = 0; k < n; ++k) {
		e[k].x = mkVec3_Sub(e[k].a1.s, e[k].a2.s);
		e[k].H = mkVec3_Dot(m[k], e[k].x);
	}
}

/* The Jacobian of x in the plane of (t1, t2): A[i][j] = ti^T J tj. */
MK_PAIR_FN void mkPair_Tangent(const mkPairCtx *c, const mkPairAt *e, mkVec3 t1, mkVec3 t2, double A[2][2])
{
	double a[3] = { 0.0, 0.0, 0.0 };
	mkSupAt_Tangent(&c->k1, &e->a1, t1, t2, a);
	mkSupAt_Tangent(&c->k2, &e->a2, t1, t2, a);
	A[0][0] = a[0];
	A[0][1] = A[1][0] = a[1];
	A[1][1] = a[2];
}

/* An orthonormal basis (t1, t2) of the plane orthogonal to the unit n
 * (Frisvad's construction, in the branch-free form of Duff et al. 2017). */
MK_PAIR_INLINE void mkTangents(mkVec3 n, mkVec3 *t1, mkVec3 *t2)
{
	double sign = n.z >= 0.0 ? 1.0 : -1.0;
	double a = -1.0 / (sign + n.z);
	double b = n.x * n.y * a;
	*t1 = mkVec3_Make(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
	*t2 = mkVec3_Make(b, sign + n.y * n.y * a, -n.y);
}

/* The trust-region step of the model  m(s) = -g.s + 1/2 s^T A s  (A 2 x 2
 * symmetric) within |s| <= radius: the Newton step when A is positive
 * definite and it fits, else (A + mu I) s = g with mu >= max(0, -lambda_min)
 * on the boundary (Newton on the secular equation; the "hard case" adds the
 * lowest eigenvector). Returns the predicted increase g.s - 1/2 s^T A s. */
/* Eigen-decomposition of a symmetric 2 x 2 matrix: lam[0] <= lam[1] with
 * unit eigenvectors v0, v1. */
MK_PAIR_FN void mkEig2(double A[2][2], double lam[2], double v0[2], double v1[2])
{
	double a = A[0][0], b = 0.5 * (A[0][1] + A[1][0]), c = A[1][1];
	double mean = 0.5 * (a + c), half = 0.5 * (a - c);
	double rad = mkLen2(half, b);
	lam[0] = mean - rad;
	lam[1] = mean + rad;
	if (rad == 0.0) {
		v1[0] = 1.0; v1[1] = 0.0;
	} else if (half >= 0.0) {
		double nx = half + rad, ny = b, nn = mkLen2(nx, ny);
		v1[0] = nx / nn; v1[1] = ny / nn;
	} else {
		double nx = b, ny = rad - half, nn = mkLen2(nx, ny);
		v1[0] = nx / nn; v1[1] = ny / nn;
	}
	v0[0] = -v1[1];
	v0[1] = v1[0];
}

MK_PAIR_FN double mkTrustStep(const double g[2], double A[2][2], double radius, double s[2])
{
	/* The common case first: A positive definite and the Newton step inside
	 * the region (Cramer's rule; pred = g.s / 2 for the Newton step). */
	double a = A[0][0], b = 0.5 * (A[0][1] + A[1][0]), c = A[1][1], det = a * c - b * b;
	if (a > 0.0 && det > 1e-12 * (a * c)) {
		double z0 = (c * g[0] - b * g[1]) / det, z1 = (a * g[1] - b * g[0]) / det;
		if (z0 * z0 + z1 * z1 <= radius * radius) {
			s[0] = z0;
			s[1] = z1;
			return 0.5 * (g[0] * z0 + g[1] * z1);
		}
	}
	double lam2[2], v0[2], v1[2];
	mkEig2(A, lam2, v0, v1);
	double l0 = lam2[0], l1 = lam2[1];
	double v0x = v0[0], v0y = v0[1], v1x = v1[0], v1y = v1[1];
	double g0 = v0x * g[0] + v0y * g[1], g1 = v1x * g[0] + v1y * g[1];
	double lam[2] = { l0, l1 }, gg[2] = { g0, g1 }, z[2];
	double mu = 0.0;
	int newton_ok = l0 > 0.0;
	if (newton_ok) {
		z[0] = g0 / l0;
		z[1] = g1 / l1;
		newton_ok = mkLen2(z[0], z[1]) <= radius;
	}
	if (!newton_ok) {
		double lo = l0 > 0.0 ? 0.0 : -l0;
		/* Start just right of the pole; Newton on 1/|s(mu)| - 1/radius is
		 * monotone from the left. */
		double gn = mkLen2(g0, g1);
		mu = lo + 1e-14 * (fabs(l0) + fabs(l1) + gn / radius) + DBL_MIN;
		double norm = 0.0;
		for (int it = 0; it < 60; ++it) {
			double n2 = 0.0, d3 = 0.0;
			for (int i = 0; i < 2; ++i) {
				double den = lam[i] + mu;
				z[i] = gg[i] / den;
				n2 += z[i] * z[i];
				d3 += z[i] * z[i] / den;
			}
			norm = sqrt(n2);
			if (norm <= radius * (1.0 + 1e-10))
				break;
			double step = (norm - radius) / radius * n2 / d3;
			mu += step;
		}
		if (norm < radius * (1.0 - 1e-6) && l0 <= 0.0) {
			/* Hard case: fill the step to the boundary along v0. */
			double extra = sqrt(radius * radius - norm * norm);
			z[0] += z[0] >= 0.0 ? extra : -extra;
		}
	}
	s[0] = v0x * z[0] + v1x * z[1];
	s[1] = v0y * z[0] + v1y * z[1];
	return g0 * z[0] + g1 * z[1] - 0.5 * (l0 * z[0] * z[0] + l1 * z[1] * z[1]);
}

/* ---- exact line searches ------------------------------------------------ */

/* One probe of a function of one variable t: its value and derivative. */
typedef void (*mkLineFn)(void *ctx, double t, double *v, double *dv);

/* Maximises a function v(t) of one variable that is concave (MinkSum (Ray):
 * -psi along a line) or concave near its maximum (MinkSum (Normal): f along
 * a great circle), from t = 0, where its value is v0 and its slope d0 > 0.
 * The bracket [0, h] is widened by 4 while the slope at its end is still
 * positive; then each step probes where the tangent lines at the bracket's
 * two ends cross (on a concave function they bound it from above there; on
 * a piecewise linear one that point is the kink itself, so a nearly kinked
 * support function, where Newton's model fails, takes a few probes instead
 * of a bisection to rounding), or the midpoint when the last step did not
 * halve the bracket, and keeps the end whose slope has the same sign. It
 * stops when the tangent lines' bound is within 4 ulps of the best value
 * found (|v| + scale), or when no double lies inside the bracket; then it
 * returns 1 (converged), else 0 (out of probes, or the slope never turned).
 * The probes themselves keep the best point (fn's context). */
MK_PAIR_FN int mkLine_Max(mkLineFn fn, void *ctx, double h, double v0, double d0, double scale)
{
	double lo = 0.0, vlo = v0, dlo = d0, hi = h, vhi, dhi;
	double best = v0;
	fn(ctx, hi, &vhi, &dhi);
	for (int k = 0; dhi > 0.0 && k < 40 && hi < 1e8; ++k) {
		best = fmax(best, vhi);
		lo = hi;
		vlo = vhi;
		dlo = dhi;
		hi *= 4.0;
		fn(ctx, hi, &vhi, &dhi);
	}
	best = fmax(best, vhi);
	if (!(dhi <= 0.0))
		return 0; /* still rising (or NaN) */
	int halved = 1;
	for (int k = 0; k < 100; ++k) {
		double t = 0.5 * (lo + hi);
		if (dlo - dhi > 0.0) {
			double cross = (vhi - vlo + dlo * lo - dhi * hi) / (dlo - dhi);
			double bound = vlo + dlo * (cross - lo);
			if (bound - best <= 4.0 * DBL_EPSILON * (fabs(best) + scale))
				return 1;
			if (halved && cross > lo && cross < hi)
				t = cross;
		}
		if (!(t > lo && t < hi))
			return 1; /* the bracket is down to adjacent doubles */
		double v, dv, width = hi - lo;
		fn(ctx, t, &v, &dv);
		best = fmax(best, v);
		if (dv > 0.0) {
			lo = t;
			vlo = v;
			dlo = dv;
		} else {
			hi = t;
			vhi = v;
			dhi = dv;
		}
		halved = hi - lo <= 0.5 * width;
	}
	return 0;
}

/* ---- the pair's context ------------------------------------------------- */

MK_PAIR_FN int mkIsFinite3(mkVec3 v)
{
	return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

MK_PAIR_FN double mkScale(const mkBody3 *b1, const mkBody3 *b2)
{
	double r[2];
	const mkBody3 *b[2] = { b1, b2 };
	for (int k = 0; k < 2; ++k) {
		double fro = 0.0;
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				fro += b[k]->M.m[i][j] * b[k]->M.m[i][j];
		mkShape3 s = b[k]->shape;
		double big = s.a > s.b ? s.a : s.b;
		r[k] = (big > s.c ? big : s.c) * sqrt(fro);
	}
	return mkVec3_LengthInline(mkVec3_Sub(b2->t, b1->t)) + r[0] + r[1];
}

MK_PAIR_FN void mkPairCtx_Init(mkPairCtx *c, const mkBody3 *b1, const mkBody3 *b2)
{
	c->b1 = b1;
	c->b2 = b2;
	mkSupBody_Init(&c->k1, b1);
	mkSupBody_Init(&c->k2, b2);
	c->d = mkVec3_Sub(b2->t, b1->t);
	c->scale = mkScale(b1, b2);
}

/* The start of both queries (after clearing out): the pair's context set
 * up, out's scale; MK_ERR_UNSUPPORTED when the scale is not finite. */
static inline mkResult mkPairCtx_Begin(mkPairCtx *c, const mkBody3 *b1, const mkBody3 *b2, mkCollision3 *out)
{
	mkPairCtx_Init(c, b1, b2);
	out->scale = c->scale;
	return isfinite(c->scale) ? MK_OK : MK_ERR_UNSUPPORTED;
}

#endif
