/* mink_exp/meta.h - the metadata sidecar "<results>.meta" of every results
 * file: where, when, how and from what the numbers were made.
 *
 * Format: one "key: value" line per key, keys in [a-z0-9_], values on one
 * line (line breaks in a value are written as spaces), in the order set.
 *
 * mkMeta_Init records what the program can find out itself:
 *   experiment, schema_version       (from the driver)
 *   date_utc                         start of the run, ISO 8601
 *   command_line                     argv (the program by its file name),
 *                                    shell-quoted where needed
 *   cpu_model, cpu_count, os         /proc/cpuinfo, sysconf, uname
 *   compiler, compiler_flags, build_type   of this build (CMake)
 *   git_commit, git_dirty            of the source tree at the last build
 *                                    ("unknown" outside a git checkout)
 *   mink_version                     mkVersion() of the linked core
 *   sleef_version                    SLEEF the core was built with, or "none"
 *   shard                            "0/1" until the driver sets its own
 * The driver must add seed and trials (mkMeta_Write fails without them) and
 * whatever else defines its run (draws, sizes, forms). A driver that links
 * CGAL, GMP or MPFR adds cgal_version, gmp_version, mpfr_version.
 * mkCsv_Commit adds rows; mkMeta_Write adds finished_utc and wall_seconds. */
#ifndef MINK_EXP_META_H
#define MINK_EXP_META_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define MK_META_MAX_KEYS 96

/* The keys every sidecar has. */
#define MK_META_REQUIRED_KEYS \
	"experiment", "schema_version", "date_utc", "finished_utc", "wall_seconds", \
	"command_line", "cpu_model", "cpu_count", "os", "compiler", "compiler_flags", \
	"build_type", "git_commit", "git_dirty", "mink_version", "sleef_version", \
	"shard", "seed", "trials", "rows"

typedef struct mkMeta {
	int count;
	char *keys[MK_META_MAX_KEYS];
	char *values[MK_META_MAX_KEYS];
	double start; /* monotonic clock at init, seconds */
	int overflow; /* a key did not fit; makes writing fail */
} mkMeta;

/* Start a record and fill in what the program can find out itself (see
 * above). argv may be NULL when argc is 0. */
void mkMeta_Init(mkMeta *meta, const char *experiment, int schema_version, int argc, char **argv);
/* An empty record (for mkMeta_ReadFile). */
void mkMeta_InitEmpty(mkMeta *meta);
void mkMeta_Free(mkMeta *meta);

/* Set or replace a key. Keys outside [a-z0-9_] are a program error
 * (asserted). */
void mkMeta_Set(mkMeta *meta, const char *key, const char *value);
void mkMeta_SetInt(mkMeta *meta, const char *key, long long value);
void mkMeta_SetU64(mkMeta *meta, const char *key, uint64_t value);
void mkMeta_SetDouble(mkMeta *meta, const char *key, double value);
/* Drop a key (nothing when it is not set); the others keep their order.
 * For a driver whose shards are not blocks of trials: it replaces the
 * harness's trial_range by its own account. */
void mkMeta_Remove(mkMeta *meta, const char *key);
/* Set several text keys in order: pairs[i][0] the key, pairs[i][1] its value
 * (a driver's fixed description of its run). */
void mkMeta_SetPairs(mkMeta *meta, const char *const pairs[][2], int count);
/* The value, or NULL when the key is not set. */
const char *mkMeta_Get(const mkMeta *meta, const char *key);

/* The first required key (MK_META_REQUIRED_KEYS) that is not set, or NULL.
 * finished_utc and wall_seconds are exempt: writing adds them. */
const char *mkMeta_Missing(const mkMeta *meta);

/* Add finished_utc and wall_seconds and write every line to fp. Fails (-1,
 * message) when a required key is missing or too many keys were set. */
int mkMeta_Write(mkMeta *meta, FILE *fp, char *msg, size_t msglen);

/* Read a sidecar back (tests, tools). The record must be initialised
 * (mkMeta_InitEmpty); keys read are added to it. Returns 0, or -1 with a
 * message on an unreadable file or a line that is not "key: value". */
int mkMeta_ReadFile(mkMeta *meta, const char *path, char *msg, size_t msglen);

/* The current UTC time as ISO 8601 ("2022-01-31T12:00:00Z") into buf. */
void mkMeta_UtcNow(char *buf, size_t len);

#endif
