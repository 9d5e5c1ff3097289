/* validation.h - the numerical validation of the paper (Sec. 6.1).
 *
 * Per trial, two random bodies; the closed-form contact space B1 (+) (-B2)
 * (or B1 (+) B2) at B1's surface parameters in every form: Theorem 1
 * (normal), Theorem 2 evaluated stably (gradient) and Theorem 2 as printed
 * (paper, the reference of what the published code computes). Each boundary
 * point x with its kissing point k on B1 is checked by mkCheck2_Normal /
 * mkCheck3_Normal (e_implicit, e_gradient, the normal angle and e_support
 * with B1's normal taken from its parameter); one row per trial and form.
 *
 * Draws (paper Sec. 6.1, with the reference code's distributions):
 *  2D: a, b ~ U(0,10), eps ~ U(0.1,1.9), M = rot(2 pi U(0,1)) [1 s; 0 1],
 *      s ~ U(-2,2), for both bodies; N points on B1.
 *  3D: B1 semi-axes ~ U(1,10)^3, B2 ~ U(1,6)^3, eps1, eps2 ~ U(0.1,1.9),
 *      pure rotations (mink_exp/draw.h: the reference code's quaternion or
 *      uniform on SO(3)); a G x G grid on B1.
 *  Both bodies are centred at the origin (the contact space does not depend
 *  on B2's centre, and B1's only shifts it).
 * Each trial draws from its own stream (dim << 32 | trial) of the run's
 * seed. A draw the core rejects as invalid (a semi-axis below MK_AXIS_MIN,
 * probability about 1e-10) is drawn again from the same stream and counted
 * in the row's `redraws`. Means and maxima are over the points whose
 * metrics are all finite; the others are counted in nonfinite_count. */
#ifndef MINK_EXP_VALIDATION_H
#define MINK_EXP_VALIDATION_H

#include <mink/mink.h>
#include <mink_exp/exp.h>

#define MK_VALIDATION_SCHEMA 2 /* 2: e_support_mean, e_support_max */

typedef struct mkValidationOptions {
	uint64_t seed;
	long n2;          /* points in 2D */
	long grid3;       /* grid side in 3D */
	mkRotDraw rotations;
	mkSet set;
	mkImpl impl;
} mkValidationOptions;

/* The CSV's columns, ended by NULL. */
extern const char *const mkValidation_Columns[];

/* The parameters of both dimensions and room for the larger output. */
typedef struct mkValidationWork {
	double *u2x, *u2y, *u3x, *u3y, *u3z;
	double *x, *y, *z, *kx, *ky, *kz;
} mkValidationWork;
mkResult mkValidationWork_Init(mkValidationWork *w, const mkValidationOptions *o, int dim2, int dim3);
void mkValidationWork_Free(mkValidationWork *w);

/* One trial of one dimension: draw, compute every form, write its rows.
 * Returns 0, or -1 after printing why. */
int mkValidation_Trial(const mkValidationOptions *o, int dim, long trial, mkValidationWork *w, mkCsv *csv);

/* The section of the tables: <dir>/validation.csv beside the paper's means. */
void mkValidation_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
