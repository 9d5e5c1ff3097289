/* cobstacle.c - configuration-space obstacles: draws, the timed loop, the
 * rows, the Fig. 9 geometry and the Table 2 summary (see cobstacle.h). */
#include "cobstacle.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const mkCObstacle_Columns[] = {
	"dim", "obstacles", "points", "orientations", "total_points", "total_s", "us_per_point",
	"cpu_s", "trial", "form", "impl", "published_total_s", "published_us_per_point",
	"nonfinite", "clamped", "checksum",
	"robot_a", "robot_b", "robot_c", "robot_eps1", "robot_eps2", NULL
};

int mkCObstacleLevels_Parse(void *levels, const char *text, char *msg, size_t msglen)
{
	mkCObstacleLevels *l = levels;
	l->n = 0;
	const char *p = text;
	for (;;) {
		const char *comma = strchr(p, ',');
		size_t len = comma ? (size_t)(comma - p) : strlen(p);
		char item[32], why[256];
		long v = 0;
		int bad = len == 0 || len >= sizeof item || l->n >= MK_COBSTACLE_MAX_LEVELS;
		if (!bad) {
			memcpy(item, p, len);
			item[len] = '\0';
			bad = mkArg_Long("level", item, 1, MK_COBSTACLE_OBSTACLES_MAX, &v, why, sizeof why) != 0;
		}
		if (bad) {
			snprintf(msg, msglen, "is not allowed: must be up to %d comma-separated integers in [1, %ld]",
				MK_COBSTACLE_MAX_LEVELS, MK_COBSTACLE_OBSTACLES_MAX);
			return -1;
		}
		l->count[l->n++] = v;
		if (!comma)
			return 0;
		p = comma + 1;
	}
}

/* ---- draws --------------------------------------------------------------- */

static double mkClamp(double v, double lo, double hi, long *clamped)
{
	if (v < lo) {
		*clamped += 1;
		return lo;
	}
	if (v > hi) {
		*clamped += 1;
		return hi;
	}
	return v;
}

/* Shapes by mkDraw_Shape2/3 from U(0, hi) ranges, then clamped into the
 * core's valid ranges (each value out of range counted). */
static mkShape2 mkDrawShape2(mkRng *r, double a, double b, double eps, long *clamped)
{
	const mkShapeRange2 range = { { 0.0, a }, { 0.0, b }, { 0.0, eps } };
	mkShape2 s = mkDraw_Shape2(r, &range);
	s.a = mkClamp(s.a, MK_AXIS_MIN, MK_AXIS_MAX, clamped);
	s.b = mkClamp(s.b, MK_AXIS_MIN, MK_AXIS_MAX, clamped);
	s.eps = mkClamp(s.eps, MK_EPS_MIN, MK_EPS_MAX, clamped);
	return s;
}

static mkShape3 mkDrawShape3(mkRng *r, double axis, long *clamped)
{
	const mkShapeRange3 range = { { 0.0, axis }, { 0.0, axis }, { 0.0, axis }, { 0.0, 2.0 }, { 0.0, 2.0 } };
	mkShape3 s = mkDraw_Shape3(r, &range);
	s.a = mkClamp(s.a, MK_AXIS_MIN, MK_AXIS_MAX, clamped);
	s.b = mkClamp(s.b, MK_AXIS_MIN, MK_AXIS_MAX, clamped);
	s.c = mkClamp(s.c, MK_AXIS_MIN, MK_AXIS_MAX, clamped);
	s.eps1 = mkClamp(s.eps1, MK_EPS_MIN, MK_EPS_MAX, clamped);
	s.eps2 = mkClamp(s.eps2, MK_EPS_MIN, MK_EPS_MAX, clamped);
	return s;
}

/* *angle (may be NULL) receives the obstacle's rotation angle. */
static mkBody2 mkDrawObstacle2(mkRng *r, long *clamped, double *angle)
{
	mkShape2 s = mkDrawShape2(r, 10.0, 10.0, 2.0, clamped);
	mkVec2 t;
	t.x = mkRng_Uniform(r, -200.0, 200.0);
	t.y = mkRng_Uniform(r, -200.0, 200.0);
	double phi = mkRng_Uniform(r, 0.0, MK_PI);
	if (angle)
		*angle = phi;
	return mkBody2_Make(s, mkMat2_Rotation(phi), t);
}

/* The obstacle's rotation is the reference code's draw of this experiment,
 * the quaternion q_i = pi U(0,1) normalised: not mkDraw_Quat's 4 U(0,1)
 * (normalising pi q rounds differently from normalising q, so the shared
 * draw would change the bodies in the last bits). Returns 0 when the
 * quaternion is degenerate (all four draws zero: probability 2^-212),
 * which the caller reports. */
