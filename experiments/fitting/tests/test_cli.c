/* test_cli.c - the `fitting` command line: its own flag (--case) names the
 * flag and its range (the shared flags are tested once, in mink_exp.driver),
 * results come with a sidecar, an existing result is refused and kept unless
 * forced, and the shards' rows, concatenated in shard order, are exactly
 * the rows of the whole run.
 * Usage: test_cli <path of fitting> <scratch directory> */
#define _POSIX_C_SOURCE 200809L
#include "ensure.h"

#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static const char *exe, *dir;

/* Run the driver with args, stdout and stderr into dir/log; exit status. */
static int run(const char *args)
{
	char cmd[2048];
	snprintf(cmd, sizeof cmd, "'%s' %s > '%s/log' 2>&1", exe, args, dir);
	int st = system(cmd);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static char *slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	if (f == NULL) {
		return NULL;
	}
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	fseek(f, 0, SEEK_SET);
	char *buf = malloc((size_t)n + 1);
	size_t got = fread(buf, 1, (size_t)n, f);
	buf[got] = '\0';
	fclose(f);
	return buf;
}

static int logHas(const char *text)
{
	char path[1024];
	snprintf(path, sizeof path, "%s/log", dir);
	char *log = slurp(path);
	int has = log != NULL && strstr(log, text) != NULL;
	free(log);
	return has;
}

/* Split a CSV's data rows (header dropped) into *lines; count returned. */
static int dataRows(char *text, char ***lines)
{
	int n = 0, cap = 64;
	*lines = malloc(sizeof(char *) * (size_t)cap);
	char *save = NULL;
	char *line = strtok_r(text, "\n", &save); /* header */
	while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
		if (n == cap) {
			cap *= 2;
			*lines = realloc(*lines, sizeof(char *) * (size_t)cap);
		}
		(*lines)[n++] = line;
	}
	return n;
}

int main(int argc, char **argv)
{
	if (argc != 3) {
		fprintf(stderr, "usage: test_cli <fitting> <scratch dir>\n");
		return 2;
	}
	exe = argv[1];
	dir = argv[2];
	char args[1536], path[1024];

	/* bad flags: exit status 2, the message names the flag and the range */
	ENSURE(run("--case 5") == 2 && logHas("--case") && logHas("1, 2, 3, all"));
	ENSURE(run("--case=0") == 2 && logHas("fitting: --case = '0' is not allowed: must be one of 1, 2, 3, all"));
	ENSURE(run("--trials 0") == 2 && logHas("[1, 1000000]"));
	ENSURE(run("--help") == 0 && logHas("--shard I/N") && logHas("--case 1|2|3|all"));

	/* a whole run: header + rows, and the sidecar */
	snprintf(args, sizeof args, "--case all --trials 3 --seed 99 --force --out '%s/whole.csv'", dir);
	ENSURE(run(args) == 0);
	snprintf(path, sizeof path, "%s/whole.csv", dir);
	char *whole = slurp(path);
	snprintf(path, sizeof path, "%s/whole.csv.meta", dir);
	char *meta = slurp(path);
	ENSURE(whole != NULL && meta != NULL);
	ENSURE(meta != NULL && strstr(meta, "seed: 99\n") != NULL && strstr(meta, "trials: 3\n") != NULL);
	ENSURE(meta != NULL && strstr(meta, "rows: 129\n") != NULL && strstr(meta, "qhull_version") != NULL);
	ENSURE(whole != NULL && strncmp(whole, "case,trial,truth,model,sampling,level,vertices,", 47) == 0);

	/* an existing result is refused, untouched */
	snprintf(args, sizeof args, "--case all --trials 3 --seed 99 --out '%s/whole.csv'", dir);
	ENSURE(run(args) == 1 && logHas("exists"));
	snprintf(path, sizeof path, "%s/whole.csv", dir);
	char *still = slurp(path);
	ENSURE(whole != NULL && still != NULL && strcmp(whole, still) == 0);
	free(still);

	/* three shards, concatenated in shard order, give the whole run */
	char *shards[3] = { NULL, NULL, NULL };
	for (int s = 0; s < 3; ++s) {
		snprintf(args, sizeof args, "--case all --trials 3 --seed 99 --force --shard %d/3 --out '%s/s%d.csv'", s, dir, s);
		ENSURE(run(args) == 0);
		snprintf(path, sizeof path, "%s/s%d.csv", dir, s);
		shards[s] = slurp(path);
		ENSURE(shards[s] != NULL);
	}
	if (whole != NULL && shards[0] != NULL && shards[1] != NULL && shards[2] != NULL) {
		char **lw;
		int nw = dataRows(whole, &lw), total = 0, same = 1;
		/* 3 trials: case 1 one row each, case 2 34, case 3 8 */
		ENSURE(nw == 3 * (1 + 34 + 8));
		for (int s = 0; s < 3; ++s) {
			char **ls;
			int ns = dataRows(shards[s], &ls);
			ENSURE(ns > 0);
			for (int i = 0; i < ns; ++i) {
				same &= total + i < nw && strcmp(ls[i], lw[total + i]) == 0;
			}
			total += ns;
			free(ls);
		}
		ENSURE(total == nw);
		ENSURE(same);
		free(lw);
	}
	for (int s = 0; s < 3; ++s) {
		free(shards[s]);
	}
	free(whole);
	free(meta);
	return mk_summary("fitting.test_cli");
}
