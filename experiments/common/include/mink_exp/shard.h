/* mink_exp/shard.h - splitting a run's trials over independent jobs.
 *
 * "--shard I/N" (0 <= I < N) makes a driver run only its share of the
 * trials: the contiguous block [floor(I T / N), floor((I+1) T / N)) of the
 * trials 0 .. T-1. The blocks of I = 0 .. N-1 cover every trial exactly once
 * and in order, and each trial draws from its own random stream
 * (mink_exp/rng.h), so concatenating the shards' CSV rows in shard order
 * (one header) reproduces the unsplit run row for row. I is 0-based, like a
 * Slurm job array declared as --array=0-(N-1). */
#ifndef MINK_EXP_SHARD_H
#define MINK_EXP_SHARD_H

#include <stddef.h>

#define MK_SHARD_MAX 1000000

typedef struct mkShard { int index, count; } mkShard;

/* The whole run: 0/1. */
mkShard mkShard_All(void);

/* Parse "I/N" with 1 <= N <= MK_SHARD_MAX and 0 <= I < N (decimal, no
 * blanks or signs). Returns 0, or -1 and a one-line message naming `flag`
 * and the allowed form. */
int mkShard_Parse(const char *text, const char *flag, mkShard *out, char *msg, size_t msglen);

/* The trials [*begin, *end) of this shard out of `total` (total >= 0). */
void mkShard_Range(mkShard shard, long total, long *begin, long *end);

#endif
