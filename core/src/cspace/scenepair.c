/* scenepair.c - the scene query's quick certificates of a pair
 * (cspace/scenepair.h): support values and gauges of superquadrics by
 * their norms, separating directions (the centre line, from a box-like
 * body's box, the sum of the semi-axes' ellipsoids, a box's faces) and
 * common points (on the centre segment, past a box's face, the point of a
 * box-like body's inner box where an ellipsoid's gauge is least, and the
 * contact point of the semi-axes' ellipsoids' Perram-Wertheim function). */
#include "cspace/scenepair.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/base2.h"
#include "base/geom_inline.h"

#define MK_SQ_QUICK 4e-12   /* margin of the certificates, times the pair's size (as MK_BATCH_MARGIN) */

/* The larger and the smaller of a and b, b where either is NaN (one SSE
 * instruction; fmax and fmin are library calls on x86-64). A NaN so
 * passed on fails every certificate's comparison. */
static inline double mkSq_Fmax(double a, double b) { return a > b ? a : b; }
static inline double mkSq_Fmin(double a, double b) { return a < b ? a : b; }

mkSqQuick mkSqQuick_Make(mkBody3 b)
{
	mkSqQuick k;
	k.Mi = mkMat3_Inverse(b.M);
	double fm = 0.0, fi = 0.0, big = mkSq_Fmax(b.shape.a, mkSq_Fmax(b.shape.b, b.shape.c));
	for (int i = 0; i < 9; ++i) {
		fm += b.M.m[i / 3][i % 3] * b.M.m[i / 3][i % 3];
		fi += k.Mi.m[i / 3][i % 3] * k.Mi.m[i / 3][i % 3];
	}
	k.r = big * sqrt(fm);
	/* the shape holds the cross-polytope of its axes, whose inradius is 1 / |(1/a, 1/b, 1/c)| */
	k.rho = 1.0 / (sqrt(fi) * sqrt(1.0 / (b.shape.a * b.shape.a) + 1.0 / (b.shape.b * b.shape.b)
		+ 1.0 / (b.shape.c * b.shape.c))) * (1.0 - 1e-12);
	k.slack = 64.0 * DBL_EPSILON * (1.0 + sqrt(fm * fi));
	/* by Hoelder per level (mkSq_Bounds), the gauge is at most 2^((eps1 + eps2) / 2) times the box's */
	double f = exp2(-0.5 * (b.shape.eps1 + b.shape.eps2)) * (1.0 - 1e-12);
	k.w[0] = f * b.shape.a;
	k.w[1] = f * b.shape.b;
	k.w[2] = f * b.shape.c;
	return k;
}

/* |(u, v)|_p of u, v >= 0: m 2^(log2(1 + (k/m)^p) / p) with m >= k, the
 * inner logarithm by mkSoftplus2 (base2.h; within 1e-15 relative: two
 * orders under the certificates' margins). */
static double mkSq_Norm2(double u, double v, double p)
{
	double m = u > v ? u : v, k = u > v ? v : u;
	if (!(m > 0.0)) return 0.0;
	if (p == 2.0) return m * sqrt(1.0 + (k / m) * (k / m));
	double x = p * log2(k / m);
	return m * mkExp2(mkSoftplus2(x, mkExp2(x)) / p);
}

/* log2 |(2^a, 2^b)|_p = max + log2(1 + 2^(p (min - max))) / p (ip = 1/p). */
static inline double mkSq_LogNorm2(double a, double b, double p, double ip)
{
	double m = a > b ? a : b, k = a > b ? b : a;
	if (!(k > -INFINITY)) return m;
	double x = p * (k - m);
	return m + mkSoftplus2(x, mkExp2(x)) * ip;
}

/* |(|(x1, x2)|_p2, x3)|_p1 of x >= 0 (ip = 1/p): in base-2 logarithms of
 * the components scaled by the power of 2 that brings the largest into
 * [1, 2) (so that the logarithms' rounding stays that of numbers near 1),
 * level by level (mkSq_LogNorm2); by mkSq_Norm2 where that scale would
 * leave the range of doubles. */
