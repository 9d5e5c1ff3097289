/* kernel_scalarf.h - the scalar reference of the single-precision tier:
 * kernel_body.h over one float per lane with the C library's float
 * functions (expf, logf). The vector builds (kernel_f32_avx2.c,
 * kernel_f32_avx512.c) are tested against it. Included by
 * kernel_f32_scalar.c (double arrays) and, with MK_F32_FLOATIO defined, by
 * kernel_f32io_scalar.c (float arrays). */
#include <math.h>
#include <stddef.h>

#include "kernels/kernel_f32.h"

#ifndef MK_F32_FLOATIO
/* Normalise (x, y[, z]) in double, as kernel_body.h's double builds do, then
 * round to float. */
static inline void mkF1_unit2(const double *px, const double *py, float *u1, float *u2)
{
	double x = *px, y = *py;
	if (!(fabs(x * x + y * y - 1.0) <= MK_F32_UNIT_TOL)) {
		double m = fmax(fabs(x), fabs(y));
		double v1 = x / m, v2 = y / m;
		double inv = 1.0 / sqrt(v1 * v1 + v2 * v2);
		x = v1 * inv; y = v2 * inv;
	}
	*u1 = (float)x; *u2 = (float)y;
}

static inline void mkF1_unit3(const double *px, const double *py, const double *pz, float *u1, float *u2, float *u3)
{
	double x = *px, y = *py, z = *pz;
	if (!(fabs(x * x + y * y + z * z - 1.0) <= MK_F32_UNIT_TOL)) {
		double m = fmax(fmax(fabs(x), fabs(y)), fabs(z));
		double v1 = x / m, v2 = y / m, v3 = z / m;
		double inv = 1.0 / sqrt(v1 * v1 + v2 * v2 + v3 * v3);
		x = v1 * inv; y = v2 * inv; z = v3 * inv;
	}
	*u1 = (float)x; *u2 = (float)y; *u3 = (float)z;
}
#endif

#define KV float
#define KM int
#define KW 1
#define KEXP expf
#define KLOG logf
#define KSQRT sqrtf
#define KABS fabsf
#define KCOPYSIGN copysignf
#define KSEL(m, a, b) ((m) ? (a) : (b))
#define KSPLAT(s) ((float)(s))
#define KALL(m) (m)
#ifdef MK_F32_FLOATIO
#  define KLOAD(p) (*(p))
#  define KSTORE(p, v) (*(p) = (v))
#  define KFN(name) name##_f32io_scalar
#else
#  define KLOAD(p) ((float)*(p))
#  define KSTORE(p, v) (*(p) = (double)(v))
#  define KLOAD_UNIT2(s, px, py, u1, u2) mkF1_unit2((px) + (s), (py) + (s), &(u1), &(u2))
#  define KLOAD_UNIT3(s, px, py, pz, u1, u2, u3) mkF1_unit3((px) + (s), (py) + (s), (pz) + (s), &(u1), &(u2), &(u3))
#  define KFN(name) name##_f32_scalar
#endif

#include "kernels/kernel_body.h"
