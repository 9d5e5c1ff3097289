/* mink/geom.h - small vector and matrix types, passed by value, and pi.
 *
 * Matrices are row-major: m[row][col]. Only what the closed forms, the
 * baselines and the experiments need is here; this is not a linear-algebra
 * library. The vector helpers are static inline so that they cost nothing
 * in inner loops; everything else is an ordinary function. */
#ifndef MINK_GEOM_H
#define MINK_GEOM_H

#include "base.h"

MK_EXTERN_C_BEGIN

typedef struct mkVec2 { double x, y; } mkVec2;
typedef struct mkVec3 { double x, y, z; } mkVec3;
typedef struct mkMat2 { double m[2][2]; } mkMat2;
typedef struct mkMat3 { double m[3][3]; } mkMat3;

/* pi to the precision of a double (C11 has no portable M_PI). */
#define MK_PI 3.14159265358979323846

/* ---- vectors ------------------------------------------------------------ */
static inline mkVec2 mkVec2_Make(double x, double y) { mkVec2 r = { x, y }; return r; }
static inline mkVec2 mkVec2_Add(mkVec2 a, mkVec2 b) { return mkVec2_Make(a.x + b.x, a.y + b.y); }
static inline mkVec2 mkVec2_Sub(mkVec2 a, mkVec2 b) { return mkVec2_Make(a.x - b.x, a.y - b.y); }
static inline mkVec2 mkVec2_Scale(mkVec2 a, double s) { return mkVec2_Make(a.x * s, a.y * s); }
static inline mkVec2 mkVec2_Neg(mkVec2 a) { return mkVec2_Make(-a.x, -a.y); }
static inline double mkVec2_Dot(mkVec2 a, mkVec2 b) { return a.x * b.x + a.y * b.y; }
/* The z component of the cross product (a, 0) x (b, 0). */
static inline double mkVec2_Cross(mkVec2 a, mkVec2 b) { return a.x * b.y - a.y * b.x; }
/* Euclidean length, sqrt of the dot product (for vectors whose squares do
 * not overflow). */
MK_API double mkVec2_Length(mkVec2 a);
/* a * (1 / |a|); a vector of NaN when |a| is 0 or not finite. */
MK_API mkVec2 mkVec2_Normalize(mkVec2 a);

static inline mkVec3 mkVec3_Make(double x, double y, double z) { mkVec3 r = { x, y, z }; return r; }
static inline mkVec3 mkVec3_Add(mkVec3 a, mkVec3 b) { return mkVec3_Make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline mkVec3 mkVec3_Sub(mkVec3 a, mkVec3 b) { return mkVec3_Make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline mkVec3 mkVec3_Scale(mkVec3 a, double s) { return mkVec3_Make(a.x * s, a.y * s, a.z * s); }
static inline mkVec3 mkVec3_Neg(mkVec3 a) { return mkVec3_Make(-a.x, -a.y, -a.z); }
static inline double mkVec3_Dot(mkVec3 a, mkVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline mkVec3 mkVec3_Cross(mkVec3 a, mkVec3 b)
{
	return mkVec3_Make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
MK_API double mkVec3_Length(mkVec3 a);
MK_API mkVec3 mkVec3_Normalize(mkVec3 a);

/* ---- matrices ----------------------------------------------------------- */

MK_API mkMat2 mkMat2_Identity(void);
MK_API mkMat3 mkMat3_Identity(void);
/* Rotation by angle (radians), counter-clockwise. */
MK_API mkMat2 mkMat2_Rotation(double angle);
/* Shear [1 s; 0 1]. */
MK_API mkMat2 mkMat2_Shear(double s);
/* Rotation matrix of the quaternion (w, x, y, z); the quaternion is
 * normalised first. Fails (returns a matrix of NaN) on a zero or non-finite
 * quaternion: like every small-math function here, failure is a documented
 * NaN, which mkMat3_IsFinite detects. */
MK_API mkMat3 mkMat3_FromQuat(double w, double x, double y, double z);

MK_API mkMat2 mkMat2_Mul(mkMat2 a, mkMat2 b);
MK_API mkMat3 mkMat3_Mul(mkMat3 a, mkMat3 b);
MK_API mkMat2 mkMat2_Transpose(mkMat2 a);
MK_API mkMat3 mkMat3_Transpose(mkMat3 a);
MK_API double mkMat2_Det(mkMat2 a);
MK_API double mkMat3_Det(mkMat3 a);
/* 1 when every entry is finite, else 0. */
MK_API int mkMat2_IsFinite(mkMat2 a);
MK_API int mkMat3_IsFinite(mkMat3 a);
/* Inverse by the adjugate. Fails (returns a matrix of NaN) when det == 0. */
MK_API mkMat2 mkMat2_Inverse(mkMat2 a);
MK_API mkMat3 mkMat3_Inverse(mkMat3 a);
/* Frobenius-norm condition number |A|_F |A^-1|_F (>= d); +inf if singular. */
MK_API double mkMat2_Cond(mkMat2 a);
MK_API double mkMat3_Cond(mkMat3 a);

MK_API mkVec2 mkMat2_MulVec(mkMat2 a, mkVec2 v);
MK_API mkVec3 mkMat3_MulVec(mkMat3 a, mkVec3 v);
/* a^T v without forming the transpose. */
MK_API mkVec2 mkMat2_MulTVec(mkMat2 a, mkVec2 v);
MK_API mkVec3 mkMat3_MulTVec(mkMat3 a, mkVec3 v);

MK_EXTERN_C_END

#endif
