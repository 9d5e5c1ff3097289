/* ref_measure.c - the distance from the exact boundary, the score of a point
 * set and the problem's condition (mink/mpref_measure.h), on cases whose
 * answers are known without the search under test:
 *
 *  1. Sums of two circles / spheres are discs / balls of radius r1 + r2
 *     around t1 (+ t2 for the plus set): d(p) = |p - c| - R, evaluated here
 *     at 256 bits directly from the rounded p.
 *  2. A boundary point moved outwards by delta along its normal is at
 *     distance exactly delta from any convex body (the supporting line
 *     separates), on every exponent pair including the extremes; moved
 *     inwards by a delta far below the radius of curvature, at -delta.
 *  3. Near-boxes (eps = 1e-6, axis-aligned): the sum is flat to 1e-600000
 *     over the middle of each face, so a point off the middle of a face is at
 *     p_x - (a1 + a2) from the boundary. phi has a kink there at every
 *     representable scale: this is the case that needs the derivative-free
 *     fallback.
 *  4. The score of a planted set: the largest |d| and its index, non-finite
 *     points counted, found with and without start normals; and on the
 *     edges of a near-cube, where only the derivative-free stage finds it.
 *  5. The condition on a translation-dominated pair, worked by hand: the
 *     boundary moves exactly with t1, by one ulp of each coordinate.
 *  6. The searches' support point by logarithms against the one by powers.
 *  7. The memo of refSum_ScoreMemo: scores bit for bit those without it.
 * Tolerances: the rounding of p itself (2^-53 |p| per coordinate, so
 * 2^-52 sqrt(dim) |p| in all) plus four times the search's target (1e-5 of
 * the distance or 1e-21 of the size S, mink/mpref_measure.h). */
#include <mink/mpref_measure.h>
#include "reftest.h"

#include <math.h>
#include <string.h>

static refBody makeBody(int dim, double a, double b, double c, double e1, double e2,
	double rot, const double *t)
{
	refBody r;
	memset(&r, 0, sizeof r);
	r.s.dim = dim;
	r.s.a[0] = a;
	r.s.a[1] = b;
	r.s.a[2] = dim == 3 ? c : 0.0;
	r.s.e1 = e1;
	r.s.e2 = dim == 3 ? e2 : 0.0;
	for (int i = 0; i < dim; ++i)
		r.M.m[i][i] = 1.0;
	/* a rotation about the last axis */
	r.M.m[0][0] = cos(rot);
	r.M.m[0][1] = -sin(rot);
	r.M.m[1][0] = sin(rot);
	r.M.m[1][1] = cos(rot);
	for (int i = 0; i < dim; ++i)
		r.t[i] = t ? t[i] : 0.0;
	return r;
}

/* x + delta n at 256 bits, rounded to double into p (dim entries). */
static void movedPoint(const refVec *x, const refVec *n, int dim, double delta, double *p)
{
	for (int i = 0; i < dim; ++i) {
		mpfr_t t;
		mpfr_init2(t, REF_PREC);
		mpfr_mul_d(t, n->c[i], delta, MPFR_RNDN);
		mpfr_add(t, t, x->c[i], MPFR_RNDN);
		p[i] = mpfr_get_d(t, MPFR_RNDN);
		mpfr_clear(t);
	}
}

/* The exact point of the surface parameter ud moved by delta along its
 * exact normal, rounded to double into p (dim entries). */
static void offNormal(const refBody *b1, const refBody *b2, int plus, const double *ud, double delta, double *p)
{
	int dim = b1->s.dim;
	refVec u, xv, nv;
	refVec_Init(&u);
	refVec_Init(&xv);
	refVec_Init(&nv);
	refVec_FromD(&u, dim, ud);
	refSum_Point(b1, b2, plus, 1, &u, &xv, NULL, &nv);
	movedPoint(&xv, &nv, dim, delta, p);
	refVec_Clear(&u);
	refVec_Clear(&xv);
	refVec_Clear(&nv);
}

