/* mpref_measure.c - the distance of a point from the exact boundary of a
 * sum at 256 bits, and the sum's size (mink/mpref_measure.h); scoring a
 * point set and the problem's condition are in mpref_score.c.
 *
 * The search for max phi(n), phi(n) = <n, p> - h_K(n), works on offsets s
 * (1 or 2 doubles) in the tangent space of a base normal n0 held at 256 bits:
 * n(s) = (n0 + sum s_k T_k) / |...|. The base is moved to the best normal
 * after every accepted step, so the offsets stay small and a double resolves
 * them to far below anything that matters (an offset of 1e-30 is a turn of
 * 1e-30 radian). Derivatives: d phi / d s_k = <v, dn/ds_k> with v = p - x_K(n)
 * (the gradient of the support function is the support point), and
 * dn/ds_k = (T_k - <T_k, n> n) / |n0 + sum s T|. The second derivatives are
 * differences of that gradient over a step of 1e-30 taken at 256 bits
 * (77 digits, so the difference keeps over 40 of them).
 *
 * Newton steps with a halving line search on phi converge in a few steps
 * where the boundary is smooth at the scale of the step. Where it is not
 * (bodies with eps -> 0 or 2 have faces that the support point crosses
 * within 1e-600000 radian of the face normal, so phi has a kink there at any
 * representable scale) the second difference vanishes or changes sign, and
 * a Nelder-Mead search on the same offsets takes over: it needs no
 * derivative and closes in on a kinked maximum linearly, with restarts that
 * re-centre the base. The accuracy it reports there is the simplex diameter
 * times the slope |d phi/d s| (a Lipschitz estimate of the remaining gain). */
#include <mink/mpref_measure.h>

#include "mpref_measure_internal.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RND MPFR_RNDN
#define FD_STEP 1e-30      /* step of the second differences, radian */
#define NEWTON_ITERS 16
#define NM_EVALS 1000      /* Nelder-Mead budget per point */

/* ---- double-precision helpers ------------------------------------------ */

static double dNorm(const double *v, int dim)
{
	double s = 0.0;
	for (int i = 0; i < dim; ++i)
		s += v[i] * v[i];
	return sqrt(s);
}

static double dFrob(const refMat *M, int dim)
{
	double s = 0.0;
	for (int i = 0; i < dim; ++i)
		for (int j = 0; j < dim; ++j)
			s += M->m[i][j] * M->m[i][j];
	return sqrt(s);
}

double refSum_Size(const refBody *b1, const refBody *b2, int plus)
{
	int dim = b1->s.dim;
	double S = dNorm(b1->t, dim) + dFrob(&b1->M, dim) * dNorm(b1->s.a, dim)
		+ dFrob(&b2->M, dim) * dNorm(b2->s.a, dim);
	if (plus)
		S += dNorm(b2->t, dim);
	return S;
}

/* The support value in double precision, written from the dual-norm formula
 * of mpref.c (|(a1 w1, a2 w2)|_q, nested in 3D), scaled against overflow.
 * Used only to find a start normal; never in a result. */
static double dNormQ(double x, double y, double q)
{
	x = fabs(x);
	y = fabs(y);
	double m = x > y ? x : y;
	if (m == 0.0)
		return 0.0;
	return m * pow(pow(x / m, q) + pow(y / m, q), 1.0 / q);
}

static double dShapeH(refShape s, const double *w)
{
	double q1 = 2.0 / (2.0 - s.e1);
	if (s.dim == 2)
		return dNormQ(s.a[0] * w[0], s.a[1] * w[1], q1);
	double q2 = 2.0 / (2.0 - s.e2);
	return dNormQ(dNormQ(s.a[0] * w[0], s.a[1] * w[1], q2), s.a[2] * w[2], q1);
}

static double dBodyH(const refBody *b, const double *n, double sg, int withT)
{
	int dim = b->s.dim;
	double w[3] = { 0.0, 0.0, 0.0 }, h;
	for (int i = 0; i < dim; ++i)
		for (int j = 0; j < dim; ++j)
			w[i] += b->M.m[j][i] * sg * n[j];
	h = dShapeH(b->s, w);
	if (withT)
		for (int i = 0; i < dim; ++i)
			h += sg * n[i] * b->t[i];
	return h;
}