static double mkSq_Nested(double x1, double x2, double x3, double p2, double ip2, double p1, double ip1)
{
	double m = x1 > x2 ? x1 : x2;
	m = m > x3 ? m : x3;
	uint64_t bits;
	memcpy(&bits, &m, sizeof bits);
	int e = (int)(bits >> 52) - 1023;   /* (m >= 0: no sign bit) */
	if (!(m > 0.0) || e < -1000 || e > 1000) return mkSq_Norm2(mkSq_Norm2(x1, x2, p2), x3, p1);
	uint64_t down = (uint64_t)(1023 - e) << 52, up = (uint64_t)(1023 + e) << 52;
	double sd, su;
	memcpy(&sd, &down, sizeof sd);
	memcpy(&su, &up, sizeof su);
	double l12 = mkSq_LogNorm2(log2(x1 * sd), log2(x2 * sd), p2, ip2);
	return mkExp2(mkSq_LogNorm2(l12, log2(x3 * sd), p1, ip1)) * su;
}

static int mkSq_Ellipsoid(mkShape3 s) { return s.eps1 == 1.0 && s.eps2 == 1.0; }

double mkSq_ShapeNorm(mkShape3 s, mkVec3 y, int dual)
{
	double x1 = fabs(y.x), x2 = fabs(y.y), x3 = fabs(y.z);
	if (mkSq_Ellipsoid(s)) { /* an ellipsoid: the 2-norm (inf when it overflows: never certifies) */
		if (dual) { x1 *= s.a; x2 *= s.b; x3 *= s.c; }
		else { x1 /= s.a; x2 /= s.b; x3 /= s.c; }
		return sqrt(x1 * x1 + x2 * x2 + x3 * x3);
	}
	if (dual) /* q = 2 / (2 - eps), 1/q = 1 - eps/2 */
		return mkSq_Nested(s.a * x1, s.b * x2, s.c * x3, 2.0 / (2.0 - s.eps2), 1.0 - 0.5 * s.eps2, 2.0 / (2.0 - s.eps1),
			1.0 - 0.5 * s.eps1);
	return mkSq_Nested(x1 / s.a, x2 / s.b, x3 / s.c, 2.0 / s.eps2, 0.5 * s.eps2, 2.0 / s.eps1, 0.5 * s.eps1);
}

static inline void mkSq_Bounds(mkShape3 s, mkVec3 y, int dual, double *lo, double *hi)
{
	double x1 = fabs(y.x), x2 = fabs(y.y), x3 = fabs(y.z);
	if (dual) { x1 *= s.a; x2 *= s.b; x3 *= s.c; }
	else { x1 /= s.a; x2 /= s.b; x3 /= s.c; }
	double l2 = sqrt(x1 * x1 + x2 * x2 + x3 * x3), inf = mkSq_Fmax(x1, mkSq_Fmax(x2, x3)), l1 = x1 + x2 + x3;
	int round = s.eps1 >= 1.0 && s.eps2 >= 1.0, boxy = s.eps1 <= 1.0 && s.eps2 <= 1.0;
	/* support value: at least the octahedron's (inf) or the ellipsoid's, at most the box's (l1) or the
	 * ellipsoid's; gauge: at least the box's (inf) or the ellipsoid's, at most the octahedron's (l1) */
	*lo = (dual ? boxy : round) ? l2 : inf;
	*hi = (dual ? round : boxy) ? l2 : l1;
	if (!boxy || mkSq_Ellipsoid(s)) return;
	/* box-like: by Hoelder per level, |(u, v)|_p <= 2^(1/p) max(u, v) and |(u, v)|_q >= 2^(1/q - 1) (u + v),
	 * so the gauge is at most 2^((eps1 + eps2) / 2) inf and the support value at least 2^(-(eps1 + eps2) / 2) l1
	 * (each rounded outwards) */
	double k = mkExp2(0.5 * (s.eps1 + s.eps2));
	if (dual) *lo = mkSq_Fmax(*lo, l1 / k * (1.0 - 1e-15));
	else *hi = mkSq_Fmin(*hi, inf * k * (1.0 + 1e-15));
}

