/* meta.c - the metadata sidecar. */
#define _POSIX_C_SOURCE 200809L

#include "mink_exp/clock.h"
#include "mink_exp/meta.h"
#include "mink_exp_buildinfo.h"

#include <mink/base.h>

#include <assert.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

static const char *const mkRequiredKeys[] = { MK_META_REQUIRED_KEYS };

static char *mkStrDup(const char *s)
{
	size_t n = strlen(s) + 1;
	char *d = malloc(n);
	if (d)
		memcpy(d, s, n);
	return d;
}

static int mkKeyIsValid(const char *key)
{
	if (!key[0])
		return 0;
	for (const char *p = key; *p; ++p) {
		if (!((*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9') || *p == '_'))
			return 0;
	}
	return 1;
}

void mkMeta_UtcNow(char *buf, size_t len)
{
	time_t now = time(NULL);
	struct tm tm;
	gmtime_r(&now, &tm);
	strftime(buf, len, "%Y-%m-%dT%H:%M:%SZ", &tm);
}

void mkMeta_InitEmpty(mkMeta *meta)
{
	memset(meta, 0, sizeof *meta);
	meta->start = mkClock_Wall();
}

void mkMeta_Free(mkMeta *meta)
{
	for (int i = 0; i < meta->count; ++i) {
		free(meta->keys[i]);
		free(meta->values[i]);
	}
	meta->count = 0;
}

void mkMeta_Set(mkMeta *meta, const char *key, const char *value)
{
	assert(mkKeyIsValid(key));
	char *v = mkStrDup(value ? value : "");
	if (!v) {
		meta->overflow = 1;
		return;
	}
	/* One line per key: line breaks become spaces. */
	for (char *p = v; *p; ++p) {
		if (*p == '\n' || *p == '\r')
			*p = ' ';
	}
	for (int i = 0; i < meta->count; ++i) {
		if (strcmp(meta->keys[i], key) == 0) {
			free(meta->values[i]);
			meta->values[i] = v;
			return;
		}
	}
	if (meta->count >= MK_META_MAX_KEYS) {
		free(v);
		meta->overflow = 1;
		return;
	}
	char *k = mkStrDup(key);
	if (!k) {
		free(v);
		meta->overflow = 1;
		return;
	}
	meta->keys[meta->count] = k;
	meta->values[meta->count] = v;
	meta->count += 1;
}

void mkMeta_SetInt(mkMeta *meta, const char *key, long long value)
{
	char buf[32];
	snprintf(buf, sizeof buf, "%lld", value);
	mkMeta_Set(meta, key, buf);
}

void mkMeta_SetU64(mkMeta *meta, const char *key, uint64_t value)
{
	char buf[32];
	snprintf(buf, sizeof buf, "%" PRIu64, value);
	mkMeta_Set(meta, key, buf);
}

void mkMeta_SetDouble(mkMeta *meta, const char *key, double value)
{
	char buf[40];
	snprintf(buf, sizeof buf, "%.17g", value);
	mkMeta_Set(meta, key, buf);
}

void mkMeta_Remove(mkMeta *meta, const char *key)
{
	for (int i = 0; i < meta->count; ++i) {
		if (strcmp(meta->keys[i], key) != 0)
			continue;
		free(meta->keys[i]);
		free(meta->values[i]);
		for (int j = i + 1; j < meta->count; ++j) {
			meta->keys[j - 1] = meta->keys[j];
			meta->values[j - 1] = meta->values[j];
		}
		meta->count -= 1;
		return;
	}
}

const char *mkMeta_Get(const mkMeta *meta, const char *key)
{
	for (int i = 0; i < meta->count; ++i) {
		if (strcmp(meta->keys[i], key) == 0)
			return meta->values[i];
	}
	return NULL;
}

const char *mkMeta_Missing(const mkMeta *meta)
{
	size_t n = sizeof mkRequiredKeys / sizeof mkRequiredKeys[0];
	for (size_t i = 0; i < n; ++i) {
		const char *k = mkRequiredKeys[i];
		if (strcmp(k, "finished_utc") == 0 || strcmp(k, "wall_seconds") == 0)
			continue;
		if (!mkMeta_Get(meta, k))
			return k;
	}
	return NULL;
}

/* Remove leading and trailing blanks in place. */
static char *mkTrim(char *s)
{
	while (*s == ' ' || *s == '\t')
		++s;
	size_t n = strlen(s);
	while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\n' || s[n - 1] == '\r'))
		s[--n] = '\0';
	return s;
}

/* The "model name" (x86) or "Model" / "Processor" line of /proc/cpuinfo. */
static void mkCpuModel(char *buf, size_t len)
{
	snprintf(buf, len, "unknown");
	FILE *fp = fopen("/proc/cpuinfo", "r");
	if (!fp)
		return;
	char line[512];
	static const char *const keys[] = { "model name", "Model", "Processor", "cpu model" };
	int best = 99;
	while (fgets(line, sizeof line, fp)) {
		char *colon = strchr(line, ':');
		if (!colon)
			continue;
		*colon = '\0';
		char *key = mkTrim(line);
		char *value = mkTrim(colon + 1);
		for (int i = 0; i < (int)(sizeof keys / sizeof keys[0]); ++i) {
			if (i < best && strcmp(key, keys[i]) == 0 && value[0]) {
				snprintf(buf, len, "%s", value);
				best = i;
			}
		}
	}
	fclose(fp);
}

/* argv joined by spaces, the program by its file name only (where it was
 * built or installed says nothing about the run); an argument holding
 * anything but plain characters is single-quoted for the shell. */
static char *mkJoinArgs(int argc, char **argv)
{
	size_t cap = 1;
	for (int i = 0; i < argc; ++i)
		cap += 4 * strlen(argv[i]) + 3;
	char *out = malloc(cap);
	if (!out)
		return NULL;
	char *p = out;
	for (int i = 0; i < argc; ++i) {
		const char *a = argv[i];
		if (i == 0 && strrchr(a, '/') && strrchr(a, '/')[1])
			a = strrchr(a, '/') + 1;
		int plain = a[0] != '\0';
		for (const char *q = a; *q; ++q) {
			if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_=./,:+@%", *q))
				plain = 0;
		}
		if (i > 0)
			*p++ = ' ';
		if (plain) {
			size_t n = strlen(a);
			memcpy(p, a, n);
			p += n;
		} else {
			*p++ = '\'';
			for (const char *q = a; *q; ++q) {
				if (*q == '\'') {
					memcpy(p, "'\\''", 4);
					p += 4;
				} else {
					*p++ = *q;
				}
			}
			*p++ = '\'';
		}
	}
	*p = '\0';
	return out;
}

/* The git state written at build time beside the build (see
 * experiments/common/CMakeLists.txt): lines "commit: ..." and "dirty: ...". */
static void mkGitInfo(mkMeta *meta)
{
	const char *commit = "unknown", *dirty = "unknown";
	char cbuf[128] = "", dbuf[32] = "";
	FILE *fp = fopen(MKEXP_GITINFO_FILE, "r");
	if (fp) {
		char line[256];
		while (fgets(line, sizeof line, fp)) {
			char *colon = strchr(line, ':');
			if (!colon)
				continue;
			*colon = '\0';
			char *value = mkTrim(colon + 1);
			if (strcmp(line, "commit") == 0 && value[0]) {
				snprintf(cbuf, sizeof cbuf, "%s", value);
				commit = cbuf;
			} else if (strcmp(line, "dirty") == 0 && value[0]) {
				snprintf(dbuf, sizeof dbuf, "%s", value);
				dirty = dbuf;
			}
		}
		fclose(fp);
	}
	mkMeta_Set(meta, "git_commit", commit);
	mkMeta_Set(meta, "git_dirty", dirty);
}

void mkMeta_Init(mkMeta *meta, const char *experiment, int schema_version, int argc, char **argv)
{
	mkMeta_InitEmpty(meta);
	char buf[512];
	mkMeta_Set(meta, "experiment", experiment);
	mkMeta_SetInt(meta, "schema_version", schema_version);
	mkMeta_UtcNow(buf, sizeof buf);
	mkMeta_Set(meta, "date_utc", buf);
	char *cmd = argc > 0 ? mkJoinArgs(argc, argv) : NULL;
	mkMeta_Set(meta, "command_line", cmd ? cmd : "");
	free(cmd);

	mkCpuModel(buf, sizeof buf);
	mkMeta_Set(meta, "cpu_model", buf);
	mkMeta_SetInt(meta, "cpu_count", (long long)sysconf(_SC_NPROCESSORS_ONLN));
	struct utsname un;
	if (uname(&un) == 0) {
		snprintf(buf, sizeof buf, "%s %s %s", un.sysname, un.release, un.machine);
		mkMeta_Set(meta, "os", buf);
	} else {
		mkMeta_Set(meta, "os", "unknown");
	}

	mkMeta_Set(meta, "compiler", MKEXP_COMPILER);
	mkMeta_Set(meta, "compiler_flags", MKEXP_C_FLAGS);
	mkMeta_Set(meta, "build_type", MKEXP_BUILD_TYPE);
	mkGitInfo(meta);
	mkMeta_Set(meta, "mink_version", mkVersion());
	mkMeta_Set(meta, "sleef_version", MKEXP_SLEEF_VERSION);
	mkMeta_Set(meta, "shard", "0/1");
}

int mkMeta_Write(mkMeta *meta, FILE *fp, char *msg, size_t msglen)
{
	const char *missing = mkMeta_Missing(meta);
	if (missing) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "metadata key '%s' was not set (program error)", missing);
		return -1;
	}
	char buf[64];
	mkMeta_UtcNow(buf, sizeof buf);
	mkMeta_Set(meta, "finished_utc", buf);
	snprintf(buf, sizeof buf, "%.3f", mkClock_Wall() - meta->start);
	mkMeta_Set(meta, "wall_seconds", buf);
	if (meta->overflow) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "more than %d metadata keys, or out of memory", MK_META_MAX_KEYS);
		return -1;
	}
	for (int i = 0; i < meta->count; ++i)
		fprintf(fp, "%s: %s\n", meta->keys[i], meta->values[i]);
	return 0;
}

