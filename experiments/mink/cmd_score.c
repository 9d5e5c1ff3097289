/* cmd_score.c - `mink score`: the error of any boundary point set (a CSV of
 * points, from any program) against the true sum, by the independent error
 * measure (mink/score.h, mink/error.h). */
#include <stdio.h>
#include <string.h>

#include <mink/score.h>

#include "cli.h"
#include "commands.h"
#include "faces.h"
#include "points.h"

static void help(FILE *fp)
{
	fprintf(fp, "usage: mink score --dim 2|3 --body1 SPEC --body2 SPEC --points FILE [--set contact|plus]\n"
		"                  [--faces FILE] [--csv]\n"
		"\n"
		"Measure how far the points in FILE are from the true boundary of the contact\n"
		"set B1 (+) (-B2) (default; body 2's translation drops out) or of B1 (+) B2\n"
		"(--set plus), with the error measure of the baselines (mink/error.h), which\n"
		"uses only the bodies' parameters and shares nothing with mink's closed forms.\n"
		"The points may come from any program, in any order. Printed: the Hausdorff\n"
		"distance between their convex hull P and the true set K (absolute, relative to\n"
		"the sum's size S, and its bound), its two one-sided parts (gap_in: K beyond P;\n"
		"gap_out: points outside K), the points' largest distance off the boundary,\n"
		"the relative area (3D: volume) error, the support gap max |h_K - h_P| over a\n"
		"scan of directions and the worst direction, and whether P lies inside K and\n"
		"whether it encloses K (within the rounding allowance 64 u S).\n"
		"--points: a CSV with a header naming columns x, y (and z), as 'mink sum'\n"
		"writes, or no header and x, y[, z] first; '-' for standard input; lines\n"
		"starting with # are skipped. Bad input names the file, line and column.\n"
		"--faces (3D): the points' triangles, one i,j,k per line (0-based point\n"
		"indices; a header naming i, j, k selects those columns, so the .faces.csv of\n"
		"'mink scene' reads as it is). The measure takes the points' convex hull, so\n"
		"the faces are checked to close a convex surface over the points (every edge\n"
		"shared by two triangles in opposite directions, no point outside a triangle's\n"
		"plane by more than 1e-9 of the points' extent), which makes them that hull's\n"
		"boundary: the figures are then those of the faces, and the volume they\n"
		"enclose is printed (CSV: columns faces, faces_volume at the end). Faces that\n"
		"fail the check, or a bad index (file, line, column, allowed range): exit 2.\n"
		"--csv: one header line and one row instead of the text.\n"
		"Exit status: 0 when measured, 2 on bad input.\n\n");
}

static const char *const mkScoreColumns =
	"points,nonfinite,vertices,size,hausdorff_abs,hausdorff_rel,hausdorff_bound,gap_in,gap_out,"
	"off_boundary_max,off_boundary_rel,off_boundary_bound,worst_point,measure_rel,measure_bound,"
	"support_gap,worst_dir_x,worst_dir_y,worst_dir_z,worst_signed,inside,encloses,allowance";

static void mkScore_PrintCsv(const mkScore *s, const mkFaces_Check *faces)
{
	const mkDeviation *d = &s->dev;
	printf("%s%s\n", mkScoreColumns, faces ? ",faces,faces_volume" : "");
	printf("%d,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
		"%.17g,%d,%d,%.17g",
		d->points, d->nonfinite, d->vertices, d->size, d->hausdorff_abs, d->hausdorff_rel, d->hausdorff_bound,
		d->gap_in, d->gap_out, d->off_boundary_max, d->off_boundary_rel, d->off_boundary_bound, d->worst,
		d->area_rel, d->area_bound, s->support_gap, s->worst_dir[0], s->worst_dir[1], s->worst_dir[2],
		s->worst_signed, s->inside, s->encloses, s->allowance);
	if (faces) printf(",%d,%.17g", faces->faces, faces->volume);
	printf("\n");
}

