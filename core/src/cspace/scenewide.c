/* scenewide.c - the eight-way hierarchy of box queries (scenewide.h). */
#include "cspace/scenewide.h"
#include "mink/sum.h"

#include <math.h>
#include <stdlib.h>

typedef struct mkSwKey { double key; int idx; } mkSwKey;

static int mkSw_CompareKey(const void *pa, const void *pb)
{
	const mkSwKey *a = pa, *b = pb;
	if (a->key != b->key) return a->key < b->key ? -1 : 1;
	return a->idx - b->idx;
}

typedef struct mkSwBuild {
	mkSwTree *t;
	const mkSwBox *box;
	mkSwKey *keys;
	int cap, failed;   /* nodes allocated; out of memory */
} mkSwBuild;

/* The bounds of the boxes at positions first .. first + count. */
static mkSwBox mkSw_Bounds(const mkSwBuild *b, int first, int count)
{
	mkSwBox x;
	for (int i = 0; i < 3; ++i) { x.lo[i] = INFINITY; x.hi[i] = -INFINITY; }
	for (int k = first; k < first + count; ++k) {
		const mkSwBox *y = &b->box[b->t->order[k]];
		for (int i = 0; i < 3; ++i) {
			x.lo[i] = fmin(x.lo[i], y->lo[i]);
			x.hi[i] = fmax(x.hi[i], y->hi[i]);
		}
	}
	return x;
}

/* Positions first .. first + count sorted by their boxes' centres along
 * the longest axis of their bounds (the lower half then goes first). */
static void mkSw_Sort(mkSwBuild *b, int first, int count)
{
	mkSwBox x = mkSw_Bounds(b, first, count);
	int axis = 0;
	for (int i = 1; i < 3; ++i)
		if (x.hi[i] - x.lo[i] > x.hi[axis] - x.lo[axis]) axis = i;
	int *order = b->t->order;
	for (int k = 0; k < count; ++k) {
		int i = order[first + k];
		b->keys[k] = (mkSwKey){b->box[i].lo[axis] + b->box[i].hi[axis], i};
	}
	qsort(b->keys, (size_t)count, sizeof *b->keys, mkSw_CompareKey);
	for (int k = 0; k < count; ++k) order[first + k] = b->keys[k].idx;
}

/* Node id over positions first .. first + count (count > MK_SW_LEAF):
 * three rounds of median splits into at most eight groups, each a leaf or
 * a new node. */
static void mkSw_Node(mkSwBuild *b, int id, int first, int count)
{
	int gf[MK_SW_WIDTH] = {first}, gc[MK_SW_WIDTH] = {count}, ng = 1;
	for (int round = 0; round < 3; ++round) {
		int n = ng;
		for (int g = 0; g < n; ++g) {
			if (gc[g] <= MK_SW_LEAF) continue;
			mkSw_Sort(b, gf[g], gc[g]);
			int half = gc[g] / 2;
			gf[ng] = gf[g] + half;
			gc[ng++] = gc[g] - half;
			gc[g] = half;
		}
	}
	b->t->node[id].leaves = 0;
	for (int k = 0; k < MK_SW_WIDTH; ++k) {
		mkSwNode *nd = &b->t->node[id];
		if (k >= ng) {
			for (int i = 0; i < 3; ++i) { nd->lo[i][k] = INFINITY; nd->hi[i][k] = -INFINITY; }
			nd->first[k] = -1;
			nd->count[k] = 0;
			continue;
		}
		mkSwBox x = mkSw_Bounds(b, gf[k], gc[k]);
		for (int i = 0; i < 3; ++i) { nd->lo[i][k] = mkSw_Down(x.lo[i]); nd->hi[i][k] = mkSw_Up(x.hi[i]); }
		if (gc[k] <= MK_SW_LEAF) {
			nd->first[k] = gf[k];
			nd->count[k] = gc[k];
			nd->leaves |= 1u << k;
			continue;
		}
		if (b->t->nnode == b->cap) {
			mkSwNode *more = b->failed ? NULL : realloc(b->t->node, 2 * (size_t)b->cap * sizeof *more);
			if (!more) { b->failed = 1; return; }
			b->t->node = more;
			b->cap *= 2;
			nd = &b->t->node[id];
		}
		int c = b->t->nnode++;
		nd->first[k] = c;
		nd->count[k] = 0;
		mkSw_Node(b, c, gf[k], gc[k]);
		if (b->failed) return;
	}
}

mkResult mkSwTree_Build(mkSwTree *t, const mkSwBox *box, int n)
{
	t->node = NULL;
	t->order = NULL;
	t->box = NULL;
	t->nnode = t->n = 0;
	t->avx = 0;
#if defined(MINK_HAVE_X86_KERNELS)
	t->avx = mkImpl_Available(MK_IMPL_AVX2);
#endif
	if (n <= 0) return MK_OK;
	mkSwBuild b = {t, box, malloc((size_t)n * sizeof(mkSwKey)), n / 4 + 1, 0};   /* (grown as needed) */
	t->node = malloc((size_t)b.cap * sizeof *t->node);
	t->order = malloc((size_t)n * sizeof *t->order);
	t->box = malloc((size_t)n * sizeof *t->box);
	if (!t->node || !t->order || !t->box || !b.keys) {
		free(b.keys);
		mkSwTree_Free(t);
		return MK_ERR_MEMORY;
	}
	for (int i = 0; i < n; ++i) t->order[i] = i;
	t->n = n;
	t->nnode = 1;
	if (n <= MK_SW_LEAF) { /* a root of one leaf */
		mkSwNode *nd = &t->node[0];
		for (int k = 0; k < MK_SW_WIDTH; ++k) {
			for (int i = 0; i < 3; ++i) { nd->lo[i][k] = INFINITY; nd->hi[i][k] = -INFINITY; }
			nd->first[k] = -1;
			nd->count[k] = 0;
		}
		mkSwBox x = mkSw_Bounds(&b, 0, n);
		for (int i = 0; i < 3; ++i) { nd->lo[i][0] = mkSw_Down(x.lo[i]); nd->hi[i][0] = mkSw_Up(x.hi[i]); }
		nd->first[0] = 0;
		nd->count[0] = n;
		nd->leaves = 1u;
	} else {
		mkSw_Node(&b, 0, 0, n);
	}
	if (b.failed) {
		free(b.keys);
		mkSwTree_Free(t);
		return MK_ERR_MEMORY;
	}
	for (int k = 0; k < n; ++k) t->box[k] = box[t->order[k]];
	free(b.keys);
	return MK_OK;
}

void mkSwTree_Free(mkSwTree *t)
{
	free(t->node);
	free(t->order);
	free(t->box);
	t->node = NULL;
	t->order = NULL;
	t->box = NULL;
	t->nnode = t->n = 0;
}
