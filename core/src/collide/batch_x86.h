/* batch_x86.h - the support points of eight superquadrics at eight
 * directions in vector lanes, for the lock-step searches of batch.c: the
 * nested norm |(|(p1, p2)|_q2, p3)|_q1 at p = P^T y and its gradient
 * weights, each pair norm from the ratio r of the smaller to the larger
 * component (t = r^q, |.|_q = m (1 + t)^(1/q), weights (1 + t)^(1/q) /
 * (1 + t) and t / r times that), s = P (w_out,1 sg1 w_in,1, w_out,1 sg2
 * w_in,2, sg3 w_out,2): the same formulas as the scalar support map
 * (collide/support.h), with SLEEF's 1-ulp exp2 and log2. The including unit
 * defines MK_BX_W (4: AVX2, 8: AVX-512F) and is compiled with the matching
 * -m flags; contraction stays off. The lane primitives (mkB_*) also serve
 * the ellipsoids' Newton lanes (batch_newton.h). */
#include <immintrin.h>
#include <sleef.h>

#include "collide/collision_impl.h"

#if MK_BX_W == 4
typedef __m256d mkBV;
#  define MK_BEXP2 Sleef_exp2d4_u10avx2
#  define MK_BLOG2 Sleef_log2d4_u10avx2
#  define MK_BFN(name) name##Avx2
#elif MK_BX_W == 8
typedef __m512d mkBV;
#  define MK_BEXP2 Sleef_exp2d8_u10avx512f
#  define MK_BLOG2 Sleef_log2d8_u10avx512f
#  define MK_BFN(name) name##Avx512
#else
#  error "MK_BX_W must be 4 or 8"
#endif

typedef long long mkBM __attribute__((vector_size(8 * MK_BX_W)));

static inline mkBV mkB_Load(const double *p)
{
	mkBV v;
	memcpy(&v, p, sizeof v);
	return v;
}
static inline mkBV mkB_Sel(mkBM k, mkBV a, mkBV b) { return (mkBV)(((mkBM)a & k) | ((mkBM)b & ~k)); }
static inline mkBV mkB_Abs(mkBV v) { return (mkBV)((mkBM)v & ((mkBM){ 0 } + 0x7fffffffffffffffLL)); }
static inline mkBV mkB_Splat(double x) { return (mkBV){ 0 } + x; }
static inline void mkB_Store(double *p, mkBV v) { memcpy(p, &v, sizeof v); }
static inline mkBM mkB_Lt(mkBV a, mkBV b) { return (mkBM)(a < b); }
static inline mkBM mkB_Le(mkBV a, mkBV b) { return (mkBM)(a <= b); }
static inline int mkB_Any(mkBM k)
{
	long long a[MK_BX_W], r = 0;
	memcpy(a, &k, sizeof a);
	for (int i = 0; i < MK_BX_W; ++i)
		r |= a[i];
	return r != 0;
}
#if MK_BX_W == 4
static inline mkBV mkB_Sqrt(mkBV v) { return _mm256_sqrt_pd(v); }
#else
static inline mkBV mkB_Sqrt(mkBV v) { return _mm512_sqrt_pd(v); }
#endif

/* A pair norm's weights of (a, b), a, b >= 0, exponent q (iq = 1 / q):
 * *norm, *wa, *wb. */
static inline void mkB_PairNorm(mkBV a, mkBV b, mkBV q, mkBV iq, mkBV *norm, mkBV *wa, mkBV *wb)
{
	mkBM big = a >= b;
	mkBV zero = mkB_Splat(0.0), one = mkB_Splat(1.0);
	mkBV m = mkB_Sel(big, a, b), k = mkB_Sel(big, b, a);
	mkBV r = mkB_Sel(m > zero, k / m, zero);
	mkBV t = MK_BEXP2(q * MK_BLOG2(r)); /* r = 0: exp2(-inf) = 0 */
	mkBV opt = one + t, irm = MK_BEXP2(iq * MK_BLOG2(opt));
	mkBV wm = irm / opt, wk = mkB_Sel(r > zero, t / r * wm, zero);
	*norm = m * irm;
	*wa = mkB_Sel(big, wm, wk);
	*wb = mkB_Sel(big, wk, wm);
}

void MK_BFN(mkBatch_SupportLanes)(const mkBatchLanesIn *in, double s[3][MK_BATCH_VLANES])
{
	for (int o = 0; o < MK_BATCH_VLANES; o += MK_BX_W) {
		mkBV y[3], p[3], P[9], sg[3];
		for (int i = 0; i < 3; ++i)
			y[i] = mkB_Load(in->y[i] + o);
		for (int i = 0; i < 9; ++i)
			P[i] = mkB_Load(in->P[i] + o);
		for (int j = 0; j < 3; ++j) {
			p[j] = P[j] * y[0] + P[3 + j] * y[1] + P[6 + j] * y[2];
			sg[j] = mkB_Sel(p[j] < mkB_Splat(0.0), mkB_Splat(-1.0), mkB_Splat(1.0));
		}
		mkBV nin, wu, wv, nout, win, ww;
		mkB_PairNorm(mkB_Abs(p[0]), mkB_Abs(p[1]), mkB_Load(in->q2 + o), mkB_Load(in->iq2 + o), &nin, &wu, &wv);
		mkB_PairNorm(nin, mkB_Abs(p[2]), mkB_Load(in->q1 + o), mkB_Load(in->iq1 + o), &nout, &win, &ww);
		mkBV g0 = win * sg[0] * wu, g1 = win * sg[1] * wv, g2 = sg[2] * ww;
		for (int i = 0; i < 3; ++i) {
			mkBV si = P[3 * i] * g0 + P[3 * i + 1] * g1 + P[3 * i + 2] * g2;
			memcpy(s[i] + o, &si, sizeof si);
		}
	}
}
