/* ref_finite.c - not one NaN or Inf from the batch closed forms anywhere in
 * the extremes grid: every exponent (pair) from {1e-3, 0.01, 0.1, 0.5, 1,
 * 1.5, 1.9, 1.99, 2 - 1e-3}, semi-axis ratios up to 1e4, shears of
 * magnitude 10, every available kernel, both forms (normal and gradient),
 * both parameterisations and both sets, on the paper's full samplings
 * (1000 angles in 2D; the 50 x 50 grid with the poles in 3D) plus the world
 * normals of the faces of both bodies. Outputs and kissing points must be
 * finite. (Accuracy on these inputs is ref_sum2/ref_sum3's business.) */
#include "reftest.h"

#include <mink/mink.h>

#include <math.h>
#include <stdlib.h>

static const double E[] = { 1e-3, 0.01, 0.1, 0.5, 1.0, 1.5, 1.9, 1.99, 2.0 - 1e-3 };
#define NE 9
static const mkImpl implList[] = { MK_IMPL_SCALAR, MK_IMPL_AVX2, MK_IMPL_AVX512 };

static long evaluated, bad;

static void checkAll(int dim, const mkBody2 *p2, const mkBody3 *p3,
	const double *ux, const double *uy, const double *uz, int n, double *out)
{
	double *o[6];
	for (int i = 0; i < 6; ++i)
		o[i] = out + (size_t)i * (size_t)n;
	for (int ii = 0; ii < 3; ++ii) {
		if (!mkImpl_Available(implList[ii]))
			continue;
		for (int mask = 0; mask < 8; ++mask) {
			mkSumOptions opt = mkSumOptions_Default();
			opt.impl = implList[ii];
			opt.form = (mask & 1) ? MK_FORM_GRADIENT : MK_FORM_NORMAL;
			opt.param = (mask & 2) ? MK_PARAM_NORMAL : MK_PARAM_SURFACE;
			opt.set = (mask & 4) ? MK_SET_PLUS : MK_SET_CONTACT;
			mkResult r = dim == 2
				? mkSum2_Batch(p2[0], p2[1], &opt, ux, uy, n, o[0], o[1], o[3], o[4])
				: mkSum3_Batch(p3[0], p3[1], &opt, ux, uy, uz, n, o[0], o[1], o[2], o[3], o[4], o[5]);
			ENSURE(r == MK_OK);
			for (int j = 0; j < n; ++j) {
				int ok = 1;
				for (int i = 0; i < 6; ++i)
					if (dim == 3 || (i != 2 && i != 5))
						ok &= isfinite(o[i][j]);
				evaluated++;
				if (!ok) {
					bad++;
					if (dim == 2)
						ENSURE_MSG(ok, "2D %s %s %s %s eps %g/%g a=(%g,%g)/(%g,%g) u=(%.17g, %.17g)",
							mkImpl_Name(opt.impl), mkForm_Name(opt.form), mkParam_Name(opt.param),
							mkSet_Name(opt.set), p2[0].shape.eps, p2[1].shape.eps, p2[0].shape.a,
							p2[0].shape.b, p2[1].shape.a, p2[1].shape.b, ux[j], uy[j]);
					else
						ENSURE_MSG(ok, "3D %s %s %s %s eps %g,%g/%g,%g u=(%.17g, %.17g, %.17g)",
							mkImpl_Name(opt.impl), mkForm_Name(opt.form), mkParam_Name(opt.param),
							mkSet_Name(opt.set), p3[0].shape.eps1, p3[0].shape.eps2, p3[1].shape.eps1,
							p3[1].shape.eps2, ux[j], uy[j], uz[j]);
				}
			}
		}
	}
}

