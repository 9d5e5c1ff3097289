/* test_meta.c - the sidecar has every required key, each non-empty, in the
 * documented form, and reads back to what was set. */
#define _POSIX_C_SOURCE 200809L

#include "ensure.h"

#include <mink_exp/meta.h>
#include <mink_exp/outfile.h>

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int mkIsUtcStamp(const char *s)
{
	/* YYYY-MM-DDTHH:MM:SSZ */
	static const char *const form = "dddd-dd-ddTdd:dd:ddZ";
	if (strlen(s) != strlen(form))
		return 0;
	for (size_t i = 0; form[i]; ++i) {
		if (form[i] == 'd' ? !(s[i] >= '0' && s[i] <= '9') : s[i] != form[i])
			return 0;
	}
	return 1;
}

int main(void)
{
	static const char *const required[] = { MK_META_REQUIRED_KEYS };
	char path[256], msg[512];
	snprintf(path, sizeof path, "%s/mink_exp_test_meta.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
	int fd = mkstemp(path);
	ENSURE(fd >= 0);
	close(fd);

	char *argv[] = { "/some/build/dir/validation", "--seed", "7", "--out", "a b.csv", "it's" };
	mkMeta m;
	mkMeta_Init(&m, "validation", 3, 6, argv);
	/* Before the driver's keys are set, writing is refused. */
	ENSURE(mkMeta_Missing(&m) != NULL && strcmp(mkMeta_Missing(&m), "seed") == 0);
	FILE *sink = fopen("/dev/null", "w");
	ENSURE(mkMeta_Write(&m, sink, msg, sizeof msg) != 0);
	ENSURE(strstr(msg, "seed") != NULL);
	fclose(sink);

	mkMeta_SetU64(&m, "seed", UINT64_C(18446744073709551615));
	mkMeta_SetInt(&m, "trials", 100);
	mkMeta_SetInt(&m, "rows", 600);
	mkMeta_Set(&m, "shard", "1/4");
	mkMeta_Set(&m, "rotation_draw", "paper");
	mkMeta_Set(&m, "note", "two\nlines");
	mkMeta_Set(&m, "trials", "200"); /* replaces, does not duplicate */
	ENSURE(mkMeta_Missing(&m) == NULL);
	/* A removed key is gone, the others keep their order, and removing a
	 * key that is not there changes nothing. */
	int count = m.count;
	mkMeta_Set(&m, "trial_range", "0..9");
	mkMeta_Set(&m, "after", "x");
	mkMeta_Remove(&m, "trial_range");
	mkMeta_Remove(&m, "no_such_key");
	ENSURE(m.count == count + 1 && mkMeta_Get(&m, "trial_range") == NULL);
	ENSURE(strcmp(m.keys[m.count - 1], "after") == 0 && strcmp(m.keys[m.count - 2], "note") == 0);
	mkMeta_Remove(&m, "after");

	mkOutFile f;
	ENSURE(mkOutFile_Open(&f, path, msg, sizeof msg) == 0);
	ENSURE(mkMeta_Write(&m, f.fp, msg, sizeof msg) == 0);
	ENSURE(mkOutFile_Commit(&f, msg, sizeof msg) == 0);
	mkMeta_Free(&m);

	mkMeta r;
	mkMeta_InitEmpty(&r);
	ENSURE(mkMeta_ReadFile(&r, path, msg, sizeof msg) == 0);
	for (size_t i = 0; i < sizeof required / sizeof required[0]; ++i) {
		const char *v = mkMeta_Get(&r, required[i]);
		if (!v || !v[0])
			fprintf(stderr, "missing or empty key: %s\n", required[i]);
		ENSURE(v && v[0]);
	}
	/* Each key once. */
	int trials_seen = 0;
	for (int i = 0; i < r.count; ++i)
		trials_seen += strcmp(r.keys[i], "trials") == 0;
	ENSURE(trials_seen == 1);

	const char *v;
	ENSURE((v = mkMeta_Get(&r, "experiment")) && strcmp(v, "validation") == 0);
	ENSURE((v = mkMeta_Get(&r, "schema_version")) && strcmp(v, "3") == 0);
	ENSURE((v = mkMeta_Get(&r, "seed")) && strcmp(v, "18446744073709551615") == 0);
	ENSURE((v = mkMeta_Get(&r, "trials")) && strcmp(v, "200") == 0);
	ENSURE((v = mkMeta_Get(&r, "shard")) && strcmp(v, "1/4") == 0);
	ENSURE((v = mkMeta_Get(&r, "rotation_draw")) && strcmp(v, "paper") == 0);
	ENSURE((v = mkMeta_Get(&r, "note")) && strcmp(v, "two lines") == 0);
	ENSURE((v = mkMeta_Get(&r, "date_utc")) && mkIsUtcStamp(v));
	ENSURE((v = mkMeta_Get(&r, "finished_utc")) && mkIsUtcStamp(v));
	ENSURE((v = mkMeta_Get(&r, "wall_seconds")) && atof(v) >= 0.0);
	ENSURE((v = mkMeta_Get(&r, "cpu_count")) && atoi(v) >= 1);
	ENSURE((v = mkMeta_Get(&r, "git_dirty")) &&
		(strcmp(v, "yes") == 0 || strcmp(v, "no") == 0 || strcmp(v, "unknown") == 0));
	ENSURE((v = mkMeta_Get(&r, "git_commit")) && (strlen(v) == 40 || strcmp(v, "unknown") == 0));
	/* The command line is quoted so a shell gives back the same words. */
	ENSURE((v = mkMeta_Get(&r, "command_line")) &&
		strcmp(v, "validation --seed 7 --out 'a b.csv' 'it'\\''s'") == 0);
	ENSURE((v = mkMeta_Get(&r, "compiler_flags")) && strstr(v, "-std=c11") != NULL);
	mkMeta_Free(&r);

	/* A line that is not "key: value" is refused with its line number. */
	FILE *fp = fopen(path, "w");
	fputs("experiment: x\nthis line has no separator\n", fp);
	fclose(fp);
	mkMeta_InitEmpty(&r);
	ENSURE(mkMeta_ReadFile(&r, path, msg, sizeof msg) != 0);
	ENSURE(strstr(msg, ":2:") != NULL);
	mkMeta_Free(&r);

	unlink(path);
	return mk_summary("common.test_meta");
}
