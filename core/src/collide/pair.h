/* pair.h - a pair of placed bodies evaluated at a normal n: both support
 * points (B1's at n, B2's at -n), the contact-space point x = s1 - s2 and
 * its Jacobian in the tangent plane, for one direction or several in
 * lock-step; and the query's context (the bodies' constants, the centre
 * line d, the scale). Static definitions, the evaluation the solvers
 * iterate on. */
#ifndef MINK_COLLIDE_PAIR_H
#define MINK_COLLIDE_PAIR_H

#include "collide/support.h"

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
 * support points, values and weights are the same to the last bit.
 * One long function on purpose: the hot kernel of every Newton step, whose
 * stages share both bodies' reciprocals, weights and projections (helpers
 * would pass a dozen of them each way), inlined into its caller whole. */
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

/* The pair's context with its scale (mkScale) already known. */
MK_PAIR_FN void mkPairCtx_InitScaled(mkPairCtx *c, const mkBody3 *b1, const mkBody3 *b2, double scale)
{
	c->b1 = b1;
	c->b2 = b2;
	mkSupBody_Init(&c->k1, b1);
	mkSupBody_Init(&c->k2, b2);
	c->d = mkVec3_Sub(b2->t, b1->t);
	c->scale = scale;
}

MK_PAIR_FN void mkPairCtx_Init(mkPairCtx *c, const mkBody3 *b1, const mkBody3 *b2)
{
	mkPairCtx_InitScaled(c, b1, b2, mkScale(b1, b2));
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
