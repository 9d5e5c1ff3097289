/* example.h - the smallest experiment: the roundoff of the closed form on
 * random pairs of superellipses. Copy this folder to start a new one. */
#ifndef MINK_EXP_EXAMPLE_H
#define MINK_EXP_EXAMPLE_H

#include <mink_exp/exp.h>

extern const char *const mkExample_Columns[];

/* One trial: draw two bodies from (seed, trial), write one row. */
mkResult mkExample_Trial(uint64_t seed, long trial, long n, mkCsv *csv);

#endif