int mkMeta_ReadFile(mkMeta *meta, const char *path, char *msg, size_t msglen)
{
	FILE *fp = fopen(path, "r");
	if (!fp) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "cannot read %s", path);
		return -1;
	}
	/* Lines may be long (command lines); read them whole. */
	size_t cap = 256;
	char *line = malloc(cap);
	int lineno = 0, rc = 0;
	while (line && rc == 0) {
		size_t n = 0;
		int c;
		while ((c = fgetc(fp)) != EOF && c != '\n') {
			if (n + 1 >= cap) {
				char *bigger = realloc(line, cap * 2);
				if (!bigger) {
					rc = -1;
					break;
				}
				line = bigger;
				cap *= 2;
			}
			line[n++] = (char)c;
		}
		if (rc != 0 || (c == EOF && n == 0))
			break;
		line[n] = '\0';
		++lineno;
		char *colon = strstr(line, ": ");
		if (!colon && n > 0 && line[n - 1] == ':')
			colon = line + n - 1;
		if (!colon) {
			if (msg && msglen > 0)
				snprintf(msg, msglen, "%s:%d: not a 'key: value' line", path, lineno);
			rc = -1;
			break;
		}
		*colon = '\0';
		if (!mkKeyIsValid(line)) {
			if (msg && msglen > 0)
				snprintf(msg, msglen, "%s:%d: bad key '%s'", path, lineno, line);
			rc = -1;
			break;
		}
		mkMeta_Set(meta, line, colon[1] ? colon + 2 : "");
		if (c == EOF)
			break;
	}
	if (!line) {
		rc = -1;
		if (msg && msglen > 0)
			snprintf(msg, msglen, "out of memory reading %s", path);
	}
	free(line);
	fclose(fp);
	return rc;
}

void mkMeta_SetPairs(mkMeta *meta, const char *const pairs[][2], int count)
{
	for (int i = 0; i < count; ++i)
		mkMeta_Set(meta, pairs[i][0], pairs[i][1]);
}
