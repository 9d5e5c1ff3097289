/* ref_egradient.c - the floor of the paper's e_gradient: what the exact
 * boundary, correctly rounded to double, scores on it.
 *
 * e_gradient (paper eq. verify_gradient) takes the output point x of the
 * contact space and the kissing point k, places B2 at x, and compares the
 * normals of B1 and B2 at k: |cos(n1, n2) + 1|. Both normals are recomputed
 * from positions. Near the tips of a body with eps near 2 the normal is only
 * Hoelder continuous in the position (exponent 2/eps - 1): at eps = 1.84 a
 * boundary point whose small coordinate is 1e-19 of the body's size has a
 * well-defined normal, but any double near that point, at 1 ulp of |x| away,
 * has a normal turned by up to a radian. So the mean of e_gradient over the
 * paper's draws is bounded below by the rounding of the output itself, not
 * by the method that computed it.
 *
 * This test measures that bound. On the paper's 2D validation draws (a, b ~
 * U(0, 10), eps ~ U(0.1, 1.9), M = rot(2 pi U) shear(U(-2, 2)), centred,
 * N = 1000 of the paper's angles per trial) it computes for every point
 *  - the core's output (gradient form, surface parameters, widest kernel)
 *    and its e_gradient by the core's metric (mkCheck2, long double inside);
 *  - the exact x and k at 256 bits (mpref), correctly rounded to double,
 *    and the e_gradient of those doubles evaluated again at 256 bits: the
 *    best any double-precision output can score, judged exactly.
 * It asserts that the core's mean is within a factor of 4 of that floor
 * (two outputs a few ulp apart land on different sides of the same cliff,
 * so their means agree in order of magnitude, not in digits: moving every
 * output by one ulp changes the mean by about 1.5x, core.test_sum), and that
 * the floor on these draws lies above 1e-14: a target below it cannot be met
 * by any double output. It also prints the median, where the floor is at
 * rounding level. */
#include <mink/mpref.h>
#include "refcheck.h"
#include "reftest.h"

#include <math.h>
#include <stdlib.h>

#define RND MPFR_RNDN
enum { TRIALS = 100, N = 1000 };

static refMat transpose(const refMat *M)
{
	refMat T;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			T.m[i][j] = M->m[j][i];
	return T;
}

/* The world normal of a placed body at the world point p (from the centre
 * `centre`): M^-T grad Psi(M^-1 (p - centre)), unit length. */
static void normalAt(const refBody *b, const refVec *p, const refVec *centre, refVec *n)
{
	refVec d, y, g;
	refVec_Init(&d);
	refVec_Init(&y);
	refVec_Init(&g);
	for (int i = 0; i < 2; ++i)
		mpfr_sub(d.c[i], p->c[i], centre->c[i], RND);
	refMat T = transpose(&b->M);
	refMat_InvTVec(&T, 2, &d, &y); /* (M^T)^-T d = M^-1 d */
	refShape_Gradient(b->s, &y, &g);
	refMat_InvTVec(&b->M, 2, &g, n);
	refVec_Normalize(n, 2);
	refVec_Clear(&d);
	refVec_Clear(&y);
	refVec_Clear(&g);
}

/* e_gradient of the contact-space output (x, k), both doubles, at 256 bits. */
static double exactEGradient(const refBody *b1, const refBody *b2, const double *x, const double *k)
{
	refVec X, K, T1, n1, n2;
	refVec_Init(&X);
	refVec_Init(&K);
	refVec_Init(&T1);
	refVec_Init(&n1);
	refVec_Init(&n2);
	refVec_FromD(&X, 2, x);
	refVec_FromD(&K, 2, k);
	refVec_FromD(&T1, 2, b1->t);
	normalAt(b1, &K, &T1, &n1);
	normalAt(b2, &K, &X, &n2); /* B2 placed at x */
	mpfr_t c;
	mpfr_init2(c, REF_PREC);
	refVec_Dot(c, &n1, &n2, 2);
	mpfr_add_ui(c, c, 1, RND);
	double e = fabs(mpfr_get_d(c, RND));
	mpfr_clear(c);
	refVec_Clear(&X);
	refVec_Clear(&K);
	refVec_Clear(&T1);
	refVec_Clear(&n1);
	refVec_Clear(&n2);
	return e;
}