void mkSq_NormBounds(mkShape3 s, mkVec3 y, int dual, double *lo, double *hi) { mkSq_Bounds(s, y, dual, lo, hi); }

/* A lower bound of the distance along u (unit) between bodies b and x
 * whose centres are d apart (from b's to x's), u.d - h_b(u) - h_x(u): by
 * the support values' upper bounds (mkSq_NormBounds, no powers), by their
 * norms where the bounds leave open whether it exceeds lim (lim infinite:
 * the bounds alone). */
static double mkSq_Along(const mkBody3 *b, const mkBody3 *x, mkVec3 u, mkVec3 d, double lim)
{
	mkVec3 yb = mkMat3_MulTVecInline(b->M, u), yx = mkMat3_MulTVecInline(x->M, u);
	double blo, bhi, xlo, xhi, L = mkVec3_Dot(u, d);
	mkSq_Bounds(b->shape, yb, 1, &blo, &bhi);
	mkSq_Bounds(x->shape, yx, 1, &xlo, &xhi);
	if (L - bhi - xhi > lim || L - blo - xlo <= lim) return L - bhi - xhi;
	return L - (mkSq_Ellipsoid(b->shape) ? bhi : mkSq_ShapeNorm(b->shape, yb, 1))
		- (mkSq_Ellipsoid(x->shape) ? xhi : mkSq_ShapeNorm(x->shape, yx, 1));
}


/* The lower bound of the distance between a body b whose exponents are at
 * most 1 and body x along the direction from the box of b's semi-axes
 * (which holds b) to x's centre, y in b's canonical frame (its nearest point
 * in that frame); -inf when y lies in the box. */
static double mkSq_BoxDirection(const mkBody3 *b, const mkBody3 *x, mkVec3 y, mkVec3 d)
{
	mkShape3 s = b->shape;
	mkVec3 g = {y.x - mkSq_Fmax(-s.a, mkSq_Fmin(s.a, y.x)), y.y - mkSq_Fmax(-s.b, mkSq_Fmin(s.b, y.y)), y.z - mkSq_Fmax(-s.c, mkSq_Fmin(s.c, y.z))};
	mkVec3 w = mkMat3_MulVecInline(b->M, g);
	double n = sqrt(mkVec3_Dot(w, w));
	if (!(n > 0.0) || !isfinite(n)) return -INFINITY;
	return mkSq_Along(b, x, mkVec3_Scale(w, 1.0 / n), d, INFINITY);
}

static int mkSq_Boxy(mkShape3 s) { return s.eps1 <= 1.0 && s.eps2 <= 1.0 && !mkSq_Ellipsoid(s); }

/* The gauge of a body's model at the point x - its centre, y in its
 * canonical frame, rounded up by the slack. */
static double mkSq_GaugeFrom(mkShape3 s, const mkSqQuick *k, mkVec3 y, double lo, double hi)
{
	double g = hi <= lo * (1.0 + 1e-2) ? hi : mkSq_ShapeNorm(s, y, 0);   /* the bound where it is within 1 % */
	return g * (1.0 + k->slack) + k->slack;
}

static double mkSq_Gauge(mkShape3 s, const mkSqQuick *k, mkVec3 y)
{
	double lo, hi;
	mkSq_Bounds(s, y, 0, &lo, &hi);   /* (an ellipsoid's: its norm) */
	return mkSq_GaugeFrom(s, k, y, lo, hi);
}

