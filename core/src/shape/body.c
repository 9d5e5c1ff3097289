/* body.c - canonical shapes and placed bodies: implicit functions, gradients,
 * the three boundary maps f, f~, f~~, Phi, areas and volumes, validation. */
#include "mink/body.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>

#include "kernels/kernel.h"

/* ---- validation ------------------------------------------------------------ */

static int check_range(double v, double lo, double hi, const char *what, const char *field,
	char *msg, size_t msglen)
{
	if (isfinite(v) && v >= lo && v <= hi) return 1;
	if (msg && msglen)
		snprintf(msg, msglen, "%s.%s = %.17g is out of range: must be a finite number in [%.10g, %.10g]",
			what, field, v, lo, hi);
	return 0;
}

int mkShape2_IsValid(mkShape2 s, const char *what, char *msg, size_t msglen)
{
	return check_range(s.a, MK_AXIS_MIN, MK_AXIS_MAX, what, "a", msg, msglen)
		&& check_range(s.b, MK_AXIS_MIN, MK_AXIS_MAX, what, "b", msg, msglen)
		&& check_range(s.eps, MK_EPS_MIN, MK_EPS_MAX, what, "eps", msg, msglen);
}

int mkShape3_IsValid(mkShape3 s, const char *what, char *msg, size_t msglen)
{
	return check_range(s.a, MK_AXIS_MIN, MK_AXIS_MAX, what, "a", msg, msglen)
		&& check_range(s.b, MK_AXIS_MIN, MK_AXIS_MAX, what, "b", msg, msglen)
		&& check_range(s.c, MK_AXIS_MIN, MK_AXIS_MAX, what, "c", msg, msglen)
		&& check_range(s.eps1, MK_EPS_MIN, MK_EPS_MAX, what, "eps1", msg, msglen)
		&& check_range(s.eps2, MK_EPS_MIN, MK_EPS_MAX, what, "eps2", msg, msglen);
}

static int check_map(const double *m, int d, double cond, const char *what, char *msg, size_t msglen)
{
	static const char *names[9] = {"M[1][1]", "M[1][2]", "M[1][3]", "M[2][1]", "M[2][2]", "M[2][3]",
		"M[3][1]", "M[3][2]", "M[3][3]"};
	for (int i = 0; i < d * d; ++i) {
		const char *nm = names[(i / d) * 3 + i % d];
		if (!check_range(m[i], -MK_MAP_ENTRY_MAX, MK_MAP_ENTRY_MAX, what, nm, msg, msglen)) return 0;
	}
	if (!(cond <= MK_MAP_COND_MAX)) {
		if (msg && msglen)
			snprintf(msg, msglen, "%s.M is singular or too ill-conditioned: condition number %g, "
				"must be at most %g", what, cond, MK_MAP_COND_MAX);
		return 0;
	}
	return 1;
}

int mkBody2_IsValid(mkBody2 b, const char *what, char *msg, size_t msglen)
{
	return mkShape2_IsValid(b.shape, what, msg, msglen)
		&& check_map(&b.M.m[0][0], 2, mkMat2_Cond(b.M), what, msg, msglen)
		&& check_range(b.t.x, -MK_POS_MAX, MK_POS_MAX, what, "at.x", msg, msglen)
		&& check_range(b.t.y, -MK_POS_MAX, MK_POS_MAX, what, "at.y", msg, msglen);
}

int mkBody3_IsValid(mkBody3 b, const char *what, char *msg, size_t msglen)
{
	return mkShape3_IsValid(b.shape, what, msg, msglen)
		&& check_map(&b.M.m[0][0], 3, mkMat3_Cond(b.M), what, msg, msglen)
		&& check_range(b.t.x, -MK_POS_MAX, MK_POS_MAX, what, "at.x", msg, msglen)
		&& check_range(b.t.y, -MK_POS_MAX, MK_POS_MAX, what, "at.y", msg, msglen)
		&& check_range(b.t.z, -MK_POS_MAX, MK_POS_MAX, what, "at.z", msg, msglen);
}

int mkShape2_IsEllipse(mkShape2 s) { return s.eps == 1.0; }
int mkShape3_IsEllipsoid(mkShape3 s) { return s.eps1 == 1.0 && s.eps2 == 1.0; }

/* ---- kernel constants -------------------------------------------------------- */

void mkKShape2_Prepare(mkKShape2 *k, mkShape2 s)
{
	k->a = s.a; k->b = s.b; k->eps = s.eps;
	k->twome = 2.0 - s.eps;
	k->inv2me = 1.0 / k->twome;
	k->q = 2.0 / k->twome;
	k->qm1 = s.eps / k->twome;
	k->k = 0.5 * s.eps; /* 1 - 1/q */
	k->loga = log(s.a); k->logb = log(s.b);
	k->ellipse = mkShape2_IsEllipse(s);
}

