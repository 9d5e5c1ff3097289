/* test_interrupt.c - interrupted runs leave the previous result or the
 * complete new one, and no temporary file after SIGINT or SIGTERM.
 *
 *   test_interrupt MINK DRIVER SCENE3 KILLS SEED WORKDIR
 *
 * Three commands, each writing into WORKDIR: `mink scene SCENE3 --outer`
 * (two files committed together: points and faces), `mink sum` (3D, a
 * large grid) and the experiment driver DRIVER (`--trials`, with its
 * sidecar). Each is first run to the end twice: the reference output and
 * its wall time. Then KILLS times (seeded random stream SEED) a command is
 * picked, its output is made absent or set to a stale text, the command is
 * started and sent SIGINT, SIGTERM or SIGKILL after a random delay of up to
 * 1.3 times its reference time. Checked after each kill:
 *  - the process ended by that signal (or finished first, exit status 0);
 *  - every output file is absent (when it was absent before), the stale
 *    text, or the complete new output: the reference's bytes when the two
 *    reference runs agreed, else the same number of lines and a final
 *    newline; the files committed together are all old or all new (after
 *    SIGKILL: the file renamed last is new only when all are);
 *  - after SIGINT or SIGTERM no "*.tmp.*" file is left in WORKDIR (after
 *    SIGKILL they may be: they are counted and removed).
 * Prints "test_interrupt: N passed, M failed" and the count of kills of each
 * signal that landed before the end of the run. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define MK_IT_OUTS 3

typedef struct mkItCase {
	const char *name;
	char *argv[32];
	char out[MK_IT_OUTS][4096];  /* files committed together; "" unused */
	char *ref[MK_IT_OUTS];
	long ref_len[MK_IT_OUTS];
	int last;                    /* the output renamed last: when it is new, all are */
	int exact[MK_IT_OUTS];       /* the two reference runs gave the same bytes */
	double seconds;
} mkItCase;

static int mkIt_Failed = 0, mkIt_Passed = 0;

static void mkIt_Check(int ok, const char *what, const char *name, int trial)
{
	if (ok) {
		++mkIt_Passed;
		return;
	}
	++mkIt_Failed;
	fprintf(stderr, "test_interrupt: FAILED %s (%s, kill %d)\n", what, name, trial);
}

static double mkIt_Now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t mkIt_Rng = 88172645463325252ULL;
static double mkIt_Uniform(void)
{
	mkIt_Rng ^= mkIt_Rng << 13;
	mkIt_Rng ^= mkIt_Rng >> 7;
	mkIt_Rng ^= mkIt_Rng << 17;
	return (double)(mkIt_Rng >> 11) * 0x1p-53;
}

/* The whole file, or NULL when absent; *len its length. */
static char *mkIt_Read(const char *path, long *len)
{
	FILE *f = fopen(path, "rb");
	if (!f) return NULL;
	long cap = 1 << 16, n = 0;
	char *buf = malloc((size_t)cap);
	size_t got;
	while (buf && (got = fread(buf + n, 1, (size_t)(cap - n), f)) > 0) {
		n += (long)got;
		if (n == cap) {
			char *b = realloc(buf, (size_t)(cap *= 2));
			if (!b) free(buf);
			buf = b;
		}
	}
	fclose(f);
	if (!buf) { fprintf(stderr, "test_interrupt: out of memory\n"); exit(1); }
	*len = n;
	return buf;
}

static long mkIt_Lines(const char *b, long n)
{
	long k = 0;
	for (long i = 0; i < n; ++i) k += b[i] == '\n';
	return k;
}

/* Start the case; returns the child's pid. */
static pid_t mkIt_Start(mkItCase *c)
{
	pid_t pid = fork();
	if (pid == 0) {
		int nul = open("/dev/null", O_WRONLY);
		if (nul >= 0) { dup2(nul, 1); dup2(nul, 2); }
		execv(c->argv[0], c->argv);
		_exit(127);
	}
	if (pid < 0) { perror("test_interrupt: fork"); exit(1); }
	return pid;
}