static int mkDrawObstacle3(mkRng *r, long *clamped, mkBody3 *out)
{
	mkShape3 s = mkDrawShape3(r, 10.0, clamped);
	mkVec3 t;
	t.x = mkRng_Uniform(r, -200.0, 200.0);
	t.y = mkRng_Uniform(r, -200.0, 200.0);
	t.z = mkRng_Uniform(r, -200.0, 200.0);
	double q[4];
	for (int i = 0; i < 4; ++i)
		q[i] = MK_PI * mkRng_Unit(r);
	mkMat3 R = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
	*out = mkBody3_Make(s, R, t);
	return mkMat3_IsFinite(R);
}

static uint64_t mkStream(int figure, int dim, long obstacles, long trial)
{
	return ((uint64_t)(figure != 0) << 62) | ((uint64_t)dim << 56)
		| ((uint64_t)obstacles << 24) | (uint64_t)trial;
}

static mkSumOptions mkCObstacle_SumOptions(const mkCObstacleOptions *o)
{
	mkSumOptions opt = mkSumOptions_Default();
	opt.set = MK_SET_CONTACT;
	opt.form = o->form;
	opt.param = MK_PARAM_SURFACE;
	opt.impl = o->impl;
	return opt;
}

/* ---- the orientations of the 3D robot ------------------------------------ */

/* Nine comma-separated numbers (blanks around them allowed) into v;
 * 0 or -1. */
static int mkParseNine(const char *line, double v[9])
{
	const char *p = line;
	char *end = NULL;
	for (int k = 0; k < 9; ++k) {
		errno = 0;
		v[k] = strtod(p, &end);
		if (end == p || errno != 0 || !isfinite(v[k]))
			return -1;
		p = end;
		while (*p == ' ' || *p == '\t')
			++p;
		if (k < 8) {
			if (*p != ',')
				return -1;
			++p;
		}
	}
	while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')
		++p;
	return *p == '\0' ? 0 : -1;
}

/* The largest entry of |R^T R - I| and |det R - 1|. */
static double mkRotationError(mkMat3 R)
{
	mkMat3 RtR = mkMat3_Mul(mkMat3_Transpose(R), R);
	double err = fabs(mkMat3_Det(R) - 1.0);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			err = fmax(err, fabs(RtR.m[i][j] - (i == j ? 1.0 : 0.0)));
	return err;
}

/* One line's rotation appended to rot; 0 or -1 with a message. */
static int mkRotations_Add(mkRotations *rot, long *cap, const char *path, long lineno, const char *line,
	char *msg, size_t msglen)
{
	double v[9];
	if (mkParseNine(line, v) != 0) {
		snprintf(msg, msglen, "--so3: %s:%ld: expected nine comma-separated numbers", path, lineno);
		return -1;
	}
	mkMat3 R;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			R.m[i][j] = v[3 * i + j];
	double err = mkRotationError(R);
	if (!(err <= 1e-9)) {
		snprintf(msg, msglen, "--so3: %s:%ld: not a rotation matrix (|R^T R - I| or |det R - 1| is %.3g)",
			path, lineno, err);
		return -1;
	}
	rot->max_error = fmax(rot->max_error, err);
	if (rot->count == *cap) {
		long ncap = *cap ? 2 * *cap : 1024;
		mkMat3 *nr = realloc(rot->R, (size_t)ncap * sizeof *nr);
		if (!nr) {
			snprintf(msg, msglen, "--so3: out of memory reading '%s'", path);
			return -1;
		}
		rot->R = nr;
		*cap = ncap;
	}
	rot->R[rot->count++] = R;
	if (rot->count > MK_COBSTACLE_SO3_MAX) {
		snprintf(msg, msglen, "--so3: %s: more than %ld rotations", path, MK_COBSTACLE_SO3_MAX);
		return -1;
	}
	return 0;
}

int mkRotations_Read(mkRotations *rot, const char *path, long limit, char *msg, size_t msglen)
{
	memset(rot, 0, sizeof *rot);
	FILE *fp = fopen(path, "r");
	if (!fp) {
		snprintf(msg, msglen, "--so3: cannot open '%s': %s", path, strerror(errno));
		return -1;
	}
	char line[1024];
	long lineno = 0, cap = 0;
	int failed = 0;
	while (!failed && fgets(line, sizeof line, fp)) {
		++lineno;
		if (lineno == 1)
			continue; /* header */
		if (line[0] == '\n' || line[0] == '\r' || line[0] == '\0')
			continue;
		if (limit > 0 && rot->count >= limit)
			break;
		failed = mkRotations_Add(rot, &cap, path, lineno, line, msg, msglen) != 0;
	}
	if (!failed && ferror(fp)) {
		snprintf(msg, msglen, "--so3: error reading '%s'", path);
		failed = 1;
	}
	fclose(fp);
	if (!failed && rot->count == 0) {
		snprintf(msg, msglen, "--so3: '%s' holds no rotation", path);
		failed = 1;
	}
	if (!failed && limit > 0 && rot->count < limit) {
		snprintf(msg, msglen, "--orientations: %ld requested, but '%s' holds only %ld",
			limit, path, rot->count);
		failed = 1;
	}
	if (failed) {
		mkRotations_Free(rot);
		return -1;
	}
	return 0;
}

