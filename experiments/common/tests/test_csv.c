/* test_csv.c - result files appear whole or not at all: commit, interrupted
 * writes (SIGTERM, SIGINT, a normal exit without commit), a rewrite that is
 * interrupted keeps the old file, misused rows and missing metadata fail. */
#define _POSIX_C_SOURCE 200809L

#include "ensure.h"

#include <mink_exp/csv.h>
#include <mink_exp/meta.h>
#include <mink_exp/table.h>

#include <dirent.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static char dir[256];

static void mkPathIn(char *out, size_t len, const char *name)
{
	snprintf(out, len, "%s/%s", dir, name);
}

/* Number of directory entries whose name contains `part`. */
static int mkCountNames(const char *part)
{
	DIR *d = opendir(dir);
	int n = 0;
	if (!d)
		return -1;
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		if (strstr(e->d_name, part))
			++n;
	}
	closedir(d);
	return n;
}

static char *mkSlurp(const char *path)
{
	FILE *fp = fopen(path, "r");
	if (!fp)
		return NULL;
	static char buf[65536];
	size_t n = fread(buf, 1, sizeof buf - 1, fp);
	buf[n] = '\0';
	fclose(fp);
	return buf;
}

static void mkWriteFile(const char *path, const char *text)
{
	FILE *fp = fopen(path, "w");
	fputs(text, fp);
	fclose(fp);
}

static const char *const names[] = { "trial", "form", "value" };

static void mkMakeMeta(mkMeta *m)
{
	char *argv[] = { "test_csv", "--seed", "1" };
	mkMeta_Init(m, "test", 1, 3, argv);
	mkMeta_SetU64(m, "seed", 1);
	mkMeta_SetInt(m, "trials", 2);
}

/* A child that writes rows, tells the parent it is mid-write, and then
 * either waits to be killed (how == 0) or leaves by exit(3) (how == 1). */
static pid_t mkWriterChild(const char *path, int how, int *ready_fd)
{
	int fds[2];
	if (pipe(fds) != 0)
		return -1;
	pid_t pid = fork();
	if (pid == 0) {
		close(fds[0]);
		mkCsv csv;
		char msg[256];
		if (mkCsv_Open(&csv, path, names, 3, msg, sizeof msg) != 0)
			_exit(10);
		for (int i = 0; i < 1000; ++i) {
			mkCsv_Int(&csv, i);
			mkCsv_Str(&csv, "normal");
			mkCsv_Double(&csv, 0.5 * i);
			mkCsv_EndRow(&csv);
		}
		fflush(csv.file.fp);
		if (write(fds[1], "r", 1) != 1)
			_exit(11);
		if (how == 1)
			exit(3);
		for (;;)
			pause();
	}
	close(fds[1]);
	*ready_fd = fds[0];
	return pid;
}

static void mkInterrupt(const char *name, int sig, const char *old_text)
{
	char path[512];
	mkPathIn(path, sizeof path, name);
	if (old_text)
		mkWriteFile(path, old_text);
	int ready;
	pid_t pid = mkWriterChild(path, sig == 0 ? 1 : 0, &ready);
	ENSURE(pid > 0);
	char c;
	ENSURE(read(ready, &c, 1) == 1);
	close(ready);
	/* The temporary file exists while the child writes (a child that exits
	 * by itself may already be gone). */
	if (sig != 0)
		ENSURE(mkCountNames(".tmp.") == 1);
	if (sig != 0)
		kill(pid, sig);
	int status = 0;
	ENSURE(waitpid(pid, &status, 0) == pid);
	if (sig != 0) {
		/* Still ends as killed by the signal (exit status of a killed job). */
		ENSURE(WIFSIGNALED(status) && WTERMSIG(status) == sig);
	} else {
		ENSURE(WIFEXITED(status) && WEXITSTATUS(status) == 3);
	}
	ENSURE(mkCountNames(".tmp.") == 0);
	if (old_text) {
		char *now = mkSlurp(path);
		ENSURE(now && strcmp(now, old_text) == 0);
		unlink(path);
	} else {
		ENSURE(access(path, F_OK) != 0);
	}
}