static double dPhi(const refBody *b1, const refBody *b2, int plus, const double *p, const double *n)
{
	int dim = b1->s.dim;
	double h = dBodyH(b1, n, 1.0, 1) + (plus ? dBodyH(b2, n, 1.0, 1) : dBodyH(b2, n, -1.0, 0));
	double np = 0.0;
	for (int i = 0; i < dim; ++i)
		np += n[i] * p[i];
	return np - h;
}

/* Two unit vectors orthogonal to n (3D) or one (2D), in double. */
static void dTangents(const double *n, int dim, double T[2][3])
{
	if (dim == 2) {
		T[0][0] = -n[1];
		T[0][1] = n[0];
		T[0][2] = 0.0;
		return;
	}
	/* Cross n with the axis it is least aligned with. */
	int k = 0;
	for (int i = 1; i < 3; ++i)
		if (fabs(n[i]) < fabs(n[k]))
			k = i;
	double e[3] = { 0.0, 0.0, 0.0 };
	e[k] = 1.0;
	double a[3] = { n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2], n[0] * e[1] - n[1] * e[0] };
	double la = dNorm(a, 3);
	for (int i = 0; i < 3; ++i)
		a[i] /= la;
	double b[3] = { n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0] };
	double lb = dNorm(b, 3);
	for (int i = 0; i < 3; ++i) {
		T[0][i] = a[i];
		T[1][i] = b[i] / lb;
	}
}

static void dOffsetNormal(const double *n0, double T[2][3], int dim, const double *s, double *n)
{
	for (int i = 0; i < dim; ++i) {
		n[i] = n0[i] + s[0] * T[0][i];
		if (dim == 3)
			n[i] += s[1] * T[1][i];
	}
	double l = dNorm(n, dim);
	for (int i = 0; i < dim; ++i)
		n[i] /= l;
}

/* The cofactor matrix of M (M^-T = cof(M) / det M). */
static void cofactors(const refMat *M, int dim, double C[3][3])
{
	if (dim == 2) {
		C[0][0] = M->m[1][1];
		C[0][1] = -M->m[1][0];
		C[1][0] = -M->m[0][1];
		C[1][1] = M->m[0][0];
		return;
	}
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
			C[i][j] = M->m[i1][j1] * M->m[i2][j2] - M->m[i1][j2] * M->m[i2][j1];
		}
}

/* A start normal for p: the best of a scan of the circle (256 angles) or the
 * sphere (512 Fibonacci points) and of the bodies' face normals, polished by
 * a pattern search in double. Returns phi there, in double. */
