/* test_hull.c - convex hull volumes against hand-computed ones. */
#include "ensure.h"
#include "latlong.h"
#include "hull.h"

#include <stdlib.h>


static double sphereGridHull(double r, int n, int *vertices)
{
	int count = n * n;
	double *x = malloc(sizeof(double) * 3 * (size_t)count);
	double *y = x + count, *z = y + count;
	for (int i = 0; i < n; ++i) {
		double e = -MK_PI / 2 + MK_PI * i / (n - 1);
		for (int j = 0; j < n; ++j) {
			double w = 2 * MK_PI * j / n;
			x[i * n + j] = r * cos(e) * cos(w);
			y[i * n + j] = r * cos(e) * sin(w);
			z[i * n + j] = r * sin(e);
		}
	}
	double v = NAN;
	ENSURE(mkHull3_Volume(x, y, z, count, &v, vertices, NULL) == MK_OK);
	free(x);
	return v;
}

int main(void)
{
	/* Unit cube: its 8 corners, a duplicate corner, a point inside and one
	 * on a face. Volume 1; qhull sums a dozen facet determinants of O(1)
	 * numbers, so rounding stays within a few units of 1e-16: 1e-14. */
	{
		double x[11], y[11], z[11];
		for (int k = 0; k < 8; ++k) {
			x[k] = k & 1;
			y[k] = (k >> 1) & 1;
			z[k] = (k >> 2) & 1;
		}
		x[8] = 1; y[8] = 1; z[8] = 1;        /* duplicate of corner 7 */
		x[9] = 0.3; y[9] = 0.6; z[9] = 0.2;  /* interior */
		x[10] = 0.5; y[10] = 0.5; z[10] = 0; /* on the face z = 0 */
		double v = NAN;
		int nv = -1, flag[11];
		ENSURE(mkHull3_Volume(x, y, z, 11, &v, &nv, flag) == MK_OK);
		ENSURE_NEAR(v, 1.0, 1e-14);
		ENSURE(nv == 8);
		ENSURE(flag[9] == 0 && flag[10] == 0);
		ENSURE(flag[0] && flag[1] && flag[2] && flag[3] && flag[4] && flag[5] && flag[6]);
		ENSURE(flag[7] + flag[8] == 1);
	}

	/* Regular tetrahedron on alternate corners of the cube [-1,1]^3: edge
	 * 2 sqrt 2, volume edge^3 / (6 sqrt 2) = 8/3 (the cube's 8 minus four
	 * corner pieces of 4/3). Tolerance as for the cube. */
	{
		double x[4] = { 1, 1, -1, -1 }, y[4] = { 1, -1, 1, -1 }, z[4] = { 1, -1, -1, 1 };
		double v = NAN;
		int nv = -1;
		ENSURE(mkHull3_Volume(x, y, z, 4, &v, &nv, NULL) == MK_OK);
		ENSURE_REL(v, 8.0 / 3.0, 1e-14);
		ENSURE(nv == 4);
		/* translated far away: the hull is translation invariant; qhull's
		 * determinants now lose about log10(1e4) digits: 1e-11 */
		for (int k = 0; k < 4; ++k) {
			x[k] += 1e4;
			y[k] -= 3e3;
		}
		ENSURE(mkHull3_Volume(x, y, z, 4, &v, NULL, NULL) == MK_OK);
		ENSURE_REL(v, 8.0 / 3.0, 1e-11);
	}

	/* A fine sphere grid: the inscribed polyhedron's volume equals the
	 * independent face-by-face sum (1e-12: both are sums of ~n^2 terms of
	 * rounding 1e-16) and approaches 4/3 pi r^3 from below at the O(h^2)
	 * rate: the defect quarters when n doubles. The latitude step is
	 * pi/(n-1), not pi/n, so the ratio approaches 4 from above like
	 * ((2n-1)/(n-1))^2 / 4 ~ 1 + 1/n; measured here 4.034 (16 -> 32) and
	 * 4.026 (32 -> 64): accept 3.8 .. 4.2, which a first-order (ratio 2)
	 * or third-order (ratio 8) defect would fail. */
	{
		const double r = 2.0, exact = 4.0 / 3.0 * MK_PI * r * r * r;
		double defect[3];
		int ns[3] = { 16, 32, 64 };
		for (int i = 0; i < 3; ++i) {
			int nv = -1;
			double v = sphereGridHull(r, ns[i], &nv);
			ENSURE_REL(v, r * r * r * latLongVolume(ns[i], ns[i]), 1e-12);
			ENSURE(nv == (ns[i] - 2) * ns[i] + 2);
			defect[i] = exact - v;
			ENSURE(defect[i] > 0.0);
		}
		double ratio1 = defect[0] / defect[1], ratio2 = defect[1] / defect[2];
		printf("sphere grid defect ratios: %.4f %.4f\n", ratio1, ratio2);
		ENSURE(ratio1 > 3.8 && ratio1 < 4.2);
		ENSURE(ratio2 > 3.8 && ratio2 < 4.2);
	}

	/* Failures: too few points, coplanar points, non-finite input. */
	{
		double x[5] = { 0, 1, 0, 1, 0.5 }, y[5] = { 0, 0, 1, 1, 0.5 }, z[5] = { 0, 0, 0, 0, 0 };
		double v = 0.0;
		ENSURE(mkHull3_Volume(x, y, z, 3, &v, NULL, NULL) == MK_ERR_ARGUMENT);
		ENSURE(mkHull3_Volume(NULL, y, z, 5, &v, NULL, NULL) == MK_ERR_ARGUMENT);
		fprintf(stderr, "(a qhull error message for flat input is expected next)\n");
		ENSURE(mkHull3_Volume(x, y, z, 5, &v, NULL, NULL) == MK_ERR_UNSUPPORTED);
		z[4] = NAN;
		ENSURE(mkHull3_Volume(x, y, z, 5, &v, NULL, NULL) == MK_ERR_UNSUPPORTED);
	}
	return mk_summary("fitting.test_hull");
}
