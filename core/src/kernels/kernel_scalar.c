/* kernel_scalar.c - the scalar reference build of the kernels (libm), and
 * the single-shape maps that the public per-point API uses. */
#include <math.h>
#include <stddef.h>

#include "kernels/kernel.h"

#define KV double
#define KM int
#define KW 1
#define KEXP exp
#define KLOG log
#define KSQRT sqrt
#define KABS fabs
#define KCOPYSIGN copysign
#define KSEL(m, a, b) ((m) ? (a) : (b))
#define KSPLAT(s) ((double)(s))
#define KALL(m) (m)
#define KLOAD(p) (*(p))
#define KSTORE(p, v) (*(p) = (v))
#define KFN(name) name##_scalar
#define KHALVES 1

#include "kernels/kernel_body.h"

void mkK2_Surface(const mkKShape2 *s, double u1, double u2, double *x, double *m)
{
	se_surface_scalar(s, &u1, &u2, &x[0], &x[1], &m[0], &m[1]);
}

void mkK2_Support(const mkKShape2 *s, double d1, double d2, double *x)
{
	se_support_scalar(s, &d1, &d2, &x[0], &x[1]);
}

void mkK2_GradInv(const mkKShape2 *s, double m1, double m2, double *x)
{
	se_gradinv_scalar(s, &m1, &m2, &x[0], &x[1]);
}

void mkK3_Surface(const mkKShape3 *s, double u1, double u2, double u3, double *x, double *m)
{
	sq_surface_scalar(s, &u1, &u2, &u3, &x[0], &x[1], &x[2], &m[0], &m[1], &m[2]);
}

void mkK3_Support(const mkKShape3 *s, double d1, double d2, double d3, double *x)
{
	sq_support_scalar(s, &d1, &d2, &d3, &x[0], &x[1], &x[2]);
}

void mkK3_GradInv(const mkKShape3 *s, double m1, double m2, double m3, double *x)
{
	sq_gradinv_scalar(s, &m1, &m2, &m3, &x[0], &x[1], &x[2]);
}

void mkK2_GradInvLogs(const mkKShape2 *s, double m1, double m2, double *l)
{
	se_gradinv_logs_scalar(s, &m1, &m2, &l[0], &l[1]);
}

void mkK3_GradInvLogs(const mkKShape3 *s, double m1, double m2, double m3, double *l)
{
	sq_gradinv_logs_scalar(s, &m1, &m2, &m3, &l[0], &l[1], &l[2], &l[3]);
}
