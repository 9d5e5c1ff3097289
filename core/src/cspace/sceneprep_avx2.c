/* sceneprep_avx2.c - sceneprep_body.h built for AVX2. */
#include "cspace/sceneprep_body.h"

void mkSqPrep_RunAvx2(const double *poses, int n, int parts, const mkVec3 *t, const double *half, mkSqPrep *out)
{
	mkSqPrep_Body(poses, n, parts, t, half, out);
}

long mkSqPrep_FirstBadAvx2(const double *poses, long n)
{
	return mkSqPrep_FirstBadBody(poses, n);
}