/* The reference output: two full runs. */
static void mkIt_Reference(mkItCase *c)
{
	char *first[MK_IT_OUTS] = {NULL};
	long flen[MK_IT_OUTS] = {0};
	for (int k = 0; k < MK_IT_OUTS; ++k) c->exact[k] = 1;
	for (int run = 0; run < 2; ++run) {
		for (int k = 0; k < MK_IT_OUTS; ++k) if (c->out[k][0]) unlink(c->out[k]);
		double t0 = mkIt_Now();
		int st;
		waitpid(mkIt_Start(c), &st, 0);
		c->seconds = mkIt_Now() - t0;
		if (!WIFEXITED(st) || WEXITSTATUS(st) != 0) {
			fprintf(stderr, "test_interrupt: the reference run of %s failed (status %d)\n", c->name, st);
			exit(1);
		}
		for (int k = 0; k < MK_IT_OUTS; ++k) {
			if (!c->out[k][0]) continue;
			long n = 0;
			char *b = mkIt_Read(c->out[k], &n);
			if (!b) { fprintf(stderr, "test_interrupt: %s wrote no %s\n", c->name, c->out[k]); exit(1); }
			if (run == 0) { first[k] = b; flen[k] = n; continue; }
			c->exact[k] = n == flen[k] && memcmp(b, first[k], (size_t)n) == 0;
			c->ref[k] = b;
			c->ref_len[k] = n;
			free(first[k]);
		}
	}
}

/* 1 when the output k is the complete new one. */
static int mkIt_IsNew(const mkItCase *c, int k, const char *b, long n)
{
	if (c->exact[k]) return n == c->ref_len[k] && memcmp(b, c->ref[k], (size_t)n) == 0;
	return n > 0 && b[n - 1] == '\n' && mkIt_Lines(b, n) == mkIt_Lines(c->ref[k], c->ref_len[k]);
}

/* Temporary files left in dir (removed). */
static int mkIt_Temps(const char *dir)
{
	DIR *d = opendir(dir);
	int n = 0;
	struct dirent *e;
	while (d && (e = readdir(d))) {
		if (!strstr(e->d_name, ".tmp.")) continue;
		char p[8192];
		snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
		unlink(p);
		++n;
	}
	if (d) closedir(d);
	return n;
}

static const char mkIt_Stale[] = "stale,previous\n1,2\n";

static void mkIt_Trial(mkItCase *c, int trial, const char *dir, int landed[3])
{
	static const int sigs[3] = { SIGINT, SIGTERM, SIGKILL };
	int s = (int)(mkIt_Uniform() * 3.0) % 3, stale = mkIt_Uniform() < 0.5;
	for (int k = 0; k < MK_IT_OUTS; ++k) {
		if (!c->out[k][0]) continue;
		unlink(c->out[k]);
		if (stale) {
			FILE *f = fopen(c->out[k], "wb");
			if (!f || fwrite(mkIt_Stale, 1, sizeof mkIt_Stale - 1, f) != sizeof mkIt_Stale - 1) exit(1);
			fclose(f);
		}
	}
	double delay = 1.3 * c->seconds * mkIt_Uniform();
	pid_t pid = mkIt_Start(c);
	struct timespec ts = { (time_t)delay, (long)((delay - (double)(time_t)delay) * 1e9) };
	nanosleep(&ts, NULL);
	kill(pid, sigs[s]);
	int st;
	while (waitpid(pid, &st, 0) < 0 && errno == EINTR) {}
	int killed = WIFSIGNALED(st) && WTERMSIG(st) == sigs[s];
	mkIt_Check(killed || (WIFEXITED(st) && WEXITSTATUS(st) == 0), "ended by the signal or finished", c->name, trial);
	landed[s] += killed;
	int nnew = 0, nold = 0, nout = 0, lastnew = 0;
	for (int k = 0; k < MK_IT_OUTS; ++k) {
		if (!c->out[k][0]) continue;
		++nout;
		long n = 0;
		char *b = mkIt_Read(c->out[k], &n);
		int isnew = b && mkIt_IsNew(c, k, b, n);
		int isold = stale ? b && n == (long)sizeof mkIt_Stale - 1 && memcmp(b, mkIt_Stale, (size_t)n) == 0 : !b;
		mkIt_Check(isnew || isold, "output is the previous or the complete new one", c->name, trial);
		nnew += isnew;
		nold += isold && !isnew;
		if (k == c->last) lastnew = isnew;
		free(b);
	}
	/* INT and TERM are held while the files are renamed: all or none; a
	 * KILL may land between two renames, but never before the last one
	 * with the others still old */
	if (sigs[s] != SIGKILL)
		mkIt_Check(nnew == nout || nold == nout, "outputs committed together are all old or all new", c->name, trial);
	else
		mkIt_Check(!lastnew || nnew == nout, "the output renamed last is new only with all others", c->name, trial);
	if (!killed) mkIt_Check(nnew == nout, "a finished run has its outputs", c->name, trial);
	int temps = mkIt_Temps(dir);
	if (sigs[s] != SIGKILL) mkIt_Check(temps == 0, "no temporary file after SIGINT or SIGTERM", c->name, trial);
}