/* A .gz result: `rows` rows written and committed to dir/name. */
static void mkWriteGz(const char *name, int rows)
{
	char path[512], msg[512];
	mkPathIn(path, sizeof path, name);
	mkCsv csv;
	ENSURE(mkCsv_Open(&csv, path, names, 3, msg, sizeof msg) == 0);
	for (int i = 0; i < rows; ++i) {
		mkCsv_Int(&csv, i); mkCsv_Str(&csv, i % 2 ? "odd" : "even"); mkCsv_Double(&csv, 0.1 * i);
		mkCsv_EndRow(&csv);
	}
	ENSURE(mkCsv_Commit(&csv, NULL, msg, sizeof msg) == 0);
}

/* Compressed results: gzip with no name and no time in the header, the
 * same bytes for the same rows, no scratch file left, read back whole
 * (also by the CSV name when only the .gz exists). */
static void mkCheckGz(void)
{
	mkWriteGz("a.csv.gz", 50000);
	sleep(1); /* a time stamp in the header would now differ */
	mkWriteGz("b.csv.gz", 50000);
	ENSURE(mkCountNames(".tmp.") == 0);
	char a[512], b[512], cmd[1200];
	mkPathIn(a, sizeof a, "a.csv.gz");
	mkPathIn(b, sizeof b, "b.csv.gz");
	snprintf(cmd, sizeof cmd, "cmp -s '%s' '%s'", a, b);
	ENSURE(system(cmd) == 0);
	FILE *fp = fopen(a, "rb");
	unsigned char head[10] = { 0 };
	ENSURE(fp && fread(head, 1, 10, fp) == 10);
	fclose(fp);
	ENSURE(head[0] == 0x1f && head[1] == 0x8b && head[3] == 0); /* gzip, no name */
	ENSURE(head[4] == 0 && head[5] == 0 && head[6] == 0 && head[7] == 0); /* no time */
	mkTable t;
	mkPathIn(a, sizeof a, "a.csv");
	mkTable_Load(&t, a);
	ENSURE(t.present && t.rows == 50000 && t.cols == 3);
	ENSURE(strcmp(mkTable_Str(&t, 49999, 1), "odd") == 0 && mkTable_Num(&t, 3, 2) == 0.1 * 3);
	mkTable_Free(&t);
}

