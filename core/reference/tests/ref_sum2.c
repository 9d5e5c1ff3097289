/* ref_sum2.c - the 2D closed forms against the 256-bit MPFR reference, in
 * every kernel, both forms, both parameterisations and both sets (the checks
 * and their tolerances are in refcheck.c).
 *
 * Cases:
 *  - the paper's validation draws (Sec. 6.1): 100 trials, a, b ~ U(0, 10),
 *    eps ~ U(0.1, 1.9), M = rot(2 pi U) shear(U(-2, 2)) for both bodies; we
 *    also place both bodies at t ~ U(-10, 10)^2 (the paper centres them), and
 *    take 32 of the paper's angles per trial instead of 1000;
 *  - extremes: every pair of exponents from {1e-3, 0.01, 0.5, 1, 1.5, 1.99,
 *    2 - 1e-3}, each with three poses (mild; semi-axis ratio 1e4 with shear
 *    +-10; ratio 1e4 with shear -10 and 2.5), at angles on the axes, 1e-8 and
 *    1e-4 off them, on the diagonals, at the world normals of the bodies'
 *    faces (exactly and turned by 1e-13 and 1e-9 rad) and at random;
 *  - the extremes' cases again at the ends of the exponent range, every
 *    pair from {1e-6, 1e-5, 1e-4, 1, 2 - 1e-4, 2 - 1e-5, 2 - 1e-6} (group 4);
 *  - parameter vectors that are not unit vectors (scaled by 3, 1e-5, 1e5,
 *    1e-150, 1e150, 1e-300, 1e300), which sum.h accepts.
 * Usage: ref_sumN [group [tier [all]]]: group 1-4 in the order above, the
 * parameter vectors being 3 (0: all); tier "double" (default), "f32" or
 * "f32io" (the f32 tier through the float-array entry points, on the
 * parameter vectors rounded to float; group 3 then scales them by 3, 1e-5,
 * 1e5, 1e-15, 1e15, 1e-30 and 1e30, the float range);
 * "all" evaluates the conditioning of every point of group 4 as well. */
#include "refcheck.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The precision tier under test: double unless the second argument names
 * another ("f32": the single-precision tier against its stated accuracy). */
static mkPrecision tier = MK_PRECISION_DOUBLE;
static int floatio = 0; /* "f32io" */


static mkBody2 body(double a, double b, double eps, double angle, double shear, double tx, double ty)
{
	mkShape2 s = { a, b, eps };
	mkMat2 M = mkMat2_Mul(mkMat2_Rotation(angle), mkMat2_Shear(shear));
	mkVec2 t = { tx, ty };
	mkBody2 B = mkBody2_Make(s, M, t);
	char msg[256];
	int valid = mkBody2_IsValid(B, "body", msg, sizeof msg);
	if (!valid)
		fprintf(stderr, "%s\n", msg);
	ENSURE(valid);
	return B;
}

static void validationDraws(void)
{
	refGroup g = { .name = "ref_sum2 validation", .precision = tier, .floatio = floatio };
	refRng rng = { 6101u };
	enum { N = 32 };
	double ux[N], uy[N];
	ENSURE(mkSample2_Angles(N, ux, uy) == MK_OK);
	for (int trial = 0; trial < 100; ++trial) {
		refCase c = { .dim = 2, .n = N, .ux = ux, .uy = uy };
		for (int k = 0; k < 2; ++k) {
			double a = refRng_Uniform(&rng, 0.0, 10.0);
			double b = refRng_Uniform(&rng, 0.0, 10.0);
			double e = refRng_Uniform(&rng, 0.1, 1.9);
			double ang = 2.0 * REF_PI * refRng_Uniform(&rng, 0.0, 1.0);
			double s = refRng_Uniform(&rng, -2.0, 2.0);
			double tx = refRng_Uniform(&rng, -10.0, 10.0);
			double ty = refRng_Uniform(&rng, -10.0, 10.0);
			mkBody2 B = body(a, b, e, ang, s, tx, ty);
			if (k == 0)
				c.a2 = B;
			else
				c.b2 = B;
		}
		refCheck_Case(&c, &g);
	}
	refGroup_Print(&g);
}

/* The unit world normal of the face of B that faces canonical axis `axis`
 * (the direction M^-T e_axis), turned by `turn` radians. */
static void faceNormal(mkBody2 B, int axis, double turn, double *ux, double *uy)
{
	mkMat2 Mi = mkMat2_Inverse(B.M);
	double x = Mi.m[axis][0], y = Mi.m[axis][1]; /* row of M^-1 = column of M^-T */
	double r = sqrt(x * x + y * y), c = cos(turn), s = sin(turn);
	*ux = (c * x - s * y) / r;
	*uy = (s * x + c * y) / r;
}

/* E: seven exponents, every pair of which is tried; all: evaluate the
 * conditioning of every point (for the statistics; costly in MPFR). */