double mkSqQuick_PointDepth(const mkSqModels *o, const mkSqModels *p, const mkMat3 *R, mkVec3 x)
{
	if (!isfinite(x.x + x.y + x.z)) return 0.0;
	mkVec3 yo = mkMat3_MulVecInline(o->kinner->Mi, mkVec3_Sub(x, o->inner->t));
	double go = mkSq_Gauge(o->inner->shape, o->kinner, yo);
	if (go >= 1.0 && go < 2.0) { /* outside the obstacle's inner model: x drawn towards its centre, just inside it */
		x = mkVec3_Add(o->inner->t, mkVec3_Scale(mkVec3_Sub(x, o->inner->t), (1.0 - 1e-6) / go));
		go = mkSq_Gauge(o->inner->shape, o->kinner, mkMat3_MulVecInline(o->kinner->Mi, mkVec3_Sub(x, o->inner->t)));
	}
	if (!(go < 1.0)) return 0.0;
	mkVec3 yp = mkMat3_MulVecInline(p->kinner->Mi, mkMat3_MulTVecInline(*R, mkVec3_Sub(x, p->inner->t)));
	double gp = mkSq_Gauge(p->inner->shape, p->kinner, yp);
	return gp < 1.0 ? (1.0 - go) * o->kinner->rho + (1.0 - gp) * p->kinner->rho : 0.0;
}

/* 1 when mkSq_BoxDirection of a box-like body of the pair exceeds lim. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int mkSq_BoxApart(const mkSqModels *o, const mkSqModels *p, const mkMat3 *R, mkVec3 d, double lim)
{
	const mkBody3 *ob = o->outer, *pb = p->outer;
	mkVec3 back = mkVec3_Neg(d);
	if (mkSq_Boxy(ob->shape) && mkSq_BoxDirection(ob, pb, mkMat3_MulVecInline(o->kouter->Mi, d), d) > lim) return 1;
	return mkSq_Boxy(pb->shape)
		&& mkSq_BoxDirection(pb, ob, mkMat3_MulVecInline(p->kouter->Mi, mkMat3_MulTVecInline(*R, back)), back) > lim;
}

/* The depth certified by the best point of the centre segment of the
 * inner models (0 when none is inside both). */
static double mkSq_SegmentDepth(const mkSqModels *o, const mkSqModels *p, const mkMat3 *R)
{
	const mkSqQuick *ko = o->kinner, *kp = p->kinner;
	mkShape3 os = o->inner->shape, ps = p->inner->shape;
	mkVec3 d = mkVec3_Sub(p->inner->t, o->inner->t);
	mkVec3 yp = mkMat3_MulVecInline(kp->Mi, mkMat3_MulTVecInline(*R, mkVec3_Neg(d)));   /* the obstacle's centre, in the part's frame */
	mkVec3 yo = mkMat3_MulVecInline(ko->Mi, d);                                    /* the part's centre, in the obstacle's */
	/* the gauges' lower bounds first: no interval when even they leave none */
	double plo, phi, olo, ohi;
	mkSq_Bounds(ps, yp, 0, &plo, &phi);
	mkSq_Bounds(os, yo, 0, &olo, &ohi);
	double gpl = plo * (1.0 + kp->slack) + kp->slack, gol = olo * (1.0 + ko->slack) + ko->slack;
	if (mkSq_Fmax(0.0, 1.0 - 1.0 / gpl) >= mkSq_Fmin(1.0, 1.0 / gol) + 1e-12) return 0.0;
	double gp = mkSq_Ellipsoid(ps) ? gpl : mkSq_GaugeFrom(ps, kp, yp, plo, phi);   /* (the bounds above) */
	double go = mkSq_Ellipsoid(os) ? gol : mkSq_GaugeFrom(os, ko, yo, olo, ohi);
	double lo = mkSq_Fmax(0.0, 1.0 - 1.0 / gp), hi = mkSq_Fmin(1.0, 1.0 / go);
	if (!(lo < hi)) return 0.0;
	double dlo = mkSq_Fmax(0.0, 1.0 - lo * go) * ko->rho + mkSq_Fmax(0.0, 1.0 - (1.0 - lo) * gp) * kp->rho;
	double dhi = mkSq_Fmax(0.0, 1.0 - hi * go) * ko->rho + mkSq_Fmax(0.0, 1.0 - (1.0 - hi) * gp) * kp->rho;
	return mkSq_Fmax(dlo, dhi);
}

