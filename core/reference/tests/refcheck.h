/* refcheck.h - runs the core's batch closed forms on one pair of bodies in
 * every available kernel, form, parameterisation and set, and judges each
 * output point against the 256-bit MPFR reference (mpref.h).
 *
 * Three figures per point, all divided by the sum's size (mkSum2_Size)
 *   S = |t1| (+ |t2| for the plus set) + |M1|_F |a1| + |M2|_F |a2|
 * (|a| the Euclidean norm of the semi-axes, which bounds |f(u)|):
 *  eA = |x - x_ref| / S          distance to the exact point for the same input
 *  eK = |k - k_ref| / S          the same for the kissing point on B1
 *  eB = |<n, x> - h(n)| / S      distance from the exact boundary of the sum,
 *                                measured along the exact normal n of the point
 * and e12 = |x_normal - x_gradient| / S, Theorem 1 against Theorem 2.
 * The tolerances are derived in refcheck.c. */
#ifndef MINK_TEST_REFCHECK_H
#define MINK_TEST_REFCHECK_H

#include <mink/mink.h>

#include <mink/mpref.h>
#include "reftest.h"

/* One pair of bodies and the parameter vectors (structure of arrays; uz is
 * NULL in 2D). */
typedef struct refCase {
	int dim;
	mkBody2 a2, b2; /* dim 2 */
	mkBody3 a3, b3; /* dim 3 */
	int n;
	const double *ux, *uy, *uz;
} refCase;

#define REF_IMPLS 4 /* indexed by mkImpl; AUTO is not run, it is one of the others */
#define REF_FORMS 2 /* MK_FORM_NORMAL, MK_FORM_GRADIENT */

/* Statistics of a group of cases, per kernel and form. */
typedef struct refGroup {
	const char *name;
	refStat eA[REF_IMPLS][REF_FORMS];
	refStat eK[REF_IMPLS][REF_FORMS];
	refStat eB[REF_IMPLS][REF_FORMS];
	refStat e12[REF_IMPLS];
	refStat ratioA, ratioB; /* error / tolerance, over everything */
	int conditionAll; /* set: evaluate the conditioning of every point, so
	                     that `illConditioned` counts them all; otherwise only
	                     where an error exceeds the rounding part */
	long illConditioned; /* points whose exact answer moves by more than
	                        1e-9 S (1e-7 S for MK_PRECISION_F32) under
	                        rounding-size perturbations */
	mkPrecision precision; /* the tier run (DOUBLE unless set; see refcheck.c) */
	int floatio;   /* set: through the float-array entry points (mkSum2f_Batch),
	                  on the parameter vectors rounded to float */
	long points;   /* reference points computed */
	long nonfinite;
} refGroup;

/* Check every combination on one case; failures go through ENSURE. */
void refCheck_Case(const refCase *c, refGroup *g);
/* One summary line per kernel and form, and the Theorem 1 vs 2 line. */
void refGroup_Print(const refGroup *g);

/* The groups of ref_sum2 and ref_sum3 and their driver, refSum_Main: the
 * command line "ref_sumN [group [tier [all]]]" sets *tier and *floatio, then
 * the groups run (group 0: all): 1 the validation draws, 2 the extreme
 * exponents (seed + 2), 4 the ends of the exponent range (seed + 4, its
 * conditioning of every point only with "all"), 3 the scaled parameter
 * vectors. Returns the test's exit status. */
typedef struct refSumTests {
	const char *name; /* "ref_sum2" */
	uint64_t seed;
	void (*validation)(void);
	void (*extremes)(const double *E, const char *name, uint64_t seed, int all);
	void (*scaled)(void);
} refSumTests;
int refSum_Main(int argc, char **argv, const refSumTests *t, mkPrecision *tier, int *floatio);

/* The reference body of a core body. */
refBody refBody_From2(mkBody2 b);
refBody refBody_From3(mkBody3 b);

#endif
