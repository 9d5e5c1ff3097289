/* ref_sum3.c - the 3D closed forms against the 256-bit MPFR reference, in
 * every kernel, both forms, both parameterisations and both sets (the checks
 * and their tolerances are in refcheck.c).
 *
 * Cases:
 *  - the paper's validation draws (Sec. 6.1): 100 trials, B1 semi-axes
 *    ~ U(1, 10)^3, B2 ~ U(1, 6)^3, eps1, eps2 ~ U(0.1, 1.9), rotations from
 *    quaternions drawn in U(0, 1)^4 as the reference code does; we also place
 *    both bodies at t ~ U(-10, 10)^3, and take the 5 x 5 grid of the paper's
 *    sampling (poles included) instead of 50 x 50;
 *  - extremes: B1 takes every pair (eps1, eps2) from {1e-3, 0.01, 0.5, 1,
 *    1.5, 1.99, 2 - 1e-3}, B2 a shifted pair from the same list, each in two
 *    poses (mild; semi-axis ratio 1e4 with shears of 10 and rotations), at
 *    the poles exactly, 1e-8 and 1e-4 rad from them, on and near the axes,
 *    at the world normals of the bodies' faces (exactly and tilted by 1e-13
 *    and 1e-9) and at random;
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

/* Shear in 3D: [1 s 0; 0 1 s2; 0 0 1]. */

static mkMat3 shear3(double s, double s2)
{
	mkMat3 M = mkMat3_Identity();
	M.m[0][1] = s;
	M.m[1][2] = s2;
	return M;
}

static mkBody3 body(mkShape3 s, mkMat3 M, double tx, double ty, double tz)
{
	mkVec3 t = { tx, ty, tz };
	mkBody3 B = mkBody3_Make(s, M, t);
	char msg[256];
	int valid = mkBody3_IsValid(B, "body", msg, sizeof msg);
	if (!valid)
		fprintf(stderr, "%s\n", msg);
	ENSURE(valid);
	return B;
}

static mkMat3 quatRotation(refRng *rng)
{
	double q[4];
	for (int i = 0; i < 4; ++i)
		q[i] = refRng_Uniform(rng, 0.0, 1.0);
	int ok = 0;
	mkMat3 R = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
	ok = mkMat3_IsFinite(R);
	ENSURE(ok);
	return R;
}

static void validationDraws(void)
{
	refGroup g = { .name = "ref_sum3 validation", .precision = tier, .floatio = floatio };
	refRng rng = { 6201u };
	enum { G = 5, N = G * G };
	double ux[N], uy[N], uz[N];
	ENSURE(mkSample3_Grid(G, ux, uy, uz) == MK_OK);
	for (int trial = 0; trial < 100; ++trial) {
		refCase c = { .dim = 3, .n = N, .ux = ux, .uy = uy, .uz = uz };
		for (int k = 0; k < 2; ++k) {
			double hi = k == 0 ? 10.0 : 6.0;
			mkShape3 s;
			s.a = refRng_Uniform(&rng, 1.0, hi);
			s.b = refRng_Uniform(&rng, 1.0, hi);
			s.c = refRng_Uniform(&rng, 1.0, hi);
			s.eps1 = refRng_Uniform(&rng, 0.1, 1.9);
			s.eps2 = refRng_Uniform(&rng, 0.1, 1.9);
			mkMat3 R = quatRotation(&rng);
			double t[3];
			for (int i = 0; i < 3; ++i)
				t[i] = refRng_Uniform(&rng, -10.0, 10.0);
			mkBody3 B = body(s, R, t[0], t[1], t[2]);
			if (k == 0)
				c.a3 = B;
			else
				c.b3 = B;
		}
		refCheck_Case(&c, &g);
	}
	refGroup_Print(&g);
}

static void setUnit(double *ux, double *uy, double *uz, int m, double eta, double omega)
{
	ux[m] = cos(eta) * cos(omega);
	uy[m] = cos(eta) * sin(omega);
	uz[m] = sin(eta);
}

/* The unit world normal of the face of B that faces canonical axis `axis`
 * (M^-T e_axis), tilted by `tilt` radians towards the world axis `toward`. */
static void faceNormal(mkBody3 B, int axis, double tilt, int toward, double *ux, double *uy, double *uz)
{
	mkMat3 Mi = mkMat3_Inverse(B.M);
	double v[3] = { Mi.m[axis][0], Mi.m[axis][1], Mi.m[axis][2] }; /* row of M^-1 */
	double r = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	for (int i = 0; i < 3; ++i)
		v[i] /= r;
	v[toward] += tilt;
	r = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	*ux = v[0] / r;
	*uy = v[1] / r;
	*uz = v[2] / r;
}

/* E: seven exponents, every pair of which is tried; all: evaluate the
 * conditioning of every point (for the statistics; costly in MPFR). */
