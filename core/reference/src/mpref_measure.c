/* mpref_measure.c - distance from the exact boundary of a sum, the scale and
 * the problem's condition (mink/mpref_measure.h).
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

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RND MPFR_RNDN
#define MEAS_PI 3.14159265358979323846
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
static double coarseNormal(const refBody *b1, const refBody *b2, int plus, const double *p, double *best)
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

/* The target of the search: 1e-21 of the scale, or 1e-5 of the distance
 * itself (a figure quoted to 4 digits on a log scale needs no more; the
 * rounding of any double output is 1e-16 of the scale). */
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

static int finite3(const double *v, int dim)
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
static int distanceFrom(const refBody *b1, const refBody *b2, int plus, const double *p,
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
	if (!finite3(p, dim))
		return -1;
	if (hint && (!finite3(hint, dim) || !(dNorm(hint, dim) > 0.0)))
		return -1;
	/* The scan, and the hint where it does better in double precision. */
	coarseNormal(b1, b2, plus, p, n0);
	if (hint) {
		double h[3] = { 0.0, 0.0, 0.0 }, l = dNorm(hint, dim);
		for (int i = 0; i < dim; ++i)
			h[i] = hint[i] / l;
		if (dPhi(b1, b2, plus, p, h) >= dPhi(b1, b2, plus, p, n0))
			memcpy(n0, h, sizeof h);
	}
	distanceFrom(b1, b2, plus, p, n0, NULL, refSum_Size(b1, b2, plus), 0, out);
	return 0;
}

/* ---- the memo of refSum_ScoreMemo ---------------------------------------- */

/* Kinds of memoised work: the scan (coarseNormal) of a point, the Newton
 * stage from the exact normal at u, and distanceFrom from a double start
 * normal with or without the derivative-free stage. */
enum { MEMO_SCAN = 1, MEMO_EXACT_NEWTON = 2, MEMO_START_NEWTON = 3, MEMO_START_FULL = 4 };

typedef struct refMemoEntry {
	int kind;          /* 0: empty slot */
	double p[3], s[3]; /* the point and its start (u or the start normal; unused by MEMO_SCAN) */
	int done;          /* distanceFrom's return */
	double phi;        /* MEMO_SCAN: coarseNormal's return */
	double n0[3];      /* MEMO_SCAN: the normal it found */
	refDistance d;
} refMemoEntry;

struct refScoreMemo {
	refBody b1, b2;
	int plus, valid;
	refMemoEntry *slot;
	size_t cap, used;
	long hits, misses;
};

refScoreMemo *refScoreMemo_New(void)
{
	return calloc(1, sizeof(refScoreMemo));
}

void refScoreMemo_Free(refScoreMemo *memo)
{
	if (memo)
		free(memo->slot);
	free(memo);
}

void refScoreMemo_Counts(const refScoreMemo *memo, long *hits, long *misses)
{
	*hits = memo ? memo->hits : 0;
	*misses = memo ? memo->misses : 0;
}

static int bodySame(const refBody *a, const refBody *b)
{
	if (a->s.dim != b->s.dim || a->s.e1 != b->s.e1 || a->s.e2 != b->s.e2)
		return 0;
	for (int i = 0; i < 3; ++i) {
		if (a->s.a[i] != b->s.a[i] || a->t[i] != b->t[i])
			return 0;
		for (int j = 0; j < 3; ++j)
			if (a->M.m[i][j] != b->M.m[i][j])
				return 0;
	}
	return 1;
}

/* Bound the memo to the pair (emptied when it was another's). */
static void memoBind(refScoreMemo *m, const refBody *b1, const refBody *b2, int plus)
{
	if (m->valid && m->plus == plus && bodySame(&m->b1, b1) && bodySame(&m->b2, b2))
		return;
	if (m->slot)
		memset(m->slot, 0, m->cap * sizeof *m->slot);
	m->used = 0;
	m->b1 = *b1;
	m->b2 = *b2;
	m->plus = plus;
	m->valid = 1;
}

