/* ref_selfcheck.c - the MPFR reference checks itself before it judges the
 * core: its separately derived maps must agree with each other and with the
 * definitions.
 *
 *  1. Psi(f(u)) = 1                        (parametric form vs implicit form)
 *  2. support(grad Psi(f(u))) = f(u)       (Hoelder's maximiser vs f)
 *  3. f(g^-1(grad Psi(f(u)))) = f(u)       (gradient inverse vs f)
 *  4. <d, support(d)> = h(d), Psi(support(d)) = 1
 *  5. ellipse (eps = 1): support(d) = A^2 d / |A d|, the hand-worked form
 *  6. h(d) is the maximum of <d, x> over the boundary: a dense sample of
 *     boundary points never exceeds it and comes within the sampling error
 *  7. M^T (M^-T v) = v
 *  8. grad Psi(support(d)) = (2/e1) d / h(d): Psi is the p1-th power of the
 *     body's norm, whose gradient at a boundary point with normal d is
 *     d / h(d) (Lemma 1's Phi is then (2/e1) |m| / h(m))
 * Tolerance: every quantity is computed at 256 bits (unit roundoff 2^-256,
 * about 9e-78). The longest chain is a few dozen operations, and the powers
 * amplify relative errors by at most their exponent (below 2/1e-3 = 2000) and
 * the semi-axis ratios used here (at most 1e4) once more, so 1e-50 relative
 * leaves more than 20 orders of magnitude of room while staying 30 orders
 * below anything a double can see. */
#include <mink/mpref.h>
#include "reftest.h"

#include <math.h>

#define SELF_TOL 1e-50

static const double epsList[] = { 1e-3, 0.01, 0.1, 0.5, 1.0, 1.5, 1.9, 1.99, 2.0 - 1e-3 };
#define EPS_COUNT ((int)(sizeof epsList / sizeof epsList[0]))

/* Relative difference |x - y| / |y| in double (the difference is taken in
 * MPFR, so nothing cancels in double). */
static double relDiff(const refVec *x, const refVec *y, int dim)
{
	refVec d;
	refVec_Init(&d);
	for (int i = 0; i < dim; ++i)
		mpfr_sub(d.c[i], x->c[i], y->c[i], MPFR_RNDN);
	double r = refVec_NormD(&d, dim) / refVec_NormD(y, dim);
	refVec_Clear(&d);
	return r;
}

