/* test_collide.c - the collision queries of mink/collide.h on hand-worked
 * configurations whose answer is known in closed form, and on random pairs
 * of the paper's draw against the referee. */
#include <mink/collide.h>

#include "ensure.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>


static mkBody3 mkPlace(double a, double b, double c, double e1, double e2, mkMat3 R, mkVec3 t)
{
	mkShape3 s = { a, b, c, e1, e2 };
	return mkBody3_Make(s, R, t);
}

static mkVec3 mkMul(mkMat3 R, mkVec3 v) { return mkMat3_MulVec(R, v); }

/* The verdicts of every query on one pair; `gjk` 0 leaves GJK out (its
 * polytope is inscribed, so it needs a wider margin than the smooth
 * queries); ASC runs on ellipsoid pairs. */
static void mkCheckAll(const char *what, mkBody3 b1, mkBody3 b2, int expect, int gjk, int residuals)
{
	mkCollide r = mkCollide_RayLm(b1, b2, MK_COLLIDE_LM_MAX_ITER);
	mkCollide n = mkCollide_NormalLm(b1, b2, MK_COLLIDE_LM_MAX_ITER);
	mkCollide c = mkCollide_CommonNormal(b1, b2, MK_COLLIDE_LM_MAX_ITER);
	mkCollide i = mkCollide_Implicit(b1, b2, 1e-10);
	int before = mk_failures;
	ENSURE(r.collide == expect);
	ENSURE(n.collide == expect);
	ENSURE(c.collide == expect);
	ENSURE(i.collide == expect);
	/* The paper's success criterion, where the solution is a regular
	 * point of the angle parameterisation (see the superquadric cases). */
	if (residuals) {
		ENSURE_LE(r.residual, MK_COLLIDE_SUCCESS_RESIDUAL);
		ENSURE_LE(n.residual, MK_COLLIDE_SUCCESS_RESIDUAL);
		ENSURE_LE(c.residual, MK_COLLIDE_SUCCESS_RESIDUAL);
	}
	double g = mkCollide_Referee(b1, b2, 24, NULL);
	ENSURE((g >= 0.0) == (expect == 1));
	if (gjk) {
		double ux[100], uy[100], uz[100], x1[100], y1[100], z1[100], x2[100], y2[100], z2[100];
		ENSURE(mkCollide_GridVertices(b1, 10, ux, uy, uz, x1, y1, z1) == MK_OK);
		ENSURE(mkCollide_GridVertices(b2, 10, ux, uy, uz, x2, y2, z2) == MK_OK);
		mkVertices3 v1 = { x1, y1, z1, 100 }, v2 = { x2, y2, z2, 100 };
		ENSURE(mkCollide_GJK(v1, v2, 100).collide == expect);
	}
	if (mkShape3_IsEllipsoid(b1.shape) && mkShape3_IsEllipsoid(b2.shape))
		ENSURE(mkCollide_ASC(b1, b2).collide == expect);
	if (mk_failures != before)
		fprintf(stderr, "  in case: %s (expect %d; ray %d normal %d common %d implicit %d referee %.3g)\n",
			what, expect, r.collide, n.collide, c.collide, i.collide, g);
}

/* A rotation that is no symmetry of the cases below. */
static mkMat3 mkTilt(void)
{
	int ok = 0;
	mkMat3 R = mkMat3_FromQuat(0.8, 0.3, -0.4, 0.33);
	ok = mkMat3_IsFinite(R);
	ENSURE(ok);
	return R;
}

/* Two spheres of radii 2 and 1.5 touch at |d| = 3.5; along a general
 * direction. MinkSum (Ray)'s contact-space point of two spheres lies on
 * the sphere of radius r1 + r2 about c1 at every parameter, so its
 * distance from c1 is 3.5 up to rounding (a few ulps of 3.5, checked at
 * 1e-12). */