double refSum_CoarseNormal(const refBody *b1, const refBody *b2, int plus, const double *p, double *best)
{
	int dim = b1->s.dim;
	double bestPhi = -INFINITY, n[3] = { 0.0, 0.0, 0.0 };
	int count = dim == 2 ? 256 : 512;
	best[0] = 1.0;
	best[1] = best[2] = 0.0;
	for (int i = 0; i < count; ++i) {
		if (dim == 2) {
			double th = 2.0 * MEAS_PI * i / count;
			n[0] = cos(th);
			n[1] = sin(th);
		} else {
			double z = 1.0 - (2.0 * i + 1.0) / count, r = sqrt(1.0 - z * z);
			double th = i * 2.39996322972865332;
			n[0] = r * cos(th);
			n[1] = r * sin(th);
			n[2] = z;
		}
		double f = dPhi(b1, b2, plus, p, n);
		if (f > bestPhi) {
			bestPhi = f;
			memcpy(best, n, sizeof n);
		}
	}
	/* The normals of the faces of bodies with eps near 0 or 2 (canonical
	 * (c_i / a_i), c in {-1, 0, 1}^dim, mapped by M^-T): there phi has a kink
	 * that a scan would only approach. */
	const refBody *bs[2] = { b1, b2 };
	for (int bi = 0; bi < 2; ++bi) {
		double C[3][3];
		cofactors(&bs[bi]->M, dim, C);
		for (int code = 0; code < (dim == 2 ? 9 : 27); ++code) {
			double m[3] = { 0.0, 0.0, 0.0 };
			int cc = code, nz = 0;
			for (int i = 0; i < dim; ++i) {
				int c = cc % 3 - 1;
				cc /= 3;
				m[i] = c / bs[bi]->s.a[i];
				nz |= c != 0;
			}
			if (!nz)
				continue;
			/* M^-T m is along cof(M) m (the determinant only scales it) */
			for (int i = 0; i < dim; ++i) {
				n[i] = 0.0;
				for (int j = 0; j < dim; ++j)
					n[i] += C[i][j] * m[j];
			}
			double l = dNorm(n, dim);
			if (!(l > 0.0))
				continue;
			for (int i = 0; i < dim; ++i)
				n[i] /= l;
			double f = dPhi(b1, b2, plus, p, n);
			if (f > bestPhi) {
				bestPhi = f;
				memcpy(best, n, sizeof n);
			}
		}
	}
	/* Pattern search: steps along +-T_k (and the diagonals in 3D),
	 * halved when none improves. */
	double step = dim == 2 ? 2.0 * MEAS_PI / count : 0.2;
	int moves = 0; /* at most 40 moves per step size: phi can rise along a
	                  ridge by steps too small to end the walk */
	while (step > 1e-12) {
		double T[2][3], cand[3], s[2];
		int improved = 0;
		dTangents(best, dim, T);
		static const double dirs[8][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 },
			{ 0.7071, 0.7071 }, { -0.7071, 0.7071 }, { 0.7071, -0.7071 }, { -0.7071, -0.7071 } };
		int ndir = dim == 2 ? 2 : 8;
		for (int d = 0; d < ndir; ++d) {
			s[0] = step * dirs[d][0];
			s[1] = step * dirs[d][1];
			dOffsetNormal(best, T, dim, s, cand);
			double f = dPhi(b1, b2, plus, p, cand);
			if (f > bestPhi) {
				bestPhi = f;
				memcpy(best, cand, sizeof cand);
				improved = 1;
				break;
			}
		}
		if (!improved || ++moves >= 40) {
			step *= 0.5;
			moves = 0;
		}
	}
	return bestPhi;
}

/* ---- the 256-bit search ------------------------------------------------- */

/* The boundary point of K with outward normal n, as refSum_Point with
 * normal parameters, except that a component of a body's canonical direction
 * below 2^-200 of the largest is taken as zero. Such components come from
 * rounding the round trip M^T (M^-T w) at 256 bits when the exact direction
 * has a zero there (the normal of a point in the middle of an edge or face
 * of an eps -> 0 body): the support point would jump from that middle to the
 * rim, where the face is flat to 1e-600000, and the bound |p - x| would
 * measure the face's size instead of the point's error. Both points lie on
 * the boundary; the support value moves by 2^-200 of the body's size. */
static void snapDirection(refVec *w, int dim)
{
	mpfr_t m, t;
	mpfr_inits2(REF_PREC, m, t, (mpfr_ptr)0);
	mpfr_set_zero(m, 1);
	for (int i = 0; i < dim; ++i) {
		mpfr_abs(t, w->c[i], RND);
		if (mpfr_greater_p(t, m))
			mpfr_set(m, t, RND);
	}
	mpfr_mul_2si(m, m, -200, RND);
	for (int i = 0; i < dim; ++i) {
		mpfr_abs(t, w->c[i], RND);
		if (mpfr_less_p(t, m))
			mpfr_set_zero(w->c[i], 1);
	}
	mpfr_clears(m, t, (mpfr_ptr)0);
}