/* The depth certified by a point past a box-like obstacle's face: q, the
 * point of the box of the inner model's semi-axes nearest the part's centre
 * c in the obstacle's frame, and x on the ray from c through q halfway
 * between q and the part's boundary (the part's gauge is linear along it),
 * when q lies inside the part (0 otherwise, or when c lies in the box). */
static double mkSq_FaceDepth(const mkSqModels *o, const mkSqModels *p, const mkMat3 *R)
{
	const mkBody3 *ob = o->inner, *pb = p->inner;
	mkShape3 s = ob->shape;
	mkVec3 y = mkMat3_MulVecInline(o->kinner->Mi, mkVec3_Sub(pb->t, ob->t));
	mkVec3 c = {mkSq_Fmax(-s.a, mkSq_Fmin(s.a, y.x)), mkSq_Fmax(-s.b, mkSq_Fmin(s.b, y.y)), mkSq_Fmax(-s.c, mkSq_Fmin(s.c, y.z))};
	if (c.x == y.x && c.y == y.y && c.z == y.z) return 0.0;
	mkVec3 v = mkVec3_Sub(mkVec3_Add(ob->t, mkMat3_MulVecInline(ob->M, c)), pb->t);   /* q - c */
	double g = mkSq_Gauge(pb->shape, p->kinner, mkMat3_MulVecInline(p->kinner->Mi, mkMat3_MulTVecInline(*R, v)));
	if (!(g < 1.0) || !(g > 0.0)) return 0.0;
	return mkSqQuick_PointDepth(o, p, R, mkVec3_Add(pb->t, mkVec3_Scale(v, 0.5 * (1.0 + 1.0 / g))));
}

/* M diag(a^2, b^2, c^2) M^T: the shape matrix of the ellipsoid of b's
 * semi-axes. */
static mkMat3 mkSq_Spread(const mkBody3 *b)
{
	double s[3] = {b->shape.a * b->shape.a, b->shape.b * b->shape.b, b->shape.c * b->shape.c};
	mkMat3 S;
	for (int i = 0; i < 3; ++i)
		for (int j = i; j < 3; ++j)
			S.m[i][j] = S.m[j][i] = b->M.m[i][0] * s[0] * b->M.m[j][0] + b->M.m[i][1] * s[1] * b->M.m[j][1]
				+ b->M.m[i][2] * s[2] * b->M.m[j][2];
	return S;
}

/* The lower bound of the distance along (S_o + S_p)^-1 d, S the bodies'
 * mkSq_Spread: the normal of their sum's boundary towards d when the two
 * are ellipsoids of one shape (-inf when it cannot be formed); *x the
 * point c_o + S_o (S_o + S_p)^-1 d. */
static double mkSq_SpreadApart(const mkBody3 *ob, const mkBody3 *pb, mkVec3 d, double lim, mkVec3 *x)
{
	mkMat3 O = mkSq_Spread(ob), S = mkSq_Spread(pb);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) S.m[i][j] += O.m[i][j];
	mkVec3 r0 = {S.m[0][0], S.m[0][1], S.m[0][2]}, r1 = {S.m[1][0], S.m[1][1], S.m[1][2]}, r2 = {S.m[2][0], S.m[2][1], S.m[2][2]};
	/* S^-1 d up to its (positive) determinant: the adjugate's rows are the cross products */
	mkVec3 c0 = mkVec3_Cross(r1, r2);
	mkVec3 n = {mkVec3_Dot(c0, d), mkVec3_Dot(mkVec3_Cross(r2, r0), d), mkVec3_Dot(mkVec3_Cross(r0, r1), d)};
	*x = mkVec3_Add(ob->t, mkVec3_Scale(mkMat3_MulVecInline(O, n), 1.0 / mkVec3_Dot(r0, c0)));
	double l = sqrt(mkVec3_Dot(n, n));
	if (!(l > 0.0) || !isfinite(l)) return -INFINITY;
	return mkSq_Along(ob, pb, mkVec3_Scale(n, 1.0 / l), d, lim);
}

