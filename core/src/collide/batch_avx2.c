/* batch_avx2.c - batch_x86.h and batch_newton.h for 4 lanes (AVX2). */
#include <string.h>
#define MK_BX_W 4
#include "collide/batch_x86.h"
#include "collide/batch_newton.h"

void mkBatch_EllipsoidLanesAvx2(const mkBatchEllIn *in, mkBatchEllOut *out)
{
	mkBN_Run(in, out);
}