/* x = x_K(n) and k = B1's part (t1 + M1 s1), n unit. */
static void sumSupport(const refBody *b1, const refBody *b2, int plus, const refVec *n, refVec *x, refVec *k)
{
	int dim = b1->s.dim;
	refVec w, sp, q;
	refVec_Init(&w);
	refVec_Init(&sp);
	refVec_Init(&q);
	refMat_MulTVec(&b1->M, dim, n, &w);
	snapDirection(&w, dim);
	refShape_SupportByLogs(b1->s, &w, &sp);
	refMat_MulVec(&b1->M, dim, &sp, k);
	for (int i = 0; i < dim; ++i)
		mpfr_add_d(k->c[i], k->c[i], b1->t[i], RND);
	refMat_MulTVec(&b2->M, dim, n, &w);
	if (!plus)
		for (int i = 0; i < dim; ++i)
			mpfr_neg(w.c[i], w.c[i], RND);
	snapDirection(&w, dim);
	refShape_SupportByLogs(b2->s, &w, &sp);
	refMat_MulVec(&b2->M, dim, &sp, &q);
	for (int i = 0; i < dim; ++i) {
		if (plus) {
			mpfr_add(x->c[i], k->c[i], q.c[i], RND);
			mpfr_add_d(x->c[i], x->c[i], b2->t[i], RND);
		} else {
			mpfr_sub(x->c[i], k->c[i], q.c[i], RND);
		}
	}
	for (int i = dim; i < 3; ++i)
		mpfr_set_zero(x->c[i], 1);
	refVec_Clear(&w);
	refVec_Clear(&sp);
	refVec_Clear(&q);
}

typedef struct refSearch {
	const refBody *b1, *b2;
	int plus, dim, k;
	refVec p, n0, T[2];
	refVec m, n, x, kk, v; /* workspace of searchEval */
	mpfr_t t, len;
	int evals;
} refSearch;

static void searchInit(refSearch *S, const refBody *b1, const refBody *b2, int plus, const double *p)
{
	S->b1 = b1;
	S->b2 = b2;
	S->plus = plus;
	S->dim = b1->s.dim;
	S->k = S->dim - 1;
	refVec_Init(&S->p);
	refVec_Init(&S->n0);
	refVec_Init(&S->T[0]);
	refVec_Init(&S->T[1]);
	refVec_Init(&S->m);
	refVec_Init(&S->n);
	refVec_Init(&S->x);
	refVec_Init(&S->kk);
	refVec_Init(&S->v);
	mpfr_init2(S->t, REF_PREC);
	mpfr_init2(S->len, REF_PREC);
	refVec_FromD(&S->p, S->dim, p);
	S->evals = 0;
}

static void searchClear(refSearch *S)
{
	refVec_Clear(&S->p);
	refVec_Clear(&S->n0);
	refVec_Clear(&S->T[0]);
	refVec_Clear(&S->T[1]);
	refVec_Clear(&S->m);
	refVec_Clear(&S->n);
	refVec_Clear(&S->x);
	refVec_Clear(&S->kk);
	refVec_Clear(&S->v);
	mpfr_clear(S->t);
	mpfr_clear(S->len);
}

/* Make n0 the base (n0 is normalised) and build its tangents. */
static void searchSetBase(refSearch *S, const refVec *n0)
{
	double nd[3] = { 0.0, 0.0, 0.0 }, T[2][3];
	refVec_Set(&S->n0, n0);
	refVec_Normalize(&S->n0, S->dim);
	refVec_ToD(&S->n0, S->dim, nd);
	dTangents(nd, S->dim, T);
	for (int k = 0; k < S->k; ++k)
		refVec_FromD(&S->T[k], S->dim, T[k]);
}

/* phi, its gradient g[k] in the offsets, and |v| at offset s. On return
 * S->n is the normal evaluated. */