int main(int argc, char **argv)
{
	if (argc != 7) {
		fprintf(stderr, "usage: test_interrupt MINK DRIVER SCENE3 KILLS SEED WORKDIR\n");
		return 2;
	}
	const char *dir = argv[6];
	int kills = atoi(argv[4]);
	mkIt_Rng ^= (uint64_t)strtoull(argv[5], NULL, 10) * 0x9e3779b97f4a7c15ULL;
	mkdir(dir, 0777);
	static mkItCase cases[3];
	mkItCase *sc = &cases[0], *su = &cases[1], *dr = &cases[2];
	sc->name = "mink scene";
	snprintf(sc->out[0], sizeof sc->out[0], "%s/scene.csv", dir);
	snprintf(sc->out[1], sizeof sc->out[1], "%s/scene.faces.csv", dir);
	snprintf(sc->out[2], sizeof sc->out[2], "%s/scene_report.csv", dir);
	char *a0[] = { argv[1], "scene", argv[3], "--tol", "0.03", "--outer", "--out", sc->out[0], "--report",
		sc->out[2], NULL };
	memcpy(sc->argv, a0, sizeof a0);
	sc->last = 2;
	su->name = "mink sum";
	snprintf(su->out[0], sizeof su->out[0], "%s/sum.csv", dir);
	char *a1[] = { argv[1], "sum", "--dim", "3", "--body1", "superquadric a=3 b=2 c=1 eps1=0.3 eps2=0.6",
		"--body2", "ellipsoid a=1 b=2 c=0.5", "--n", "300", "--contact", "--out", su->out[0], NULL };
	memcpy(su->argv, a1, sizeof a1);
	dr->name = "experiment driver";
	snprintf(dr->out[0], sizeof dr->out[0], "%s/driver.csv", dir);
	snprintf(dr->out[1], sizeof dr->out[1], "%s/driver.csv.meta", dir);
	char *a2[] = { argv[2], "--trials", "100", "--n", "1000", "--force", "--out", dr->out[0], NULL };
	memcpy(dr->argv, a2, sizeof a2);
	/* a run of this test that was itself killed (a ctest timeout) may have
	 * left its child's temporary files here: they are not this run's */
	int old = mkIt_Temps(dir);
	if (old) printf("test_interrupt: removed %d temporary files left by an earlier, killed run\n", old);
	for (int i = 0; i < 3; ++i) {
		mkIt_Reference(&cases[i]);
		int nexact = 0, nout = 0;
		for (int k = 0; k < MK_IT_OUTS; ++k) {
			nout += cases[i].out[k][0] != 0;
			nexact += cases[i].out[k][0] && cases[i].exact[k];
		}
		printf("test_interrupt: %s: reference run %.3f s, %d of %d outputs the same bytes on each run (the "
			"others, with times, checked by lines)\n", cases[i].name, cases[i].seconds, nexact, nout);
	}
	int landed[3] = {0, 0, 0};
	for (int t = 0; t < kills; ++t) mkIt_Trial(&cases[t % 3], t, dir, landed);
	printf("test_interrupt: %d kills: SIGINT %d, SIGTERM %d, SIGKILL %d landed before the end\n", kills, landed[0],
		landed[1], landed[2]);
	printf("test_interrupt: %d passed, %d failed\n", mkIt_Passed, mkIt_Failed);
	return mkIt_Failed ? 1 : 0;
}
