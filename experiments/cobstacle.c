/* cobstacle.c - configuration-space obstacles (paper Sec. 7.1, Table 2 and
 * Fig. 9).
 *
 * A robot and many obstacles are superellipses (2D) or superquadrics (3D).
 * For every robot orientation and every obstacle, the C-obstacle boundary is
 * the contact space  obstacle (+) (-robot)  (mink/sum.h, MK_SET_CONTACT with
 * B1 = the obstacle and B2 = the robot turned to that orientation): the
 * places of the robot's centre at which it touches the obstacle. It is
 * computed by one mkSum2_Batch / mkSum3_Batch call per obstacle and
 * orientation, at the obstacle's surface parameters, and the whole loop is
 * timed on one thread with CLOCK_MONOTONIC.
 *
 * Draws (paper Sec. 7.1, with the reference code's distributions):
 *  2D: robot a ~ U(0,5), b ~ U(0,3), eps ~ U(0,1); obstacles a, b ~ U(0,10),
 *      eps ~ U(0,2), centre ~ U(-200,200)^2, angle ~ U(0,pi); 50 points per
 *      boundary; 50 robot headings (k-1) pi / 50, k = 1..50.
 *  3D: robot a, b, c ~ U(0,5), eps1, eps2 ~ U(0,2); obstacles a, b, c ~
 *      U(0,10), eps1, eps2 ~ U(0,2), centre ~ U(-200,200)^3, rotation from
 *      the quaternion pi U(0,1)^4 normalised (the reference code's draw);
 *      a 10 x 10 surface grid (100 points, poles included); the robot's
 *      orientations are the rotations of a file (the 3600 of the
 *      double-coset quantisation of SO(3) by default).
 *  A U(0, x) draw can fall outside the core's valid ranges (semi-axes at
 *  least MK_AXIS_MIN, exponents in [MK_EPS_MIN, MK_EPS_MAX]); such values are
 *  clamped into range and counted in the row's `clamped` column.
 *
 * Random streams: each (dimension, obstacle count, trial) draws from its own
 * stream  (dim << 56) | (obstacles << 24) | trial  of the run's seed (robot
 * first, then the obstacles in order, each as listed above); the figure's
 * scene draws from  (1 << 62) | (2 << 56) | (obstacles << 24).
 *
 * Rows: one per dimension, obstacle count and trial, with the time, the time
 * per boundary point, the published figures of that level (empty for levels
 * the paper does not list) and a checksum of every computed coordinate, so
 * that a run can be told apart from one that skipped work.
 *
 * Fig. 9's geometry (the obstacles and 10 of the 50 C-slices of one 2D scene
 * of 500 obstacles) is written beside the result, in the directory named
 * like the result without ".csv". */
#define _POSIX_C_SOURCE 200809L

#include <mink/mink.h>
#include <mink_exp/exp.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MK_SCHEMA_VERSION 1
#define MK_MAX_LEVELS 16
#define MK_OBSTACLES_MAX 10000000L   /* fits the 32 bits of the stream map */
#define MK_TRIALS_MAX 1000000L       /* fits the 24 bits of the stream map */
#define MK_SO3_MAX 1000000L

/* ---- the published Table 2 (MATLAB, Xeon 2.8 GHz, one core) ------------- */

typedef struct mkPublished {
	int dim;
	long obstacles, points, orientations;
	double total_s, us_per_point;
} mkPublished;

static const mkPublished mkTable2[] = {
	{ 2, 50, 50, 50, 0.36, 2.860 },
	{ 2, 1000, 50, 50, 6.41, 2.563 },
	{ 2, 10000, 50, 50, 64.26, 2.570 },
	{ 3, 50, 100, 3600, 95.54, 5.308 },
	{ 3, 200, 100, 3600, 375.02, 5.209 },
	{ 3, 1000, 100, 3600, 1907.85, 5.299 },
};
#define MK_TABLE2_COUNT ((int)(sizeof mkTable2 / sizeof mkTable2[0]))

/* The published row of this level, or NULL when the paper lists none (the
 * level must match in obstacles, points and orientations). */
static const mkPublished *mkPublished_Find(int dim, long obstacles, long points, long orientations)
{
	for (int i = 0; i < MK_TABLE2_COUNT; ++i) {
		const mkPublished *p = &mkTable2[i];
		if (p->dim == dim && p->obstacles == obstacles && p->points == points
			&& p->orientations == orientations)
			return p;
	}
	return NULL;
}

/* ---- options ------------------------------------------------------------- */

typedef struct mkOptions {
	long trials;
	uint64_t seed;
	int dim2, dim3;
	long levels2[MK_MAX_LEVELS];
	int nlevels2;
	long levels3[MK_MAX_LEVELS];
	int nlevels3;
	long headings;     /* 2D robot headings */
	long points2;      /* 2D points per boundary */
	long grid3;        /* 3D grid side */
	const char *so3;   /* 3D orientations file */
	long orient3;      /* use the first orient3 rotations (0: all) */
	mkForm form;
	mkImpl impl;
	long fig_obstacles;  /* 0: no figure geometry */
	long fig_slices;
	const char *out;
	int out_given;
	mkShard shard;
	int force;
} mkOptions;

static const char *const mkDimNames[] = { "2", "3", "both" };
static const char *const mkFormNames[] = { "normal", "gradient" };

