/* hull.h - the least-norm point of the hull of at most four points: the
 * step of Gilbert's iteration on B2 - B1, shared by the solver's fallback
 * (fallback.h) and the batch's certificates (batch.c). Static definitions. */
#ifndef MINK_COLLIDE_HULL_H
#define MINK_COLLIDE_HULL_H

#include "collide/support.h"

/* The least-norm point of the convex hull of w[0..k), k <= 4: every subset
 * of one, two or three points is tried (the nearest point of its affine hull
 * by the normal equations), those with nonnegative weights kept, the least
 * norm wins. lam receives the weights (0 outside the winning subset). */
MK_PAIR_FN mkVec3 mkHull_Nearest(const mkVec3 *w, int k, double lam[4])
{
	double bestn = INFINITY;
	mkVec3 best = w[0];
	for (int i = 0; i < 4; ++i)
		lam[i] = i == 0 ? 1.0 : 0.0;
	for (int mask = 1; mask < (1 << k); ++mask) {
		int id[4], n = 0;
		for (int i = 0; i < k; ++i)
			if (mask & (1 << i))
				id[n++] = i;
		if (n > 3)
			continue;
		double mu[3] = { 1.0, 0.0, 0.0 };
		if (n == 2) {
			mkVec3 e = mkVec3_Sub(w[id[1]], w[id[0]]);
			double ee = mkVec3_Dot(e, e);
			if (!(ee > 0.0))
				continue;
			mu[1] = -mkVec3_Dot(e, w[id[0]]) / ee;
			mu[0] = 1.0 - mu[1];
		} else if (n == 3) {
			mkVec3 e1 = mkVec3_Sub(w[id[1]], w[id[0]]), e2 = mkVec3_Sub(w[id[2]], w[id[0]]);
			double a = mkVec3_Dot(e1, e1), b = mkVec3_Dot(e1, e2), c = mkVec3_Dot(e2, e2);
			double r1 = -mkVec3_Dot(e1, w[id[0]]), r2 = -mkVec3_Dot(e2, w[id[0]]);
			double det = a * c - b * b;
			if (!(det > 1e-300 && det > 1e-14 * a * c))
				continue;
			mu[1] = (c * r1 - b * r2) / det;
			mu[2] = (a * r2 - b * r1) / det;
			mu[0] = 1.0 - mu[1] - mu[2];
		}
		if (mu[0] < 0.0 || mu[1] < 0.0 || mu[2] < 0.0)
			continue;
		mkVec3 z = mkVec3_Make(0.0, 0.0, 0.0);
		for (int j = 0; j < n; ++j)
			z = mkVec3_Add(z, mkVec3_Scale(w[id[j]], mu[j]));
		double zn = mkVec3_Dot(z, z);
		if (zn < bestn) {
			bestn = zn;
			best = z;
			for (int i = 0; i < 4; ++i)
				lam[i] = 0.0;
			for (int j = 0; j < n; ++j)
				lam[id[j]] = mu[j];
		}
	}
	return best;
}

#endif
