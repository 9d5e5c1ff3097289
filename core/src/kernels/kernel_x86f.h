/* kernel_x86f.h - the lane helpers of the single-precision x86 builds of
 * kernel_body.h: float lanes in __m256 (AVX2, 8 lanes) or __m512
 * (AVX-512F, 16 lanes) with SLEEF's 1-ulp float exp and 3.5-ulp float log.
 * The log's extra 2.5 ulp do not show in the tier's errors against MPFR
 * (the same maxima as with the 1-ulp log on every group of
 * core/reference/tests; docs/notes.md, Fast tiers), and it costs 0.6 of the
 * 1-ulp one per call; it is the only elementary function in SLEEF
 * with a faster float variant (exp has none). The including file
 * defines MK_X86F_W to 8 or 16 and is compiled with the matching -m flags.
 * Loads read doubles, normalise them in double (kernel_f32.h) and round to
 * float; stores widen to double. With MK_F32_FLOATIO (kernel_f32io_*.c)
 * they read and write the caller's floats instead. */
#include <immintrin.h>
#include <stddef.h>
#include <string.h>
#include <sleef.h>

#include "kernels/kernel_f32.h"

#if MK_X86F_W == 8
typedef __m256 mkFV;
typedef __m256d mkFD; /* half a lane vector, in double */
#  define MK_FD_W 4
#  define KEXP Sleef_expf8_u10avx2
#  define KLOG Sleef_logf8_u35avx2
#  define KSQRT _mm256_sqrt_ps
#  define MK_FD_SQRT _mm256_sqrt_pd
#  ifdef MK_F32_FLOATIO
#    define KFN(name) name##_f32io_avx2
#  else
#    define KFN(name) name##_f32_avx2
#  endif
static inline mkFV mkF_join(mkFD lo, mkFD hi) { return _mm256_set_m128(_mm256_cvtpd_ps(hi), _mm256_cvtpd_ps(lo)); }
static inline mkFD mkF_lo(mkFV v) { return _mm256_cvtps_pd(_mm256_castps256_ps128(v)); }
static inline mkFD mkF_hi(mkFV v) { return _mm256_cvtps_pd(_mm256_extractf128_ps(v, 1)); }
#elif MK_X86F_W == 16
typedef __m512 mkFV;
typedef __m512d mkFD;
#  define MK_FD_W 8
#  define KEXP Sleef_expf16_u10avx512f
#  define KLOG Sleef_logf16_u35avx512f
#  define KSQRT _mm512_sqrt_ps
#  define MK_FD_SQRT _mm512_sqrt_pd
#  ifdef MK_F32_FLOATIO
#    define KFN(name) name##_f32io_avx512
#  else
#    define KFN(name) name##_f32_avx512
#  endif
static inline mkFV mkF_join(mkFD lo, mkFD hi)
{
	__m512d w = _mm512_castps_pd(_mm512_castps256_ps512(_mm512_cvtpd_ps(lo)));
	return _mm512_castpd_ps(_mm512_insertf64x4(w, _mm256_castps_pd(_mm512_cvtpd_ps(hi)), 1));
}
static inline mkFD mkF_lo(mkFV v) { return _mm512_cvtps_pd(_mm512_castps512_ps256(v)); }
static inline mkFD mkF_hi(mkFV v)
{
	return _mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(v), 1)));
}
#else
#  error "MK_X86F_W must be 8 or 16"
#endif

typedef int mkFM __attribute__((vector_size(4 * MK_X86F_W)));
typedef long long mkFDM __attribute__((vector_size(8 * MK_FD_W)));

#define MK_FABSMASK ((mkFM){0} + 0x7fffffff)
#define MK_FDABSMASK ((mkFDM){0} + 0x7fffffffffffffffLL)

static inline mkFV mkF_abs(mkFV v) { return (mkFV)((mkFM)v & MK_FABSMASK); }
static inline mkFV mkF_copysign(mkFV m, mkFV s)
{
	return (mkFV)(((mkFM)m & MK_FABSMASK) | ((mkFM)s & ~MK_FABSMASK));
}
static inline mkFV mkF_sel(mkFM k, mkFV a, mkFV b) { return (mkFV)(((mkFM)a & k) | ((mkFM)b & ~k)); }
/* Every lane of a comparison mask set: one mask test instead of a loop over
 * the lanes (which the compiler keeps as lane extractions). */
static inline int mkF_all(mkFM k)
{
#if MK_X86F_W == 8
	return _mm256_movemask_ps(_mm256_castsi256_ps((__m256i)k)) == 0xFF;
#else
	return _mm512_test_epi32_mask((__m512i)k, (__m512i)k) == 0xFFFF;
#endif
}
static inline mkFD mkFD_load(const double *p) { mkFD v; memcpy(&v, p, sizeof v); return v; }
static inline void mkFD_store(double *p, mkFD v) { memcpy(p, &v, sizeof v); }
static inline mkFV mkF_load(const double *p) { return mkF_join(mkFD_load(p), mkFD_load(p + MK_FD_W)); }
static inline void mkF_store(double *p, mkFV v) { mkFD_store(p, mkF_lo(v)); mkFD_store(p + MK_FD_W, mkF_hi(v)); }