static void searchEval(refSearch *S, const double *s, mpfr_t phi, mpfr_t *g, double *vlen)
{
	int dim = S->dim;
	for (int i = 0; i < dim; ++i) {
		mpfr_set(S->m.c[i], S->n0.c[i], RND);
		for (int k = 0; k < S->k; ++k) {
			mpfr_mul_d(S->t, S->T[k].c[i], s[k], RND);
			mpfr_add(S->m.c[i], S->m.c[i], S->t, RND);
		}
	}
	refVec_Dot(S->len, &S->m, &S->m, dim);
	mpfr_sqrt(S->len, S->len, RND);
	for (int i = 0; i < dim; ++i)
		mpfr_div(S->n.c[i], S->m.c[i], S->len, RND);
	sumSupport(S->b1, S->b2, S->plus, &S->n, &S->x, &S->kk);
	for (int i = 0; i < dim; ++i)
		mpfr_sub(S->v.c[i], S->p.c[i], S->x.c[i], RND);
	refVec_Dot(phi, &S->n, &S->v, dim);
	if (g)
		for (int k = 0; k < S->k; ++k) {
			/* (<v, T_k> - <T_k, n> phi) / |m| */
			refVec_Dot(g[k], &S->v, &S->T[k], dim);
			refVec_Dot(S->t, &S->T[k], &S->n, dim);
			mpfr_mul(S->t, S->t, phi, RND);
			mpfr_sub(g[k], g[k], S->t, RND);
			mpfr_div(g[k], g[k], S->len, RND);
		}
	if (vlen)
		*vlen = refVec_NormD(&S->v, dim);
	S->evals++;
}

/* The target of the search: 1e-21 of the size S, or 1e-5 of the distance
 * itself (a figure quoted to 4 digits on a log scale needs no more; the
 * rounding of any double output is 1e-16 of the size S). */
#define TOL_SCALE 1e-21
#define TOL_REL 1e-5
static double searchTol(double S, const mpfr_t phi)
{
	double t = TOL_REL * fabs(mpfr_get_d(phi, RND));
	return t > TOL_SCALE * S ? t : TOL_SCALE * S;
}

/* Newton on the sphere from the current base. Returns 1 when converged
 * (predicted gain below tol; *acc is that gain), 0 when it had to stop (no
 * negative-definite model or no ascent): the base is then the best normal
 * reached. phi holds the best value. */
static int searchNewton(refSearch *S, double scale, mpfr_t phi, double *acc)
{
	int k = S->k;
	mpfr_t g0[2], g1[2], ph, d;
	refVec best;
	double zero[2] = { 0.0, 0.0 };
	mpfr_inits2(REF_PREC, g0[0], g0[1], g1[0], g1[1], ph, d, (mpfr_ptr)0);
	refVec_Init(&best);
	int converged = 0;
	for (int it = 0; it < NEWTON_ITERS; ++it) {
		searchEval(S, zero, phi, g0, NULL);
		double H[2][2] = { { 0.0, 0.0 }, { 0.0, 0.0 } }, g[2] = { 0.0, 0.0 };
		for (int i = 0; i < k; ++i)
			g[i] = mpfr_get_d(g0[i], RND);
		for (int j = 0; j < k; ++j) {
			double s[2] = { 0.0, 0.0 };
			s[j] = FD_STEP;
			searchEval(S, s, ph, g1, NULL);
			for (int i = 0; i < k; ++i) {
				mpfr_sub(d, g1[i], g0[i], RND);
				H[i][j] = mpfr_get_d(d, RND) / FD_STEP;
			}
		}
		double delta[2] = { 0.0, 0.0 };
		if (k == 1) {
			if (!(H[0][0] < 0.0))
				break;
			delta[0] = -g[0] / H[0][0];
		} else {
			double h01 = 0.5 * (H[0][1] + H[1][0]);
			double det = H[0][0] * H[1][1] - h01 * h01;
			if (!(H[0][0] < 0.0 && det > 0.0))
				break;
			delta[0] = -(H[1][1] * g[0] - h01 * g[1]) / det;
			delta[1] = -(H[0][0] * g[1] - h01 * g[0]) / det;
		}
		double gain = 0.5 * (g[0] * delta[0] + g[1] * delta[1]);
		if (!isfinite(gain) || !isfinite(delta[0]) || !isfinite(delta[1]))
			break;
		if (fabs(gain) <= searchTol(scale, phi)) {
			*acc = fabs(gain);
			converged = 1;
			break;
		}
		/* Halving line search on phi itself. */
		int accepted = 0;
		for (int ls = 0; ls < 24; ++ls) {
			searchEval(S, delta, ph, NULL, NULL);
			if (mpfr_greater_p(ph, phi)) {
				accepted = 1;
				break;
			}
			delta[0] *= 0.5;
			delta[1] *= 0.5;
		}
		if (!accepted)
			break;
		refVec_Set(&best, &S->n);
		searchSetBase(S, &best);
	}
	mpfr_clears(g0[0], g0[1], g1[0], g1[1], ph, d, (mpfr_ptr)0);
	refVec_Clear(&best);
	return converged;
}

