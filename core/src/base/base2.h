/* base2.h - two base-2 elementary functions, inline, for the superquadric
 * pair pass of the collision solver (collide/pair.h, mkSupBody_EvalHess2):
 *
 *   mkExp2(x)        2^x, within 0.52 ulp for normal results (0.509 the
 *                    largest core.ref.base2 meets; glibc's exp2 0.507);
 *   mkSoftplus2(x)   log2(1 + 2^x) for x <= 0, within 2.2e-16 absolute
 *                    (1.96e-16 met; log2(1 + exp2(x)) by glibc 2.07e-16),
 *                    in one step instead of log2(1 + exp2(x)).
 *
 * Why not glibc's: the pass's nested norms chain a logarithm and an
 * exponential per stage, and with the rest of the pass cheap the calls
 * themselves weigh: the fused softplus is one table row and a degree-7
 * polynomial where exp2 then log2 are two dependent calls, and an inline
 * exp2 needs no call, so no live register is saved around it. The library
 * is built for baseline x86-64 (no FMA): both evaluate short Estrin trees
 * of multiplies and adds. core.ref.base2 checks both against 256-bit MPFR, and that the
 * tables (base2_tables.h, written by core/reference/tools/base2_tables.c)
 * are what the generator writes.
 *
 * Both assume the default rounding mode (round to nearest): they round by
 * adding 1.5 * 2^52 (scaled), which leaves the rounded integer in the low
 * bits of the sum. */
#ifndef MINK_BASE2_H
#define MINK_BASE2_H

#include <stdint.h>
#include <string.h>

#include "base/base2_tables.h"

_Static_assert(MK_EXP2_N == 128, "mkExp2_Core shifts by log2(MK_EXP2_N) = 7");

/* 2^x for -1000 < x < 1024: x = k / 128 + r with |r| <= 1/256, 2^x =
 * 2^floor(k / 128) T[k mod 128] (1 + p(r) + e) with p the degree-5 Taylor
 * polynomial of 2^r - 1 (error below 2^-60 relative) and e the table
 * entry's relative rounding. */
static inline double mkExp2_Core(double x)
{
	const double shift = 0x1.8p52 / MK_EXP2_N;
	double kd = x + shift;
	uint64_t ki;
	memcpy(&ki, &kd, sizeof ki);
	kd -= shift;
	double r = x - kd; /* exact */
	const double *T = mkExp2_Tab[ki % MK_EXP2_N];
	uint64_t sb;
	memcpy(&sb, &T[0], sizeof sb);
	/* adds floor(k / 128) to T's exponent (mod 2^64: k < 0 wraps) */
	sb += (ki & ~(uint64_t)(MK_EXP2_N - 1)) << (52 - 7);
	double scale;
	memcpy(&scale, &sb, sizeof scale);
	double r2 = r * r;
	double p = r * (MK_EXP2_C1 + r * MK_EXP2_C2) + (r * r2) * ((MK_EXP2_C3 + r * MK_EXP2_C4) + r2 * MK_EXP2_C5);
	return scale + scale * (p + T[1]);
}

/* 2^x for x < 1024 (NaN gives NaN, -inf and x < -1100 give 0; subnormal
 * results within 1 ulp). */
static inline double mkExp2(double x)
{
	if (x > -1000.0)
		return mkExp2_Core(x);
	if (x != x)
		return x;
	return x < -1100.0 ? 0.0 : mkExp2_Core(x + 128.0) * 0x1p-128;
}

/* log2(1 + 2^x) for x <= 0 (-0 included; NaN gives NaN), given t = 2^x
 * (which the caller has at hand). On (-MK_SP2_X, 0]: the row of the
 * segment containing x, a degree-7 polynomial in u = MK_SP2_W x - j,
 * evaluated by Estrin's scheme. Below, where t < 2^-16: the series
 * t (1 - t/2 + t^2/3) / ln 2, its first omitted term under 2^-48 of it.
 * x > 1 / (2 MK_SP2_W) would read outside the table: the callers' x is
 * q log2(k/m) with k <= m, or -q |l|. */
static inline double mkSoftplus2(double x, double t)
{
	if (!(x > -MK_SP2_X))
		return t * 1.4426950408889634 * (1.0 - t * (0.5 - t * (1.0 / 3.0)));
	/* j = -round(W x), from the low bits of W x + 1.5 * 2^52; u = W x + j is
	 * exact (W is a power of 2 and |u| <= 1/2 <= |W x| unless j = 0). */
	const double shift = 0x1.8p52;
	double wx = x * MK_SP2_W, k = wx + shift;
	uint64_t bits;
	memcpy(&bits, &k, sizeof bits);
	const double *c = mkSp2_Tab[(uint32_t)-(uint32_t)bits];
	double u = wx - (k - shift), u2 = u * u, u4 = u2 * u2;
	return (c[0] + c[1] * u + (c[2] + c[3] * u) * u2) + (c[4] + c[5] * u + (c[6] + c[7] * u) * u2) * u4;
}

#endif
