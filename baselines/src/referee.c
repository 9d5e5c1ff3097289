/* referee.c - the support check of boundary points and the dispatch of the
 * referee (mink/referee.h); the hull check of sampled methods is in
 * referee_hull.c. The body model here is the referee's own: the
 * textbook parametric point and gradient of the superellipse and the
 * superquadric, written out again so that the check does not lean on the
 * core code it judges.
 *
 * Bounds used (d a unit direction, B a convex body, x_k its dense samples
 * with exact outward unit normals n_k, so that h(n_k) = <n_k, x_k>):
 *   lower:  H(d) = max_k <d, x_k> <= h(d), since the samples lie in B;
 *   upper:  for any l_k >= 0 and the residual r = d - sum l_k n_k,
 *           h(d) <= sum l_k h(n_k) + h(r) <= sum l_k <n_k, x_k> + |r| R,
 *           by sublinearity of h, with R >= max |x| over B (a bound from the
 *           semi-axes and |M|_F). The l_k come from the two (2D) or three
 *           (3D) sample normals nearest to d whose cone holds d; the residual
 *           term keeps the bound valid whatever rounding did to them.
 * The support function of the sum is the sum of the bodies' (body 2 enters
 * reflected for the contact set), so H and U add.
 *
 * Rounding allowance. An exact method's point is a few dozen roundings
 * away from the boundary: a pow per coordinate (<= 1 ulp, amplified by the
 * exponent 2/eps or 1/(2-eps), up to about 200 for eps in [0.01, 1.99]),
 * the maps M1, M2 and the translation (a few ulps of |M| |f| and |t|). The
 * referee's own H and U carry similar roundings. So each side is within
 * some 10^3 units of roundoff of the sum's extent E = |t|_inf + R1 + R2;
 * MK_REFEREE_ULPS is 4096 such units (about 4.5e-13 E). A wrong formula is
 * off by orders more (the tests perturb points by 1e-9 E and see the
 * referee fail them). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/error.h>
#include <mink/referee.h>
#include <mink/registry.h>

#include "referee_cgal.h"

#define FAN_ANGLE 0.02 /* radians between n_k and the fan directions */

static double spow(double x, double e)
{
	return copysign(pow(fabs(x), e), x);
}

/* ---- the referee's body model -------------------------------------------- */

/* Canonical point and gradient direction at the unit vector (c, s). */
static void shape2(mkShape2 sh, double c, double s, double *f, double *g)
{
	f[0] = sh.a * spow(c, sh.eps);
	f[1] = sh.b * spow(s, sh.eps);
	g[0] = spow(c, 2.0 - sh.eps) / sh.a;
	g[1] = spow(s, 2.0 - sh.eps) / sh.b;
}

/* (ce, se) = (cos eta, sin eta), ce >= 0; (cw, sw) = (cos omega, sin omega). */
static void shape3(mkShape3 sh, double ce, double se, double cw, double sw, double *f, double *g)
{
	double r1 = spow(ce, sh.eps1), r2 = spow(ce, 2.0 - sh.eps1);
	f[0] = sh.a * r1 * spow(cw, sh.eps2);
	f[1] = sh.b * r1 * spow(sw, sh.eps2);
	f[2] = sh.c * spow(se, sh.eps1);
	g[0] = r2 * spow(cw, 2.0 - sh.eps2) / sh.a;
	g[1] = r2 * spow(sw, 2.0 - sh.eps2) / sh.b;
	g[2] = spow(se, 2.0 - sh.eps1) / sh.c;
}

/* v parallel to M^-T g, same sense: sign(det M) times the cofactor matrix. */
static void cof2(const mkMat2 *M, const double *g, double *v)
{
	const double(*m)[2] = M->m;
	double s = m[0][0] * m[1][1] - m[0][1] * m[1][0] < 0 ? -1.0 : 1.0;
	v[0] = s * (m[1][1] * g[0] - m[1][0] * g[1]);
	v[1] = s * (-m[0][1] * g[0] + m[0][0] * g[1]);
}

static void cof3(const mkMat3 *M, const double *g, double *v)
{
	const double(*m)[3] = M->m;
	double c[3][3] = {
		{m[1][1] * m[2][2] - m[1][2] * m[2][1], m[1][2] * m[2][0] - m[1][0] * m[2][2],
			m[1][0] * m[2][1] - m[1][1] * m[2][0]},
		{m[0][2] * m[2][1] - m[0][1] * m[2][2], m[0][0] * m[2][2] - m[0][2] * m[2][0],
			m[0][1] * m[2][0] - m[0][0] * m[2][1]},
		{m[0][1] * m[1][2] - m[0][2] * m[1][1], m[0][2] * m[1][0] - m[0][0] * m[1][2],
			m[0][0] * m[1][1] - m[0][1] * m[1][0]},
	};
	double det = m[0][0] * c[0][0] + m[0][1] * c[0][1] + m[0][2] * c[0][2];
	double s = det < 0 ? -1.0 : 1.0;
	for (int i = 0; i < 3; ++i) v[i] = s * (c[i][0] * g[0] + c[i][1] * g[1] + c[i][2] * g[2]);
}

