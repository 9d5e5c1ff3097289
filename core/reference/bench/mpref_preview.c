/* mpref_preview.c - a preview of the extremes experiment on the core's
 * closed forms alone: every grid cell, both sets, the normal, gradient and
 * printed (paper) forms at surface parameters (the registry's closed-*
 * methods), scored by the 256-bit reference, with the problem's condition
 * and the time each part takes. It prints one line per cell, form and set,
 * then the worst cell per form and the cost per point; it writes no result
 * file (the experiment proper is the extremes driver). The normal form's
 * points are scored a second time without their parameters, as a sampled
 * hull's vertices would be (a scan of the sphere per point): the two scores
 * must agree (this is the unparameterised path's worst case: every point is
 * within its margin, so every point is searched; 2D only, as in 3D it costs
 * minutes per cell at the kinks). Last, hull-like points
 * (B1's point of one parameter plus B2's part of the next) are scored without
 * parameters: the cost model of the sampled methods.
 *
 *   mpref_preview [quick|full] [2|3] [N]
 * N: parameters per cell (2D n angles, 3D an n x n grid); defaults 64 / 8. */
#define _POSIX_C_SOURCE 200809L
#include <mink/mink.h>
#include <mink/mpref_grid.h>
#include <mink/mpref_measure.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Process CPU time: the machine is shared, so wall time measures the
 * neighbours. */
static double now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Timings and counts of the extra scorings of the normal form. */
typedef struct refPreviewStats {
	double tBlind, blindDiff, tHull;
	long blindScored, hullSearched;
} refPreviewStats;

/* The normal form's points scored again without their parameters (as hull
 * vertices are; 2D), and hull-like points scored. */
static void previewExtra(const refCell *cell, int plus, int dim, int count, const double *x, const double *y,
	const double *z, double *kx, double *ky, double *kz, const refScore *sc, refPreviewStats *st)
{
	if (dim == 2) {
		refScore blind;
		double t0 = now();
		refSum_Score(&cell->b1, &cell->b2, plus, x, y, NULL, count, NULL, NULL, NULL, &blind);
		st->tBlind += now() - t0;
		double dd = fabs(blind.errorRel - sc->errorRel) / (sc->errorRel > 0 ? sc->errorRel : 1.0);
		if (dd > st->blindDiff)
			st->blindDiff = dd;
	}
	st->blindScored += count;
	/* Hull-like points: B1's point of parameter i plus B2's
	 * part of parameter i + 1 (a sum of two boundary points
	 * with different normals, as a hull vertex is). */
	double *hx = kx, *hy = ky, *hz = kz; /* reused in place */
	for (int i = 0; i < count; ++i) {
		int j = (i + 1) % count;
		hx[i] = kx[i] + (x[j] - kx[j]);
		hy[i] = ky[i] + (y[j] - ky[j]);
		if (dim == 3)
			hz[i] = kz[i] + (z[j] - kz[j]);
	}
	refScore hull;
	double t0 = now();
	refSum_Score(&cell->b1, &cell->b2, plus, hx, hy, dim == 3 ? hz : NULL, count, NULL, NULL, NULL, &hull);
	st->tHull += now() - t0;
	st->hullSearched += hull.searched;
}

