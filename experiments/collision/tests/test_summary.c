/* test_summary.c - the collision section of the tables
 * (mkCollision_Summary) on a result file written here; every expected text
 * is worked out by hand:
 *  - gjk-poly (the paper's GJK) on ellipsoids, 10 ms and 20 ms: mean 15 ms,
 *    15 / 18.4 (Table 3) = 0.815; agreement 1 of 2; 15000 µs in the details;
 *  - minksum-normal-lm (the paper's MinkSum (Normal)) on ellipsoids, 2 ms
 *    and a failure of 4 ms: mean 3 ms, 3 / 3.5 = 0.857, success 1 of 2; on
 *    superquadrics 5.1 ms, ratio 1;
 *  - implicit with one skipped row only: Table 3 has no counterpart, the
 *    details count it as skipped;
 *  - an entry no list knows ("my-query") gets its row of details, with the
 *    distance errors {1e-7} and the penetration errors {2e-7, 4e-7}
 *    (median 3e-7, nearest-rank 99th percentile and max 4e-7);
 *  - of the 11 published times, 3 have a counterpart;
 *  - the referee uncertain on superquadrics trial 2 (referee_certain 0):
 *    1 of 3 superquadric pairs, 0 of 3 ellipsoid pairs (trials 0..2, the
 *    skipped row of trial 2 counts as a pair);
 *  - my-query's answers carry its own certificate (column certified) on
 *    its 3 rows, 0 on superquadrics trial 1: 1 of 3 without it.
 *  - these results have no batch entries (no column path): said so.
 * A second result with the column path and batch entries:
 *  - superquadrics trials 0..2: minksum-normal 4, 6, 8 µs (median 6, mean
 *    6), ccd-gjk 1, 2, 6 µs (median 2, mean 3), ccd-gjk-epa-1e-10 2, 3, 4 µs
 *    (3, 3); minksum-batch-status 0.25 µs per pair on each (paths
 *    separating, overlap-point, one-pair): × 6 / 0.25 = 24, 2 / 0.25 = 8 by
 *    median and 3 / 0.25 = 12 by mean, 3 / 0.25 = 12; one-pair 1 of 3;
 *    minksum-batch-full 2 µs on each (one-pair, one-pair, failed): × 3, 1 and
 *    1.5, 1.5, one-pair 2 of 3, 1 failed;
 *  - ellipsoids trial 0: minksum-batch-status 0.5 µs and no peer: "—".
 * A missing result leaves all 11 "not reproduced yet". */
