/* test_summary.c - the tradeoff section of the tables (mkTradeoff_Summary)
 * on a result file written here, every expected text worked out by hand:
 * 2D SQ with
 *  - closed-normal at n = 10, 100, 1000, two pairs per level: seconds
 *    0.5e-6 and 1.5e-6 (median 1e-6), errors 4e-3 and 6e-3 (median 5e-3) at
 *    n = 10; then one pair: 1e-5 s / 5e-5 and 1e-4 s / 5e-7;
 *  - hull-qhull at n = 10 (1e-4 s, error 1e-2) and 100 (1e-2 s, 1e-4);
 *  - "my-baseline", a name no code knows, at n = 10: 1e-7 s, error 2e-2,
 *    faster than every closed-form point, so a baseline wins there.
 * Then: to reach 1e-2 the closed form needs 1e-6 s, hull-qhull 1e-4 s: a
 * speed-up of 100; to reach 1e-3, 1e-5 s against 1e-2 s: 1000 (printed
 * 1e+03); 1e-6 only the closed form reaches; 1e-9 nobody. At equal time,
 * hull-qhull's points (1e-4 s, 1e-2) and (1e-2 s, 1e-4) face the closed
 * form's best error 5e-7 in no more time: ratios 2e4 and 200, at least 200.
 * In 3D EE a baseline is faster: "fast-baseline" reaches 1e-3 in 1e-4 s, the
 * closed form in 1e-3 s: the baseline is 10 times as fast and wins there.
 * A missing result gives the "not reproduced yet" line. */
#include "tradeoff.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ensure.h"
#include "summary_text.h"

static const char *mkDir;

static void mkTestTables(void)
{
	mkTally tally = { 0, 0, 0 };
	static const char *const files[2][2] = {
		{ "tradeoff.csv", "dim,case,method,set,n,trial,points,seconds,hausdorff_abs,hausdorff_rel,area_rel,"
			"nonfinite,body1,body2\n"
			"2,SQ,my-baseline,contact,10,0,10,1e-7,0,2e-2,0,0,x,y\n"
			"2,SQ,closed-normal,contact,10,0,10,0.5e-6,0,4e-3,0,0,x,y\n"
			"2,SQ,closed-normal,contact,10,1,10,1.5e-6,0,6e-3,0,0,x,y\n"
			"2,SQ,closed-normal,contact,100,0,100,1e-5,0,5e-5,0,0,x,y\n"
			"2,SQ,closed-normal,contact,1000,0,1000,1e-4,0,5e-7,0,0,x,y\n"
			"2,SQ,hull-qhull,contact,10,0,20,1e-4,0,1e-2,0,0,x,y\n"
			"2,SQ,hull-qhull,contact,100,0,200,1e-2,0,1e-4,0,0,x,y\n"
			"3,EE,closed-normal,contact,4,0,16,1e-3,0,1e-3,0,0,x,y\n"
			"3,EE,fast-baseline,contact,4,0,16,1e-4,0,1e-3,0,0,x,y\n" },
		{ "tradeoff.csv.meta", "experiment: tradeoff\nseed: 1\ntrials: 2\ncut: none\n" },
	};
	for (int i = 0; i < 2; ++i) {
		char path[MK_PATH_MAX];
		snprintf(path, sizeof path, "%s/%s", mkDir, files[i][0]);
		FILE *fp = fopen(path, "w");
		ENSURE(fp != NULL && fputs(files[i][1], fp) >= 0 && fclose(fp) == 0);
	}
	/* The table: one row per method, in order of first appearance. */
	char *md = mkSummary_Text(mkTradeoff_Summary, mkDir, &tally);
	mkSummary_Expect(md, "| my-baseline | not reached up to n = 10 | not reached up to n = 10 |");
	mkSummary_Expect(md, "| closed-normal | 1e-06 s (n = 10) | 1e-05 s (n = 100) | 0.0001 s (n = 1000) | "
		"not reached up to n = 1000 |");
	mkSummary_Expect(md, "| hull-qhull | 0.0001 s (n = 10) | 0.01 s (n = 100) | not reached up to n = 100 | "
		"not reached up to n = 100 |");
	mkSummary_Expect(md, "error ≤ 1e-02: the closed form (closed-normal, n = 10, 1e-06 s) is 100 times as fast as "
		"the fastest baseline (hull-qhull, n = 10, 0.0001 s)");
	mkSummary_Expect(md, "error ≤ 1e-03: the closed form (closed-normal, n = 100, 1e-05 s) is 1e+03 times");
	mkSummary_Expect(md, "error ≤ 1e-06: the closed form reaches it (closed-normal, n = 1000, 0.0001 s); no baseline does.");
	mkSummary_Expect(md, "error ≤ 1e-09: the closed form does not reach it, nor does any baseline.");
	mkSummary_Expect(md, "a baseline wins at my-baseline n = 10 (1e-07 s, error 0.02)");
	mkSummary_Expect(md, "equal time: over the 2 baseline points the closed form dominates, its best error in no "
		"more time is smaller by a factor of at least 200 (at hull-qhull n = 100, 0.01 s)");
	mkSummary_Expect(md, "3D EE, error ≤ 1e-02: **a baseline is faster**: fast-baseline (n = 4, 0.0001 s) is 10 times "
		"as fast as the fastest closed form (closed-normal, n = 4, 0.001 s).");
	mkSummary_Expect(md, "3D EE: a baseline wins at fast-baseline n = 4 (0.0001 s, error 0.001)");
	ENSURE(tally.published == 0 && tally.reproduced == 0 && tally.missing == 0);
	/* Methods in order of first appearance. */
	const char *mine = strstr(md, "| my-baseline |"), *cn = strstr(md, "| closed-normal |");
	ENSURE(mine && cn && mine < cn);
	free(md);
}

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	mkDir = argv[1];
	mkTestTables();
	/* No result: the section says so and names the driver; a tally that
	 * already holds counts is left as it was (no published figure here). */
	mkTally tally = { 7, 5, 2 };
	mkSummary_ExpectMissing(mkTradeoff_Summary, mkDir, "tradeoff", &tally);
	ENSURE(tally.published == 7 && tally.reproduced == 5 && tally.missing == 2);
	return 0;
}