static void normalize(double *v, int dim)
{
	double big = 0;
	for (int i = 0; i < dim; ++i) big = fmax(big, fabs(v[i]));
	if (!(big > 0) || !isfinite(big)) return;
	double len = 0;
	for (int i = 0; i < dim; ++i) {
		v[i] /= big;
		len += v[i] * v[i];
	}
	len = sqrt(len);
	for (int i = 0; i < dim; ++i) v[i] /= len;
}

/* Point relative to the centre (M f) and unit world normal of a placed body
 * at the unit parameter vector u. */
static void body2_local(const mkBody2 *b, double ux, double uy, double *x, double *n)
{
	double len = hypot(ux, uy), f[2], g[2];
	shape2(b->shape, ux / len, uy / len, f, g);
	x[0] = b->M.m[0][0] * f[0] + b->M.m[0][1] * f[1];
	x[1] = b->M.m[1][0] * f[0] + b->M.m[1][1] * f[1];
	cof2(&b->M, g, n);
	normalize(n, 2);
}

static void body3_local(const mkBody3 *b, double ux, double uy, double uz, double *x, double *n)
{
	double big = fmax(fabs(ux), fmax(fabs(uy), fabs(uz)));
	ux /= big;
	uy /= big;
	uz /= big;
	double len = sqrt(ux * ux + uy * uy + uz * uz);
	ux /= len;
	uy /= len;
	uz /= len;
	double rho = hypot(ux, uy), f[3], g[3];
	double cw = rho > 0 ? ux / rho : 1.0, sw = rho > 0 ? uy / rho : 0.0;
	shape3(b->shape, rho, uz, cw, sw, f, g);
	for (int i = 0; i < 3; ++i) x[i] = b->M.m[i][0] * f[0] + b->M.m[i][1] * f[1] + b->M.m[i][2] * f[2];
	cof3(&b->M, g, n);
	normalize(n, 3);
}

mkVec2 mkReferee2_Point(mkBody2 b, mkVec2 u, mkVec2 *normal)
{
	double x[2], n[2];
	body2_local(&b, u.x, u.y, x, n);
	if (normal) *normal = (mkVec2){n[0], n[1]};
	return (mkVec2){b.t.x + x[0], b.t.y + x[1]};
}

mkVec3 mkReferee3_Point(mkBody3 b, mkVec3 u, mkVec3 *normal)
{
	double x[3], n[3];
	body3_local(&b, u.x, u.y, u.z, x, n);
	if (normal) *normal = (mkVec3){n[0], n[1], n[2]};
	return (mkVec3){b.t.x + x[0], b.t.y + x[1], b.t.z + x[2]};
}

/* A bound on max |x - t| over the body: |M|_F times the half-diagonal of the
 * canonical shape's bounding box. */
static double radius2(const mkBody2 *b)
{
	double m = 0;
	for (int i = 0; i < 2; ++i)
		for (int j = 0; j < 2; ++j) m = hypot(m, b->M.m[i][j]);
	return m * hypot(b->shape.a, b->shape.b);
}

static double radius3(const mkBody3 *b)
{
	double m = 0;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) m = hypot(m, b->M.m[i][j]);
	return m * hypot(hypot(b->shape.a, b->shape.b), b->shape.c);
}

/* ---- dense samples and the support bounds ---------------------------------
 * Samples are stored as they enter the sum: relative to the body's centre,
 * and reflected (points and normals) for body 2 of the contact set. */

typedef struct Dense {
	int dim;
	int n;       /* samples (2D) or grid side (3D) */
	int count;   /* samples */
	double *x;   /* dim * count coordinates */
	double *nrm; /* dim * count unit normals */
	double *h;   /* <n_k, x_k> */
	double R;    /* radius bound */
	double rmax; /* max |x_k|_inf */
	const mkBody2 *b2; /* the body (one of the two), for the local bounds */
	const mkBody3 *b3;
	double sign; /* -1: the body enters reflected */
} Dense;

static void dense_free(Dense *d)
{
	free(d->x);
	free(d->nrm);
	free(d->h);
	memset(d, 0, sizeof *d);
}

static int dense_alloc(Dense *d, int dim, int n, int count)
{
	memset(d, 0, sizeof *d);
	d->dim = dim;
	d->n = n;
	d->count = count;
	d->x = malloc((size_t)dim * (size_t)count * sizeof *d->x);
	d->nrm = malloc((size_t)dim * (size_t)count * sizeof *d->nrm);
	d->h = malloc((size_t)count * sizeof *d->h);
	if (!d->x || !d->nrm || !d->h) {
		dense_free(d);
		return -1;
	}
	return 0;
}