static void mkTestSpheres(void)
{
	mkMat3 I = mkMat3_Identity(), R = mkTilt();
	mkVec3 dir = { 1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0 };
	mkVec3 c1 = { 0.7, -1.2, 0.4 };
	/* margins: 0.05 for the smooth queries; 0.5 for GJK, whose 10 x 10
	 * grid polytope of a sphere of radius r reaches r cos(20.6 deg) = 0.936 r
	 * in every direction (grid steps 20 deg in eta, 36 deg in omega), so
	 * two of them overlap whenever |d| <= 0.936 * 3.5 = 3.28. */
	const double dd[] = { 3.45, 3.55, 3.0, 4.0 };
	const int expect[] = { 1, 0, 1, 0 }, gjk[] = { 0, 1, 1, 1 };
	for (int k = 0; k < 4; ++k) {
		mkVec3 c2 = { c1.x + dd[k] * dir.x, c1.y + dd[k] * dir.y, c1.z + dd[k] * dir.z };
		mkBody3 b1 = mkPlace(2, 2, 2, 1, 1, R, c1), b2 = mkPlace(1.5, 1.5, 1.5, 1, 1, I, c2);
		char what[64];
		snprintf(what, sizeof what, "spheres |d| = %.2f", dd[k]);
		mkCheckAll(what, b1, b2, expect[k], gjk[k], 1);
		mkCollide r = mkCollide_RayLm(b1, b2, MK_COLLIDE_LM_MAX_ITER);
		mkVec3 x = { r.x.x - c1.x, r.x.y - c1.y, r.x.z - c1.z };
		ENSURE_NEAR(sqrt(x.x * x.x + x.y * x.y + x.z * x.z), 3.5, 1e-12);
		/* the referee's min g is -(|d| - 3.5) for spheres: distance or depth */
		ENSURE_NEAR(mkCollide_Referee(b1, b2, 24, NULL), 3.5 - dd[k], 1e-9);
	}
}

/* Two bodies of shapes a1 and a2 (a, b, c, eps1, eps2) turned alike (the
 * identity, then the tilt), B2's centre at c1 + Q (d dir) for each offset d:
 * every query's verdict against expect (mkCheckAll's gjk and residuals
 * flags), the referee's signed gap against touch - d. */
static void mkCheckOffsets(const char *name, const double *a1, const double *a2, mkVec3 c1, mkVec3 dir,
	const double *dd, const int *expect, int count, double touch, int gjk, int residuals)
{
	mkMat3 R = mkTilt();
	for (int k = 0; k < count; ++k) {
		for (int rot = 0; rot < 2; ++rot) {
			mkMat3 Q = rot ? R : mkMat3_Identity();
			mkVec3 o = mkMul(Q, mkVec3_Scale(dir, dd[k]));
			mkVec3 c2 = { c1.x + o.x, c1.y + o.y, c1.z + o.z };
			mkBody3 b1 = mkPlace(a1[0], a1[1], a1[2], a1[3], a1[4], Q, c1);
			mkBody3 b2 = mkPlace(a2[0], a2[1], a2[2], a2[3], a2[4], Q, c2);
			char what[64];
			snprintf(what, sizeof what, "%s |d| = %.3f rot %d", name, dd[k], rot);
			mkCheckAll(what, b1, b2, expect[k], gjk, residuals);
			ENSURE_NEAR(mkCollide_Referee(b1, b2, 24, NULL), touch - dd[k], 1e-9);
		}
	}
}

/* Axis-aligned ellipsoids (3,2,1) and (2,1,1.5) along the x axis touch at
 * |d| = 3 + 2 = 5 (the extreme points (3,0,0) and (-2,0,0)); the whole
 * configuration is then rotated, which changes no answer. */
static void mkTestEllipsoids(void)
{
	/* 0.01 from touching: beyond Implicit's distance threshold 1e-3 */
	const double dd[] = { 4.95, 5.05, 4.99, 5.01 };
	const int expect[] = { 1, 0, 1, 0 };
	const double a1[5] = { 3, 2, 1, 1, 1 }, a2[5] = { 2, 1, 1.5, 1, 1 };
	/* GJK: (3,0,0) is no grid vertex; its polytope is checked on the spheres
	 * and in the random test. */
	mkCheckOffsets("ellipsoids", a1, a2, (mkVec3){ 1.0, 2.0, -1.0 }, (mkVec3){ 1, 0, 0 }, dd, expect, 4, 5.0, 0, 1);
}

/* Superquadrics eps = (0.5, 1.5) and (1.2, 0.3), stacked along z: the top
 * of B1 is (0,0,c1) and the bottom of B2 is t2 - (0,0,c2), both extreme in
 * z, so they touch at |d| = c1 + c2 = 3.5. The poles are vertices of the
 * 10 x 10 grid, so GJK is exact here too. The solutions sit at the
 * poles of the angle parameterisation, where omega is undefined and the
 * Jacobian is singular: the verdicts are right but LM converges only
 * linearly there, so no residual is asserted (the next case asserts it at
 * a regular point). */
