/* metrics.c - e_implicit, e_gradient and the normal angle, in long double. */
#include "mink/metrics.h"

#include <math.h>

typedef long double ld;

static ld spowl(ld v, ld e) { return copysignl(powl(fabsl(v), e), v); }

/* Psi and its gradient for the canonical shapes, long double. */
static ld psi2(mkShape2 s, const ld *x, ld *g)
{
	ld p = 2.0L / s.eps, a = s.a, b = s.b;
	if (g) {
		g[0] = p / a * spowl(x[0] / a, p - 1.0L);
		g[1] = p / b * spowl(x[1] / b, p - 1.0L);
	}
	return powl(fabsl(x[0] / a), p) + powl(fabsl(x[1] / b), p);
}

/* Scaled as in mkShape3_Implicit so that no power underflows. */
static ld psi3(mkShape3 s, const ld *x, ld *g)
{
	ld p2 = 2.0L / s.eps2, p1 = 2.0L / s.eps1, a = s.a, b = s.b, c = s.c;
	ld al = x[0] / a, be = x[1] / b, M = fmaxl(fabsl(al), fabsl(be));
	ld inner = 0.0L;
	if (g) { g[0] = g[1] = 0.0L; g[2] = p1 / c * spowl(x[2] / c, p1 - 1.0L); }
	if (M > 0.0L) {
		ld ra = al / M, rb = be / M;
		ld S = powl(fabsl(ra), p2) + powl(fabsl(rb), p2);
		ld q = (ld)s.eps2 / s.eps1;
		inner = powl(M, p1) * powl(S, q);
		if (g) {
			ld f = powl(M, p1 - 1.0L) * powl(S, q - 1.0L);
			g[0] = p1 / a * f * spowl(ra, p2 - 1.0L);
			g[1] = p1 / b * f * spowl(rb, p2 - 1.0L);
		}
	}
	return inner + powl(fabsl(x[2] / c), p1);
}

/* |(p, q)|_e for p, q >= 0, scaled by the larger. */
static ld pnorm(ld p, ld q, ld e)
{
	ld m = fmaxl(p, q);
	if (m == 0.0L) return 0.0L;
	return m * powl(powl(p / m, e) + powl(q / m, e), 1.0L / e);
}

/* The support functions as dual norms (NUMERICS: ell_q with q = 2/(2-eps);
 * nested for the superquadric), independent of the kernels' support points. */
static ld h2(mkShape2 s, const ld *d)
{
	return pnorm(fabsl(s.a * d[0]), fabsl(s.b * d[1]), 2.0L / (2.0L - s.eps));
}

static ld h3(mkShape3 s, const ld *d)
{
	ld g = pnorm(fabsl(s.a * d[0]), fabsl(s.b * d[1]), 2.0L / (2.0L - s.eps2));
	return pnorm(g, fabsl(s.c * d[2]), 2.0L / (2.0L - s.eps1));
}

/* Solve M y = r for y (d = 2 or 3) by the adjugate, in long double. */
static void solve(const double *M, int d, const ld *r, ld *y)
{
	ld m[3][3];
	for (int i = 0; i < d; ++i)
		for (int j = 0; j < d; ++j) m[i][j] = M[i * d + j];
	if (d == 2) {
		ld det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
		y[0] = (m[1][1] * r[0] - m[0][1] * r[1]) / det;
		y[1] = (m[0][0] * r[1] - m[1][0] * r[0]) / det;
		return;
	}
	ld c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
	ld c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
	ld c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
	ld det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
	ld inv[3][3] = {
		{c00, m[0][2] * m[2][1] - m[0][1] * m[2][2], m[0][1] * m[1][2] - m[0][2] * m[1][1]},
		{c01, m[0][0] * m[2][2] - m[0][2] * m[2][0], m[0][2] * m[1][0] - m[0][0] * m[1][2]},
		{c02, m[0][1] * m[2][0] - m[0][0] * m[2][1], m[0][0] * m[1][1] - m[0][1] * m[1][0]},
	};
	for (int i = 0; i < 3; ++i) y[i] = (inv[i][0] * r[0] + inv[i][1] * r[1] + inv[i][2] * r[2]) / det;
}

/* World gradient M^-T g: solve M^T w = g. */
static void world_grad(const double *M, int d, const ld *g, ld *w)
{
	double T[9];
	for (int i = 0; i < d; ++i)
		for (int j = 0; j < d; ++j) T[i * d + j] = M[j * d + i];
	solve(T, d, g, w);
}

