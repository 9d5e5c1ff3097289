/* scenewide_body.h - the box query's walk of the hierarchy (cspace/scenewide.h),
 * one source built twice: scenewide_walk.c (SSE: four children per compare)
 * and scenewide_avx2.c (AVX: eight), picked when the tree is built. The same
 * comparisons, so the same walk. */
#ifndef MINK_CSPACE_SCENEWIDE_BODY_H
#define MINK_CSPACE_SCENEWIDE_BODY_H

#include "cspace/scenewide.h"

/* Node e visited: its inner children that meet [lo, hi] stacked, its
 * leaves that do pending. */
static inline void mkSw_Visit(const mkSwTree *t, mkSwWalk *w, int e, const float lo[3], const float hi[3])
{
	const mkSwNode *nd = &t->node[e];
	unsigned m = mkSwNode_Meet(nd, lo, hi), inner = m & ~nd->leaves;
	/* (at most MK_SW_WIDTH - 1 entries per level stay on the stack) */
	for (; inner; inner &= inner - 1) w->stack[w->top++] = nd->first[mkSw_Low(inner)];
	w->node = e;
	w->pend = m & nd->leaves;
}

static inline void mkSw_BeginBody(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3])
{
	w->top = 0;
	w->pend = 0;
	w->k = w->end = 0;
	if (t->nnode > 0) mkSw_Visit(t, w, 0, lo, hi);
}

static inline int mkSw_NextBody(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3], int *pos, int max)
{
	int n = 0;
	while (n < max) {
		if (w->k < w->end) {
			pos[n++] = w->k++;
			continue;
		}
		if (w->pend) { /* the next leaf of the node last visited */
			const mkSwNode *nd = &t->node[w->node];
			int k = mkSw_Low(w->pend);
			w->pend &= w->pend - 1;
			w->k = nd->first[k];
			w->end = w->k + nd->count[k];
			continue;
		}
		if (w->top == 0) break;
		mkSw_Visit(t, w, w->stack[--w->top], lo, hi);
	}
	return n;
}

#endif
