/* extremes.h - the numerical-stability map at the extremes: every registry method that accepts the pair, on every
 * cell of the extremes grid (mink/mpref_grid.h: exponents towards both ends
 * of their range, semi-axis ratios, shears, size ratios and translations),
 * scored by the 256-bit MPFR reference (mink/mpref_measure.h): the largest
 * distance of an output point from the exact boundary, absolute and relative
 * to the sum's size S (refSum_Size), beside the problem's own condition
 * (how far the exact boundary moves under one-ulp input perturbations).
 *
 * One row per (cell, set, method). A method that fails on a cell gets its
 * row with status error:<result> or nonfinite; no row is ever dropped. A
 * method that does not accept the pair (the geometric formula off ellipses,
 * edge sorting in 3D) has no row: the sidecar counts those. */
#ifndef MINK_EXP_EXTREMES_H
#define MINK_EXP_EXTREMES_H

#include <mink/mpref_grid.h>
#include <mink/registry.h>
#include <mink_exp/exp.h>

#define MK_EXTREMES_SCHEMA 1
#define MK_EXTREMES_METHODS_MAX 64
/* The closed forms' bar: error_rel within 1e-13 wherever the condition is at
 * most MK_EXTREMES_COND_OK (the geometry then allows it with a margin of ten). */
#define MK_EXTREMES_KEEP 1e-12
#define MK_EXTREMES_BAR 1e-13
#define MK_EXTREMES_COND_OK 1e-14

extern const char *const mkExtremes_Columns[];

typedef struct mkExtremesOptions {
	refGridKind grid;
	int dim_on[4];      /* [2], [3] */
	int set_on[2];      /* [0] contact, [1] plus */
	long n2, n3;        /* closed forms: 2D angles, 3D grid side */
	long s2, s3;        /* sampled methods: samples per body (3D grid side) */
	long cells;         /* 0: every cell; else only the first `cells` of each dim (tests) */
	long threads;       /* cells run at once (default 2); rows stay in cell order */
	int method_on[MK_EXTREMES_METHODS_MAX]; /* by registry index */
} mkExtremesOptions;

void mkExtremesOptions_Default(mkExtremesOptions *o);

/* MK_FLAG_TEXT parser of --methods: comma-separated registry names or "all"
 * into the int[MK_EXTREMES_METHODS_MAX] `on`. */
int mkExtremes_ParseMethods(void *on, const char *text, char *msg, size_t msglen);

/* The resolution a method runs at under o (closed forms n2/n3, sampled
 * s2/s3). Checks every selected method against mkMethod_CheckN; returns 0,
 * or -1 with the method's message. */
long mkExtremes_N(const mkExtremesOptions *o, const mkMethod *m, int dim);
int mkExtremes_Check(const mkExtremesOptions *o, char *msg, size_t msglen);

/* The run's units: (dim, cell) pairs in order, 2D cells first. Returns the
 * count; fills dims/cells when not NULL. */
long mkExtremes_Units(const mkExtremesOptions *o, int *dims, int *cells);

/* Counters a run keeps for its sidecar. */
typedef struct mkExtremesTally {
	long rows, failed, nonfinite, rejected;
	long searches, reused; /* per-point 256-bit searches run, and answered from the memo */
} mkExtremesTally;

/* Every row of one (dim, cell): both sets (as selected), every selected
 * method that accepts the pair. Returns 0, or -1 when the cell cannot be
 * built (a grid or SPEC fault: a bug, the run fails) or memory runs out. */
int mkExtremes_RunCell(const mkExtremesOptions *o, int dim, int cell, mkCsv *csv, mkExtremesTally *tally);

/* Every unit k in [0, count) (dims[k], cells[k]) on `threads` threads,
 * the rows written to csv in unit order whatever the thread count (each
 * unit's rows are gathered in memory, then appended in order). step(ctx)
 * is called by the calling thread after each unit is written. Returns 0,
 * or -1 when a unit failed (the units after it are not run) or a thread
 * could not be started. */
int mkExtremes_RunUnits(const mkExtremesOptions *o, const int *dims, const int *cells, long count,
	mkCsv *csv, mkExtremesTally *tally, void (*step)(void *ctx), void *ctx);

/* The stability section of results/tables.md: per method and dim, the
 * cells kept within 1e-12 of the size S, the worst cell, the non-finite
 * outputs and error returns; for the exact closed forms whether 1e-13
 * holds wherever the condition is at most 1e-14. Compares with no
 * published number: the tally is left untouched. */
void mkExtremes_Summary(mkDoc *d, const char *dir, mkTally *tally);

#endif