void mkKShape3_Prepare(mkKShape3 *k, mkShape3 s)
{
	k->a = s.a; k->b = s.b; k->c = s.c; k->e1 = s.eps1; k->e2 = s.eps2;
	k->twome1 = 2.0 - s.eps1; k->twome2 = 2.0 - s.eps2;
	k->inv2me1 = 1.0 / k->twome1; k->inv2me2 = 1.0 / k->twome2;
	k->q1 = 2.0 / k->twome1; k->q1m1 = s.eps1 / k->twome1; k->k1 = 0.5 * s.eps1;
	k->q2 = 2.0 / k->twome2; k->q2m1 = s.eps2 / k->twome2; k->k2 = 0.5 * s.eps2;
	k->invq2 = 0.5 * k->twome2;
	k->loga = log(s.a); k->logb = log(s.b); k->logc = log(s.c);
	k->ellipse = mkShape3_IsEllipsoid(s);
}

/* ---- canonical shapes ---------------------------------------------------------- */

static double spow(double v, double e) { return copysign(pow(fabs(v), e), v); }

double mkShape2_Implicit(mkShape2 s, mkVec2 x)
{
	double p = 2.0 / s.eps;
	return pow(fabs(x.x / s.a), p) + pow(fabs(x.y / s.b), p);
}

mkVec2 mkShape2_Gradient(mkShape2 s, mkVec2 x)
{
	double p = 2.0 / s.eps;
	mkVec2 g = {p / s.a * spow(x.x / s.a, p - 1.0), p / s.b * spow(x.y / s.b, p - 1.0)};
	return g;
}

/* The inner term (|x/a|^p2 + |y/b|^p2)^(e2/e1) is evaluated as
 * M^(2/e1) S^(e2/e1) with M = max(|x/a|, |y/b|) and S = sum of (ratio)^p2 in
 * [1, 2], so that neither power underflows when p2 = 2/e2 is large. */
double mkShape3_Implicit(mkShape3 s, mkVec3 x)
{
	double p2 = 2.0 / s.eps2, p1 = 2.0 / s.eps1;
	double al = fabs(x.x / s.a), be = fabs(x.y / s.b), M = al > be ? al : be;
	double inner = 0.0;
	if (M > 0.0) {
		double S = pow(al / M, p2) + pow(be / M, p2);
		inner = pow(M, p1) * pow(S, s.eps2 / s.eps1);
	}
	return inner + pow(fabs(x.z / s.c), p1);
}

mkVec3 mkShape3_Gradient(mkShape3 s, mkVec3 x)
{
	double p2 = 2.0 / s.eps2, p1 = 2.0 / s.eps1;
	double al = x.x / s.a, be = x.y / s.b, M = fmax(fabs(al), fabs(be));
	mkVec3 g = {0.0, 0.0, p1 / s.c * spow(x.z / s.c, p1 - 1.0)};
	if (M > 0.0) {
		double ra = al / M, rb = be / M;
		double S = pow(fabs(ra), p2) + pow(fabs(rb), p2);
		double f = pow(M, p1 - 1.0) * pow(S, s.eps2 / s.eps1 - 1.0);
		g.x = p1 / s.a * f * spow(ra, p2 - 1.0);
		g.y = p1 / s.b * f * spow(rb, p2 - 1.0);
	}
	return g;
}

mkVec2 mkShape2_Point(mkShape2 s, mkVec2 u)
{
	mkKShape2 k; mkKShape2_Prepare(&k, s);
	double n = hypot(u.x, u.y);
	double x[2], m[2];
	mkK2_Surface(&k, u.x / n, u.y / n, x, m);
	mkVec2 r = {x[0], x[1]};
	return r;
}

mkVec3 mkShape3_Point(mkShape3 s, mkVec3 u)
{
	mkKShape3 k; mkKShape3_Prepare(&k, s);
	double n = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
	double x[3], m[3];
	mkK3_Surface(&k, u.x / n, u.y / n, u.z / n, x, m);
	mkVec3 r = {x[0], x[1], x[2]};
	return r;
}

mkVec2 mkShape2_PointGradient(mkShape2 s, mkVec2 u)
{
	double n = hypot(u.x, u.y);
	double e = 2.0 - s.eps, f = 2.0 / s.eps;
	mkVec2 g = {f / s.a * spow(u.x / n, e), f / s.b * spow(u.y / n, e)};
	return g;
}

