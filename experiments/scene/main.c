/* main.c - the `scene` driver: adaptive against uniform C-obstacles at equal
 * certified error (Part A) and the paper's Table 2 on 1 and 2 threads
 * (Part B); scene.h says what each row holds. */
#include "scene.h"

#include <string.h>

static const mkDriver mkSceneXDriver = {
	"scene", "C-obstacles certified to a tolerance: adaptive against uniform sampling at equal\n"
	"worst-case certified error (Part A), and the paper's Table 2 on 1 and 2 threads\n"
	"side by side (Part B).",
	MK_SCENEX_SCHEMA, mkSceneX_Columns, MK_SHARED_SEED, 1, 1, 2022, NULL,
};

static void mkSetList(mkMeta *m, const char *key, const mkSceneXList *l)
{
	char buf[512] = "";
	for (int k = 0; k < l->n; ++k)
		snprintf(buf + strlen(buf), sizeof buf - strlen(buf), "%s%g", k ? "," : "", l->v[k]);
	mkMeta_Set(m, key, buf);
}

static int mkPartA(mkRun *run, const mkSceneXOptions *o, int dim, const mkSceneXList *l)
{
	char msg[1024];
	for (int i = 0; i < l->n; ++i) {
		mkScene s;
		if (mkSceneX_Draw(&s, o->seed, dim, (long)l->v[i], 1, dim == 2 ? o->headings_a : o->orient_a, o->rot) != MK_OK) {
			mkRun_Fail(run, "out of memory drawing a %dD scene of %g obstacles", dim, l->v[i]);
			return -1;
		}
		const mkSceneXList *tols = dim == 2 ? &o->tols2 : &o->tols3;
		for (int t = 0; t < tols->n; ++t, mkRun_Step(run, 1))
			if (mkSceneX_Compare(&s, tols->v[t], (int)o->threads, &run->csv, msg, sizeof msg) != MK_OK) {
				mkRun_Fail(run, "%dD, %g obstacles, T = %g: %s", dim, l->v[i], tols->v[t], msg);
				mkScene_Free(&s);
				return -1;
			}
		mkScene_Free(&s);
	}
	return 0;
}

static int mkPartB(mkRun *run, const mkSceneXOptions *o, int dim, const mkSceneXList *l)
{
	char msg[1024];
	for (int i = 0; i < l->n; ++i, mkRun_Step(run, 1)) {
		mkScene s;
		if (mkSceneX_Draw(&s, o->seed ^ 0x7461626c6532ULL, dim, (long)l->v[i], 0, dim == 2 ? o->headings_b : o->orient_b,
				o->rot) != MK_OK) {
			mkRun_Fail(run, "out of memory drawing a %dD scene of %g obstacles", dim, l->v[i]);
			return -1;
		}
		int points = dim == 2 ? (int)o->points_b : (int)(o->grid_b * o->grid_b);
		int rc = mkSceneX_Table2(&s, points, (int)o->reps, &run->csv, msg, sizeof msg);
		mkScene_Free(&s);
		if (rc != 0) {
			mkRun_Fail(run, "%s", msg);
			return -1;
		}
	}
	return 0;
}

