/* test_summary.c - the extremes section of the tables (mkExtremes_Summary)
 * on rows written here, every expected cell worked out by hand:
 *  - 2D closed-gradient: cell 0 error 1e-16 at condition 1e-16, cell 1
 *    error 5e-13 at condition 1e-15. Both within 1e-12 ("2 of 2"); the worst
 *    is cell 1; its condition is at most 1e-14 and its error above 1e-13, so
 *    the bar "**fails** on 1 of 2 rows".
 *  - 3D closed-gradient: one row at 1e-15, condition 1e-16: "holds (1 rows)".
 *  - 2D hull-qhull: 2e-2 (not within 1e-12) and an error row (empty error,
 *    status error:...): "0 of 2", 1 error row, no bar (a sampled method).
 *  - "my-method", unknown to the registry and first in the file: its row
 *    comes last, with 3 non-finite points counted.
 * A missing result gives the "not reproduced yet" line; the tally is never
 * touched (the paper publishes no number of this experiment). */
#include "extremes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ensure.h"
#include "summary_text.h"

static const char *mkDir;

/* The hand-made result: header and rows, one string each. */
static const char *const mkRows[] = {
	"dim,cell,family,set,method,n,points,eps1_b1,eps2_b1,eps1_b2,eps2_b2,axis,shear,size,shift,"
	"error_abs,error_rel,accuracy,condition,nonfinite,status,body1,body2",
	"2,0,eps,contact,my-method,16,16,1,1,1,1,1,0,1,0,1e-3,1e-3,0,1e-16,3,nonfinite,x,y",
	"2,0,eps,contact,closed-gradient,16,16,0.5,0.5,1,1,1,0,1,0,1e-16,1e-16,0,1e-16,0,ok,x,y",
	"2,1,eps,contact,closed-gradient,16,16,0.5,0.5,2,2,1,0,1,0,5e-13,5e-13,0,1e-15,0,ok,x,y",
	"2,0,eps,plus,hull-qhull,16,30,0.5,0.5,1,1,1,0,1,0,2e-2,2e-2,0,1e-16,0,ok,x,y",
	"2,1,eps,plus,hull-qhull,16,0,0.5,0.5,2,2,1,0,1,0,,,,1e-16,0,error:invalid argument,x,y",
	"3,0,eps,contact,closed-gradient,3,9,0.5,0.5,1,1,1,0,1,0,1e-15,1e-15,0,1e-16,0,ok,x,y",
};

static void mkTestTable(void)
{
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/extremes.csv", mkDir);
	FILE *fp = fopen(path, "w");
	ENSURE(fp != NULL);
	for (size_t i = 0; fp && i < sizeof mkRows / sizeof mkRows[0]; ++i)
		fprintf(fp, "%s\n", mkRows[i]);
	if (fp)
		fclose(fp);
	mkTally tally = { 0, 0, 0 };
	char *md = mkSummary_Text(mkExtremes_Summary, mkDir, &tally);
	mkSummary_Expect(md, "| closed-gradient | 2D | 2 | 2 of 2 | 5.0000e-13 | eps 1 contact, ε (0.5, 0.5) / (2, 2) | 0 | "
		"0 | **fails** on 1 of 2 rows |");
	mkSummary_Expect(md, "| closed-gradient | 3D | 1 | 1 of 1 | 1.0000e-15 | eps 0 contact, ε (0.5, 0.5) / (1, 1) | 0 | "
		"0 | holds (1 rows) |");
	mkSummary_Expect(md, "| hull-qhull | 2D | 2 | 0 of 2 | 2.0000e-02 | eps 0 plus, ε (0.5, 0.5) / (1, 1) | 0 | 1 | — |");
	mkSummary_Expect(md, "| my-method | 2D | 1 | 0 of 1 | 1.0000e-03 | eps 0 contact, ε (1, 1) / (1, 1) | 3 | 0 | — |");
	const char *cg = strstr(md, "| closed-gradient | 3D"), *qh = strstr(md, "| hull-qhull |");
	const char *mine = strstr(md, "| my-method |");
	ENSURE(cg && qh && mine && cg < qh && qh < mine);
	ENSURE(tally.published == 0 && tally.reproduced == 0 && tally.missing == 0);
	free(md);
}

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	mkDir = argv[1];
	mkTestTable();
	/* No result at all: the section says so, the tally stays as it was. */
	mkTally tally = { 1, 2, 3 };
	mkSummary_ExpectMissing(mkExtremes_Summary, mkDir, "extremes", &tally);
	ENSURE(tally.published == 1 && tally.reproduced == 2 && tally.missing == 3);
	return 0;
}