static void mkUsage(FILE *fp)
{
	fputs(
		"usage: cobstacle [options]\n"
		"Configuration-space obstacles (paper Sec. 7.1, Table 2 and Fig. 9): for every\n"
		"robot orientation and obstacle, the contact space obstacle (+) (-robot) by one\n"
		"closed-form batch call, timed on one thread. One CSV row per dimension,\n"
		"obstacle count and trial, plus a metadata sidecar <out>.meta, and the geometry\n"
		"of Fig. 9 in the directory <out without .csv>/.\n"
		"\n"
		"  --trials T          timed trials per obstacle count, 1..1000000 (default 3)\n"
		"  --seed S            run seed, 0..2^64-1, decimal or 0x.. (default 2022)\n"
		"  --dim 2|3|both      which experiments (default both)\n"
		"  --obstacles2 LIST   2D obstacle counts, comma-separated, each 1..10000000\n"
		"                      (default 50,1000,10000)\n"
		"  --obstacles3 LIST   3D obstacle counts (default 50,200,1000)\n"
		"  --headings H        2D robot headings k pi / H, k = 0..H-1, 1..100000 (default 50)\n"
		"  --points N          2D points per boundary, 3..100000 (default 50)\n"
		"  --grid G            3D G x G grid per boundary, 2..1000 (default 10)\n"
		"  --so3 PATH          3D robot orientations: CSV r11,...,r33 with a header, one\n"
		"                      rotation per line (default\n"
		"                      experiments/data/so3_double_coset_3600.csv)\n"
		"  --orientations K    use only the first K rotations of the file, 0 = all\n"
		"                      (default 0)\n"
		"  --form gradient|normal\n"
		"                      closed form (default gradient, as the paper)\n"
		"  --impl auto|scalar|avx2|avx512\n"
		"                      kernel (default auto)\n"
		"  --fig-obstacles N   obstacles of the Fig. 9 scene, 0..100000, 0 = no figure\n"
		"                      geometry (default 500)\n"
		"  --fig-slices L      C-slices drawn, every (H/L)-th heading, 1..H (default 10)\n"
		"  --out PATH          output CSV (default results/cobstacle.csv, or\n"
		"                      results/cobstacle.shard-I-of-N.csv with --shard)\n"
		"  --shard I/N         run only block I (0-based) of N of the (dimension, obstacle\n"
		"                      count, trial) units; only shard 0 writes the figure geometry\n"
		"  --force             replace an existing output file\n"
		"  --help              this text\n"
		"Progress goes to stderr when it is a terminal (MINK_PROGRESS=always|never).\n",
		fp);
}

static const mkOption mkOptionTable[] = {
	{ "--trials", 1 }, { "--seed", 1 }, { "--dim", 1 }, { "--obstacles2", 1 }, { "--obstacles3", 1 },
	{ "--headings", 1 }, { "--points", 1 }, { "--grid", 1 }, { "--so3", 1 }, { "--orientations", 1 },
	{ "--form", 1 }, { "--impl", 1 }, { "--fig-obstacles", 1 }, { "--fig-slices", 1 }, { "--out", 1 },
	{ "--shard", 1 }, { "--force", 0 },
};

/* A comma-separated list of counts into levels[]; 0 or -1 with a message. */
static int mkParseLevels(const char *flag, const char *text, long *levels, int *count,
	char *msg, size_t msglen)
{
	*count = 0;
	const char *p = text;
	for (;;) {
		const char *comma = strchr(p, ',');
		size_t len = comma ? (size_t)(comma - p) : strlen(p);
		char item[32];
		if (len == 0 || len >= sizeof item || *count >= MK_MAX_LEVELS) {
			snprintf(msg, msglen, "%s: expected up to %d comma-separated integers in [1, %ld], got '%s'",
				flag, MK_MAX_LEVELS, MK_OBSTACLES_MAX, text);
			return -1;
		}
		memcpy(item, p, len);
		item[len] = '\0';
		long v;
		if (mkArg_Long(flag, item, 1, MK_OBSTACLES_MAX, &v, msg, msglen) != 0) {
			snprintf(msg, msglen, "%s: expected up to %d comma-separated integers in [1, %ld], got '%s'",
				flag, MK_MAX_LEVELS, MK_OBSTACLES_MAX, text);
			return -1;
		}
		levels[(*count)++] = v;
		if (!comma)
			return 0;
		p = comma + 1;
	}
}

/* Parse argv into o. Returns 0 to run, 1 when --help was printed, 2 on a
 * usage error (message printed). */
