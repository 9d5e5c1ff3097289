/* scene.c - the `scene` experiment (scene.h): the draws, Part A, Part B. */
#define _POSIX_C_SOURCE 200809L
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

const char *const mkSceneX_Columns[] = { "part", "dim", "obstacles", "boxes", "orientations", "tol", "mode",
	"threads", "param", "points", "seconds", "cpu_seconds", "error", "target", "capped", "factor", "checksum",
	"efficiency", "paper_s", "load", NULL };

static int mkSceneXList_Parse(mkSceneXList *l, const char *text, double lo, double hi, int integer,
	char *msg, size_t msglen)
{
	const char *p = text;
	l->n = 0;
	while (*p) {
		char *end;
		double v = strtod(p, &end);
		if (end == p || (*end && *end != ',') || l->n == MK_SCENEX_MAX || !(v >= lo && v <= hi)
			|| (integer && v != floor(v))) {
			snprintf(msg, msglen, "is not allowed: must be up to %d comma-separated %s in [%g, %g]", MK_SCENEX_MAX,
				integer ? "integers" : "numbers", lo, hi);
			return -1;
		}
		l->v[l->n++] = v;
		p = *end ? end + 1 : end;
	}
	if (l->n == 0) {
		snprintf(msg, msglen, "is not allowed: must be up to %d comma-separated %s in [%g, %g]", MK_SCENEX_MAX,
			integer ? "integers" : "numbers", lo, hi);
		return -1;
	}
	return 0;
}

int mkSceneXList_ParseCounts(void *list, const char *text, char *msg, size_t msglen)
{
	return mkSceneXList_Parse(list, text, 1, 100000, 1, msg, msglen);
}

int mkSceneXList_ParseTols(void *list, const char *text, char *msg, size_t msglen)
{
	return mkSceneXList_Parse(list, text, 1e-6, 10, 0, msg, msglen);
}

/* ---- draws ---------------------------------------------------------------- */

static double mkClampAxis(double a) { return a < MK_AXIS_MIN ? MK_AXIS_MIN : a; }
static double mkClampEps(double e) { return e < MK_EPS_MIN ? MK_EPS_MIN : e > MK_EPS_MAX ? MK_EPS_MAX : e; }

static mkMat3 mkPaperRotation3(mkRng *r)
{
	double q[4], n = 0.0;
	for (int k = 0; k < 4; ++k) {
		q[k] = MK_PI * mkRng_Unit(r);
		n += q[k] * q[k];
	}
	n = sqrt(n);
	return mkMat3_FromQuat(q[0] / n, q[1] / n, q[2] / n, q[3] / n);
}

/* One body of dimension dim, numbers drawn in the order of scene.h: shape
 * (a, b[, c], eps[, eps2]), centre, rotation, then a box's sides or a
 * cylinder's radius and height (box: 0 smooth, 1 box, 2 cylinder). */
static void mkDrawBody(mkRng *r, int dim, mkSceneBody *b, int box)
{
	memset(b, 0, sizeof *b);
	b->dim = b->spec.dim = dim;
	b->spec.kind = dim == 2 ? MK_KIND_SUPERELLIPSE : MK_KIND_SUPERQUADRIC;
	double v[5], t[3];
	for (int k = 0; k < dim; ++k)
		v[k] = mkClampAxis(mkRng_Uniform(r, 0, 10));
	for (int k = dim; k < 2 * dim - 1; ++k)
		v[k] = mkClampEps(mkRng_Uniform(r, 0, 2));
	for (int k = 0; k < dim; ++k)
		t[k] = mkRng_Uniform(r, -200, 200);
	if (dim == 2)
		b->spec.body2 = mkBody2_Make((mkShape2){ v[0], v[1], v[2] }, mkMat2_Rotation(mkRng_Uniform(r, 0, MK_PI)),
			(mkVec2){ t[0], t[1] });
	else
		b->spec.body3 = mkBody3_Make((mkShape3){ v[0], v[1], v[2], v[3], v[4] }, mkPaperRotation3(r),
			(mkVec3){ t[0], t[1], t[2] });
	b->kind = box == 0 ? MK_SCENE_SMOOTH : box == 1 ? MK_SCENE_BOX : MK_SCENE_CYLINDER;
	for (int k = 0; box == 1 && k < dim; ++k)
		b->size[k] = mkRng_Uniform(r, 1, 20);
	if (box == 2) {
		b->size[0] = mkRng_Uniform(r, 0.5, 10);
		b->size[1] = mkRng_Uniform(r, 1, 20);
	}
}

