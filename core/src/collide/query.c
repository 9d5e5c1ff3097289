/* query.c - MinkSum (Normal)'s public entry points (mkCollide3_Normal,
 * mkCollide3_NormalFrom, mkCollide3_Build): they pick the solver's build for
 * the processor, normal_portable.c or, where it has AVX2 and FMA,
 * normal_fma.c. */
#include <math.h>

#include "base/geom_inline.h"
#include "collide/collision_impl.h"
#include "collide/pair.h"

/* The solver in the build impl names (collision_impl.h). */
mkResult mkCollide3_NormalImpl(mkImpl impl, mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out)
{
#if defined(MINK_HAVE_FMA_SOLVER)
	if (impl == MK_IMPL_AVX2 || impl == MK_IMPL_AVX512)
		return mkCollide3_NormalAtFma(b1, b2, start, out);
#endif
	(void)impl;
	return mkCollide3_NormalAtPortable(b1, b2, start, out);
}

/* The solver's build for this processor: the FMA build where it was
 * compiled and the processor has AVX2 and FMA (the kernels' AVX2 tier;
 * mkImpl_Available reads the CPU features libgcc resolved at start-up),
 * the portable one otherwise. */
static mkImpl mkCollide3_Impl(void)
{
#if defined(MINK_HAVE_FMA_SOLVER)
	if (mkImpl_Available(MK_IMPL_AVX2))
		return MK_IMPL_AVX2;
#endif
	return MK_IMPL_SCALAR;
}

const char *mkCollide3_Build(void)
{
	return mkCollide3_Impl() == MK_IMPL_SCALAR ? "portable" : "fma";
}

mkResult mkCollide3_Normal(mkBody3 b1, mkBody3 b2, mkCollision3 *out)
{
	return mkCollide3_NormalImpl(mkCollide3_Impl(), b1, b2, NULL, out);
}

mkResult mkCollide3_NormalFrom(mkBody3 b1, mkBody3 b2, mkVec3 start, mkCollision3 *out)
{
	/* scaled by its largest component first, so that no length of a finite
	 * nonzero vector overflows or underflows */
	double m = fmax(fabs(start.x), fmax(fabs(start.y), fabs(start.z)));
	if (!mkIsFinite3(start) || !(m > 0.0)) {
		mkCollision3_Clear(out);
		return MK_ERR_ARGUMENT;
	}
	mkVec3 n = mkVec3_NormalizeInline(mkVec3_Make(start.x / m, start.y / m, start.z / m));
	return mkCollide3_NormalImpl(mkCollide3_Impl(), b1, b2, &n, out);
}
