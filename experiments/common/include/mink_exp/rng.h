/* mink_exp/rng.h - the seeded random numbers of every experiment.
 *
 * Generator: xoshiro256** 1.0 (Blackman & Vigna, 2018), a 256-bit state with
 * period 2^256 - 1 that passes BigCrush; its state is filled by splitmix64
 * (Steele, Lea & Flood, 2014), as its authors recommend.
 *
 * Streams. A run is identified by one 64-bit seed. Each trial draws from its
 * own stream, seeded from (seed, stream) alone, so that a trial's numbers do
 * not depend on which other trials ran before it: a run split into shards
 * (mink_exp/shard.h) gives exactly the rows of the unsplit run. Drivers use
 * stream = (dimension << 32) | trial, or any other documented injective map.
 *
 * Uniform doubles take the top 53 bits of one output: U(0,1) is in [0, 1),
 * on the grid k 2^-53, and U(a,b) = a + (b - a) U(0,1). */
#ifndef MINK_EXP_RNG_H
#define MINK_EXP_RNG_H

#include <stdint.h>

typedef struct mkRng { uint64_t s[4]; } mkRng;

/* One step of splitmix64: advance *state by the golden-ratio increment and
 * return the mixed value. */
uint64_t mkSplitMix64(uint64_t *state);

/* Seed the stream `stream` of the run `seed`: the four state words are
 * consecutive splitmix64 outputs from the start value
 * seed ^ mix(stream), where mix is one splitmix64 step from `stream`. A state
 * of all zeros (which xoshiro cannot leave) cannot result: splitmix64 is a
 * bijection of consecutive distinct counters, so its four outputs are never
 * all zero. */
void mkRng_Seed(mkRng *rng, uint64_t seed, uint64_t stream);

/* Set the state directly (tests against the published reference outputs).
 * The state must not be all zero. */
void mkRng_SetState(mkRng *rng, uint64_t s0, uint64_t s1, uint64_t s2, uint64_t s3);

/* Next 64 random bits. */
uint64_t mkRng_Next(mkRng *rng);

/* U(0,1) in [0, 1) with 53 random bits. */
double mkRng_Unit(mkRng *rng);

/* U(a,b): a + (b - a) * U(0,1); in [a, b) up to the rounding of that
 * expression (a == b gives a). */
double mkRng_Uniform(mkRng *rng, double a, double b);

#endif