/* Nelder-Mead on the offsets with restarts that re-centre the base on the
 * best vertex. phi holds the best value on entry (at the base) and on exit;
 * *acc the estimated remaining gain. */
static void searchSimplex(refSearch *S, double scale, mpfr_t phi, double *acc)
{
	int k = S->k, nv = k + 1;
	mpfr_t f[3], fr, fe, gb[2];
	double v[3][2], xr[2], xe[2], c[2];
	refVec bestN;
	refVec_Init(&bestN);
	mpfr_inits2(REF_PREC, f[0], f[1], f[2], fr, fe, gb[0], gb[1], (mpfr_ptr)0);
	double r = 1e-8; /* Nelder-Mead grows it by expansions where needed */
	int budget = S->evals + NM_EVALS;
	*acc = INFINITY;
	while (S->evals < budget) {
		/* Simplex at the base: 0 and r e_j. */
		for (int i = 0; i < nv; ++i) {
			v[i][0] = v[i][1] = 0.0;
			if (i > 0)
				v[i][i - 1] = r;
			searchEval(S, v[i], f[i], NULL, NULL);
		}
		double diam = r;
		while (S->evals < budget) {
			/* order: f[0] best (largest) ... f[nv-1] worst */
			for (int i = 1; i < nv; ++i)
				for (int j = i; j > 0 && mpfr_greater_p(f[j], f[j - 1]); --j) {
					mpfr_swap(f[j], f[j - 1]);
					double t0 = v[j][0], t1 = v[j][1];
					v[j][0] = v[j - 1][0];
					v[j][1] = v[j - 1][1];
					v[j - 1][0] = t0;
					v[j - 1][1] = t1;
				}
			diam = 0.0;
			for (int i = 1; i < nv; ++i) {
				double dd = hypot(v[i][0] - v[0][0], v[i][1] - v[0][1]);
				if (dd > diam)
					diam = dd;
			}
			if (diam < 1e-3 * r || diam < 1e-60)
				break;
			int w = nv - 1;
			c[0] = c[1] = 0.0;
			for (int i = 0; i < w; ++i) {
				c[0] += v[i][0] / w;
				c[1] += v[i][1] / w;
			}
			for (int j = 0; j < 2; ++j)
				xr[j] = c[j] + (c[j] - v[w][j]);
			searchEval(S, xr, fr, NULL, NULL);
			if (mpfr_greater_p(fr, f[0])) {
				for (int j = 0; j < 2; ++j)
					xe[j] = c[j] + 2.0 * (c[j] - v[w][j]);
				searchEval(S, xe, fe, NULL, NULL);
				if (mpfr_greater_p(fe, fr)) {
					mpfr_set(f[w], fe, RND);
					v[w][0] = xe[0];
					v[w][1] = xe[1];
				} else {
					mpfr_set(f[w], fr, RND);
					v[w][0] = xr[0];
					v[w][1] = xr[1];
				}
			} else if (w > 1 && mpfr_greater_p(fr, f[w - 1])) {
				mpfr_set(f[w], fr, RND);
				v[w][0] = xr[0];
				v[w][1] = xr[1];
			} else {
				/* contraction (inside or outside), else shrink */
				int outside = mpfr_greater_p(fr, f[w]);
				for (int j = 0; j < 2; ++j)
					xe[j] = outside ? c[j] + 0.5 * (xr[j] - c[j]) : c[j] + 0.5 * (v[w][j] - c[j]);
				searchEval(S, xe, fe, NULL, NULL);
				if (mpfr_greater_p(fe, outside ? fr : f[w])) {
					mpfr_set(f[w], fe, RND);
					v[w][0] = xe[0];
					v[w][1] = xe[1];
				} else {
					for (int i = 1; i < nv; ++i) {
						v[i][0] = v[0][0] + 0.5 * (v[i][0] - v[0][0]);
						v[i][1] = v[0][1] + 0.5 * (v[i][1] - v[0][1]);
						searchEval(S, v[i], f[i], NULL, NULL);
					}
				}
			}
		}
		/* Re-centre on the best vertex and estimate the remaining gain as
		 * the slope there times the simplex size. */
		int b = 0;
		for (int i = 1; i < nv; ++i)
			if (mpfr_greater_p(f[i], f[b]))
				b = i;
		searchEval(S, v[b], f[b], gb, NULL);
		if (mpfr_greater_p(f[b], phi))
			mpfr_set(phi, f[b], RND);
		refVec_Set(&bestN, &S->n);
		searchSetBase(S, &bestN);
		double gl = 0.0;
		for (int i = 0; i < k; ++i)
			gl += mpfr_get_d(gb[i], RND) * mpfr_get_d(gb[i], RND);
		*acc = sqrt(gl) * diam;
		if (*acc <= searchTol(scale, phi) || diam < 1e-60)
			break;
		r = diam > 1e-60 ? diam : 1e-60;
	}
	mpfr_clears(f[0], f[1], f[2], fr, fe, gb[0], gb[1], (mpfr_ptr)0);
	refVec_Clear(&bestN);
}

