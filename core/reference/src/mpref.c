/* mpref.c - the 256-bit MPFR model of mpref.h.
 *
 * Derivations (y is the point in units of the semi-axes: y_i = x_i / a_i, and
 * w_i = a_i d_i is the direction seen in the same units, so <d, x> = <w, y>):
 *
 * Support, 2D. The body is |y|_p <= 1 with p = 2/eps. Hoelder's inequality
 * gives <w, y> <= |w|_q |y|_p with 1/p + 1/q = 1, i.e. q = 2/(2 - eps), so
 * h(d) = |w|_q. Equality holds for |y_i|^p proportional to |w_i|^q with the
 * signs of w: y_i = sp(w_i/h, q - 1), because (q - 1) p = q makes
 * sum |y_i|^p = sum |w_i/h|^q = 1, and <w, y> = h sum |w_i/h|^q = h.
 *
 * Support, 3D. The body is N(y) = |(R, |y3|)|_p1 <= 1 with R = |(y1, y2)|_p2
 * (Psi = N^p1). Hoelder twice: <w, y> <= G R + |w3| |y3| <= |(G, w3)|_q1 N(y)
 * with G = |(w1, w2)|_q2, so h(d) = |(G, w3)|_q1. Equality in the outer step
 * needs (R, |y3|) = ((G/h)^(q1-1), |w3/h|^(q1-1)), in the inner one
 * (y1, y2) = R sp((w1, w2)/G, q2 - 1): the point is
 *   y_1,2 = (G/h)^(q1-1) sp(w_1,2 / G, q2 - 1),   y3 = sp(w3/h, q1 - 1).
 *
 * Gradient inverse, 3D. Differentiating Psi and substituting f(u) gives
 *   g(u) = (2/(e1 a) r^(e2-e1) sp(u1, 2-e2), 2/(e1 b) r^(e2-e1) sp(u2, 2-e2),
 *           2/(e1 c) sp(u3, 2-e1)),  r = |(u1, u2)|.
 * Write (u1, u2) = r (cw, sw). g(u) = lambda m with K = lambda e1 / 2 gives
 * sp(cw, 2-e2) r^(2-e1) = K a m1 (and so for b m2) and sp(u3, 2-e1) = K c m3.
 * Hence (cw, sw) is the unit vector along alpha_i = sp(a_i m_i, 1/(2-e2));
 * then sp(cw, 2-e2) = a m1 / |alpha|^(2-e2), so r^(2-e1) = K |alpha|^(2-e2),
 * and u3 = K^(1/(2-e1)) sp(c m3, 1/(2-e1)). The common factor K^(1/(2-e1))
 * drops out when (r, u3) is scaled to unit length. 2D: u_i is along
 * sp(a_i m_i, 1/(2-eps)). */
#include <mink/mpref.h>

#include <assert.h>

#define RND MPFR_RNDN

/* ---- small helpers ----------------------------------------------------- */

static void refInit(mpfr_t v)
{
	mpfr_init2(v, REF_PREC);
	mpfr_set_zero(v, 1);
}

void refVec_Init(refVec *v)
{
	for (int i = 0; i < 3; ++i)
		refInit(v->c[i]);
}

void refVec_Clear(refVec *v)
{
	for (int i = 0; i < 3; ++i)
		mpfr_clear(v->c[i]);
}

void refVec_Set(refVec *dst, const refVec *src)
{
	for (int i = 0; i < 3; ++i)
		mpfr_set(dst->c[i], src->c[i], RND);
}

void refVec_FromD(refVec *v, int dim, const double *d)
{
	for (int i = 0; i < 3; ++i) {
		if (i < dim)
			mpfr_set_d(v->c[i], d[i], RND); /* exact: 53 < 256 bits */
		else
			mpfr_set_zero(v->c[i], 1);
	}
}

void refVec_ToD(const refVec *v, int dim, double *d)
{
	for (int i = 0; i < dim; ++i)
		d[i] = mpfr_get_d(v->c[i], RND);
}