/* The largest lower bound of the distance along the face normals of the
 * box of box-like body b's semi-axes (towards x: d from b's centre to x's). */
static double mkSq_FacesApart(const mkBody3 *b, const mkSqQuick *k, const mkBody3 *x, mkVec3 d, double lim)
{
	double f = -INFINITY;
	for (int i = 0; i < 3 && !(f > lim); ++i) {
		mkVec3 n = {k->Mi.m[i][0], k->Mi.m[i][1], k->Mi.m[i][2]};   /* row i of M^-1: normal to faces i */
		double l = sqrt(mkVec3_Dot(n, n));
		if (!(l > 0.0) || !isfinite(l)) continue;
		if (mkVec3_Dot(n, d) < 0.0) l = -l;
		f = mkSq_Fmax(f, mkSq_Along(b, x, mkVec3_Scale(n, 1.0 / l), d, lim));
	}
	return f;
}

/* Solves A x = r for a symmetric positive definite A (by its adjugate);
 * 0 when A is singular as computed. */
static int mkSq_Solve3(double A[3][3], const double r[3], double x[3])
{
	double c00 = A[1][1] * A[2][2] - A[1][2] * A[2][1], c01 = A[1][2] * A[2][0] - A[1][0] * A[2][2];
	double c02 = A[1][0] * A[2][1] - A[1][1] * A[2][0];
	double det = A[0][0] * c00 + A[0][1] * c01 + A[0][2] * c02;
	if (!(det > 0.0) || !isfinite(det)) return 0;
	double c11 = A[0][0] * A[2][2] - A[0][2] * A[2][0], c12 = A[0][1] * A[2][0] - A[0][0] * A[2][1];
	double c22 = A[0][0] * A[1][1] - A[0][1] * A[1][0];
	x[0] = (c00 * r[0] + c01 * r[1] + c02 * r[2]) / det;
	x[1] = (c01 * r[0] + c11 * r[1] + c12 * r[2]) / det;
	x[2] = (c02 * r[0] + c12 * r[1] + c22 * r[2]) / det;
	return 1;
}

/* (mkSqQuick_BoxLeast: scenepair.h) */
void mkSqQuick_BoxLeast(double H[3][3], const double y0[3], const double w[3], double y[3])
{
	int at[3];   /* -1, 0, 1: at -w_i, free, at w_i */
	for (int i = 0; i < 3; ++i) {
		at[i] = y0[i] > w[i] ? 1 : y0[i] < -w[i] ? -1 : 0;
		y[i] = at[i] ? at[i] * w[i] : y0[i];
	}
	for (int step = 0; step < 8; ++step) {
		double g[3], A[3][3], r[3], dy[3];
		for (int i = 0; i < 3; ++i)
			g[i] = H[i][0] * (y[0] - y0[0]) + H[i][1] * (y[1] - y0[1]) + H[i][2] * (y[2] - y0[2]);
		int nfree = 0;
		for (int i = 0; i < 3; ++i) {
			nfree += at[i] == 0;
			r[i] = at[i] ? 0.0 : -g[i];
			for (int j = 0; j < 3; ++j) A[i][j] = at[i] || at[j] ? (double)(i == j) : H[i][j];
		}
		if (nfree > 0) {
			if (!mkSq_Solve3(A, r, dy)) return;
			double t = 1.0;
			int block = -1;
			for (int i = 0; i < 3; ++i) {
				if (at[i]) continue;
				double lim = dy[i] > 0.0 ? w[i] - y[i] : -w[i] - y[i];
				if (fabs(dy[i]) * t > fabs(lim)) { t = lim / dy[i]; block = i; }
			}
			for (int i = 0; i < 3; ++i)
				if (!at[i]) y[i] = mkSq_Fmax(-w[i], mkSq_Fmin(w[i], y[i] + t * dy[i]));
			if (block >= 0) {
				at[block] = dy[block] > 0.0 ? 1 : -1;
				y[block] = at[block] * w[block];
				continue;
			}
			for (int i = 0; i < 3; ++i)
				g[i] = H[i][0] * (y[0] - y0[0]) + H[i][1] * (y[1] - y0[1]) + H[i][2] * (y[2] - y0[2]);
		}
		/* the least on this face: let go the bound whose multiplier is most wrong (moving inwards lowers it) */
		int worst = -1;
		double most = 0.0;
		for (int i = 0; i < 3; ++i)
			if (at[i] && at[i] * g[i] > most) { most = at[i] * g[i]; worst = i; }
		if (worst < 0) return;
		at[worst] = 0;
	}
}