/* Keys compare by bits (so -0 and 0 differ, as they may for the search). */
static uint64_t memoHash(int kind, const double *p, const double *s)
{
	uint64_t h = 0x9e3779b97f4a7c15u * (uint64_t)kind;
	for (int i = 0; i < 6; ++i) {
		uint64_t w;
		memcpy(&w, i < 3 ? &p[i] : &s[i - 3], sizeof w);
		h ^= w + 0x9e3779b97f4a7c15u + (h << 6) + (h >> 2);
		h *= 0xbf58476d1ce4e5b9u;
	}
	return h ^ (h >> 31);
}

static int memoKeyEq(const refMemoEntry *e, int kind, const double *p, const double *s)
{
	return e->kind == kind && memcmp(e->p, p, sizeof e->p) == 0 && memcmp(e->s, s, sizeof e->s) == 0;
}

/* The slot of (kind, p, s): its entry when present (*found = 1), else the
 * empty slot to fill (NULL when the table cannot grow). */
static refMemoEntry *memoSlot(refScoreMemo *m, int kind, const double *p, const double *s, int *found)
{
	*found = 0;
	if (2 * (m->used + 1) > m->cap) {
		size_t cap = m->cap ? 2 * m->cap : 256;
		refMemoEntry *slot = calloc(cap, sizeof *slot);
		if (!slot)
			return NULL;
		for (size_t i = 0; i < m->cap; ++i) {
			const refMemoEntry *e = &m->slot[i];
			if (!e->kind)
				continue;
			size_t j = memoHash(e->kind, e->p, e->s) & (cap - 1);
			while (slot[j].kind)
				j = (j + 1) & (cap - 1);
			slot[j] = *e;
		}
		free(m->slot);
		m->slot = slot;
		m->cap = cap;
	}
	size_t j = memoHash(kind, p, s) & (m->cap - 1);
	while (m->slot[j].kind) {
		if (memoKeyEq(&m->slot[j], kind, p, s)) {
			*found = 1;
			return &m->slot[j];
		}
		j = (j + 1) & (m->cap - 1);
	}
	return &m->slot[j];
}

static void memoFill(refScoreMemo *m, refMemoEntry *e, int kind, const double *p, const double *s)
{
	e->kind = kind;
	memcpy(e->p, p, sizeof e->p);
	memcpy(e->s, s, sizeof e->s);
	m->used++;
	m->misses++;
}

/* coarseNormal through the memo. Returns 0, or -1 when the memo cannot grow. */
static int memoScan(refScoreMemo *m, const refBody *b1, const refBody *b2, int plus, const double *p,
	double *n0, double *phi)
{
	static const double none[3] = { 0.0, 0.0, 0.0 };
	if (!m) {
		*phi = coarseNormal(b1, b2, plus, p, n0);
		return 0;
	}
	int found;
	refMemoEntry *e = memoSlot(m, MEMO_SCAN, p, none, &found);
	if (!e)
		return -1;
	if (found) {
		m->hits++;
	} else {
		e->phi = coarseNormal(b1, b2, plus, p, e->n0);
		memoFill(m, e, MEMO_SCAN, p, none);
	}
	*phi = e->phi;
	memcpy(n0, e->n0, sizeof e->n0);
	return 0;
}

/* distanceFrom through the memo: from the double start n0 (u NULL), or
 * from the exact normal nn of B1 at u (newtonOnly then). Returns
 * distanceFrom's result, or -1 when the memo cannot grow. */
static int distanceAt(const refBody *b1, const refBody *b2, int plus, const double *p,
	const double *n0, const double *u, double S, int newtonOnly, refDistance *out)
{
	if (!u)
		return distanceFrom(b1, b2, plus, p, n0, NULL, S, newtonOnly, out);
	/* The exact normal of B1 at u, kept at 256 bits (see distanceFrom). */
	int dim = b1->s.dim;
	double nd[3] = { 0.0, 0.0, 0.0 };
	refVec uu, nn;
	refVec_Init(&uu);
	refVec_Init(&nn);
	refVec_FromD(&uu, dim, u);
	refBody_Normal(b1, &uu, &nn);
	refVec_ToD(&nn, dim, nd);
	int done = distanceFrom(b1, b2, plus, p, nd, &nn, S, 1, out);
	refVec_Clear(&uu);
	refVec_Clear(&nn);
	return done;
}

