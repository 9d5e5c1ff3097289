/* test_summary.c - the running-time section of the tables (mkTiming_Summary)
 * on result files written here, with every expected text worked out by hand:
 *  - 2D SQ at N = 10, 20, 40, 80, 160 (one trial per level, so the medians
 *    are the times): closed-gradient 1e-6 N s (slope of log t against
 *    log N exactly 1), edge-sort 0.5e-6 N s (faster at all 5 levels),
 *    hull-qhull 1e-8 N^2 s (slope 2; at N = 160, 2.56e-4 s against
 *    1.6e-4 s, a ratio of 1.6 < 10, so that statement must "disagree");
 *  - a method no code knows, "my-method", at N = 20 with two trials of 2 ms
 *    and 4 ms: mean 3 ms, population std 1 ms, "3 ± 1 ms". Its rows come
 *    first in the file, yet its row of the means table comes after the
 *    registry's methods (closed-gradient, hull-qhull, edge-sort in registry
 *    order); no row of the table is dropped for an unknown name.
 * A missing result gives the "not reproduced yet" line and counts the six
 * statements as missing. */
#include "timing.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ensure.h"
#include "summary_text.h"

static const char *mkDir;

static void mkWrite(const char *name, const char *text)
{
	char path[MK_PATH_MAX];
	snprintf(path, sizeof path, "%s/%s", mkDir, name);
	FILE *fp = fopen(path, "w");
	ENSURE(fp != NULL);
	fputs(text, fp);
	fclose(fp);
}

static void mkTestStatementsAndUnknown(void)
{
	char rows[8192];
	int n = snprintf(rows, sizeof rows, "dim,case,method,level,points_per_body,trial,status,seconds,"
		"points_out,trials_planned,trials_run,warmup_seconds\n"
		"2,SQ,my-method,20,20,0,ok,2e-3,20,2,2,0\n"
		"2,SQ,my-method,20,20,1,ok,4e-3,20,2,2,0\n");
	static const int levels[5] = { 10, 20, 40, 80, 160 };
	for (int i = 0; i < 5; ++i) {
		int N = levels[i];
		n += snprintf(rows + n, sizeof rows - (size_t)n, "2,SQ,closed-gradient,%d,%d,0,ok,%de-6,%d,1,1,0\n"
			"2,SQ,edge-sort,%d,%d,0,ok,%de-7,%d,1,1,0\n2,SQ,hull-qhull,%d,%d,0,ok,%de-8,%d,1,1,0\n",
			N, N, N, N, N, N, 5 * N, N, N, N, N * N, N);
	}
	mkWrite("timing.csv", rows);
	mkWrite("timing.csv.meta", "experiment: timing\nseed: 1\ntrials: 1\nrotation_draw: paper\n");
	mkTally tally = { 0, 0, 0 };
	char *md = mkSummary_Text(mkTiming_Summary, mkDir, &tally);
	mkSummary_Expect(md, "| closed form (proposed) is linear in N | 2D | SQ | slope of closed-gradient, 20–160 points | 1.00 |");
	mkSummary_Expect(md, "| edge sorting is faster than the closed form for two superellipses | 2D | SQ | levels where "
		"edge-sort is faster than closed-gradient | 5 of 5 |");
	mkSummary_Expect(md, "| convex hull grows much faster | 2D | SQ | slopes of hull-qhull and closed-gradient; time ratio "
		"at level 160 | 2.00 vs 1.00; 1.6 | slopes differ by ≥ 0.5 and ratio ≥ 10 | **disagrees** |");
	mkSummary_Expect(md, "| edge sorting is linear | 2D | SQ | slope of edge-sort, 20–160 points | 1.00 |");
	ENSURE(tally.published == 6 && tally.reproduced == 6 && tally.missing == 0);
	/* Table 1: closed-gradient, edge sorting and the hull ran 2D SQ only. */
	mkSummary_Expect(md, "| Closed-form (proposed): closed-gradient | Any | ✓ | ✓ ✓ ✓ | — — ✓ | — — — |");
	mkSummary_Expect(md, "| Closed-form geometric | Any | ✓ | ✓ ✓ — | — — — | — — — |");
	/* The means: every method, the unknown one last, its own numbers. */
	mkSummary_Expect(md, "| case | method | N = 10 | N = 20 | N = 40 | N = 80 | N = 160 |");
	mkSummary_Expect(md, "| SQ | closed-gradient | 10 ± 0 µs | 20 ± 0 µs | 40 ± 0 µs | 80 ± 0 µs | 160 ± 0 µs |");
	mkSummary_Expect(md, "| SQ | my-method | — | 3 ± 1 ms | — | — | — |");
	const char *cg = strstr(md, "| SQ | closed-gradient |"), *qh = strstr(md, "| SQ | hull-qhull |");
	const char *es = strstr(md, "| SQ | edge-sort |"), *mine = strstr(md, "| SQ | my-method |");
	ENSURE(cg && qh && es && mine && cg < qh && qh < es && es < mine);
	free(md);
}

static void mkTestMissing(void)
{
	mkTally tally = { 0, 0, 0 };
	mkSummary_ExpectMissing(mkTiming_Summary, mkDir, "timing", &tally);
	ENSURE(tally.published == 6 && tally.reproduced == 0 && tally.missing == 6);
}

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	mkDir = argv[1];
	mkTestStatementsAndUnknown();
	mkTestMissing();
	return 0;
}