static void mkTestSuperquadrics(void)
{
	const double dd[] = { 3.45, 3.55 };
	const int expect[] = { 1, 0 };
	const double a1[5] = { 2, 3, 1.5, 0.5, 1.5 }, a2[5] = { 1, 1.3, 2, 1.2, 0.3 };
	mkCheckOffsets("superquadrics", a1, a2, (mkVec3){ -0.5, 0.3, 0.2 }, (mkVec3){ 0, 0, 1 }, dd, expect, 2, 3.5, 1, 0);
}

/* A superquadric and a sphere of radius r at a regular point p = f1(u) of
 * the superquadric: with c2 = p + (r + s) n(p), n the outward unit normal,
 * the closest point of B1 to c2 is p (the normal line of a convex body),
 * so the bodies are separated by s > 0 and overlap for s < 0; the referee's
 * min g is -s. */
static void mkTestSuperquadricSphere(void)
{
	mkMat3 R = mkTilt();
	mkVec3 c1 = { 0.3, -0.2, 1.1 };
	mkBody3 b1 = mkPlace(3, 2, 1.5, 0.6, 1.4, R, c1);
	mkVec3 u = mkCollide_AnglesToUnit(0.4, 2.1);
	mkVec3 p = mkBody3_Point(b1, u);
	mkVec3 g = mkMat3_MulTVec(mkMat3_Inverse(R), mkShape3_PointGradient(b1.shape, u));
	double gn = sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
	const double r = 1.5, sd[] = { 0.05, -0.05 };
	for (int k = 0; k < 2; ++k) {
		double L = (r + sd[k]) / gn;
		mkVec3 c2 = { p.x + L * g.x, p.y + L * g.y, p.z + L * g.z };
		mkBody3 b2 = mkPlace(r, r, r, 1, 1, mkMat3_Identity(), c2);
		char what[64];
		snprintf(what, sizeof what, "superquadric-sphere s = %.2f", sd[k]);
		mkCheckAll(what, b1, b2, sd[k] < 0.0, 0, 1);
		ENSURE_NEAR(mkCollide_Referee(b1, b2, 24, NULL), -sd[k], 1e-9);
	}
}

/* ASC alone on hand cases: unit spheres d apart (roots real, positive and
 * distinct iff d > 2), and a pair whose second pose differs from the first
 * only by a translation (the reference code builds both poses from body
 * 1, which would call every such pair overlapping). */
static void mkTestAsc(void)
{
	mkMat3 I = mkMat3_Identity(), R = mkTilt();
	mkVec3 o = { 0, 0, 0 };
	const double d[] = { 1.0, 1.9, 2.01, 3.0, 10.0 };
	for (int k = 0; k < 5; ++k) {
		mkVec3 c = { d[k], 0, 0 };
		mkCollide a = mkCollide_ASC(mkPlace(1, 1, 1, 1, 1, I, o), mkPlace(1, 1, 1, 1, 1, I, c));
		ENSURE(a.collide == (d[k] <= 2.0));
		ENSURE(a.status == (d[k] > 2.0 ? 2 : 0));
		if (d[k] > 2.0) {
			/* roots of l^2 - (d^2 - 2) l + 1: gap / larger root */
			double s = d[k] * d[k] - 2.0, disc = sqrt(s * s - 4.0);
			ENSURE_NEAR(a.residual, 2.0 * disc / (s + disc), 1e-9);
		}
	}
	mkVec3 far = { 20, 0, 0 };
	ENSURE(mkCollide_ASC(mkPlace(3, 2, 1, 1, 1, R, o), mkPlace(3, 2, 1, 1, 1, R, far)).collide == 0);
	/* Not ellipsoids: no answer. */
	ENSURE(mkCollide_ASC(mkPlace(3, 2, 1, 0.5, 1, R, o), mkPlace(3, 2, 1, 1, 1, R, far)).collide == -1);
}

/* ---- random pairs of the paper's draw --------------------------------- */

static uint64_t mk_state = 0x9E3779B97F4A7C15ull;

static double mkU(double a, double b)
{
	/* xorshift64*: enough for drawing test cases */
	mk_state ^= mk_state >> 12;
	mk_state ^= mk_state << 25;
	mk_state ^= mk_state >> 27;
	uint64_t r = mk_state * 2685821657736338717ull;
	return a + (b - a) * (double)(r >> 11) * 0x1.0p-53;
}