int refFinite(const double *v, int dim)
{
	for (int i = 0; i < dim; ++i)
		if (!isfinite(v[i]))
			return 0;
	return 1;
}

/* The face certificate. Bodies with eps -> 0 have faces that are flat to
 * 1e-600000, far below 256 bits: every representable normal near the face
 * normal n has its support point at the face's centre or at its rim, and phi
 * has a kink at n at every scale the search can resolve. There the answer
 * is known directly: y = p - phi(n) n lies on the supporting plane of K at
 * n; if y belongs to K it lies on the boundary, so |d(p)| <= |phi(n)|, and
 * with d(p) >= phi(n) that gives d(p) = phi(n) when phi(n) >= 0 (exact), and
 * d(p) in [phi(n), -phi(n)] otherwise (|d| <= |phi| is then a bound, equal
 * to the distance to that face unless another face is nearer). y belongs to
 * K when y minus the other body's support point at n lies in one body: one
 * evaluation of that body's implicit function (<= 1 + 2^-200: the face is
 * flat to that precision in this model). Returns 1 when certified. */
static int faceCertificate(refSearch *S, const mpfr_t phi)
{
	int dim = S->dim, ok = 0;
	refVec x, k, y, z, c;
	refMat Mt;
	mpfr_t t, psi;
	refVec_Init(&x);
	refVec_Init(&k);
	refVec_Init(&y);
	refVec_Init(&z);
	refVec_Init(&c);
	mpfr_inits2(REF_PREC, t, psi, (mpfr_ptr)0);
	sumSupport(S->b1, S->b2, S->plus, &S->n0, &x, &k);
	for (int i = 0; i < dim; ++i) {
		mpfr_mul(t, phi, S->n0.c[i], RND);
		mpfr_sub(y.c[i], S->p.c[i], t, RND);
	}
	for (int which = 0; which < 2 && !ok; ++which) {
		const refBody *b = which == 0 ? S->b1 : S->b2;
		/* which 0: y - (x - k) in B1; which 1: y - k in B2 (plus) or
		 * k - y in M2 B2 (contact, no t2) */
		for (int i = 0; i < dim; ++i) {
			if (which == 0) {
				mpfr_sub(t, x.c[i], k.c[i], RND);
				mpfr_sub(z.c[i], y.c[i], t, RND);
				mpfr_sub_d(z.c[i], z.c[i], b->t[i], RND);
			} else if (S->plus) {
				mpfr_sub(z.c[i], y.c[i], k.c[i], RND);
				mpfr_sub_d(z.c[i], z.c[i], b->t[i], RND);
			} else {
				mpfr_sub(z.c[i], k.c[i], y.c[i], RND);
			}
		}
		/* canonical point M^-1 z = (M^T)^-T z */
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				Mt.m[i][j] = b->M.m[j][i];
		refMat_InvTVec(&Mt, dim, &z, &c);
		refShape_Implicit(b->s, &c, psi);
		mpfr_sub_ui(psi, psi, 1, RND);
		mpfr_set_ui_2exp(t, 1, -200, RND);
		ok = mpfr_lessequal_p(psi, t);
	}
	refVec_Clear(&x);
	refVec_Clear(&k);
	refVec_Clear(&y);
	refVec_Clear(&z);
	refVec_Clear(&c);
	mpfr_clears(t, psi, (mpfr_ptr)0);
	return ok;
}