static void angle_metrics(const ld *n1, const ld *n2, int d, int plus, mkCheck *c)
{
	/* n2 is B2's outward normal; the ideal is n1 = -n2 (contact) or n1 = n2 (plus). */
	ld s = plus ? 1.0L : -1.0L;
	ld dot = 0, nn1 = 0, nn2 = 0, cr2 = 0;
	for (int i = 0; i < d; ++i) { dot += n1[i] * s * n2[i]; nn1 += n1[i] * n1[i]; nn2 += n2[i] * n2[i]; }
	if (d == 2) {
		ld cr = n1[0] * s * n2[1] - n1[1] * s * n2[0];
		cr2 = cr * cr;
	} else {
		ld c0 = n1[1] * n2[2] - n1[2] * n2[1], c1 = n1[2] * n2[0] - n1[0] * n2[2], c2 = n1[0] * n2[1] - n1[1] * n2[0];
		cr2 = c0 * c0 + c1 * c1 + c2 * c2;
	}
	ld cosang = dot / sqrtl(nn1 * nn2);
	/* e_gradient as printed: |cos(angle(grad1, grad2)) + 1| with grad2 reversed for the plus set */
	c->e_gradient = (double)fabsl(1.0L - cosang);
	c->angle = (double)atan2l(sqrtl(cr2), dot);
}

static mkCheck check2(mkBody2 b1, mkBody2 b2, mkSet set, mkVec2 x, mkVec2 k, const mkVec2 *given)
{
	mkCheck c;
	int plus = set == MK_SET_PLUS;
	ld r[2] = {(ld)k.x - x.x, (ld)k.y - x.y};
	if (plus) { r[0] = (ld)x.x - k.x - b2.t.x; r[1] = (ld)x.y - k.y - b2.t.y; }
	ld y[2], g2[2], n2[2];
	solve(&b2.M.m[0][0], 2, r, y);
	c.e_implicit = (double)fabsl(psi2(b2.shape, y, g2) - 1.0L);
	world_grad(&b2.M.m[0][0], 2, g2, n2);
	ld r1[2] = {(ld)k.x - b1.t.x, (ld)k.y - b1.t.y}, y1[2], g1[2], n1[2];
	solve(&b1.M.m[0][0], 2, r1, y1);
	c.e_implicit1 = (double)fabsl(psi2(b1.shape, y1, g1) - 1.0L);
	world_grad(&b1.M.m[0][0], 2, g1, n1);
	angle_metrics(n1, n2, 2, plus, &c);
	if (given) { n1[0] = given->x; n1[1] = given->y; }
	ld d[2], s = plus ? 1.0L : -1.0L;
	for (int i = 0; i < 2; ++i) d[i] = s * (b2.M.m[0][i] * n1[0] + b2.M.m[1][i] * n1[1]);
	ld h = h2(b2.shape, d);
	c.e_support = (double)((h - (d[0] * y[0] + d[1] * y[1])) / h);
	return c;
}

mkCheck mkCheck2(mkBody2 b1, mkBody2 b2, mkSet set, mkVec2 x, mkVec2 k) { return check2(b1, b2, set, x, k, NULL); }
mkCheck mkCheck2_Normal(mkBody2 b1, mkBody2 b2, mkSet set, mkVec2 x, mkVec2 k, mkVec2 n1)
{
	return check2(b1, b2, set, x, k, &n1);
}

static mkCheck check3(mkBody3 b1, mkBody3 b2, mkSet set, mkVec3 x, mkVec3 k, const mkVec3 *given)
{
	mkCheck c;
	int plus = set == MK_SET_PLUS;
	ld r[3] = {(ld)k.x - x.x, (ld)k.y - x.y, (ld)k.z - x.z};
	if (plus) { r[0] = (ld)x.x - k.x - b2.t.x; r[1] = (ld)x.y - k.y - b2.t.y; r[2] = (ld)x.z - k.z - b2.t.z; }
	ld y[3], g2[3], n2[3];
	solve(&b2.M.m[0][0], 3, r, y);
	c.e_implicit = (double)fabsl(psi3(b2.shape, y, g2) - 1.0L);
	world_grad(&b2.M.m[0][0], 3, g2, n2);
	ld r1[3] = {(ld)k.x - b1.t.x, (ld)k.y - b1.t.y, (ld)k.z - b1.t.z}, y1[3], g1[3], n1[3];
	solve(&b1.M.m[0][0], 3, r1, y1);
	c.e_implicit1 = (double)fabsl(psi3(b1.shape, y1, g1) - 1.0L);
	world_grad(&b1.M.m[0][0], 3, g1, n1);
	angle_metrics(n1, n2, 3, plus, &c);
	if (given) { n1[0] = given->x; n1[1] = given->y; n1[2] = given->z; }
	ld d[3], s = plus ? 1.0L : -1.0L;
	for (int i = 0; i < 3; ++i) d[i] = s * (b2.M.m[0][i] * n1[0] + b2.M.m[1][i] * n1[1] + b2.M.m[2][i] * n1[2]);
	ld h = h3(b2.shape, d);
	c.e_support = (double)((h - (d[0] * y[0] + d[1] * y[1] + d[2] * y[2])) / h);
	return c;
}

mkCheck mkCheck3(mkBody3 b1, mkBody3 b2, mkSet set, mkVec3 x, mkVec3 k) { return check3(b1, b2, set, x, k, NULL); }
mkCheck mkCheck3_Normal(mkBody3 b1, mkBody3 b2, mkSet set, mkVec3 x, mkVec3 k, mkVec3 n1)
{
	return check3(b1, b2, set, x, k, &n1);
}
