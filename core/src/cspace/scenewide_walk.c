/* scenewide_walk.c - the box query's walk of the hierarchy
 * (cspace/scenewide.h): its portable build (SSE: four children per
 * compare) and the choice of the AVX2 build (scenewide_avx2.c) where the
 * tree says the CPU runs it. */
#include "cspace/scenewide_body.h"

void mkSwWalk_Begin(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3])
{
#if defined(MINK_HAVE_X86_KERNELS)
	if (t->avx) {
		mkSwWalk_BeginAvx2(t, w, lo, hi);
		return;
	}
#endif
	mkSw_BeginBody(t, w, lo, hi);
}

int mkSwWalk_Next(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3], int *pos, int max)
{
#if defined(MINK_HAVE_X86_KERNELS)
	if (t->avx) return mkSwWalk_NextAvx2(t, w, lo, hi, pos, max);
#endif
	return mkSw_NextBody(t, w, lo, hi, pos, max);
}