void mkRotations_Free(mkRotations *rot)
{
	free(rot->R);
	memset(rot, 0, sizeof *rot);
}

/* ---- units and work ------------------------------------------------------ */

long mkCObstacle_Units(const mkCObstacleOptions *o, mkCObstacleUnit **units)
{
	long nunits = o->trials * ((o->dim2 ? o->levels2.n : 0) + (o->dim3 ? o->levels3.n : 0));
	*units = malloc((size_t)(nunits > 0 ? nunits : 1) * sizeof **units);
	if (!*units)
		return -1;
	long u = 0;
	for (int d = 2; d <= 3; ++d) {
		if ((d == 2 && !o->dim2) || (d == 3 && !o->dim3))
			continue;
		const mkCObstacleLevels *l = d == 2 ? &o->levels2 : &o->levels3;
		for (int k = 0; k < l->n; ++k)
			for (long t = 0; t < o->trials; ++t) {
				(*units)[u].dim = d;
				(*units)[u].obstacles = l->count[k];
				(*units)[u].trial = t;
				++u;
			}
	}
	return nunits;
}

int mkCObstacleWork_Init(mkCObstacleWork *w2, mkCObstacleWork *w3, const mkCObstacleOptions *o)
{
	memset(w2, 0, sizeof *w2);
	memset(w3, 0, sizeof *w3);
	w2->n = o->points2;
	w3->n = o->grid3 * o->grid3;
	w2->ux = malloc((size_t)w2->n * sizeof(double));
	w2->uy = malloc((size_t)w2->n * sizeof(double));
	w3->ux = malloc((size_t)w3->n * sizeof(double));
	w3->uy = malloc((size_t)w3->n * sizeof(double));
	w3->uz = malloc((size_t)w3->n * sizeof(double));
	if (!w2->ux || !w2->uy || !w3->ux || !w3->uy || !w3->uz)
		return -1;
	return mkSample2_Angles((int)w2->n, w2->ux, w2->uy) != MK_OK
		|| mkSample3_Grid((int)o->grid3, w3->ux, w3->uy, w3->uz) != MK_OK ? -1 : 0;
}

static int mkCObstacleWork_Reserve(mkCObstacleWork *w, long count)
{
	if (count <= w->capacity)
		return 0;
	double *p[3];
	for (int i = 0; i < 3; ++i)
		p[i] = malloc((size_t)count * sizeof(double));
	if (!p[0] || !p[1] || !p[2]) {
		for (int i = 0; i < 3; ++i)
			free(p[i]);
		return -1;
	}
	free(w->x);
	free(w->y);
	free(w->z);
	w->x = p[0];
	w->y = p[1];
	w->z = p[2];
	w->capacity = count;
	return 0;
}

void mkCObstacleWork_Free(mkCObstacleWork *w)
{
	free(w->ux);
	free(w->uy);
	free(w->uz);
	free(w->x);
	free(w->y);
	free(w->z);
	memset(w, 0, sizeof *w);
}

/* ---- the timed loop ------------------------------------------------------ */

/* Sum and count of the non-finite values of one slice, outside the timing. */
static void mkSlice_Digest(const mkCObstacleWork *w, long count, int dim, mkCObstacleResult *res)
{
	double s = 0.0;
	for (long i = 0; i < count; ++i) {
		double v = w->x[i] + w->y[i] + (dim == 3 ? w->z[i] : 0.0);
		if (isfinite(v))
			s += v;
		else
			res->nonfinite += 1;
	}
	res->checksum += s;
}

/* The obstacles of a unit (an array of mkBody2 in 2D, of mkBody3 in 3D),
 * drawn after the robot, and room for their slice; NULL after printing
 * why. */
static void *mkDrawObstacles(mkRng *rng, int dim, long nobs, long trial, mkCObstacleWork *w, long *clamped)
{
	void *obs = malloc((size_t)nobs * (dim == 2 ? sizeof(mkBody2) : sizeof(mkBody3)));
	if (!obs || mkCObstacleWork_Reserve(w, nobs * w->n) != 0) {
		free(obs);
		fprintf(stderr, "cobstacle: out of memory for %ld obstacles\n", nobs);
		return NULL;
	}
	char msg[256];
	for (long j = 0; j < nobs; ++j) {
		int valid;
		if (dim == 2) {
			mkBody2 *b = (mkBody2 *)obs + j;
			*b = mkDrawObstacle2(rng, clamped, NULL);
			valid = mkBody2_IsValid(*b, "obstacle", msg, sizeof msg);
		} else {
			mkBody3 *b = (mkBody3 *)obs + j;
			if (!mkDrawObstacle3(rng, clamped, b)) {
				snprintf(msg, sizeof msg, "a zero quaternion was drawn");
				valid = 0;
			} else {
				valid = mkBody3_IsValid(*b, "obstacle", msg, sizeof msg);
			}
		}
		if (!valid) {
			fprintf(stderr, "cobstacle: %dD trial %ld, obstacle %ld: %s\n", dim, trial, j, msg);
			free(obs);
			return NULL;
		}
	}
	return obs;
}