static int cmpDouble(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

int main(void)
{
	static double ux[N], uy[N], x[N], y[N], kx[N], ky[N];
	static double core[TRIALS * N], floorExact[TRIALS * N];
	ENSURE(mkSample2_Angles(N, ux, uy) == MK_OK);
	refRng rng = { 6701u };
	mkSumOptions opt = { MK_SET_CONTACT, MK_FORM_GRADIENT, MK_PARAM_SURFACE, MK_IMPL_AUTO, MK_PRECISION_DOUBLE };
	refVec u, X, K;
	refVec_Init(&u);
	refVec_Init(&X);
	refVec_Init(&K);
	double sumCore = 0.0, sumFloor = 0.0, worstTrialFloor = 0.0;
	long count = 0;
	for (int trial = 0; trial < TRIALS; ++trial) {
		mkBody2 b[2];
		for (int j = 0; j < 2; ++j) {
			mkShape2 s;
			s.a = refRng_Uniform(&rng, 0.0, 10.0);
			s.b = refRng_Uniform(&rng, 0.0, 10.0);
			s.eps = refRng_Uniform(&rng, 0.1, 1.9);
			double ang = 2.0 * REF_PI * refRng_Uniform(&rng, 0.0, 1.0);
			double sh = refRng_Uniform(&rng, -2.0, 2.0);
			b[j] = mkBody2_Make(s, mkMat2_Mul(mkMat2_Rotation(ang), mkMat2_Shear(sh)), (mkVec2){ 0.0, 0.0 });
		}
		ENSURE(mkSum2_Batch(b[0], b[1], &opt, ux, uy, N, x, y, kx, ky) == MK_OK);
		refBody r1 = refBody_From2(b[0]), r2 = refBody_From2(b[1]);
		double trialFloor = 0.0;
		for (int i = 0; i < N; ++i) {
			core[count] = mkCheck2(b[0], b[1], MK_SET_CONTACT, (mkVec2){ x[i], y[i] },
				(mkVec2){ kx[i], ky[i] }).e_gradient;
			double uu[2] = { ux[i], uy[i] }, xd[2], kd[2];
			refVec_FromD(&u, 2, uu);
			refSum_Point(&r1, &r2, 0, 1, &u, &X, &K, NULL);
			refVec_ToD(&X, 2, xd);
			refVec_ToD(&K, 2, kd);
			floorExact[count] = exactEGradient(&r1, &r2, xd, kd);
			ENSURE_MSG(isfinite(core[count]) && isfinite(floorExact[count]), "trial %d point %d", trial, i);
			sumCore += core[count];
			sumFloor += floorExact[count];
			trialFloor += floorExact[count];
			++count;
		}
		trialFloor /= N;
		if (trialFloor > worstTrialFloor)
			worstTrialFloor = trialFloor;
	}
	double meanCore = sumCore / (double)count, meanFloor = sumFloor / (double)count;
	qsort(core, (size_t)count, sizeof core[0], cmpDouble);
	qsort(floorExact, (size_t)count, sizeof floorExact[0], cmpDouble);
	printf("ref_egradient: %d trials x %d points of the paper's 2D draws\n", TRIALS, N);
	printf("  the core's output, its own metric:          mean %.3e, median %.3e\n", meanCore, core[count / 2]);
	printf("  exact output rounded to double, exact metric: mean %.3e, median %.3e (worst trial %.3e)\n",
		meanFloor, floorExact[count / 2], worstTrialFloor);
	ENSURE_LE(meanCore, 4.0 * meanFloor, "the core's mean e_gradient against the floor of rounded exact output");
	ENSURE_LE(meanFloor / 4.0, meanCore, "the floor against the core's mean (a factor of 4 either way)");
	ENSURE_LE(1e-14, meanFloor, "the floor on these draws (a mean e_gradient below it is out of reach in double)");
	/* Where the normal is well conditioned the floor is at rounding level:
	 * half of the points score below 1e-15 (u^2-sized, as a cosine of an
	 * angle of order u). */
	ENSURE_LE(floorExact[count / 2], 1e-15, "median of the floor");
	ENSURE_LE(core[count / 2], 1e-15, "median of the core's e_gradient");
	refVec_Clear(&u);
	refVec_Clear(&X);
	refVec_Clear(&K);
	return refTest_Result("ref_egradient");
}
