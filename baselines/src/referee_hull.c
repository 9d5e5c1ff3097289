/* referee_hull.c - the referee's hull check of sampled methods
 * (mink/referee.h): the method's input sums rebuilt, then CGAL's exact
 * check that the output is exactly their extreme points (referee_cgal.cpp),
 * with the allowance for edge sorting's roundings and Qhull's merges. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/referee.h>
#include <mink/registry.h>

#include "referee_cgal.h"

/* ---- the hull check ------------------------------------------------------- */

static int all_finite(const mkPointSet *p)
{
	for (int k = 0; k < p->count; ++k)
		if (!isfinite(p->x[k]) || !isfinite(p->y[k]) || (p->dim == 3 && !isfinite(p->z[k]))) return 0;
	return 1;
}

static void hull_verdict(mkVerdict *v, const mkHullReport *h, double coord_max)
{
	v->convex = h->convex;
	v->subset = h->subset;
	v->extreme = h->extreme;
	v->outside = h->outside;
	v->outside_max = h->outside_max;
	v->outside_tol = MK_REFEREE_HULL_ULPS * (DBL_EPSILON / 2) * coord_max;
	int measured_all = h->measured == h->outside;
	int within = h->outside == 0 || (measured_all && h->outside_max <= v->outside_tol);
	v->pass = h->convex && h->subset && within;
	if (h->outside && measured_all)
		snprintf(v->message, sizeof v->message,
			"%s: %d vertices of %d input sums; %s%s%s; %d input sums outside, by at most %.3g (allowance %.3g)%s%.120s",
			v->pass ? "PASS" : "FAIL", v->points, v->inputs, h->convex ? "convex" : "NOT convex",
			h->subset ? ", vertices are input sums" : ", vertices NOT all input sums",
			v->pass ? "" : "", h->outside, h->outside_max, v->outside_tol, h->why[0] ? "; " : "", h->why);
	else
		snprintf(v->message, sizeof v->message, "%s: %d vertices of %d input sums; %s; %s; %s%s%.120s",
			v->pass ? "PASS" : "FAIL", v->points, v->inputs, h->convex ? "convex" : "NOT convex",
			h->subset ? "vertices are input sums" : "vertices NOT all input sums",
			h->extreme ? "exactly the extreme points" : (h->convex ? "input sums outside" : "extremality not decided"),
			h->why[0] ? "; " : "", h->why);
}

/* The part of the hull check before the input is rebuilt: 0, with the
 * verdict written, when the output has points that are not finite. */
static int hull_start(mkVerdict *v, const mkPointSet *out, long ns)
{
	memset(v, 0, sizeof *v);
	v->kind = MK_VERDICT_HULL;
	v->points = out->count;
	v->worst = -1;
	v->inputs = (int)ns;
	if (all_finite(out)) return 1;
	v->nonfinite = 1;
	snprintf(v->message, sizeof v->message, "FAIL: the output has points that are not finite");
	return 0;
}

/* The verdict from the exact check's return code rc and report h, with
 * the allowance scaled by the largest of the input's `values` coordinates. */
static mkResult hull_finish(mkVerdict *v, int rc, const mkHullReport *h, const double *s, long values)
{
	if (rc) return rc == -1 ? MK_ERR_MEMORY : MK_ERR_UNSUPPORTED;
	double cmax = 0;
	for (long k = 0; k < values; ++k) cmax = fmax(cmax, fabs(s[k]));
	hull_verdict(v, h, cmax);
	return MK_OK;
}

mkResult mkReferee2_Hull(mkBody2 b1, mkBody2 b2, mkSet set, int n, const mkPointSet *out, mkVerdict *v)
{
	if (!out || !v || out->dim != 2 || n < 1 || n > MK_HULL2_N_MAX) return MK_ERR_ARGUMENT;
	long ns = (long)n * n;
	if (!hull_start(v, out, ns)) return MK_OK;
	double *pq = malloc(4 * (size_t)n * sizeof *pq), *s = malloc(2 * (size_t)ns * sizeof *s);
	mkResult r = pq && s ? MK_OK : MK_ERR_MEMORY;
	if (r == MK_OK) r = mkSampled2_Bodies(b1, b2, set, n, pq, pq + 2 * n);
	if (r == MK_OK) {
		mkSampled2_Sums(pq, n, pq + 2 * n, n, s);
		mkHullReport h;
		int rc = mkRefereeCgal_Polygon(out->x, out->y, out->count, s, ns, &h);
		r = hull_finish(v, rc, &h, s, 2 * ns);
	}
	free(pq);
	free(s);
	return r;
}

mkResult mkReferee3_Hull(mkBody3 b1, mkBody3 b2, mkSet set, int n, const mkPointSet *out, mkVerdict *v)
{
	if (!out || !v || out->dim != 3 || n < 2 || n > MK_HULL3_N_MAX) return MK_ERR_ARGUMENT;
	int per = n * n;
	long ns = (long)per * per;
	if (!hull_start(v, out, ns)) return MK_OK;
	double *pq = malloc(6 * (size_t)per * sizeof *pq), *s = malloc(3 * (size_t)ns * sizeof *s);
	mkResult r = pq && s ? MK_OK : MK_ERR_MEMORY;
	if (r == MK_OK) r = mkSampled3_Bodies(b1, b2, set, n, pq, pq + 3 * (size_t)per);
	if (r == MK_OK) {
		mkSampled3_Sums(pq, per, pq + 3 * (size_t)per, per, s);
		mkHullReport h;
		int rc = mkRefereeCgal_Polytope(out->x, out->y, out->z, out->count, s, ns, &h);
		r = hull_finish(v, rc, &h, s, 3 * ns);
	}
	free(pq);
	free(s);
	return r;
}