/* One unit in progress: the robot and the obstacles drawn for it. */
typedef struct mkLevel {
	const mkCObstacleOptions *o;
	const mkRotations *rot;
	mkCObstacleWork *w;
	int dim;
	long nobs;
	mkShape2 robot2;
	mkShape3 robot3;
	void *obs;            /* mkBody2 or mkBody3 array */
	mkSumOptions opt;
} mkLevel;

/* The timed work of orientation k: the robot turned (2D: heading
 * k pi / H; 3D: rotation k of the file), one batch call per obstacle. */
static mkResult mkLevel_Slice(const mkLevel *l, long k)
{
	const mkCObstacleWork *w = l->w;
	int n = (int)w->n;
	mkResult rc = MK_OK;
	if (l->dim == 2) {
		mkVec2 origin = { 0.0, 0.0 };
		mkBody2 rb = mkBody2_Make(l->robot2, mkMat2_Rotation((double)k * MK_PI / (double)l->o->headings), origin);
		const mkBody2 *obs = l->obs;
		for (long j = 0; j < l->nobs && rc == MK_OK; ++j)
			rc = mkSum2_Batch(obs[j], rb, &l->opt, w->ux, w->uy, n,
				w->x + j * n, w->y + j * n, NULL, NULL);
	} else {
		mkVec3 origin = { 0.0, 0.0, 0.0 };
		mkBody3 rb = mkBody3_Make(l->robot3, l->rot->R[k], origin);
		const mkBody3 *obs = l->obs;
		for (long j = 0; j < l->nobs && rc == MK_OK; ++j)
			rc = mkSum3_Batch(obs[j], rb, &l->opt, w->ux, w->uy, w->uz, n,
				w->x + j * n, w->y + j * n, w->z + j * n, NULL, NULL, NULL);
	}
	return rc;
}

/* The robot of a unit (drawn first from its stream) into l and res. */
static void mkLevel_DrawRobot(mkLevel *l, mkRng *rng, mkCObstacleResult *res)
{
	if (l->dim == 2) {
		l->robot2 = mkDrawShape2(rng, 5.0, 3.0, 1.0, &res->clamped);
		const double rv[5] = { l->robot2.a, l->robot2.b, NAN, l->robot2.eps, NAN };
		memcpy(res->robot, rv, sizeof rv);
	} else {
		l->robot3 = mkDrawShape3(rng, 5.0, &res->clamped);
		const double rv[5] = { l->robot3.a, l->robot3.b, l->robot3.c, l->robot3.eps1, l->robot3.eps2 };
		memcpy(res->robot, rv, sizeof rv);
	}
}

/* 1 when the unturned robot at the origin is a valid body, else 0 with a
 * message. */
static int mkLevel_RobotIsValid(const mkLevel *l, char *msg, size_t msglen)
{
	mkVec2 o2 = { 0.0, 0.0 };
	mkVec3 o3 = { 0.0, 0.0, 0.0 };
	if (l->dim == 2)
		return mkBody2_IsValid(mkBody2_Make(l->robot2, mkMat2_Identity(), o2), "robot", msg, msglen);
	return mkBody3_IsValid(mkBody3_Make(l->robot3, mkMat3_Identity(), o3), "robot", msg, msglen);
}

int mkCObstacle_Level(const mkCObstacleOptions *o, const mkCObstacleUnit *u, const mkRotations *rot,
	mkCObstacleWork *w, mkProgress *prog, mkCObstacleResult *res)
{
	memset(res, 0, sizeof *res);
	mkLevel l;
	memset(&l, 0, sizeof l);
	l.o = o;
	l.rot = rot;
	l.w = w;
	l.dim = u->dim;
	l.nobs = u->obstacles;
	l.opt = mkCObstacle_SumOptions(o);
	mkRng rng;
	mkRng_Seed(&rng, o->seed, mkStream(0, u->dim, u->obstacles, u->trial));
	mkLevel_DrawRobot(&l, &rng, res);
	l.obs = mkDrawObstacles(&rng, u->dim, u->obstacles, u->trial, w, &res->clamped);
	if (!l.obs)
		return -1;
	char msg[256];
	if (!mkLevel_RobotIsValid(&l, msg, sizeof msg)) {
		fprintf(stderr, "cobstacle: %dD trial %ld: %s\n", u->dim, u->trial, msg);
		free(l.obs);
		return -1;
	}
	long orientations = u->dim == 2 ? o->headings : rot->count;
	for (long k = 0; k < orientations; ++k) {
		double t0 = mkClock_Wall(), c0 = mkClock_ThreadCpu();
		mkResult rc = mkLevel_Slice(&l, k);
		res->cpu_s += mkClock_ThreadCpu() - c0;
		res->total_s += mkClock_Wall() - t0;
		if (rc != MK_OK) {
			fprintf(stderr, "cobstacle: %dD trial %ld: the closed form failed: %s\n", u->dim, u->trial,
				mkResult_Name(rc));
			free(l.obs);
			return -1;
		}
		mkSlice_Digest(w, u->obstacles * w->n, u->dim, res);
		mkProgress_Add(prog, 1);
	}
	free(l.obs);
	return 0;
}