/* A box-like inner model X (M^-1 Mi, the box inside it w: mkSqQuick's)
 * and an ellipsoid E (its world frame to its canonical one: Ei): the point
 * x of X's box where E's gauge is least (mkSqQuick_BoxLeast). Returns 1 when
 * that gauge is below 1 (*x), else 0 and *n, the normal of E's level set
 * at x, pointing from E towards X (not unit). */
static int mkSq_BoxPoint(const mkBody3 *X, const mkMat3 *Mi, const double w[3], const mkBody3 *E, mkMat3 Ei, mkVec3 *x,
	mkVec3 *n)
{
	/* Bw: world to E's unit ball; B = Bw M_X: X's frame to it */
	double s[3] = {1.0 / E->shape.a, 1.0 / E->shape.b, 1.0 / E->shape.c};
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) Ei.m[i][j] *= s[i];
	mkMat3 B = mkMat3_MulInline(Ei, X->M);
	mkVec3 c = mkMat3_MulVecInline(*Mi, mkVec3_Sub(E->t, X->t));
	double H[3][3], y0[3] = {c.x, c.y, c.z}, y[3];
	for (int i = 0; i < 3; ++i)
		for (int j = i; j < 3; ++j)
			H[i][j] = H[j][i] = B.m[0][i] * B.m[0][j] + B.m[1][i] * B.m[1][j] + B.m[2][i] * B.m[2][j];
	mkSqQuick_BoxLeast(H, y0, w, y);
	mkVec3 yv = {y[0], y[1], y[2]}, z = mkMat3_MulVecInline(B, mkVec3_Sub(yv, c));
	*x = mkVec3_Add(X->t, mkMat3_MulVecInline(X->M, yv));
	*n = mkMat3_MulTVecInline(Ei, z);   /* the gradient of E's gauge (squared, halved) at x */
	return mkVec3_Dot(z, z) < 1.0;
}

/* A box-like inner model against an ellipsoid one, the obstacle's o and
 * the part's p (either way round): the point of the box inside the
 * box-like one where the ellipsoid's gauge is least (mkSq_BoxPoint).
 * Returns 2 when it certifies an overlap deeper than m
 * (mkSqQuick_PointDepth, *depth), 1 when the normal of the ellipsoid's
 * level set there certifies the outer models at least lim apart
 * (mkSq_Along; not tried when lim is infinite), else 0. */
static int mkSq_BoxEllipsoid(const mkSqModels *o, const mkSqModels *p, const mkMat3 *R, mkVec3 d, double lim, double m,
	double *depth)
{
	mkVec3 x, n;
	mkMat3 Pi = mkMat3_MulInline(p->kinner->Mi, mkMat3_Transpose(*R));   /* the part's world frame to its canonical one */
	int obox = mkSq_Boxy(o->inner->shape);
	int in = obox ? mkSq_BoxPoint(o->inner, &o->kinner->Mi, o->kinner->w, p->inner, Pi, &x, &n)
		: mkSq_BoxPoint(p->inner, &Pi, p->kinner->w, o->inner, o->kinner->Mi, &x, &n);
	if (in) {
		double dep = mkSqQuick_PointDepth(o, p, R, x);
		if (!(dep > m)) return 0;
		*depth = dep;
		return 2;
	}
	double l = sqrt(mkVec3_Dot(n, n));
	if (!isfinite(lim) || !(l > 0.0) || !isfinite(l)) return 0;
	/* (along d: from the obstacle to the part) */
	return mkSq_Along(o->outer, p->outer, mkVec3_Scale(n, (obox ? -1.0 : 1.0) / l), d, lim) > lim;
}