static void dense_finish(Dense *d, double sign)
{
	d->rmax = 0;
	for (int k = 0; k < d->count; ++k) {
		double *x = d->x + d->dim * k, *nn = d->nrm + d->dim * k, h = 0;
		for (int i = 0; i < d->dim; ++i) {
			x[i] *= sign;
			nn[i] *= sign;
			h += x[i] * nn[i];
			d->rmax = fmax(d->rmax, fabs(x[i]));
		}
		d->h[k] = h;
	}
}

static int dense2(Dense *d, const mkBody2 *b, int n, double sign)
{
	if (dense_alloc(d, 2, n, n)) return -1;
	for (int k = 0; k < n; ++k) {
		/* Angles offset by half a step from the methods' own grid. */
		double th = -MK_PI + 2.0 * MK_PI * (k + 0.5) / n;
		body2_local(b, cos(th), sin(th), d->x + 2 * k, d->nrm + 2 * k);
	}
	d->R = radius2(b);
	d->b2 = b;
	d->sign = sign;
	dense_finish(d, sign);
	return 0;
}

static int dense3(Dense *d, const mkBody3 *b, int n, double sign)
{
	if (dense_alloc(d, 3, n, n * n)) return -1;
	for (int i = 0; i < n; ++i) {
		double eta = -MK_PI / 2 + MK_PI * i / (n - 1);
		double ce = (i == 0 || i == n - 1) ? 0.0 : cos(eta), se = sin(eta);
		for (int j = 0; j < n; ++j) {
			double om = -MK_PI + 2.0 * MK_PI * (j + 0.5) / n;
			int k = i * n + j;
			body3_local(b, ce * cos(om), ce * sin(om), se, d->x + 3 * k, d->nrm + 3 * k);
		}
	}
	d->R = radius3(b);
	d->b3 = b;
	d->sign = sign;
	dense_finish(d, sign);
	return 0;
}

static double dot(const double *a, const double *b, int dim)
{
	double s = 0;
	for (int i = 0; i < dim; ++i) s += a[i] * b[i];
	return s;
}

/* H(d): the largest <d, x_k>. */
static double dense_lower(const Dense *d, const double *dir)
{
	double best = -HUGE_VAL;
	for (int k = 0; k < d->count; ++k) best = fmax(best, dot(dir, d->x + d->dim * k, d->dim));
	return best;
}

/* The sample whose normal is closest to dir. */
static int dense_locate(const Dense *d, const double *dir)
{
	int best = 0;
	double bv = -HUGE_VAL;
	for (int k = 0; k < d->count; ++k) {
		double v = dot(dir, d->nrm + d->dim * k, d->dim);
		if (v > bv) {
			bv = v;
			best = k;
		}
	}
	return best;
}

/* The dual bound for weights l (negative ones clamped to 0) on samples idx:
 * sum l_k h_k + |dir - sum l_k n_k| R. *inside tells whether no weight was
 * clamped (the cone of those normals holds dir). */
static double dual_bound(const Dense *d, const double *dir, const int *idx, const double *l, int m, int *inside)
{
	double r[3] = {dir[0], dir[1], d->dim == 3 ? dir[2] : 0.0}, sum = 0;
	*inside = 1;
	for (int k = 0; k < m; ++k) {
		double w = l[k];
		if (!(w >= 0)) {
			*inside = 0;
			continue;
		}
		const double *nn = d->nrm + d->dim * idx[k];
		for (int i = 0; i < d->dim; ++i) r[i] -= w * nn[i];
		sum += w * d->h[idx[k]];
	}
	double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
	return sum + rl * d->R;
}

/* U(d) for a 2D body: pairs of neighbouring samples around the located one,
 * widening until a pair's cone holds d. */
static double dense_upper2(const Dense *d, const double *dir, int *loose)
{
	int n = d->count, c = dense_locate(d, dir), in;
	int one[1] = {c};
	double l1[1] = {dot(dir, d->nrm + 2 * c, 2)};
	double best = dual_bound(d, dir, one, l1, 1, &in);
	for (int w = 1;; w *= 2) {
		int found = 0;
		for (int s = -w; s < w; ++s) {
			int i = ((c + s) % n + n) % n, j = (i + 1) % n;
			const double *a = d->nrm + 2 * i, *b = d->nrm + 2 * j;
			double det = a[0] * b[1] - a[1] * b[0];
			if (fabs(det) < 1e-15) continue;
			double l[2] = {(dir[0] * b[1] - dir[1] * b[0]) / det, (a[0] * dir[1] - a[1] * dir[0]) / det};
			int idx[2] = {i, j};
			double v = dual_bound(d, dir, idx, l, 2, &in);
			if (in) found = 1;
			best = fmin(best, v);
		}
		if (found) return best;
		if (2 * w >= n) break;
	}
	++*loose;
	return best;
}

