/* error3_distance.c - the error measure's 3D pieces that work on K alone or
 * on one point: the volume of K (Richardson-extrapolated support-point
 * surfaces) and the signed distance of a point to K (Newton on the sphere,
 * the ray parameter of the boxier body, a branch and bound). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/error.h>

#include "error_internal.h"

/* ---- the volume of K (3D) -----------------------------------------------------------
 * Exact support points of K form a closed triangulated surface over a grid
 * of normals, G + 1 rows from pole to pole and 2G columns; its signed volume
 * (divergence theorem, sum of det(a, b, c) / 6) converges as G^-2. The
 * normals are the boxier body's (the one with the smaller exponent; its
 * textbook gradient mapped by M^-T) at the surface parameters of the
 * "almost equally spaced" grid (the
 * reference code's map of the angles, exponent 1/eps; mink/sum.h), so that
 * the points spread evenly over that body instead of crowding its edges
 * (normals taken evenly in angle leave its flat faces as single triangles
 * and its rounded edges underresolved). Grids G/2, G and 2G give two
 * Richardson extrapolations, V(G) + (V(G) - V(G/2)) / 3 and V(2G) + (V(2G)
 * - V(G)) / 3; the second is the value, and the difference of the two is
 * reported as the bound: an estimate, not a certificate. */
#define VOLUME_G 192

static double spow(double x, double e)
{
	return copysign(pow(fabs(x), e), x);
}

/* (c, s) of a grid angle, exact on the axes, then the spaced map. */
static void spaced_angle(double t, double inv_eps, double *c, double *s)
{
	double cc = cos(t), ss = sin(t);
	if (fabs(cc) < 1e-15) cc = 0.0, ss = ss > 0 ? 1.0 : -1.0;
	if (fabs(ss) < 1e-15) ss = 0.0, cc = cc > 0 ? 1.0 : -1.0;
	double big = fmax(fabs(cc), fabs(ss)), x = spow(cc / big, inv_eps), y = spow(ss / big, inv_eps), l = hypot(x, y);
	*c = x / l;
	*s = y / l;
}

/* A body's outward unit normal at surface parameter (eta, omega) angles
 * given by their cos/sin: the gradient of the canonical gauge,
 * (sp(ce, 2-e1) sp(cw, 2-e2) / a, sp(ce, 2-e1) sp(sw, 2-e2) / b, sp(se, 2-e1) / c),
 * mapped by M^-T (the cofactor matrix, up to a positive factor). */
static void body_normal(const mkBody3 *b, double ce, double se, double cw, double sw, double *n)
{
	const mkShape3 *sh = &b->shape;
	double r = spow(ce, 2.0 - sh->eps1);
	double g[3] = {r * spow(cw, 2.0 - sh->eps2) / sh->a, r * spow(sw, 2.0 - sh->eps2) / sh->b,
		spow(se, 2.0 - sh->eps1) / sh->c};
	mkMat3 C = mkMat3_Transpose(mkMat3_Inverse(b->M));
	for (int i = 0; i < 3; ++i) n[i] = C.m[i][0] * g[0] + C.m[i][1] * g[1] + C.m[i][2] * g[2];
	mkDev_Unit3(n);
}

static mkResult grid_volume(const mkDevProb3 *P, int G, double *vol)
{
	int rows = G + 1, cols = 2 * G;
	double *x = malloc(3 * (size_t)rows * (size_t)cols * sizeof *x);
	if (!x) return MK_ERR_MEMORY;
	const mkBody3 *lb = mkDev_LeadBody(P);
	double ie1 = 1.0 / lb->shape.eps1, ie2 = 1.0 / lb->shape.eps2;
	for (int i = 0; i < rows; ++i) {
		double ce, se;
		spaced_angle(-0.5 * MK_PI + MK_PI * i / G, ie1, &ce, &se);
		for (int j = 0; j < cols; ++j) {
			double cw, sw, n[3];
			spaced_angle(-MK_PI + 2.0 * MK_PI * j / cols, ie2, &cw, &sw);
			body_normal(lb, ce, se, cw, sw, n);
			mkDev_Hk3(P, n, x + 3 * ((size_t)i * cols + j));
		}
	}
	mkDevSum s = {0, 0};
	for (int i = 0; i < G; ++i)
		for (int j = 0; j < cols; ++j) {
			int j1 = (j + 1) % cols;
			const double *a = x + 3 * ((size_t)i * cols + j), *b = x + 3 * ((size_t)i * cols + j1);
			const double *c = x + 3 * ((size_t)(i + 1) * cols + j1), *d = x + 3 * ((size_t)(i + 1) * cols + j);
			double bc[3], cd[3];
			mkDev_Cross3(b, c, bc);
			mkDev_Cross3(c, d, cd);
			mkDevSum_Add(&s, mkDev_Dot3(a, bc) / 6.0);
			mkDevSum_Add(&s, mkDev_Dot3(a, cd) / 6.0);
		}
	free(x);
	*vol = fabs(mkDevSum_Get(&s));
	return MK_OK;
}