/* The search from start normal n0 (double, nonzero). With newtonOnly the
 * derivative-free stage is skipped; returns 1 when the search reached its
 * target (out->accuracy is then the estimate), 0 otherwise (out->dist is
 * still a lower bound of d(p) and out->upper an upper bound of |d(p)|). */
int refSum_DistanceFrom(const refBody *b1, const refBody *b2, int plus, const double *p,
	const double *n0, const refVec *n0m, double S, int newtonOnly, refDistance *out)
{
	int dim = b1->s.dim;
	refSearch st;
	refVec base;
	mpfr_t phi, fin;
	searchInit(&st, b1, b2, plus, p);
	refVec_Init(&base);
	mpfr_init2(phi, REF_PREC);
	mpfr_init2(fin, REF_PREC);
	/* An exact start normal is kept at 256 bits: near the corners of
	 * eps -> 0 bodies its small components (1e-35 and less) decide where the
	 * support point is, and a double would round them away. */
	if (n0m)
		refVec_Set(&base, n0m);
	else
		refVec_FromD(&base, dim, n0);
	searchSetBase(&st, &base);
	double zero[2] = { 0.0, 0.0 }, vlen, acc = INFINITY;
	/* A face: certified at the start normal itself (Newton would only
	 * wander along the kink). */
	searchEval(&st, zero, phi, NULL, &vlen);
	double vStart = vlen;
	int done = faceCertificate(&st, phi);
	if (done)
		acc = 0.0;
	else
		done = searchNewton(&st, S, phi, &acc);
	if (!done && faceCertificate(&st, phi)) {
		done = 1;
		acc = 0.0;
	}
	if (!done && !newtonOnly) {
		searchSimplex(&st, S, phi, &acc);
		done = acc <= searchTol(S, phi);
	}
	/* The base is the best normal reached: its |v| bounds |d|. */
	searchEval(&st, zero, fin, NULL, &vlen);
	if (mpfr_greater_p(fin, phi))
		mpfr_set(phi, fin, RND);
	out->dist = mpfr_get_d(phi, RND);
	/* both |v| at the start and at the end bound |d| (x_K(n) lies on the
	 * boundary for any n); the start's is the tight one for an exact hint
	 * whose search wandered along a kink */
	out->upper = vStart < vlen ? vStart : vlen;
	out->accuracy = acc;
	out->normal[0] = out->normal[1] = out->normal[2] = 0.0;
	refVec_ToD(&st.n, dim, out->normal);
	out->evals = st.evals;
	mpfr_clear(phi);
	mpfr_clear(fin);
	refVec_Clear(&base);
	searchClear(&st);
	return done;
}

int refSum_Distance(const refBody *b1, const refBody *b2, int plus,
	const double *p, const double *hint, refDistance *out)
{
	int dim = b1->s.dim;
	double n0[3] = { 0.0, 0.0, 0.0 };
	if (!refFinite(p, dim))
		return -1;
	if (hint && (!refFinite(hint, dim) || !(dNorm(hint, dim) > 0.0)))
		return -1;
	/* The scan, and the hint where it does better in double precision. */
	refSum_CoarseNormal(b1, b2, plus, p, n0);
	if (hint) {
		double h[3] = { 0.0, 0.0, 0.0 }, l = dNorm(hint, dim);
		for (int i = 0; i < dim; ++i)
			h[i] = hint[i] / l;
		if (dPhi(b1, b2, plus, p, h) >= dPhi(b1, b2, plus, p, n0))
			memcpy(n0, h, sizeof h);
	}
	refSum_DistanceFrom(b1, b2, plus, p, n0, NULL, refSum_Size(b1, b2, plus), 0, out);
	return 0;
}

