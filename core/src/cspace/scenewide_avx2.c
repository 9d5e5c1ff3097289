/* scenewide_avx2.c - the hierarchy's walk (scenewide_body.h) built for AVX2:
 * eight children per compare. */
#include "cspace/scenewide_body.h"

void mkSwWalk_BeginAvx2(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3])
{
	mkSw_BeginBody(t, w, lo, hi);
}

int mkSwWalk_NextAvx2(const mkSwTree *t, mkSwWalk *w, const float lo[3], const float hi[3], int *pos, int max)
{
	return mkSw_NextBody(t, w, lo, hi, pos, max);
}
