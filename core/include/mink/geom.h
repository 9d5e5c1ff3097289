/* mink/geom.h - small vector and matrix types, passed by value.
 *
 * Matrices are row-major: m[row][col]. Only what the closed forms and the
 * drivers need is here; this is not a linear-algebra library. */
#ifndef MINK_GEOM_H
#define MINK_GEOM_H

#include "base.h"

MK_EXTERN_C_BEGIN

typedef struct mkVec2 { double x, y; } mkVec2;
typedef struct mkVec3 { double x, y, z; } mkVec3;
typedef struct mkMat2 { double m[2][2]; } mkMat2;
typedef struct mkMat3 { double m[3][3]; } mkMat3;

MK_API mkMat2 mkMat2_Identity(void);
MK_API mkMat3 mkMat3_Identity(void);
/* Rotation by angle (radians), counter-clockwise. */
MK_API mkMat2 mkMat2_Rotation(double angle);
/* Shear [1 s; 0 1]. */
MK_API mkMat2 mkMat2_Shear(double s);
/* Rotation matrix of the quaternion (w, x, y, z); the quaternion is normalised
 * first. Fails (returns identity and sets *ok = 0, when ok is not NULL) on a
 * zero or non-finite quaternion. */
MK_API mkMat3 mkMat3_FromQuat(double w, double x, double y, double z, int *ok);

MK_API mkMat2 mkMat2_Mul(mkMat2 a, mkMat2 b);
MK_API mkMat3 mkMat3_Mul(mkMat3 a, mkMat3 b);
MK_API mkMat2 mkMat2_Transpose(mkMat2 a);
MK_API mkMat3 mkMat3_Transpose(mkMat3 a);
MK_API double mkMat2_Det(mkMat2 a);
MK_API double mkMat3_Det(mkMat3 a);
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