int main(int argc, char **argv)
{
	refGridKind kind = REF_GRID_QUICK;
	char msg[256];
	if (argc > 1 && refGrid_Parse(argv[1], "grid", &kind, msg, sizeof msg) != 0) {
		fprintf(stderr, "%s\n", msg);
		return 2;
	}
	int dim = argc > 2 ? atoi(argv[2]) : 2;
	if (dim != 2 && dim != 3) {
		fprintf(stderr, "dim = %s is out of range: must be 2 or 3\n", argv[2]);
		return 2;
	}
	int n = argc > 3 ? atoi(argv[3]) : (dim == 2 ? 64 : 8);
	if (n < 2 || n > 4096) {
		fprintf(stderr, "N = %d is out of range: must be in [2, 4096]\n", n);
		return 2;
	}
	int count = dim == 2 ? n : n * n;
	double *buf = malloc(sizeof(double) * 9 * (size_t)count);
	if (!buf)
		return 1;
	double *ux = buf, *uy = buf + count, *uz = buf + 2 * count;
	double *x = buf + 3 * count, *y = buf + 4 * count, *z = buf + 5 * count;
	double *kx = buf + 6 * count, *ky = buf + 7 * count, *kz = buf + 8 * count;
	if (dim == 2)
		mkSample2_Angles(n, ux, uy);
	else
		mkSample3_Grid(n, ux, uy, uz);
	static const char *formName[3] = { "closed-normal", "closed-gradient", "closed-paper" };
	double worst[3] = { 0, 0, 0 };
	char worstCell[3][3 * REF_SPEC_MAX] = { "", "", "" };
	double tScore = 0.0, tCond = 0.0, tCore = 0.0;
	refPreviewStats extra = { 0.0, 0.0, 0.0, 0, 0 };
	long scored = 0, refinedAll = 0, nonfiniteAll[3] = { 0, 0, 0 }, errors[3] = { 0, 0, 0 };
	int cells = refGrid_Count(kind, dim);
	printf("dim,family,eps1,eps2,axis,shear,size,shift,set,method,n,error_rel,condition,cond_point,nonfinite,status,refined,accuracy\n");
	for (int c = 0; c < cells; ++c) {
		refCell cell;
		refGrid_Cell(kind, dim, c, &cell);
		mkSpec s1, s2;
		if (mkSpec_Parse(cell.spec1, dim, "body1", &s1, msg, sizeof msg) != MK_OK
			|| mkSpec_Parse(cell.spec2, dim, "body2", &s2, msg, sizeof msg) != MK_OK) {
			printf("cell %d: %s\n", c, msg);
			return 1;
		}
		for (int plus = 0; plus <= 1; ++plus) {
			double t0 = now();
			refCondition cond;
			refSum_Condition(&cell.b1, &cell.b2, plus, dim == 2 ? 16 : 5, 3, 1000u + (unsigned)c, &cond);
			tCond += now() - t0;
			for (int f = 0; f < 3; ++f) {
				mkSumOptions opt = mkSumOptions_Default();
				opt.set = plus ? MK_SET_PLUS : MK_SET_CONTACT;
				opt.param = MK_PARAM_SURFACE;
				opt.form = (mkForm)f;
				if (f == 2)
					opt.impl = MK_IMPL_SCALAR;
				t0 = now();
				mkResult r = dim == 2
					? mkSum2_Batch(s1.body2, s2.body2, &opt, ux, uy, count, x, y, kx, ky)
					: mkSum3_Batch(s1.body3, s2.body3, &opt, ux, uy, uz, count, x, y, z, kx, ky, kz);
				tCore += now() - t0;
				refScore sc;
				memset(&sc, 0, sizeof sc);
				if (r == MK_OK) {
					t0 = now();
					refSum_Score(&cell.b1, &cell.b2, plus, x, y, dim == 3 ? z : NULL, count,
						ux, uy, dim == 3 ? uz : NULL, &sc);
					tScore += now() - t0;
					scored += count;
					refinedAll += sc.refined;
					nonfiniteAll[f] += sc.nonfinite;
					if (f == 0)
						previewExtra(&cell, plus, dim, count, x, y, z, kx, ky, kz, &sc, &extra);
				} else {
					errors[f]++;
				}
				printf("%d,%s,%.17g,%.17g,%g,%g,%g,%g,%s,%s,%d,%.3e,%.3e,%.3e,%ld,%d,%ld,%.1e\n", dim, cell.family,
					cell.eps[0][0], dim == 2 ? cell.eps[1][0] : cell.eps[0][1], cell.axis, cell.shear, cell.size,
					cell.shift, plus ? "plus" : "contact", formName[f], n, sc.errorRel, cond.value, cond.point,
					sc.nonfinite, (int)r, sc.refined, sc.accuracy);
				if (r == MK_OK && sc.errorRel > worst[f]) {
					worst[f] = sc.errorRel;
					snprintf(worstCell[f], sizeof worstCell[f], "%s cell %d set %s | %s | %s (condition %.2e)",
						cell.family, c, plus ? "plus" : "contact", cell.spec1, cell.spec2, cond.value);
				}
			}
			fflush(stdout);
		}
	}
	for (int f = 0; f < 3; ++f)
		fprintf(stderr, "%s: worst error_rel %.3e at %s; %ld non-finite outputs, %ld error returns\n",
			formName[f], worst[f], worstCell[f], nonfiniteAll[f], errors[f]);
	fprintf(stderr, "%dD %s grid, %d cells, N = %d: scoring %.2f s (%.1f us per point, %ld points needed the "
		"derivative-free search), condition %.2f s, core %.3f s (CPU)\n", dim, kind == REF_GRID_FULL ? "full" : "quick",
		cells, n, tScore, 1e6 * tScore / (double)(scored ? scored : 1), refinedAll, tCond, tCore);
	fprintf(stderr, "without parameters (as hull vertices): %.2f s, %.1f us per point; largest relative difference "
		"of the two scores %.2e\n", extra.tBlind, 1e6 * extra.tBlind / (double)(extra.blindScored ? extra.blindScored : 1), extra.blindDiff);
	fprintf(stderr, "hull-like points (mismatched pairs of boundary points): %.2f s, %.1f us per point, "
		"%ld of %ld searched at 256 bits\n", extra.tHull, 1e6 * extra.tHull / (double)(extra.blindScored ? extra.blindScored : 1),
		extra.hullSearched, extra.blindScored);
	free(buf);
	return 0;
}