mkVec3 mkShape3_PointGradient(mkShape3 s, mkVec3 u)
{
	double n = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
	double u1 = u.x / n, u2 = u.y / n, u3 = u.z / n;
	double rho = hypot(u1, u2);
	double f = 2.0 / s.eps1;
	/* eq. 3d_sq_m_u: u_i^(2-e2) (u1^2+u2^2)^((e2-e1)/2) = rho^(2-e1) (u_i/rho)^(2-e2) */
	double c = rho > 0.0 ? u1 / rho : 0.0, sn = rho > 0.0 ? u2 / rho : 0.0;
	double r = pow(rho, 2.0 - s.eps1);
	mkVec3 g = {
		f / s.a * r * spow(c, 2.0 - s.eps2),
		f / s.b * r * spow(sn, 2.0 - s.eps2),
		f / s.c * spow(u3, 2.0 - s.eps1),
	};
	return g;
}

mkVec2 mkShape2_Support(mkShape2 s, mkVec2 n)
{
	mkKShape2 k; mkKShape2_Prepare(&k, s);
	double x[2];
	mkK2_Support(&k, n.x, n.y, x);
	mkVec2 r = {x[0], x[1]};
	return r;
}

mkVec3 mkShape3_Support(mkShape3 s, mkVec3 n)
{
	mkKShape3 k; mkKShape3_Prepare(&k, s);
	double x[3];
	mkK3_Support(&k, n.x, n.y, n.z, x);
	mkVec3 r = {x[0], x[1], x[2]};
	return r;
}

double mkShape2_SupportValue(mkShape2 s, mkVec2 n)
{
	mkVec2 x = mkShape2_Support(s, n);
	return n.x * x.x + n.y * x.y;
}

double mkShape3_SupportValue(mkShape3 s, mkVec3 n)
{
	mkVec3 x = mkShape3_Support(s, n);
	return n.x * x.x + n.y * x.y + n.z * x.z;
}

mkVec2 mkShape2_FromGradient(mkShape2 s, mkVec2 m)
{
	mkKShape2 k; mkKShape2_Prepare(&k, s);
	double x[2];
	mkK2_GradInv(&k, m.x, m.y, x);
	mkVec2 r = {x[0], x[1]};
	return r;
}

mkVec3 mkShape3_FromGradient(mkShape3 s, mkVec3 m)
{
	mkKShape3 k; mkKShape3_Prepare(&k, s);
	double x[3];
	mkK3_GradInv(&k, m.x, m.y, m.z, x);
	mkVec3 r = {x[0], x[1], x[2]};
	return r;
}

/* eq. 2d_sq_f_m as printed, signs carried by sp. */
mkVec2 mkShape2_FromGradientPaper(mkShape2 s, mkVec2 m)
{
	double e = s.eps, ex = e / (2.0 - e);
	mkVec2 x = {
		s.a * pow(2.0 / (e * s.a), -ex) * spow(m.x, ex),
		s.b * pow(2.0 / (e * s.b), -ex) * spow(m.y, ex),
	};
	return x;
}

/* eq. 3d_sq_f_m as printed, with gamma(m3) = 1 - (c e1 m3 / 2)^(2/(2-e1)). */
mkVec3 mkShape3_FromGradientPaper(mkShape3 s, mkVec3 m)
{
	double e1 = s.eps1, e2 = s.eps2;
	double gamma = 1.0 - pow(fabs(s.c * e1 * m.z / 2.0), 2.0 / (2.0 - e1));
	double gp = pow(gamma, (e1 - e2) / (2.0 - e2));
	double ex2 = e2 / (2.0 - e2);
	mkVec3 x = {
		s.a * spow(s.a * e1 / 2.0 * m.x, ex2) * gp,
		s.b * spow(s.b * e1 / 2.0 * m.y, ex2) * gp,
		s.c * spow(s.c * e1 / 2.0 * m.z, e1 / (2.0 - e1)),
	};
	return x;
}

/* Lemma 1: Phi(m) = |g2(u2)| with u2 the normalised g2^-1(m) (eq.
 * Phi_m1_general): the norm of the gradient at the boundary point whose
 * gradient is parallel to m. u2 comes from the same log-domain evaluation as
 * f~~, so that neither 1/(2-eps) nor 2/eps exponents meet raw numbers. */
double mkShape2_Phi(mkShape2 s, mkVec2 m)
{
	mkKShape2 k; mkKShape2_Prepare(&k, s);
	double l[2], e = 2.0 - s.eps;
	mkK2_GradInvLogs(&k, m.x, m.y, l);
	/* g_i = 2/(eps a_i) |u_i|^(2-eps) (eq. 2d_sq_m_u) */
	return hypot(2.0 / (s.eps * s.a) * exp(e * l[0]), 2.0 / (s.eps * s.b) * exp(e * l[1]));
}

