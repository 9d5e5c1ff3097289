/* demos.h - the geometry of the paper's demonstration figures 1-4.
 *
 * Writes, for each figure, the curves and surfaces a plot needs (bodies,
 * closed-form Minkowski-sum boundaries, B2 placed on them, contact normals)
 * as CSV files in the directory named like the result without ".csv", and
 * one index row per file in the result itself. Every body is built from its
 * SPEC text (mink/spec.h), which the index records, so that a reader can
 * rebuild it. The sum is always the contact space B1 (+) (-B2): the places
 * of B2's centre at which B2 touches B1 (mink/sum.h).
 *
 * Parameters. Where the paper gives them they are used exactly:
 *  Fig. 1  SE(a=(10,8.6), eps=0.36) and SE(a=(9.4,6.8), eps=1.28), N = 50,
 *          M_i = rot(angle_i) shear(s_i), angles (pi/8, -pi/5), shears
 *          (1.32, 1.6): the pairwise differences x1_i - x2_j of the 50
 *          samples of each body (the definition) and the closed form at B1's
 *          50 surface parameters.
 *  Fig. 2  SE((3.3,2.6), 0.73) and SE((2.4,2), 1.28), N = 100, angles
 *          (pi/6.3, -pi/3), shears (0.276, 0.85); Theorem 1 (normal form at
 *          100 normal angles) and Theorem 2 (gradient form at B1's 100
 *          surface angles), B2 placed where B1's surface parameter is the
 *          25th of 100 (the reference code's idx = 25, i.e. k = 24 here).
 *  Fig. 4  primitives: cubes eps = (0.1, 0.1), elliptic cylinders
 *          eps = (0.1, 1), parallelepipeds = cubes mapped by
 *          M1 = [1 0 .5; 0 1 .2; 0 0 1], M2 = [1 0 .47; 0 1 .14; 0 0 1]
 *          (the shear first, then the body's rotation: M = R S, as in the
 *          reference code),
 *          50 x 50 grids.
 * Where the paper is silent the choices are fixed here and recorded in the
 * index and the sidecar (the constants in demos.c; the experiments README says why):
 * the Fig. 3 superellipses and transforms, the general superquadrics of
 * Fig. 4(a, b), the sizes of the primitives (taken from the reference code's
 * demo script where it has them), the rotations (the reference code draws
 * them at random), the ellipsoids' semi-axes, and where B2 is placed.
 *
 * No random draws: the run is the same every time. --shard splits the
 * figures (1..4) into blocks; the shards' index rows, concatenated in
 * order, are the unsplit run's rows.
 *
 * Options: which figures (all by default), the samples of a drawn 2D
 * outline (not of the sums, which use the paper's N) and the kernel. */
#ifndef MINK_EXP_DEMOS_H
#define MINK_EXP_DEMOS_H

#include <mink/mink.h>
#include <mink_exp/exp.h>

#define MK_DEMOS_SCHEMA 1
#define MK_DEMOS_OUTLINE_DEFAULT 400

typedef struct mkDemosOptions {
	int figure[5];     /* figure[f] = 1 when figure f (1..4) is wanted */
	long outline;      /* samples per drawn 2D outline */
	mkImpl impl;
} mkDemosOptions;

/* The index CSV's columns, ended by NULL: one row per geometry file. */
extern const char *const mkDemos_Columns[];

/* Write figure f (1..4): its geometry files beside run->out
 * (mkRun_OpenSibling), each committed with run->meta plus the keys of
 * the file, and one index row per file into run->csv. Returns 0, or -1
 * after printing why. */
int mkDemos_Figure(mkRun *run, const mkDemosOptions *o, int f);

/* The run's sidecar keys (after the harness's): no seed, one "trial", the
 * figures of this shard (units[begin..end)), the fixed choices. */
void mkDemos_Describe(mkMeta *meta, const mkDemosOptions *o, const int *units, long begin, long end);
/* The keys of the index's own sidecar, set last (the geometry files'
 * sidecars carry their own figure, panel, content, bodies, note). */
void mkDemos_DescribeIndex(mkMeta *meta);

#endif
