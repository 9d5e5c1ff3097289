/* test_polygon.c - convex polygons from rings, and edge sorting against
 * CGAL's minkowski_sum_2 on the exact kernel (the independent reference)
 * and against hand-worked sums. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include <mink/baselines.h>
#include <mink/registry.h>

#include "ensure.h"

/* Edge sort against CGAL: same vertex count, same vertices in the same
 * order. Both are the exact vertices P_i + Q_j, one rounded to nearest by
 * the addition (error <= u |v|), the other converted by CGAL::to_double from
 * its exact number type (error <= 1 ulp = 2u |v|), so per coordinate they
 * differ by at most 3u |v|; 4u |v| is allowed. */
static int same_polygon(const mkPointSet *a, const mkPointSet *b)
{
	if (a->count != b->count) {
		fprintf(stderr, "vertex counts differ: %d vs %d\n", a->count, b->count);
		return 0;
	}
	const double u = DBL_EPSILON / 2;
	for (int k = 0; k < a->count; ++k) {
		double tx = 4 * u * fabs(b->x[k]), ty = 4 * u * fabs(b->y[k]);
		if (fabs(a->x[k] - b->x[k]) > tx || fabs(a->y[k] - b->y[k]) > ty) {
			fprintf(stderr, "vertex %d: (%.17g, %.17g) vs (%.17g, %.17g)\n", k, a->x[k], a->y[k], b->x[k], b->y[k]);
			return 0;
		}
	}
	return 1;
}

static int check_merge(const double *P, int m, const double *Q, int n)
{
	mkPointSet mine = {0}, cgal = {0};
	int ok = mkEdgeSort2_Merge(P, m, Q, n, &mine) == MK_OK && mkMinkowski2_CgalEpeck(P, m, Q, n, &cgal) == MK_OK
		&& same_polygon(&mine, &cgal);
	mkPointSet_Free(&mine);
	mkPointSet_Free(&cgal);
	return ok;
}

/* Samples of a placed superellipse as a ring (the order of its angles). */
static int body_ring(unsigned long long *seed, int n, double *ring, double *poly)
{
	mkShape2 s = {mk_test_uniform(seed, 0.5, 10), mk_test_uniform(seed, 0.5, 10), mk_test_uniform(seed, 0.1, 1.9)};
	mkMat2 M = mkMat2_Mul(mkMat2_Rotation(mk_test_uniform(seed, 0, 2 * MK_PI)), mkMat2_Shear(mk_test_uniform(seed, -2, 2)));
	if (mk_test_unit(seed) < 0.3) M.m[0][0] = -M.m[0][0], M.m[1][0] = -M.m[1][0]; /* a reflection: clockwise ring */
	mkBody2 b = mkBody2_Make(s, M, (mkVec2){mk_test_uniform(seed, -5, 5), mk_test_uniform(seed, -5, 5)});
	double *u = malloc(2 * (size_t)n * sizeof *u);
	mkSample2_Angles(n, u, u + n);
	for (int k = 0; k < n; ++k) {
		mkVec2 p = mkBody2_Point(b, (mkVec2){u[k], u[n + k]});
		ring[2 * k] = p.x;
		ring[2 * k + 1] = p.y;
	}
	free(u);
	return mkPolygon2_Convex(ring, n, poly);
}