static void cross3(const double *a, const double *b, double *c)
{
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
}

/* U(d) for a 3D body: the four triangles of each grid cell around the
 * located sample, widening until a triangle's cone holds d. */
static double dense_upper3(const Dense *d, const double *dir, int *loose)
{
	int n = d->n, c = dense_locate(d, dir), in;
	int ci = c / n, cj = c % n;
	int one[1] = {c};
	double l1[1] = {dot(dir, d->nrm + 3 * c, 3)};
	double best = dual_bound(d, dir, one, l1, 1, &in);
	static const int tri[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 2, 3}};
	for (int w = 1;; w *= 2) {
		int found = 0;
		int i0 = ci - w < 0 ? 0 : ci - w, i1 = ci + w > n - 2 ? n - 2 : ci + w;
		int jspan = 2 * w + 1 > n ? n : 2 * w + 1;
		for (int i = i0; i <= i1; ++i)
			for (int s = 0; s < jspan; ++s) {
				int j = ((cj - w + s) % n + n) % n, j1 = (j + 1) % n;
				int corner[4] = {i * n + j, (i + 1) * n + j, (i + 1) * n + j1, i * n + j1};
				for (int t = 0; t < 4; ++t) {
					int idx[3] = {corner[tri[t][0]], corner[tri[t][1]], corner[tri[t][2]]};
					const double *a = d->nrm + 3 * idx[0], *b = d->nrm + 3 * idx[1], *e = d->nrm + 3 * idx[2];
					double bc[3], ca[3], ab[3];
					cross3(b, e, bc);
					cross3(e, a, ca);
					cross3(a, b, ab);
					double det = dot(a, bc, 3);
					if (fabs(det) < 1e-15) continue;
					double l[3] = {dot(dir, bc, 3) / det, dot(dir, ca, 3) / det, dot(dir, ab, 3) / det};
					double v = dual_bound(d, dir, idx, l, 3, &in);
					if (in) found = 1;
					best = fmin(best, v);
				}
			}
		if (found) return best;
		if (w >= n) break;
	}
	++*loose;
	return best;
}

static double dense_upper(const Dense *d, const double *dir, int *loose)
{
	return d->dim == 2 ? dense_upper2(d, dir, loose) : dense_upper3(d, dir, loose);
}

/* ---- local bounds at the support point ------------------------------------
 * The dense samples' bounds are loose by their sampling error. Near the
 * support point of d they are sharpened: the referee inverts its own normal
 * formula (the dual-norm map of the superellipse / superquadric) to find the
 * parameter u* whose normal is d, takes the point there (a lower bound of
 * h(d), being a point of the body) and points at a small angle D around u*
 * (whose tangent planes give the dual upper bound, valid whatever u* is;
 * only its tightness, about rho D^2, depends on u* being right). */

#define LOCAL_STEPS 9
static const double local_step[LOCAL_STEPS] = {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 3e-2, 0.1, 0.3};

/* The dual bound of weights l on points x (rows) with unit normals nn. */
static double dual_local(const double *dir, const double (*x)[3], const double (*nn)[3], const double *l, int m,
	int dim, double R, int *inside)
{
	double r[3] = {dir[0], dir[1], dim == 3 ? dir[2] : 0.0}, sum = 0;
	*inside = 1;
	for (int k = 0; k < m; ++k) {
		if (!(l[k] >= 0)) {
			*inside = 0;
			continue;
		}
		for (int i = 0; i < dim; ++i) r[i] -= l[k] * nn[k][i];
		sum += l[k] * dot(nn[k], x[k], dim);
	}
	return sum + sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) * R;
}

