/* fitting.h - the fitting experiment of paper Sec. 6.2 as the driver and
 * the tables see it: its CSV columns, its rows and its summary. The cases
 * themselves are in cases.h, the fits in sqfit.h, hulls in hull.h. */
#ifndef MK_FIT_FITTING_H
#define MK_FIT_FITTING_H

#include <mink_exp/exp.h>

#include "cases.h"

#define MK_FIT_SCHEMA 1

/* The CSV's columns, ended by NULL. */
extern const char *const mkFitting_Columns[];

/* One row of the CSV. */
void mkFitting_WriteRow(mkCsv *csv, const mkFitRow *r);

/* The section of the tables: <dir>/fitting.csv beside the paper's means. */
void mkFitting_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
