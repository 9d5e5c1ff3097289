/* test_extremes.c - the tiny run of the extremes driver (tests/CMakeLists.txt:
 * quick grid, first 4 cells of each dimension, both sets, closed-normal,
 * closed-gradient, geometric, hull-qhull, edge-sort; closed forms at 16
 * angles / a 3 x 3 grid, sampled methods at 16 / 3 x 3 per body).
 *
 * The scores come from the 256-bit MPFR reference, which shares no code
 * with the core's closed forms; the bars (docs/experiments/extremes.md): no non-finite
 * output from a closed form, and error_rel <= 1e-13 wherever the condition
 * is at most 1e-14. In 2D, qhull's hull and edge sorting are two libraries
 * computing the same polygon from the same samples: their rows must score
 * alike (1e-9 relative: the same vertices up to rounding), and a hull's
 * vertices (sums of boundary points whose normals differ) lie no nearer the
 * boundary than the closed forms' points. Every SPEC string must parse back. */
#include "extremes.h"
#include "ensure.h"

#include <math.h>
#include <string.h>

static int mkIs(const mkTable *t, long r, const char *col, const char *v)
{
	return strcmp(mkTable_Str(t, r, mkTable_Col(t, col)), v) == 0;
}

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	mkTable t;
	mkTable_Load(&t, argv[1]);
	ENSURE(t.present);
	for (int i = 0; mkExtremes_Columns[i]; ++i)
		ENSURE(t.present && mkTable_Col(&t, mkExtremes_Columns[i]) == i);
	long closed[4] = { 0, 0, 0, 0 }, geometric = 0, edge3 = 0;
	for (long r = 0; t.present && r < t.rows; ++r) {
		int dim = (int)mkTable_Num(&t, r, mkTable_Col(&t, "dim"));
		double err = mkTable_Num(&t, r, mkTable_Col(&t, "error_rel"));
		double cond = mkTable_Num(&t, r, mkTable_Col(&t, "condition"));
		ENSURE(dim == 2 || dim == 3);
		ENSURE(isfinite(cond) && cond > 0.0);
		int isClosed = mkIs(&t, r, "method", "closed-normal") || mkIs(&t, r, "method", "closed-gradient");
		if (isClosed) {
			closed[dim] += 1;
			ENSURE(mkIs(&t, r, "status", "ok") && mkIs(&t, r, "nonfinite", "0"));
			ENSURE_NEAR(mkTable_Num(&t, r, mkTable_Col(&t, "points")), dim == 2 ? 16 : 9, 0);
			if (cond <= MK_EXTREMES_COND_OK)
				ENSURE_LE(err, MK_EXTREMES_BAR);
		}
		if (mkIs(&t, r, "method", "hull-qhull") && dim == 2) {
			/* the driver writes edge-sort's row right after qhull's (registry order) */
			ENSURE(r + 1 < t.rows && mkIs(&t, r + 1, "method", "edge-sort"));
			ENSURE_NEAR(mkTable_Num(&t, r + 1, mkTable_Col(&t, "error_rel")), err, 1e-9 * err);
			long g = r - 1; /* the closed form's row of the same cell and set */
			while (g > 0 && !mkIs(&t, g, "method", "closed-gradient"))
				--g;
			ENSURE(mkIs(&t, g, "method", "closed-gradient") && mkIs(&t, g, "set", mkTable_Str(&t, r, mkTable_Col(&t, "set"))));
			ENSURE(err >= mkTable_Num(&t, g, mkTable_Col(&t, "error_rel")));
		}
		/* The geometric formula only where body 2 is an ellipse (eps = 1,
		 * and eps2 = 1 in 3D). */
		if (mkIs(&t, r, "method", "geometric")) {
			geometric += 1;
			ENSURE(mkTable_Num(&t, r, mkTable_Col(&t, "eps1_b2")) == 1.0);
			ENSURE(mkTable_Num(&t, r, mkTable_Col(&t, "eps2_b2")) == 1.0);
		}
		edge3 += dim == 3 && mkIs(&t, r, "method", "edge-sort");
		char msg[256];
		mkSpec s;
		ENSURE(mkSpec_Parse(mkTable_Str(&t, r, mkTable_Col(&t, "body1")), dim, "body1", &s, msg, sizeof msg) == MK_OK);
		ENSURE(mkSpec_Parse(mkTable_Str(&t, r, mkTable_Col(&t, "body2")), dim, "body2", &s, msg, sizeof msg) == MK_OK);
	}
	/* 4 cells x 2 sets x 2 closed forms per dimension. */
	ENSURE(closed[2] == 16 && closed[3] == 16);
	ENSURE(edge3 == 0);
	(void)geometric;
	mkTable_Free(&t);
	return mk_summary("extremes.check");
}