static void sweep2(refRng *rng)
{
	enum { NA = 1000, N = NA + 4 };
	double ux[N], uy[N];
	double *out = malloc(sizeof(double) * 6 * N);
	ENSURE(out != NULL);
	if (!out)
		return;
	ENSURE(mkSample2_Angles(NA, ux, uy) == MK_OK);
	const double ax[3][4] = { { 1, 1, 2, 0.5 }, { 1e4, 1, 1, 1e4 }, { 1e2, 1e-2, 5, 5e-4 } };
	const double sh[3][2] = { { 0, 0 }, { 10, -10 }, { -10, 2.5 } };
	for (int i = 0; i < NE; ++i)
		for (int j = 0; j < NE; ++j)
			for (int v = 0; v < 3; ++v) {
				mkBody2 b[2];
				for (int k = 0; k < 2; ++k) {
					mkShape2 s = { ax[v][2 * k], ax[v][2 * k + 1], k ? E[j] : E[i] };
					double ang = refRng_Uniform(rng, 0.0, 2.0 * REF_PI);
					mkMat2 M = mkMat2_Mul(mkMat2_Rotation(ang), mkMat2_Shear(sh[v][k]));
					b[k] = mkBody2_Make(s, M, (mkVec2){ refRng_Uniform(rng, -10, 10), 0.0 });
					ENSURE(mkBody2_IsValid(b[k], "body", NULL, 0));
				}
				/* the face normals M^-T e_i of both bodies */
				for (int k = 0; k < 4; ++k) {
					mkMat2 Mi = mkMat2_Inverse(b[k / 2].M);
					ux[NA + k] = Mi.m[k % 2][0];
					uy[NA + k] = Mi.m[k % 2][1];
				}
				checkAll(2, b, NULL, ux, uy, NULL, N, out);
			}
	free(out);
}

static void sweep3(refRng *rng)
{
	enum { G = 50, NG = G * G, N = NG + 6 };
	double ux[N], uy[N], uz[N];
	double *out = malloc(sizeof(double) * 6 * N);
	ENSURE(out != NULL);
	if (!out)
		return;
	ENSURE(mkSample3_Grid(G, ux, uy, uz) == MK_OK);
	for (int i = 0; i < NE; ++i)
		for (int j = 0; j < NE; ++j)
			for (int v = 0; v < 2; ++v) {
				mkBody3 b[2];
				for (int k = 0; k < 2; ++k) {
					mkShape3 s = v == 0 ? (mkShape3){ 1, 1, 1, 0, 0 } : k == 0
						? (mkShape3){ 1e4, 1, 30, 0, 0 } : (mkShape3){ 1, 1e2, 1e-2, 0, 0 };
					s.eps1 = k ? E[(i + 4) % NE] : E[i];
					s.eps2 = k ? E[(j + 7) % NE] : E[j];
					double q[4];
					for (int c = 0; c < 4; ++c)
						q[c] = refRng_Uniform(rng, -1.0, 1.0);
					int ok = 0;
					mkMat3 M = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
					ok = mkMat3_IsFinite(M);
					ENSURE(ok);
					if (v == 1) {
						mkMat3 S = mkMat3_Identity();
						S.m[0][1] = k ? -10.0 : 10.0;
						S.m[1][2] = 10.0;
						M = mkMat3_Mul(M, S);
					}
					b[k] = mkBody3_Make(s, M, (mkVec3){ 1.0, -2.0, 3.0 });
					ENSURE(mkBody3_IsValid(b[k], "body", NULL, 0));
				}
				for (int k = 0; k < 6; ++k) {
					mkMat3 Mi = mkMat3_Inverse(b[k / 3].M);
					ux[NG + k] = Mi.m[k % 3][0];
					uy[NG + k] = Mi.m[k % 3][1];
					uz[NG + k] = Mi.m[k % 3][2];
				}
				checkAll(3, NULL, b, ux, uy, uz, N, out);
			}
	free(out);
}

int main(void)
{
	refRng rng = { 6501u };
	sweep2(&rng);
	long n2 = evaluated, bad2 = bad;
	sweep3(&rng);
	printf("ref_finite: 2D %ld outputs (point and kiss), %ld with NaN/Inf; 3D %ld outputs, %ld with NaN/Inf\n",
		n2, bad2, evaluated - n2, bad - bad2);
	return refTest_Result("ref_finite");
}