static double dnorm(const double *v, int dim)
{
	double s = 0.0;
	for (int i = 0; i < dim; ++i)
		s += v[i] * v[i];
	return sqrt(s);
}

/* 1: discs and balls. */
static void checkCircles(void)
{
	refRng rng = { 7 };
	static const double deltas[] = { 0.0, 1e-14, -1e-14, 1e-9, -1e-9, 1e-3, -1e-3, -1.0, 5.0 };
	long evals = 0, count = 0;
	for (int dim = 2; dim <= 3; ++dim)
		for (int plus = 0; plus <= 1; ++plus) {
			double t1[3] = { 0.5, -1.0, 2.0 }, t2[3] = { 3.0, 4.0, -1.0 };
			/* unrotated: a rotation rounded to doubles is not exactly
			 * orthogonal, and would make the discs ellipses at 1e-17 */
			refBody b1 = makeBody(dim, 1.25, 1.25, 1.25, 1.0, 1.0, 0.0, t1);
			refBody b2 = makeBody(dim, 0.5, 0.5, 0.5, 1.0, 1.0, 0.0, t2);
			double c[3], R = 1.75, S = refSum_Size(&b1, &b2, plus);
			for (int i = 0; i < 3; ++i)
				c[i] = t1[i] + (plus ? t2[i] : 0.0);
			for (int k = 0; k < (int)(sizeof deltas / sizeof deltas[0]); ++k)
				for (int trial = 0; trial < 3; ++trial) {
					double u[3] = { 0.0, 0.0, 0.0 }, p[3] = { 0.0, 0.0, 0.0 };
					refRng_Unit(&rng, dim, u);
					for (int i = 0; i < dim; ++i)
						p[i] = c[i] + (R + deltas[k]) * u[i];
					/* the exact distance of the rounded p */
					mpfr_t s, t;
					mpfr_inits2(REF_PREC, s, t, (mpfr_ptr)0);
					mpfr_set_zero(s, 1);
					for (int i = 0; i < dim; ++i) {
						mpfr_set_d(t, p[i], MPFR_RNDN);
						mpfr_sub_d(t, t, c[i], MPFR_RNDN);
						mpfr_sqr(t, t, MPFR_RNDN);
						mpfr_add(s, s, t, MPFR_RNDN);
					}
					mpfr_sqrt(s, s, MPFR_RNDN);
					mpfr_sub_d(s, s, R, MPFR_RNDN);
					double expect = mpfr_get_d(s, MPFR_RNDN);
					mpfr_clears(s, t, (mpfr_ptr)0);
					/* the search's target and a factor 4 */
					double tol = 4.0 * (1e-21 * S + 1e-5 * fabs(expect));
					for (int h = 0; h < 2; ++h) {
						double hint[3] = { u[0] + 1e-4, u[1] - 2e-4, u[2] };
						refDistance d;
						int r = refSum_Distance(&b1, &b2, plus, p, h ? hint : NULL, &d);
						ENSURE(r == 0);
						ENSURE_LE(fabs(d.dist - expect), tol, "%dD %s delta %g hint %d: d %.17g expected %.17g",
							dim, plus ? "plus" : "contact", deltas[k], h, d.dist, expect);
						/* the bracket d <= |v| holds, and the normal found is the
						 * radial one: phi falls off as R (1 - cos) from its
						 * maximum, so a gain of 1e-5 |d| <= 1e-5 left (the
						 * target) allows 1 - cos up to about 1e-5 / R; far
						 * smaller in practice, as Newton overshoots the target */
						ENSURE_LE(d.dist, d.upper * (1.0 + 1e-15), "%dD upper", dim);
						if (fabs(deltas[k]) < 1.0) {
							double dot = 0.0;
							for (int i = 0; i < dim; ++i)
								dot += d.normal[i] * u[i];
							ENSURE_LE(1.0 - dot, 1e-5 / R, "%dD normal delta %g", dim, deltas[k]);
						}
						evals += d.evals;
						count++;
					}
				}
		}
	printf("discs and balls: %ld distances, %.1f support evaluations each on average\n",
		count, (double)evals / (double)count);
}

