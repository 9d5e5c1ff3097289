/* collision_impl.h - inside the library: MinkSum (Normal)'s solver in its
 * two builds (normal.h compiled by normal_portable.c, and by normal_fma.c
 * for processors with the FMA instruction) and the call that picks one.
 * The tests call both builds through mkCollide3_NormalImpl. */
#ifndef MINK_COLLISION_IMPL_H
#define MINK_COLLISION_IMPL_H

#include <mink/mink.h>

/* The solver from the unit start (NULL: the centre line), as
 * mkCollide3_Normal / mkCollide3_NormalFrom describe. */
mkResult mkCollide3_NormalAtPortable(mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out);
/* The same compiled with -mavx2 -mfma and contraction (MINK_HAVE_FMA_SOLVER
 * only); call it only where mkImpl_Available(MK_IMPL_AVX2). */
mkResult mkCollide3_NormalAtFma(mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out);
/* The FMA build for MK_IMPL_AVX2 or MK_IMPL_AVX512 where it was compiled
 * (the caller checks mkImpl_Available), the portable one otherwise. */
mkResult mkCollide3_NormalImpl(mkImpl impl, mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out);

/* The batch's vector lanes (batch_x86.h): the support points s = P grad N
 * (P^T y) of MK_BATCH_VLANES superquadrics, P row-major (P[3 i + j] the
 * entry i, j), one lane per column. */
#define MK_BATCH_VLANES 8
typedef struct mkBatchLanesIn {
	double P[9][MK_BATCH_VLANES], q1[MK_BATCH_VLANES], q2[MK_BATCH_VLANES], iq1[MK_BATCH_VLANES],
		iq2[MK_BATCH_VLANES], y[3][MK_BATCH_VLANES];
} mkBatchLanesIn;
void mkBatch_SupportLanesAvx2(const mkBatchLanesIn *in, double s[3][MK_BATCH_VLANES]);
void mkBatch_SupportLanesAvx512(const mkBatchLanesIn *in, double s[3][MK_BATCH_VLANES]);
/* The batch's Newton lanes for pairs of ellipsoids (batch_newton.h),
 * MK_BATCH_NLANES per call: per lane the bodies' Q = P P^T (Q00, Q01, Q02, Q11,
 * Q12, Q22), the centre line d = c2 - c1, the unit start n and the pair's
 * scale; out: the final normal, the support points s1 (B1 at n) and s2 (B2
 * at -n) about the centres, f at n, the residual |g|, the steps taken and
 * done (1 converged, 0 to leave for the scalar path); the outputs of
 * lanes past count's vector are not written. */
#define MK_BATCH_NLANES 16
#define MK_BATCH_NEWTON_STEPS 16
#define MK_BATCH_NEWTON_CUTS 4
#define MK_BATCH_NEWTON_SETTLE 1e-15
typedef struct mkBatchEllIn {
	double Q1[6][MK_BATCH_NLANES], Q2[6][MK_BATCH_NLANES], d[3][MK_BATCH_NLANES], n[3][MK_BATCH_NLANES],
		scale[MK_BATCH_NLANES];
	int count; /* lanes [0, count) are run (whole vectors: a vector's spare lanes must hold valid pairs) */
} mkBatchEllIn;
typedef struct mkBatchEllOut {
	double n[3][MK_BATCH_NLANES], s1[3][MK_BATCH_NLANES], s2[3][MK_BATCH_NLANES], f[MK_BATCH_NLANES],
		res[MK_BATCH_NLANES], steps[MK_BATCH_NLANES], done[MK_BATCH_NLANES];
} mkBatchEllOut;
/* The scalar reference (one lane at a time) and the vector builds. */
void mkBatch_EllipsoidLanesScalar(const mkBatchEllIn *in, mkBatchEllOut *out);
void mkBatch_EllipsoidLanesAvx2(const mkBatchEllIn *in, mkBatchEllOut *out);
void mkBatch_EllipsoidLanesAvx512(const mkBatchEllIn *in, mkBatchEllOut *out);
/* mkCollide3_Batch with the lanes of impl (MK_IMPL_SCALAR: the scalar
 * support map; MK_IMPL_AVX2 / MK_IMPL_AVX512 where available, else
 * MK_ERR_UNSUPPORTED; MK_IMPL_AUTO: the widest available); quick 0 leaves
 * out the certificates before any search (batch_quick.h), so that every
 * pair goes through the lanes. */
mkResult mkCollide3_BatchImpl(mkImpl impl, int quick, const mkBatchPairs3 *pairs, mkBatchMode mode, double delta,
	const mkBatchOut3 *out, mkBatchStats3 *stats);

#endif