static void mkScore_PrintText(const mkScore *s, int dim)
{
	const mkDeviation *d = &s->dev;
	printf("points             %d (%d not finite), %d hull vertices\n", d->points, d->nonfinite, d->vertices);
	printf("size S             %.6g (the sum's size, mkSum%d_Size)\n", d->size, dim);
	printf("hausdorff          %.6g absolute, %.6g of S (bound %.3g)\n", d->hausdorff_abs, d->hausdorff_rel,
		d->hausdorff_bound);
	printf("  gap_in           %.6g (how far K reaches beyond the points' hull)\n", d->gap_in);
	printf("  gap_out          %.6g (how far a point lies outside K)\n", d->gap_out);
	printf("off boundary       %.6g absolute, %.6g of S (worst point %d, bound %.3g)\n", d->off_boundary_max,
		d->off_boundary_rel, d->worst, d->off_boundary_bound);
	printf("%-19s%.6g relative (bound %.3g)\n", dim == 2 ? "area error" : "volume error", d->area_rel, d->area_bound);
	printf("support gap        %.6g over %d directions; worst direction (%.6f, %.6f%s", s->support_gap, s->directions,
		s->worst_dir[0], s->worst_dir[1], dim == 3 ? ", " : ")");
	if (dim == 3) printf("%.6f)", s->worst_dir[2]);
	printf(", h_P - h_K = %.6g there\n", s->worst_signed);
	printf("inside K           %s\n", s->inside ? "yes" : "no");
	printf("encloses K         %s (allowance %.3g = 64 u S)\n", s->encloses ? "yes" : "no", s->allowance);
}

int mkCmd_Score(int argc, char **argv)
{
	const char *spec1 = NULL, *spec2 = NULL, *points = NULL, *faces = NULL;
	long dim = 0;
	int setc = 0, csv = 0;
	mkFlag flags[] = {
		MK_FLAG_LONG("--dim", "2|3", "dimension (required)", &dim, 2, 3),
		MK_FLAG_TEXT("--body1", "SPEC", "the first body (required)", &spec1, NULL),
		MK_FLAG_TEXT("--body2", "SPEC", "the second body (required)", &spec2, NULL),
		MK_FLAG_TEXT("--points", "FILE", "the points as CSV (x,y[,z]), '-' for standard input (required)", &points,
			NULL),
		MK_FLAG_SET("--set", "the set the points are of (default contact)", &setc),
		MK_FLAG_TEXT("--faces", "FILE", "3D: the points' triangles (i,j,k per line), checked to close\n"
			"a convex surface over them", &faces, NULL),
		MK_FLAG_SWITCH("--csv", "one header line and one row of figures", &csv),
	};
	int rc = mkCli_Parse("score", flags, MK_COUNT(flags), argc, argv, help);
	if (rc != MK_CLI_GO) return rc;
	for (int k = 0; k < 4; ++k)
		if ((rc = mkCli_Require("score", &flags[k])) != MK_CLI_GO) return rc;
	mkSet set = setc == 0 ? MK_SET_CONTACT : MK_SET_PLUS;
	mkSpec s1, s2;
	char msg[512];
	if (mkSpec_Parse(spec1, (int)dim, "body1", &s1, msg, sizeof msg) != MK_OK
		|| mkSpec_Parse(spec2, (int)dim, "body2", &s2, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "mink score: %s\n", msg);
		return 2;
	}
	mkPointSet pts = {0};
	if (mkPoints_Read("score", points, (int)dim, &pts)) {
		mkPointSet_Free(&pts);
		return 2;
	}
	mkFaces_Check fc = {0};
	if (faces && dim != 3) {
		fprintf(stderr, "mink score: --faces is for --dim 3 only (2D boundaries need no triangles)\n");
		mkPointSet_Free(&pts);
		return 2;
	}
	if (faces && mkFaces_Check3(faces, &pts, &fc)) {
		mkPointSet_Free(&pts);
		return 2;
	}
	mkScore s;
	mkResult r = dim == 2 ? mkScore2_Points(s1.body2, s2.body2, set, &pts, NULL, &s)
		: mkScore3_Points(s1.body3, s2.body3, set, &pts, NULL, &s);
	mkPointSet_Free(&pts);
	if (r != MK_OK) {
		fprintf(stderr, "mink score: the error measure could not run: %s\n", mkResult_Name(r));
		return 2;
	}
	if (csv)
		mkScore_PrintCsv(&s, faces ? &fc : NULL);
	else
		mkScore_PrintText(&s, (int)dim);
	if (faces && !csv)
		printf("faces              %d triangles, a closed convex surface over the points; volume %.17g\n",
			fc.faces, fc.volume);
	if (fflush(stdout)) {
		fprintf(stderr, "mink score: writing to standard output failed\n");
		return 2;
	}
	return 0;
}