double refVec_NormD(const refVec *v, int dim)
{
	mpfr_t s, t;
	refInit(s);
	refInit(t);
	for (int i = 0; i < dim; ++i) {
		mpfr_sqr(t, v->c[i], RND);
		mpfr_add(s, s, t, RND);
	}
	mpfr_sqrt(s, s, RND);
	double r = mpfr_get_d(s, RND);
	mpfr_clear(s);
	mpfr_clear(t);
	return r;
}

double refVec_DistD(const refVec *v, int dim, const double *d)
{
	refVec w;
	refVec_Init(&w);
	for (int i = 0; i < dim; ++i)
		mpfr_sub_d(w.c[i], v->c[i], d[i], RND);
	double r = refVec_NormD(&w, dim);
	refVec_Clear(&w);
	return r;
}

void refVec_Dot(mpfr_t out, const refVec *v, const refVec *w, int dim)
{
	mpfr_t t;
	refInit(t);
	mpfr_set_zero(out, 1);
	for (int i = 0; i < dim; ++i) {
		mpfr_mul(t, v->c[i], w->c[i], RND);
		mpfr_add(out, out, t, RND);
	}
	mpfr_clear(t);
}

void refVec_Normalize(refVec *v, int dim)
{
	mpfr_t s, t;
	refInit(s);
	refInit(t);
	for (int i = 0; i < dim; ++i) {
		mpfr_sqr(t, v->c[i], RND);
		mpfr_add(s, s, t, RND);
	}
	mpfr_sqrt(s, s, RND);
	assert(!mpfr_zero_p(s));
	for (int i = 0; i < dim; ++i)
		mpfr_div(v->c[i], v->c[i], s, RND);
	mpfr_clear(s);
	mpfr_clear(t);
}

void refSp(mpfr_t out, const mpfr_t v, const mpfr_t e)
{
	if (mpfr_zero_p(v)) {
		mpfr_set_zero(out, 1);
		return;
	}
	int neg = mpfr_sgn(v) < 0;
	mpfr_abs(out, v, RND);
	mpfr_pow(out, out, e, RND);
	if (neg)
		mpfr_neg(out, out, RND);
}

/* |(x, y)|_q = (|x|^q + |y|^q)^(1/q). */
static void refNormQ(mpfr_t out, const mpfr_t x, const mpfr_t y, const mpfr_t q)
{
	mpfr_t s, t;
	refInit(s);
	refInit(t);
	mpfr_abs(t, x, RND);
	mpfr_pow(s, t, q, RND);
	mpfr_abs(t, y, RND);
	mpfr_pow(t, t, q, RND);
	mpfr_add(s, s, t, RND);
	mpfr_ui_div(t, 1, q, RND);
	mpfr_pow(out, s, t, RND);
	mpfr_clear(s);
	mpfr_clear(t);
}

/* q = 2 / (2 - e), the dual exponent of p = 2 / e. */
static void refDualExponent(mpfr_t q, double e)
{
	mpfr_t t;
	refInit(t);
	mpfr_set_d(t, e, RND);
	mpfr_ui_sub(t, 2, t, RND);
	mpfr_ui_div(q, 2, t, RND);
	mpfr_clear(t);
}

/* ---- canonical shape --------------------------------------------------- */

void refShape_Point(refShape s, const refVec *u0, refVec *x)
{
	refVec u;
	mpfr_t e1, e2, r, t;
	refVec_Init(&u);
	refInit(e1);
	refInit(e2);
	refInit(r);
	refInit(t);
	refVec_Set(&u, u0);
	refVec_Normalize(&u, s.dim);
	mpfr_set_d(e1, s.e1, RND);
	if (s.dim == 2) {
		for (int i = 0; i < 2; ++i) {
			refSp(t, u.c[i], e1);
			mpfr_mul_d(x->c[i], t, s.a[i], RND);
		}
		mpfr_set_zero(x->c[2], 1);
	} else {
		mpfr_set_d(e2, s.e2, RND);
		mpfr_hypot(r, u.c[0], u.c[1], RND);
		if (mpfr_zero_p(r)) {
			mpfr_set_zero(x->c[0], 1);
			mpfr_set_zero(x->c[1], 1);
		} else {
			mpfr_t re;
			refInit(re);
			mpfr_pow(re, r, e1, RND);
			for (int i = 0; i < 2; ++i) {
				mpfr_div(t, u.c[i], r, RND);
				refSp(t, t, e2);
				mpfr_mul(t, t, re, RND);
				mpfr_mul_d(x->c[i], t, s.a[i], RND);
			}
			mpfr_clear(re);
		}
		refSp(t, u.c[2], e1);
		mpfr_mul_d(x->c[2], t, s.a[2], RND);
	}
	refVec_Clear(&u);
	mpfr_clear(e1);
	mpfr_clear(e2);
	mpfr_clear(r);
	mpfr_clear(t);
}

