/* test_scene.c - the scene experiment's rows (scene.h), in a scratch folder
 * given as the argument:
 *  - Table 2 (Part B) on a small 2D scene: the 1- and 2-thread rows carry the
 *    same checksum, and it equals the sum of every coordinate computed here
 *    directly with mkSum2_Batch at the paper's sampling (mkSample2_Angles
 *    of the obstacle, the robot turned to each heading: map R M), code that
 *    shares nothing with mkCSpace_Run's tasks and threads. Tolerance: a
 *    relative 1e-12 of the sum of |coordinates|, room for a different order
 *    of the additions (the boundaries are summed the same way; the points
 *    inside one may not be).
 *  - Part A on a 2D scene of 10 obstacles at T = 0.05: the adaptive row's
 *    certified error is at most T; the uniform row's is at most the
 *    adaptive one (or the row says capped); factor = the points ratio; and
 *    the uniform parameter is checked independently: per boundary,
 *    mkCSpace2_Uniform at that n (single-boundary code, not the scene
 *    run) gives errors whose maximum is the row's error, and at n - 1 some
 *    boundary is above the adaptive error (the smallest n).
 *  - Part A on a small 3D scene at T = 0.05: likewise with
 *    mkCSpace3_Uniform at the row's splits s and s - 1. */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "ensure.h"

static mkTable mkRunRows(const char *dir, const char *name, const mkScene *s, int part_b, double tol)
{
	char path[MK_PATH_MAX], msg[1024];
	snprintf(path, sizeof path, "%s/%s", dir, name);
	mkCsv csv;
	int cols = 0;
	while (mkSceneX_Columns[cols]) ++cols;
	ENSURE(mkCsv_Open(&csv, path, mkSceneX_Columns, cols, msg, sizeof msg) == 0);
	if (part_b)
		ENSURE(mkSceneX_Table2(s, 50, 1, &csv, msg, sizeof msg) == 0);
	else
		ENSURE(mkSceneX_Compare(s, tol, 2, &csv, msg, sizeof msg) == MK_OK);
	ENSURE(mkCsv_Commit(&csv, NULL, msg, sizeof msg) == 0);
	mkTable t;
	mkTable_Load(&t, path);
	ENSURE(t.present && t.rows == 2);
	return t;
}

static void mkTestTable2(const char *dir)
{
	mkScene s;
	ENSURE(mkSceneX_Draw(&s, 5, 2, 7, 0, 3, NULL) == MK_OK);
	mkTable t = mkRunRows(dir, "b.csv", &s, 1, 0.0);
	int cc = mkTable_Col(&t, "checksum"), ct = mkTable_Col(&t, "threads");
	ENSURE(mkTable_Num(&t, 0, ct) == 1 && mkTable_Num(&t, 1, ct) == 2);
	ENSURE(mkTable_Num(&t, 0, cc) == mkTable_Num(&t, 1, cc));
	double ux[50], uy[50], x[50], y[50], kx[50], ky[50], sum = 0.0, mag = 0.0;
	mkSumOptions opt = mkSumOptions_Default();
	ENSURE(mkSample2_Angles(50, ux, uy) == MK_OK);
	for (int o = 0; o < s.orientation_count; ++o)
		for (int i = 0; i < s.obstacle_count; ++i) {
			mkBody2 rob = s.robot.spec.body2;
			rob.M = mkMat2_Mul(mkMat2_Rotation(s.headings[o]), rob.M);
			ENSURE(mkSum2_Batch(s.obstacles[i].spec.body2, rob, &opt, ux, uy, 50, x, y, kx, ky) == MK_OK);
			for (int k = 0; k < 50; ++k) {
				sum += x[k] + y[k];
				mag += fabs(x[k]) + fabs(y[k]);
			}
		}
	ENSURE_NEAR(mkTable_Num(&t, 0, cc), sum, 1e-12 * mag);
	mkTable_Free(&t);
	mkScene_Free(&s);
}

