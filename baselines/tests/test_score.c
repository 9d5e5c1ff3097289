/* test_score.c - mink/score.h on cases worked by hand:
 *  - a regular n-gon inscribed in the circle K = B1 (+) (-B2) of two discs
 *    (radii 2 and 1, R = 3, centred at t1): Hausdorff = gap_in =
 *    R (1 - cos(pi/n)), gap_out = 0 (points on the circle), area error
 *    (n/2) sin(2 pi/n) / pi - 1; inside, not enclosing; the worst direction
 *    bisects two vertices;
 *  - the square circumscribing that circle: Hausdorff = gap_out =
 *    R (sqrt 2 - 1) at a corner, gap_in = 0: encloses, not inside;
 *  - a box against a sphere: the cube inscribed in the ball K of two balls
 *    (radii 1.5 and 1, R = 2.5): Hausdorff = R (1 - 1/sqrt 3) along an axis,
 *    volume error (2s)^3 / (4/3 pi R^3) - 1, s = R / sqrt 3; and the cube
 *    [-R, R]^3 around it: Hausdorff = R (sqrt 3 - 1) at a corner.
 * The support scan agrees with the measure's Hausdorff. */
#include <math.h>
#include <stdio.h>

#include <mink/score.h>

#include "ensure.h"

static const double pi = 3.14159265358979323846;

static mkBody2 disc(double r, double tx, double ty)
{
	return mkBody2_Make((mkShape2){r, r, 1.0}, mkMat2_Identity(), (mkVec2){tx, ty});
}

static mkBody3 ball(double r, double tx, double ty, double tz)
{
	return mkBody3_Make((mkShape3){r, r, r, 1.0, 1.0}, mkMat3_Identity(), (mkVec3){tx, ty, tz});
}

static void polygon(void)
{
	const double R = 3.0, tx = 0.7, ty = -1.2;
	mkBody2 b1 = disc(2.0, tx, ty), b2 = disc(1.0, 5.0, 4.0); /* b2's translation drops out */
	mkPointSet pts = {0};
	for (int n = 3; n <= 96; n = n * 2 + 1) {
		ENSURE(mkPointSet_Resize(&pts, 2, n) == MK_OK);
		for (int k = 0; k < n; ++k) {
			pts.x[k] = tx + R * cos(2 * pi * k / n);
			pts.y[k] = ty + R * sin(2 * pi * k / n);
		}
		mkScore s;
		ENSURE(mkScore2_Points(b1, b2, MK_SET_CONTACT, &pts, NULL, &s) == MK_OK);
		double want = R * (1 - cos(pi / n)), tol = 1e-12 * R;
		ENSURE_NEAR(s.dev.hausdorff_abs, want, tol);
		ENSURE_NEAR(s.dev.gap_in, want, tol);
		ENSURE_LE(fabs(s.dev.gap_out), tol);
		ENSURE_LE(s.dev.off_boundary_max, tol);
		ENSURE_NEAR(s.dev.area_rel, n / 2.0 * sin(2 * pi / n) / pi - 1, 1e-9);
		ENSURE(s.inside && !s.encloses);
		/* The scan's worst direction bisects two vertices (angle pi/n mod 2 pi/n). */
		double a = atan2(s.worst_dir[1], s.worst_dir[0]), m = fmod(a + 2 * pi, 2 * pi / n);
		ENSURE_NEAR(m, pi / n, 2 * pi / MK_SCORE2_DIRECTIONS);
		ENSURE_LE(s.support_gap, s.dev.hausdorff_abs + s.allowance);
		ENSURE_NEAR(s.support_gap, want, R * (1 - cos(pi / MK_SCORE2_DIRECTIONS)) + tol);
		ENSURE(s.worst_signed < 0);
		printf("%3d-gon: hausdorff %.17g (hand %.17g), scan %.17g\n", n, s.dev.hausdorff_abs, want, s.support_gap);
	}
	/* The circumscribed square. */
	ENSURE(mkPointSet_Resize(&pts, 2, 4) == MK_OK);
	for (int k = 0; k < 4; ++k) {
		pts.x[k] = tx + ((k == 0 || k == 3) ? R : -R);
		pts.y[k] = ty + (k < 2 ? R : -R);
	}
	mkScore s;
	ENSURE(mkScore2_Points(b1, b2, MK_SET_CONTACT, &pts, NULL, &s) == MK_OK);
	ENSURE_NEAR(s.dev.hausdorff_abs, R * (sqrt(2.0) - 1), 1e-12 * R);
	ENSURE_NEAR(s.dev.gap_out, R * (sqrt(2.0) - 1), 1e-12 * R);
	ENSURE_NEAR(s.dev.area_rel, 4 / pi - 1, 1e-9);
	ENSURE(s.encloses && !s.inside);
	ENSURE_NEAR(s.support_gap, R * (sqrt(2.0) - 1), 1e-9 * R);
	ENSURE(s.worst_signed > 0);
	mkPointSet_Free(&pts);
}