void refShape_Implicit(refShape s, const refVec *x, mpfr_t psi)
{
	mpfr_t p1, p2, t, a, b;
	refInit(p1);
	refInit(p2);
	refInit(t);
	refInit(a);
	refInit(b);
	mpfr_set_d(t, s.e1, RND);
	mpfr_ui_div(p1, 2, t, RND);
	if (s.dim == 2) {
		mpfr_div_d(a, x->c[0], s.a[0], RND);
		mpfr_abs(a, a, RND);
		mpfr_pow(a, a, p1, RND);
		mpfr_div_d(b, x->c[1], s.a[1], RND);
		mpfr_abs(b, b, RND);
		mpfr_pow(b, b, p1, RND);
		mpfr_add(psi, a, b, RND);
	} else {
		mpfr_set_d(t, s.e2, RND);
		mpfr_ui_div(p2, 2, t, RND);
		mpfr_div_d(a, x->c[0], s.a[0], RND);
		mpfr_abs(a, a, RND);
		mpfr_pow(a, a, p2, RND);
		mpfr_div_d(b, x->c[1], s.a[1], RND);
		mpfr_abs(b, b, RND);
		mpfr_pow(b, b, p2, RND);
		mpfr_add(a, a, b, RND);
		mpfr_div(t, p1, p2, RND);
		mpfr_pow(a, a, t, RND);
		mpfr_div_d(b, x->c[2], s.a[2], RND);
		mpfr_abs(b, b, RND);
		mpfr_pow(b, b, p1, RND);
		mpfr_add(psi, a, b, RND);
	}
	mpfr_clear(p1);
	mpfr_clear(p2);
	mpfr_clear(t);
	mpfr_clear(a);
	mpfr_clear(b);
}

