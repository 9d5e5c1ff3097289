/* cobstacle.h - configuration-space obstacles (paper Sec. 7.1, Table 2 and
 * Fig. 9).
 *
 * A robot and many obstacles are superellipses (2D) or superquadrics (3D).
 * For every robot orientation and every obstacle, the C-obstacle boundary is
 * the contact space  obstacle (+) (-robot)  (mink/sum.h, MK_SET_CONTACT with
 * B1 = the obstacle and B2 = the robot turned to that orientation): the
 * places of the robot's centre at which it touches the obstacle. It is
 * computed by one mkSum2_Batch / mkSum3_Batch call per obstacle and
 * orientation, at the obstacle's surface parameters, and the whole loop is
 * timed on one thread (mink_exp/clock.h: wall and thread CPU time).
 *
 * Draws (paper Sec. 7.1, with the reference code's distributions):
 *  2D: robot a ~ U(0,5), b ~ U(0,3), eps ~ U(0,1); obstacles a, b ~ U(0,10),
 *      eps ~ U(0,2), centre ~ U(-200,200)^2, angle ~ U(0,pi); 50 points per
 *      boundary; 50 robot headings (k-1) pi / 50, k = 1..50.
 *  3D: robot a, b, c ~ U(0,5), eps1, eps2 ~ U(0,2); obstacles a, b, c ~
 *      U(0,10), eps1, eps2 ~ U(0,2), centre ~ U(-200,200)^3, rotation from
 *      the quaternion pi U(0,1)^4 normalised (the reference code's draw of
 *      this experiment, not the 4 U(0,1) of mink_exp/draw.h's paper draw);
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
 * Rows: one per dimension, obstacle count and trial (the run's units, which
 * --shard splits), with the time, the time per boundary point, the
 * published figures of that level (mink_exp/paper.h; empty for levels the
 * paper does not list) and a checksum of every computed coordinate, so that
 * a run can be told apart from one that skipped work.
 *
 * Fig. 9's geometry (the obstacles and 10 of the 50 C-slices of one 2D scene
 * of 500 obstacles) is written beside the result, in the directory named
 * like the result without ".csv" (mkPath_Sibling). */
#ifndef MINK_EXP_COBSTACLE_H
#define MINK_EXP_COBSTACLE_H

#include <mink/cspace.h>
#include <mink_exp/exp.h>

#define MK_COBSTACLE_SCHEMA 1
#define MK_COBSTACLE_MAX_LEVELS 16
#define MK_COBSTACLE_OBSTACLES_MAX 10000000L   /* fits the 32 bits of the stream map */
#define MK_COBSTACLE_TRIALS_MAX 1000000L       /* fits the 24 bits of the stream map */
#define MK_COBSTACLE_SO3_MAX 1000000L

/* Obstacle counts of one dimension, as --obstacles2 / --obstacles3 give
 * them. */
typedef struct mkCObstacleLevels {
	long count[MK_COBSTACLE_MAX_LEVELS];
	int n;
} mkCObstacleLevels;

/* The flag parser of a level list (mkFlag.parse; context an
 * mkCObstacleLevels): up to 16 comma-separated integers in [1, 1e7]. */
int mkCObstacleLevels_Parse(void *levels, const char *text, char *msg, size_t msglen);

typedef struct mkCObstacleOptions {
	uint64_t seed;
	long trials;
	int dim2, dim3;
	mkCObstacleLevels levels2, levels3;
	long headings;       /* 2D robot headings */
	long points2;        /* 2D points per boundary */
	long grid3;          /* 3D grid side */
	const char *so3;     /* 3D orientations file */
	long orient3;        /* use the first orient3 rotations (0: all) */
	mkForm form;
	mkImpl impl;
	long fig_obstacles;  /* 0: no figure geometry */
	long fig_slices;
} mkCObstacleOptions;

/* The CSV's columns, ended by NULL. */
extern const char *const mkCObstacle_Columns[];

/* ---- the 3D robot's orientations ----------------------------------------- */