mkResult mkDev_Volume3(const mkDevProb3 *P, double *vol, double *bound)
{
	double v0, v1, v2;
	mkResult r = grid_volume(P, VOLUME_G / 2, &v0);
	if (r == MK_OK) r = grid_volume(P, VOLUME_G, &v1);
	if (r == MK_OK) r = grid_volume(P, 2 * VOLUME_G, &v2);
	if (r != MK_OK) return r;
	double e1 = v1 + (v1 - v0) / 3.0, e2 = v2 + (v2 - v1) / 3.0;
	*vol = e2;
	*bound = fabs(e2 - e1) + 16.0 * UNIT_ROUND * v2;
	return MK_OK;
}

mkResult mkDeviation3_Volume(mkBody3 b1, mkBody3 b2, mkSet set, double *volume, double *bound)
{
	mkDevProb3 P;
	if (!volume || !bound || !mkDev_Prob3Init(&P, b1, b2, set)) return MK_ERR_ARGUMENT;
	return mkDev_Volume3(&P, volume, bound);
}

/* ---- signed distance of a point to K (3D) -------------------------------------------
 * sd(p) = max over unit n of f(n) = <n, p> - h_K(n). Newton on the sphere:
 * with x = x_K(n) and r the tangential part of x - p in a frame (e1, e2) at
 * n, moving n by s1 e1 + s2 e2 changes r by (J + f I) s, J the 2 x 2
 * derivative of x's tangential part (K's radii of curvature, by finite
 * differences). Steps that do not raise f are halved. Every f is a lower
 * bound of sd; the last accepted rise is reported as the estimate of what
 * is left. */
typedef struct Eval3 { double n[3], x[3], f; } Eval3;

static Eval3 eval3(const mkDevProb3 *P, const double *n, const double *p)
{
	Eval3 e;
	memcpy(e.n, n, sizeof e.n);
	double h = mkDev_Hk3(P, n, e.x);
	e.f = mkDev_Dot3(n, p) - h;
	return e;
}

static void move3(const double *n, const double *e1, const double *e2, double s1, double s2, double *out)
{
	for (int i = 0; i < 3; ++i) out[i] = n[i] + s1 * e1[i] + s2 * e2[i];
	mkDev_Unit3(out);
}

/* A lower bound of g = h_{K-p} over the spherical triangle with unit corners
 * n[0..2], from the support points y[i] = x_K(n[i]) - p: on the flat
 * triangle, g(w) >= max_i <y_i, w> (the tangent planes of the convex g), a
 * piecewise-linear function whose minimum over the triangle is at a
 * corner, where two pieces cross on an edge, or where all three meet; and
 * a unit direction is w / |w| with mu <= |w| <= 1 (mu as in tri_bound). */
