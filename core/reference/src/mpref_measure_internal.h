/* mpref_measure_internal.h - what mpref_score.c takes from the distance
 * search of mpref_measure.c. Not installed. */
#ifndef MINK_MPREF_MEASURE_INTERNAL_H
#define MINK_MPREF_MEASURE_INTERNAL_H

#include <mink/mpref_measure.h>

#define MEAS_PI 3.14159265358979323846

/* 1 when the first dim entries of v are finite. */
int refFinite(const double *v, int dim);

/* A start normal for p from a coarse scan of the sphere (512 Fibonacci
 * points) and the bodies' face normals, polished by a pattern search in
 * double: written to best; returns phi there, in double. */
double refSum_CoarseNormal(const refBody *b1, const refBody *b2, int plus, const double *p, double *best);

/* The 256-bit search for d(p) from the start normal n0 (double) or n0m
 * (256 bits); S the sum's size; newtonOnly skips the derivative-free stage.
 * 1 when the search reached its target, 0 otherwise (out->dist is still a
 * lower bound of d(p) and out->upper an upper bound of |d(p)|). */
int refSum_DistanceFrom(const refBody *b1, const refBody *b2, int plus, const double *p,
	const double *n0, const refVec *n0m, double S, int newtonOnly, refDistance *out);

#endif