/* ---- rows and the sidecar ------------------------------------------------ */

/* A number, or an empty field for NaN (a level the paper does not list,
 * a robot dimension 2D does not have). */
static void mkCsv_DoubleOrEmpty(mkCsv *csv, double v)
{
	if (isnan(v))
		mkCsv_Empty(csv);
	else
		mkCsv_Double(csv, v);
}

void mkCObstacle_WriteRow(mkCsv *csv, const mkCObstacleOptions *o, const mkCObstacleUnit *u, long points,
	long orientations, const mkCObstacleResult *res)
{
	long long total = (long long)u->obstacles * points * orientations;
	const mkPaperTable2 *pub = mkPaper_FindTable2(u->dim, u->obstacles, points, orientations);
	mkCsv_Int(csv, u->dim);
	mkCsv_Int(csv, u->obstacles);
	mkCsv_Int(csv, points);
	mkCsv_Int(csv, orientations);
	mkCsv_Int(csv, total);
	mkCsv_Double(csv, res->total_s);
	mkCsv_Double(csv, res->total_s * 1e6 / (double)total);
	mkCsv_Double(csv, res->cpu_s);
	mkCsv_Int(csv, u->trial);
	mkCsv_Str(csv, mkForm_Name(o->form));
	mkCsv_Str(csv, mkImpl_Name(mkImpl_Resolve(o->impl)));
	mkCsv_DoubleOrEmpty(csv, pub ? pub->total_s : NAN);
	mkCsv_DoubleOrEmpty(csv, pub ? pub->us_per_point : NAN);
	mkCsv_Int(csv, res->nonfinite);
	mkCsv_Int(csv, res->clamped);
	mkCsv_Double(csv, res->checksum);
	for (int i = 0; i < 5; ++i)
		mkCsv_DoubleOrEmpty(csv, res->robot[i]);
	mkCsv_EndRow(csv);
}

static void mkSetLevels(mkMeta *meta, const char *key, const mkCObstacleLevels *l)
{
	char text[512] = "";
	for (int k = 0; k < l->n; ++k)
		snprintf(text + strlen(text), sizeof text - strlen(text), "%s%ld", k ? "," : "", l->count[k]);
	mkMeta_Set(meta, key, text);
}

void mkCObstacle_Describe(mkMeta *meta, const mkCObstacleOptions *o, long begin, long end, long nunits,
	const mkRotations *rot)
{
	char text[512];
	snprintf(text, sizeof text, "%ld..%ld of %ld", begin, end - 1, nunits);
	mkMeta_Set(meta, "unit_range", end > begin ? text : "none");
	mkMeta_Set(meta, "units", "(dim, obstacles, trial), dim 2 first, obstacle counts as listed, trials inner");
	mkMeta_Set(meta, "dims", o->dim2 && o->dim3 ? "2,3" : o->dim2 ? "2" : "3");
	mkSetLevels(meta, "obstacles_2d", &o->levels2);
	mkSetLevels(meta, "obstacles_3d", &o->levels3);
	mkMeta_SetInt(meta, "headings_2d", o->headings);
	mkMeta_Set(meta, "headings_2d_angles", "k pi / H, k = 0..H-1 (the reference code's (k-1) pi / 50, k = 1..50)");
	mkMeta_SetInt(meta, "points_2d", o->points2);
	mkMeta_SetInt(meta, "grid_3d", o->grid3);
	mkMeta_Set(meta, "so3_file", rot ? o->so3 : "not read");
	mkMeta_SetInt(meta, "orientations_3d", rot ? rot->count : 0);
	if (rot)
		mkMeta_SetDouble(meta, "so3_max_rotation_error", rot->max_error);
	mkMeta_Set(meta, "set", mkSet_Name(MK_SET_CONTACT));
	mkMeta_Set(meta, "bodies", "B1 = obstacle (its surface parameters), B2 = robot at the orientation, centred at the origin");
	mkMeta_Set(meta, "param", mkParam_Name(MK_PARAM_SURFACE));
	mkMeta_Set(meta, "form", mkForm_Name(o->form));
	mkMeta_Set(meta, "impl_requested", mkImpl_Name(o->impl));
	mkMeta_Set(meta, "impl", mkImpl_Name(mkImpl_Resolve(o->impl)));
	mkMeta_Set(meta, "timer", "CLOCK_MONOTONIC (total_s), CLOCK_THREAD_CPUTIME_ID (cpu_s), one thread");
	mkClock_LoadAverage(text, sizeof text);
	mkMeta_Set(meta, "loadavg_start", text);
	mkMeta_Set(meta, "timed_region",
		"per orientation: turning the robot and one batch call per obstacle; "
		"excludes the draws, the checksum and the output");
	mkMeta_Set(meta, "rng", "xoshiro256** seeded by splitmix64; stream (dim << 56) | (obstacles << 24) | trial; "
		"figure scene (1 << 62) | (2 << 56) | (obstacles << 24)");
	mkMeta_Set(meta, "draw_2d", "robot a~U(0,5) b~U(0,3) eps~U(0,1); obstacles a,b~U(0,10) eps~U(0,2) "
		"centre~U(-200,200)^2 angle~U(0,pi)");
	mkMeta_Set(meta, "draw_3d", "robot a,b,c~U(0,5) eps1,eps2~U(0,2) unrotated; obstacles a,b,c~U(0,10) "
		"eps1,eps2~U(0,2) centre~U(-200,200)^3 rotation quat pi*U(0,1)^4 normalised");
	snprintf(text, sizeof text, "semi-axes into [%g, %g], exponents into [%g, %.7g]; counted per row in 'clamped'",
		MK_AXIS_MIN, MK_AXIS_MAX, MK_EPS_MIN, MK_EPS_MAX);
	mkMeta_Set(meta, "clamping", text);
	mkMeta_Set(meta, "published", "paper Table 2 (MATLAB, Xeon 2.8 GHz, one core), in published_total_s / published_us_per_point");
}