double mkShape3_Phi(mkShape3 s, mkVec3 m)
{
	mkKShape3 k; mkKShape3_Prepare(&k, s);
	double l[4], e1 = 2.0 - s.eps1, e2 = 2.0 - s.eps2, f = 2.0 / s.eps1;
	mkK3_GradInvLogs(&k, m.x, m.y, m.z, l);
	/* eq. 3d_sq_m_u in the angles: rho^(2-e1) cw^(2-e2) / a, ..., |u3|^(2-e1) / c */
	double g1 = f / s.a * exp(e1 * l[0] + e2 * l[2]);
	double g2 = f / s.b * exp(e1 * l[0] + e2 * l[3]);
	double g3 = f / s.c * exp(e1 * l[1]);
	return sqrt(g1 * g1 + g2 * g2 + g3 * g3);
}

double mkShape2_Area(mkShape2 s)
{
	double h = 0.5 * s.eps;
	return 4.0 * s.a * s.b * exp(2.0 * lgamma(1.0 + h) - lgamma(1.0 + s.eps));
}

static double beta_fn(double x, double y) { return exp(lgamma(x) + lgamma(y) - lgamma(x + y)); }

double mkShape3_Volume(mkShape3 s)
{
	return 2.0 * s.a * s.b * s.c * s.eps1 * s.eps2
		* beta_fn(0.5 * s.eps1 + 1.0, s.eps1) * beta_fn(0.5 * s.eps2, 0.5 * s.eps2);
}

/* ---- placed bodies --------------------------------------------------------------- */

mkBody2 mkBody2_Make(mkShape2 s, mkMat2 M, mkVec2 t)
{
	mkBody2 b = {s, M, t};
	return b;
}

mkBody3 mkBody3_Make(mkShape3 s, mkMat3 M, mkVec3 t)
{
	mkBody3 b = {s, M, t};
	return b;
}

double mkBody2_Implicit(mkBody2 b, mkVec2 x)
{
	mkVec2 d = {x.x - b.t.x, x.y - b.t.y};
	return mkShape2_Implicit(b.shape, mkMat2_MulVec(mkMat2_Inverse(b.M), d));
}

double mkBody3_Implicit(mkBody3 b, mkVec3 x)
{
	mkVec3 d = {x.x - b.t.x, x.y - b.t.y, x.z - b.t.z};
	return mkShape3_Implicit(b.shape, mkMat3_MulVec(mkMat3_Inverse(b.M), d));
}

mkVec2 mkBody2_Gradient(mkBody2 b, mkVec2 x)
{
	mkMat2 Mi = mkMat2_Inverse(b.M);
	mkVec2 d = {x.x - b.t.x, x.y - b.t.y};
	return mkMat2_MulTVec(Mi, mkShape2_Gradient(b.shape, mkMat2_MulVec(Mi, d)));
}

mkVec3 mkBody3_Gradient(mkBody3 b, mkVec3 x)
{
	mkMat3 Mi = mkMat3_Inverse(b.M);
	mkVec3 d = {x.x - b.t.x, x.y - b.t.y, x.z - b.t.z};
	return mkMat3_MulTVec(Mi, mkShape3_Gradient(b.shape, mkMat3_MulVec(Mi, d)));
}

mkVec2 mkBody2_Point(mkBody2 b, mkVec2 u)
{
	mkVec2 p = mkMat2_MulVec(b.M, mkShape2_Point(b.shape, u));
	mkVec2 r = {b.t.x + p.x, b.t.y + p.y};
	return r;
}

mkVec3 mkBody3_Point(mkBody3 b, mkVec3 u)
{
	mkVec3 p = mkMat3_MulVec(b.M, mkShape3_Point(b.shape, u));
	mkVec3 r = {b.t.x + p.x, b.t.y + p.y, b.t.z + p.z};
	return r;
}

mkVec2 mkBody2_Support(mkBody2 b, mkVec2 n)
{
	mkVec2 p = mkMat2_MulVec(b.M, mkShape2_Support(b.shape, mkMat2_MulTVec(b.M, n)));
	mkVec2 r = {b.t.x + p.x, b.t.y + p.y};
	return r;
}

mkVec3 mkBody3_Support(mkBody3 b, mkVec3 n)
{
	mkVec3 p = mkMat3_MulVec(b.M, mkShape3_Support(b.shape, mkMat3_MulTVec(b.M, n)));
	mkVec3 r = {b.t.x + p.x, b.t.y + p.y, b.t.z + p.z};
	return r;
}

double mkBody2_SupportValue(mkBody2 b, mkVec2 n)
{
	mkVec2 x = mkBody2_Support(b, n);
	return n.x * x.x + n.y * x.y;
}

double mkBody3_SupportValue(mkBody3 b, mkVec3 n)
{
	mkVec3 x = mkBody3_Support(b, n);
	return n.x * x.x + n.y * x.y + n.z * x.z;
}

double mkBody2_Area(mkBody2 b) { return fabs(mkMat2_Det(b.M)) * mkShape2_Area(b.shape); }
double mkBody3_Volume(mkBody3 b) { return fabs(mkMat3_Det(b.M)) * mkShape3_Volume(b.shape); }