static void local2(const Dense *d, const double *dir, double *lo, double *up)
{
	const mkBody2 *b = d->b2;
	/* The body itself (unreflected) in direction e = sign dir. */
	double e[2] = {d->sign * dir[0], d->sign * dir[1]};
	double m0 = b->M.m[0][0] * e[0] + b->M.m[1][0] * e[1], m1 = b->M.m[0][1] * e[0] + b->M.m[1][1] * e[1];
	double A = b->shape.a * m0, B = b->shape.b * m1, big = fmax(fabs(A), fabs(B));
	double q = 1.0 / (2.0 - b->shape.eps);
	double th = atan2(spow(B / big, q), spow(A / big, q));
	double x[3][3] = {{0}}, nn[3][3] = {{0}};
	body2_local(b, cos(th), sin(th), x[0], nn[0]);
	*lo = dot(e, x[0], 2);
	*up = HUGE_VAL;
	for (int s = 0; s < LOCAL_STEPS; ++s) {
		body2_local(b, cos(th - local_step[s]), sin(th - local_step[s]), x[1], nn[1]);
		body2_local(b, cos(th + local_step[s]), sin(th + local_step[s]), x[2], nn[2]);
		double det = nn[1][0] * nn[2][1] - nn[1][1] * nn[2][0];
		if (!(fabs(det) > 1e-300)) continue;
		double l[2] = {0, 0}, r[2] = {e[0], e[1]};
		/* Cramer's rule, then two steps of refinement on the residual: the
		 * normals are nearly parallel, so one solve leaves a residual of
		 * u / det along d, which the bound would pay for in full. */
		for (int it = 0; it < 3; ++it) {
			l[0] += (r[0] * nn[2][1] - r[1] * nn[2][0]) / det;
			l[1] += (nn[1][0] * r[1] - nn[1][1] * r[0]) / det;
			for (int i = 0; i < 2; ++i) r[i] = e[i] - l[0] * nn[1][i] - l[1] * nn[2][i];
		}
		int in;
		double v = dual_local(e, (const double(*)[3])x + 1, (const double(*)[3])nn + 1, l, 2, 2, d->R, &in);
		if (in) {
			*up = v;
			return;
		}
	}
}

static void local3(const Dense *d, const double *dir, double *lo, double *up)
{
	const mkBody3 *b = d->b3;
	const mkShape3 *sh = &b->shape;
	double e[3] = {d->sign * dir[0], d->sign * dir[1], d->sign * dir[2]}, m[3];
	for (int j = 0; j < 3; ++j) m[j] = b->M.m[0][j] * e[0] + b->M.m[1][j] * e[1] + b->M.m[2][j] * e[2];
	double A = sh->a * m[0], B = sh->b * m[1], C = sh->c * m[2];
	double big = fmax(fabs(A), fmax(fabs(B), fabs(C)));
	A /= big;
	B /= big;
	C /= big;
	double q1 = 1.0 / (2.0 - sh->eps1), q2 = 1.0 / (2.0 - sh->eps2);
	double ca = spow(A, q2), sb = spow(B, q2), w = hypot(ca, sb);
	double cw = w > 0 ? ca / w : 1.0, sw = w > 0 ? sb / w : 0.0;
	double ce = pow(w, (2.0 - sh->eps2) * q1), se = spow(C, q1), len = hypot(ce, se);
	ce /= len;
	se /= len;
	double u[3] = {ce * cw, ce * sw, se};
	double x[4][3], nn[4][3];
	body3_local(b, u[0], u[1], u[2], x[0], nn[0]);
	*lo = dot(e, x[0], 3);
	*up = HUGE_VAL;
	/* Tangent directions at u*: u crossed with its least-aligned axis. */
	double axis[3] = {0, 0, 0}, t1[3], t2[3];
	int k = fabs(u[0]) <= fabs(u[1]) ? (fabs(u[0]) <= fabs(u[2]) ? 0 : 2) : (fabs(u[1]) <= fabs(u[2]) ? 1 : 2);
	axis[k] = 1;
	cross3(u, axis, t1);
	normalize(t1, 3);
	cross3(u, t1, t2);
	/* In 3D the three normals span a cone of width D, so the solve is
	 * conditioned like 1/D^2: start at D = 1e-6 (gap about rho 1e-12), where
	 * a few steps of refinement still bring the residual to roundoff. */
	for (int s = 1; s < LOCAL_STEPS; ++s) {
		double D = local_step[s];
		for (int j = 0; j < 3; ++j) {
			double c = cos(2 * MK_PI * j / 3), sn = sin(2 * MK_PI * j / 3), v[3];
			for (int i = 0; i < 3; ++i) v[i] = u[i] + D * (c * t1[i] + sn * t2[i]);
			body3_local(b, v[0], v[1], v[2], x[1 + j], nn[1 + j]);
		}
		double bc[3], ca3[3], ab[3];
		cross3(nn[2], nn[3], bc);
		cross3(nn[3], nn[1], ca3);
		cross3(nn[1], nn[2], ab);
		double det = dot(nn[1], bc, 3);
		if (!(fabs(det) > 1e-300)) continue;
		double l[3] = {0, 0, 0}, r[3] = {e[0], e[1], e[2]};
		for (int it = 0; it < 6; ++it) { /* solve and refine, as in local2 */
			l[0] += dot(r, bc, 3) / det;
			l[1] += dot(r, ca3, 3) / det;
			l[2] += dot(r, ab, 3) / det;
			for (int i = 0; i < 3; ++i) r[i] = e[i] - l[0] * nn[1][i] - l[1] * nn[2][i] - l[2] * nn[3][i];
		}
		int in;
		double val = dual_local(e, (const double(*)[3])x + 1, (const double(*)[3])nn + 1, l, 3, 3, d->R, &in);
		if (in) {
			*up = val;
			return;
		}
	}
}