/* ---- Fig. 9: one 2D scene, its obstacles and some C-slices ---------------- */

typedef struct mkFig9Scene {
	mkShape2 robot;
	long nobs;
	mkBody2 *obs;
	double *angle;
} mkFig9Scene;

static int mkFigure_Commit(mkCsv *csv, mkMeta *meta, const char *content)
{
	char msg[1024];
	mkMeta_Set(meta, "content", content);
	if (mkCsv_Commit(csv, meta, msg, sizeof msg) != 0) {
		fprintf(stderr, "cobstacle: %s\n", msg);
		return -1;
	}
	return 0;
}

/* Two blank lines: gnuplot's separator of data blocks. */
static void mkEndBlock(mkCsv *csv)
{
	fputs("\n\n", csv->file.fp);
}

/* The closed outline of b at the samples of w (k = n repeats k = 0):
 * rows of the lead fields (nlead 1: i; 3: i, h, heading), k, x, y, then a
 * block end. */
static void mkWriteOutline(mkCsv *csv, mkBody2 b, const mkCObstacleWork *w, int nlead, long i, long h,
	double heading)
{
	int n = (int)w->n;
	for (int k = 0; k <= n; ++k) {
		mkVec2 u = { w->ux[k % n], w->uy[k % n] };
		mkVec2 p = mkBody2_Point(b, u);
		mkCsv_Int(csv, i);
		if (nlead == 3) {
			mkCsv_Int(csv, h);
			mkCsv_Double(csv, heading);
		}
		mkCsv_Int(csv, k);
		mkCsv_Double(csv, p.x);
		mkCsv_Double(csv, p.y);
		mkCsv_EndRow(csv);
	}
	mkEndBlock(csv);
}

static int mkFigure_Scene(mkRun *run, const mkFig9Scene *s)
{
	static const char *const cols[] = { "body", "index", "a", "b", "eps", "cx", "cy", "angle" };
	mkCsv csv;
	if (mkRun_OpenSibling(run, "fig9-scene.csv", cols, MK_COUNT(cols), &csv) != 0)
		return -1;
	for (long j = -1; j < s->nobs; ++j) {
		mkShape2 sh = j < 0 ? s->robot : s->obs[j].shape;
		mkCsv_Str(&csv, j < 0 ? "robot" : "obstacle");
		mkCsv_Int(&csv, j < 0 ? 0 : j);
		mkCsv_Double(&csv, sh.a);
		mkCsv_Double(&csv, sh.b);
		mkCsv_Double(&csv, sh.eps);
		mkCsv_Double(&csv, j < 0 ? 0.0 : s->obs[j].t.x);
		mkCsv_Double(&csv, j < 0 ? 0.0 : s->obs[j].t.y);
		mkCsv_Double(&csv, j < 0 ? 0.0 : s->angle[j]);
		mkCsv_EndRow(&csv);
	}
	return mkFigure_Commit(&csv, &run->meta, "fig. 9 scene: the robot (unturned, at the origin) and the obstacles");
}

static int mkFigure_Obstacles(mkRun *run, const mkFig9Scene *s, const mkCObstacleWork *w)
{
	static const char *const cols[] = { "obstacle", "k", "x", "y" };
	mkCsv csv;
	if (mkRun_OpenSibling(run, "fig9-obstacles.csv.gz", cols, MK_COUNT(cols), &csv) != 0)
		return -1;
	for (long j = 0; j < s->nobs; ++j)
		mkWriteOutline(&csv, s->obs[j], w, 1, j, 0, 0.0);
	return mkFigure_Commit(&csv, &run->meta, "fig. 9 obstacles in the workspace, closed outlines");
}