static void checkShape(refShape s, refRng *rng, refStat *stat)
{
	refVec u, f, m, x, d;
	mpfr_t psi, h, t;
	refVec_Init(&u);
	refVec_Init(&f);
	refVec_Init(&m);
	refVec_Init(&x);
	refVec_Init(&d);
	mpfr_inits2(REF_PREC, psi, h, t, (mpfr_ptr)0);
	for (int trial = 0; trial < 20; ++trial) {
		double ud[3];
		refRng_Unit(rng, s.dim, ud);
		refVec_FromD(&u, s.dim, ud);
		refShape_Point(s, &u, &f);
		/* 1 */
		refShape_Implicit(s, &f, psi);
		mpfr_sub_ui(psi, psi, 1, MPFR_RNDN);
		double e1 = fabs(mpfr_get_d(psi, MPFR_RNDN));
		ENSURE_LE(e1, SELF_TOL, "Psi(f(u)) dim %d eps %g,%g", s.dim, s.e1, s.e2);
		refStat_Add(stat, e1);
		/* 2 */
		refShape_Gradient(s, &f, &m);
		refShape_Support(s, &m, &x);
		double e2 = relDiff(&x, &f, s.dim);
		ENSURE_LE(e2, SELF_TOL, "support(grad f) dim %d eps %g,%g", s.dim, s.e1, s.e2);
		refStat_Add(stat, e2);
		/* 3 */
		refShape_FromGradientInverse(s, &m, &x);
		double e3 = relDiff(&x, &f, s.dim);
		ENSURE_LE(e3, SELF_TOL, "f(g^-1(grad f)) dim %d eps %g,%g", s.dim, s.e1, s.e2);
		refStat_Add(stat, e3);
		/* 4 */
		refRng_Unit(rng, s.dim, ud);
		refVec_FromD(&d, s.dim, ud);
		refShape_Support(s, &d, &x);
		refShape_SupportValue(s, &d, h);
		refVec_Dot(t, &d, &x, s.dim);
		mpfr_sub(t, t, h, MPFR_RNDN);
		mpfr_div(t, t, h, MPFR_RNDN);
		double e4 = fabs(mpfr_get_d(t, MPFR_RNDN));
		ENSURE_LE(e4, SELF_TOL, "<d,s(d)> = h(d) dim %d eps %g,%g", s.dim, s.e1, s.e2);
		refStat_Add(stat, e4);
		refShape_Implicit(s, &x, psi);
		mpfr_sub_ui(psi, psi, 1, MPFR_RNDN);
		double e5 = fabs(mpfr_get_d(psi, MPFR_RNDN));
		ENSURE_LE(e5, SELF_TOL, "Psi(s(d)) dim %d eps %g,%g", s.dim, s.e1, s.e2);
		refStat_Add(stat, e5);
		/* 8 */
		refShape_Gradient(s, &x, &m);
		mpfr_set_d(t, s.e1, MPFR_RNDN);
		mpfr_ui_div(t, 2, t, MPFR_RNDN);
		mpfr_div(t, t, h, MPFR_RNDN);
		for (int i = 0; i < s.dim; ++i)
			mpfr_mul(f.c[i], d.c[i], t, MPFR_RNDN);
		double e6 = relDiff(&m, &f, s.dim);
		ENSURE_LE(e6, SELF_TOL, "grad Psi(s(d)) = (2/e1) d/h dim %d eps %g,%g", s.dim, s.e1, s.e2);
		refStat_Add(stat, e6);
	}
	refVec_Clear(&u);
	refVec_Clear(&f);
	refVec_Clear(&m);
	refVec_Clear(&x);
	refVec_Clear(&d);
	mpfr_clears(psi, h, t, (mpfr_ptr)0);
}

/* 5: the ellipse/ellipsoid support point A^2 d / |A d|, A = diag(a). */
static void checkEllipse(refShape s, refRng *rng, refStat *stat)
{
	refVec d, x, y;
	mpfr_t n, t;
	refVec_Init(&d);
	refVec_Init(&x);
	refVec_Init(&y);
	mpfr_inits2(REF_PREC, n, t, (mpfr_ptr)0);
	for (int trial = 0; trial < 20; ++trial) {
		double ud[3];
		refRng_Unit(rng, s.dim, ud);
		refVec_FromD(&d, s.dim, ud);
		refShape_Support(s, &d, &x);
		mpfr_set_zero(n, 1);
		for (int i = 0; i < s.dim; ++i) {
			mpfr_mul_d(t, d.c[i], s.a[i], MPFR_RNDN);
			mpfr_sqr(t, t, MPFR_RNDN);
			mpfr_add(n, n, t, MPFR_RNDN);
		}
		mpfr_sqrt(n, n, MPFR_RNDN);
		for (int i = 0; i < s.dim; ++i) {
			mpfr_mul_d(t, d.c[i], s.a[i], MPFR_RNDN);
			mpfr_mul_d(t, t, s.a[i], MPFR_RNDN);
			mpfr_div(y.c[i], t, n, MPFR_RNDN);
		}
		double e = relDiff(&x, &y, s.dim);
		ENSURE_LE(e, SELF_TOL, "ellipse support dim %d", s.dim);
		refStat_Add(stat, e);
	}
	refVec_Clear(&d);
	refVec_Clear(&x);
	refVec_Clear(&y);
	mpfr_clears(n, t, (mpfr_ptr)0);
}

/* 6: h(d) against a dense sample of boundary points. In 2D, 5000 angles; the
 * maximum of <d, f(theta)> over the sample lies below h by at most the
 * sampling gap, so we only ask max <= h (up to SELF_TOL) and max >= h (1 - 1e-3)
 * (a loose lower bound: the sample is far denser than a 1e-3 gap needs for
 * eps in [0.5, 1.5]). */