static void extremes(const double *E, const char *name, uint64_t seed, int all)
{
	refGroup g = { .name = name, .precision = tier, .floatio = floatio, .conditionAll = all };
	refRng rng = { seed };
	enum { N = 20 };
	double ux[N], uy[N], uz[N];
	const double h = REF_PI / 2;
	for (int i = 0; i < 7; ++i)
		for (int j = 0; j < 7; ++j)
			for (int v = 0; v < 2; ++v) {
				refCase c = { .dim = 3, .n = N, .ux = ux, .uy = uy, .uz = uz };
				mkShape3 s1 = { 1.0, 1.0, 1.0, E[i], E[j] };
				mkShape3 s2 = { 2.0, 0.5, 1.5, E[(i + 3) % 7], E[(j + 5) % 7] };
				if (v == 0) {
					c.a3 = body(s1, mkMat3_Identity(), 0.0, 0.0, 0.0);
					c.b3 = body(s2, quatRotation(&rng), 1.0, -2.0, 0.5);
				} else {
					s1.a = 1e4;
					s1.b = 1.0;
					s1.c = 30.0;
					s2.a = 1.0;
					s2.b = 1e2;
					s2.c = 1e-2;
					c.a3 = body(s1, mkMat3_Mul(quatRotation(&rng), shear3(10.0, 0.0)), 3.0, 4.0, -1.0);
					c.b3 = body(s2, mkMat3_Mul(quatRotation(&rng), shear3(-10.0, 10.0)), -5.0, 2.0, 8.0);
				}
				int m = 0;
				/* the poles exactly, and 1e-8, 1e-4 rad from them */
				ux[m] = 0.0; uy[m] = 0.0; uz[m] = 1.0; ++m;
				ux[m] = 0.0; uy[m] = 0.0; uz[m] = -1.0; ++m;
				setUnit(ux, uy, uz, m++, h - 1e-8, 0.3);
				setUnit(ux, uy, uz, m++, -h + 1e-8, 2.0);
				setUnit(ux, uy, uz, m++, h - 1e-4, -1.2);
				setUnit(ux, uy, uz, m++, -h + 1e-4, REF_PI / 4);
				/* on and near the axes of the equator */
				ux[m] = 1.0; uy[m] = 0.0; uz[m] = 0.0; ++m;
				ux[m] = 0.0; uy[m] = -1.0; uz[m] = 0.0; ++m;
				setUnit(ux, uy, uz, m++, 1e-8, 1e-8);
				setUnit(ux, uy, uz, m++, -1e-4, h + 1e-4);
				setUnit(ux, uy, uz, m++, 0.0, REF_PI / 4);
				setUnit(ux, uy, uz, m++, 0.6154797086703873, REF_PI / 4); /* the diagonal */
				/* world normals at and next to the faces of both bodies */
				faceNormal(c.b3, 0, 0.0, 0, &ux[m], &uy[m], &uz[m]);
				++m;
				faceNormal(c.b3, 1, 1e-13, 2, &ux[m], &uy[m], &uz[m]);
				++m;
				faceNormal(c.b3, 2, -1e-9, 0, &ux[m], &uy[m], &uz[m]);
				++m;
				faceNormal(c.a3, 2, 0.0, 0, &ux[m], &uy[m], &uz[m]);
				++m;
				faceNormal(c.a3, 0, 1e-13, 1, &ux[m], &uy[m], &uz[m]);
				++m;
				while (m < N) {
					double d[3], n2;
					do {
						n2 = 0.0;
						for (int k = 0; k < 3; ++k) {
							d[k] = refRng_Uniform(&rng, -1.0, 1.0);
							n2 += d[k] * d[k];
						}
					} while (n2 < 1e-2 || n2 > 1.0);
					ux[m] = d[0] / sqrt(n2);
					uy[m] = d[1] / sqrt(n2);
					uz[m] = d[2] / sqrt(n2);
					++m;
				}
				refCheck_Case(&c, &g);
			}
	refGroup_Print(&g);
}

/* Parameter vectors of any length: sum.h takes any nonzero vector and uses
 * only its direction. The grid's unit vectors are handed to the core scaled
 * by 3, 1e-5, 1e5, 1e-150, 1e150, 1e-300 and 1e300 (where the squared length
 * leaves the double range); the MPFR reference normalises the same scaled
 * doubles. */
static void scaledParameters(void)
{
	static const double scale_d[] = { 3.0, 1e-5, 1e5, 1e-150, 1e150, 1e-300, 1e300 };
	static const double scale_f[] = { 3.0, 1e-5, 1e5, 1e-15, 1e15, 1e-30, 1e30 };
	const double *scale = floatio ? scale_f : scale_d;
	refGroup g = { .name = "ref_sum3 scaled-u", .precision = tier, .floatio = floatio };
	refRng rng = { 6203u };
	enum { G = 4, N = G * G };
	double ux0[N], uy0[N], uz0[N], ux[N], uy[N], uz[N];
	ENSURE(mkSample3_Grid(G, ux0, uy0, uz0) == MK_OK);
	for (int trial = 0; trial < 10; ++trial) {
		refCase c = { .dim = 3, .n = N, .ux = ux, .uy = uy, .uz = uz };
		for (int j = 0; j < N; ++j) {
			double k = scale[(j + trial) % 7];
			ux[j] = ux0[j] * k;
			uy[j] = uy0[j] * k;
			uz[j] = uz0[j] * k;
		}
		for (int k = 0; k < 2; ++k) {
			mkShape3 s;
			s.a = refRng_Uniform(&rng, 1.0, 10.0);
			s.b = refRng_Uniform(&rng, 1.0, 10.0);
			s.c = refRng_Uniform(&rng, 1.0, 10.0);
			s.eps1 = refRng_Uniform(&rng, 0.1, 1.9);
			s.eps2 = refRng_Uniform(&rng, 0.1, 1.9);
			mkBody3 B = body(s, quatRotation(&rng), refRng_Uniform(&rng, -10.0, 10.0),
				refRng_Uniform(&rng, -10.0, 10.0), refRng_Uniform(&rng, -10.0, 10.0));
			if (k == 0)
				c.a3 = B;
			else
				c.b3 = B;
		}
		refCheck_Case(&c, &g);
	}
	refGroup_Print(&g);
}

int main(int argc, char **argv)
{
	static const refSumTests t = { "ref_sum3", 6200u, validationDraws, extremes, scaledParameters };
	return refSum_Main(argc, argv, &t, &tier, &floatio);
}