/* The heading index of drawn slice i: floor(i H / L). */
static long mkSliceHeading(const mkCObstacleOptions *o, long i, double *heading)
{
	long h = i * o->headings / o->fig_slices;
	*heading = (double)h * MK_PI / (double)o->headings;
	return h;
}

static int mkFigure_Robot(mkRun *run, const mkCObstacleOptions *o, const mkFig9Scene *s, const mkCObstacleWork *w)
{
	static const char *const cols[] = { "slice", "heading_index", "heading", "k", "x", "y" };
	mkCsv csv;
	mkVec2 origin = { 0.0, 0.0 };
	if (mkRun_OpenSibling(run, "fig9-robot.csv", cols, MK_COUNT(cols), &csv) != 0)
		return -1;
	for (long i = 0; i < o->fig_slices; ++i) {
		double heading;
		long h = mkSliceHeading(o, i, &heading);
		mkWriteOutline(&csv, mkBody2_Make(s->robot, mkMat2_Rotation(heading), origin), w, 3, i, h, heading);
	}
	return mkFigure_Commit(&csv, &run->meta, "fig. 9 robot at the drawn headings, centred at the origin");
}

static int mkFigure_Slices(mkRun *run, const mkCObstacleOptions *o, const mkFig9Scene *s, const mkCObstacleWork *w,
	double *x, double *y)
{
	static const char *const cols[] = { "slice", "heading_index", "heading", "obstacle", "k", "x", "y" };
	mkCsv csv;
	int n = (int)w->n;
	mkVec2 origin = { 0.0, 0.0 };
	mkSumOptions opt = mkCObstacle_SumOptions(o);
	if (mkRun_OpenSibling(run, "fig9-slices.csv.gz", cols, MK_COUNT(cols), &csv) != 0)
		return -1;
	for (long i = 0; i < o->fig_slices; ++i) {
		double heading;
		long h = mkSliceHeading(o, i, &heading);
		mkBody2 rb = mkBody2_Make(s->robot, mkMat2_Rotation(heading), origin);
		for (long j = 0; j < s->nobs; ++j) {
			mkResult rc = mkSum2_Batch(s->obs[j], rb, &opt, w->ux, w->uy, n, x, y, NULL, NULL);
			if (rc != MK_OK) {
				fprintf(stderr, "cobstacle: figure: the closed form failed: %s\n", mkResult_Name(rc));
				mkCsv_Discard(&csv);
				return -1;
			}
			for (int k = 0; k <= n; ++k) {
				mkCsv_Int(&csv, i);
				mkCsv_Int(&csv, h);
				mkCsv_Double(&csv, heading);
				mkCsv_Int(&csv, j);
				mkCsv_Int(&csv, k);
				mkCsv_Double(&csv, x[k % n]);
				mkCsv_Double(&csv, y[k % n]);
				mkCsv_EndRow(&csv);
			}
			mkEndBlock(&csv);
		}
	}
	return mkFigure_Commit(&csv, &run->meta, "fig. 9 C-obstacles obstacle (+) (-robot) at the drawn headings");
}

int mkCObstacle_Figure9(mkRun *run, const mkCObstacleOptions *o, const mkCObstacleWork *w2)
{
	char msg[1024];
	mkFig9Scene s;
	s.nobs = o->fig_obstacles;
	int n = (int)w2->n;
	long clamped = 0;
	mkRng rng;
	mkRng_Seed(&rng, o->seed, mkStream(1, 2, s.nobs, 0));
	s.robot = mkDrawShape2(&rng, 5.0, 3.0, 1.0, &clamped);
	s.obs = malloc((size_t)s.nobs * sizeof *s.obs);
	s.angle = malloc((size_t)s.nobs * sizeof *s.angle);
	double *x = malloc((size_t)n * sizeof *x), *y = malloc((size_t)n * sizeof *y);
	int failed = !s.obs || !s.angle || !x || !y;
	if (failed)
		fprintf(stderr, "cobstacle: out of memory for the figure\n");
	for (long j = 0; j < s.nobs && !failed; ++j) {
		s.obs[j] = mkDrawObstacle2(&rng, &clamped, &s.angle[j]);
		if (!mkBody2_IsValid(s.obs[j], "obstacle", msg, sizeof msg)) {
			fprintf(stderr, "cobstacle: figure, obstacle %ld: %s\n", j, msg);
			failed = 1;
		}
	}
	mkMeta *meta = &run->meta;
	mkMeta_SetInt(meta, "fig9_obstacles", s.nobs);
	mkMeta_SetInt(meta, "fig9_slices", o->fig_slices);
	mkMeta_SetInt(meta, "fig9_clamped", clamped);
	mkMeta_Set(meta, "fig9_slices_drawn", "headings k pi / H for k = floor(i H / L), i = 0..L-1");
	failed = failed || mkFigure_Scene(run, &s) != 0 || mkFigure_Obstacles(run, &s, w2) != 0
		|| mkFigure_Robot(run, o, &s, w2) != 0 || mkFigure_Slices(run, o, &s, w2, x, y) != 0;
	free(s.obs);
	free(s.angle);
	free(x);
	free(y);
	return failed ? -1 : 0;
}