/* 2: a boundary point moved along its normal. */
static void checkMoved(void)
{
	static const double pairs[][4] = {
		/* eps1 (B1), eps2 (B1, 3D), eps1 (B2), eps2 (B2) */
		{ 0.5, 1.5, 1.5, 0.5 }, { 1e-6, 1.0, 1.0, 1e-6 }, { 2.0 - 1e-6, 0.1, 0.1, 2.0 - 1e-6 },
		{ 1e-6, 1e-6, 1e-6, 1e-6 }, { 1.999, 1.999, 1.999, 1.999 }, { 1.0, 1.0, 1.0, 1.0 } };
	refRng rng = { 99 };
	long evals = 0, count = 0;
	for (int dim = 2; dim <= 3; ++dim)
		for (int pi = 0; pi < (int)(sizeof pairs / sizeof pairs[0]); ++pi)
			for (int plus = 0; plus <= 1; ++plus) {
				double t1[3] = { 0.3, -0.2, 0.1 }, t2[3] = { -1.0, 2.0, 0.5 };
				refBody b1 = makeBody(dim, 1.0, 0.4, 0.7, pairs[pi][0], pairs[pi][1], 0.4, t1);
				refBody b2 = makeBody(dim, 0.6, 0.9, 0.3, pairs[pi][2], pairs[pi][3], 1.3, t2);
				double S = refSum_Size(&b1, &b2, plus);
				int smooth = pairs[pi][0] >= 0.5 && pairs[pi][0] <= 1.5 && pairs[pi][2] >= 0.5 && pairs[pi][2] <= 1.5;
				static const double rel[] = { 1e-6, 1e-13, -1e-9 };
				for (int k = 0; k < 3; ++k) {
					if (rel[k] < 0.0 && !smooth)
						continue; /* inside a corner the nearest boundary may be another face */
					for (int trial = 0; trial < 3; ++trial) {
						double nd[3] = { 0.0, 0.0, 0.0 }, p[3] = { 0.0, 0.0, 0.0 };
						refRng_Unit(&rng, dim, nd);
						refVec n, x;
						refVec_Init(&n);
						refVec_Init(&x);
						refVec_FromD(&n, dim, nd);
						refVec_Normalize(&n, dim);
						refSum_Point(&b1, &b2, plus, 0, &n, &x, NULL, NULL);
						double delta = rel[k] * S;
						movedPoint(&x, &n, dim, delta, p);
						refVec_Clear(&n);
						refVec_Clear(&x);
						/* rounding p moves it by at most 2^-53 |p_i| per coordinate;
						 * the second-order effect of that move is far below it */
						double tol = 0x1p-52 * sqrt((double)dim) * dnorm(p, dim) + 4.0 * (1e-21 * S + 1e-5 * fabs(delta));
						for (int h = 0; h < 2; ++h) {
							refDistance d;
							ENSURE(refSum_Distance(&b1, &b2, plus, p, h ? nd : NULL, &d) == 0);
							ENSURE_LE(fabs(d.dist - delta), tol, "%dD eps (%g %g | %g %g) %s delta/S %g hint %d: "
								"d/S %.17g", dim, pairs[pi][0], pairs[pi][1], pairs[pi][2], pairs[pi][3],
								plus ? "plus" : "contact", rel[k], h, d.dist / S);
							evals += d.evals;
							count++;
						}
					}
				}
			}
	printf("moved boundary points: %ld distances, %.1f support evaluations each on average\n",
		count, (double)evals / (double)count);
}