static double sph_lower(double n[3][3], double y[3][3])
{
	double A[3][3]; /* A[i][j] = <y_i, n_j> */
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) A[i][j] = mkDev_Dot3(y[i], n[j]);
	double lb = HUGE_VAL;
	for (int j = 0; j < 3; ++j) lb = fmin(lb, fmax(A[0][j], fmax(A[1][j], A[2][j])));
	for (int j = 0; j < 3; ++j) {
		int k = (j + 1) % 3;
		for (int i = 0; i < 3; ++i)
			for (int l = i + 1; l < 3; ++l) {
				double dj = A[i][j] - A[l][j], dk = A[i][k] - A[l][k];
				if (dj == dk) continue;
				double t = dj / (dj - dk);
				if (!(t > 0 && t < 1)) continue;
				double v = -HUGE_VAL;
				for (int m = 0; m < 3; ++m) v = fmax(v, (1 - t) * A[m][j] + t * A[m][k]);
				lb = fmin(lb, v);
			}
	}
	/* All three equal: with l2 = 1 - l0 - l1, row i is (A[i][0] - A[i][2]) l0
	 * + (A[i][1] - A[i][2]) l1 + A[i][2]; rows 0 and 1 minus row 2 give a
	 * 2 x 2 system (Cramer). */
	double m00 = (A[0][0] - A[0][2]) - (A[2][0] - A[2][2]), m01 = (A[0][1] - A[0][2]) - (A[2][1] - A[2][2]);
	double m10 = (A[1][0] - A[1][2]) - (A[2][0] - A[2][2]), m11 = (A[1][1] - A[1][2]) - (A[2][1] - A[2][2]);
	double det = m00 * m11 - m01 * m10;
	if (det != 0) {
		double c0 = -(A[0][2] - A[2][2]), c1 = -(A[1][2] - A[2][2]);
		double l0 = (c0 * m11 - m01 * c1) / det, l1 = (m00 * c1 - c0 * m10) / det, l2 = 1 - l0 - l1;
		if (l0 >= 0 && l1 >= 0 && l2 >= 0) {
			double v = -HUGE_VAL;
			for (int m = 0; m < 3; ++m) v = fmax(v, A[m][0] * l0 + A[m][1] * l1 + A[m][2] * l2);
			lb = fmin(lb, v);
		}
	}
	if (lb >= 0) return lb;
	double c[3] = {n[0][0] + n[1][0] + n[2][0], n[0][1] + n[1][1] + n[2][1], n[0][2] + n[1][2] + n[2][2]};
	if (!mkDev_Unit3(c)) return -HUGE_VAL;
	double mu = fmin(mkDev_Dot3(n[0], c), fmin(mkDev_Dot3(n[1], c), mkDev_Dot3(n[2], c)));
	return mu > 0 ? lb / mu : -HUGE_VAL;
}

typedef struct STri { double n[3][3], y[3][3]; int depth; } STri;

#define SD_BUDGET 1500

/* Branch and bound for min g over a hexagon of spherical triangles of
 * radius rho around n0: *best receives the smallest g found (attained, with
 * its direction in nbest), the return value a lower bound of g over the
 * hexagon. */