/* H(d) and U(d) for one body: the dense samples' bounds, sharpened by the
 * local ones. *dense_gap receives the dense samples' own U - H. */
static void body_bounds(const Dense *d, const double *dir, double *lo, double *up, double *dense_gap, int *loose)
{
	double hl = dense_lower(d, dir), hu = dense_upper(d, dir, loose), ll, lu;
	*dense_gap = hu - hl;
	if (d->dim == 2) local2(d, dir, &ll, &lu);
	else local3(d, dir, &ll, &lu);
	*lo = fmax(hl, ll);
	*up = fmin(hu, lu);
}

/* ---- the support check --------------------------------------------------- */

static void verdict_init(mkVerdict *v, int kind, int points)
{
	memset(v, 0, sizeof *v);
	v->kind = kind;
	v->points = points;
	v->worst = -1;
	v->depth = -HUGE_VAL;
	v->excess = -HUGE_VAL;
}

/* Fan directions around the unit vector n: n itself, then n turned by
 * FAN_ANGLE each way (2D) or towards four tangent directions (3D). */
static int fan_dirs(int dim, const double *n, int fan, double out[5][3])
{
	out[0][0] = n[0];
	out[0][1] = n[1];
	out[0][2] = dim == 3 ? n[2] : 0.0;
	if (!fan) return 1;
	double c = cos(FAN_ANGLE), s = sin(FAN_ANGLE);
	if (dim == 2) {
		out[1][0] = c * n[0] - s * n[1];
		out[1][1] = s * n[0] + c * n[1];
		out[2][0] = c * n[0] + s * n[1];
		out[2][1] = -s * n[0] + c * n[1];
		out[1][2] = out[2][2] = 0.0;
		return 3;
	}
	/* e1: n crossed with its least-aligned axis; e2 = n x e1. */
	double axis[3] = {0, 0, 0}, e1[3], e2[3];
	int m = fabs(n[0]) <= fabs(n[1]) ? (fabs(n[0]) <= fabs(n[2]) ? 0 : 2) : (fabs(n[1]) <= fabs(n[2]) ? 1 : 2);
	axis[m] = 1;
	cross3(n, axis, e1);
	normalize(e1, 3);
	cross3(n, e1, e2);
	for (int k = 0; k < 4; ++k) {
		const double *e = k < 2 ? e1 : e2;
		double sg = (k % 2) ? -1.0 : 1.0;
		for (int i = 0; i < 3; ++i) out[1 + k][i] = c * n[i] + sg * s * e[i];
	}
	return 5;
}

static mkResult support_check(const Dense *d1, const Dense *d2, const double *shift, int dim, const mkPointSet *pts,
	const double *nx, const double *ny, const double *nz, const mkRefereeOptions *opt, mkVerdict *v)
{
	int fan = !(opt && opt->nofan);
	double factor = opt && opt->tol_factor > 0 ? opt->tol_factor : 1.0;
	double tmax = 0;
	for (int i = 0; i < dim; ++i) tmax = fmax(tmax, fabs(shift[i]));
	v->extent = tmax + d1->rmax + d2->rmax;
	v->tol = factor * MK_REFEREE_ULPS * (DBL_EPSILON / 2) * v->extent;
	double worst = -HUGE_VAL;
	for (int k = 0; k < pts->count; ++k) {
		double p[3] = {pts->x[k] - shift[0], pts->y[k] - shift[1], dim == 3 ? pts->z[k] - shift[2] : 0.0};
		double n[3] = {nx[k], ny[k], dim == 3 ? nz[k] : 0.0};
		if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) {
			if (v->nonfinite++ == 0) v->worst = k; /* report the first one */
			continue;
		}
		normalize(n, dim);
		double dirs[5][3];
		int nd = fan_dirs(dim, n, fan, dirs);
		double bad = -HUGE_VAL;
		for (int t = 0; t < nd; ++t) {
			double lo1, up1, g1, lo2, up2, g2;
			body_bounds(d1, dirs[t], &lo1, &up1, &g1, &v->loose);
			body_bounds(d2, dirs[t], &lo2, &up2, &g2, &v->loose);
			double pd = dot(dirs[t], p, dim);
			double excess = pd - (up1 + up2);
			if (t == 0) {
				double depth = lo1 + lo2 - pd;
				v->depth = fmax(v->depth, depth);
				bad = depth;
				v->gap = fmax(v->gap, up1 + up2 - lo1 - lo2);
				v->dense_gap = fmax(v->dense_gap, g1 + g2);
			}
			v->excess = fmax(v->excess, excess);
			bad = fmax(bad, excess);
		}
		if (!v->nonfinite && bad > worst) {
			worst = bad;
			v->worst = k;
		}
	}
	v->pass = v->nonfinite == 0 && v->depth <= v->tol && v->excess <= v->tol;
	if (v->nonfinite)
		snprintf(v->message, sizeof v->message, "FAIL: %d of %d points are not finite (first at index %d)",
			v->nonfinite, v->points, v->worst);
	else
		snprintf(v->message, sizeof v->message,
			"%s: %d points; depth %.3g, excess %.3g (relative to scale %.6g; allowance %.3g); "
			"bound gap %.3g (dense samples alone %.3g); worst point %d",
			v->pass ? "PASS" : "FAIL", v->points, v->depth / v->extent, v->excess / v->extent, v->extent,
			v->tol / v->extent, v->gap / v->extent, v->dense_gap / v->extent, v->worst);
	return MK_OK;
}

