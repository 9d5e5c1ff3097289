/* scenewide.h - a bounding volume hierarchy of eight children per node for
 * box queries: which obstacles' boxes meet a given box (internal to
 * libmink_cspace; the scene query's walk when max_clearance is finite);
 * and cells of the obstacles' spheres, the scene query's test of the
 * spheres near a part in place of that walk where they fit (mkSwCells).
 *
 * The children's boxes are stored axis by axis, rounded outwards to
 * floats, so that a node's eight tests are comparisons only (no
 * arithmetic, no rounding: a box that meets the query box always passes)
 * and run side by side. Built top down: each node splits its obstacles at
 * the median of their box centres along the longest axis of their bounds,
 * three times over, into eight groups; a group of at most MK_SW_LEAF
 * obstacles is a leaf. */
#ifndef MINK_CSPACE_SCENEWIDE_H
#define MINK_CSPACE_SCENEWIDE_H

#include <math.h>
#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE__)
#include <emmintrin.h>
#endif

#include "mink/base.h"

#define MK_SW_WIDTH 8   /* children per node */
#define MK_SW_LEAF 1    /* obstacles per leaf at most */
#define MK_SW_STACK 96  /* walk stack: 7 per level + 1; the median splits make at most 12 levels for any int count */

/* An axis-aligned box. */
typedef struct mkSwBox { double lo[3], hi[3]; } mkSwBox;

/* A node: child k's box [lo[.][k], hi[.][k]]; an inner child has count 0
 * and first its node; a leaf has the obstacles order[first .. first +
 * count); an unused child an empty box (lo > hi). */
typedef struct mkSwNode {
	float lo[3][MK_SW_WIDTH], hi[3][MK_SW_WIDTH];
	int first[MK_SW_WIDTH], count[MK_SW_WIDTH];
	unsigned leaves;   /* bit k: child k is a leaf */
} mkSwNode;

/* The children of node nd whose boxes meet [lo, hi], as bits (bit k:
 * child k; unused children meet a box with infinite sides): eight children
 * per AVX compare, four per SSE compare on x86, one at a time elsewhere
 * (the same bits). */
#if defined(__AVX__)
static inline unsigned mkSwNode_Meet(const mkSwNode *nd, const float lo[3], const float hi[3])
{
	__m256 in = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
	for (int i = 0; i < 3; ++i) {
		in = _mm256_and_ps(in, _mm256_cmp_ps(_mm256_loadu_ps(&nd->lo[i][0]), _mm256_set1_ps(hi[i]), _CMP_LE_OQ));
		in = _mm256_and_ps(in, _mm256_cmp_ps(_mm256_loadu_ps(&nd->hi[i][0]), _mm256_set1_ps(lo[i]), _CMP_GE_OQ));
	}
	return (unsigned)_mm256_movemask_ps(in);
}
#elif defined(__SSE__)
static inline unsigned mkSwNode_Meet(const mkSwNode *nd, const float lo[3], const float hi[3])
{
	unsigned m = 0;
	for (int h = 0; h < MK_SW_WIDTH; h += 4) {
		__m128 in = _mm_castsi128_ps(_mm_set1_epi32(-1));
		for (int i = 0; i < 3; ++i) {
			in = _mm_and_ps(in, _mm_cmple_ps(_mm_loadu_ps(&nd->lo[i][h]), _mm_set1_ps(hi[i])));
			in = _mm_and_ps(in, _mm_cmpge_ps(_mm_loadu_ps(&nd->hi[i][h]), _mm_set1_ps(lo[i])));
		}
		m |= (unsigned)_mm_movemask_ps(in) << h;
	}
	return m;
}
#else
static inline unsigned mkSwNode_Meet(const mkSwNode *nd, const float lo[3], const float hi[3])
{
	unsigned m = 0;
	for (int k = 0; k < MK_SW_WIDTH; ++k) {
		int in = (nd->lo[0][k] <= hi[0]) & (nd->hi[0][k] >= lo[0]) & (nd->lo[1][k] <= hi[1]) & (nd->hi[1][k] >= lo[1])
			& (nd->lo[2][k] <= hi[2]) & (nd->hi[2][k] >= lo[2]);
		m |= (unsigned)in << k;
	}
	return m;
}
#endif

typedef struct mkSwTree {
	mkSwNode *node;   /* root at 0 */
	int *order;       /* the obstacle at each position */
	mkSwBox *box;     /* its box, at its position (the boxes of a leaf side by side) */
	int nnode, n;
	int avx;          /* the walk's AVX2 build runs (scenewide_avx2.c: eight children per compare) */
} mkSwTree;

/* The tree of the n boxes (n >= 0; NULL arrays when n = 0). Returns
 * MK_ERR_MEMORY when out of memory (t then empty). */
mkResult mkSwTree_Build(mkSwTree *t, const mkSwBox *box, int n);
void mkSwTree_Free(mkSwTree *t);

/* A walk: nodes to visit, the leaves of node `node` still to read (bits
 * of pend), and the leaf being read (positions k .. end). */
typedef struct mkSwWalk {
	int stack[MK_SW_STACK], top, node, k, end;
	unsigned pend;
} mkSwWalk;

/* A walk of the boxes that meet [lo, hi], its root visited: w->top > 0
 * when it goes on below the root's children. */
void mkSwWalk_Begin(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3]);

