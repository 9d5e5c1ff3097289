/* geom_inline.h - the bodies of the small vector helpers of mink/geom.h
 * that hot loops inside the library call (the collision solver, the 2D
 * C-obstacle sampler), as static inline functions: geom.c defines the
 * exported mkVec2/mkVec3 Length and Normalize with them, so there is one
 * arithmetic, inlined where a call would show in profiles. Internal to the
 * library. */
#ifndef MINK_GEOM_INLINE_H
#define MINK_GEOM_INLINE_H

#include <math.h>

#include "mink/geom.h"

static inline double mkVec2_LengthInline(mkVec2 a)
{
	return sqrt(a.x * a.x + a.y * a.y);
}

/* NaN vector for a zero or non-finite length, as mkVec2_Normalize. */
static inline mkVec2 mkVec2_NormalizeInline(mkVec2 a)
{
	double n = mkVec2_LengthInline(a);
	if (!(n > 0.0) || !isfinite(n))
		return (mkVec2){NAN, NAN};
	double s = 1.0 / n;
	return (mkVec2){a.x * s, a.y * s};
}

static inline double mkVec3_LengthInline(mkVec3 a)
{
	return sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}

/* NaN vector for a zero or non-finite length, as mkVec3_Normalize. */
static inline mkVec3 mkVec3_NormalizeInline(mkVec3 a)
{
	double n = mkVec3_LengthInline(a);
	if (!(n > 0.0) || !isfinite(n))
		return (mkVec3){NAN, NAN, NAN};
	double s = 1.0 / n;
	return (mkVec3){a.x * s, a.y * s, a.z * s};
}

#endif