/* 3: off the middle of a face of a sum of near-boxes. */
static void checkFaces(void)
{
	static const double deltas[] = { 1e-3, 1e-12, -1e-12, -1e-3, 0.0 };
	for (int dim = 2; dim <= 3; ++dim)
		for (int plus = 0; plus <= 1; ++plus) {
			double t2[3] = { 0.0, 0.0, 0.0 };
			refBody b1 = makeBody(dim, 1.0, 0.5, 0.8, 1e-6, 1e-6, 0.0, NULL);
			refBody b2 = makeBody(dim, 0.7, 0.4, 0.5, 1e-6, 1e-6, 0.0, t2);
			double S = refSum_Size(&b1, &b2, plus);
			for (int k = 0; k < (int)(sizeof deltas / sizeof deltas[0]); ++k) {
				double p[3] = { 1.7 + deltas[k], 0.2, -0.3 };
				/* p_x - 1.7, exactly (a difference of two doubles near each other) */
				double expect = p[0] - 1.7;
				double tol = 4.0 * (1e-21 * S + 1e-5 * fabs(expect));
				for (int h = 0; h < 2; ++h) {
					double hint[3] = { 1.0, 0.03, -0.02 };
					refDistance d;
					ENSURE(refSum_Distance(&b1, &b2, plus, p, h ? hint : NULL, &d) == 0);
					ENSURE_LE(fabs(d.dist - expect), tol, "near-box %dD %s delta %g hint %d: d %.17g",
						dim, plus ? "plus" : "contact", deltas[k], h, d.dist);
					ENSURE_LE(d.accuracy, tol, "near-box %dD accuracy", dim);
					printf("near-box face %dD %s delta %+g hint %d: d - expected = %.2e, %d evaluations\n",
						dim, plus ? "plus" : "contact", deltas[k], h, d.dist - expect, d.evals);
				}
			}
		}
}

