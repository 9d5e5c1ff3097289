/* kernel_f32.h - what every single-precision build of kernel_body.h shares
 * (kernel_f32_scalar.c, kernel_f32_avx2.c, kernel_f32_avx512.c): float
 * scalars and the float copies of the prepared constants (kernel.h), the
 * thresholds for the float range, and the normalisation of the caller's
 * parameter vectors, which is done in double before rounding to float: a
 * vector of length 1e300 or 1e-300, which sum.h accepts, has no float
 * image. */
#ifndef MINK_KERNEL_F32_H
#define MINK_KERNEL_F32_H

#include "kernel.h"

#define KS float
#define KC(x) ((float)(x))
#define KSHAPE2 mkKShape2f
#define KSHAPE3 mkKShape3f
#define KPLAN2 mkKPlan2f
#define KPLAN3 mkKPlan3f
/* Floor of a divisor that may be zero: the smallest normal float, rounded
 * up a little. */
#define KTINY 1.2e-38f
/* Parameter vectors whose squared length is within this of 1 (in double) are
 * used as given, others are normalised in double first. */
#define MK_F32_UNIT_TOL 1e-12

#endif