void refShape_Gradient(refShape s, const refVec *x, refVec *m)
{
	/* 2D: dPsi/dx_i = (p / a_i) sp(y_i, p - 1).
	 * 3D: dPsi/dx_i = (p1 / a_i) psi^(p1/p2 - 1) sp(y_i, p2 - 1), i = 1, 2,
	 *     psi = |y1|^p2 + |y2|^p2, and dPsi/dx3 = (p1 / c) sp(y3, p1 - 1).
	 * When psi = 0 the first two vanish: the product is bounded by
	 * psi^((p1 - 1)/p2), and p1 > 1. */
	mpfr_t p1, p2, pm1, y, t, psi;
	refInit(p1);
	refInit(p2);
	refInit(pm1);
	refInit(y);
	refInit(t);
	refInit(psi);
	mpfr_set_d(t, s.e1, RND);
	mpfr_ui_div(p1, 2, t, RND);
	if (s.dim == 2) {
		mpfr_sub_ui(pm1, p1, 1, RND);
		for (int i = 0; i < 2; ++i) {
			mpfr_div_d(y, x->c[i], s.a[i], RND);
			refSp(t, y, pm1);
			mpfr_mul(t, t, p1, RND);
			mpfr_div_d(m->c[i], t, s.a[i], RND);
		}
		mpfr_set_zero(m->c[2], 1);
	} else {
		mpfr_set_d(t, s.e2, RND);
		mpfr_ui_div(p2, 2, t, RND);
		for (int i = 0; i < 2; ++i) {
			mpfr_div_d(y, x->c[i], s.a[i], RND);
			mpfr_abs(y, y, RND);
			mpfr_pow(y, y, p2, RND);
			mpfr_add(psi, psi, y, RND);
		}
		if (mpfr_zero_p(psi)) {
			mpfr_set_zero(m->c[0], 1);
			mpfr_set_zero(m->c[1], 1);
		} else {
			mpfr_t f;
			refInit(f);
			mpfr_div(t, p1, p2, RND);
			mpfr_sub_ui(t, t, 1, RND);
			mpfr_pow(f, psi, t, RND);
			mpfr_mul(f, f, p1, RND);
			mpfr_sub_ui(pm1, p2, 1, RND);
			for (int i = 0; i < 2; ++i) {
				mpfr_div_d(y, x->c[i], s.a[i], RND);
				refSp(t, y, pm1);
				mpfr_mul(t, t, f, RND);
				mpfr_div_d(m->c[i], t, s.a[i], RND);
			}
			mpfr_clear(f);
		}
		mpfr_sub_ui(pm1, p1, 1, RND);
		mpfr_div_d(y, x->c[2], s.a[2], RND);
		refSp(t, y, pm1);
		mpfr_mul(t, t, p1, RND);
		mpfr_div_d(m->c[2], t, s.a[2], RND);
	}
	mpfr_clear(p1);
	mpfr_clear(p2);
	mpfr_clear(pm1);
	mpfr_clear(y);
	mpfr_clear(t);
	mpfr_clear(psi);
}

/* The support value and, when x is not NULL, the support point. */
static void refShape_SupportBoth(refShape s, const refVec *d, mpfr_t h, refVec *x)
{
	refVec w;
	mpfr_t q1, q1m, t;
	refVec_Init(&w);
	refInit(q1);
	refInit(q1m);
	refInit(t);
	int n = s.dim;
	for (int i = 0; i < n; ++i)
		mpfr_mul_d(w.c[i], d->c[i], s.a[i], RND);
	refDualExponent(q1, s.e1);
	mpfr_sub_ui(q1m, q1, 1, RND);
	if (n == 2) {
		refNormQ(h, w.c[0], w.c[1], q1);
		assert(!mpfr_zero_p(h));
		if (x) {
			for (int i = 0; i < 2; ++i) {
				mpfr_div(t, w.c[i], h, RND);
				refSp(t, t, q1m);
				mpfr_mul_d(x->c[i], t, s.a[i], RND);
			}
			mpfr_set_zero(x->c[2], 1);
		}
	} else {
		mpfr_t q2, q2m, G;
		refInit(q2);
		refInit(q2m);
		refInit(G);
		refDualExponent(q2, s.e2);
		mpfr_sub_ui(q2m, q2, 1, RND);
		refNormQ(G, w.c[0], w.c[1], q2);
		refNormQ(h, G, w.c[2], q1);
		assert(!mpfr_zero_p(h));
		if (x) {
			if (mpfr_zero_p(G)) {
				mpfr_set_zero(x->c[0], 1);
				mpfr_set_zero(x->c[1], 1);
			} else {
				mpfr_t R;
				refInit(R);
				mpfr_div(R, G, h, RND);
				mpfr_pow(R, R, q1m, RND);
				for (int i = 0; i < 2; ++i) {
					mpfr_div(t, w.c[i], G, RND);
					refSp(t, t, q2m);
					mpfr_mul(t, t, R, RND);
					mpfr_mul_d(x->c[i], t, s.a[i], RND);
				}
				mpfr_clear(R);
			}
			mpfr_div(t, w.c[2], h, RND);
			refSp(t, t, q1m);
			mpfr_mul_d(x->c[2], t, s.a[2], RND);
		}
		mpfr_clear(q2);
		mpfr_clear(q2m);
		mpfr_clear(G);
	}
	refVec_Clear(&w);
	mpfr_clear(q1);
	mpfr_clear(q1m);
	mpfr_clear(t);
}

