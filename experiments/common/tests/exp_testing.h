/* exp_testing.h - small helpers the experiments' tests share: cells of a
 * result read back by column name, and the p-norm of a pair (the gauge of
 * a superellipse and the dual norm of its support function), written from
 * the definition. Header-only; include with the folder on the path. */
#ifndef MK_EXP_TESTING_H
#define MK_EXP_TESTING_H

#include <mink_exp/table.h>

#include <math.h>

/* A cell by column name: "" or NaN when the column is missing. */
static inline const char *str(const mkTable *t, long r, const char *name)
{
	return mkTable_Str(t, r, mkTable_Col(t, name));
}

static inline double num(const mkTable *t, long r, const char *name)
{
	return mkTable_Num(t, r, mkTable_Col(t, name));
}

/* ||(u, v)||_p for p >= 1, scaled by the larger entry so that powers up
 * to p = 2e6 neither overflow nor underflow harmfully. */
static inline double pnorm2(double u, double v, double p)
{
	u = fabs(u);
	v = fabs(v);
	double m = u > v ? u : v;
	if (m == 0.0)
		return 0.0;
	return m * pow(pow(u / m, p) + pow(v / m, p), 1.0 / p);
}

#endif
