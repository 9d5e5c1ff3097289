/* test_convergence.c - the sampled methods converge to the closed-form
 * boundary at the rate sampling predicts.
 *
 * A hull of pairwise sums of samples is the Minkowski sum of two inscribed
 * polygons (polyhedra), which lies inside the true sum; its Hausdorff
 * distance to the true sum is the largest gap of support functions,
 *     e(N) = max_d [ h(d) - max_v <d, v> ],
 * with h(d) = <d, x(d)> for the closed-form boundary point x(d) of outward
 * normal d (Theorem 1, normal parameterisation). For a smooth convex curve
 * sampled with parameter spacing h, each chord leaves a cap of height
 * ~ kappa h^2 / 8, so e(N) = O(N^-2) in 2D, and O(n^-2) for an n x n grid
 * in 3D. The test fits the slope of log e against log N over a range of N
 * and asks for -2 within 0.25 (the finite set of test directions, the
 * pre-asymptotic terms and the drifting phase of the two bodies' samples
 * move it by up to about 0.15 here). */
#include <math.h>
#include <stdlib.h>

#include <mink/registry.h>

#include "ensure.h"

static double slope(const double *n, const double *e, int m)
{
	double sx = 0, sy = 0, sxx = 0, sxy = 0;
	for (int i = 0; i < m; ++i) {
		double x = log(n[i]), y = log(e[i]);
		sx += x, sy += y, sxx += x * x, sxy += x * y;
	}
	return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

int main(void)
{
	/* 2D: a rounded box (eps 0.6) sheared and rotated, and a pointed body
	 * (eps 1.4); contact set. Directions: 4096 evenly spaced angles. */
	mkShape2 s1 = {4, 2.5, 0.6}, s2 = {1.5, 3, 1.4};
	mkBody2 a = mkBody2_Make(s1, mkMat2_Mul(mkMat2_Rotation(0.4), mkMat2_Shear(0.8)), (mkVec2){1, -2});
	mkBody2 b = mkBody2_Make(s2, mkMat2_Mul(mkMat2_Rotation(-1.2), mkMat2_Shear(-0.5)), (mkVec2){3, 4});
	enum { D2 = 4096 };
	static double dx[D2], dy[D2], h2[D2];
	for (int i = 0; i < D2; ++i) {
		dx[i] = cos(2 * MK_PI * (i + 0.25) / D2), dy[i] = sin(2 * MK_PI * (i + 0.25) / D2);
		mkVec2 d = {dx[i], dy[i]};
		mkVec2 x = mkSum2_Point(a, b, MK_SET_CONTACT, MK_FORM_NORMAL, MK_PARAM_NORMAL, d, NULL);
		h2[i] = d.x * x.x + d.y * x.y;
	}
	static const char *const m2[] = {"hull-cgal-epick", "hull-cgal-epeck", "hull-qhull", "edge-sort"};
	/* Six doublings: the largest gap is the sum of two bodies' caps whose
	 * phases drift with N, which moves e(N) N^2 by up to a factor of two
	 * from one N to the next (N = 128 here), so the fit needs the range. */
	enum { S2 = 6 };
	const double N2[S2] = {16, 32, 64, 128, 256, 512};
	mkPointSet out = {0};
	for (int k = 0; k < 4; ++k) {
		const mkMethod *m = mkRegistry_Find(m2[k]);
		double e[S2];
		int ok = 1;
		for (int j = 0; j < S2; ++j) {
			ok &= m->run2(a, b, MK_SET_CONTACT, (int)N2[j], &out) == MK_OK;
			double worst = 0;
			for (int i = 0; i < D2; ++i) {
				double best = -HUGE_VAL;
				for (int v = 0; v < out.count; ++v) best = fmax(best, dx[i] * out.x[v] + dy[i] * out.y[v]);
				worst = fmax(worst, h2[i] - best);
			}
			e[j] = worst;
		}
		ENSURE(ok);
		double sl = slope(N2, e, S2);
		printf("2D %-16s e(N) for N = 16..512:", m->name);
		for (int j = 0; j < S2; ++j) printf(" %.3e", e[j]);
		printf("; slope %.3f\n", sl);
		ENSURE_NEAR(sl, -2.0, 0.25);
	}

	/* 3D: two superquadrics, rotated; plus set. Directions: 2000 on a
	 * Fibonacci sphere. */
	double qa[4] = {0.8, 0.3, -0.4, 0.2}, qb[4] = {0.1, -0.7, 0.5, 0.5};
	mkShape3 t1 = {3, 2, 1.5, 0.7, 1.3}, t2 = {1, 1.5, 2, 1.2, 0.8};
	mkBody3 c = mkBody3_Make(t1, mkMat3_FromQuat(qa[0], qa[1], qa[2], qa[3]), (mkVec3){1, 0, -1});
	mkBody3 d = mkBody3_Make(t2, mkMat3_FromQuat(qb[0], qb[1], qb[2], qb[3]), (mkVec3){-2, 1, 0});
	enum { D3 = 2000 };
	static double ex[D3], ey[D3], ez[D3], h3[D3];
	for (int i = 0; i < D3; ++i) {
		double z = 1 - (2.0 * i + 1) / D3, r = sqrt(1 - z * z), phi = MK_PI * (3 - sqrt(5.0)) * i;
		ex[i] = r * cos(phi), ey[i] = r * sin(phi), ez[i] = z;
		mkVec3 dd = {ex[i], ey[i], ez[i]};
		mkVec3 x = mkSum3_Point(c, d, MK_SET_PLUS, MK_FORM_NORMAL, MK_PARAM_NORMAL, dd, NULL);
		h3[i] = dd.x * x.x + dd.y * x.y + dd.z * x.z;
	}
	static const char *const m3[] = {"hull-cgal-epick", "hull-cgal-epeck", "hull-qhull"};
	const double N3[] = {6, 12, 24};
	for (int k = 0; k < 3; ++k) {
		const mkMethod *m = mkRegistry_Find(m3[k]);
		/* Exact constructions cost ten times more: two sizes suffice for a
		 * slope. */
		int sizes = k == 1 ? 2 : 3, ok = 1;
		double e[3];
		for (int j = 0; j < sizes; ++j) {
			ok &= m->run3(c, d, MK_SET_PLUS, (int)N3[j], &out) == MK_OK;
			double worst = 0;
			for (int i = 0; i < D3; ++i) {
				double best = -HUGE_VAL;
				for (int v = 0; v < out.count; ++v) best = fmax(best, ex[i] * out.x[v] + ey[i] * out.y[v] + ez[i] * out.z[v]);
				worst = fmax(worst, h3[i] - best);
			}
			e[j] = worst;
		}
		ENSURE(ok);
		double sl = slope(N3, e, sizes);
		printf("3D %-16s e(n) for n = 6, 12%s: %.3e %.3e", m->name, sizes == 3 ? ", 24" : "", e[0], e[1]);
		if (sizes == 3) printf(" %.3e", e[2]);
		printf("; slope %.3f\n", sl);
		ENSURE_NEAR(sl, -2.0, 0.25);
	}
	mkPointSet_Free(&out);
	return mk_summary("test_convergence");
}