int main(void)
{
	snprintf(dir, sizeof dir, "%s/mink_exp_test_csv.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
	if (!mkdtemp(dir)) {
		perror("mkdtemp");
		return 1;
	}
	char path[512], metapath[600], msg[512];

	/* 1. A committed file holds exactly what was written, with its sidecar. */
	mkPathIn(path, sizeof path, "ok.csv");
	mkCsv csv;
	ENSURE(mkCsv_Open(&csv, path, names, 3, msg, sizeof msg) == 0);
	ENSURE(access(path, F_OK) != 0); /* nothing under the final name yet */
	mkCsv_Int(&csv, 0); mkCsv_Str(&csv, "a,b \"q\""); mkCsv_Double(&csv, 0.1); mkCsv_EndRow(&csv);
	mkCsv_Int(&csv, 1); mkCsv_Str(&csv, "plain"); mkCsv_Double(&csv, NAN); mkCsv_EndRow(&csv);
	mkCsv_Int(&csv, 2); mkCsv_Empty(&csv); mkCsv_Double(&csv, -INFINITY); mkCsv_EndRow(&csv);
	mkMeta meta;
	mkMakeMeta(&meta);
	ENSURE(mkCsv_Commit(&csv, &meta, msg, sizeof msg) == 0);
	mkMeta_Free(&meta);
	const char *text = mkSlurp(path);
	ENSURE(text && strcmp(text,
		"trial,form,value\n"
		"0,\"a,b \"\"q\"\"\",0.10000000000000001\n"
		"1,plain,nan\n"
		"2,,-inf\n") == 0);
	snprintf(metapath, sizeof metapath, "%s.meta", path);
	ENSURE(access(metapath, F_OK) == 0);
	ENSURE(mkCountNames(".tmp.") == 0);
	/* Mode as fopen would give: readable by the owner at least, and no
	 * execute bits. */
	struct stat st;
	ENSURE(stat(path, &st) == 0 && (st.st_mode & 0400) && !(st.st_mode & 0111));

	/* 2. Interrupted writes leave no final file and no temporary file. */
	mkInterrupt("term.csv", SIGTERM, NULL);
	mkInterrupt("int.csv", SIGINT, NULL);
	mkInterrupt("exit.csv", 0, NULL);
	/* 3. An interrupted rewrite leaves the previous file as it was. */
	mkInterrupt("old.csv", SIGTERM, "trial,form,value\n7,old,1\n");

	/* 4. A row with the wrong field count makes the commit fail. */
	mkPathIn(path, sizeof path, "misuse.csv");
	ENSURE(mkCsv_Open(&csv, path, names, 3, msg, sizeof msg) == 0);
	mkCsv_Int(&csv, 0); mkCsv_EndRow(&csv);
	ENSURE(mkCsv_Commit(&csv, NULL, msg, sizeof msg) != 0);
	ENSURE(strstr(msg, "fields") != NULL);
	ENSURE(access(path, F_OK) != 0);
	ENSURE(mkCountNames(".tmp.") == 0);

	/* 5. Metadata without the driver's keys fails, and nothing appears. */
	mkPathIn(path, sizeof path, "nometa.csv");
	ENSURE(mkCsv_Open(&csv, path, names, 3, msg, sizeof msg) == 0);
	mkCsv_Int(&csv, 0); mkCsv_Str(&csv, "x"); mkCsv_Double(&csv, 1.0); mkCsv_EndRow(&csv);
	char *argv[] = { "test_csv" };
	mkMeta_Init(&meta, "test", 1, 1, argv);
	ENSURE(mkCsv_Commit(&csv, &meta, msg, sizeof msg) != 0);
	ENSURE(strstr(msg, "'seed'") != NULL);
	mkMeta_Free(&meta);
	ENSURE(access(path, F_OK) != 0);
	snprintf(metapath, sizeof metapath, "%s.meta", path);
	ENSURE(access(metapath, F_OK) != 0);
	ENSURE(mkCountNames(".tmp.") == 0);

	/* 6. A directory that does not exist: a message naming the path. */
	mkPathIn(path, sizeof path, "no/such/dir/x.csv");
	ENSURE(mkCsv_Open(&csv, path, names, 3, msg, sizeof msg) != 0);
	ENSURE(strstr(msg, "no/such/dir/x.csv") != NULL);
	/* ... which mkPath_MakeParents creates. */
	ENSURE(mkPath_MakeParents(path, msg, sizeof msg) == 0);
	ENSURE(mkCsv_Open(&csv, path, names, 3, msg, sizeof msg) == 0);
	mkCsv_Discard(&csv);
	ENSURE(access(path, F_OK) != 0);

	/* 7. A geometry file read back: blank lines (gnuplot's block
	 * separators, "\n" or "\r\n") are not rows; those after the header
	 * are counted, and the plain reader refuses such a file. */
	mkPathIn(path, sizeof path, "blocks.csv");
	mkWriteFile(path, "\nk,x\n0,1.5\n1,2\n\n\n0,3\r\n\r\n1,\"4\"\n\n");
	mkTable t;
	long blank = -1;
	mkTable_LoadBlocks(&t, path, &blank);
	ENSURE(t.present && t.cols == 2 && t.rows == 4);
	ENSURE(blank == 4);
	ENSURE(t.present && mkTable_Num(&t, 2, mkTable_Col(&t, "x")) == 3.0);
	ENSURE(t.present && strcmp(mkTable_Str(&t, 3, 1), "4") == 0);
	mkTable_Free(&t);
	fprintf(stderr, "(a message on a non-rectangular file is expected next)\n");
	mkTable_Load(&t, path);
	ENSURE(!t.present);
	mkTable_Free(&t);

	mkCheckGz();

	/* Clean up. */
	char cmd[600];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
	ENSURE(system(cmd) == 0);
	return mk_summary("common.test_csv");
}
