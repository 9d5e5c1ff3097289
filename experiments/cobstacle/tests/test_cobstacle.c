/* test_cobstacle.c - a small cobstacle run checked row by row, and its
 * Fig. 9 geometry checked against support functions written here from the
 * definitions, independent of the core's closed forms.
 *
 * Usage: test_cobstacle <result CSV> <expected rows>
 *
 * The C-obstacle K = O (+) (-R) of an obstacle O and the robot R at a
 * heading has the support function h_K(n) = h_O(n) + h_R(-n). A point x is
 * on K's boundary exactly when g(n) = h_K(n) - <n, x> is >= 0 for every unit
 * n and 0 for one (its outward normal). A superellipse |x/a|^(2/e) +
 * |y/b|^(2/e) <= 1 is the unit ball of the (2/e)-norm of (x/a, y/b), so its
 * support function is the dual norm h(d) = ||(a d1, b d2)||_q with
 * q = 2/(2 - e) (Hoelder); a placed body t + M B has h(n) = <n, t> +
 * h_B(M^T n). The test scans 3600 directions, then narrows the smallest gap
 * by golden-section search. */
#include "ensure.h"
#include "exp_testing.h"

#include <mink/geom.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


/* The q-norms below are pnorm2 (exp_testing.h), scaled by the larger
 * entry (q reaches 2e6). */
typedef struct Body { double a, b, eps, cx, cy, angle; } Body;

/* Support function of the placed superellipse in direction (nx, ny):
 * M = rot(angle), M^T n = (c nx + s ny, -s nx + c ny). */
static double support(const Body *B, double nx, double ny)
{
	double c = cos(B->angle), s = sin(B->angle);
	double dx = c * nx + s * ny, dy = -s * nx + c * ny;
	return nx * B->cx + ny * B->cy + pnorm2(B->a * dx, B->b * dy, 2.0 / (2.0 - B->eps));
}

/* The gauge (2/e)-norm of M^T (x - t) / (a, b): 1 on the boundary. */
static double gauge(const Body *B, double x, double y)
{
	double c = cos(B->angle), s = sin(B->angle);
	double dx = x - B->cx, dy = y - B->cy;
	double u = c * dx + s * dy, v = -s * dx + c * dy;
	return pnorm2(u / B->a, v / B->b, 2.0 / B->eps);
}

static double gap(const Body *O, const Body *R, double x, double y, double th)
{
	double nx = cos(th), ny = sin(th);
	/* h_R(-n) for the robot centred at the origin. */
	return support(O, nx, ny) + support(R, -nx, -ny) - (nx * x + ny * y);
}

/* The smallest gap over the circle and its most negative sample. */
static double minGap(const Body *O, const Body *R, double x, double y, double *most_negative)
{
	const int M = 3600;
	double best = INFINITY, bth = 0.0;
	*most_negative = INFINITY;
	for (int k = 0; k < M; ++k) {
		double th = 2.0 * MK_PI * k / M;
		double g = gap(O, R, x, y, th);
		*most_negative = fmin(*most_negative, g);
		if (g < best) {
			best = g;
			bth = th;
		}
	}
	/* Golden section on one step either side: g is unimodal there for
	 * these smooth, strictly convex bodies. */
	double lo = bth - 2.0 * MK_PI / M, hi = bth + 2.0 * MK_PI / M;
	const double r = 0.6180339887498949;
	double c = hi - r * (hi - lo), d = lo + r * (hi - lo);
	double gc = gap(O, R, x, y, c), gd = gap(O, R, x, y, d);
	for (int it = 0; it < 80; ++it) {
		if (gc < gd) {
			hi = d;
			d = c;
			gd = gc;
			c = hi - r * (hi - lo);
			gc = gap(O, R, x, y, c);
		} else {
			lo = c;
			c = d;
			gc = gd;
			d = lo + r * (hi - lo);
			gd = gap(O, R, x, y, d);
		}
	}
	best = fmin(best, fmin(gc, gd));
	*most_negative = fmin(*most_negative, best);
	return best;
}

static void checkRows(const char *path, long expected)
{
	mkTable t;
	mkTable_Load(&t, path);
	ENSURE(t.present);
	ENSURE(t.rows == expected);
	static const char *const cols[] = { "dim", "obstacles", "points", "orientations", "total_points", "total_s",
		"us_per_point", "cpu_s", "trial", "form", "impl", "published_total_s", "published_us_per_point", "nonfinite",
		"clamped", "checksum", "robot_a", "robot_b", "robot_c", "robot_eps1", "robot_eps2" };
	ENSURE(t.cols == (int)(sizeof cols / sizeof cols[0]));
	for (int c = 0; c < t.cols && c < (int)(sizeof cols / sizeof cols[0]); ++c)
		ENSURE(strcmp(t.names[c], cols[c]) == 0);
	for (long r = 0; r < t.rows; ++r) {
		double n = num(&t, r, "obstacles"), p = num(&t, r, "points");
		double o = num(&t, r, "orientations"), tot = num(&t, r, "total_points");
		double s = num(&t, r, "total_s"), us = num(&t, r, "us_per_point");
		ENSURE(tot == n * p * o);
		ENSURE(s > 0.0);
		ENSURE(num(&t, r, "cpu_s") > 0.0);
		/* One division and one product: a few units of 1e-16 apart. */
		ENSURE_NEAR(us, s * 1e6 / tot, 1e-12 * us);
		ENSURE(num(&t, r, "nonfinite") == 0.0);
		ENSURE(isfinite(num(&t, r, "checksum")));
		ENSURE(strcmp(str(&t, r, "form"), "gradient") == 0);
		/* The small levels of this run are none of the paper's. */
		ENSURE(strcmp(str(&t, r, "published_total_s"), "") == 0);
		int dim = (int)num(&t, r, "dim");
		ENSURE(dim == 2 || dim == 3);
		ENSURE((dim == 2) == (strcmp(str(&t, r, "robot_c"), "") == 0));
		double eps1 = num(&t, r, "robot_eps1");
		ENSURE(eps1 >= 1e-6 && eps1 <= 2.0 - 1e-6);
	}
	mkTable_Free(&t);
}

