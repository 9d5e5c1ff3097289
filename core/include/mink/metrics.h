/* mink/metrics.h - the paper's validation metrics (Sec. 6.1).
 *
 * For a computed boundary point x with kissing point k on the boundary of B1:
 *  - contact space: B2 placed with its centre at x touches B1 at k, so
 *    y = M2^-1 (k - x) lies on the boundary of canonical B2;
 *  - B1 (+) B2: x = k + t2 + M2 y with y on the boundary of B2.
 * e_implicit = |Psi2(y) - 1|                              (eq. verify_implicit)
 * e_gradient = |cos angle(grad1(k), -+grad2) + 1|         (eq. verify_gradient)
 *   (grad2 is negated for B1 (+) B2, whose normals are parallel, not opposed),
 * angle = the angle in radians between B1's outward normal at k and the
 *   reversed (contact) or plain (plus) outward normal of B2, via atan2 so
 *   that small angles keep their digits.
 * e_implicit1 = |Psi1(k) - 1| (zero by construction in surface sampling).
 * e_support = (h2(d) - <d, y>) / h2(d), with d = -+M2^T n1 the direction in
 *   which B2's canonical point y should be extreme (h2 the support function):
 *   the same anti-parallel-normal condition as e_gradient, but as a support
 *   gap, which does not differentiate positions. Why it is needed: the normal
 *   of a body with eps near 2 is only Hoelder continuous at its tips (exponent
 *   2/eps - 1), so a normal recomputed from a point rounded to double can be
 *   off by a tenth of a radian there whatever computed the point; e_gradient
 *   then measures the rounding of the output, not the method. The gap is
 *   first-order in the distance from the boundary and second-order in the
 *   normal's error.
 * The metrics are evaluated in long double so that their own rounding stays
 * below the errors they measure. */
#ifndef MINK_METRICS_H
#define MINK_METRICS_H

#include "sum.h"

MK_EXTERN_C_BEGIN

typedef struct mkCheck {
	double e_implicit;
	double e_gradient;
	double angle;
	double e_implicit1;
	double e_support;
} mkCheck;

MK_API mkCheck mkCheck2(mkBody2 b1, mkBody2 b2, mkSet set, mkVec2 x, mkVec2 k);
MK_API mkCheck mkCheck3(mkBody3 b1, mkBody3 b2, mkSet set, mkVec3 x, mkVec3 k);
/* The same, with B1's outward world normal n1 at k given by the caller (for
 * example from B1's parameter, M1^-T g1(u)) for e_support; the other metrics
 * are as above. */
MK_API mkCheck mkCheck2_Normal(mkBody2 b1, mkBody2 b2, mkSet set, mkVec2 x, mkVec2 k, mkVec2 n1);
MK_API mkCheck mkCheck3_Normal(mkBody3 b1, mkBody3 b2, mkSet set, mkVec3 x, mkVec3 k, mkVec3 n1);

MK_EXTERN_C_END

#endif