static int mkParseOptions(int argc, char **argv, mkOptions *o, char *outbuf, size_t outlen)
{
	memset(o, 0, sizeof *o);
	o->trials = 3;
	o->seed = 2022;
	o->dim2 = o->dim3 = 1;
	o->levels2[0] = 50;
	o->levels2[1] = 1000;
	o->levels2[2] = 10000;
	o->nlevels2 = 3;
	o->levels3[0] = 50;
	o->levels3[1] = 200;
	o->levels3[2] = 1000;
	o->nlevels3 = 3;
	o->headings = 50;
	o->points2 = 50;
	o->grid3 = 10;
	o->so3 = "experiments/data/so3_double_coset_3600.csv";
	o->orient3 = 0;
	o->form = MK_FORM_GRADIENT;
	o->impl = MK_IMPL_AUTO;
	o->fig_obstacles = 500;
	o->fig_slices = 10;
	o->out = "results/cobstacle.csv";
	o->shard = mkShard_All();

	char msg[512] = "";
	mkArgs args;
	mkArgs_Begin(&args, argc, argv);
	const char *name, *value;
	int choice = 0, bad = 0;
	mkArgsStep step;
	while (!bad && (step = mkArgs_Step(&args, mkOptionTable, MK_COUNT(mkOptionTable), &name, &value,
			msg, sizeof msg)) != MK_ARGS_END) {
		if (step == MK_ARGS_HELP) {
			mkUsage(stdout);
			return 1;
		}
		if (step == MK_ARGS_ERROR) {
			bad = 1;
		} else if (strcmp(name, "--force") == 0) {
			o->force = 1;
		} else if (strcmp(name, "--trials") == 0) {
			bad = mkArg_Long(name, value, 1, MK_TRIALS_MAX, &o->trials, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--seed") == 0) {
			bad = mkArg_U64(name, value, &o->seed, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--dim") == 0) {
			bad = mkArg_Choice(name, value, mkDimNames, 3, &choice, msg, sizeof msg) != 0;
			o->dim2 = choice != 1;
			o->dim3 = choice != 0;
		} else if (strcmp(name, "--obstacles2") == 0) {
			bad = mkParseLevels(name, value, o->levels2, &o->nlevels2, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--obstacles3") == 0) {
			bad = mkParseLevels(name, value, o->levels3, &o->nlevels3, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--headings") == 0) {
			bad = mkArg_Long(name, value, 1, 100000, &o->headings, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--points") == 0) {
			bad = mkArg_Long(name, value, 3, 100000, &o->points2, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--grid") == 0) {
			bad = mkArg_Long(name, value, 2, 1000, &o->grid3, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--so3") == 0) {
			bad = mkArg_Path(name, value, &o->so3, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--orientations") == 0) {
			bad = mkArg_Long(name, value, 0, MK_SO3_MAX, &o->orient3, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--form") == 0) {
			bad = mkArg_Choice(name, value, mkFormNames, 2, &choice, msg, sizeof msg) != 0;
			o->form = choice == 0 ? MK_FORM_NORMAL : MK_FORM_GRADIENT;
		} else if (strcmp(name, "--impl") == 0) {
			bad = mkArg_Impl(name, value, &choice, msg, sizeof msg) != 0;
			if (!bad)
				o->impl = (mkImpl)choice;
		} else if (strcmp(name, "--fig-obstacles") == 0) {
			bad = mkArg_Long(name, value, 0, 100000, &o->fig_obstacles, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--fig-slices") == 0) {
			bad = mkArg_Long(name, value, 1, 100000, &o->fig_slices, msg, sizeof msg) != 0;
		} else if (strcmp(name, "--out") == 0) {
			bad = mkArg_Path(name, value, &o->out, msg, sizeof msg) != 0;
			o->out_given = 1;
		} else if (strcmp(name, "--shard") == 0) {
			bad = mkShard_Parse(value, name, &o->shard, msg, sizeof msg) != 0;
		}
	}
	if (!bad && o->fig_obstacles > 0 && o->fig_slices > o->headings) {
		snprintf(msg, sizeof msg, "--fig-slices: expected an integer in [1, %ld] (the headings), got '%ld'",
			o->headings, o->fig_slices);
		bad = 1;
	}
	if (bad) {
		fprintf(stderr, "cobstacle: %s\n", msg);
		return 2;
	}
	if (!o->out_given && o->shard.count > 1) {
		snprintf(outbuf, outlen, "results/cobstacle.shard-%d-of-%d.csv", o->shard.index, o->shard.count);
		o->out = outbuf;
	}
	return 0;
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

static double mkDrawAxis(mkRng *r, double hi, long *clamped)
{
	return mkClamp(mkRng_Uniform(r, 0.0, hi), MK_AXIS_MIN, MK_AXIS_MAX, clamped);
}

static double mkDrawEps(mkRng *r, double hi, long *clamped)
{
	return mkClamp(mkRng_Uniform(r, 0.0, hi), MK_EPS_MIN, MK_EPS_MAX, clamped);
}

static mkShape2 mkDrawRobot2(mkRng *r, long *clamped)
{
	mkShape2 s;
	s.a = mkDrawAxis(r, 5.0, clamped);
	s.b = mkDrawAxis(r, 3.0, clamped);
	s.eps = mkDrawEps(r, 1.0, clamped);
	return s;
}

/* *angle (may be NULL) receives the obstacle's rotation angle. */
static mkBody2 mkDrawObstacle2(mkRng *r, long *clamped, double *angle)
{
	mkShape2 s;
	s.a = mkDrawAxis(r, 10.0, clamped);
	s.b = mkDrawAxis(r, 10.0, clamped);
	s.eps = mkDrawEps(r, 2.0, clamped);
	mkVec2 t;
	t.x = mkRng_Uniform(r, -200.0, 200.0);
	t.y = mkRng_Uniform(r, -200.0, 200.0);
	double phi = mkRng_Uniform(r, 0.0, MK_PI);
	if (angle)
		*angle = phi;
	return mkBody2_Make(s, mkMat2_Rotation(phi), t);
}

static mkShape3 mkDrawRobot3(mkRng *r, long *clamped)
{
	mkShape3 s;
	s.a = mkDrawAxis(r, 5.0, clamped);
	s.b = mkDrawAxis(r, 5.0, clamped);
	s.c = mkDrawAxis(r, 5.0, clamped);
	s.eps1 = mkDrawEps(r, 2.0, clamped);
	s.eps2 = mkDrawEps(r, 2.0, clamped);
	return s;
}

/* Returns 0 when the quaternion draw is degenerate (all four U(0,1) draws
 * zero: probability 2^-212), which the caller reports. */
static int mkDrawObstacle3(mkRng *r, long *clamped, mkBody3 *out)
{
	mkShape3 s;
	s.a = mkDrawAxis(r, 10.0, clamped);
	s.b = mkDrawAxis(r, 10.0, clamped);
	s.c = mkDrawAxis(r, 10.0, clamped);
	s.eps1 = mkDrawEps(r, 2.0, clamped);
	s.eps2 = mkDrawEps(r, 2.0, clamped);
	mkVec3 t;
	t.x = mkRng_Uniform(r, -200.0, 200.0);
	t.y = mkRng_Uniform(r, -200.0, 200.0);
	t.z = mkRng_Uniform(r, -200.0, 200.0);
	double q[4];
	for (int i = 0; i < 4; ++i)
		q[i] = MK_PI * mkRng_Unit(r);
	int ok = 0;
	mkMat3 R = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
	ok = mkMat3_IsFinite(R);
	*out = mkBody3_Make(s, R, t);
	return ok;
}

static uint64_t mkStream(int figure, int dim, long obstacles, long trial)
{
	return ((uint64_t)(figure != 0) << 62) | ((uint64_t)dim << 56)
		| ((uint64_t)obstacles << 24) | (uint64_t)trial;
}

/* ---- the orientations of the 3D robot ------------------------------------ */

typedef struct mkRotations {
	long count;
	mkMat3 *R;
	double max_error;   /* largest |R^T R - I| entry or |det R - 1| */
} mkRotations;

/* Read up to `limit` rotations (0: all). Each line after the header holds
 * the nine entries of one rotation matrix, row-major. The entries are
 * checked to form a rotation: the file stores doubles rounded to 17
 * significant digits from a double-precision computation, so R^T R = I and
 * det R = 1 hold to a few units of 1e-16; a deviation above 1e-9 means the
 * file is not a list of rotations and is an error. Returns 0, or -1 with a
 * message. */
static int mkRotations_Read(mkRotations *rot, const char *path, long limit, char *msg, size_t msglen)
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
		double v[9];
		char *p = line, *end = NULL;
		int k = 0;
		for (; k < 9; ++k) {
			errno = 0;
			v[k] = strtod(p, &end);
			if (end == p || errno != 0 || !isfinite(v[k]))
				break;
			p = end;
			while (*p == ' ' || *p == '\t')
				++p;
			if (k < 8) {
				if (*p != ',')
					break;
				++p;
			}
		}
		while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')
			++p;
		if (k < 9 || *p != '\0') {
			snprintf(msg, msglen, "--so3: %s:%ld: expected nine comma-separated numbers", path, lineno);
			failed = 1;
			break;
		}
		mkMat3 R;
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				R.m[i][j] = v[3 * i + j];
		mkMat3 RtR = mkMat3_Mul(mkMat3_Transpose(R), R);
		double err = fabs(mkMat3_Det(R) - 1.0);
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				err = fmax(err, fabs(RtR.m[i][j] - (i == j ? 1.0 : 0.0)));
		if (!(err <= 1e-9)) {
			snprintf(msg, msglen, "--so3: %s:%ld: not a rotation matrix (|R^T R - I| or |det R - 1| is %.3g)",
				path, lineno, err);
			failed = 1;
			break;
		}
		rot->max_error = fmax(rot->max_error, err);
		if (rot->count == cap) {
			long ncap = cap ? 2 * cap : 1024;
			mkMat3 *nr = realloc(rot->R, (size_t)ncap * sizeof *nr);
			if (!nr) {
				snprintf(msg, msglen, "--so3: out of memory reading '%s'", path);
				failed = 1;
				break;
			}
			rot->R = nr;
			cap = ncap;
		}
		rot->R[rot->count++] = R;
		if (rot->count > MK_SO3_MAX) {
			snprintf(msg, msglen, "--so3: %s: more than %ld rotations", path, MK_SO3_MAX);
			failed = 1;
		}
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
		free(rot->R);
		rot->R = NULL;
		rot->count = 0;
		return -1;
	}
	return 0;
}

/* ---- timing -------------------------------------------------------------- */

static double mkNow(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* CPU time of this thread: beside the wall time, it shows whether other
 * processes on a shared machine took the CPU away during a measurement
 * (then wall > CPU). */
static double mkCpuNow(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The system's load averages (Linux /proc/loadavg: 1, 5, 15 minutes), or
 * "unknown", for the sidecar. */
static void mkLoadAverage(char *buf, size_t len)
{
	FILE *fp = fopen("/proc/loadavg", "r");
	double a = 0, b = 0, c = 0;
	if (fp && fscanf(fp, "%lf %lf %lf", &a, &b, &c) == 3)
		snprintf(buf, len, "%.2f %.2f %.2f", a, b, c);
	else
		snprintf(buf, len, "unknown");
	if (fp)
		fclose(fp);
}

/* The parameter samples and one C-slice's output (every obstacle's points
 * for one orientation; kept, like the reference code keeps each slice). */
typedef struct mkWork {
	long n;                       /* points per boundary */
	double *ux, *uy, *uz;         /* parameters */
	double *x, *y, *z;            /* obstacles * n outputs */
	long capacity;
} mkWork;

static int mkWork_Reserve(mkWork *w, long count)
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

static void mkWork_Free(mkWork *w)
{
	free(w->ux);
	free(w->uy);
	free(w->uz);
	free(w->x);
	free(w->y);
	free(w->z);
	memset(w, 0, sizeof *w);
}

typedef struct mkLevelResult {
	double total_s;
	double cpu_s;
	long nonfinite;
	long clamped;
	double checksum;
	double robot[5];   /* a, b, c, eps1, eps2 (c and eps2 NaN in 2D) */
} mkLevelResult;

/* Sum and count of the non-finite values of one slice, outside the timing. */
static void mkSlice_Digest(const mkWork *w, long count, int dim, mkLevelResult *res)
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

static int mkRunLevel2(const mkOptions *o, long nobs, long trial, mkWork *w, mkProgress *prog,
	mkLevelResult *res)
{
	memset(res, 0, sizeof *res);
	mkRng rng;
	mkRng_Seed(&rng, o->seed, mkStream(0, 2, nobs, trial));
	mkShape2 robot = mkDrawRobot2(&rng, &res->clamped);
	res->robot[0] = robot.a;
	res->robot[1] = robot.b;
	res->robot[2] = NAN;
	res->robot[3] = robot.eps;
	res->robot[4] = NAN;
	mkBody2 *obs = malloc((size_t)nobs * sizeof *obs);
	if (!obs || mkWork_Reserve(w, nobs * w->n) != 0) {
		free(obs);
		fprintf(stderr, "cobstacle: out of memory for %ld obstacles\n", nobs);
		return -1;
	}
	char msg[256];
	for (long j = 0; j < nobs; ++j) {
		obs[j] = mkDrawObstacle2(&rng, &res->clamped, NULL);
		if (!mkBody2_IsValid(obs[j], "obstacle", msg, sizeof msg)) {
			fprintf(stderr, "cobstacle: 2D trial %ld, obstacle %ld: %s\n", trial, j, msg);
			free(obs);
			return -1;
		}
	}
	mkVec2 origin = { 0.0, 0.0 };
	if (!mkBody2_IsValid(mkBody2_Make(robot, mkMat2_Identity(), origin), "robot", msg, sizeof msg)) {
		fprintf(stderr, "cobstacle: 2D trial %ld: %s\n", trial, msg);
		free(obs);
		return -1;
	}
	mkSumOptions opt = mkSumOptions_Default();
	opt.set = MK_SET_CONTACT;
	opt.form = o->form;
	opt.param = MK_PARAM_SURFACE;
	opt.impl = o->impl;
	int n = (int)w->n;
	for (long h = 0; h < o->headings; ++h) {
		double t0 = mkNow(), c0 = mkCpuNow();
		mkBody2 rb = mkBody2_Make(robot, mkMat2_Rotation((double)h * MK_PI / (double)o->headings), origin);
		mkResult rc = MK_OK;
		for (long j = 0; j < nobs && rc == MK_OK; ++j)
			rc = mkSum2_Batch(obs[j], rb, &opt, w->ux, w->uy, n,
				w->x + j * n, w->y + j * n, NULL, NULL);
		res->cpu_s += mkCpuNow() - c0;
		res->total_s += mkNow() - t0;
		if (rc != MK_OK) {
			fprintf(stderr, "cobstacle: 2D trial %ld: the closed form failed: %s\n", trial, mkResult_Name(rc));
			free(obs);
			return -1;
		}
		mkSlice_Digest(w, nobs * n, 2, res);
		mkProgress_Add(prog, 1);
	}
	free(obs);
	return 0;
}

static int mkRunLevel3(const mkOptions *o, long nobs, long trial, const mkRotations *rot, mkWork *w,
	mkProgress *prog, mkLevelResult *res)
{
	memset(res, 0, sizeof *res);
	mkRng rng;
	mkRng_Seed(&rng, o->seed, mkStream(0, 3, nobs, trial));
	mkShape3 robot = mkDrawRobot3(&rng, &res->clamped);
	res->robot[0] = robot.a;
	res->robot[1] = robot.b;
	res->robot[2] = robot.c;
	res->robot[3] = robot.eps1;
	res->robot[4] = robot.eps2;
	mkBody3 *obs = malloc((size_t)nobs * sizeof *obs);
	if (!obs || mkWork_Reserve(w, nobs * w->n) != 0) {
		free(obs);
		fprintf(stderr, "cobstacle: out of memory for %ld obstacles\n", nobs);
		return -1;
	}
	char msg[256];
	for (long j = 0; j < nobs; ++j) {
		int ok = mkDrawObstacle3(&rng, &res->clamped, &obs[j]);
		if (!ok || !mkBody3_IsValid(obs[j], "obstacle", msg, sizeof msg)) {
			if (!ok)
				snprintf(msg, sizeof msg, "a zero quaternion was drawn");
			fprintf(stderr, "cobstacle: 3D trial %ld, obstacle %ld: %s\n", trial, j, msg);
			free(obs);
			return -1;
		}
	}
	mkVec3 origin = { 0.0, 0.0, 0.0 };
	if (!mkBody3_IsValid(mkBody3_Make(robot, mkMat3_Identity(), origin), "robot", msg, sizeof msg)) {
		fprintf(stderr, "cobstacle: 3D trial %ld: %s\n", trial, msg);
		free(obs);
		return -1;
	}
	mkSumOptions opt = mkSumOptions_Default();
	opt.set = MK_SET_CONTACT;
	opt.form = o->form;
	opt.param = MK_PARAM_SURFACE;
	opt.impl = o->impl;
	int n = (int)w->n;
	for (long k = 0; k < rot->count; ++k) {
		double t0 = mkNow(), c0 = mkCpuNow();
		mkBody3 rb = mkBody3_Make(robot, rot->R[k], origin);
		mkResult rc = MK_OK;
		for (long j = 0; j < nobs && rc == MK_OK; ++j)
			rc = mkSum3_Batch(obs[j], rb, &opt, w->ux, w->uy, w->uz, n,
				w->x + j * n, w->y + j * n, w->z + j * n, NULL, NULL, NULL);
		res->cpu_s += mkCpuNow() - c0;
		res->total_s += mkNow() - t0;
		if (rc != MK_OK) {
			fprintf(stderr, "cobstacle: 3D trial %ld: the closed form failed: %s\n", trial, mkResult_Name(rc));
			free(obs);
			return -1;
		}
		mkSlice_Digest(w, nobs * n, 3, res);
		mkProgress_Add(prog, 1);
	}
	free(obs);
	return 0;
}

/* ---- rows ---------------------------------------------------------------- */

static const char *const mkColumns[] = {
	"dim", "obstacles", "points", "orientations", "total_points", "total_s", "us_per_point",
	"cpu_s", "trial", "form", "impl", "published_total_s", "published_us_per_point",
	"nonfinite", "clamped", "checksum",
	"robot_a", "robot_b", "robot_c", "robot_eps1", "robot_eps2"
};
#define MK_COLUMN_COUNT ((int)(sizeof mkColumns / sizeof mkColumns[0]))

static void mkWriteRow(mkCsv *csv, int dim, long nobs, long points, long orientations, long trial,
	mkForm form, mkImpl impl, const mkLevelResult *res)
{
	long long total = (long long)nobs * points * orientations;
	const mkPublished *pub = mkPublished_Find(dim, nobs, points, orientations);
	mkCsv_Int(csv, dim);
	mkCsv_Int(csv, nobs);
	mkCsv_Int(csv, points);
	mkCsv_Int(csv, orientations);
	mkCsv_Int(csv, total);
	mkCsv_Double(csv, res->total_s);
	mkCsv_Double(csv, res->total_s * 1e6 / (double)total);
	mkCsv_Double(csv, res->cpu_s);
	mkCsv_Int(csv, trial);
	mkCsv_Str(csv, mkForm_Name(form));
	mkCsv_Str(csv, mkImpl_Name(impl));
	if (pub) {
		mkCsv_Double(csv, pub->total_s);
		mkCsv_Double(csv, pub->us_per_point);
	} else {
		mkCsv_Empty(csv);
		mkCsv_Empty(csv);
	}
	mkCsv_Int(csv, res->nonfinite);
	mkCsv_Int(csv, res->clamped);
	mkCsv_Double(csv, res->checksum);
	for (int i = 0; i < 5; ++i) {
		if (isnan(res->robot[i]))
			mkCsv_Empty(csv);
		else
			mkCsv_Double(csv, res->robot[i]);
	}
	mkCsv_EndRow(csv);
}

/* ---- Fig. 9: one 2D scene, its obstacles and some C-slices ---------------- */

/* "<out without .csv>/<name>" into buf. */
static void mkSiblingPath(const char *out, const char *name, char *buf, size_t len)
{
	size_t n = strlen(out);
	int cut = n > 4 && strcmp(out + n - 4, ".csv") == 0;
	snprintf(buf, len, "%.*s/%s", (int)(cut ? n - 4 : n), out, name);
}

/* Open <out without .csv>/<name> as CSV; 0 or -1 after printing why. */
static int mkFigure_Open(const mkOptions *o, const char *name, const char *const *cols, int ncols, mkCsv *csv)
{
	char msg[1024], path[MK_PATH_MAX];
	mkSiblingPath(o->out, name, path, sizeof path);
	if (mkPath_MakeParents(path, msg, sizeof msg) != 0 || mkCsv_Open(csv, path, cols, ncols, msg, sizeof msg) != 0) {
		fprintf(stderr, "cobstacle: %s\n", msg);
		return -1;
	}
	return 0;
}

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

/* The scene of Fig. 9: a robot and o->fig_obstacles obstacles drawn as in
 * the 2D experiment, from their own stream. Four files, each with its
 * sidecar:
 *   fig9-scene.csv      one row per body (the robot first): its parameters
 *   fig9-obstacles.csv  each obstacle's outline in the workspace
 *   fig9-robot.csv      the robot's outline at each drawn heading
 *   fig9-slices.csv     every obstacle's C-obstacle at each drawn heading
 * Outlines are closed (k = n repeats the point k = 0) and end in two blank
 * lines, gnuplot's separator of data blocks, so that neither plot nor splot
 * joins one curve to the next. */
static int mkFigure9(const mkOptions *o, mkMeta *meta, const mkWork *w)
{
	char msg[1024];
	long nobs = o->fig_obstacles;
	int n = (int)w->n;
	long clamped = 0;
	mkRng rng;
	mkRng_Seed(&rng, o->seed, mkStream(1, 2, nobs, 0));
	mkShape2 robot = mkDrawRobot2(&rng, &clamped);
	mkBody2 *obs = malloc((size_t)nobs * sizeof *obs);
	double *angle = malloc((size_t)nobs * sizeof *angle);
	double *x = malloc((size_t)n * sizeof *x), *y = malloc((size_t)n * sizeof *y);
	int failed = !obs || !angle || !x || !y;
	if (failed)
		fprintf(stderr, "cobstacle: out of memory for the figure\n");
	for (long j = 0; j < nobs && !failed; ++j) {
		obs[j] = mkDrawObstacle2(&rng, &clamped, &angle[j]);
		if (!mkBody2_IsValid(obs[j], "obstacle", msg, sizeof msg)) {
			fprintf(stderr, "cobstacle: figure, obstacle %ld: %s\n", j, msg);
			failed = 1;
		}
	}
	mkMeta_SetInt(meta, "fig9_obstacles", nobs);
	mkMeta_SetInt(meta, "fig9_slices", o->fig_slices);
	mkMeta_SetInt(meta, "fig9_clamped", clamped);
	mkMeta_Set(meta, "fig9_slices_drawn", "headings k pi / H for k = floor(i H / L), i = 0..L-1");
	mkSumOptions opt = mkSumOptions_Default();
	opt.set = MK_SET_CONTACT;
	opt.form = o->form;
	opt.param = MK_PARAM_SURFACE;
	opt.impl = o->impl;
	mkVec2 origin = { 0.0, 0.0 };

	static const char *const ccols[] = { "body", "index", "a", "b", "eps", "cx", "cy", "angle" };
	mkCsv csv;
	if (!failed && mkFigure_Open(o, "fig9-scene.csv", ccols, 8, &csv) == 0) {
		for (long j = -1; j < nobs; ++j) {
			mkShape2 s = j < 0 ? robot : obs[j].shape;
			mkCsv_Str(&csv, j < 0 ? "robot" : "obstacle");
			mkCsv_Int(&csv, j < 0 ? 0 : j);
			mkCsv_Double(&csv, s.a);
			mkCsv_Double(&csv, s.b);
			mkCsv_Double(&csv, s.eps);
			mkCsv_Double(&csv, j < 0 ? 0.0 : obs[j].t.x);
			mkCsv_Double(&csv, j < 0 ? 0.0 : obs[j].t.y);
			mkCsv_Double(&csv, j < 0 ? 0.0 : angle[j]);
			mkCsv_EndRow(&csv);
		}
		failed = mkFigure_Commit(&csv, meta, "fig. 9 scene: the robot (unturned, at the origin) and the obstacles") != 0;
	} else {
		failed = 1;
	}

	static const char *const ocols[] = { "obstacle", "k", "x", "y" };
	if (!failed && mkFigure_Open(o, "fig9-obstacles.csv", ocols, 4, &csv) == 0) {
		for (long j = 0; j < nobs; ++j) {
			for (int k = 0; k <= n; ++k) {
				mkVec2 u = { w->ux[k % n], w->uy[k % n] };
				mkVec2 p = mkBody2_Point(obs[j], u);
				mkCsv_Int(&csv, j);
				mkCsv_Int(&csv, k);
				mkCsv_Double(&csv, p.x);
				mkCsv_Double(&csv, p.y);
				mkCsv_EndRow(&csv);
			}
			fputs("\n\n", csv.file.fp);
		}
		failed = mkFigure_Commit(&csv, meta, "fig. 9 obstacles in the workspace, closed outlines") != 0;
	} else {
		failed = 1;
	}

	static const char *const rcols[] = { "slice", "heading_index", "heading", "k", "x", "y" };
	if (!failed && mkFigure_Open(o, "fig9-robot.csv", rcols, 6, &csv) == 0) {
		for (long i = 0; i < o->fig_slices; ++i) {
			long h = i * o->headings / o->fig_slices;
			double heading = (double)h * MK_PI / (double)o->headings;
			mkBody2 rb = mkBody2_Make(robot, mkMat2_Rotation(heading), origin);
			for (int k = 0; k <= n; ++k) {
				mkVec2 u = { w->ux[k % n], w->uy[k % n] };
				mkVec2 p = mkBody2_Point(rb, u);
				mkCsv_Int(&csv, i);
				mkCsv_Int(&csv, h);
				mkCsv_Double(&csv, heading);
				mkCsv_Int(&csv, k);
				mkCsv_Double(&csv, p.x);
				mkCsv_Double(&csv, p.y);
				mkCsv_EndRow(&csv);
			}
			fputs("\n\n", csv.file.fp);
		}
		failed = mkFigure_Commit(&csv, meta, "fig. 9 robot at the drawn headings, centred at the origin") != 0;
	} else {
		failed = 1;
	}

	static const char *const scols[] = { "slice", "heading_index", "heading", "obstacle", "k", "x", "y" };
	if (!failed && mkFigure_Open(o, "fig9-slices.csv", scols, 7, &csv) == 0) {
		for (long i = 0; i < o->fig_slices && !failed; ++i) {
			long h = i * o->headings / o->fig_slices;
			double heading = (double)h * MK_PI / (double)o->headings;
			mkBody2 rb = mkBody2_Make(robot, mkMat2_Rotation(heading), origin);
			for (long j = 0; j < nobs && !failed; ++j) {
				mkResult rc = mkSum2_Batch(obs[j], rb, &opt, w->ux, w->uy, n, x, y, NULL, NULL);
				if (rc != MK_OK) {
					fprintf(stderr, "cobstacle: figure: the closed form failed: %s\n", mkResult_Name(rc));
					failed = 1;
					break;
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
				fputs("\n\n", csv.file.fp);
			}
		}
		if (failed)
			mkCsv_Discard(&csv);
		else
			failed = mkFigure_Commit(&csv, meta, "fig. 9 C-obstacles obstacle (+) (-robot) at the drawn headings") != 0;
	} else {
		failed = 1;
	}
	free(obs);
	free(angle);
	free(x);
	free(y);
	return failed ? -1 : 0;
}

/* ---- main ---------------------------------------------------------------- */

typedef struct mkUnit { int dim; long obstacles; long trial; } mkUnit;

int main(int argc, char **argv)
{
	mkOptions o;
	char outbuf[128];
	int parsed = mkParseOptions(argc, argv, &o, outbuf, sizeof outbuf);
	if (parsed == 1)
		return 0;
	if (parsed != 0)
		return 2;

	if (mkPath_PrepareOutput("cobstacle", o.out, o.force) != 0)
		return 1;
	char msg[1024];

	/* The run's units: dimension, obstacle count, trial, in row order. */
	long nunits = o.trials * ((o.dim2 ? o.nlevels2 : 0) + (o.dim3 ? o.nlevels3 : 0));
	mkUnit *units = malloc((size_t)nunits * sizeof *units);
	if (!units) {
		fprintf(stderr, "cobstacle: out of memory\n");
		return 1;
	}
	long u = 0;
	for (int d = 2; d <= 3; ++d) {
		if ((d == 2 && !o.dim2) || (d == 3 && !o.dim3))
			continue;
		int nl = d == 2 ? o.nlevels2 : o.nlevels3;
		for (int l = 0; l < nl; ++l)
			for (long t = 0; t < o.trials; ++t) {
				units[u].dim = d;
				units[u].obstacles = d == 2 ? o.levels2[l] : o.levels3[l];
				units[u].trial = t;
				++u;
			}
	}
	long begin, end;
	mkShard_Range(o.shard, nunits, &begin, &end);
	int need3 = 0;
	for (long i = begin; i < end; ++i)
		need3 = need3 || units[i].dim == 3;

	mkRotations rot;
	memset(&rot, 0, sizeof rot);
	if (need3 && mkRotations_Read(&rot, o.so3, o.orient3, msg, sizeof msg) != 0) {
		fprintf(stderr, "cobstacle: %s\n", msg);
		free(units);
		return 1;
	}

	mkWork w2, w3;
	memset(&w2, 0, sizeof w2);
	memset(&w3, 0, sizeof w3);
	w2.n = o.points2;
	w3.n = o.grid3 * o.grid3;
	w2.ux = malloc((size_t)w2.n * sizeof(double));
	w2.uy = malloc((size_t)w2.n * sizeof(double));
	w3.ux = malloc((size_t)w3.n * sizeof(double));
	w3.uy = malloc((size_t)w3.n * sizeof(double));
	w3.uz = malloc((size_t)w3.n * sizeof(double));
	int failed = !w2.ux || !w2.uy || !w3.ux || !w3.uy || !w3.uz;
	if (!failed)
		failed = mkSample2_Angles((int)w2.n, w2.ux, w2.uy) != MK_OK
			|| mkSample3_Grid((int)o.grid3, w3.ux, w3.uy, w3.uz) != MK_OK;
	if (failed) {
		fprintf(stderr, "cobstacle: out of memory or bad sampling\n");
		mkWork_Free(&w2);
		mkWork_Free(&w3);
		free(rot.R);
		free(units);
		return 1;
	}

	mkMeta meta;
	mkMeta_Init(&meta, "cobstacle", MK_SCHEMA_VERSION, argc, argv);
	char text[512];
	mkMeta_SetU64(&meta, "seed", o.seed);
	mkMeta_SetInt(&meta, "trials", o.trials);
	snprintf(text, sizeof text, "%d/%d", o.shard.index, o.shard.count);
	mkMeta_Set(&meta, "shard", text);
	snprintf(text, sizeof text, "%ld..%ld of %ld", begin, end - 1, nunits);
	mkMeta_Set(&meta, "unit_range", end > begin ? text : "none");
	mkMeta_Set(&meta, "units", "(dim, obstacles, trial), dim 2 first, obstacle counts as listed, trials inner");
	mkMeta_Set(&meta, "dims", o.dim2 && o.dim3 ? "2,3" : o.dim2 ? "2" : "3");
	text[0] = '\0';
	for (int l = 0; l < o.nlevels2; ++l)
		snprintf(text + strlen(text), sizeof text - strlen(text), "%s%ld", l ? "," : "", o.levels2[l]);
	mkMeta_Set(&meta, "obstacles_2d", text);
	text[0] = '\0';
	for (int l = 0; l < o.nlevels3; ++l)
		snprintf(text + strlen(text), sizeof text - strlen(text), "%s%ld", l ? "," : "", o.levels3[l]);
	mkMeta_Set(&meta, "obstacles_3d", text);
	mkMeta_SetInt(&meta, "headings_2d", o.headings);
	mkMeta_Set(&meta, "headings_2d_angles", "k pi / H, k = 0..H-1 (the reference code's (k-1) pi / 50, k = 1..50)");
	mkMeta_SetInt(&meta, "points_2d", o.points2);
	mkMeta_SetInt(&meta, "grid_3d", o.grid3);
	mkMeta_Set(&meta, "so3_file", need3 ? o.so3 : "not read");
	mkMeta_SetInt(&meta, "orientations_3d", need3 ? rot.count : 0);
	if (need3)
		mkMeta_SetDouble(&meta, "so3_max_rotation_error", rot.max_error);
	mkMeta_Set(&meta, "set", mkSet_Name(MK_SET_CONTACT));
	mkMeta_Set(&meta, "bodies", "B1 = obstacle (its surface parameters), B2 = robot at the orientation, centred at the origin");
	mkMeta_Set(&meta, "param", mkParam_Name(MK_PARAM_SURFACE));
	mkMeta_Set(&meta, "form", mkForm_Name(o.form));
	mkMeta_Set(&meta, "impl_requested", mkImpl_Name(o.impl));
	mkMeta_Set(&meta, "impl", mkImpl_Name(mkImpl_Resolve(o.impl)));
	mkMeta_Set(&meta, "timer", "CLOCK_MONOTONIC (total_s), CLOCK_THREAD_CPUTIME_ID (cpu_s), one thread");
	mkLoadAverage(text, sizeof text);
	mkMeta_Set(&meta, "loadavg_start", text);
	mkMeta_Set(&meta, "timed_region",
		"per orientation: turning the robot and one batch call per obstacle; "
		"excludes the draws, the checksum and the output");
	mkMeta_Set(&meta, "rng", "xoshiro256** seeded by splitmix64; stream (dim << 56) | (obstacles << 24) | trial; "
		"figure scene (1 << 62) | (2 << 56) | (obstacles << 24)");
	mkMeta_Set(&meta, "draw_2d", "robot a~U(0,5) b~U(0,3) eps~U(0,1); obstacles a,b~U(0,10) eps~U(0,2) "
		"centre~U(-200,200)^2 angle~U(0,pi)");
	mkMeta_Set(&meta, "draw_3d", "robot a,b,c~U(0,5) eps1,eps2~U(0,2) unrotated; obstacles a,b,c~U(0,10) "
		"eps1,eps2~U(0,2) centre~U(-200,200)^3 rotation quat pi*U(0,1)^4 normalised");
	snprintf(text, sizeof text, "semi-axes into [%g, %g], exponents into [%g, %.7g]; counted per row in 'clamped'",
		MK_AXIS_MIN, MK_AXIS_MAX, MK_EPS_MIN, MK_EPS_MAX);
	mkMeta_Set(&meta, "clamping", text);
	mkMeta_Set(&meta, "published", "paper Table 2 (MATLAB, Xeon 2.8 GHz, one core), in published_total_s / published_us_per_point");

	/* Figure geometry first (shard 0 only), so that the main result,
	 * committed last, is never newer than a half-written figure. */
	if (o.fig_obstacles > 0 && o.shard.index == 0) {
		failed = mkFigure9(&o, &meta, &w2) != 0;
		mkMeta_Set(&meta, "content", "C-obstacle timings, one row per (dim, obstacles, trial)");
	} else {
		mkMeta_Set(&meta, "content", "C-obstacle timings, one row per (dim, obstacles, trial)");
		mkMeta_SetInt(&meta, "fig9_obstacles", 0);
	}

	mkCsv csv;
	int open = 0;
	if (!failed) {
		open = mkCsv_Open(&csv, o.out, mkColumns, MK_COLUMN_COUNT, msg, sizeof msg) == 0;
		if (!open) {
			fprintf(stderr, "cobstacle: %s\n", msg);
			failed = 1;
		}
	}
	long steps = 0;
	for (long i = begin; i < end; ++i)
		steps += units[i].dim == 2 ? o.headings : rot.count;
	mkProgress prog;
	mkProgress_Begin(&prog, "cobstacle", failed ? 0 : steps);
	for (long i = begin; i < end && !failed; ++i) {
		mkLevelResult res;
		const mkUnit *un = &units[i];
		if (un->dim == 2) {
			failed = mkRunLevel2(&o, un->obstacles, un->trial, &w2, &prog, &res) != 0;
			if (!failed)
				mkWriteRow(&csv, 2, un->obstacles, w2.n, o.headings, un->trial, o.form,
					mkImpl_Resolve(o.impl), &res);
		} else {
			failed = mkRunLevel3(&o, un->obstacles, un->trial, &rot, &w3, &prog, &res) != 0;
			if (!failed)
				mkWriteRow(&csv, 3, un->obstacles, w3.n, rot.count, un->trial, o.form,
					mkImpl_Resolve(o.impl), &res);
		}
		if (!failed && res.nonfinite > 0)
			fprintf(stderr, "cobstacle: %dD, %ld obstacles, trial %ld: %ld non-finite points "
				"(counted in the row's 'nonfinite' column)\n", un->dim, un->obstacles, un->trial, res.nonfinite);
	}
	mkProgress_End(&prog);
	mkLoadAverage(text, sizeof text);
	mkMeta_Set(&meta, "loadavg_end", text);

	if (open)
		failed = mkCsv_Finish(&csv, &meta, failed, "cobstacle");
	else
		mkMeta_Free(&meta);
	mkWork_Free(&w2);
	mkWork_Free(&w3);
	free(rot.R);
	free(units);
	return failed ? 1 : 0;
}
