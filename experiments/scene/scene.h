/* scene.h - the `scene` experiment: C-obstacles certified to a tolerance
 * (mink/cobstacle.h) against uniform sampling, and the paper's Table 2 on
 * every core.
 *
 * Part A (rows part = A): per scene (dimension, obstacle count) and
 * tolerance T, the adaptive mode's points, time and worst-case certified
 * error E over the scene (every obstacle, every orientation), then the
 * smallest uniform sampling (2D: n normals 2 pi k / n; 3D: octahedron
 * splits) whose worst-case certified error is at most E, its points and
 * time. factor = uniform points / adaptive points. The search climbs on
 * the boundary that failed last and confirms a level on the whole scene
 * only where that boundary passes. A search that would need a whole-scene
 * run of more than MK_SCENEX_BUDGET2/3 points, or a level past 2D
 * n = 2^22 / 3D 10 splits, is marked capped = 1: its row is the largest
 * level known to fail (param), the points the whole scene would use there,
 * the error of the failing boundary (so a lower bound of the scene's), no
 * times or checksum when only that boundary ran, and its factor a lower
 * bound.
 *
 * Scenes are drawn like the paper's C-obstacle experiment (Sec. 7.1):
 *  2D robot a ~ U(0,5), b ~ U(0,3), eps ~ U(0,1); obstacles a, b ~ U(0,10),
 *     eps ~ U(0,2), centre ~ U(-200,200)^2, angle ~ U(0,pi);
 *  3D robot a, b, c ~ U(0,5), eps1, eps2 ~ U(0,2); obstacles a, b, c ~
 *     U(0,10), eps1, eps2 ~ U(0,2), centre ~ U(-200,200)^3, rotation from
 *     the quaternion pi U(0,1)^4 normalised;
 * values clamped into the core's ranges. Every tenth obstacle (i % 10 == 9)
 * is instead a box of sides ~ U(1,20) (3D: alternately a box and a cylinder
 * of radius ~ U(0.5,10), height ~ U(1,20)), placed the same way. The draws
 * are this file's own: the C-obstacle experiment's are static in
 * cobstacle.c. Stream of a scene: (dim << 56) | obstacles of the run's seed;
 * numbers in the order: a body for the robot drawn like an obstacle (its
 * numbers then unused), the robot's shape, then each obstacle (shape,
 * centre, rotation, then a box's sides or a cylinder's radius and height).
 * Orientations: 2D headings pi k / H, k < H; 3D the first ones of the SO(3)
 * file.
 *
 * Part B (rows part = B): Table 2's levels through mkCSpace_Run in paper
 * mode with store = 0, on 1 and 2 threads alternately (1, 2, 1, 2 ... for
 * --reps pairs) in one process; wall and process CPU seconds, the sum of
 * the per-boundary checksums (a run fails when the two thread counts
 * disagree), the parallel efficiency t1 / (2 t2) of each pair on its
 * 2-thread row and the paper's total (mink_exp/paper.h). */
#ifndef MINK_EXP_SCENE_H
#define MINK_EXP_SCENE_H

#include <mink/cspace.h>
#include <mink_exp/exp.h>

#include "cobstacle.h"

#define MK_SCENEX_SCHEMA 1
#define MK_SCENEX_MAX 16
/* Part A: the most points a whole-scene uniform run may use (2D, 3D) */
#define MK_SCENEX_BUDGET2 1e8
#define MK_SCENEX_BUDGET3 6e7
/* Part A: failing boundaries tried first at the next level */
#define MK_SCENEX_TOP 16
/* Part B levels whose 1-thread run is shorter (seconds) have no meaningful
 * parallel efficiency: thread start-up is a visible part of them */
#define MK_SCENEX_TINY_S 0.1

extern const char *const mkSceneX_Columns[];

/* A comma-separated list of up to 16 numbers (mkFlag parse callbacks):
 * obstacle counts in [1, 100000] or tolerances in [1e-6, 10]. */
typedef struct mkSceneXList {
	double v[MK_SCENEX_MAX];
	int n;
} mkSceneXList;
int mkSceneXList_ParseCounts(void *list, const char *text, char *msg, size_t msglen);
int mkSceneXList_ParseTols(void *list, const char *text, char *msg, size_t msglen);

typedef struct mkSceneXOptions {
	uint64_t seed;
	mkSceneXList a2, a3, tols2, tols3;   /* Part A scenes and tolerances */
	long headings_a, orient_a;   /* Part A orientations (2D, 3D) */
	mkSceneXList b2, b3;         /* Part B levels */
	long headings_b, points_b, grid_b, orient_b, reps;
	const mkRotations *rot;      /* the SO(3) file's rotations */
	long threads;                /* Part A */
} mkSceneXOptions;

/* Draw a scene of `obstacles` bodies (boxes and cylinders included when
 * `boxes`) with `orientations` orientations (3D: the first of rot). The
 * caller frees it with mkScene_Free. Returns MK_OK or MK_ERR_MEMORY. */
mkResult mkSceneX_Draw(mkScene *s, uint64_t seed, int dim, long obstacles, int boxes, long orientations,
	const mkRotations *rot);

/* Part A for one scene and tolerance: the adaptive row and the uniform row. */
mkResult mkSceneX_Compare(const mkScene *s, double tol, int threads, mkCsv *csv, char *msg, size_t msglen);

/* Part B for one level: 2 * reps rows. Returns 0, or -1 with msg saying
 * why: mkCSpace_Run failed, or the checksums of 1 and 2 threads differ. */
int mkSceneX_Table2(const mkScene *s, int points, int reps, mkCsv *csv, char *msg, size_t msglen);

/* Fig. 9 with inner and outer boundaries: the 2D scene of `obstacles`
 * (drawn as in Part A) at heading 0, adaptive to tol with outer bounds,
 * written beside the result as fig9-boundaries.csv (obstacle, bound, x, y;
 * each boundary closed and ended by two blank lines, gnuplot's block
 * separator). Returns 0, or -1 after printing why. */
int mkSceneX_Figure9(mkRun *run, uint64_t seed, long obstacles, double tol);

/* The section of results/tables.md: <dir>/scene.csv. */
void mkScene_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