static void checkFigure(const char *dir)
{
	char path[8192];
	mkTable scene, obst, robot, slices;
	long blank = 0;   /* the outlines' block separators */
	snprintf(path, sizeof path, "%s/fig9-scene.csv", dir);
	mkTable_Load(&scene, path);
	ENSURE(scene.present);
	snprintf(path, sizeof path, "%s/fig9-obstacles.csv.gz", dir);
	mkTable_LoadBlocks(&obst, path, &blank);
	ENSURE(obst.present);
	snprintf(path, sizeof path, "%s/fig9-robot.csv", dir);
	mkTable_LoadBlocks(&robot, path, &blank);
	ENSURE(robot.present);
	snprintf(path, sizeof path, "%s/fig9-slices.csv.gz", dir);
	mkTable_LoadBlocks(&slices, path, &blank);
	ENSURE(slices.present);
	if (scene.rows < 2 || slices.rows == 0)
		return;
	long nobs = scene.rows - 1;
	ENSURE(strcmp(str(&scene, 0, "body"), "robot") == 0);
	Body R = { num(&scene, 0, "a"), num(&scene, 0, "b"), num(&scene, 0, "eps"), 0, 0, 0 };
	Body *O = malloc(sizeof *O * (size_t)nobs);
	for (long j = 0; j < nobs; ++j) {
		O[j].a = num(&scene, j + 1, "a");
		O[j].b = num(&scene, j + 1, "b");
		O[j].eps = num(&scene, j + 1, "eps");
		O[j].cx = num(&scene, j + 1, "cx");
		O[j].cy = num(&scene, j + 1, "cy");
		O[j].angle = num(&scene, j + 1, "angle");
		/* The draws: a, b in (0, 10], eps in [1e-6, 2 - 1e-6], centres in
		 * [-200, 200), angles in [0, pi). */
		ENSURE(O[j].a > 0 && O[j].a <= 10 && O[j].b > 0 && O[j].b <= 10);
		ENSURE(O[j].eps >= 1e-6 && O[j].eps <= 2.0 - 1e-6);
		ENSURE(fabs(O[j].cx) <= 200 && fabs(O[j].cy) <= 200 && O[j].angle >= 0 && O[j].angle < MK_PI);
	}
	/* Gauges of outline points: positions near 200 carry rounding of a few
	 * 1e-14; divided by semi-axes that may be small (an obstacle's a can
	 * be 0.1), 1e-9 is a wide margin. */
	double worst = 0.0;
	for (long k = 0; k < obst.rows; ++k) {
		long j = (long)num(&obst, k, "obstacle");
		ENSURE(j >= 0 && j < nobs);
		if (j >= 0 && j < nobs)
			worst = fmax(worst, fabs(gauge(&O[j], num(&obst, k, "x"), num(&obst, k, "y")) - 1.0));
	}
	printf("obstacle outlines: |g - 1| %.3g\n", worst);
	ENSURE(worst <= 1e-9);
	worst = 0.0;
	for (long k = 0; k < robot.rows; ++k) {
		Body Rh = R;
		Rh.angle = num(&robot, k, "heading");
		worst = fmax(worst, fabs(gauge(&Rh, num(&robot, k, "x"), num(&robot, k, "y")) - 1.0));
	}
	ENSURE(worst <= 1e-9);
	/* Every C-obstacle point on the boundary of O (+) (-R): the gap is never
	 * negative and reaches 0. Both are sums of support values of size up
	 * to ~300 evaluated in double, a few 1e-13; 1e-8 is the bound. */
	double lowest = INFINITY, largest_min = 0.0;
	for (long k = 0; k < slices.rows; ++k) {
		long j = (long)num(&slices, k, "obstacle");
		if (j < 0 || j >= nobs)
			continue;
		Body Rh = R;
		Rh.angle = num(&slices, k, "heading");
		double neg;
		double m = minGap(&O[j], &Rh, num(&slices, k, "x"), num(&slices, k, "y"), &neg);
		lowest = fmin(lowest, neg);
		largest_min = fmax(largest_min, m);
	}
	printf("%ld C-obstacle points: most negative gap %.3g, largest minimum gap %.3g\n",
		slices.rows, lowest, largest_min);
	ENSURE(lowest >= -1e-8);
	ENSURE(largest_min <= 1e-8);
	free(O);
	mkTable_Free(&scene);
	mkTable_Free(&obst);
	mkTable_Free(&robot);
	mkTable_Free(&slices);
}

int main(int argc, char **argv)
{
	if (argc != 3) {
		fprintf(stderr, "usage: test_cobstacle <result CSV> <expected rows>\n");
		return 2;
	}
	const char *path = argv[1];
	checkRows(path, strtol(argv[2], NULL, 10));
	size_t n = strlen(path);
	char dir[4096];
	snprintf(dir, sizeof dir, "%.*s", (int)(n > 4 ? n - 4 : n), path);
	checkFigure(dir);
	return mk_summary("cobstacle");
}