/* 4: a planted point set. */
static void checkScore(void)
{
	for (int dim = 2; dim <= 3; ++dim) {
		int n = dim == 2 ? 64 : 8, count = dim == 2 ? n : n * n;
		double ux[64], uy[64], uz[64], x[64], y[64], z[64];
		double t1[3] = { 0.3, -0.2, 0.1 }, t2[3] = { -1.0, 2.0, 0.5 };
		refBody b1 = makeBody(dim, 1.0, 0.4, 0.7, 0.5, 1.5, 0.4, t1);
		refBody b2 = makeBody(dim, 0.6, 0.9, 0.3, 1.5, 0.5, 1.3, t2);
		refSample_Params(dim, n, ux, uy, dim == 3 ? uz : NULL);
		double S = refSum_Size(&b1, &b2, 0);
		int planted = 17;
		for (int k = 0; k < count; ++k) {
			double ud[3] = { ux[k], uy[k], dim == 3 ? uz[k] : 0.0 };
			/* move by delta_k along the normal: -1e-10 S ... 1e-10 S, and
			 * 3e-9 S at the planted index */
			double delta = k == planted ? 3e-9 * S : 1e-10 * S * ((k % 7) - 3) / 3.0;
			double p[3];
			offNormal(&b1, &b2, 0, ud, delta, p);
			x[k] = p[0];
			y[k] = p[1];
			z[k] = dim == 3 ? p[2] : 0.0;
		}
		x[5] = NAN;
		y[40 % count] = INFINITY;
		for (int h = 0; h < 2; ++h) {
			refScore sc;
			int r = refSum_Score(&b1, &b2, 0, x, y, dim == 3 ? z : NULL, count,
				h ? ux : NULL, h ? uy : NULL, h && dim == 3 ? uz : NULL, &sc);
			ENSURE(r == 0);
			ENSURE(sc.nonfinite == 2 && sc.points == count - 2);
			ENSURE_MSG(sc.worst == planted, "%dD hint %d: worst %d", dim, h, sc.worst);
			ENSURE_LE(fabs(sc.errorRel - 3e-9), 1e-15, "%dD hint %d: error_rel %.17g", dim, h, sc.errorRel);
			ENSURE(sc.worstDist > 0.0);
			ENSURE(sc.size == S);
			printf("score %dD hint %d: error_rel %.6e (planted 3e-9), %ld of %ld points searched at 256 bits "
				"(%ld by Nelder-Mead), accuracy %.1e\n", dim, h, sc.errorRel, sc.searched, sc.points, sc.refined,
				sc.accuracy);
			/* a smooth pair: Newton settles every point */
			ENSURE(sc.refined == 0);
			/* without parameters the double-precision bound (|phi| + 1e-9 S)
			 * leaves only the planted point above the others (<= 1e-10 S) */
			if (!h)
				ENSURE_MSG(sc.searched == 1, "%dD: %ld points searched", dim, sc.searched);
		}
	}
	/* Edges of a near-cube (eps 1e-6) summed with an ellipsoid: parameters
	 * with an exact zero component put B1's point in the middle of an edge,
	 * where phi has a ridge at every representable scale, Newton stops and
	 * no face certificate applies, so the derivative-free stage must find
	 * the planted maximum. Points moved outwards along the exact normal are
	 * at exactly that distance. */
	{
		double t1[3] = { 0.3, -0.2, 0.1 };
		refBody b1 = makeBody(3, 1.0, 0.4, 0.7, 1e-6, 1e-6, 0.4, t1);
		refBody b2 = makeBody(3, 0.6, 0.9, 0.3, 1.0, 1.0, 1.3, NULL);
		double S = refSum_Size(&b1, &b2, 0), ux[12], uy[12], uz[12], x[12], y[12], z[12], pmax = 0.0;
		int count = 12, planted = 7;
		for (int k = 0; k < count; ++k) {
			double a = 0.3 + 0.5 * k;
			ux[k] = k % 3 == 0 ? 0.0 : cos(a);
			uy[k] = k % 3 == 1 ? 0.0 : sin(a);
			uz[k] = k % 3 == 2 ? 0.0 : (k % 2 ? 0.6 : -0.6);
			refVec u, xv, nv;
			refVec_Init(&u);
			refVec_Init(&xv);
			refVec_Init(&nv);
			double ud[3] = { ux[k], uy[k], uz[k] }, p[3];
			refVec_FromD(&u, 3, ud);
			refSum_Point(&b1, &b2, 0, 1, &u, &xv, NULL, &nv);
			double delta = (k == planted ? 5e-12 : 1e-12 * (k % 4)) * S;
			for (int i = 0; i < 3; ++i) {
				mpfr_t t;
				mpfr_init2(t, REF_PREC);
				mpfr_mul_d(t, nv.c[i], delta, MPFR_RNDN);
				mpfr_add(t, t, xv.c[i], MPFR_RNDN);
				p[i] = mpfr_get_d(t, MPFR_RNDN);
				mpfr_clear(t);
			}
			x[k] = p[0];
			y[k] = p[1];
			z[k] = p[2];
			if (dnorm(p, 3) > pmax)
				pmax = dnorm(p, 3);
			refVec_Clear(&u);
			refVec_Clear(&xv);
			refVec_Clear(&nv);
		}
		refScore sc;
		ENSURE(refSum_Score(&b1, &b2, 0, x, y, z, count, ux, uy, uz, &sc) == 0);
		/* rounding of p, plus the accuracy the search reports for itself */
		double tol = 0x1p-52 * sqrt(3.0) * pmax / S + 4.0 * sc.accuracy + 4e-5 * 5e-12;
		ENSURE_MSG(sc.worst == planted, "near-cube edges: worst %d", sc.worst);
		ENSURE_LE(fabs(sc.errorRel - 5e-12), tol, "near-cube edges: error_rel %.17g", sc.errorRel);
		ENSURE_LE(sc.accuracy, 1e-16, "near-cube edges: accuracy");
		printf("score near-cube edges: error_rel %.6e (planted 5e-12), %ld of %ld points searched by "
			"Nelder-Mead, accuracy %.1e\n", sc.errorRel, sc.refined, sc.points, sc.accuracy);
	}
	refScore sc;
	ENSURE(refSum_Score(NULL, NULL, 0, NULL, NULL, NULL, 0, NULL, NULL, NULL, NULL) == -1);
	refBody b = makeBody(2, 1, 1, 1, 1, 1, 0, NULL);
	ENSURE(refSum_Score(&b, &b, 0, NULL, NULL, NULL, -1, NULL, NULL, NULL, &sc) == -1);
	ENSURE(refSum_Score(&b, &b, 0, NULL, NULL, NULL, 0, NULL, NULL, NULL, &sc) == 0 && sc.worst == -1);
	double p[2] = { NAN, 0.0 }, zero[2] = { 0.0, 0.0 };
	refDistance d;
	ENSURE(refSum_Distance(&b, &b, 0, p, NULL, &d) == -1);
	p[0] = 1.0;
	ENSURE(refSum_Distance(&b, &b, 0, p, zero, &d) == -1);
}

