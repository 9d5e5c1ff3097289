/* sceneprep_avx512.c - sceneprep_body.h built for AVX-512F. */
#include "cspace/sceneprep_body.h"

#include <immintrin.h>

void mkSqPrep_RunAvx512(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, mkSqPrep *out)
{
	mkSqPrep_Body(poses, n, parts, t, half, M, abc, ell, out);
}

long mkSqPrep_FirstBadAvx512(const double *poses, long n)
{
	return mkSqPrep_FirstBadBody(poses, n);
}

uint32_t mkSqPrep_NearAvx512(const double *x, const double *y, const double *z, const double *r, int n,
	const double c[3], double prad, double b)
{
	__m512d cx = _mm512_set1_pd(c[0]), cy = _mm512_set1_pd(c[1]), cz = _mm512_set1_pd(c[2]);
	__m512d pr = _mm512_set1_pd(prad), bb = _mm512_set1_pd(b), k = _mm512_set1_pd(1.0 + 1e-12);
	uint32_t m = 0;
	for (int i = 0; i < n; i += 8) {
		__mmask8 in = n - i >= 8 ? (__mmask8)0xFF : (__mmask8)((1u << (n - i)) - 1u);
		__m512d dx = _mm512_sub_pd(cx, _mm512_maskz_loadu_pd(in, x + i));
		__m512d dy = _mm512_sub_pd(cy, _mm512_maskz_loadu_pd(in, y + i));
		__m512d dz = _mm512_sub_pd(cz, _mm512_maskz_loadu_pd(in, z + i));
		__m512d rr = _mm512_mul_pd(_mm512_add_pd(_mm512_add_pd(pr, _mm512_maskz_loadu_pd(in, r + i)), bb), k);
		__m512d d2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
		__mmask8 apart = _mm512_cmp_pd_mask(d2, _mm512_mul_pd(rr, rr), _CMP_GT_OQ);
		m |= (uint32_t)(uint8_t)(~apart & in) << i;
	}
	return m;
}