/* The support point by logarithms (mpref.h): with L_i = log|w_i| every
 * power of the formulas above is an exponential of a sum of logs, so each
 * |w_i| is taken to a logarithm once instead of once per power:
 *   2D  Lh = log(sum exp(q L_i)) / q,  y_i = sg(w_i) exp((q-1)(L_i - Lh));
 *   3D  LG = log(exp(q2 L1) + exp(q2 L2)) / q2, Lh = log(exp(q1 LG) + exp(q1 L3)) / q1,
 *       y_1,2 = sg exp((q2-1)(L_i - LG) + (q1-1)(LG - Lh)),  y3 = sg exp((q1-1)(L3 - Lh)).
 * A zero w_i has no term and y_i = 0, as in refShape_SupportBoth. An
 * argument q L of exp carries a rounding of about |q L| 2^-256 absolute,
 * which is the relative error of the result: q = 2e6 at eps = 2 - 1e-6 and
 * |L| < 50 for directions of size 1e-20 ... 1e20 give |q L| < 2^27, so the
 * point is exact to about 2^-228 relative (1e-68) instead of 2^-256. */
void refShape_SupportByLogs(refShape s, const refVec *d, refVec *x)
{
	int n = s.dim;
	mpfr_t L[3], q1, q1m, q2, q2m, t, u, sum, Lh, LG;
	for (int i = 0; i < 3; ++i)
		refInit(L[i]);
	refInit(q1);
	refInit(q1m);
	refInit(q2);
	refInit(q2m);
	refInit(t);
	refInit(u);
	refInit(sum);
	refInit(Lh);
	refInit(LG);
	int zero[3] = { 1, 1, 1 }, neg[3] = { 0, 0, 0 };
	for (int i = 0; i < n; ++i) {
		mpfr_mul_d(t, d->c[i], s.a[i], RND);
		zero[i] = mpfr_zero_p(t) != 0;
		neg[i] = mpfr_sgn(t) < 0;
		if (!zero[i]) {
			mpfr_abs(t, t, RND);
			mpfr_log(L[i], t, RND);
		}
	}
	refDualExponent(q1, s.e1);
	mpfr_sub_ui(q1m, q1, 1, RND);
	/* The block of (w1, w2) in 3D; in 2D the whole of w. */
	int blockZero = 0;
	mpfr_t *qb = n == 2 ? &q1 : &q2;
	if (n == 3) {
		refDualExponent(q2, s.e2);
		mpfr_sub_ui(q2m, q2, 1, RND);
	}
	mpfr_set_zero(sum, 1);
	for (int i = 0; i < 2; ++i)
		if (!zero[i]) {
			mpfr_mul(t, *qb, L[i], RND);
			mpfr_exp(t, t, RND);
			mpfr_add(sum, sum, t, RND);
		}
	blockZero = mpfr_zero_p(sum) != 0;
	if (n == 2) {
		assert(!blockZero);
		mpfr_log(Lh, sum, RND);
		mpfr_div(Lh, Lh, q1, RND);
		for (int i = 0; i < 2; ++i) {
			if (zero[i]) {
				mpfr_set_zero(x->c[i], 1);
				continue;
			}
			mpfr_sub(t, L[i], Lh, RND);
			mpfr_mul(t, t, q1m, RND);
			mpfr_exp(t, t, RND);
			mpfr_mul_d(x->c[i], t, neg[i] ? -s.a[i] : s.a[i], RND);
		}
		mpfr_set_zero(x->c[2], 1);
	} else {
		if (!blockZero) {
			mpfr_log(LG, sum, RND);
			mpfr_div(LG, LG, q2, RND);
		}
		mpfr_set_zero(sum, 1);
		if (!blockZero) {
			mpfr_mul(t, q1, LG, RND);
			mpfr_exp(t, t, RND);
			mpfr_add(sum, sum, t, RND);
		}
		if (!zero[2]) {
			mpfr_mul(t, q1, L[2], RND);
			mpfr_exp(t, t, RND);
			mpfr_add(sum, sum, t, RND);
		}
		assert(!mpfr_zero_p(sum));
		mpfr_log(Lh, sum, RND);
		mpfr_div(Lh, Lh, q1, RND);
		for (int i = 0; i < 2; ++i) {
			if (zero[i]) {
				mpfr_set_zero(x->c[i], 1);
				continue;
			}
			mpfr_sub(t, L[i], LG, RND);
			mpfr_mul(t, t, q2m, RND);
			mpfr_sub(u, LG, Lh, RND);
			mpfr_mul(u, u, q1m, RND);
			mpfr_add(t, t, u, RND);
			mpfr_exp(t, t, RND);
			mpfr_mul_d(x->c[i], t, neg[i] ? -s.a[i] : s.a[i], RND);
		}
		if (zero[2]) {
			mpfr_set_zero(x->c[2], 1);
		} else {
			mpfr_sub(t, L[2], Lh, RND);
			mpfr_mul(t, t, q1m, RND);
			mpfr_exp(t, t, RND);
			mpfr_mul_d(x->c[2], t, neg[2] ? -s.a[2] : s.a[2], RND);
		}
	}
	for (int i = 0; i < 3; ++i)
		mpfr_clear(L[i]);
	mpfr_clears(q1, q1m, q2, q2m, t, u, sum, Lh, LG, (mpfr_ptr)0);
}