static void mkTestCompare(const char *dir)
{
	mkScene s;
	ENSURE(mkSceneX_Draw(&s, 9, 2, 10, 0, 2, NULL) == MK_OK);
	mkTable t = mkRunRows(dir, "a.csv", &s, 0, 0.05);
	int ce = mkTable_Col(&t, "error"), cn = mkTable_Col(&t, "points"), cf = mkTable_Col(&t, "factor"),
		cp = mkTable_Col(&t, "param"), cc = mkTable_Col(&t, "capped");
	ENSURE_LE(mkTable_Num(&t, 0, ce), 0.05);
	ENSURE(mkTable_Num(&t, 1, cc) == 1 || mkTable_Num(&t, 1, ce) <= mkTable_Num(&t, 0, ce));
	ENSURE_NEAR(mkTable_Num(&t, 1, cf), mkTable_Num(&t, 1, cn) / mkTable_Num(&t, 0, cn), 1e-12);
	int n = (int)mkTable_Num(&t, 1, cp);
	double worst = 0.0;
	for (int o = 0; o < s.orientation_count; ++o)
		for (int i = 0; i < s.obstacle_count; ++i) {
			mkBody2 rob = s.robot.spec.body2;
			rob.M = mkMat2_Mul(mkMat2_Rotation(s.headings[o]), rob.M);
			double *x = NULL, *y = NULL, err = NAN;
			int cap = 0, cnt = 0;
			ENSURE(mkCSpace2_Uniform(s.obstacles[i].spec.body2, rob, MK_BOUND_INNER, n, MK_IMPL_AUTO, &x, &y, &cap,
				&cnt, &err) == MK_OK);
			worst = err > worst ? err : worst;
			free(x);
			free(y);
		}
	ENSURE_NEAR(worst, mkTable_Num(&t, 1, ce), 1e-12 * worst);
	/* the smallest: one normal fewer leaves some boundary above the target */
	double below = 0.0;
	for (int o = 0; o < s.orientation_count && n > 4; ++o)
		for (int i = 0; i < s.obstacle_count; ++i) {
			mkBody2 rob = s.robot.spec.body2;
			rob.M = mkMat2_Mul(mkMat2_Rotation(s.headings[o]), rob.M);
			double *x = NULL, *y = NULL, err = NAN;
			int cap = 0, cnt = 0;
			ENSURE(mkCSpace2_Uniform(s.obstacles[i].spec.body2, rob, MK_BOUND_INNER, n - 1, MK_IMPL_AUTO, &x, &y,
				&cap, &cnt, &err) == MK_OK);
			below = err > below ? err : below;
			free(x);
			free(y);
		}
	ENSURE(n == 4 || below > mkTable_Num(&t, 0, ce));
	mkTable_Free(&t);
	mkScene_Free(&s);
}

/* 3D: the uniform row's splits s reach the adaptive error on every
 * boundary and s - 1 does not on some, both checked per boundary with
 * mkCSpace3_Uniform (single-boundary code, not the scene run). */
static void mkTestCompare3(const char *dir)
{
	static const char text[] = "dim 3\nrobot superquadric a=1 b=0.6 c=0.8 eps1=0.5 eps2=0.8\n"
		"obstacle superquadric a=2 b=1 c=1.5 eps1=0.3 eps2=1.2 at=5,0,0\n"
		"obstacle ellipsoid a=1 b=2 c=0.5 at=-4,1,0\nquaternions 1,0,0,0; 0.8,0.6,0,0\n";
	mkScene s;
	char msg[512];
	ENSURE(mkScene_Parse(text, &s, msg, sizeof msg) == MK_OK || (printf("%s\n", msg), 0));
	mkTable t = mkRunRows(dir, "a3.csv", &s, 0, 0.05);
	int ce = mkTable_Col(&t, "error"), cp = mkTable_Col(&t, "param"), cc = mkTable_Col(&t, "capped");
	ENSURE(mkTable_Num(&t, 1, cc) == 0);
	int splits = (int)mkTable_Num(&t, 1, cp);
	double worst[2] = { 0.0, 0.0 };
	for (int k = 0; k < 2 && splits >= 1; ++k)
		for (int o = 0; o < s.orientation_count; ++o)
			for (int i = 0; i < s.obstacle_count; ++i) {
				mkBody3 rob = s.robot.spec.body3;
				rob.M = mkMat3_Mul(mkScene3_Orientation(&s, o), rob.M);
				double *x = NULL, *y = NULL, *z = NULL, err = NAN;
				int cap = 0, cnt = 0, fcap = 0, fcount = 0;
				ENSURE(mkCSpace3_Uniform(s.obstacles[i].spec.body3, rob, MK_BOUND_INNER, splits - k, MK_IMPL_AUTO,
					&x, &y, &z, &cap, NULL, &fcap, &cnt, &fcount, &err) == MK_OK);
				worst[k] = err > worst[k] ? err : worst[k];
				free(x);
				free(y);
				free(z);
			}
	ENSURE(splits >= 1);
	ENSURE_NEAR(worst[0], mkTable_Num(&t, 1, ce), 1e-12 * worst[0]);
	ENSURE(worst[1] > mkTable_Num(&t, 0, ce));
	mkTable_Free(&t);
	mkScene_Free(&s);
}

int main(int argc, char **argv)
{
	ENSURE(argc == 2);
	if (argc == 2) {
		mkTestTable2(argv[1]);
		mkTestCompare(argv[1]);
		mkTestCompare3(argv[1]);
	}
	return mk_summary("scene.rows");
}