int mkSqQuick_Pair(const mkSqModels *o, const mkSqModels *p, const mkMat3 *R, double best, double *depth)
{
	const mkBody3 *ob = o->outer, *pb = p->outer;
	mkVec3 d = mkVec3_Sub(pb->t, ob->t);
	double L = sqrt(mkVec3_Dot(d, d)), size = L + o->kouter->r + p->kouter->r, m = MK_SQ_QUICK * size;
	/* (the bounds without powers decide only what the norms would decide, by a margin beyond both's rounding) */
	double e = 1e-13 * size;
	if (L > 0.0) {
		mkVec3 u = mkVec3_Scale(d, 1.0 / L), yo = mkMat3_MulTVecInline(ob->M, u), yp = mkMat3_MulTVecInline(pb->M, u);
		double olo, ohi, plo, phi;
		mkSq_Bounds(ob->shape, yo, 1, &olo, &ohi);
		mkSq_Bounds(pb->shape, yp, 1, &plo, &phi);
		double flo = L - ohi - phi, fhi = L - olo - plo;
		if (flo > best + m + e) return 1;
		if (flo > m + e && fhi <= best + m - e) return isfinite(best) ? 0 : 3;
		if (fhi > m - e) {
			/* (an ellipsoid's bounds are its norm, the same operations as mkSq_ShapeNorm's) */
			double ho = mkSq_Ellipsoid(ob->shape) ? ohi : mkSq_ShapeNorm(ob->shape, yo, 1);
			double f = L - ho - (mkSq_Ellipsoid(pb->shape) ? phi : mkSq_ShapeNorm(pb->shape, yp, 1));
			if (f > best + m) return 1;
			if (f > m) return isfinite(best) ? 0 : 3;
		}
	}
	/* the overlap, of the inner models (the bodies themselves when smooth) */
	double dep = mkSq_SegmentDepth(o, p, R);
	*depth = dep;
	if (dep > m) return 2;
	/* a box-like body: the direction from the box of its semi-axes to the other's centre */
	if (isfinite(best) && (mkSq_Boxy(ob->shape) || mkSq_Boxy(pb->shape)) && mkSq_BoxApart(o, p, R, d, best + m + e))
		return 1;
	if (mkSq_Boxy(o->inner->shape)) dep = mkSq_Fmax(dep, mkSq_FaceDepth(o, p, R));
	*depth = dep;
	if (dep > m) return 2;
	/* a box-like body and an ellipsoid: the box inside the box-like one (about a declared box) */
	if ((mkSq_Boxy(o->inner->shape) && mkSq_Ellipsoid(p->inner->shape))
		|| (mkSq_Boxy(p->inner->shape) && mkSq_Ellipsoid(o->inner->shape))) {
		int r = mkSq_BoxEllipsoid(o, p, R, d, isfinite(best) ? best + m + e : INFINITY, m, depth);
		if (r) return r;
	}
	/* the direction of the sum of the semi-axes' ellipsoids */
	if (!isfinite(best)) return 0;
	double lim = best + m + e;
	mkVec3 x;
	if (mkSq_SpreadApart(ob, pb, d, lim, &x) > lim) return 1;
	/* a box-like body's face normals */
	if (mkSq_Boxy(ob->shape) && mkSq_FacesApart(ob, o->kouter, pb, d, lim) > lim) return 1;
	/* the contact point of Perram and Wertheim's function of the semi-axes' ellipsoids at lambda = 1/2,
	 * x = c_O + S_O (S_O + S_P)^-1 d (mkSq_SpreadApart's) */
	dep = mkSqQuick_PointDepth(o, p, R, x);
	if (dep > m) {
		*depth = dep;
		return 2;
	}
	return 0;
}