void refShape_Support(refShape s, const refVec *d, refVec *x)
{
	mpfr_t h;
	refInit(h);
	refShape_SupportBoth(s, d, h, x);
	mpfr_clear(h);
}

void refShape_SupportValue(refShape s, const refVec *d, mpfr_t h)
{
	refShape_SupportBoth(s, d, h, NULL);
}

void refShape_FromGradientInverse(refShape s, const refVec *m, refVec *x)
{
	refVec u;
	mpfr_t e, t;
	refVec_Init(&u);
	refInit(e);
	refInit(t);
	if (s.dim == 2) {
		/* u_i along sp(a_i m_i, 1/(2 - eps)). */
		mpfr_set_d(t, s.e1, RND);
		mpfr_ui_sub(t, 2, t, RND);
		mpfr_ui_div(e, 1, t, RND);
		for (int i = 0; i < 2; ++i) {
			mpfr_mul_d(t, m->c[i], s.a[i], RND);
			refSp(u.c[i], t, e);
		}
	} else {
		mpfr_t al0, al1, ra, r;
		refInit(al0);
		refInit(al1);
		refInit(ra);
		refInit(r);
		/* alpha_i = sp(a_i m_i, 1/(2 - e2)). */
		mpfr_set_d(t, s.e2, RND);
		mpfr_ui_sub(t, 2, t, RND);
		mpfr_ui_div(e, 1, t, RND);
		mpfr_mul_d(t, m->c[0], s.a[0], RND);
		refSp(al0, t, e);
		mpfr_mul_d(t, m->c[1], s.a[1], RND);
		refSp(al1, t, e);
		mpfr_hypot(ra, al0, al1, RND);
		/* r = |alpha|^((2 - e2)/(2 - e1)), u3 = sp(c m3, 1/(2 - e1)). */
		mpfr_set_d(t, s.e1, RND);
		mpfr_ui_sub(t, 2, t, RND);
		mpfr_set_d(e, s.e2, RND);
		mpfr_ui_sub(e, 2, e, RND);
		mpfr_div(e, e, t, RND);
		mpfr_pow(r, ra, e, RND);
		mpfr_ui_div(e, 1, t, RND);
		mpfr_mul_d(t, m->c[2], s.a[2], RND);
		refSp(u.c[2], t, e);
		if (mpfr_zero_p(ra)) {
			mpfr_set_zero(u.c[0], 1);
			mpfr_set_zero(u.c[1], 1);
		} else {
			mpfr_div(t, al0, ra, RND);
			mpfr_mul(u.c[0], t, r, RND);
			mpfr_div(t, al1, ra, RND);
			mpfr_mul(u.c[1], t, r, RND);
		}
		mpfr_clear(al0);
		mpfr_clear(al1);
		mpfr_clear(ra);
		mpfr_clear(r);
	}
	refShape_Point(s, &u, x);
	refVec_Clear(&u);
	mpfr_clear(e);
	mpfr_clear(t);
}

