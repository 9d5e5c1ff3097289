/* test_progress.c - the progress line stays quiet when stderr is not a
 * terminal (here a file), unless MINK_PROGRESS=always asks for log lines.
 * Run it with stderr not a terminal's: ctest does that. */
#define _POSIX_C_SOURCE 200809L

#include "ensure.h"

#include <mink_exp/progress.h>

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static long mkRunAndMeasure(const char *path)
{
	fflush(stderr);
	if (!freopen(path, "w", stderr))
		return -1;
	mkProgress p;
	mkProgress_Begin(&p, "test", 10);
	for (int i = 0; i < 10; ++i)
		mkProgress_Add(&p, 1);
	mkProgress_End(&p);
	fflush(stderr);
	FILE *fp = fopen(path, "r");
	if (!fp)
		return -1;
	fseek(fp, 0, SEEK_END);
	long size = ftell(fp);
	fclose(fp);
	return size;
}

int main(void)
{
	char path[256];
	snprintf(path, sizeof path, "%s/mink_exp_test_progress.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
	int fd = mkstemp(path);
	if (fd < 0)
		return 1;
	close(fd);
	int saved = dup(STDERR_FILENO);
	if (saved < 0)
		return 1;
	unsetenv("MINK_PROGRESS");
	long quiet = mkRunAndMeasure(path);
	setenv("MINK_PROGRESS", "never", 1);
	long never = mkRunAndMeasure(path);
	setenv("MINK_PROGRESS", "always", 1);
	long always = mkRunAndMeasure(path);
	unlink(path);
	/* Give stderr back its original target for the report. */
	fflush(stderr);
	dup2(saved, STDERR_FILENO);
	close(saved);
	printf("progress bytes: default %ld, never %ld, always %ld\n", quiet, never, always);
	ENSURE(quiet == 0);
	ENSURE(never == 0);
	ENSURE(always > 0);
	return mk_summary("common.test_progress");
}