static int dense_default(const mkRefereeOptions *opt, int dim)
{
	if (opt && opt->dense > 0) return opt->dense;
	return dim == 2 ? 8192 : 128;
}

mkResult mkReferee2_Support(mkBody2 b1, mkBody2 b2, mkSet set, const mkPointSet *pts, const double *nx,
	const double *ny, const mkRefereeOptions *opt, mkVerdict *v)
{
	if (!pts || !nx || !ny || !v || pts->dim != 2 || (set != MK_SET_CONTACT && set != MK_SET_PLUS))
		return MK_ERR_ARGUMENT;
	int nd = dense_default(opt, 2);
	if (nd < 16) return MK_ERR_ARGUMENT;
	verdict_init(v, MK_VERDICT_SUPPORT, pts->count);
	Dense d1, d2;
	if (dense2(&d1, &b1, nd, 1.0)) return MK_ERR_MEMORY;
	if (dense2(&d2, &b2, nd, set == MK_SET_CONTACT ? -1.0 : 1.0)) {
		dense_free(&d1);
		return MK_ERR_MEMORY;
	}
	double shift[3] = {b1.t.x + (set == MK_SET_PLUS ? b2.t.x : 0.0), b1.t.y + (set == MK_SET_PLUS ? b2.t.y : 0.0), 0};
	mkResult r = support_check(&d1, &d2, shift, 2, pts, nx, ny, NULL, opt, v);
	dense_free(&d1);
	dense_free(&d2);
	return r;
}

mkResult mkReferee3_Support(mkBody3 b1, mkBody3 b2, mkSet set, const mkPointSet *pts, const double *nx,
	const double *ny, const double *nz, const mkRefereeOptions *opt, mkVerdict *v)
{
	if (!pts || !nx || !ny || !nz || !v || pts->dim != 3 || (set != MK_SET_CONTACT && set != MK_SET_PLUS))
		return MK_ERR_ARGUMENT;
	int nd = dense_default(opt, 3);
	if (nd < 8) return MK_ERR_ARGUMENT;
	verdict_init(v, MK_VERDICT_SUPPORT, pts->count);
	Dense d1, d2;
	if (dense3(&d1, &b1, nd, 1.0)) return MK_ERR_MEMORY;
	if (dense3(&d2, &b2, nd, set == MK_SET_CONTACT ? -1.0 : 1.0)) {
		dense_free(&d1);
		return MK_ERR_MEMORY;
	}
	int plus = set == MK_SET_PLUS;
	double shift[3] = {b1.t.x + (plus ? b2.t.x : 0.0), b1.t.y + (plus ? b2.t.y : 0.0), b1.t.z + (plus ? b2.t.z : 0.0)};
	mkResult r = support_check(&d1, &d2, shift, 3, pts, nx, ny, nz, opt, v);
	dense_free(&d1);
	dense_free(&d2);
	return r;
}

/* ---- dispatch -------------------------------------------------------------- */

/* Boundary points in no particular order carry no normal the support check
 * could use: they are judged by the error measure (mink/error.h, code of its
 * own), each point's distance off the true boundary against the tolerance
 * plus the measure's own bound on that distance. The tolerance, relative to
 * the sum's size: opt->unordered_tol when given, else the method's stated
 * one, else for an exact method the rounding allowance; a method with none
 * of these is refused (MK_ERR_UNSUPPORTED, the message saying what to give). */