static int memoDistance(refScoreMemo *m, const refBody *b1, const refBody *b2, int plus, const double *p,
	const double *n0, const double *u, double S, int newtonOnly, refDistance *out)
{
	if (!m)
		return distanceAt(b1, b2, plus, p, n0, u, S, newtonOnly, out);
	int kind = u ? MEMO_EXACT_NEWTON : newtonOnly ? MEMO_START_NEWTON : MEMO_START_FULL, found;
	const double *s = u ? u : n0;
	refMemoEntry *e = memoSlot(m, kind, p, s, &found);
	if (!e)
		return -1;
	if (found) {
		m->hits++;
	} else {
		e->done = distanceAt(b1, b2, plus, p, n0, u, S, newtonOnly, &e->d);
		memoFill(m, e, kind, p, s);
	}
	*out = e->d;
	return e->done;
}

/* ---- scoring a point set ------------------------------------------------ */

typedef struct refCand { int index; double bound; double n0[3]; } refCand;

static int candCompare(const void *a, const void *b)
{
	double x = ((const refCand *)a)->bound, y = ((const refCand *)b)->bound;
	return x < y ? 1 : x > y ? -1 : 0;
}

static void scoreTake(refScore *out, int index, const refDistance *d)
{
	double a = fabs(d->dist);
	if (out->worst < 0 || a > out->errorAbs) {
		out->errorAbs = a;
		out->worst = index;
		out->worstDist = d->dist;
	}
}

int refSum_Score(const refBody *b1, const refBody *b2, int plus,
	const double *x, const double *y, const double *z, int count,
	const double *ux, const double *uy, const double *uz, refScore *out)
{
	return refSum_ScoreMemo(b1, b2, plus, x, y, z, count, ux, uy, uz, NULL, out);
}

