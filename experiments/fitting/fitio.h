/* fitio.h - the few services the fitting driver takes from outside its own
 * science: seeded random streams, the results file with its metadata
 * sidecar, and the --shard option. Kept behind these calls so that the
 * driver does not depend on how they are provided. */
#ifndef MK_FIT_IO_H
#define MK_FIT_IO_H

#include <stddef.h>
#include <stdint.h>

/* ---- random numbers ------------------------------------------------------ */
typedef struct mkFitRng { uint64_t s[4]; } mkFitRng;

/* The stream `stream` of the run `seed`; streams do not depend on each other. */
void mkFitRng_Seed(mkFitRng *rng, uint64_t seed, uint64_t stream);
/* U(0,1) in [0, 1). */
double mkFitRng_Unit(mkFitRng *rng);
/* U(a,b) = a + (b - a) U(0,1). */
double mkFitRng_Uniform(mkFitRng *rng, double a, double b);

/* ---- shards --------------------------------------------------------------- */
/* Parse "I/N" with 0 <= I < N <= 1000000. Returns 0, or -1 with a message
 * naming --shard and the allowed range. */
int mkFitShard_Parse(const char *text, int *index, int *count, char *msg, size_t msglen);
/* 1 when trial t belongs to shard index of count (trials dealt round robin). */
int mkFitShard_Owns(int index, int count, int trial);

/* ---- the results file ------------------------------------------------------ */
typedef struct mkFitOut mkFitOut;

/* What the sidecar records besides the machine, build and library facts. */
typedef struct mkFitRunInfo {
	const char *command; /* the command line, as run */
	uint64_t seed;
	int trials;
	const char *cases;   /* "1", "2", "3" or "all" */
	int shardIndex, shardCount;
} mkFitRunInfo;

/* Open the CSV at path (through a temporary file) and write the header.
 * Returns NULL with a message on failure. */
mkFitOut *mkFitOut_Open(const char *path, const char *const *columns, int count, char *msg, size_t msglen);
void mkFitOut_Str(mkFitOut *out, const char *text);
void mkFitOut_Int(mkFitOut *out, long long v);
void mkFitOut_Double(mkFitOut *out, double v);
void mkFitOut_EndRow(mkFitOut *out);
/* Write the sidecar "<path>.meta" and publish both files. Returns 0, or -1
 * with a message (nothing is then published). Frees out either way. */
int mkFitOut_Commit(mkFitOut *out, const mkFitRunInfo *info, char *msg, size_t msglen);
/* Drop everything; frees out. */
void mkFitOut_Discard(mkFitOut *out);
/* 1 when a file exists at path. */
int mkFitOut_Exists(const char *path);

#endif
