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

double mkSq_ShapeNorm(mkShape3 s, mkVec3 y, int dual)
{
	double x1 = fabs(y.x), x2 = fabs(y.y), x3 = fabs(y.z);
	if (s.eps1 == 1.0 && s.eps2 == 1.0) { /* an ellipsoid: the 2-norm (inf when it overflows: never certifies) */
		if (dual) { x1 *= s.a; x2 *= s.b; x3 *= s.c; }
		else { x1 /= s.a; x2 /= s.b; x3 /= s.c; }
		return sqrt(x1 * x1 + x2 * x2 + x3 * x3);
	}
	if (dual)
		return mkSq_Norm2(mkSq_Norm2(s.a * x1, s.b * x2, 2.0 / (2.0 - s.eps2)), s.c * x3, 2.0 / (2.0 - s.eps1));
	return mkSq_Norm2(mkSq_Norm2(x1 / s.a, x2 / s.b, 2.0 / s.eps2), x3 / s.c, 2.0 / s.eps1);
}

int mkSqQuick_Pair(const mkBody3 *o, const mkSqQuick *ko, const mkBody3 *p, const mkSqQuick *kp, const mkMat3 *R, int smooth,
	double best, double *depth)
{
	mkVec3 d = mkVec3_Sub(p->t, o->t);
	double L = sqrt(mkVec3_Dot(d, d)), m = MK_SQ_QUICK * (L + ko->r + kp->r);
	if (L > 0.0) {
		mkVec3 u = mkVec3_Scale(d, 1.0 / L);
		double f = L - mkSq_ShapeNorm(o->shape, mkMat3_MulTVecInline(o->M, u), 1)
			- mkSq_ShapeNorm(p->shape, mkMat3_MulTVecInline(p->M, u), 1);
		if (f > best + m) return 1;
		if (f > m) return isfinite(best) ? 0 : 3;
	}
	if (!smooth) return 0;
	mkVec3 yp = mkMat3_MulVecInline(kp->Mi, mkMat3_MulTVecInline(*R, mkVec3_Neg(d)));   /* the obstacle's centre, in the part's frame */
	mkVec3 yo = mkMat3_MulVecInline(ko->Mi, d);                                    /* the part's centre, in the obstacle's */
	double gp = mkSq_ShapeNorm(p->shape, yp, 0) * (1.0 + kp->slack) + kp->slack;
	double go = mkSq_ShapeNorm(o->shape, yo, 0) * (1.0 + ko->slack) + ko->slack;
	double lo = fmax(0.0, 1.0 - 1.0 / gp), hi = fmin(1.0, 1.0 / go);
	if (!(lo < hi)) return 0;
	double dlo = fmax(0.0, 1.0 - lo * go) * ko->rho + fmax(0.0, 1.0 - (1.0 - lo) * gp) * kp->rho;
	double dhi = fmax(0.0, 1.0 - hi * go) * ko->rho + fmax(0.0, 1.0 - (1.0 - hi) * gp) * kp->rho;
	*depth = fmax(dlo, dhi);
	return *depth > m ? 2 : 0;
}