static void extremes(const double *E, const char *name, uint64_t seed, int all)
{
	refGroup g = { .name = name, .precision = tier, .floatio = floatio, .conditionAll = all };
	refRng rng = { seed };
	enum { N = 20 };
	double ux[N], uy[N];
	for (int i = 0; i < 7; ++i)
		for (int j = 0; j < 7; ++j)
			for (int v = 0; v < 3; ++v) {
				double r1 = refRng_Uniform(&rng, 0.0, 2.0 * REF_PI);
				double r2 = refRng_Uniform(&rng, 0.0, 2.0 * REF_PI);
				refCase c = { .dim = 2, .n = N, .ux = ux, .uy = uy };
				if (v == 0) {
					c.a2 = body(1.0, 1.0, E[i], 0.0, 0.0, 0.0, 0.0);
					c.b2 = body(2.0, 0.5, E[j], REF_PI / 5, 0.0, 1.0, -2.0);
				} else if (v == 1) {
					c.a2 = body(1e4, 1.0, E[i], r1, 10.0, 3.0, 4.0);
					c.b2 = body(1.0, 1e4, E[j], r2, -10.0, -5.0, 2.0);
				} else {
					c.a2 = body(1e2, 1e-2, E[i], 0.0, -10.0, 0.0, 0.0);
					c.b2 = body(5.0, 5e-4, E[j], r2, 2.5, 7.0, 7.0);
				}
				int m = 0;
				/* B1's parameter on its axes, 1e-8 and 1e-4 off them */
				for (int k = 0; k < 4; ++k) {
					const double off[3] = { 0.0, 1e-8, -1e-4 };
					for (int o = 0; o < 3; ++o) {
						double t = k * REF_PI / 2.0 + off[o];
						ux[m] = cos(t);
						uy[m] = sin(t);
						++m;
					}
				}
				ux[m] = cos(REF_PI / 4);
				uy[m] = sin(REF_PI / 4);
				++m;
				ux[m] = cos(3 * REF_PI / 4 + 1e-3);
				uy[m] = sin(3 * REF_PI / 4 + 1e-3);
				++m;
				/* world normals at and next to the faces of both bodies, where
				 * the support point jumps as eps -> 0 (normal parameters) */
				faceNormal(c.b2, 0, 0.0, &ux[m], &uy[m]);
				++m;
				faceNormal(c.b2, 1, 1e-13, &ux[m], &uy[m]);
				++m;
				faceNormal(c.b2, 0, -1e-9, &ux[m], &uy[m]);
				++m;
				faceNormal(c.a2, 1, 0.0, &ux[m], &uy[m]);
				++m;
				faceNormal(c.a2, 0, 1e-13, &ux[m], &uy[m]);
				++m;
				double t = refRng_Uniform(&rng, -REF_PI, REF_PI);
				ux[m] = cos(t);
				uy[m] = sin(t);
				++m;
				ENSURE(m == N);
				refCheck_Case(&c, &g);
			}
	refGroup_Print(&g);
}

/* Parameter vectors of any length: sum.h takes any nonzero vector and uses
 * only its direction. The validation draws' angles (unit vectors in the
 * reference) are handed to the core scaled by 3, 1e-5, 1e5, 1e-150, 1e150,
 * 1e-300 and 1e300 (where the squared length leaves the double range); the
 * MPFR reference normalises the same scaled doubles. */
static void scaledParameters(void)
{
	static const double scale_d[] = { 3.0, 1e-5, 1e5, 1e-150, 1e150, 1e-300, 1e300 };
	static const double scale_f[] = { 3.0, 1e-5, 1e5, 1e-15, 1e15, 1e-30, 1e30 };
	const double *scale = floatio ? scale_f : scale_d;
	refGroup g = { .name = "ref_sum2 scaled-u", .precision = tier, .floatio = floatio };
	refRng rng = { 6103u };
	enum { N = 16 };
	double ux0[N], uy0[N], ux[N], uy[N];
	ENSURE(mkSample2_Angles(N, ux0, uy0) == MK_OK);
	for (int trial = 0; trial < 10; ++trial) {
		refCase c = { .dim = 2, .n = N, .ux = ux, .uy = uy };
		for (int j = 0; j < N; ++j) {
			double k = scale[(j + trial) % 7];
			ux[j] = ux0[j] * k;
			uy[j] = uy0[j] * k;
		}
		for (int k = 0; k < 2; ++k) {
			mkBody2 B = body(refRng_Uniform(&rng, 0.5, 10.0), refRng_Uniform(&rng, 0.5, 10.0),
				refRng_Uniform(&rng, 0.1, 1.9), 2.0 * REF_PI * refRng_Uniform(&rng, 0.0, 1.0),
				refRng_Uniform(&rng, -2.0, 2.0), refRng_Uniform(&rng, -10.0, 10.0), refRng_Uniform(&rng, -10.0, 10.0));
			if (k == 0)
				c.a2 = B;
			else
				c.b2 = B;
		}
		refCheck_Case(&c, &g);
	}
	refGroup_Print(&g);
}

int main(int argc, char **argv)
{
	static const refSumTests t = { "ref_sum2", 6100u, validationDraws, extremes, scaledParameters };
	return refSum_Main(argc, argv, &t, &tier, &floatio);
}
