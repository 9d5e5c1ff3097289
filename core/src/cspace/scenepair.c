/* scenepair.c - the scene query's quick certificates of a pair
 * (cspace/scenepair.h): support values and gauges of superquadrics by
 * their norms, a separating direction along the centre line and a common
 * point on the centre segment. */
#include "cspace/scenepair.h"

#include <float.h>
#include <math.h>

#include "base/geom_inline.h"

#define MK_SQ_QUICK 4e-12   /* margin of the certificates, times the pair's size (as MK_BATCH_MARGIN) */

mkSqQuick mkSqQuick_Make(mkBody3 b)
{
	mkSqQuick k;
	k.Mi = mkMat3_Inverse(b.M);
	double fm = 0.0, fi = 0.0, big = fmax(b.shape.a, fmax(b.shape.b, b.shape.c));
	for (int i = 0; i < 9; ++i) {
		fm += b.M.m[i / 3][i % 3] * b.M.m[i / 3][i % 3];
		fi += k.Mi.m[i / 3][i % 3] * k.Mi.m[i / 3][i % 3];
	}
	k.r = big * sqrt(fm);
	/* the shape holds the cross-polytope of its axes, whose inradius is 1 / |(1/a, 1/b, 1/c)| */
	k.rho = 1.0 / (sqrt(fi) * sqrt(1.0 / (b.shape.a * b.shape.a) + 1.0 / (b.shape.b * b.shape.b)
		+ 1.0 / (b.shape.c * b.shape.c))) * (1.0 - 1e-12);
	k.slack = 64.0 * DBL_EPSILON * (1.0 + sqrt(fm * fi));
	return k;
}

/* |(u, v)|_p of u, v >= 0. */
static double mkSq_Norm2(double u, double v, double p)
{
	double m = u > v ? u : v, k = u > v ? v : u;
	if (!(m > 0.0)) return 0.0;
	return p == 2.0 ? m * sqrt(1.0 + (k / m) * (k / m)) : m * pow(1.0 + pow(k / m, p), 1.0 / p);
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
	if (dual)
		return mkSq_Norm2(mkSq_Norm2(s.a * x1, s.b * x2, 2.0 / (2.0 - s.eps2)), s.c * x3, 2.0 / (2.0 - s.eps1));
	return mkSq_Norm2(mkSq_Norm2(x1 / s.a, x2 / s.b, 2.0 / s.eps2), x3 / s.c, 2.0 / s.eps1);
}

void mkSq_NormBounds(mkShape3 s, mkVec3 y, int dual, double *lo, double *hi)
{
	double x1 = fabs(y.x), x2 = fabs(y.y), x3 = fabs(y.z);
	if (dual) { x1 *= s.a; x2 *= s.b; x3 *= s.c; }
	else { x1 /= s.a; x2 /= s.b; x3 /= s.c; }
	double l2 = sqrt(x1 * x1 + x2 * x2 + x3 * x3), inf = fmax(x1, fmax(x2, x3)), l1 = x1 + x2 + x3;
	int round = s.eps1 >= 1.0 && s.eps2 >= 1.0, boxy = s.eps1 <= 1.0 && s.eps2 <= 1.0;
	/* support value: at least the octahedron's (inf) or the ellipsoid's, at most the box's (l1) or the
	 * ellipsoid's; gauge: at least the box's (inf) or the ellipsoid's, at most the octahedron's (l1) */
	*lo = (dual ? boxy : round) ? l2 : inf;
	*hi = (dual ? round : boxy) ? l2 : l1;
}

int mkSqQuick_Pair(const mkBody3 *o, const mkSqQuick *ko, const mkBody3 *p, const mkSqQuick *kp, const mkMat3 *R, int smooth,
	double best, double *depth)
{
	mkVec3 d = mkVec3_Sub(p->t, o->t);
	double L = sqrt(mkVec3_Dot(d, d)), size = L + ko->r + kp->r, m = MK_SQ_QUICK * size;
	/* (the bounds without powers decide only what the norms would decide, by a margin beyond both's rounding) */
	double e = 1e-13 * size;
	if (L > 0.0) {
		mkVec3 u = mkVec3_Scale(d, 1.0 / L), yo = mkMat3_MulTVecInline(o->M, u), yp = mkMat3_MulTVecInline(p->M, u);
		double olo, ohi, plo, phi;
		mkSq_NormBounds(o->shape, yo, 1, &olo, &ohi);
		mkSq_NormBounds(p->shape, yp, 1, &plo, &phi);
		double flo = L - ohi - phi, fhi = L - olo - plo;
		if (flo > best + m + e) return 1;
		if (flo > m + e && fhi <= best + m - e) return isfinite(best) ? 0 : 3;
		if (fhi > m - e) {
			/* (an ellipsoid's bounds are its norm, the same operations as mkSq_ShapeNorm's) */
			double ho = mkSq_Ellipsoid(o->shape) ? ohi : mkSq_ShapeNorm(o->shape, yo, 1);
			double f = L - ho - (mkSq_Ellipsoid(p->shape) ? phi : mkSq_ShapeNorm(p->shape, yp, 1));
			if (f > best + m) return 1;
			if (f > m) return isfinite(best) ? 0 : 3;
		}
	}
	if (!smooth) return 0;
	mkVec3 yp = mkMat3_MulVecInline(kp->Mi, mkMat3_MulTVecInline(*R, mkVec3_Neg(d)));   /* the obstacle's centre, in the part's frame */
	mkVec3 yo = mkMat3_MulVecInline(ko->Mi, d);                                    /* the part's centre, in the obstacle's */
	/* the gauges' lower bounds first: no interval when even they leave none */
	double plo, phi, olo, ohi;
	mkSq_NormBounds(p->shape, yp, 0, &plo, &phi);
	mkSq_NormBounds(o->shape, yo, 0, &olo, &ohi);
	double gpl = plo * (1.0 + kp->slack) + kp->slack, gol = olo * (1.0 + ko->slack) + ko->slack;
	if (fmax(0.0, 1.0 - 1.0 / gpl) >= fmin(1.0, 1.0 / gol) + 1e-12) return 0;
	double gp = mkSq_Ellipsoid(p->shape) ? gpl : mkSq_ShapeNorm(p->shape, yp, 0) * (1.0 + kp->slack) + kp->slack;
	double go = mkSq_Ellipsoid(o->shape) ? gol : mkSq_ShapeNorm(o->shape, yo, 0) * (1.0 + ko->slack) + ko->slack;
	double lo = fmax(0.0, 1.0 - 1.0 / gp), hi = fmin(1.0, 1.0 / go);
	if (!(lo < hi)) return 0;
	double dlo = fmax(0.0, 1.0 - lo * go) * ko->rho + fmax(0.0, 1.0 - (1.0 - lo) * gp) * kp->rho;
	double dhi = fmax(0.0, 1.0 - hi * go) * ko->rho + fmax(0.0, 1.0 - (1.0 - hi) * gp) * kp->rho;
	*depth = fmax(dlo, dhi);
	return *depth > m ? 2 : 0;
}
