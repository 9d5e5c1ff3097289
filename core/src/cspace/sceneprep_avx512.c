/* sceneprep_avx512.c - sceneprep_body.h built for AVX-512F. */
#include "cspace/sceneprep_body.h"

#include <immintrin.h>

void mkSqPrep_RunAvx512(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *spheres, mkSqPrep *out)
{
	mkSqPrep_Body(poses, n, parts, t, half, M, abc, ell, spheres, out);
}

long mkSqPrep_FirstBadAvx512(const double *poses, long n)
{
	return mkSqPrep_FirstBadBody(poses, n);
}

/* (full chunks by plain loads and only the tail masked: masked loads are dearer on some CPUs;
 * docs/notes.md) */
static inline __mmask8 mkSqPrep_Apart8(__m512d cx, __m512d cy, __m512d cz, __m512d X, __m512d Y, __m512d Z, __m512d rr2)
{
	__m512d dx = _mm512_sub_pd(cx, X), dy = _mm512_sub_pd(cy, Y), dz = _mm512_sub_pd(cz, Z);
	__m512d d2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
	return _mm512_cmp_pd_mask(d2, rr2, _CMP_GT_OQ);
}

uint32_t mkSqPrep_NearAvx512(const double *x, const double *y, const double *z, const double *rr, int n, const double c[3])
{
	__m512d cx = _mm512_set1_pd(c[0]), cy = _mm512_set1_pd(c[1]), cz = _mm512_set1_pd(c[2]);
	uint32_t m = 0;
	int i = 0;
	for (; i + 8 <= n; i += 8)
		m |= (uint32_t)(uint8_t)~mkSqPrep_Apart8(cx, cy, cz, _mm512_loadu_pd(x + i), _mm512_loadu_pd(y + i), _mm512_loadu_pd(z + i),
			_mm512_loadu_pd(rr + i)) << i;
	if (i < n) {
		__mmask8 in = (__mmask8)((1u << (n - i)) - 1u);
		__mmask8 apart = mkSqPrep_Apart8(cx, cy, cz, _mm512_maskz_loadu_pd(in, x + i), _mm512_maskz_loadu_pd(in, y + i),
			_mm512_maskz_loadu_pd(in, z + i), _mm512_maskz_loadu_pd(in, rr + i));
		m |= (uint32_t)(uint8_t)(~apart & in) << i;
	}
	return m;
}