static mkBody3 mkDraw(double amax, double clo, double chi, int ellipsoid)
{
	double a = mkU(1, amax), b = mkU(1, amax), c = mkU(1, amax);
	double e1 = ellipsoid ? 1.0 : mkU(0.1, 1.9), e2 = ellipsoid ? 1.0 : mkU(0.1, 1.9);
	mkVec3 t = { mkU(clo, chi), mkU(clo, chi), mkU(clo, chi) };
	mkMat3 R = mkMat3_FromQuat(mkU(0, 1), mkU(0, 1), mkU(0, 1), mkU(0, 1));
	ENSURE(mkMat3_IsFinite(R));
	return mkPlace(a, b, c, e1, e2, R, t);
}

/* Agreement with the referee on `count` random pairs of the paper's draw,
 * outside the margin |min g| <= 1e-3 (the Implicit query's own distance
 * threshold; the referee's min g is accurate to about 1e-9, see the hand
 * cases). The rates asserted are those measured on this test's fixed draw
 * at the time of writing, rounded down, so that a regression shows. */
static void mkTestRandom(int ellipsoid, int count, int count_implicit, const double *want)
{
	int n = 0, n_implicit = 0, agree[6] = { 0 };
	for (int k = 0; k < count; ++k) {
		mkBody3 b1 = mkDraw(11, -5, 5, ellipsoid), b2 = mkDraw(6, 5, 15, ellipsoid);
		double g = mkCollide_Referee(b1, b2, 24, NULL);
		if (fabs(g) <= 1e-3)
			continue;
		int truth = g >= 0.0;
		n += 1;
		double ux[100], uy[100], uz[100], x1[100], y1[100], z1[100], x2[100], y2[100], z2[100];
		mkCollide_GridVertices(b1, 10, ux, uy, uz, x1, y1, z1);
		mkCollide_GridVertices(b2, 10, ux, uy, uz, x2, y2, z2);
		mkVertices3 v1 = { x1, y1, z1, 100 }, v2 = { x2, y2, z2, 100 };
		int v[6] = {
			mkCollide_RayLm(b1, b2, MK_COLLIDE_LM_MAX_ITER).collide,
			mkCollide_NormalLm(b1, b2, MK_COLLIDE_LM_MAX_ITER).collide,
			mkCollide_CommonNormal(b1, b2, MK_COLLIDE_LM_MAX_ITER).collide,
			k < count_implicit ? mkCollide_Implicit(b1, b2, 1e-10).collide : truth,
			mkCollide_GJK(v1, v2, 100).collide,
			ellipsoid ? mkCollide_ASC(b1, b2).collide : truth,
		};
		n_implicit += k < count_implicit;
		for (int j = 0; j < 6; ++j)
			agree[j] += v[j] == truth && (j != 3 || k < count_implicit);
	}
	static const char *const names[] = { "MinkSum (Ray)", "MinkSum (Normal)", "Common Normal", "Implicit", "GJK", "ASC" };
	printf("random %s: %d pairs outside the margin\n", ellipsoid ? "ellipsoids" : "superquadrics", n);
	for (int j = 0; j < (ellipsoid ? 6 : 5); ++j) {
		int of = j == 3 ? n_implicit : n;
		double rate = of ? (double)agree[j] / of : NAN;
		printf("  %-17s agreement %.4f\n", names[j], rate);
		ENSURE_LE(want[j], rate);
	}
}

int main(void)
{
	mkTestSpheres();
	mkTestEllipsoids();
	mkTestSuperquadrics();
	mkTestSuperquadricSphere();
	mkTestAsc();
	/* Measured: ellipsoids 1, 1, 1, 59/60, 298/300, 1; superquadrics 1,
	 * 298/300, 299/300, 15/15, 299/300 (order: Ray, Normal, Common Normal,
	 * Implicit, GJK, ASC). The draw is fixed, so these are exact; the
	 * bounds are those rates rounded down to two digits. */
	const double want_e[6] = { 1.0, 1.0, 1.0, 0.98, 0.99, 1.0 }, want_s[6] = { 1.0, 0.99, 0.99, 1.0, 0.99, 0 };
	/* Implicit (about 20 ms per ellipsoid pair and 180 ms per superquadric
	 * pair) runs on the first pairs only, to keep the test within seconds. */
	mkTestRandom(1, 300, 60, want_e);
	mkTestRandom(0, 300, 15, want_s);
	return mk_summary("test_collide");
}