static void checkSupportIsMax(refRng *rng)
{
	const double eps[] = { 0.5, 1.0, 1.5 };
	refVec u, x, d;
	mpfr_t h, t, best;
	refVec_Init(&u);
	refVec_Init(&x);
	refVec_Init(&d);
	mpfr_inits2(REF_PREC, h, t, best, (mpfr_ptr)0);
	for (int k = 0; k < 3; ++k) {
		refShape s = { 2, { 3.0, 1.25, 0.0 }, eps[k], 0.0 };
		double dd[2];
		refRng_Unit(rng, 2, dd);
		refVec_FromD(&d, 2, dd);
		refShape_SupportValue(s, &d, h);
		mpfr_set_inf(best, -1);
		for (int i = 0; i < 5000; ++i) {
			double th = -REF_PI + 2.0 * REF_PI * i / 5000.0;
			double ud[2] = { cos(th), sin(th) };
			refVec_FromD(&u, 2, ud);
			refShape_Point(s, &u, &x);
			refVec_Dot(t, &d, &x, 2);
			if (mpfr_cmp(t, best) > 0)
				mpfr_set(best, t, MPFR_RNDN);
		}
		mpfr_sub(t, best, h, MPFR_RNDN);
		mpfr_div(t, t, h, MPFR_RNDN);
		double r = mpfr_get_d(t, MPFR_RNDN);
		ENSURE_LE(r, SELF_TOL, "sampled max above h, eps %g", eps[k]);
		ENSURE_LE(-r, 1e-3, "sampled max far below h, eps %g", eps[k]);
	}
	refVec_Clear(&u);
	refVec_Clear(&x);
	refVec_Clear(&d);
	mpfr_clears(h, t, best, (mpfr_ptr)0);
}

/* 7: M^T (M^-T v) = v for a sheared rotation. */
static void checkInverse(refRng *rng)
{
	for (int trial = 0; trial < 10; ++trial) {
		refMat M;
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				M.m[i][j] = refRng_Uniform(rng, -10.0, 10.0);
		M.m[0][0] += 30.0; /* keep it well away from singular */
		for (int dim = 2; dim <= 3; ++dim) {
			double vd[3] = { 0.3, -1.7, 2.2 };
			refVec v, w, y;
			refVec_Init(&v);
			refVec_Init(&w);
			refVec_Init(&y);
			refVec_FromD(&v, dim, vd);
			refMat_InvTVec(&M, dim, &v, &w);
			refMat_MulTVec(&M, dim, &w, &y);
			double e = relDiff(&y, &v, dim);
			ENSURE_LE(e, SELF_TOL, "M^T M^-T v, dim %d", dim);
			refVec_Clear(&v);
			refVec_Clear(&w);
			refVec_Clear(&y);
		}
	}
}

int main(void)
{
	refRng rng = { 20260101u };
	refStat stat = { 0 };
	const double axes[][3] = { { 1.0, 1.0, 1.0 }, { 7.5, 0.3, 2.0 }, { 1e4, 1.0, 30.0 }, { 1.0, 1e4, 1e-2 } };
	for (int ia = 0; ia < 4; ++ia)
		for (int i = 0; i < EPS_COUNT; ++i) {
			refShape s2 = { 2, { axes[ia][0], axes[ia][1], 0.0 }, epsList[i], 0.0 };
			checkShape(s2, &rng, &stat);
			for (int j = 0; j < EPS_COUNT; ++j) {
				refShape s3 = { 3, { axes[ia][0], axes[ia][1], axes[ia][2] }, epsList[i], epsList[j] };
				checkShape(s3, &rng, &stat);
			}
		}
	for (int ia = 0; ia < 4; ++ia) {
		refShape e2 = { 2, { axes[ia][0], axes[ia][1], 0.0 }, 1.0, 0.0 };
		refShape e3 = { 3, { axes[ia][0], axes[ia][1], axes[ia][2] }, 1.0, 1.0 };
		checkEllipse(e2, &rng, &stat);
		checkEllipse(e3, &rng, &stat);
	}
	checkSupportIsMax(&rng);
	checkInverse(&rng);
	printf("ref_selfcheck: %ld identities at 256 bits, max deviation %.2e, mean %.2e (tolerance %.0e)\n",
		stat.count, stat.max, refStat_Mean(&stat), SELF_TOL);
	return refTest_Result("ref_selfcheck");
}