/* 6: refShape_SupportByLogs, the searches' support point, against
 * refShape_Support (powers taken one by one with mpfr_pow, correctly
 * rounded each) on exponents towards both ends of the range, semi-axes
 * 1e-6 ... 1e6 and directions with zero and tiny components. The logarithm
 * form is exact to about |q log|a d|| 2^-256 relative (mink/mpref.h: below
 * 2^-227 here, q <= 2e6 and |log| < 50); the powers one by one to a few
 * ulps of 2^-256 times the same amplification. 2^-200 of the point's size
 * leaves a margin of 2^27 over both and is still 1e-60: far below any
 * distance the searches resolve (1e-21 of the size S). */
static void checkSupportByLogs(void)
{
	static const double eps[] = { 1e-6, 1e-3, 0.1, 0.5, 1.0, 1.5, 1.9, 1.999, 2.0 - 1e-6 };
	static const double axes[] = { 1.0, 1e-6, 1e6, 0.37 };
	refRng rng = { 2024 };
	int ne = (int)(sizeof eps / sizeof eps[0]), checked = 0;
	double worst = 0.0;
	refVec d, x, y, diff;
	refVec_Init(&d);
	refVec_Init(&x);
	refVec_Init(&y);
	refVec_Init(&diff);
	for (int dim = 2; dim <= 3; ++dim)
		for (int i = 0; i < ne; ++i)
			for (int j = 0; j < (dim == 3 ? ne : 1); ++j)
				for (int k = 0; k < 12; ++k) {
					refShape s;
					memset(&s, 0, sizeof s);
					s.dim = dim;
					s.e1 = eps[i];
					s.e2 = dim == 3 ? eps[j] : 0.0;
					for (int c = 0; c < dim; ++c)
						s.a[c] = axes[(k + c) % 4];
					double u[3] = { 0.0, 0.0, 0.0 };
					refRng_Unit(&rng, dim, u);
					/* a zero component (k = 0, 1, 2) or a tiny one (k = 3, 4) */
					if (k < dim)
						u[k] = 0.0;
					else if (k == 3 || k == 4)
						u[k - 3] *= 1e-15;
					refVec_FromD(&d, dim, u);
					refShape_Support(s, &d, &x);
					refShape_SupportByLogs(s, &d, &y);
					for (int c = 0; c < 3; ++c)
						mpfr_sub(diff.c[c], x.c[c], y.c[c], MPFR_RNDN);
					double size = refVec_NormD(&x, dim), err = refVec_NormD(&diff, dim) / size;
					ENSURE_LE(err, 0x1p-200, "%dD eps %g %g axes %g %g %g: by logs %.3e relative off",
						dim, s.e1, s.e2, s.a[0], s.a[1], s.a[2], err);
					if (err > worst)
						worst = err;
					checked++;
				}
	printf("support by logarithms: %d points, largest relative difference from the powers %.3e\n", checked, worst);
	refVec_Clear(&d);
	refVec_Clear(&x);
	refVec_Clear(&y);
	refVec_Clear(&diff);
}

/* 7: the memo of refSum_ScoreMemo changes no bit of a score: the same
 * outputs scored with and without it, twice in a row (the second time from
 * the memo alone), then another pair through the same memo (it must empty
 * itself, not answer from the first pair). Points: boundary points of each
 * pair moved by 1e-12 ... 1e-9 of the size S (near-box and ellipsoid edges
 * included, where the derivative-free stage runs). */
