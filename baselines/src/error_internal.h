/* error_internal.h - what the parts of the error measure (error.c, error2.c,
 * error3_distance.c, error3.c) share: the problem (the bodies, the centre o
 * of K, the sum's size S, the rounding allowance), the textbook support
 * function h_K, compensated sums, the result's bookkeeping and small 3D
 * vector helpers. Not installed. */
#ifndef MINK_ERROR_INTERNAL_H
#define MINK_ERROR_INTERNAL_H

#include <float.h>

#include <mink/mink.h>
#include <mink/error.h>

#define UNIT_ROUND (DBL_EPSILON / 2)
/* Rounding allowance, in units of u times the sum's size S: a support value is a
 * few pows (each <= 1 ulp, the outer power 1/q contracting their errors)
 * and two small matrix products, so some 10 u of |x|; a dot product with a
 * point adds a few u of |p|. 64 keeps a margin. */
#define ROUND_ULPS 64.0
#define TOL_DEFAULT 1e-6
#define EVAL_BUDGET 4000000L /* support evaluations for refining gap_in */

/* The problem: the bodies, K's centre o, the sum's size S, R and the
 * rounding allowance ROUND_ULPS u S. */
typedef struct mkDevProb2 {
	mkBody2 b1, b2;
	double o[2]; /* centre of K */
	double S;    /* the sum's size, mkSum2_Size */
	double R;    /* bound on |x - o| over K */
	double round;/* rounding allowance ROUND_ULPS u S */
} mkDevProb2;

typedef struct mkDevProb3 {
	mkBody3 b1, b2;
	double o[3];
	double S, R, round;
	int lead; /* 2 when body 2 is the boxier (smaller exponent): the volume
	             grid and the ray-parameter search follow that body */
} mkDevProb3;

/* A Neumaier compensated sum (mkDevSum_Add, mkDevSum_Get). */
typedef struct mkDevSum { double s, c; } mkDevSum;

/* error.c: the problem (0 on a bad set or an invalid body), h_K and x_K
 * (relative to o) at a unit direction, the lead (boxier) body, the canonical
 * superquadric's support, the compensated sum, the result's bookkeeping
 * and 3D vector helpers. */
int mkDev_Prob2Init(mkDevProb2 *P, mkBody2 b1, mkBody2 b2, mkSet set);
int mkDev_Prob3Init(mkDevProb3 *P, mkBody3 b1, mkBody3 b2, mkSet set);
double mkDev_Hk2(const mkDevProb2 *P, double nx, double ny, double *x);
double mkDev_Hk3(const mkDevProb3 *P, const double *n, double *x);
const mkBody3 *mkDev_LeadBody(const mkDevProb3 *P);
double mkDev_Canon3(mkShape3 s, double m0, double m1, double m2, double *x);
void mkDevSum_Add(mkDevSum *a, double v);
double mkDevSum_Get(const mkDevSum *a);
void mkDev_Finish(mkDeviation *e, const char *what);
int mkDev_TakeTruth(const mkDeviationOptions *opt, mkDeviation *out);
void mkDev_NoPoints(mkDeviation *out, const char *what);
void mkDev_Init(mkDeviation *e, int points, double size);
double mkDev_Dot3(const double *a, const double *b);
void mkDev_Cross3(const double *a, const double *b, double *c);
int mkDev_Unit3(double *v);
void mkDev_Frame3(const double *n, double *e1, double *e2);

/* error3_distance.c: the volume of K and its bound; the signed distance of
 * p (relative to o) to K from the unit start normal, with the estimate of
 * what is left. */
mkResult mkDev_Volume3(const mkDevProb3 *P, double *vol, double *bound);
void mkDev_SignedDistance3(const mkDevProb3 *P, const double *start, const double *p, double *sd, double *left);

#endif
