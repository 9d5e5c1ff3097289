/* rng.c - splitmix64 and xoshiro256**, written from the published
 * descriptions (prng.di.unimi.it). */
#include "mink_exp/rng.h"

#include <assert.h>

static uint64_t mkRotl(uint64_t x, int k)
{
	return (x << k) | (x >> (64 - k));
}

uint64_t mkSplitMix64(uint64_t *state)
{
	uint64_t z = (*state += UINT64_C(0x9E3779B97F4A7C15));
	z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
	z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
	return z ^ (z >> 31);
}

void mkRng_Seed(mkRng *rng, uint64_t seed, uint64_t stream)
{
	uint64_t mix = stream;
	uint64_t state = seed ^ mkSplitMix64(&mix);
	for (int i = 0; i < 4; ++i)
		rng->s[i] = mkSplitMix64(&state);
}

void mkRng_SetState(mkRng *rng, uint64_t s0, uint64_t s1, uint64_t s2, uint64_t s3)
{
	assert((s0 | s1 | s2 | s3) != 0);
	rng->s[0] = s0;
	rng->s[1] = s1;
	rng->s[2] = s2;
	rng->s[3] = s3;
}

uint64_t mkRng_Next(mkRng *rng)
{
	uint64_t *s = rng->s;
	const uint64_t result = mkRotl(s[1] * 5, 7) * 9;
	const uint64_t t = s[1] << 17;
	s[2] ^= s[0];
	s[3] ^= s[1];
	s[1] ^= s[2];
	s[0] ^= s[3];
	s[2] ^= t;
	s[3] = mkRotl(s[3], 45);
	return result;
}

double mkRng_Unit(mkRng *rng)
{
	/* 2^-53 times a 53-bit integer: exact in double. */
	return (double)(mkRng_Next(rng) >> 11) * 0x1.0p-53;
}

double mkRng_Uniform(mkRng *rng, double a, double b)
{
	return a + (b - a) * mkRng_Unit(rng);
}
