/* mink_exp/draw.h - the random draws the experiments share.
 *
 * Every draw takes its numbers from an mkRng stream (mink_exp/rng.h) in a
 * fixed, documented order, so that a row can be re-drawn from (seed, stream)
 * alone.
 *
 * Rotations. The paper's reference code draws a quaternion with four U(0,1)
 * entries and normalises it (MK_ROT_PAPER): not uniform on SO(3), and only
 * the rotations of one orthant of quaternions. MK_ROT_UNIFORM is uniform on
 * SO(3) by Shoemake's subgroup algorithm (Graphics Gems III, 1992): three
 * U(0,1) numbers u1, u2, u3 give
 *   q = (sqrt(u1) cos 2pi u3, sqrt(1-u1) sin 2pi u2, sqrt(1-u1) cos 2pi u2,
 *        sqrt(u1) sin 2pi u3),
 * uniform on the unit 3-sphere, hence on SO(3). */
#ifndef MINK_EXP_DRAW_H
#define MINK_EXP_DRAW_H

#include <mink/mink.h>

#include "rng.h"

typedef enum mkRotDraw { MK_ROT_PAPER = 0, MK_ROT_UNIFORM = 1 } mkRotDraw;

/* "paper", "uniform": the names of --rotations, in mkRotDraw order. */
extern const char *const mkRotDraw_Names[2];

/* The option every driver with 3D rotations takes (mink_exp/driver.h):
 * --rotations paper|uniform into an int holding an mkRotDraw. */
#define MK_FLAG_ROTATIONS(ptr) \
	MK_FLAG_CHOICE("--rotations", "paper|uniform", "3D rotation draw: the reference code's normalised\n" \
		"positive quaternion, or uniform on SO(3) (default paper)", ptr, mkRotDraw_Names)

/* A quaternion (w, x, y, z) by `kind` (4 numbers for paper, 3 for uniform),
 * not normalised for paper. */
void mkDraw_Quat(mkRng *rng, mkRotDraw kind, double q[4]);
/* The rotation of mkDraw_Quat; a matrix of NaN (mkMat3_IsFinite) when the
 * paper's draw gives the zero quaternion (probability 2^-212). */
mkMat3 mkDraw_Rotation3(mkRng *rng, mkRotDraw kind);

/* A value from [lo, hi]: lo itself when lo == hi (no number is drawn, so
 * that a fixed value does not shift the stream), else U(lo, hi). */
double mkDraw_Value(mkRng *rng, double lo, double hi);

/* Shapes from ranges, drawn in the order a, b, (c,) eps (eps1, eps2), each
 * by mkDraw_Value. */
typedef struct mkShapeRange2 { double a[2], b[2], eps[2]; } mkShapeRange2;
typedef struct mkShapeRange3 { double a[2], b[2], c[2], eps1[2], eps2[2]; } mkShapeRange3;
mkShape2 mkDraw_Shape2(mkRng *rng, const mkShapeRange2 *r);
mkShape3 mkDraw_Shape3(mkRng *rng, const mkShapeRange3 *r);

/* The 2D map of the paper's draws: M = rot(2 pi U(0,1)) [1 s; 0 1] with
 * s ~ U(-shear, shear), drawn in that order; *angle and *s (may be NULL)
 * receive the values. */
mkMat2 mkDraw_RotShear2(mkRng *rng, double shear, double *angle, double *s);

#endif
