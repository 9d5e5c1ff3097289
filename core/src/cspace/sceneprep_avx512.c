/* sceneprep_avx512.c - sceneprep_body.h built for AVX-512F. */
#include "cspace/sceneprep_body.h"

void mkSqPrep_RunAvx512(const double *poses, int n, int parts, const mkVec3 *t, const double *half, mkSqPrep *out)
{
	mkSqPrep_Body(poses, n, parts, t, half, out);
}

long mkSqPrep_FirstBadAvx512(const double *poses, long n)
{
	return mkSqPrep_FirstBadBody(poses, n);
}