/* ---- placed body ------------------------------------------------------- */

/* M v, or M^T v when transpose is set. */
static void refMat_Product(const refMat *M, int dim, int transpose, const refVec *v, refVec *out)
{
	refVec r;
	mpfr_t t;
	refVec_Init(&r);
	refInit(t);
	for (int i = 0; i < dim; ++i)
		for (int j = 0; j < dim; ++j) {
			mpfr_mul_d(t, v->c[j], transpose ? M->m[j][i] : M->m[i][j], RND);
			mpfr_add(r.c[i], r.c[i], t, RND);
		}
	refVec_Set(out, &r);
	refVec_Clear(&r);
	mpfr_clear(t);
}

void refMat_MulVec(const refMat *M, int dim, const refVec *v, refVec *out)
{
	refMat_Product(M, dim, 0, v, out);
}

void refMat_MulTVec(const refMat *M, int dim, const refVec *v, refVec *out)
{
	refMat_Product(M, dim, 1, v, out);
}

/* M^-T v = cof(M) v / det(M), with cof the cofactor matrix; the products of
 * doubles are exact at this precision. */
void refMat_InvTVec(const refMat *M, int dim, const refVec *v, refVec *out)
{
	mpfr_t C[3][3], det, t;
	refInit(det);
	refInit(t);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			refInit(C[i][j]);
	if (dim == 2) {
		mpfr_set_d(C[0][0], M->m[1][1], RND);
		mpfr_set_d(C[0][1], -M->m[1][0], RND);
		mpfr_set_d(C[1][0], -M->m[0][1], RND);
		mpfr_set_d(C[1][1], M->m[0][0], RND);
	} else {
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j) {
				int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
				int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
				mpfr_set_d(C[i][j], M->m[i1][j1], RND);
				mpfr_mul_d(C[i][j], C[i][j], M->m[i2][j2], RND);
				mpfr_set_d(t, M->m[i1][j2], RND);
				mpfr_mul_d(t, t, M->m[i2][j1], RND);
				mpfr_sub(C[i][j], C[i][j], t, RND);
			}
	}
	for (int j = 0; j < dim; ++j) {
		mpfr_mul_d(t, C[0][j], M->m[0][j], RND);
		mpfr_add(det, det, t, RND);
	}
	assert(!mpfr_zero_p(det));
	refVec r;
	refVec_Init(&r);
	for (int i = 0; i < dim; ++i)
		for (int j = 0; j < dim; ++j) {
			mpfr_mul(t, C[i][j], v->c[j], RND);
			mpfr_add(r.c[i], r.c[i], t, RND);
		}
	for (int i = 0; i < dim; ++i)
		mpfr_div(out->c[i], r.c[i], det, RND);
	for (int i = dim; i < 3; ++i)
		mpfr_set_zero(out->c[i], 1);
	refVec_Clear(&r);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			mpfr_clear(C[i][j]);
	mpfr_clear(det);
	mpfr_clear(t);
}

void refBody_Point(const refBody *b, const refVec *u, refVec *x)
{
	refVec f;
	refVec_Init(&f);
	refShape_Point(b->s, u, &f);
	refMat_MulVec(&b->M, b->s.dim, &f, x);
	for (int i = 0; i < b->s.dim; ++i)
		mpfr_add_d(x->c[i], x->c[i], b->t[i], RND);
	refVec_Clear(&f);
}

void refBody_GradientAt(const refBody *b, const refVec *u, refVec *m)
{
	refVec f, g;
	refVec_Init(&f);
	refVec_Init(&g);
	refShape_Point(b->s, u, &f);
	refShape_Gradient(b->s, &f, &g);
	refMat_InvTVec(&b->M, b->s.dim, &g, m);
	refVec_Clear(&f);
	refVec_Clear(&g);
}

void refBody_Normal(const refBody *b, const refVec *u, refVec *n)
{
	refBody_GradientAt(b, u, n);
	refVec_Normalize(n, b->s.dim);
}

