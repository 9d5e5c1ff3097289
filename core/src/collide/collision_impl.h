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

#endif