static void cube(double side, double R, double t[3], mkScore *s)
{
	mkPointSet pts = {0};
	ENSURE(mkPointSet_Resize(&pts, 3, 8) == MK_OK);
	for (int k = 0; k < 8; ++k) {
		pts.x[k] = t[0] + ((k & 1) ? side : -side);
		pts.y[k] = t[1] + ((k & 2) ? side : -side);
		pts.z[k] = t[2] + ((k & 4) ? side : -side);
	}
	mkBody3 b1 = ball(1.5, t[0], t[1], t[2]), b2 = ball(R - 1.5, 0, 0, 0);
	ENSURE(mkScore3_Points(b1, b2, MK_SET_PLUS, &pts, NULL, s) == MK_OK);
	mkPointSet_Free(&pts);
}

static void box(void)
{
	const double R = 2.5, s3 = sqrt(3.0);
	double t[3] = {0.25, -0.5, 1.0};
	mkScore s;
	cube(R / s3, R, t, &s); /* inscribed */
	ENSURE_NEAR(s.dev.hausdorff_abs, R * (1 - 1 / s3), 1e-9 * R);
	ENSURE_LE(fabs(s.dev.gap_out), 1e-12 * R);
	double vol = pow(2 * R / s3, 3), ball_vol = 4.0 / 3.0 * pi * R * R * R;
	ENSURE_NEAR(s.dev.area_rel, vol / ball_vol - 1, 1e-6);
	ENSURE(s.inside && !s.encloses);
	ENSURE_NEAR(s.support_gap, R * (1 - 1 / s3), 1e-9 * R); /* the grid holds the axes */
	printf("inscribed cube: hausdorff %.17g (hand %.17g), scan %.17g\n", s.dev.hausdorff_abs, R * (1 - 1 / s3),
		s.support_gap);
	cube(R, R, t, &s); /* circumscribed */
	ENSURE_NEAR(s.dev.hausdorff_abs, R * (s3 - 1), 1e-9 * R);
	ENSURE(s.encloses && !s.inside);
	ENSURE_NEAR(s.dev.area_rel, 8 / ball_vol * R * R * R - 1, 1e-6);
	printf("circumscribed cube: hausdorff %.17g (hand %.17g), scan %.17g\n", s.dev.hausdorff_abs, R * (s3 - 1),
		s.support_gap);
}

int main(void)
{
	polygon();
	box();
	mkPointSet pts = {0};
	mkScore s;
	ENSURE(mkScore2_Points(disc(1, 0, 0), disc(1, 0, 0), MK_SET_CONTACT, NULL, NULL, &s) == MK_ERR_ARGUMENT);
	ENSURE(mkScore2_Points(disc(1, 0, 0), disc(1, 0, 0), MK_SET_CONTACT, &pts, NULL, NULL) == MK_ERR_ARGUMENT);
	return mk_summary("test_score");
}