static double sd_branch(const mkDevProb3 *P, const double *n0, double rho, const double *p, double *best, double *nbest)
{
	STri stack[4 * 64 + 16];
	int sp = 0;
	long evals = 0;
	double e1[3], e2[3], ring[6][3], yr[6][3], yc[3], x[3];
	mkDev_Frame3(n0, e1, e2);
	double g0 = mkDev_Hk3(P, n0, x);
	for (int i = 0; i < 3; ++i) yc[i] = x[i] - p[i];
	g0 -= mkDev_Dot3(n0, p);
	if (g0 < *best) *best = g0, memcpy(nbest, n0, 3 * sizeof *n0);
	for (int k = 0; k < 6; ++k) {
		move3(n0, e1, e2, rho * cos(MK_PI * k / 3), rho * sin(MK_PI * k / 3), ring[k]);
		double g = mkDev_Hk3(P, ring[k], x) - mkDev_Dot3(ring[k], p);
		for (int i = 0; i < 3; ++i) yr[k][i] = x[i] - p[i];
		if (g < *best) *best = g, memcpy(nbest, ring[k], 3 * sizeof *n0);
	}
	for (int k = 0; k < 6; ++k) {
		STri t;
		memcpy(t.n[0], n0, 3 * sizeof *n0), memcpy(t.y[0], yc, sizeof yc);
		memcpy(t.n[1], ring[k], sizeof ring[k]), memcpy(t.y[1], yr[k], sizeof yr[k]);
		memcpy(t.n[2], ring[(k + 1) % 6], sizeof ring[k]), memcpy(t.y[2], yr[(k + 1) % 6], sizeof yr[k]);
		t.depth = 0;
		stack[sp++] = t;
	}
	double low = HUGE_VAL;
	while (sp > 0) {
		STri t = stack[--sp];
		double lb = sph_lower(t.n, t.y), tol = fmax(1e-3 * fabs(*best), P->round);
		if (lb >= *best - tol || evals >= SD_BUDGET || t.depth >= 60 || sp + 4 > (int)(sizeof stack / sizeof *stack)) {
			low = fmin(low, lb);
			continue;
		}
		double m[3][3], ym[3][3];
		for (int k = 0; k < 3; ++k) {
			const double *a = t.n[k], *b = t.n[(k + 1) % 3];
			for (int i = 0; i < 3; ++i) m[k][i] = a[i] + b[i];
			mkDev_Unit3(m[k]);
			double g = mkDev_Hk3(P, m[k], x) - mkDev_Dot3(m[k], p);
			for (int i = 0; i < 3; ++i) ym[k][i] = x[i] - p[i];
			if (g < *best) *best = g, memcpy(nbest, m[k], sizeof m[k]);
		}
		evals += 3;
		/* Children: (n0, m0, m2), (m0, n1, m1), (m2, m1, n2), (m0, m1, m2). */
		const double *cn[4][3] = {{t.n[0], m[0], m[2]}, {m[0], t.n[1], m[1]}, {m[2], m[1], t.n[2]}, {m[0], m[1], m[2]}};
		const double *cy[4][3] = {{t.y[0], ym[0], ym[2]}, {ym[0], t.y[1], ym[1]}, {ym[2], ym[1], t.y[2]}, {ym[0], ym[1], ym[2]}};
		for (int c = 0; c < 4; ++c) {
			STri u;
			for (int k = 0; k < 3; ++k) {
				memcpy(u.n[k], cn[c][k], 3 * sizeof(double));
				memcpy(u.y[k], cy[c][k], 3 * sizeof(double));
			}
			u.depth = t.depth + 1;
			stack[sp++] = u;
		}
	}
	return fmin(low, *best);
}

/* The lead body's outward unit normal (world) where the ray of canonical direction
 * v meets its surface: the gradient of the implicit function Psi there,
 * which depends only on v's direction (Psi is homogeneous), mapped by M^-T.
 * In this parameter the normal is smooth across the flat faces of a boxy
 * body (exponents 2/eps - 1 > 1), where the support map in n is not. */
static void ray_normal(const mkDevProb3 *P, const mkMat3 *MinvT, const double *v, double *n)
{
	const mkShape3 *sh = &mkDev_LeadBody(P)->shape;
	double s0 = v[0] / sh->a, s1 = v[1] / sh->b, s2 = v[2] / sh->c;
	double big = fmax(fabs(s0), fmax(fabs(s1), fabs(s2)));
	s0 /= big, s1 /= big, s2 /= big;
	double A = pow(fabs(s0), 2.0 / sh->eps2) + pow(fabs(s1), 2.0 / sh->eps2);
	double f = A > 0 ? pow(A, sh->eps2 / sh->eps1 - 1.0) : 0.0;
	double g[3] = {A > 0 ? f * spow(s0, 2.0 / sh->eps2 - 1.0) / sh->a : 0.0,
		A > 0 ? f * spow(s1, 2.0 / sh->eps2 - 1.0) / sh->b : 0.0, spow(s2, 2.0 / sh->eps1 - 1.0) / sh->c};
	for (int i = 0; i < 3; ++i) n[i] = MinvT->m[i][0] * g[0] + MinvT->m[i][1] * g[1] + MinvT->m[i][2] * g[2];
	mkDev_Unit3(n);
}

/* f as a function of the lead body's canonical ray direction v. */
static double ray_f(const mkDevProb3 *P, const mkMat3 *MinvT, const double *v, const double *p, Eval3 *e)
{
	double n[3];
	ray_normal(P, MinvT, v, n);
	*e = eval3(P, n, p);
	return e->f;
}

/* Newton in the ray parameter, with a finite-difference gradient and
 * Hessian on the tangent plane of v (6 evaluations a step); steps that do
 * not raise f are halved. Raises *e when it finds a larger f. */