int refSum_ScoreMemo(const refBody *b1, const refBody *b2, int plus,
	const double *x, const double *y, const double *z, int count,
	const double *ux, const double *uy, const double *uz, refScoreMemo *memo, refScore *out)
{
	if (!out)
		return -1;
	memset(out, 0, sizeof *out);
	out->worst = -1;
	if (!b1 || !b2)
		return -1;
	int dim = b1->s.dim;
	out->size = refSum_Size(b1, b2, plus);
	if (count < 0 || (count > 0 && (!x || !y || (dim == 3 && !z))))
		return -1;
	int hints = ux && uy && (dim == 2 || uz);
	refCand *cand = malloc(sizeof *cand * (size_t)(count > 0 ? count : 1));
	if (!cand)
		return -1;
	if (memo)
		memoBind(memo, b1, b2, plus);
	int pending = 0, oom = 0;
	double accMax = 0.0;
	if (!hints) {
		/* Without parameters (hull vertices): the scan's phi in double is
		 * within MARGIN of d(p) (the double support value errs by up to
		 * q u h <= 2e6 * 1.1e-16 * S at eps = 2 - 1e-6, the pattern search
		 * stops 1e-12 rad from a kink of slope <= S), so |d| <= |phi| +
		 * MARGIN. The 256-bit search runs in decreasing order of that bound
		 * until it falls below the largest distance known: a sampled hull's
		 * errors (1e-6 ... 1e-2 of S) are decided by a few vertices. */
		for (int i = 0; i < count; ++i) {
			double p[3] = { x[i], y[i], dim == 3 ? z[i] : 0.0 };
			if (!finite3(p, dim)) {
				out->nonfinite++;
				continue;
			}
			out->points++;
			refCand *c = &cand[pending++];
			c->index = i;
			double f;
			if (memoScan(memo, b1, b2, plus, p, c->n0, &f) != 0) {
				oom = 1;
				break;
			}
			c->bound = fabs(f) + 1e-9 * out->size + 1e-6 * fabs(f);
		}
		qsort(cand, (size_t)pending, sizeof *cand, candCompare);
		for (int i = 0; i < pending && !oom; ++i) {
			if (out->worst >= 0 && cand[i].bound <= out->errorAbs)
				break;
			int j = cand[i].index;
			double p[3] = { x[j], y[j], dim == 3 ? z[j] : 0.0 };
			refDistance d;
			int done = memoDistance(memo, b1, b2, plus, p, cand[i].n0, NULL, out->size, 1, &d);
			if (done == 0) {
				done = memoDistance(memo, b1, b2, plus, p, cand[i].n0, NULL, out->size, 0, &d);
				out->refined++;
			}
			if (done < 0) {
				oom = 1;
				break;
			}
			out->searched++;
			scoreTake(out, j, &d);
			if (d.accuracy > accMax)
				accMax = d.accuracy;
		}
		pending = 0;
	}
	/* Stage 1 (with parameters): Newton from the exact normal of every
	 * point. Where it converges the distance is known; elsewhere (kinks)
	 * keep the bound |d| <= |v| and the normal reached. */
	for (int i = 0; i < count && hints && !oom; ++i) {
		double p[3] = { x[i], y[i], dim == 3 ? z[i] : 0.0 };
		if (!finite3(p, dim)) {
			out->nonfinite++;
			continue;
		}
		out->points++;
		double ud[3] = { ux[i], uy[i], dim == 3 ? uz[i] : 0.0 };
		refDistance d;
		out->searched++;
		int done = memoDistance(memo, b1, b2, plus, p, NULL, ud, out->size, 1, &d);
		if (done < 0) {
			oom = 1;
		} else if (done) {
			scoreTake(out, i, &d);
			if (d.accuracy > accMax)
				accMax = d.accuracy;
		} else {
			refCand *c = &cand[pending++];
			c->index = i;
			c->bound = d.upper;
			memcpy(c->n0, d.normal, sizeof c->n0);
		}
	}
	/* Stage 2: the derivative-free search, in decreasing order of the bound,
	 * until the bound falls below the largest distance known. */
	qsort(cand, (size_t)pending, sizeof *cand, candCompare);
	for (int i = 0; i < pending && !oom; ++i) {
		if (out->worst >= 0 && cand[i].bound <= out->errorAbs)
			break; /* every remaining point is bounded below the maximum */
		int j = cand[i].index;
		double p[3] = { x[j], y[j], dim == 3 ? z[j] : 0.0 };
		refDistance d;
		if (memoDistance(memo, b1, b2, plus, p, cand[i].n0, NULL, out->size, 0, &d) < 0) {
			oom = 1;
			break;
		}
		out->refined++;
		scoreTake(out, j, &d);
		if (d.accuracy > accMax)
			accMax = d.accuracy;
	}
	if (out->worst >= 0) {
		out->errorRel = out->errorAbs / out->size;
		out->accuracy = accMax / out->size;
	}
	free(cand);
	if (oom) {
		memset(out, 0, sizeof *out);
		out->worst = -1;
		return -1;
	}
	return 0;
}

/* ---- the problem's condition ------------------------------------------- */

void refSample_Params(int dim, int n, double *ux, double *uy, double *uz)
{
	if (dim == 2) {
		for (int k = 0; k < n; ++k) {
			ux[k] = cos(2.0 * MEAS_PI * k / n);
			uy[k] = sin(2.0 * MEAS_PI * k / n);
		}
		return;
	}
	for (int i = 0; i < n; ++i)
		for (int j = 0; j < n; ++j) {
			double lon = 2.0 * MEAS_PI * i / n, col = MEAS_PI * j / (n - 1);
			ux[i * n + j] = sin(col) * cos(lon);
			uy[i * n + j] = sin(col) * sin(lon);
			uz[i * n + j] = cos(col);
		}
}

