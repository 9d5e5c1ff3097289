/* mink/score.h - the score of any boundary point set against the true sum:
 * what `mink score` prints. It is the error measure of mink/error.h (which
 * shares nothing with the core's closed forms) plus what a user comparing
 * an algorithm wants next to it:
 *
 *   dev            the measure's figures (mkDeviation): Hausdorff distance
 *                  between the points' hull P and the true set K, absolute
 *                  and relative to the sum's size S, its two one-sided gaps,
 *                  the points' largest distance off the boundary of K, the
 *                  relative area (3D: volume) error, each with its bound;
 *   support_gap    max over a scan of unit directions n of |h_K(n) - h_P(n)|
 *                  (P's support function from its hull's vertices, K's from
 *                  mkDeviation2/3_Support): a second, plain estimate of the
 *                  Hausdorff distance (for convex sets the sup of that
 *                  difference), never above it by more than the rounding
 *                  allowance; worst_dir is the direction that attains it and
 *                  worst_signed = h_P - h_K there (> 0: P reaches beyond K);
 *                  the scan is 65536 angles in 2D and the 256 x 256 grid of
 *                  mkSample3_Grid in 3D;
 *   inside         1 when every point lies in K up to the allowance
 *                  (dev.gap_out <= allowance);
 *   encloses       1 when P holds K up to the allowance (dev.gap_in <=
 *                  allowance);
 *   allowance      64 u S (u = 2^-53), the measure's rounding allowance.
 *
 * The points may come in any order and any number (at least one); NaN or
 * infinite coordinates are counted (dev.nonfinite) and left out. */
#ifndef MINK_SCORE_H
#define MINK_SCORE_H

#include <mink/error.h>

MK_EXTERN_C_BEGIN

#define MK_SCORE2_DIRECTIONS 65536
#define MK_SCORE3_GRID 256

typedef struct mkScore {
	mkDeviation dev;
	double support_gap;
	double worst_dir[3]; /* unit; worst_dir[2] = 0 in 2D */
	double worst_signed;
	int inside, encloses;
	double allowance;
	int directions;      /* directions scanned */
} mkScore;

/* Score pts (dimension 2 / 3) against K = B1 (+) B2 (MK_SET_PLUS) or
 * B1 (+) (-B2) (MK_SET_CONTACT). opt is passed to the measure (NULL for its
 * defaults). Returns MK_OK, or the measure's error (MK_ERR_ARGUMENT on a
 * NULL pointer, a wrong dimension, a bad set or an invalid body,
 * MK_ERR_MEMORY, MK_ERR_UNSUPPORTED when the 3D hull fails). */
MK_API mkResult mkScore2_Points(mkBody2 b1, mkBody2 b2, mkSet set, const mkPointSet *pts,
	const mkDeviationOptions *opt, mkScore *out);
MK_API mkResult mkScore3_Points(mkBody3 b1, mkBody3 b2, mkSet set, const mkPointSet *pts,
	const mkDeviationOptions *opt, mkScore *out);

MK_EXTERN_C_END

#endif
