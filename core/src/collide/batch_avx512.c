/* batch_avx512.c - batch_x86.h and batch_newton.h for 8 lanes (AVX-512F). */
#include <string.h>
#define MK_BX_W 8
#include "collide/batch_x86.h"
#include "collide/batch_newton.h"

void mkBatch_EllipsoidLanesAvx512(const mkBatchEllIn *in, mkBatchEllOut *out)
{
	mkBN_Run(in, out);
}
