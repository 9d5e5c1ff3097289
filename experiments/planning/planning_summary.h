/* planning_summary.h - the planning experiment's section of the tables
 * (results/tables.md): success, median times and their ratio per scene and
 * planner, the certification of the returned paths, and success against
 * the time budget. Its own library (no OMPL), which `tables` links. */
#ifndef MINK_EXP_PLANNING_SUMMARY_H
#define MINK_EXP_PLANNING_SUMMARY_H

#include <mink_exp/exp.h>

#define MK_PLANNING_BUDGETS 38        /* budgets compared, log-spaced */
#define MK_PLANNING_BUDGET_MIN 1e-3   /* the smallest, seconds */

/* The section, from <dir>/planning.csv and its sidecar. */
void mkPlanning_Summary(mkDoc *d, const char *dir, mkTally *tally);

/* Budget k of the MK_PLANNING_BUDGETS from MK_PLANNING_BUDGET_MIN to top
 * (log-spaced; the last is top). */
double mkPlanning_Budget(int k, double top);

/* One-sided Fisher exact test: the chance, if both groups had the same
 * success rate, that the second group (s1 of n1 runs) has s1 or more of the
 * s0 + s1 successes (hypergeometric upper tail). */
double mkPlanning_Fisher(long s0, long n0, long s1, long n1);

#endif
