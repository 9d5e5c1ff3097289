/* test_example.c - a trial's row: the closed form keeps e_implicit at
 * roundoff (|Psi - 1| of a boundary point, 1e-12 is 4500 ulps of slack). */
#include "example.h"
#include "ensure.h"

#include <stdio.h>

int main(int argc, char **argv)
{
	char path[512], msg[256];
	snprintf(path, sizeof path, "%s/example-test.csv", argc > 1 ? argv[1] : ".");
	mkCsv csv;
	ENSURE(mkCsv_Open(&csv, path, mkExample_Columns, 5, msg, sizeof msg) == 0);
	for (long t = 0; t < 20; ++t)
		ENSURE(mkExample_Trial(7, t, 200, &csv) == MK_OK);
	ENSURE(mkCsv_Commit(&csv, NULL, msg, sizeof msg) == 0);
	mkTable tab;
	mkTable_Load(&tab, path);
	ENSURE(tab.present && tab.rows == 20);
	for (long r = 0; tab.present && r < tab.rows; ++r)
		ENSURE_LE(mkTable_Num(&tab, r, mkTable_Col(&tab, "e_implicit_max")), 1e-12);
	mkTable_Free(&tab);
	return mk_summary("example.trial");
}