static mkResult mkReferee_Measured(const mkMethod *m, mkResult r, const mkDeviation *d, const mkRefereeOptions *opt,
	mkVerdict *v)
{
	verdict_init(v, MK_VERDICT_MEASURE, d->points);
	if (r != MK_OK) return r;
	double rel = opt && opt->unordered_tol > 0.0 ? opt->unordered_tol : mkMethod_Tolerance(m);
	const char *whose = opt && opt->unordered_tol > 0.0 ? "given" : "stated by the method";
	if (!(rel > 0.0) && (m->flags & MK_METHOD_EXACT)) {
		rel = (opt && opt->tol_factor > 0.0 ? opt->tol_factor : 1.0) * MK_REFEREE_ULPS * (DBL_EPSILON / 2);
		whose = "the rounding allowance, for an exact method";
	}
	if (!(rel > 0.0)) {
		snprintf(v->message, sizeof v->message,
			"method %s declares its points unordered and states no accuracy: give --tol T "
			"(mkRefereeOptions.unordered_tol), the largest distance off the boundary to allow, relative to the "
			"sum's size (1e-17 to 1)", m->name);
		return MK_ERR_UNSUPPORTED;
	}
	v->extent = d->size;
	v->tol = rel * d->size;
	v->depth = d->off_boundary_max;
	v->excess = d->off_boundary_max;
	v->gap = d->off_boundary_bound;
	v->worst = d->worst;
	v->nonfinite = d->nonfinite;
	v->pass = d->nonfinite == 0 && d->off_boundary_max <= v->tol + d->off_boundary_bound;
	snprintf(v->message, sizeof v->message,
		"%s: largest distance off the boundary %.3g of the size (tolerance %.3g, %s); Hausdorff %.3g of the "
		"size; %d non-finite points (%s, %d unordered points, by the error measure)", v->pass ? "PASS" : "FAIL",
		d->off_boundary_rel, rel, whose, d->hausdorff_rel, d->nonfinite, m->name, d->points);
	return MK_OK;
}

mkResult mkReferee2_Check(const mkMethod *m, mkBody2 b1, mkBody2 b2, mkSet set, int n, const mkPointSet *out,
	const mkRefereeOptions *opt, mkVerdict *v)
{
	if (!m || !out || !v || out->dim != 2) return MK_ERR_ARGUMENT;
	if (m->flags & MK_METHOD_SAMPLED) return mkReferee2_Hull(b1, b2, set, n, out, v);
	mkMethodIndexing idx = mkMethod_Indexing(m);
	if (idx == MK_INDEX_UNORDERED) {
		mkDeviation d = {0};
		mkResult r = out->count >= 1 ? mkDeviation2_Measure(b1, b2, set, out, NULL, &d) : MK_ERR_ARGUMENT;
		return mkReferee_Measured(m, r, &d, opt, v);
	}
	if (n < 1 || out->count != n) return MK_ERR_ARGUMENT;
	double *u = malloc(4 * (size_t)n * sizeof *u);
	if (!u) return MK_ERR_MEMORY;
	mkResult r = mkSample2_Angles(n, u, u + n);
	if (r == MK_OK) {
		double *nx = u + 2 * n, *ny = u + 3 * n;
		for (int k = 0; k < n; ++k) {
			double x[2], nn[2] = {u[k], u[n + k]};
			if (idx == MK_INDEX_PARAMETER) body2_local(&b1, u[k], u[n + k], x, nn);
			nx[k] = nn[0];
			ny[k] = nn[1];
		}
		r = mkReferee2_Support(b1, b2, set, out, nx, ny, opt, v);
	}
	free(u);
	return r;
}

mkResult mkReferee3_Check(const mkMethod *m, mkBody3 b1, mkBody3 b2, mkSet set, int n, const mkPointSet *out,
	const mkRefereeOptions *opt, mkVerdict *v)
{
	if (!m || !out || !v || out->dim != 3) return MK_ERR_ARGUMENT;
	if (m->flags & MK_METHOD_SAMPLED) return mkReferee3_Hull(b1, b2, set, n, out, v);
	mkMethodIndexing idx = mkMethod_Indexing(m);
	if (idx == MK_INDEX_UNORDERED) {
		mkDeviation d = {0};
		mkResult r = out->count >= 1 ? mkDeviation3_Measure(b1, b2, set, out, NULL, &d) : MK_ERR_ARGUMENT;
		return mkReferee_Measured(m, r, &d, opt, v);
	}
	if (n < 2 || n > 46340 || out->count != n * n) return MK_ERR_ARGUMENT;
	int count = n * n;
	double *u = malloc(6 * (size_t)count * sizeof *u);
	if (!u) return MK_ERR_MEMORY;
	mkResult r = mkSample3_Grid(n, u, u + count, u + 2 * (size_t)count);
	if (r == MK_OK) {
		double *nx = u + 3 * (size_t)count, *ny = u + 4 * (size_t)count, *nz = u + 5 * (size_t)count;
		for (int k = 0; k < count; ++k) {
			double x[3], nn[3] = {u[k], u[count + k], u[2 * count + k]};
			if (idx == MK_INDEX_PARAMETER) body3_local(&b1, u[k], u[count + k], u[2 * count + k], x, nn);
			nx[k] = nn[0];
			ny[k] = nn[1];
			nz[k] = nn[2];
		}
		r = mkReferee3_Support(b1, b2, set, out, nx, ny, nz, opt, v);
	}
	free(u);
	return r;
}