/* Double-precision helpers of the normalisation (as in kernel_x86.h). */
static inline mkFD mkFD_abs(mkFD v) { return (mkFD)((mkFDM)v & MK_FDABSMASK); }
static inline mkFD mkFD_sel(mkFDM k, mkFD a, mkFD b) { return (mkFD)(((mkFDM)a & k) | ((mkFDM)b & ~k)); }
static inline mkFD mkFD_max(mkFD a, mkFD b) { return mkFD_sel(a >= b, a, b); }
static inline int mkFD_all(mkFDM k)
{
#if MK_X86F_W == 8
	return _mm256_movemask_pd(_mm256_castsi256_pd((__m256i)k)) == 0xF;
#else
	return _mm512_test_epi64_mask((__m512i)k, (__m512i)k) == 0xFF;
#endif
}

/* Half a lane vector of parameter vectors, made unit length in double. */
static inline void mkFD_unit2(mkFD *x, mkFD *y)
{
	mkFDM unit = mkFD_abs(*x * *x + *y * *y - 1.0) <= MK_F32_UNIT_TOL;
	if (mkFD_all(unit)) return;
	mkFD m = mkFD_max(mkFD_abs(*x), mkFD_abs(*y));
	mkFD v1 = *x / m, v2 = *y / m;
	mkFD inv = 1.0 / MK_FD_SQRT(v1 * v1 + v2 * v2);
	*x = mkFD_sel(unit, *x, v1 * inv);
	*y = mkFD_sel(unit, *y, v2 * inv);
}

static inline void mkFD_unit3(mkFD *x, mkFD *y, mkFD *z)
{
	mkFDM unit = mkFD_abs(*x * *x + *y * *y + *z * *z - 1.0) <= MK_F32_UNIT_TOL;
	if (mkFD_all(unit)) return;
	mkFD m = mkFD_max(mkFD_max(mkFD_abs(*x), mkFD_abs(*y)), mkFD_abs(*z));
	mkFD v1 = *x / m, v2 = *y / m, v3 = *z / m;
	mkFD inv = 1.0 / MK_FD_SQRT(v1 * v1 + v2 * v2 + v3 * v3);
	*x = mkFD_sel(unit, *x, v1 * inv);
	*y = mkFD_sel(unit, *y, v2 * inv);
	*z = mkFD_sel(unit, *z, v3 * inv);
}

static inline void mkF_load_unit2(const double *px, const double *py, mkFV *u1, mkFV *u2)
{
	mkFD x0 = mkFD_load(px), y0 = mkFD_load(py), x1 = mkFD_load(px + MK_FD_W), y1 = mkFD_load(py + MK_FD_W);
	mkFD_unit2(&x0, &y0);
	mkFD_unit2(&x1, &y1);
	*u1 = mkF_join(x0, x1);
	*u2 = mkF_join(y0, y1);
}

static inline void mkF_load_unit3(const double *px, const double *py, const double *pz, mkFV *u1, mkFV *u2, mkFV *u3)
{
	mkFD x0 = mkFD_load(px), y0 = mkFD_load(py), z0 = mkFD_load(pz);
	mkFD x1 = mkFD_load(px + MK_FD_W), y1 = mkFD_load(py + MK_FD_W), z1 = mkFD_load(pz + MK_FD_W);
	mkFD_unit3(&x0, &y0, &z0);
	mkFD_unit3(&x1, &y1, &z1);
	*u1 = mkF_join(x0, x1);
	*u2 = mkF_join(y0, y1);
	*u3 = mkF_join(z0, z1);
}

#define KV mkFV
#define KM mkFM
#define KW MK_X86F_W
#define KABS mkF_abs
#define KCOPYSIGN mkF_copysign
#define KSEL mkF_sel
#define KSPLAT(s) ((mkFV){0} + (float)(s))
#define KALL mkF_all
#ifdef MK_F32_FLOATIO
/* Float arrays: plain loads and stores; kernel_body.h's unit test and
 * normalisation run on the float lanes. */
static inline mkFV mkF_loadf(const float *p) { mkFV v; memcpy(&v, p, sizeof v); return v; }
static inline void mkF_storef(float *p, mkFV v) { memcpy(p, &v, sizeof v); }
#  define KLOAD mkF_loadf
#  define KSTORE mkF_storef
#else
#  define KLOAD mkF_load
#  define KSTORE mkF_store
#  define KLOAD_UNIT2(s, px, py, u1, u2) mkF_load_unit2((px) + (s), (py) + (s), &(u1), &(u2))
#  define KLOAD_UNIT3(s, px, py, pz, u1, u2, u3) \
	mkF_load_unit3((px) + (s), (py) + (s), (pz) + (s), &(u1), &(u2), &(u3))
#endif
#ifndef MK_X86F_P
#  define MK_X86F_P 4
#endif
#define KP MK_X86F_P
/* 1/sqrt(v) for the ellipse and ellipsoid support points: the hardware
 * estimate (relative error below 2^-14 with AVX-512's rsqrt14, 1.5 * 2^-12
 * with AVX's rsqrt) and one Newton step, y (3 - v y^2) / 2, which squares the
 * estimate's error (below 1e-8, resp. 2e-7 before rounding) instead of a square
 * root and a division, the two slowest instructions of those kernels. */
static inline mkFV mkF_rsqrt(mkFV v)
{
#if MK_X86F_W == 8
	mkFV y = _mm256_rsqrt_ps(v);
#else
	mkFV y = _mm512_rsqrt14_ps(v);
#endif
	return (0.5f * y) * (3.0f - (v * y) * y);
}
#define KRSQRT mkF_rsqrt

#include "kernels/kernel_body.h"
