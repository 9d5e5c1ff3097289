/* fitio.c - random streams, shards and results files for the fitting driver.
 *
 * The random streams follow the project's convention (xoshiro256** seeded
 * by splitmix64 from seed ^ mix(stream)), so rows do not change with the
 * provider of these services. */
#define _POSIX_C_SOURCE 200809L
#include "fitio.h"

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <libqhull_r/libqhull_r.h>
#include <mink/base.h>

/* ---- random numbers ------------------------------------------------------ */

static uint64_t splitMix64(uint64_t *state)
{
	uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

void mkFitRng_Seed(mkFitRng *rng, uint64_t seed, uint64_t stream)
{
	uint64_t mixState = stream;
	uint64_t state = seed ^ splitMix64(&mixState);
	for (int i = 0; i < 4; ++i) {
		rng->s[i] = splitMix64(&state);
	}
}

static uint64_t rotl(uint64_t x, int k)
{
	return (x << k) | (x >> (64 - k));
}

static uint64_t nextU64(mkFitRng *rng)
{
	uint64_t *s = rng->s;
	uint64_t result = rotl(s[1] * 5, 7) * 9;
	uint64_t t = s[1] << 17;
	s[2] ^= s[0];
	s[3] ^= s[1];
	s[1] ^= s[2];
	s[0] ^= s[3];
	s[2] ^= t;
	s[3] = rotl(s[3], 45);
	return result;
}

double mkFitRng_Unit(mkFitRng *rng)
{
	return (double)(nextU64(rng) >> 11) * 0x1.0p-53;
}

double mkFitRng_Uniform(mkFitRng *rng, double a, double b)
{
	return a + (b - a) * mkFitRng_Unit(rng);
}

/* ---- shards --------------------------------------------------------------- */

static void say(char *msg, size_t msglen, const char *fmt, ...)
{
	if (msg == NULL || msglen == 0) {
		return;
	}
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, msglen, fmt, ap);
	va_end(ap);
}

int mkFitShard_Parse(const char *text, int *index, int *count, char *msg, size_t msglen)
{
	long i = -1, n = -1;
	char *end = NULL;
	errno = 0;
	if (text != NULL) {
		i = strtol(text, &end, 10);
		if (end != text && *end == '/') {
			const char *rest = end + 1;
			n = strtol(rest, &end, 10);
			if (end == rest || *end != '\0') {
				n = -1;
			}
		} else {
			n = -1;
		}
	}
	if (errno != 0 || n < 1 || n > 1000000 || i < 0 || i >= n) {
		say(msg, msglen, "--shard: expected I/N with 0 <= I < N <= 1000000, got '%s'",
			text ? text : "");
		return -1;
	}
	*index = (int)i;
	*count = (int)n;
	return 0;
}

int mkFitShard_Owns(int index, int count, int trial)
{
	return trial % count == index;
}

/* ---- results file ----------------------------------------------------------- */

struct mkFitOut {
	FILE *fp;
	int columns, field, bad;
	char path[4096];
	char temp[4096 + 16];
};

mkFitOut *mkFitOut_Open(const char *path, const char *const *columns, int count, char *msg, size_t msglen)
{
	mkFitOut *out = calloc(1, sizeof *out);
	if (out == NULL) {
		say(msg, msglen, "out of memory");
		return NULL;
	}
	if (strlen(path) >= sizeof out->path) {
		say(msg, msglen, "--out: path too long");
		free(out);
		return NULL;
	}
	strcpy(out->path, path);
	snprintf(out->temp, sizeof out->temp, "%s.tmp.XXXXXX", path);
	int fd = mkstemp(out->temp);
	if (fd < 0 || (out->fp = fdopen(fd, "w")) == NULL) {
		say(msg, msglen, "--out: cannot create a file beside '%s': %s", path, strerror(errno));
		if (fd >= 0) {
			close(fd);
			remove(out->temp);
		}
		free(out);
		return NULL;
	}
	out->columns = count;
	for (int i = 0; i < count; ++i) {
		fprintf(out->fp, "%s%s", i ? "," : "", columns[i]);
	}
	fputc('\n', out->fp);
	return out;
}

static void sep(mkFitOut *out)
{
	if (out->field++ > 0) {
		fputc(',', out->fp);
	}
}

void mkFitOut_Str(mkFitOut *out, const char *text)
{
	sep(out);
	fputs(text, out->fp); /* the driver's texts hold no comma or quote */
}

void mkFitOut_Int(mkFitOut *out, long long v)
{
	sep(out);
	fprintf(out->fp, "%lld", v);
}

void mkFitOut_Double(mkFitOut *out, double v)
{
	sep(out);
	fprintf(out->fp, "%.17g", v);
}

void mkFitOut_EndRow(mkFitOut *out)
{
	if (out->field != out->columns) {
		out->bad = 1;
	}
	out->field = 0;
	fputc('\n', out->fp);
}