static void ray_newton(const mkDevProb3 *P, const double *p, Eval3 *e)
{
	const mkBody3 *lb = mkDev_LeadBody(P);
	mkMat3 MinvT = mkMat3_Transpose(mkMat3_Inverse(lb->M));
	double xc[3], m[3], v[3];
	const double(*M)[3] = lb->M.m;
	for (int j = 0; j < 3; ++j) m[j] = M[0][j] * e->n[0] + M[1][j] * e->n[1] + M[2][j] * e->n[2];
	mkDev_Canon3(lb->shape, m[0], m[1], m[2], xc);
	memcpy(v, xc, sizeof v);
	if (!mkDev_Unit3(v)) return;
	Eval3 cur;
	double fc = ray_f(P, &MinvT, v, p, &cur), h = 1e-5;
	for (int it = 0; it < 30; ++it) {
		double e1[3], e2[3], w[3], F[3][3];
		mkDev_Frame3(v, e1, e2);
		Eval3 tmp;
		for (int a = -1; a <= 1; ++a)
			for (int b = -1; b <= 1; ++b) {
				if (a == 0 && b == 0) {
					F[1][1] = fc;
					continue;
				}
				if (a * b == -1) continue;
				move3(v, e1, e2, a * h, b * h, w);
				F[a + 1][b + 1] = ray_f(P, &MinvT, w, p, &tmp);
			}
		double ga = (F[2][1] - F[0][1]) / (2 * h), gb = (F[1][2] - F[1][0]) / (2 * h);
		double haa = (F[2][1] - 2 * fc + F[0][1]) / (h * h), hbb = (F[1][2] - 2 * fc + F[1][0]) / (h * h);
		double hab = (F[2][2] - F[2][1] - F[1][2] + 2 * fc - F[0][1] - F[1][0] + F[0][0]) / (2 * h * h);
		double det = haa * hbb - hab * hab, sa, sb;
		if (haa < 0 && det > 0) {
			sa = -(hbb * ga - hab * gb) / det;
			sb = -(-hab * ga + haa * gb) / det;
		} else {
			double gn = hypot(ga, gb);
			if (!(gn > 0)) break;
			sa = 1e-3 * ga / gn;
			sb = 1e-3 * gb / gn;
		}
		double len = hypot(sa, sb);
		if (len > 0.1) sa *= 0.1 / len, sb *= 0.1 / len, len = 0.1;
		int moved = 0;
		for (int k = 0; k < 40 && len > 1e-16; ++k) {
			move3(v, e1, e2, sa, sb, w);
			Eval3 t;
			double ft = ray_f(P, &MinvT, w, p, &t);
			if (ft > fc) {
				memcpy(v, w, sizeof v);
				fc = ft;
				cur = t;
				moved = 1;
				break;
			}
			sa *= 0.5, sb *= 0.5, len *= 0.5;
		}
		if (!moved) break;
		h = fmin(1e-5, fmax(1e-7, len));
	}
	if (cur.f > e->f) *e = cur;
}