mkResult mkSceneX_Draw(mkScene *s, uint64_t seed, int dim, long obstacles, int boxes, long orientations,
	const mkRotations *rot)
{
	memset(s, 0, sizeof *s);
	mkRng r;
	mkRng_Seed(&r, seed, ((uint64_t)dim << 56) | (uint64_t)obstacles);
	s->dim = dim;
	s->obstacles = calloc((size_t)obstacles, sizeof *s->obstacles);
	if (dim == 2)
		s->headings = malloc((size_t)orientations * sizeof *s->headings);
	else
		s->rotations = malloc((size_t)orientations * sizeof *s->rotations);
	if (!s->obstacles || (dim == 2 ? !s->headings : !s->rotations) || (dim == 3 && (!rot || rot->count < orientations))) {
		mkScene_Free(s);
		return MK_ERR_MEMORY;
	}
	s->obstacle_count = (int)obstacles;
	s->orientation_count = (int)orientations;
	if (dim == 2) {
		mkDrawBody(&r, 2, &s->robot, 0);
		s->robot.spec.body2.shape = (mkShape2){ mkClampAxis(mkRng_Uniform(&r, 0, 5)),
			mkClampAxis(mkRng_Uniform(&r, 0, 3)), mkClampEps(mkRng_Uniform(&r, 0, 1)) };
		s->robot.spec.body2 = mkBody2_Make(s->robot.spec.body2.shape, mkMat2_Identity(), (mkVec2){ 0, 0 });
		for (long k = 0; k < orientations; ++k)
			s->headings[k] = MK_PI * (double)k / (double)orientations;
	} else {
		mkDrawBody(&r, 3, &s->robot, 0);
		mkShape3 sh = { mkClampAxis(mkRng_Uniform(&r, 0, 5)), mkClampAxis(mkRng_Uniform(&r, 0, 5)),
			mkClampAxis(mkRng_Uniform(&r, 0, 5)), mkClampEps(mkRng_Uniform(&r, 0, 2)), mkClampEps(mkRng_Uniform(&r, 0, 2)) };
		s->robot.spec.body3 = mkBody3_Make(sh, mkMat3_Identity(), (mkVec3){ 0, 0, 0 });
		memcpy(s->rotations, rot->R, (size_t)orientations * sizeof *s->rotations);
	}
	for (long i = 0; i < obstacles; ++i) {
		int box = boxes && i % 10 == 9 ? (dim == 2 || (i / 10) % 2 == 0 ? 1 : 2) : 0;
		mkDrawBody(&r, dim, &s->obstacles[i], box);
	}
	return MK_OK;
}

/* ---- Part A ----------------------------------------------------------------- */