void mkFitOut_Discard(mkFitOut *out)
{
	if (out == NULL) {
		return;
	}
	if (out->fp != NULL) {
		fclose(out->fp);
		remove(out->temp);
	}
	free(out);
}

int mkFitOut_Exists(const char *path)
{
	return access(path, F_OK) == 0;
}

static void cpuModel(char *buf, size_t len)
{
	snprintf(buf, len, "unknown");
	FILE *f = fopen("/proc/cpuinfo", "r");
	if (f == NULL) {
		return;
	}
	char line[512];
	while (fgets(line, sizeof line, f)) {
		if (strncmp(line, "model name", 10) == 0) {
			char *colon = strchr(line, ':');
			if (colon != NULL) {
				colon += 1 + (colon[1] == ' ');
				colon[strcspn(colon, "\n")] = '\0';
				snprintf(buf, len, "%s", colon);
			}
			break;
		}
	}
	fclose(f);
}

#ifndef MK_FIT_BUILD_TYPE
#define MK_FIT_BUILD_TYPE "unknown"
#endif
#ifndef MK_FIT_C_FLAGS
#define MK_FIT_C_FLAGS "unknown"
#endif
#ifndef MK_FIT_GIT_COMMIT
#define MK_FIT_GIT_COMMIT "unknown"
#endif
#ifndef MK_FIT_CMINPACK_VERSION
#define MK_FIT_CMINPACK_VERSION "unknown"
#endif

int mkFitOut_Commit(mkFitOut *out, const mkFitRunInfo *info, char *msg, size_t msglen)
{
	char metaPath[4096 + 8], metaTemp[4096 + 24];
	snprintf(metaPath, sizeof metaPath, "%s.meta", out->path);
	snprintf(metaTemp, sizeof metaTemp, "%s.tmp.XXXXXX", metaPath);
	int failed = out->bad;
	if (failed) {
		say(msg, msglen, "a row had the wrong number of fields");
	}
	if (fflush(out->fp) != 0 || fsync(fileno(out->fp)) != 0) {
		failed = 1;
		say(msg, msglen, "writing '%s': %s", out->path, strerror(errno));
	}
	int fd = failed ? -1 : mkstemp(metaTemp);
	FILE *mf = fd >= 0 ? fdopen(fd, "w") : NULL;
	if (!failed && mf == NULL) {
		failed = 1;
		say(msg, msglen, "cannot create the sidecar of '%s'", out->path);
	}
	if (mf != NULL) {
		char cpu[256], date[64];
		cpuModel(cpu, sizeof cpu);
		time_t now = time(NULL);
		strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
		fprintf(mf, "schema=fitting/1\n");
		fprintf(mf, "date=%s\n", date);
		fprintf(mf, "command=%s\n", info->command);
		fprintf(mf, "seed=%" PRIu64 "\n", info->seed);
		fprintf(mf, "trials=%d\n", info->trials);
		fprintf(mf, "cases=%s\n", info->cases);
		fprintf(mf, "shard=%d/%d\n", info->shardIndex, info->shardCount);
		fprintf(mf, "cpu_model=%s\n", cpu);
		fprintf(mf, "cpu_count=%ld\n", sysconf(_SC_NPROCESSORS_ONLN));
#ifdef __VERSION__
		fprintf(mf, "compiler=%s\n", __VERSION__);
#endif
		fprintf(mf, "c_flags=%s\n", MK_FIT_C_FLAGS);
		fprintf(mf, "build_type=%s\n", MK_FIT_BUILD_TYPE);
		fprintf(mf, "git_commit=%s\n", MK_FIT_GIT_COMMIT);
		fprintf(mf, "mink_version=%s\n", mkVersion());
		fprintf(mf, "qhull_version=%s\n", qh_version);
		fprintf(mf, "cminpack_version=%s\n", MK_FIT_CMINPACK_VERSION);
		if (fflush(mf) != 0 || fsync(fileno(mf)) != 0) {
			failed = 1;
			say(msg, msglen, "writing the sidecar of '%s'", out->path);
		}
		fclose(mf);
	}
	fclose(out->fp);
	out->fp = NULL;
	/* the sidecar first, so that a final CSV always has one */
	if (!failed && rename(metaTemp, metaPath) != 0) {
		failed = 1;
		say(msg, msglen, "renaming the sidecar of '%s': %s", out->path, strerror(errno));
	}
	if (!failed && rename(out->temp, out->path) != 0) {
		failed = 1;
		say(msg, msglen, "renaming onto '%s': %s", out->path, strerror(errno));
	}
	if (failed) {
		remove(out->temp);
		if (fd >= 0) {
			remove(metaTemp);
		}
	}
	free(out);
	return failed ? -1 : 0;
}
