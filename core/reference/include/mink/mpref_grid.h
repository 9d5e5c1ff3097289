/* mink/mpref_grid.h - the grid of the extremes experiment as data, and the
 * SPEC text of a reference body.
 *
 * A cell is one pair of bodies (B1, B2). Two families make the grid:
 *  - "eps": every pair of exponents from the eps axis below, at fixed
 *    semi-axes (B1 a=1, b=0.5 [c=0.8]; B2 a=0.8, b=0.3 [c=0.5]), fixed
 *    rotations (2D 0.3 and 1.2 rad; 3D a turn of 0.3 rad about (1,2,3)/|.|
 *    and 1.2 rad about (-2,1,1)/|.|), B1 at the origin, B2 at
 *    (0.25, -0.5 [, 0.3]). 2D: B1.eps x B2.eps. 3D: both bodies take
 *    (eps1, eps2) of the cell (the heat map's axes).
 *  - sweeps of one parameter at a time, each at the exponents of `sweepEps`
 *    (the same eps, or eps1 = eps2 = eps, for both bodies):
 *      "axis"  the long-to-short semi-axis ratio of both bodies (b, and c in
 *              3D, divided by it), 1 ... 1e6;
 *      "shear" both maps R [1 s; 0 1] (3D R [1 s 0; 0 1 0; 0 0 1]), 0 ... 100;
 *      "size"  B2's semi-axes times the ratio, 1e-6 ... 1e6;
 *      "shift" both translations times T (B1 at T (0.6, 0.8 [, 0]), B2 at
 *              T (-0.8, 0.6 [, 0.5]) plus its base position), 0 ... 1e9.
 * The "quick" grid takes five exponents (both ends, 1e-2, 1, 1.99) and only
 * the two ends of each sweep at eps = 1.
 *
 * Every body is written as a SPEC with its map as M=... (row-major) and
 * every number as %.17g, so that mkSpec_Parse (mink/spec.h) gives back the
 * very doubles of the cell: any row of the experiment can be re-run alone with
 * `mink sum`. */
#ifndef MINK_MPREF_GRID_H
#define MINK_MPREF_GRID_H

#include <stddef.h>
#include <mink/mpref.h>

typedef enum refGridKind { REF_GRID_QUICK, REF_GRID_FULL } refGridKind;

#define REF_SPEC_MAX 512

typedef struct refCell {
	int dim;
	int index;            /* 0 .. refGrid_Count - 1 */
	const char *family;   /* "eps", "axis", "shear", "size" or "shift" */
	double eps[2][2];     /* [body][0: eps or eps1, 1: eps2 (3D; = [0] in 2D)] */
	double axis, shear, size, shift; /* the sweep values (base values 1, 0, 1, 0) */
	refBody b1, b2;
	char spec1[REF_SPEC_MAX], spec2[REF_SPEC_MAX];
} refCell;

/* The eps axis of the "eps" family: for FULL these 13 values
 * (1e-6, 1e-4, 1e-3, 1e-2, 0.1, 0.5, 1, 1.5, 1.9, 1.99, 1.999, 2 - 1e-4,
 * 2 - 1e-6), for QUICK 1e-6, 1e-2, 1, 1.99, 2 - 1e-6. Returns the count and
 * points *values at a static table. */
int refGrid_Eps(refGridKind kind, const double **values);
/* The exponents each sweep is run at: FULL 1e-6, 1, 2 - 1e-6; QUICK 1. */
int refGrid_SweepEps(refGridKind kind, const double **values);

/* Number of cells for dim 2 or 3 (0 for another dim). */
int refGrid_Count(refGridKind kind, int dim);

/* Cell `index` of the grid. Returns 0, or -1 when dim is not 2 or 3 or index
 * is out of range (cell untouched). */
int refGrid_Cell(refGridKind kind, int dim, int index, refCell *cell);

/* "quick" or "full" to a kind. On anything else returns -1 and writes one
 * line naming the flag (`flag`, e.g. "--grid"), the value and the choices. */
int refGrid_Parse(const char *text, const char *flag, refGridKind *kind, char *msg, size_t msglen);

/* The SPEC text of a body: "superellipse a=.. b=.. eps=.. M=m11,m12,m21,m22
 * at=x,y" or "superquadric a=.. b=.. c=.. eps1=.. eps2=.. M=(9 entries)
 * at=x,y,z", every number %.17g (which round-trips any double). Returns the
 * length written, or -1 when it does not fit in len (buf then holds a
 * truncated, NUL-terminated text if len > 0). */
int refBody_Spec(const refBody *b, char *buf, size_t len);

#endif