static uint64_t splitmix(uint64_t *s)
{
	uint64_t z = (*s += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

static double ulpMove(double v, uint64_t *rng)
{
	return nextafter(v, (splitmix(rng) >> 63) ? INFINITY : -INFINITY);
}

/* Every input moved by one ulp, up or down at random. B2's translation only
 * matters for the plus set. */
static refBody perturb(const refBody *b, uint64_t *rng, int withT)
{
	refBody r = *b;
	int dim = b->s.dim;
	for (int i = 0; i < dim; ++i)
		r.s.a[i] = ulpMove(r.s.a[i], rng);
	r.s.e1 = ulpMove(r.s.e1, rng);
	if (dim == 3)
		r.s.e2 = ulpMove(r.s.e2, rng);
	for (int i = 0; i < dim; ++i)
		for (int j = 0; j < dim; ++j)
			r.M.m[i][j] = ulpMove(r.M.m[i][j], rng);
	if (withT)
		for (int i = 0; i < dim; ++i)
			r.t[i] = ulpMove(r.t[i], rng);
	return r;
}

int refSum_Condition(const refBody *b1, const refBody *b2, int plus,
	int samples, int draws, uint64_t seed, refCondition *out)
{
	int dim = b1->s.dim;
	if (!out)
		return -1;
	memset(out, 0, sizeof *out);
	if (samples < 2 || draws < 1)
		return -1;
	int count = dim == 2 ? samples : samples * samples;
	double *ud = malloc(sizeof(double) * 3 * (size_t)count);
	if (!ud)
		return -1;
	refSample_Params(dim, samples, ud, ud + count, dim == 3 ? ud + 2 * count : NULL);
	double S = refSum_Size(b1, b2, plus);
	refBody *p1 = malloc(sizeof(refBody) * 2 * (size_t)draws);
	if (!p1) {
		free(ud);
		return -1;
	}
	refBody *p2 = p1 + draws;
	uint64_t rng = seed;
	for (int r = 0; r < draws; ++r) {
		p1[r] = perturb(b1, &rng, 1);
		p2[r] = perturb(b2, &rng, plus);
	}
	refVec u, x, n, xp, d;
	mpfr_t h, hp;
	refVec_Init(&u);
	refVec_Init(&x);
	refVec_Init(&n);
	refVec_Init(&xp);
	refVec_Init(&d);
	mpfr_inits2(REF_PREC, h, hp, (mpfr_ptr)0);
	for (int k = 0; k < count; ++k) {
		double uk[3] = { ud[k], ud[count + k], dim == 3 ? ud[2 * count + k] : 0.0 };
		refVec_FromD(&u, dim, uk);
		refSum_Point(b1, b2, plus, 1, &u, &x, NULL, &n);
		refSum_SupportValue(b1, b2, plus, &n, h);
		/* floor: the exact point rounded to double, along the normal */
		double xd[3] = { 0.0, 0.0, 0.0 };
		refVec_ToD(&x, dim, xd);
		refVec_FromD(&d, dim, xd);
		for (int i = 0; i < dim; ++i)
			mpfr_sub(d.c[i], d.c[i], x.c[i], RND);
		refVec_Dot(hp, &d, &n, dim);
		double fl = fabs(mpfr_get_d(hp, RND)) / S;
		if (fl > out->floor)
			out->floor = fl;
		for (int r = 0; r < draws; ++r) {
			refSum_SupportValue(&p1[r], &p2[r], plus, &n, hp);
			mpfr_sub(hp, hp, h, RND);
			double bd = fabs(mpfr_get_d(hp, RND)) / S;
			if (bd > out->boundary)
				out->boundary = bd;
			refSum_Point(&p1[r], &p2[r], plus, 1, &u, &xp, NULL, NULL);
			for (int i = 0; i < dim; ++i)
				mpfr_sub(d.c[i], xp.c[i], x.c[i], RND);
			double pt = refVec_NormD(&d, dim) / S;
			if (pt > out->point)
				out->point = pt;
		}
	}
	out->value = out->boundary > out->floor ? out->boundary : out->floor;
	mpfr_clears(h, hp, (mpfr_ptr)0);
	refVec_Clear(&u);
	refVec_Clear(&x);
	refVec_Clear(&n);
	refVec_Clear(&xp);
	refVec_Clear(&d);
	free(p1);
	free(ud);
	return 0;
}