static int scoreSame(const refScore *a, const refScore *b)
{
	return a->size == b->size && a->errorAbs == b->errorAbs && a->errorRel == b->errorRel
		&& a->accuracy == b->accuracy && a->worst == b->worst && a->worstDist == b->worstDist
		&& a->points == b->points && a->nonfinite == b->nonfinite && a->searched == b->searched
		&& a->refined == b->refined;
}

static void checkMemo(void)
{
	refScoreMemo *memo = refScoreMemo_New();
	ENSURE(memo != NULL);
	for (int dim = 2; dim <= 3; ++dim)
		for (int pair = 0; pair < 2; ++pair)
			for (int plus = 0; plus <= 1; ++plus) {
				double t1[3] = { 0.3, -0.2, 0.1 }, t2[3] = { -1.0, 2.0, 0.5 };
				refBody b1 = makeBody(dim, 1.0, 0.4, 0.7, pair ? 1e-6 : 0.5, pair ? 1e-6 : 1.5, 0.4, t1);
				refBody b2 = makeBody(dim, 0.6, 0.9, 0.3, pair ? 1.0 : 1.9, 1.0, 1.3, t2);
				int n = dim == 2 ? 24 : 5, count = dim == 2 ? n : n * n;
				double ux[25], uy[25], uz[25], x[25], y[25], z[25];
				refSample_Params(dim, n, ux, uy, dim == 3 ? uz : NULL);
				double S = refSum_Size(&b1, &b2, plus);
				for (int k = 0; k < count; ++k) {
					double ud[3] = { ux[k], uy[k], dim == 3 ? uz[k] : 0.0 }, p[3] = { 0.0, 0.0, 0.0 };
					double delta = 1e-12 * S * (1 + k % 5) * (k % 2 ? 1.0 : -1.0) * (k == 3 ? 1000.0 : 1.0);
					offNormal(&b1, &b2, plus, ud, delta, p);
					x[k] = p[0];
					y[k] = p[1];
					z[k] = p[2];
				}
				for (int h = 0; h < 2; ++h) {
					const double *hx = h ? ux : NULL, *hy = h ? uy : NULL, *hz = h && dim == 3 ? uz : NULL;
					refScore plain, first, again;
					long hits0, misses0, hits1, misses1;
					ENSURE(refSum_Score(&b1, &b2, plus, x, y, dim == 3 ? z : NULL, count, hx, hy, hz, &plain) == 0);
					refScoreMemo_Counts(memo, &hits0, &misses0);
					ENSURE(refSum_ScoreMemo(&b1, &b2, plus, x, y, dim == 3 ? z : NULL, count, hx, hy, hz, memo,
						&first) == 0);
					ENSURE(refSum_ScoreMemo(&b1, &b2, plus, x, y, dim == 3 ? z : NULL, count, hx, hy, hz, memo,
						&again) == 0);
					refScoreMemo_Counts(memo, &hits1, &misses1);
					ENSURE_MSG(scoreSame(&plain, &first) && scoreSame(&plain, &again),
						"%dD pair %d plus %d hints %d: memo changed the score (%.17g %.17g %.17g)", dim, pair, plus,
						h, plain.errorAbs, first.errorAbs, again.errorAbs);
					/* the second call ran no search: every one came from the memo */
					ENSURE(hits1 - hits0 >= plain.searched + plain.refined && misses1 - misses0 > 0);
					ENSURE(plain.worst >= 0);
				}
			}
	refScoreMemo_Free(memo);
	refScoreMemo_Free(NULL);
}

