/* kernel_f32.h - what every single-precision build of kernel_body.h shares
 * (kernel_f32_scalar.c, kernel_f32_avx2.c, kernel_f32_avx512.c): float
 * scalars and the float copies of the prepared constants (kernel.h), the
 * thresholds for the float range, and the normalisation of the caller's
 * parameter vectors, which is done in double before rounding to float: a
 * vector of length 1e300 or 1e-300, which sum.h accepts, has no float
 * image. */
#ifndef MINK_KERNEL_F32_H
#define MINK_KERNEL_F32_H

#include "kernels/kernel.h"

#define KS float
#define KC(x) ((float)(x))
#define KSHAPE2 mkKShape2f
#define KSHAPE3 mkKShape3f
#define KPLAN2 mkKPlan2f
#define KPLAN3 mkKPlan3f
/* Floor of a divisor that may be zero: the smallest normal float, rounded
 * up a little. */
#define KTINY 1.2e-38f
/* The ellipse/ellipsoid gradient u_i / a_i as a product with the float
 * reciprocal the plan carries (one rounding more, a division less). */
#define KDIV_AXIS(v, s, ax) ((v) * (s)->i##ax)
/* Parameter vectors whose squared length is within this of 1 (in double) are
 * used as given, others are normalised in double first. */
#define MK_F32_UNIT_TOL 1e-12
/* Float-buffer builds (MK_F32_FLOATIO): a float vector rounded from a unit
 * one has |u|^2 - 1 within about 3e-7 computed in float (each component
 * rounds by 2^-24 relatively, each square and sum once more); such vectors
 * are used as given, others are normalised in float. */
#define MK_F32IO_UNIT_TOL 5e-7f
#ifdef MK_F32_FLOATIO
#  define KIO float
#  define KUNIT_TOL MK_F32IO_UNIT_TOL
#endif

#endif
