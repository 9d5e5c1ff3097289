/* score.c - mink/score.h: the error measure plus a direction scan of the
 * support functions, and the inside / encloses verdicts. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/score.h>

/* The finite points, interleaved (dim per point), into *xy (allocated,
 * NULL on failure); returns how many. */
static int mkScore_Finite(const mkPointSet *pts, int dim, double **xy)
{
	*xy = malloc((size_t)dim * (size_t)(pts->count > 0 ? pts->count : 1) * sizeof **xy);
	if (!*xy) return -1;
	int m = 0;
	for (int k = 0; k < pts->count; ++k) {
		double p[3] = {pts->x[k], pts->y[k], dim == 3 ? pts->z[k] : 0.0};
		if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) continue;
		for (int i = 0; i < dim; ++i) (*xy)[(size_t)dim * m + i] = p[i];
		++m;
	}
	return m;
}

/* The hull's vertices of the finite points (CGAL, exact predicates); on a
 * hull failure (degenerate input) the finite points themselves, which have
 * the same support function. */
static mkResult mkScore_Vertices(const mkPointSet *pts, int dim, mkPointSet *v)
{
	double *xy;
	int m = mkScore_Finite(pts, dim, &xy);
	if (m < 0) return MK_ERR_MEMORY;
	mkResult r = MK_ERR_UNSUPPORTED;
	if (m >= dim + 1) r = dim == 2 ? mkHull2_CgalEpick(xy, m, v) : mkHull3_CgalEpick(xy, m, v);
	if (r != MK_OK) {
		r = mkPointSet_Resize(v, dim, m);
		for (int k = 0; r == MK_OK && k < m; ++k) {
			v->x[k] = xy[(size_t)dim * k];
			v->y[k] = xy[(size_t)dim * k + 1];
			if (dim == 3) v->z[k] = xy[(size_t)dim * k + 2];
		}
	}
	free(xy);
	return r;
}

static double mkScore_HullSupport(const mkPointSet *v, const double *n)
{
	double best = -HUGE_VAL;
	for (int k = 0; k < v->count; ++k) {
		double s = n[0] * v->x[k] + n[1] * v->y[k] + (v->dim == 3 ? n[2] * v->z[k] : 0.0);
		if (s > best) best = s;
	}
	return best;
}

/* One scanned direction: keep it when |h_P - h_K| is the largest so far. */
static void mkScore_Take(mkScore *out, const double *n, double hk, double hp)
{
	double d = hp - hk;
	if (fabs(d) > out->support_gap || out->directions == 0) {
		out->support_gap = fabs(d);
		out->worst_signed = d;
		memcpy(out->worst_dir, n, sizeof out->worst_dir);
	}
	++out->directions;
}

static void mkScore_Verdicts(mkScore *out)
{
	out->allowance = 64.0 * (DBL_EPSILON / 2) * out->dev.size;
	out->inside = out->dev.nonfinite == 0 && out->dev.gap_out <= out->allowance;
	out->encloses = out->dev.nonfinite == 0 && out->dev.gap_in <= out->allowance;
}

/* The bodies of either dimension: b2 (2D) or b3 (3D), by dim. */
typedef struct mkScore_Pair {
	int dim;
	mkBody2 b2[2];
	mkBody3 b3[2];
	mkSet set;
} mkScore_Pair;

static double mkScore_SupportK(const mkScore_Pair *q, const double *n)
{
	return q->dim == 2 ? mkDeviation2_Support(q->b2[0], q->b2[1], q->set, (mkVec2){n[0], n[1]}, NULL)
		: mkDeviation3_Support(q->b3[0], q->b3[1], q->set, (mkVec3){n[0], n[1], n[2]}, NULL);
}

/* The directions scanned: 2D MK_SCORE2_DIRECTIONS angles, 3D the
 * MK_SCORE3_GRID grid of mkSample3_Grid; structure-of-arrays in *u
 * (allocated), their count returned (-1 on failure). */
static int mkScore_Directions(int dim, double **u)
{
	int count = dim == 2 ? MK_SCORE2_DIRECTIONS : MK_SCORE3_GRID * MK_SCORE3_GRID;
	*u = malloc(3 * (size_t)count * sizeof **u);
	if (!*u) return -1;
	double *ux = *u, *uy = *u + count, *uz = *u + 2 * (size_t)count;
	if (dim == 3) return mkSample3_Grid(MK_SCORE3_GRID, ux, uy, uz) == MK_OK ? count : -1;
	const double pi = 3.14159265358979323846;
	for (int i = 0; i < count; ++i) {
		ux[i] = cos(2.0 * pi * i / count);
		uy[i] = sin(2.0 * pi * i / count);
		uz[i] = 0.0;
	}
	return count;
}

static mkResult mkScore_Run(const mkScore_Pair *q, const mkPointSet *pts, const mkDeviationOptions *opt,
	mkScore *out)
{
	if (!pts || !out || pts->dim != q->dim) return MK_ERR_ARGUMENT;
	memset(out, 0, sizeof *out);
	mkResult r = q->dim == 2 ? mkDeviation2_Measure(q->b2[0], q->b2[1], q->set, pts, opt, &out->dev)
		: mkDeviation3_Measure(q->b3[0], q->b3[1], q->set, pts, opt, &out->dev);
	if (r != MK_OK) return r;
	mkScore_Verdicts(out);
	double *u;
	int count = mkScore_Directions(q->dim, &u);
	if (count < 0) {
		free(u);
		return MK_ERR_MEMORY;
	}
	mkPointSet v = {0};
	r = mkScore_Vertices(pts, q->dim, &v);
	for (int i = 0; r == MK_OK && v.count > 0 && i < count; ++i) {
		double n[3] = {u[i], u[count + i], u[2 * (size_t)count + i]};
		mkScore_Take(out, n, mkScore_SupportK(q, n), mkScore_HullSupport(&v, n));
	}
	mkPointSet_Free(&v);
	free(u);
	return r;
}

mkResult mkScore2_Points(mkBody2 b1, mkBody2 b2, mkSet set, const mkPointSet *pts,
	const mkDeviationOptions *opt, mkScore *out)
{
	mkScore_Pair q = {.dim = 2, .b2 = {b1, b2}, .set = set};
	return mkScore_Run(&q, pts, opt, out);
}

mkResult mkScore3_Points(mkBody3 b1, mkBody3 b2, mkSet set, const mkPointSet *pts,
	const mkDeviationOptions *opt, mkScore *out)
{
	mkScore_Pair q = {.dim = 3, .b3 = {b1, b2}, .set = set};
	return mkScore_Run(&q, pts, opt, out);
}