void mkDev_SignedDistance3(const mkDevProb3 *P, const double *start, const double *p, double *sd, double *left)
{
	Eval3 e = eval3(P, start, p);
	double last = HUGE_VAL, step = 1e-3;
	for (int it = 0; it < 40; ++it) {
		double e1[3], e2[3], n1[3], n2[3];
		mkDev_Frame3(e.n, e1, e2);
		double r[2] = {0, 0};
		for (int i = 0; i < 3; ++i) {
			r[0] += (e.x[i] - p[i]) * e1[i];
			r[1] += (e.x[i] - p[i]) * e2[i];
		}
		/* Finite-difference step: small enough that x stays on the same
		 * smooth patch even where the radii of curvature are large (the
		 * faces of boxy bodies), large enough that rounding (u |x| / dl)
		 * stays far below the derivative. */
		double dl = fmin(1e-7, fmax(1e-10, step));
		move3(e.n, e1, e2, dl, 0, n1);
		move3(e.n, e1, e2, 0, dl, n2);
		double x1[3], x2[3];
		mkDev_Hk3(P, n1, x1);
		mkDev_Hk3(P, n2, x2);
		double J[2][2];
		for (int i = 0; i < 2; ++i) {
			const double *ei = i == 0 ? e1 : e2;
			J[i][0] = ((x1[0] - e.x[0]) * ei[0] + (x1[1] - e.x[1]) * ei[1] + (x1[2] - e.x[2]) * ei[2]) / dl;
			J[i][1] = ((x2[0] - e.x[0]) * ei[0] + (x2[1] - e.x[1]) * ei[1] + (x2[2] - e.x[2]) * ei[2]) / dl;
		}
		/* (J + f I), symmetrised, kept positive: near a sharp edge or
		 * corner J is nearly 0 and the step is then limited below. */
		double lam = 1e-12 * P->R;
		double a = fmax(J[0][0] + e.f, lam), d = fmax(J[1][1] + e.f, lam), b = 0.5 * (J[0][1] + J[1][0]);
		double det = a * d - b * b;
		double s1, s2;
		if (det > 0) {
			s1 = -(d * r[0] - b * r[1]) / det;
			s2 = -(-b * r[0] + a * r[1]) / det;
		} else {
			s1 = -r[0] / a;
			s2 = -r[1] / d;
		}
		double len = hypot(s1, s2);
		if (len > 0.5) s1 *= 0.5 / len, s2 *= 0.5 / len, len = 0.5;
		if (!(len > 1e-15)) break;
		/* The rise the quadratic model predicts for this step, (r . s) / 2:
		 * below a thousandth of the rounding allowance no step can raise f
		 * visibly (the line search would only halve into rounding noise).
		 * Where the model is wrong (near a flat face) the residual test
		 * below still hands the point on. */
		double rise = 0.5 * fabs(r[0] * s1 + r[1] * s2);
		if (rise <= P->round * 1e-3) {
			last = rise;
			break;
		}
		int moved = 0;
		for (int h = 0; h < 30; ++h) {
			double nn[3];
			move3(e.n, e1, e2, s1, s2, nn);
			Eval3 t = eval3(P, nn, p);
			if (t.f > e.f) {
				last = t.f - e.f;
				e = t;
				moved = 1;
				break;
			}
			s1 *= 0.5;
			s2 *= 0.5;
			len *= 0.5;
			if (len < 1e-15) break;
		}
		step = len;
		if (!moved) {
			last = 0;
			break;
		}
		if (last <= P->round * 1e-3) break;
	}
	*sd = e.f;
	*left = last == HUGE_VAL ? 0.0 : last;
	/* Newton stalls where the support map is not differentiable (the axis
	 * normals of a boxy body). At the maximiser the tangential part of
	 * x_K(n) - p vanishes; where it does not, Newton is run again in the
	 * lead body's ray parameter (smooth there), and if that does not settle it
	 * either, branch and bound on spherical triangles (sph_lower) takes over
	 * around the best direction, recentred while the best direction lies
	 * near the hexagon's rim. */
	double e1[3], e2[3], r0 = 0, r1 = 0;
	mkDev_Frame3(e.n, e1, e2);
	for (int i = 0; i < 3; ++i) {
		r0 += (e.x[i] - p[i]) * e1[i];
		r1 += (e.x[i] - p[i]) * e2[i];
	}
	if (hypot(r0, r1) > 1e-7 * P->R) {
		double f0 = e.f;
		ray_newton(P, p, &e);
		if (e.f > f0) {
			*sd = e.f;
			*left = fmax(*left, e.f - f0);
		}
	}
	r0 = r1 = 0;
	mkDev_Frame3(e.n, e1, e2);
	for (int i = 0; i < 3; ++i) {
		r0 += (e.x[i] - p[i]) * e1[i];
		r1 += (e.x[i] - p[i]) * e2[i];
	}
	if (hypot(r0, r1) > 1e-7 * P->R) {
		double best = -e.f, nb[3], n0[3], rho = 0.02, low = -HUGE_VAL;
		memcpy(nb, e.n, sizeof nb);
		for (int round = 0; round < 4; ++round) {
			memcpy(n0, nb, sizeof n0);
			low = sd_branch(P, n0, rho, p, &best, nb);
			if (mkDev_Dot3(nb, n0) > cos(0.6 * rho)) break;
		}
		*sd = -best;
		*left = fmax(0.0, best - low);
	}
}