int main(int argc, char **argv)
{
	mkSceneXOptions o = { .a2 = { { 10, 100, 1000, 10000 }, 4 }, .a3 = { { 10, 100, 1000 }, 3 },
		.tols2 = { { 0.1, 0.01, 0.001 }, 3 }, .tols3 = { { 0.1, 0.01 }, 2 }, .headings_a = 4, .orient_a = 2, .b2 = { { 50, 1000, 10000 }, 3 },
		.b3 = { { 50, 200, 1000 }, 3 }, .headings_b = 50, .points_b = 50, .grid_b = 10, .orient_b = 3600, .reps = 1,
		.threads = 2 };
	const char *so3 = "experiments/data/so3_double_coset_3600.csv";
	int skip_a = 0, skip_b = 0;
	long fig9 = 0;
	double fig9_tol = 0.5;
	mkFlag flags[] = {
		MK_FLAG_TEXT("--scenes2", "LIST", "Part A 2D obstacle counts (default 10,100,1000,10000)", &o.a2, mkSceneXList_ParseCounts),
		MK_FLAG_TEXT("--scenes3", "LIST", "Part A 3D obstacle counts (default 10,100,1000)", &o.a3, mkSceneXList_ParseCounts),
		MK_FLAG_TEXT("--tols2", "LIST", "Part A 2D tolerances (default 0.1,0.01,0.001)", &o.tols2, mkSceneXList_ParseTols),
		MK_FLAG_TEXT("--tols3", "LIST", "Part A 3D tolerances (default 0.1,0.01)", &o.tols3, mkSceneXList_ParseTols),
		MK_FLAG_LONG("--headings", "H", "Part A 2D headings pi k / H (default 4)", &o.headings_a, 1, 3600),
		MK_FLAG_LONG("--orientations", "K", "Part A 3D orientations: the first K of --so3 (default 2)", &o.orient_a, 1, 3600),
		MK_FLAG_LONG("--threads", "N", "Part A threads (default 2)", &o.threads, 1, 64),
		MK_FLAG_TEXT("--table2-2d", "LIST", "Part B 2D obstacle counts (default 50,1000,10000)", &o.b2, mkSceneXList_ParseCounts),
		MK_FLAG_TEXT("--table2-3d", "LIST", "Part B 3D obstacle counts (default 50,200,1000)", &o.b3, mkSceneXList_ParseCounts),
		MK_FLAG_LONG("--table2-orientations", "K", "Part B 3D orientations: the first K of --so3 (default 3600)", &o.orient_b, 1, 3600),
		MK_FLAG_LONG("--reps", "R", "Part B pairs of runs (1 thread, 2 threads) per level (default 1)", &o.reps, 1, 10),
		MK_FLAG_PATH("--so3", "PATH", "3D orientations (default experiments/data/so3_double_coset_3600.csv)", &so3),
		MK_FLAG_LONG("--fig9", "N", "write Fig. 9's geometry for a 2D scene of N obstacles, 0 = none (default 0)", &fig9, 0, 1000),
		MK_FLAG_DOUBLE("--fig9-tol", "T", "its tolerance (default 0.5)", &fig9_tol, 1e-3, 10),
		MK_FLAG_SWITCH("--skip-a", "leave Part A out", &skip_a),
		MK_FLAG_SWITCH("--skip-b", "leave Part B out", &skip_b),
	};
	mkRun run;
	MK_RUN_BEGIN(&run, &mkSceneXDriver, flags, argc, argv);
	o.seed = run.seed;
	char msg[1024];
	mkRotations rot;
	memset(&rot, 0, sizeof rot);
	long need = o.orient_a > o.orient_b ? o.orient_a : o.orient_b;
	if (mkRotations_Read(&rot, so3, need, msg, sizeof msg) != 0) {
		mkRun_Fail(&run, "%s", msg);
		return mkRun_End(&run, 1);
	}
	o.rot = &rot;
	mkSetList(&run.meta, "scenes2", &o.a2); mkSetList(&run.meta, "scenes3", &o.a3); mkSetList(&run.meta, "tols2", &o.tols2);
	mkSetList(&run.meta, "tols3", &o.tols3);
	mkSetList(&run.meta, "table2_2d", &o.b2); mkSetList(&run.meta, "table2_3d", &o.b3);
	mkMeta_SetInt(&run.meta, "headings", o.headings_a); mkMeta_SetInt(&run.meta, "orientations", o.orient_a);
	mkMeta_SetInt(&run.meta, "table2_orientations", o.orient_b); mkMeta_SetInt(&run.meta, "threads", o.threads);
	mkMeta_SetInt(&run.meta, "reps", o.reps); mkMeta_Set(&run.meta, "so3", so3);
	mkMeta_Set(&run.meta, "trials", "1 (each scene and level once; Part B --reps pairs)");
	long units = (skip_a ? 0 : o.a2.n * o.tols2.n + o.a3.n * o.tols3.n) + (skip_b ? 0 : o.b2.n + o.b3.n);
	int failed = mkRun_OpenCsv(&run, units) != 0;
	failed = failed || (!skip_a && (mkPartA(&run, &o, 2, &o.a2) || mkPartA(&run, &o, 3, &o.a3)));
	failed = failed || (!skip_b && (mkPartB(&run, &o, 2, &o.b2) || mkPartB(&run, &o, 3, &o.b3)));
	failed = failed || (fig9 > 0 && mkSceneX_Figure9(&run, o.seed, fig9, fig9_tol) != 0);
	mkRotations_Free(&rot);
	return mkRun_End(&run, failed);
}