/* 5: the condition of a pair dominated by its translation. B1 a circle of
 * radius 1 at t1 = (1.5 2^30, 1.5 2^30), B2 a circle of radius 0.5; the
 * contact set is the disc of radius 1.5 around t1. One ulp of each
 * coordinate of t1 is 2^-22 (both ways, 1.5 2^30 is not a power of two),
 * so every draw moves t1 by (+-2^-22, +-2^-22), and the boundary, measured
 * along a normal parallel to that move, by 2^-22 sqrt 2. With 8 samples the
 * normals include all four diagonals, so the maximum is that. The radii's
 * ulps (2e-16) and the exponent's add below 1e-15 relative to it. The point
 * of the same parameter moves with t1 by the same amount. Rounding the exact
 * point to double moves it by at most half an ulp, 2^-23, per coordinate. */
static void checkCondition(void)
{
	double big = 1.5 * 0x1p30, t1[2] = { big, big };
	refBody b1 = makeBody(2, 1.0, 1.0, 0.0, 1.0, 1.0, 0.0, t1);
	refBody b2 = makeBody(2, 0.5, 0.5, 0.0, 1.0, 1.0, 0.0, NULL);
	double S = refSum_Size(&b1, &b2, 0);
	refCondition c;
	ENSURE(refSum_Condition(&b1, &b2, 0, 8, 4, 1234u, &c) == 0);
	double expect = 0x1p-22 * sqrt(2.0);
	ENSURE_LE(fabs(c.boundary * S - expect), 1e-6 * expect, "boundary %.17g expected %.17g", c.boundary * S, expect);
	ENSURE_LE(fabs(c.point * S - expect), 1e-6 * expect, "point %.17g expected %.17g", c.point * S, expect);
	ENSURE_LE(c.floor * S, 0x1p-23 * sqrt(2.0), "floor %.17g", c.floor * S);
	ENSURE(c.value == (c.boundary > c.floor ? c.boundary : c.floor));
	printf("condition, translation-dominated circles: boundary %.6e point %.6e floor %.6e (relative to S = %.6g)\n",
		c.boundary, c.point, c.floor, S);

	/* Scaling every length by 2^10 scales every ulp by 2^10 too: the
	 * same draws give the same relative figures. */
	refBody s1 = makeBody(2, 1.0, 0.3, 0.0, 0.4, 0.4, 0.3, NULL), s2 = makeBody(2, 0.2, 0.7, 0.0, 1.8, 1.8, -0.9, NULL);
	s1.t[0] = 0.75;
	s2.t[1] = -1.25;
	refBody l1 = s1, l2 = s2;
	for (int i = 0; i < 2; ++i) {
		l1.s.a[i] *= 1024.0;
		l2.s.a[i] *= 1024.0;
		l1.t[i] *= 1024.0;
		l2.t[i] *= 1024.0;
	}
	for (int plus = 0; plus <= 1; ++plus) {
		refCondition cs, cl;
		ENSURE(refSum_Condition(&s1, &s2, plus, 16, 3, 77u, &cs) == 0);
		ENSURE(refSum_Condition(&l1, &l2, plus, 16, 3, 77u, &cl) == 0);
		ENSURE_LE(fabs(cs.boundary - cl.boundary), 1e-9 * cs.boundary, "scaled boundary %g %g", cs.boundary, cl.boundary);
		ENSURE_LE(fabs(cs.point - cl.point), 1e-9 * cs.point, "scaled point %g %g", cs.point, cl.point);
		/* a one-ulp move of well-scaled inputs moves the boundary by a few
		 * ulps of the size S, no more (eps 0.4 and 1.8 amplify by at most
		 * their exponent 1/(2 - 1.8) = 5) */
		ENSURE(cs.boundary > 0.0);
		ENSURE_LE(cs.boundary, 64.0 * REF_U, "boundary of a well-conditioned pair %g", cs.boundary);
	}
	ENSURE(refSum_Condition(&b1, &b2, 0, 1, 4, 1u, &c) == -1);
	ENSURE(refSum_Condition(&b1, &b2, 0, 8, 0, 1u, &c) == -1);
}

int main(void)
{
	checkCircles();
	checkMoved();
	checkFaces();
	checkScore();
	checkCondition();
	checkSupportByLogs();
	checkMemo();
	return refTest_Result("ref_measure");
}