/* ---- the summary: Table 2 ------------------------------------------------ */

#define MK_CELL_MAX 256

/* The means of total_s and us_per_point over the rows of one published
 * level (us_per_point computed from total_s when the column is missing). */
static void mkCObstacle_Means(const mkTable *t, const mkPaperTable2 *pub, double *total, double *per)
{
	int cdim = mkTable_Col(t, "dim"), cobs = mkTable_Col(t, "obstacles"), cpts = mkTable_Col(t, "points");
	int cori = mkTable_Col(t, "orientations"), ctot = mkTable_Col(t, "total_s");
	int cper = mkTable_Col(t, "us_per_point");
	mkMean mt, mp;
	memset(&mt, 0, sizeof mt);
	memset(&mp, 0, sizeof mp);
	for (long r = 0; r < t->rows; ++r)
		if ((int)mkTable_Num(t, r, cdim) == pub->dim && (int)mkTable_Num(t, r, cobs) == pub->obstacles
			&& (int)mkTable_Num(t, r, cpts) == pub->points
			&& (int)mkTable_Num(t, r, cori) == pub->orientations) {
			double tot = mkTable_Num(t, r, ctot);
			mkMean_Add(&mt, tot);
			mkMean_Add(&mp, cper >= 0 ? mkTable_Num(t, r, cper)
				: tot / ((double)pub->obstacles * pub->points * pub->orientations) * 1e6);
		}
	*total = mkMean_Get(&mt);
	*per = mkMean_Get(&mp);
}

static void mkCObstacle_Table(mkDoc *d, const mkTable *t, int usable, mkTally *tally)
{
	static const char *const head[] = { "dim", "obstacles", "points", "orientations", "published total (s)",
		"reproduced", "ratio", "published per point (µs)", "reproduced", "ratio" };
	mkDoc_TableBegin(d, "C-obstacle generation: total time and time per boundary point.", 10, head);
	for (int i = 0; i < mkPaper_Table2Count; ++i) {
		const mkPaperTable2 *pub = &mkPaper_Table2[i];
		double v = NAN, per = NAN;
		if (usable)
			mkCObstacle_Means(t, pub, &v, &per);
		char a[8][MK_CELL_MAX];
		snprintf(a[0], MK_CELL_MAX, "%dD", pub->dim);
		snprintf(a[1], MK_CELL_MAX, "%ld", pub->obstacles);
		snprintf(a[2], MK_CELL_MAX, "%ld", pub->points);
		snprintf(a[3], MK_CELL_MAX, "%ld", pub->orientations);
		if (isnan(v)) {
			snprintf(a[4], MK_CELL_MAX, "%s", mkNotYet);
			snprintf(a[6], MK_CELL_MAX, "%s", mkNotYet);
		} else {
			snprintf(a[4], MK_CELL_MAX, "%.4g", v);
			snprintf(a[6], MK_CELL_MAX, "%.4g", per);
		}
		mkFmt_Ratio(a[5], MK_CELL_MAX, v, pub->total_s);
		mkFmt_Ratio(a[7], MK_CELL_MAX, per, pub->us_per_point);
		const char *row[10] = { a[0], a[1], a[2], a[3], pub->total_text, a[4], a[5], pub->per_point_text, a[6], a[7] };
		mkDoc_Row(d, row);
		mkTally_Add(tally, !isnan(v));
		mkTally_Add(tally, !isnan(v));
	}
	mkDoc_TableEnd(d);
}

void mkCObstacle_Summary(mkDoc *d, const char *dir, mkTally *tally)
{
	static const char *const columns[] = { "dim", "obstacles", "points", "orientations", "total_s", NULL };
	mkSection s;
	int usable = mkSection_Begin(&s, d, "Configuration-space obstacles (paper §7.1, Table 2)", dir,
		"cobstacle.csv", columns, "None of the 12 published numbers below has a counterpart.");
	if (usable) {
		const char *d3 = mkMeta_Get(&s.m, "draw_3d"), *so3 = mkMeta_Get(&s.m, "so3_file");
		const char *timed = mkMeta_Get(&s.m, "timed_region");
		mkDoc_Para(d, "Rotation draw: in the 3D draws (%s); robot orientations from %s. Timed: %s. The paper "
			"ran MATLAB on one core of a Xeon at 2.8 GHz. Means over the trials of each level.",
			d3 ? d3 : "(draw not recorded)", so3 ? so3 : "(not recorded)", timed ? timed : "not recorded");
	}
	mkCObstacle_Table(d, &s.t, usable, tally);
	mkSection_End(&s);
}