static double mkCpuNow(void)
{
	struct timespec t;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One whole-scene run (mkCSpace_Create, mkCSpace_Run), store = 0. */
typedef struct mkSceneXRun {
	int param;
	double error, seconds, cpu, checksum;
	long points;
	int worst_obstacle, worst_orientation;   /* the boundary of the largest error */
	int ntop, top_obstacle[MK_SCENEX_TOP], top_orientation[MK_SCENEX_TOP]; /* the largest errors, largest first */
} mkSceneXRun;

/* Orientations [begin, end) of the scene, or of its obstacle `only` alone
 * (only >= 0). */
static mkResult mkSceneX_RunPart(const mkScene *s, const mkCSpaceOptions *o, int only, int begin, int end,
	mkSceneXRun *out, char *msg, size_t msglen)
{
	mkCSpaceResult r;
	mkScene one = *s;
	if (only >= 0) {
		one.obstacles = s->obstacles + only;
		one.obstacle_count = 1;
	}
	double t0 = mkClock_Wall(), c0 = mkCpuNow();
	mkCSpace *cs = NULL;
	mkResult rc = mkCSpace_Create(&one, o, &cs, msg, msglen);
	if (rc == MK_OK)
		rc = mkCSpace_Run(cs, begin, end, &r, msg, msglen);
	mkCSpace_Destroy(cs);
	out->seconds = mkClock_Wall() - t0;
	out->cpu = mkCpuNow() - c0;
	if (rc != MK_OK)
		return rc;
	long nb = (long)r.obstacles * r.orientations * r.bounds;
	out->param = o->uniform;
	out->points = 0;
	out->checksum = 0.0;
	for (long b = 0; b < nb; ++b) {
		out->points += r.count[b];
		out->checksum += r.checksum[b];
	}
	out->error = mkCSpaceResult_MaxError(&r);
	long top[MK_SCENEX_TOP];
	int nt = 0;
	for (long b = 0; b < nb; ++b) { /* insertion into the list of the largest, first index on ties */
		int k = nt < MK_SCENEX_TOP ? nt++ : MK_SCENEX_TOP;
		while (k > 0 && r.error[b] > r.error[top[k - 1]]) {
			if (k < MK_SCENEX_TOP) top[k] = top[k - 1];
			--k;
		}
		if (k < MK_SCENEX_TOP) top[k] = b;
	}
	out->ntop = nt;
	for (int k = 0; k < nt; ++k) {
		out->top_obstacle[k] = only >= 0 ? only : (int)(top[k] / r.bounds % r.obstacles);
		out->top_orientation[k] = begin + (int)(top[k] / r.bounds / r.obstacles);
	}
	out->worst_obstacle = out->top_obstacle[0];
	out->worst_orientation = out->top_orientation[0];
	mkCSpaceResult_Free(&r);
	return MK_OK;
}

static mkResult mkSceneX_RunOnce(const mkScene *s, const mkCSpaceOptions *o, mkSceneXRun *out, char *msg,
	size_t msglen)
{
	return mkSceneX_RunPart(s, o, -1, 0, s->orientation_count, out, msg, msglen);
}

/* The 1-minute load average (other processes take cores from a wall
 * time), or NaN. */
static double mkSceneX_Load(void)
{
	char buf[64];
	mkClock_LoadAverage(buf, sizeof buf);
	char *end;
	double v = strtod(buf, &end);
	return end == buf ? NAN : v;
}

/* One row: the part, the mode and the 18 numbers of the other columns in
 * their order (NaN: empty). */
static void mkSceneX_Row(mkCsv *csv, const char *part, const char *mode, const double v[18])
{
	mkCsv_Str(csv, part);
	for (int k = 0; k < 18; ++k) {
		if (k == 5)
			mkCsv_Str(csv, mode);
		if (isnan(v[k]))
			mkCsv_Empty(csv);
		else
			mkCsv_Double(csv, v[k]);
	}
	mkCsv_EndRow(csv);
}

static void mkSceneX_RowA(mkCsv *csv, const mkScene *s, double tol, const char *mode, int threads,
	const mkSceneXRun *run, double target, int capped, double factor)
{
	long boxes = 0;
	for (int i = 0; i < s->obstacle_count; ++i)
		boxes += s->obstacles[i].kind != MK_SCENE_SMOOTH;
	const double v[18] = { s->dim, s->obstacle_count, (double)boxes, s->orientation_count, tol, threads,
		run->param >= 0 ? run->param : NAN, (double)run->points, run->seconds, run->cpu, run->error, target, capped,
		factor, run->checksum, NAN, NAN, mkSceneX_Load() };
	mkSceneX_Row(csv, "A", mode, v);
}

/* Points of one boundary at uniform level L: 2D L normals, 3D the
 * octahedron split L times. */
static double mkSceneX_Per(int three, int L) { return three ? 4.0 * pow(4.0, L) + 2.0 : (double)L; }

/* The smallest uniform sampling whose worst-case error over the scene is at
 * most target, every level tried in turn: 2D n = 4, 5, 6, ... normals (the
 * sets of normals are not nested, and the error is not monotone in n), 3D
 * splits 0, 1, 2, ... A level fails as soon as one boundary exceeds
 * target, so each level is first tried on the boundaries that failed at
 * the last whole-scene run (its MK_SCENEX_TOP largest errors), and the
 * whole scene runs only where all of those pass: the result is confirmed
 * on every boundary, and every smaller level failed on some boundary. The
 * search stops (capped) before a whole-scene run of more than `budget`
 * points, or past the largest level (2D n = 2^22, 3D 10 splits): *best is
 * then the largest level tried, which failed (as did all below it), with
 * the points the whole scene would have there and the error of its failing
 * boundary (a lower bound of the scene's error at that level; seconds, CPU
 * seconds and checksum NaN when only that boundary was run). Returns 1
 * when capped. */
static int mkSceneX_Smallest(const mkScene *s, mkCSpaceOptions *o, double target, double budget, mkSceneXRun *best,
	mkResult *rc, char *msg, size_t msglen)
{
	mkSceneXRun cur, fail;
	o->mode = MK_CSPACE_UNIFORM;
	*rc = MK_OK;
	int three = s->dim == 3, L = three ? 0 : 4, nf = 0, fo[MK_SCENEX_TOP], fr[MK_SCENEX_TOP];
	double nb = (double)s->obstacle_count * s->orientation_count;
	memset(&fail, 0, sizeof fail);
	for (;; L = L + 1) {
		if (L > (three ? 10 : 1 << 22)) {
			*best = fail;
			return 1;
		}
		o->uniform = L;
		int failed = 0;
		for (int k = 0; k < nf && !failed; ++k) { /* the last failing boundaries first */
			if ((*rc = mkSceneX_RunPart(s, o, fo[k], fr[k], fr[k] + 1, &cur, msg, msglen)) != MK_OK)
				return 0;
			if (cur.error > target) {
				failed = 1;
				fail = cur;
				fail.points = (long)(nb * mkSceneX_Per(three, L));
				fail.seconds = fail.cpu = fail.checksum = NAN;
			}
		}
		if (failed)
			continue;
		if (nf > 0 && nb * mkSceneX_Per(three, L) > budget) {
			*best = fail; /* capped: the confirming run is too large */
			return 1;
		}
		if ((*rc = mkSceneX_RunOnce(s, o, &cur, msg, msglen)) != MK_OK)
			return 0;
		if (cur.error <= target) {
			*best = cur;
			return 0;
		}
		fail = cur;
		nf = 0;
		for (int k = 0; k < cur.ntop; ++k) {
			fo[nf] = cur.top_obstacle[k];
			fr[nf] = cur.top_orientation[k];
			++nf;
		}
	}
}

mkResult mkSceneX_Compare(const mkScene *s, double tol, int threads, mkCsv *csv, char *msg, size_t msglen)
{
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.tol = tol;
	o.threads = threads;
	o.store = 0;
	o.mode = MK_CSPACE_ADAPTIVE;
	mkSceneXRun ad, un;
	mkResult rc = mkSceneX_RunOnce(s, &o, &ad, msg, msglen);
	if (rc != MK_OK)
		return rc;
	ad.param = -1;
	int capped = mkSceneX_Smallest(s, &o, ad.error, s->dim == 3 ? MK_SCENEX_BUDGET3 : MK_SCENEX_BUDGET2, &un, &rc,
		msg, msglen);
	if (rc != MK_OK)
		return rc;
	mkSceneX_RowA(csv, s, tol, "adaptive", threads, &ad, tol, 0, 1.0);
	mkSceneX_RowA(csv, s, tol, "uniform", threads, &un, ad.error, capped, (double)un.points / (double)ad.points);
	return MK_OK;
}

/* ---- Part B ----------------------------------------------------------------- */

static void mkSceneX_RowB(mkCsv *csv, const mkScene *s, int points, int threads, const mkSceneXRun *run,
	double efficiency, double load)
{
	const mkPaperTable2 *pub = mkPaper_FindTable2(s->dim, s->obstacle_count, points, s->orientation_count);
	const double v[18] = { s->dim, s->obstacle_count, 0, s->orientation_count, NAN, threads, run->param, points,
		run->seconds, run->cpu, NAN, NAN, 0, NAN, run->checksum, threads == 2 ? efficiency : NAN,
		pub ? pub->total_s : NAN, load };
	mkSceneX_Row(csv, "B", "paper", v);
}

int mkSceneX_Table2(const mkScene *s, int points, int reps, mkCsv *csv, char *msg, size_t msglen)
{
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.mode = MK_CSPACE_PAPER;
	o.store = 0;
	o.uniform = s->dim == 2 ? points : (int)lround(sqrt((double)points));
	for (int rep = 0; rep < reps; ++rep) {
		mkSceneXRun run[2];
		double load[2];
		for (int th = 1; th <= 2; ++th) {
			o.threads = th;
			load[th - 1] = mkSceneX_Load();
			if (mkSceneX_RunOnce(s, &o, &run[th - 1], msg, msglen) != MK_OK)
				return -1;
		}
		if (run[0].checksum != run[1].checksum) {
			snprintf(msg, msglen, "%dD, %d obstacles: the checksum on 1 thread (%.17g) differs from that on 2 "
				"threads (%.17g)", s->dim, s->obstacle_count, run[0].checksum, run[1].checksum);
			return -1;
		}
		double eff = run[0].seconds / (2.0 * run[1].seconds);
		mkSceneX_RowB(csv, s, points, 1, &run[0], eff, load[0]);
		mkSceneX_RowB(csv, s, points, 2, &run[1], eff, load[1]);
	}
	return 0;
}

/* ---- Fig. 9 geometry ---------------------------------------------------------- */

int mkSceneX_Figure9(mkRun *run, uint64_t seed, long obstacles, double tol)
{
	static const char *const cols[] = { "obstacle", "bound", "x", "y" };
	mkScene s;
	char msg[1024];
	if (mkSceneX_Draw(&s, seed, 2, obstacles, 1, 1, NULL) != MK_OK) {
		mkRun_Fail(run, "out of memory drawing the figure's scene");
		return -1;
	}
	mkCSpaceOptions o = mkCSpaceOptions_Default();
	o.tol = tol;
	o.outer = 1;
	mkCSpaceResult r;
	mkCSpace *cs = NULL;
	mkResult rc = mkCSpace_Create(&s, &o, &cs, msg, sizeof msg);
	if (rc == MK_OK)
		rc = mkCSpace_Run(cs, 0, 1, &r, msg, sizeof msg);
	mkCSpace_Destroy(cs);
	mkScene_Free(&s);
	if (rc != MK_OK) {
		mkRun_Fail(run, "figure: %s", msg);
		return -1;
	}
	mkCsv csv;
	if (mkRun_OpenSibling(run, "fig9-boundaries.csv", cols, MK_COUNT(cols), &csv) != 0) {
		mkCSpaceResult_Free(&r);
		return -1;
	}
	for (long b = 0; b < (long)r.obstacles * r.bounds; ++b) {
		mkCSpaceBoundary v = mkCSpaceResult_Boundary(&r, 0, (int)(b / r.bounds), (mkBound)(b % r.bounds));
		for (int p = 0; p <= v.count; ++p) { /* closed: the first point again */
			long q = (long)(p < v.count ? p : 0) * v.stride;
			mkCsv_Int(&csv, b / r.bounds);
			mkCsv_Str(&csv, b % r.bounds ? "outer" : "inner");
			mkCsv_Double(&csv, v.x[q]);
			mkCsv_Double(&csv, v.y[q]);
			mkCsv_EndRow(&csv);
		}
		fputs("\n\n", csv.file.fp); /* gnuplot's separator of data blocks */
	}
	mkCSpaceResult_Free(&r);
	mkMeta_Set(&run->meta, "content", "fig. 9: inner and outer C-obstacle boundaries of one 2D scene at heading 0");
	mkMeta_SetDouble(&run->meta, "fig9_tol", tol);
	int failed = mkCsv_Commit(&csv, &run->meta, msg, sizeof msg) != 0;
	if (failed)
		mkRun_Fail(run, "%s", msg);
	mkMeta_Set(&run->meta, "content", "scene rows: Part A (adaptive, uniform) and Part B (Table 2, 1 and 2 threads)");
	return failed ? -1 : 0;
}