typedef struct mkRotations {
	long count;
	mkMat3 *R;
	double max_error;   /* largest |R^T R - I| entry or |det R - 1| */
} mkRotations;

/* Read up to `limit` rotations (0: all) from a CSV with a header and one
 * row-major rotation matrix per line. Entries must form a rotation to 1e-9
 * (the file stores doubles to 17 digits; a larger deviation means it is not
 * a list of rotations). Returns 0, or -1 with a message naming --so3 (or
 * --orientations when the file holds fewer than `limit`). */
int mkRotations_Read(mkRotations *rot, const char *path, long limit, char *msg, size_t msglen);
void mkRotations_Free(mkRotations *rot);

/* ---- the run ------------------------------------------------------------- */

/* One unit of the run: a dimension, an obstacle count and a trial. */
typedef struct mkCObstacleUnit {
	int dim;
	long obstacles, trial;
} mkCObstacleUnit;

/* The run's units in row order: dim 2 first, obstacle counts as listed,
 * trials inner. Returns their number (*units allocated, NULL when out of
 * memory: then -1). */
long mkCObstacle_Units(const mkCObstacleOptions *o, mkCObstacleUnit **units);

/* Parameter samples and one C-slice's output (every obstacle's points for
 * one orientation; kept, as the reference code keeps each slice). */
typedef struct mkCObstacleWork {
	long n;                       /* points per boundary */
	double *ux, *uy, *uz;         /* parameters */
	double *x, *y, *z;            /* obstacles * n outputs */
	long capacity;
} mkCObstacleWork;

/* The 2D samples (points2 angles) and the 3D grid (grid3^2). Returns 0, or
 * -1 when out of memory (both freed by mkCObstacleWork_Free either way). */
int mkCObstacleWork_Init(mkCObstacleWork *w2, mkCObstacleWork *w3, const mkCObstacleOptions *o);
void mkCObstacleWork_Free(mkCObstacleWork *w);

/* What one unit measured. */
typedef struct mkCObstacleResult {
	double total_s;
	double cpu_s;
	long nonfinite;
	long clamped;
	double checksum;
	double robot[5];   /* a, b, c, eps1, eps2 (c and eps2 NaN in 2D) */
} mkCObstacleResult;

/* Draw and time one unit (2D: o->headings orientations; 3D: those of
 * rot, which may be NULL for a 2D unit), one progress step per
 * orientation. Returns 0, or -1 after printing why. */
int mkCObstacle_Level(const mkCObstacleOptions *o, const mkCObstacleUnit *u, const mkRotations *rot,
	mkCObstacleWork *w, mkProgress *prog, mkCObstacleResult *res);
/* The unit's row. */
void mkCObstacle_WriteRow(mkCsv *csv, const mkCObstacleOptions *o, const mkCObstacleUnit *u, long points,
	long orientations, const mkCObstacleResult *res);

/* The sidecar keys of the run (after the harness's): the units of this
 * shard [begin, end) of nunits, sizes, forms, draws, the timer. rot is
 * NULL when no 3D unit runs. */
void mkCObstacle_Describe(mkMeta *meta, const mkCObstacleOptions *o, long begin, long end, long nunits,
	const mkRotations *rot);

/* Fig. 9: a robot and o->fig_obstacles obstacles drawn as in the 2D
 * experiment, from their own stream; four files beside the result, each
 * with its sidecar:
 *   fig9-scene.csv         one row per body (the robot first): its parameters
 *   fig9-obstacles.csv.gz  each obstacle's outline in the workspace
 *   fig9-robot.csv         the robot's outline at each drawn heading
 *   fig9-slices.csv.gz     every obstacle's C-obstacle at each drawn heading
 * (the two large ones gzip-compressed, mink_exp/outfile.h).
 * Outlines are closed (k = n repeats k = 0) and end in two blank lines,
 * gnuplot's separator of data blocks. Returns 0, or -1 after printing why. */
int mkCObstacle_Figure9(mkRun *run, const mkCObstacleOptions *o, const mkCObstacleWork *w2);

/* The section of the tables: <dir>/cobstacle.csv beside the paper's
 * Table 2. */
void mkCObstacle_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
