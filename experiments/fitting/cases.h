/* cases.h - the three cases of the fitting experiment (paper Sec. 6.2).
 *
 * Every trial draws from its own random stream (see mkFitStream), so a run
 * split into shards produces exactly the rows of the whole run. Each call
 * fills one or more rows; a failure inside a trial (a hull qhull cannot
 * build, a fit that leaves the valid shapes) is written into the row's
 * status with NaN measurements, never dropped.
 *
 * Case 1: a superquadric fitted to a random convex polyhedron. 100 points
 *   [20,15,10] .* U(-1,1)^3; their hull is the truth; the superquadric is
 *   fitted to the hull vertices (sqfit.h, PCA start). e_volume against the
 *   hull volume, e_implicit = mean |Psi - 1| over the vertices.
 * Case 2: a polyhedron fitted to a superquadric. a = [20,15,10] .* U(0,1)^3,
 *   eps ~ U(0,2)^2, rotation from a quaternion U(0,1)^4; the hull of an
 *   n x n surface grid against the beta-function volume, for the sampling
 *   of the published code and for the core's grid (mkSample3_Grid).
 * Case 3: primitives of size [50,36,20] .* U(0,1)^3 + 1, each modelled both
 *   ways: cube (superquadric eps = (0.1, 0.1); polyhedron of its 8 corners),
 *   ellipsoid of semi-axes = size (superquadric eps = (1,1); 9 x 9 grid
 *   polyhedra), elliptic cylinder of cross-section semi-axes size_x, size_y
 *   and height size_z (superquadric eps = (0.1, 1); 2 rings x 30 points).
 *
 * Samplings ("sampling" column):
 *  - "paper": the published code's grid: eta has n values from -pi/2 to
 *    pi/2, omega n values from -pi - 1e-6 in steps of 2 pi/(n-1), so its
 *    first and last longitudes coincide and only n - 1 are distinct; its
 *    cylinder rings take 30 angles from -pi to pi (29 distinct).
 *  - "distinct": the core's grid (n distinct longitudes) and 30 distinct
 *    angles per cylinder ring.
 *  - "random" (case 1), "corners" (the cube's 8 corners) and "none" (a
 *    superquadric given in closed form). */
#ifndef MK_FIT_CASES_H
#define MK_FIT_CASES_H

#include <stdint.h>

#include <mink/body.h>

/* Case 2's grid sizes n (n x n points). */
#define MK_FIT_CASE2_NMIN 4
#define MK_FIT_CASE2_NMAX 20
/* Rows one trial of each case produces. */
#define MK_FIT_CASE1_ROWS 1
#define MK_FIT_CASE2_ROWS (2 * (MK_FIT_CASE2_NMAX - MK_FIT_CASE2_NMIN + 1))
#define MK_FIT_CASE3_ROWS 8
#define MK_FIT_MAX_ROWS MK_FIT_CASE2_ROWS

typedef struct mkFitRow {
	int caseId;           /* 1, 2, 3 */
	int trial;            /* 0-based */
	const char *truth;    /* "polyhedron", "superquadric", "cube", "ellipsoid", "cylinder" */
	const char *model;    /* "superquadric" or "polyhedron" */
	const char *sampling; /* "random", "paper", "distinct", "corners", "none" */
	int level;            /* points the polyhedron is built from (0 for a closed-form superquadric) */
	int vertices;         /* hull vertices (0 when no hull is built) */
	double volumeTrue;
	double volumeModel;
	double eVolume;       /* |V_model - V_true| / V_true */
	double eImplicit;     /* mean |Psi - 1| over the polyhedron's vertices; NaN where undefined */
	mkShape3 shape;       /* the superquadric of the row (fitted, true or model); NaN if none */
	double q[4];          /* its orientation (w, x, y, z); NaN if none */
	mkVec3 t;             /* its centre */
	double size[3];       /* case 3: the primitive's size; NaN otherwise */
	double cost;          /* case 1: final least-squares cost; NaN otherwise */
	int iterations;       /* case 1: Levenberg-Marquardt iterations; 0 otherwise */
	int nfev;             /* case 1: residual evaluations; 0 otherwise */
	const char *status;   /* "ok", "clamped", minpack's code name, or what failed */
} mkFitRow;

/* The random stream of one trial: case in bits 48.., level (case 2's n, case
 * 3's primitive 1..3, else 0) in bits 32..47, trial in bits 0..31. */
uint64_t mkFitStream(int caseId, int level, int trial);

/* Each fills its rows into rows[] (room for MK_FIT_MAX_ROWS) and returns how
 * many, or -1 when memory runs out (nothing else makes them fail). */
int mkFitCase1_Trial(uint64_t seed, int trial, mkFitRow *rows);
int mkFitCase2_Trial(uint64_t seed, int trial, mkFitRow *rows);
int mkFitCase3_Trial(uint64_t seed, int trial, mkFitRow *rows);

/* The published code's n x n grid of unit directions (see above), stored at
 * i*n + j like mkSample3_Grid; n >= 2. */
void mkFitSample3_PaperGrid(int n, double *ux, double *uy, double *uz);

/* Volume of the convex hull of the points of body b on an n x n grid of
 * directions, the paper's (paperGrid = 1) or the core's; also writes the
 * hull vertex count and the mean |Psi_b - 1| over the grid points (a check
 * that they lie on the surface). Fails as mkHull3_Volume. */
mkResult mkFitGridHullVolume(mkBody3 b, int n, int paperGrid, double *volume, int *vertices,
	double *eImplicit);

#endif
