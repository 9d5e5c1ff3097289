/* sceneprep_avx2.c - sceneprep_body.h built for AVX2. */
#include "cspace/sceneprep_body.h"

#include <immintrin.h>

void mkSqPrep_RunAvx2(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *spheres, mkSqPrep *out)
{
	mkSqPrep_Body(poses, n, parts, t, half, M, abc, ell, spheres, out);
}

long mkSqPrep_FirstBadAvx2(const double *poses, long n)
{
	return mkSqPrep_FirstBadBody(poses, n);
}

uint32_t mkSqPrep_NearAvx2(const double *x, const double *y, const double *z, const double *rr, int n, const double c[3])
{
	__m256d cx = _mm256_set1_pd(c[0]), cy = _mm256_set1_pd(c[1]), cz = _mm256_set1_pd(c[2]);
	uint32_t m = 0;
	int i = 0;
	for (; i + 4 <= n; i += 4) {
		__m256d dx = _mm256_sub_pd(cx, _mm256_loadu_pd(x + i)), dy = _mm256_sub_pd(cy, _mm256_loadu_pd(y + i));
		__m256d dz = _mm256_sub_pd(cz, _mm256_loadu_pd(z + i));
		__m256d d2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
		m |= (uint32_t)(~_mm256_movemask_pd(_mm256_cmp_pd(d2, _mm256_loadu_pd(rr + i), _CMP_GT_OQ)) & 15) << i;
	}
	for (; i < n; ++i) {
		double dx = c[0] - x[i], dy = c[1] - y[i], dz = c[2] - z[i];
		m |= (uint32_t)!(dx * dx + dy * dy + dz * dz > rr[i]) << i;
	}
	return m;
}
