/* kernel_x86.h - the lane helpers of the x86 vector builds of kernel_body.h,
 * for GCC/Clang vector extensions over __m256d (AVX2) or __m512d (AVX-512F),
 * with SLEEF's 1-ulp exp/log/log1p. The including file defines MK_X86_W to 4
 * or 8 and is compiled with the matching -m flags. Contraction stays off, so
 * only the elementary functions differ from the scalar reference. */
#include <immintrin.h>
#include <stddef.h>
#include <string.h>
#include <sleef.h>

#include "kernels/kernel.h"

#if MK_X86_W == 4
typedef __m256d mkXV;
#  define KEXP Sleef_expd4_u10avx2
#  define KLOG Sleef_logd4_u10avx2
#  define KSQRT _mm256_sqrt_pd
#  define KFN(name) name##_avx2
#elif MK_X86_W == 8
typedef __m512d mkXV;
#  define KEXP Sleef_expd8_u10avx512f
#  define KLOG Sleef_logd8_u10avx512f
#  define KSQRT _mm512_sqrt_pd
#  define KFN(name) name##_avx512
#else
#  error "MK_X86_W must be 4 or 8"
#endif

typedef long long mkXM __attribute__((vector_size(8 * MK_X86_W)));

#define MK_XABSMASK ((mkXM){0} + 0x7fffffffffffffffLL)

static inline mkXV mkX_abs(mkXV v) { return (mkXV)((mkXM)v & MK_XABSMASK); }
static inline mkXV mkX_copysign(mkXV m, mkXV s)
{
	return (mkXV)(((mkXM)m & MK_XABSMASK) | ((mkXM)s & ~MK_XABSMASK));
}
static inline mkXV mkX_sel(mkXM k, mkXV a, mkXV b) { return (mkXV)(((mkXM)a & k) | ((mkXM)b & ~k)); }
static inline int mkX_all(mkXM k)
{
	long long acc = -1;
	for (int i = 0; i < MK_X86_W; ++i) acc &= k[i];
	return acc != 0;
}
static inline mkXV mkX_load(const double *p) { mkXV v; memcpy(&v, p, sizeof v); return v; }
static inline void mkX_store(double *p, mkXV v) { memcpy(p, &v, sizeof v); }

#define KV mkXV
#define KM mkXM
#define KW MK_X86_W
#define KABS mkX_abs
#define KCOPYSIGN mkX_copysign
#define KSEL mkX_sel
#define KSPLAT(s) ((mkXV){0} + (double)(s))
#define KALL mkX_all
#define KLOAD mkX_load
#define KSTORE mkX_store
/* Lane vectors interleaved per block (see kernel_body.h): four independent
 * chains of SLEEF calls keep the out-of-order core busy; more add spills. */
#ifndef MK_X86_P
#  define MK_X86_P 4
#endif
#define KP MK_X86_P
#define KHALVES 1 /* the double builds have the halves of a batch */

#include "kernels/kernel_body.h"