void refBody_Support(const refBody *b, const refVec *n, refVec *x)
{
	refVec d, s;
	refVec_Init(&d);
	refVec_Init(&s);
	refMat_MulTVec(&b->M, b->s.dim, n, &d);
	refShape_Support(b->s, &d, &s);
	refMat_MulVec(&b->M, b->s.dim, &s, x);
	for (int i = 0; i < b->s.dim; ++i)
		mpfr_add_d(x->c[i], x->c[i], b->t[i], RND);
	refVec_Clear(&d);
	refVec_Clear(&s);
}

void refBody_SupportValue(const refBody *b, const refVec *n, mpfr_t h)
{
	refVec d;
	mpfr_t t;
	refVec_Init(&d);
	refInit(t);
	refMat_MulTVec(&b->M, b->s.dim, n, &d);
	refShape_SupportValue(b->s, &d, h);
	for (int i = 0; i < b->s.dim; ++i) {
		mpfr_mul_d(t, n->c[i], b->t[i], RND);
		mpfr_add(h, h, t, RND);
	}
	refVec_Clear(&d);
	mpfr_clear(t);
}

/* ---- sums -------------------------------------------------------------- */

void refSum_Point(const refBody *b1, const refBody *b2, int plus, int surface,
	const refVec *u, refVec *x, refVec *k, refVec *n)
{
	int dim = b1->s.dim;
	refVec nn, kk, d, s2, p2;
	refVec_Init(&nn);
	refVec_Init(&kk);
	refVec_Init(&d);
	refVec_Init(&s2);
	refVec_Init(&p2);
	if (surface) {
		refBody_Point(b1, u, &kk);
		refBody_Normal(b1, u, &nn);
	} else {
		refVec_Set(&nn, u);
		refVec_Normalize(&nn, dim);
		refBody_Support(b1, &nn, &kk);
	}
	/* B2's point: the support point of the canonical B2 along +-M2^T n. */
	refMat_MulTVec(&b2->M, dim, &nn, &d);
	if (!plus)
		for (int i = 0; i < dim; ++i)
			mpfr_neg(d.c[i], d.c[i], RND);
	refShape_Support(b2->s, &d, &s2);
	refMat_MulVec(&b2->M, dim, &s2, &p2);
	for (int i = 0; i < dim; ++i) {
		if (plus) {
			mpfr_add(x->c[i], kk.c[i], p2.c[i], RND);
			mpfr_add_d(x->c[i], x->c[i], b2->t[i], RND);
		} else {
			mpfr_sub(x->c[i], kk.c[i], p2.c[i], RND);
		}
	}
	for (int i = dim; i < 3; ++i)
		mpfr_set_zero(x->c[i], 1);
	if (k)
		refVec_Set(k, &kk);
	if (n)
		refVec_Set(n, &nn);
	refVec_Clear(&nn);
	refVec_Clear(&kk);
	refVec_Clear(&d);
	refVec_Clear(&s2);
	refVec_Clear(&p2);
}

void refSum_SupportValue(const refBody *b1, const refBody *b2, int plus,
	const refVec *n, mpfr_t h)
{
	int dim = b1->s.dim;
	mpfr_t h2, t;
	refVec d;
	refInit(h2);
	refInit(t);
	refVec_Init(&d);
	refBody_SupportValue(b1, n, h);
	refMat_MulTVec(&b2->M, dim, n, &d);
	if (!plus)
		for (int i = 0; i < dim; ++i)
			mpfr_neg(d.c[i], d.c[i], RND);
	refShape_SupportValue(b2->s, &d, h2);
	mpfr_add(h, h, h2, RND);
	if (plus)
		for (int i = 0; i < dim; ++i) {
			mpfr_mul_d(t, n->c[i], b2->t[i], RND);
			mpfr_add(h, h, t, RND);
		}
	mpfr_clear(h2);
	mpfr_clear(t);
	refVec_Clear(&d);
}

void refThread_Release(void)
{
	mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
}