/* The walk's next positions (at most max, into pos: obstacles order[pos],
 * boxes box[pos]): those of the leaves whose boxes meet [lo, hi]; the box
 * may shrink from call to call (nodes stacked under a larger one are
 * tested again when visited). Returns their number, 0 when the walk is
 * over. */
int mkSwWalk_Next(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3], int *pos, int max);

/* The same built for AVX2 (called by the two above where the CPU runs it). */
void mkSwWalk_BeginAvx2(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3]);
int mkSwWalk_NextAvx2(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3], int *pos, int max);

/* The lowest set bit of m != 0. */
static inline int mkSw_Low(unsigned m)
{
#if defined(__GNUC__)
	return __builtin_ctz(m);
#else
	int k = 0;
	while (!(m >> k & 1u)) ++k;
	return k;
#endif
}

/* Finite x rounded down and up to a float: x moved outwards by more than
 * the rounding to nearest can move it back (half a float's unit in the
 * last place, 2^-24 of |x|, or 2^-150 below the normal floats); infinite
 * beyond the floats' range. Both keep order: a <= b gives
 * mkSw_Down(a) <= mkSw_Up(b), so two boxes that meet meet rounded. */
static inline float mkSw_Down(double x) { return (float)(x - (fabs(x) * 0x1p-22 + 0x1p-140)); }
static inline float mkSw_Up(double x) { return (float)(x + (fabs(x) * 0x1p-22 + 0x1p-140)); }

/* Cells over the obstacles' spheres for the test of the spheres near a
 * point c (a part's centre), in place of the walk: cells of side 1 / inv
 * from lo, n[i] along axis i. Cell k's blocks, block[start[k] ..
 * start[k + 1]), hold the positions (in the walk's order) of the
 * obstacles whose spheres come within r of the cell, 16 to a block, each
 * with its sphere's centre in the cell's units (u(x) = (x - lo) inv less
 * the cell's index: the cell is [0, 1)^3) and a squared radius in them,
 * rounded to floats and grown beyond that rounding and the float test's
 * (mkSwCells_Near): where a sphere of radius at most r about c in the cell
 * comes within 0 of an obstacle's sphere (the double test), the float test
 * of that block says so. A block's unused places never pass (squared
 * radius -1). No cells (start NULL) for an empty tree, r not finite or
 * coordinates beyond 1e30. */
#define MK_SW_CELL 16
typedef struct mkSwCellBlock {
	_Alignas(64) float x[MK_SW_CELL], y[MK_SW_CELL], z[MK_SW_CELL], rr[MK_SW_CELL];
	int pos[MK_SW_CELL];
} mkSwCellBlock;

typedef struct mkSwCells {
	double lo[3], inv;
	int n[3];
	int *start;
	mkSwCellBlock *block;
} mkSwCells;

/* Cells of side `side`, grown by 1.25 until they fit in `bytes` (no cells
 * when that takes more than 4 times the side). Returns MK_ERR_MEMORY when
 * out of memory (g then without cells). */
mkResult mkSwCells_Build(mkSwCells *g, const mkSwTree *t, const double (*sphere)[4], double r, double side, long bytes);
void mkSwCells_Free(mkSwCells *g);

/* The blocks of the cell of c (*b; returns their number, 0 where c lies
 * outside the cells: no sphere comes within r there; -1 without cells)
 * and c in the cell's units, as floats (cf). */
static inline int mkSwCells_Find(const mkSwCells *g, const double c[3], const mkSwCellBlock **b, float cf[3])
{
	if (!g->start) return -1;
	long at = 0;
	for (int i = 2; i >= 0; --i) {
		double f = (c[i] - g->lo[i]) * g->inv;
		if (!(f >= 0.0 && f < (double)g->n[i])) return 0;
		long k = (long)f;
		cf[i] = (float)(f - (double)k);
		at = at * g->n[i] + k;
	}
	*b = g->block + g->start[at];
	return g->start[at + 1] - g->start[at];
}

/* The places of block b whose spheres may come within 0 of the sphere of
 * radius at most the cells' r about the point cf of the block's cell (its
 * units, mkSwCells_Find's), as bits. */
#if defined(__SSE__)
static inline unsigned mkSwCells_Near(const mkSwCellBlock *b, const float cf[3])
{
	__m128 cx = _mm_set1_ps(cf[0]), cy = _mm_set1_ps(cf[1]), cz = _mm_set1_ps(cf[2]);
	unsigned m = 0;
	for (int k = 0; k < MK_SW_CELL; k += 4) {
		__m128 dx = _mm_sub_ps(cx, _mm_load_ps(b->x + k)), dy = _mm_sub_ps(cy, _mm_load_ps(b->y + k));
		__m128 dz = _mm_sub_ps(cz, _mm_load_ps(b->z + k));
		__m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
		m |= (unsigned)_mm_movemask_ps(_mm_cmple_ps(d2, _mm_load_ps(b->rr + k))) << k;
	}
	return m;
}
#else
static inline unsigned mkSwCells_Near(const mkSwCellBlock *b, const float cf[3])
{
	unsigned m = 0;
	for (int k = 0; k < MK_SW_CELL; ++k) {
		float dx = cf[0] - b->x[k], dy = cf[1] - b->y[k], dz = cf[2] - b->z[k];
		m |= (unsigned)(dx * dx + dy * dy + dz * dz <= b->rr[k]) << k;
	}
	return m;
}
#endif

#endif
