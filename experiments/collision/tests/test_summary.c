/* test_summary.c - the collision section of the tables
 * (mkCollision_Summary) on a result file written here; every expected text
 * is worked out by hand:
 *  - GJK on ellipsoids, 10 ms and 20 ms: mean 15 ms, 15 / 18.4 (Table 3)
 *    = 0.815; agreement 1 of 2; no solver, so no success rate;
 *  - MinkSum (Normal) on ellipsoids, 2 ms and 4 ms (the second too close to
 *    call): mean 3 ms, 3 / 3.5 = 0.857, success 1 of 2; on superquadrics
 *    5.1 ms, ratio 1;
 *  - an algorithm no list knows ("My Query") still gets its row of details;
 *  - of the 11 published times, 3 have a counterpart.
 * A missing result leaves all 11 "not reproduced yet". */
#include "collision.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ensure.h"
#include "summary_text.h"

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/collision.csv", argv[1]);
	FILE *fp = fopen(path, "w");
	ENSURE(fp != NULL);
	fputs("pair,trial,algorithm,seconds,collide,residual,iterations,success,referee_min_g,agrees\n"
		"ellipsoids,0,GJK,0.010,1,,,,0.5,1\n"
		"ellipsoids,0,MinkSum (Normal),0.002,1,1e-12,5,1,0.5,1\n"
		"ellipsoids,1,GJK,0.020,0,,,,-0.5,0\n"
		"ellipsoids,1,MinkSum (Normal),0.004,0,1e-3,100,0,0.0001,\n"
		"superquadrics,0,MinkSum (Normal),0.0051,1,1e-12,7,1,0.5,1\n"
		"superquadrics,0,My Query,0.001,1,,,,0.5,1\n", fp);
	fclose(fp);
	snprintf(path, sizeof path, "%s/collision.csv.meta", argv[1]);
	fp = fopen(path, "w");
	ENSURE(fp != NULL);
	fputs("experiment: collision\nseed: 3\ntrials: 2\nrotation_draw: paper\nreferee_margin: 0.001\n", fp);
	fclose(fp);

	mkTally tally = { 0, 0, 0 };
	char *md = mkSummary_Text(mkCollision_Summary, argv[1], &tally);
	mkSummary_Expect(md, "Rotation draw: paper.");
	mkSummary_Expect(md, "| GJK | 18.4 | 15 | 0.815 | 18.3 | **NOT REPRODUCED YET** | — |");
	mkSummary_Expect(md, "| ASC | 0.133 | **NOT REPRODUCED YET** | — | — | — | — |");
	mkSummary_Expect(md, "| MinkSum (Normal) | 3.5 | 3 | 0.857 | 5.1 | 5.1 | 1 |");
	ENSURE(tally.published == 11 && tally.reproduced == 3 && tally.missing == 8);
	mkSummary_Expect(md, "|min g| exceeds the margin (0.001)");
	mkSummary_Expect(md, "| ellipsoids | GJK | 2 | 15 | 15 | — | 0.5000 (1/2) | 0 |");
	mkSummary_Expect(md, "| ellipsoids | MinkSum (Normal) | 2 | 3 | 3 | 0.5000 | 1.0000 (1/1) | 1 |");
	mkSummary_Expect(md, "| superquadrics | MinkSum (Normal) | 1 | 5.1 | 5.1 | 1.0000 | 1.0000 (1/1) | 0 |");
	mkSummary_Expect(md, "| superquadrics | My Query | 1 | 1 | 1 | — | 1.0000 (1/1) | 0 |");
	free(md);

	snprintf(path, sizeof path, "%s/none", argv[1]);
	tally = (mkTally){ 0, 0, 0 };
	md = mkSummary_Text(mkCollision_Summary, path, &tally);
	mkSummary_Expect(md, "none/collision.csv` does not exist");
	ENSURE(tally.published == 11 && tally.reproduced == 0 && tally.missing == 11);
	free(md);
	return 0;
}
