/* geom_inline.h - the bodies of the small vector and matrix helpers of
 * mink/geom.h that hot loops inside the library call (the collision
 * solver, the 2D C-obstacle sampler, the scene query), as static inline
 * functions: geom.c defines the exported ones with them (mkVec2/mkVec3
 * Length and Normalize, mkMat3 IsFinite, FromQuat, Mul, MulVec, MulTVec),
 * so there is one arithmetic, inlined where a call would show in profiles.
 * Internal to the library. */
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

static inline int mkMat3_IsFiniteInline(mkMat3 a)
{
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			if (!isfinite(a.m[i][j]))
				return 0;
	return 1;
}

/* NaN for a zero or non-finite quaternion, as mkMat3_FromQuat. */
static inline mkMat3 mkMat3_FromQuatInline(double w, double x, double y, double z)
{
	double n2 = w * w + x * x + y * y + z * z;
	if (!(n2 > 0.0) || !isfinite(n2)) {
		mkMat3 bad = {{{NAN, NAN, NAN}, {NAN, NAN, NAN}, {NAN, NAN, NAN}}};
		return bad;
	}
	double s = 1.0 / sqrt(n2);
	w *= s; x *= s; y *= s; z *= s;
	mkMat3 r = {{
		{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
		{2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
		{2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)},
	}};
	return r;
}

static inline mkMat3 mkMat3_MulInline(mkMat3 a, mkMat3 b)
{
	mkMat3 r;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
	return r;
}

static inline mkVec3 mkMat3_MulVecInline(mkMat3 a, mkVec3 v)
{
	mkVec3 r = {
		a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
		a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
		a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z,
	};
	return r;
}

static inline mkVec3 mkMat3_MulTVecInline(mkMat3 a, mkVec3 v)
{
	mkVec3 r = {
		a.m[0][0] * v.x + a.m[1][0] * v.y + a.m[2][0] * v.z,
		a.m[0][1] * v.x + a.m[1][1] * v.y + a.m[2][1] * v.z,
		a.m[0][2] * v.x + a.m[1][2] * v.y + a.m[2][2] * v.z,
	};
	return r;
}

#endif
