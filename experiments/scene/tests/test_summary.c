/* test_summary.c - the scene section of the tables (mkScene_Summary) on a
 * hand-made result: a 2D scene of 10 obstacles (1 box) at T = 0.01 with
 * 1000 adaptive and 4000 uniform points (factor 4, worked by hand: 4000 /
 * 1000), a capped 3D row (factor 8 as a lower bound), and Table 2's 2D
 * row of 50 obstacles on 1 and 2 threads (2 s and 1.25 s: efficiency
 * 2 / (2 * 1.25) = 80%) beside the paper's 0.36 s and a one-thread figure
 * from a hand-made cobstacle.csv (mean of 1.5 and 2.5 s = 2.000). A missing
 * result gives the "not reproduced yet" line. */
#include "scene.h"

#include <stdio.h>
#include <string.h>

#include "ensure.h"
#include "summary_text.h"

/* Replace (text != NULL) or remove (NULL) the files names[k] of dir. */
static void mkFiles(const char *dir, const char *const *names, const char *const *texts, int count)
{
	for (int k = 0; k < count; ++k) {
		char path[MK_PATH_MAX];
		snprintf(path, sizeof path, "%s/%s", dir, names[k]);
		remove(path);
		FILE *fp = texts[k] ? fopen(path, "w") : NULL;
		ENSURE(!texts[k] || fp);
		if (fp) {
			fputs(texts[k], fp);
			fclose(fp);
		}
	}
}

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	if (argc != 2)
		return mk_summary("scene.summary");
	const char *dir = argv[1];
	static const char *const files[] = { "scene.csv", "scene.csv.meta", "cobstacle.csv", "cobstacle.csv.meta" };
	const char *none[4] = { NULL, NULL, NULL, NULL };
	mkFiles(dir, files, none, 4); /* a previous run's files */
	mkTally tally = { 0, 0, 0 };
	char *md = mkSummary_Text(mkScene_Summary, dir, &tally);
	mkSummary_Expect(md, "NOT REPRODUCED YET");
	free(md);
	const char *head = "part,dim,obstacles,boxes,orientations,tol,mode,threads,param,points,seconds,cpu_seconds,error,"
		"target,capped,factor,checksum,efficiency,paper_s,load\n";
	char rows[4096];
	snprintf(rows, sizeof rows, "%s"
		"A,2,10,1,4,0.01,adaptive,2,,1000,0.1,0.1,0.0099,0.01,0,1,5,,,1.5\n"
		"A,2,10,1,4,0.01,uniform,2,100,4000,0.2,0.2,0.0098,0.0099,0,4,6,,,1.5\n"
		"A,3,10,1,2,0.1,adaptive,2,,500,0.1,0.1,0.099,0.1,0,1,5,,,1.5\n"
		"A,3,10,1,2,0.1,uniform,2,3,4000,0.2,0.2,0.3,0.099,1,8,6,,,1.5\n"
		"B,2,50,0,50,,paper,1,50,50,2,2,,,0,,7,,0.36,0.5\n"
		"B,2,50,0,50,,paper,2,50,50,1.25,2.4,,,0,,7,0.8,0.36,0.5\n", head);
	const char *texts[4] = { rows, "experiment: scene\nseed: 1\ntrials: 1\n",
		"dim,obstacles,orientations,total_s\n2,50,50,1.5\n2,50,50,2.5\n", "experiment: cobstacle\nseed: 1\ntrials: 2\n" };
	mkFiles(dir, files, texts, 4);
	md = mkSummary_Text(mkScene_Summary, dir, &tally);
	mkSummary_Expect(md, "| 2 | 10 (1) | 4 | 0.01 | 1000 | 0.0099 | 4000 | 0.0098 | 4.0 |");
	mkSummary_Expect(md, "| 3 | 10 (1) | 2 | 0.1 | 500 | 0.099 | 4000 | 0.3 | > 8.0 (capped) |");
	mkSummary_Expect(md, "Smallest factor over the scenes: 4.0");
	mkSummary_Expect(md, "| 2 | 50 | 50 | 50 | 0.36 | 2.000 | 2.000 | 1.250 | 80% | 0.50 |");
	ENSURE(tally.published == 0 && tally.reproduced == 0 && tally.missing == 0);
	free(md);
	return mk_summary("scene.summary");
}