#include "collision.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "ensure.h"
#include "summary_text.h"

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/collision.csv", argv[1]);
	FILE *fp = fopen(path, "w");
	ENSURE(fp != NULL);
	fputs("pair,trial,algorithm,seconds,status,distance,referee_distance,error,agrees,success,iterations,limited,"
		"referee_certain,certified\n"
		"ellipsoids,0,gjk-poly,0.010,separated,,0.5,,1,1,,,1,\n"
		"ellipsoids,0,minksum-normal-lm,0.002,separated,,0.5,,1,1,5,,1,\n"
		"ellipsoids,1,gjk-poly,0.020,separated,,-0.5,,0,1,,,1,\n"
		"ellipsoids,1,minksum-normal-lm,0.004,failed,,-0.5,,0,0,,,1,\n"
		"ellipsoids,2,implicit,,skipped,,0.3,,,,,2,1,\n"
		"superquadrics,0,minksum-normal-lm,0.0051,separated,,0.5,,1,1,7,,1,\n"
		"superquadrics,0,my-query,0.001,separated,0.5000001,0.5,1e-7,1,1,3,,1,1\n"
		"superquadrics,1,my-query,0.003,overlapping,-0.2,-0.2000002,2e-7,1,1,3,,1,0\n"
		"superquadrics,2,my-query,0.002,overlapping,-0.2,-0.2000004,4e-7,1,1,3,,0,1\n", fp);
	fclose(fp);
	snprintf(path, sizeof path, "%s/collision.csv.meta", argv[1]);
	fp = fopen(path, "w");
	ENSURE(fp != NULL);
	fputs("experiment: collision\nseed: 3\ntrials: 3\nrotation_draw: paper\nreferee_margin: 1e-09\n"
		"limits: implicit=2\n", fp);
	fclose(fp);

	mkTally tally = { 0, 0, 0 };
	char *md = mkSummary_Text(mkCollision_Summary, argv[1], &tally);
	mkSummary_Expect(md, "Rotation draw: paper.");
	mkSummary_Expect(md, "| GJK | 18.4 | 15 | 0.815 | 18.3 | **NOT REPRODUCED YET** | — | gjk-poly |");
	mkSummary_Expect(md, "| ASC | 0.133 | **NOT REPRODUCED YET** | — | — | — | — | asc-eigen |");
	mkSummary_Expect(md, "| Implicit | 27.0 | **NOT REPRODUCED YET** | — | 42.3 | **NOT REPRODUCED YET** | — | implicit |");
	mkSummary_Expect(md, "| MinkSum (Normal) | 3.5 | 3 | 0.857 | 5.1 | 5.1 | 1 | minksum-normal-lm |");
	ENSURE(tally.published == 11 && tally.reproduced == 3 && tally.missing == 8);
	mkSummary_Expect(md, "where |referee sd| > 1e-09 × scale");
	mkSummary_Expect(md, "beyond a --limit (implicit=2)");
	mkSummary_Expect(md, "left out of agreement and errors: ellipsoids 0 of 3, superquadrics 1 of 3.");
	mkSummary_Expect(md, "within its budget), of 3 certified or not: superquadrics my-query 1 of 3.");
	mkSummary_Expect(md, "| ellipsoids | gjk-poly | 2 | 0 | 1.5e+04 | 1.5e+04 | 1.0000 | 0.5000 (1/2) | — | — |");
	mkSummary_Expect(md, "| ellipsoids | minksum-normal-lm | 2 | 0 | 3e+03 | 3e+03 | 0.5000 | 0.5000 (1/2) | — | — |");
	mkSummary_Expect(md, "| ellipsoids | implicit | 0 | 1 | — | — | — | — | — | — |");
	mkSummary_Expect(md, "| superquadrics | minksum-normal-lm | 1 | 0 | 5.1e+03 | 5.1e+03 | 1.0000 | 1.0000 (1/1) |");
	mkSummary_Expect(md, "| superquadrics | my-query | 3 | 0 | 2e+03 | 2e+03 | 1.0000 | 1.0000 (3/3) | "
		"1e-07 / 1e-07 / 1e-07 | 3e-07 / 4e-07 / 4e-07 |");
	mkSummary_Expect(md, "Batch entries (mkCollide3_Batch): not in these results (written before the batch entries).");
	free(md);

	char dir[MK_PATH_MAX - 32]; /* room for /collision.csv.meta in path */
	snprintf(dir, sizeof dir, "%s/batch", argv[1]);
	ENSURE(mkdir(dir, 0777) == 0 || errno == EEXIST);
	snprintf(path, sizeof path, "%s/collision.csv", dir);
	fp = fopen(path, "w");
	ENSURE(fp != NULL);
	fputs("pair,trial,algorithm,seconds,status,distance,referee_distance,error,agrees,success,iterations,limited,"
		"referee_certain,certified,path\n"
		"ellipsoids,0,minksum-batch-status,0.5e-6,separated,,0.5,,1,1,,,1,,separating\n"
		"superquadrics,0,minksum-normal,4e-6,separated,0.5,0.5,0,1,1,3,,1,1,\n"
		"superquadrics,0,ccd-gjk,1e-6,separated,,0.5,,1,1,,,1,,\n"
		"superquadrics,0,ccd-gjk-epa-1e-10,2e-6,separated,,0.5,,1,1,,,1,,\n"
		"superquadrics,0,minksum-batch-status,0.25e-6,separated,,0.5,,1,1,,,1,,separating\n"
		"superquadrics,0,minksum-batch-full,2e-6,separated,0.5,0.5,0,1,1,,,1,,one-pair\n"
		"superquadrics,1,minksum-normal,6e-6,overlapping,-0.2,-0.2,0,1,1,3,,1,1,\n"
		"superquadrics,1,ccd-gjk,2e-6,overlapping,,-0.2,,1,1,,,1,,\n"
		"superquadrics,1,ccd-gjk-epa-1e-10,3e-6,overlapping,,-0.2,,1,1,,,1,,\n"
		"superquadrics,1,minksum-batch-status,0.25e-6,overlapping,,-0.2,,1,1,,,1,,overlap-point\n"
		"superquadrics,1,minksum-batch-full,2e-6,overlapping,-0.2,-0.2,0,1,1,,,1,,one-pair\n"
		"superquadrics,2,minksum-normal,8e-6,separated,0.1,0.1,0,1,1,3,,1,1,\n"
		"superquadrics,2,ccd-gjk,6e-6,separated,,0.1,,1,1,,,1,,\n"
		"superquadrics,2,ccd-gjk-epa-1e-10,4e-6,separated,,0.1,,1,1,,,1,,\n"
		"superquadrics,2,minksum-batch-status,0.25e-6,separated,,0.1,,1,1,,,1,,one-pair\n"
		"superquadrics,2,minksum-batch-full,2e-6,failed,,0.1,,0,0,,,1,,failed\n", fp);
	fclose(fp);
	snprintf(path, sizeof path, "%s/collision.csv.meta", dir);
	fp = fopen(path, "w");
	ENSURE(fp != NULL);
	fputs("experiment: collision\nseed: 3\ntrials: 3\nrotation_draw: paper\nreferee_margin: 1e-09\nlimits: none\n"
		"batch_chunk: 64\nbatch_lanes: avx2\n", fp);
	fclose(fp);
	tally = (mkTally){ 0, 0, 0 };
	md = mkSummary_Text(mkCollision_Summary, dir, &tally);
	mkSummary_Expect(md, "each kind's pairs answered 64 pairs per mkCollide3_Batch call (lanes: avx2)");
	mkSummary_Expect(md, "| ellipsoids | minksum-batch-status | 1 | 0.5 | 0.5 | — | — | — | 0.0000 (0/1) | 0 |");
	mkSummary_Expect(md, "| superquadrics | minksum-batch-status | 3 | 0.25 | 0.25 | 24.00 / 24.00 | 8.00 / 12.00 | "
		"12.00 / 12.00 | 0.3333 (1/3) | 0 |");
	mkSummary_Expect(md, "| superquadrics | minksum-batch-full | 3 | 2 | 2 | 3.00 / 3.00 | 1.00 / 1.50 | 1.50 / 1.50 | "
		"0.6667 (2/3) | 1 |");
	free(md);

	snprintf(path, sizeof path, "%s/none", argv[1]);
	tally = (mkTally){ 0, 0, 0 };
	md = mkSummary_Text(mkCollision_Summary, path, &tally);
	mkSummary_Expect(md, "none/collision.csv` does not exist");
	ENSURE(tally.published == 11 && tally.reproduced == 0 && tally.missing == 11);
	free(md);
	return 0;
}