int main(void)
{
	unsigned long long seed = 7;
	double out[64];

	/* A square given clockwise from a middle vertex: reversed and rotated to
	 * start at the lowest-leftmost vertex, (0, 0). */
	double sq[] = {1, 1, 1, 0, 0, 0, 0, 1};
	ENSURE(mkPolygon2_Convex(sq, 4, out) == 4);
	ENSURE(out[0] == 0 && out[1] == 0 && out[2] == 1 && out[3] == 0 && out[4] == 1 && out[5] == 1);
	/* A collinear midpoint and a repeated vertex are dropped. */
	double col[] = {0, 0, 0.5, 0, 1, 0, 1, 1, 1, 1, 0, 1};
	ENSURE(mkPolygon2_Convex(col, 6, out) == 4);
	ENSURE(out[0] == 0 && out[1] == 0 && out[2] == 1 && out[3] == 0);
	/* A pentagram: every turn is left but the ring winds twice; the result is
	 * the pentagon. */
	double star[10];
	for (int k = 0; k < 5; ++k) {
		star[2 * k] = cos(MK_PI / 2 + 4 * MK_PI * k / 5);
		star[2 * k + 1] = sin(MK_PI / 2 + 4 * MK_PI * k / 5);
	}
	int c = mkPolygon2_Convex(star, 5, out);
	ENSURE(c == 5);
	for (int k = 0; c == 5 && k < 5; ++k) ENSURE(mkOrient2(out + 2 * k, out + 2 * ((k + 1) % 5), out + 2 * ((k + 2) % 5)) == 1);
	/* One point, two points. */
	ENSURE(mkPolygon2_Convex(sq, 1, out) == 1);
	ENSURE(mkPolygon2_Convex(sq, 2, out) == 2);

	/* Hand-worked sums. Unit square + unit square = the square of side 2,
	 * parallel edges merged: 4 vertices. */
	double a[] = {0, 0, 1, 0, 1, 1, 0, 1};
	mkPointSet s = {0};
	ENSURE(mkEdgeSort2_Merge(a, 4, a, 4, &s) == MK_OK);
	ENSURE(s.count == 4);
	ENSURE(s.x[0] == 0 && s.y[0] == 0 && s.x[1] == 2 && s.y[1] == 0 && s.x[2] == 2 && s.y[2] == 2);
	/* A point plus a triangle is the translated triangle. */
	double pt[] = {5, -1}, tri[] = {0, 0, 2, 0, 0, 1};
	ENSURE(mkEdgeSort2_Merge(pt, 1, tri, 3, &s) == MK_OK);
	ENSURE(s.count == 3 && s.x[1] == 7 && s.y[1] == -1 && s.x[2] == 5 && s.y[2] == 0);
	/* A segment (two vertices, there and back) plus the square: a hexagon
	 * when the segment is diagonal, 6 vertices. */
	double seg[] = {0, 0, 1, 1};
	ENSURE(mkEdgeSort2_Merge(seg, 2, a, 4, &s) == MK_OK);
	ENSURE(s.count == 6);
	mkPointSet_Free(&s);

	/* Against CGAL: polygons with parallel edges (squares, a hexagon, an
	 * octagon sharing four directions with the square). */
	double hex[12], oct[16];
	for (int k = 0; k < 6; ++k) hex[2 * k] = cos(MK_PI * k / 3 - MK_PI / 2), hex[2 * k + 1] = sin(MK_PI * k / 3 - MK_PI / 2);
	for (int k = 0; k < 8; ++k) oct[2 * k] = 3 * cos(MK_PI * k / 4 - MK_PI / 2), oct[2 * k + 1] = 3 * sin(MK_PI * k / 4 - MK_PI / 2);
	double hexp[12], octp[16];
	ENSURE(mkPolygon2_Convex(hex, 6, hexp) == 6);
	ENSURE(mkPolygon2_Convex(oct, 8, octp) == 8);
	ENSURE(check_merge(a, 4, a, 4));
	ENSURE(check_merge(a, 4, hexp, 6));
	ENSURE(check_merge(octp, 8, a, 4));
	ENSURE(check_merge(octp, 8, hexp, 6));

	/* Against CGAL: sample polygons of random placed superellipses (rings in
	 * either orientation), 40 pairs of 16 to 400 vertices. */
	for (int t = 0; t < 40; ++t) {
		int n1 = 16 + (int)(mk_test_unit(&seed) * 384), n2 = 16 + (int)(mk_test_unit(&seed) * 384);
		double *r1 = malloc(2 * (size_t)n1 * sizeof *r1), *p1 = malloc(2 * (size_t)n1 * sizeof *p1);
		double *r2 = malloc(2 * (size_t)n2 * sizeof *r2), *p2 = malloc(2 * (size_t)n2 * sizeof *p2);
		int m1 = body_ring(&seed, n1, r1, p1), m2 = body_ring(&seed, n2, r2, p2);
		ENSURE(m1 >= 3 && m2 >= 3);
		ENSURE(check_merge(p1, m1, p2, m2));
		free(r1);
		free(p1);
		free(r2);
		free(p2);
	}
	return mk_summary("test_polygon");
}
