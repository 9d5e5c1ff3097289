/* external.c - methods defined at run time by a command (mink/external.h):
 * one child process per method, kept across calls, spoken to over pipes in
 * the line protocol of docs/compare.md. POSIX (fork, pipe, poll). */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <mink/external.h>
#include <mink/registry.h>

typedef struct mkExternal_Slot {
	mkMethod method;
	char spec[1024];   /* the name given, "exec:..." */
	char name[128];
	const char *command;
	pid_t pid;         /* 0: not running */
	int to, from;      /* pipe ends: the child's stdin, its stdout */
	char buf[1 << 16]; /* read buffer of the child's output */
	size_t have;
	long jobs;
	double seconds;
	const char *status;
	char message[256];
	pthread_mutex_t lock; /* one call at a time per process */
} mkExternal_Slot;

static mkExternal_Slot mkExternal_Slots[MK_EXTERNAL_MAX];
static int mkExternal_Used;
static double mkExternal_Limit = 60.0;
static double mkExternal_Startup = MK_EXTERNAL_STARTUP;

/* ---- the process ------------------------------------------------------------- */

static void mkExternal_Stop(mkExternal_Slot *s)
{
	if (s->pid > 0) {
		close(s->to);
		close(s->from);
		kill(-s->pid, SIGKILL);
		kill(s->pid, SIGKILL);
		waitpid(s->pid, NULL, 0);
	}
	s->pid = 0;
	s->have = 0;
}

static int mkExternal_Start(mkExternal_Slot *s)
{
	int in[2], out[2];
	if (pipe(in) != 0) return -1;
	if (pipe(out) != 0) {
		close(in[0]);
		close(in[1]);
		return -1;
	}
	pid_t pid = fork();
	if (pid < 0) {
		close(in[0]), close(in[1]), close(out[0]), close(out[1]);
		return -1;
	}
	if (pid == 0) {
		setpgid(0, 0); /* its own process group: stopping it stops its children too */
		dup2(in[0], 0);
		dup2(out[1], 1);
		close(in[0]), close(in[1]), close(out[0]), close(out[1]);
		execl("/bin/sh", "sh", "-c", s->command, (char *)NULL);
		_exit(127);
	}
	close(in[0]);
	close(out[1]);
	signal(SIGPIPE, SIG_IGN); /* a crashed child must not take the caller along */
	s->pid = pid;
	s->to = in[1];
	s->from = out[0];
	s->have = 0;
	s->jobs = 0;
	return 0;
}

static int mkExternal_Fail(mkExternal_Slot *s, const char *status, const char *what)
{
	s->status = status;
	snprintf(s->message, sizeof s->message, "%.200s", what);
	mkExternal_Stop(s);
	return -1;
}

static double mkExternal_Now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The next line of the child's output into line (no newline); -1 after
 * mkExternal_Fail on end of output, time out or an over-long line. */
static int mkExternal_Line(mkExternal_Slot *s, double deadline, char *line, size_t len)
{
	for (;;) {
		char *nl = memchr(s->buf, '\n', s->have);
		if (nl) {
			size_t n = (size_t)(nl - s->buf);
			if (n >= len) return mkExternal_Fail(s, "garbage", "an answer line is too long");
			memcpy(line, s->buf, n);
			line[n] = '\0';
			if (n && line[n - 1] == '\r') line[n - 1] = '\0';
			memmove(s->buf, nl + 1, s->have - n - 1);
			s->have -= n + 1;
			return 0;
		}
		if (s->have == sizeof s->buf) return mkExternal_Fail(s, "garbage", "an answer line is too long");
		double left = deadline - mkExternal_Now();
		if (left <= 0) return mkExternal_Fail(s, "timeout", "no answer within the time limit (process killed)");
		struct pollfd p = {s->from, POLLIN, 0};
		int r = poll(&p, 1, (int)fmin(left * 1000.0 + 1.0, 2e9));
		if (r < 0 && errno == EINTR) continue;
		if (r == 0) continue;
		ssize_t got = r < 0 ? -1 : read(s->from, s->buf + s->have, sizeof s->buf - s->have);
		if (got < 0 && errno == EINTR) continue;
		if (got <= 0) {
			int st = 0;
			char what[128];
			/* The output closed: give the process a second to exit, so that
			 * the message can say how it ended. */
			pid_t done = 0;
			for (int i = 0; i < 100 && (done = waitpid(s->pid, &st, WNOHANG)) == 0; ++i)
				nanosleep(&(struct timespec){0, 10000000L}, NULL);
			if (done == s->pid) {
				s->pid = -s->pid; /* reaped */
				if (WIFSIGNALED(st))
					snprintf(what, sizeof what, "the process died of signal %d", WTERMSIG(st));
				else
					snprintf(what, sizeof what, "the process exited with status %d", WEXITSTATUS(st));
			} else
				snprintf(what, sizeof what, "the process closed its output");
			if (s->pid < 0) {
				kill(s->pid, SIGKILL); /* what is left of its process group */
				close(s->to), close(s->from);
				s->pid = 0;
			}
			return mkExternal_Fail(s, "crashed", what);
		}
		s->have += (size_t)got;
	}
}

/* ---- the protocol ------------------------------------------------------------ */

static int mkExternal_Write(mkExternal_Slot *s, const char *text)
{
	size_t len = strlen(text), done = 0;
	while (done < len) {
		ssize_t w = write(s->to, text + done, len - done);
		if (w < 0 && errno == EINTR) continue;
		if (w <= 0) return mkExternal_Fail(s, "crashed", "the process does not read its input");
		done += (size_t)w;
	}
	return 0;
}

/* Parse up to dim numbers separated by spaces or commas; 0 when exactly dim. */
static int mkExternal_Numbers(const char *line, int dim, double *v)
{
	const char *p = line;
	for (int i = 0; i < dim; ++i) {
		while (*p == ' ' || *p == '\t' || (i > 0 && *p == ',')) ++p;
		char *end;
		v[i] = strtod(p, &end);
		if (end == p) return -1;
		p = end;
	}
	while (*p == ' ' || *p == '\t') ++p;
	return *p ? -1 : 0;
}

/* Read one answer into out (dimension dim). */
static int mkExternal_Answer(mkExternal_Slot *s, int dim, double deadline, mkPointSet *out)
{
	char line[4096], what[160];
	long count = -1;
	do {
		if (mkExternal_Line(s, deadline, line, sizeof line)) return -1;
	} while (line[0] == '#' || line[0] == '\0');
	if (strncmp(line, "error", 5) == 0 && (line[5] == ' ' || line[5] == '\0')) {
		s->status = "error";
		snprintf(s->message, sizeof s->message, "%.200s", line[5] ? line + 6 : "error");
		return -1;
	}
	char *end;
	if (strncmp(line, "points ", 7) == 0) count = strtol(line + 7, &end, 10);
	if (count < 0 || count > 100000000 || strncmp(line, "points ", 7) != 0 || *end) {
		snprintf(what, sizeof what, "expected 'points COUNT', got '%.60s'", line);
		return mkExternal_Fail(s, "garbage", what);
	}
	if (mkPointSet_Resize(out, dim, (int)count) != MK_OK) return mkExternal_Fail(s, "garbage", "too many points");
	for (long k = 0; k < count; ++k) {
		double v[3];
		if (mkExternal_Line(s, deadline, line, sizeof line)) return -1;
		if (mkExternal_Numbers(line, dim, v)) {
			snprintf(what, sizeof what, "point %ld: expected %d numbers, got '%.60s'", k, dim, line);
			return mkExternal_Fail(s, "garbage", what);
		}
		out->x[k] = v[0];
		out->y[k] = v[1];
		if (dim == 3) out->z[k] = v[2];
	}
	if (mkExternal_Line(s, deadline, line, sizeof line)) return -1;
	double sec = -1;
	if (strncmp(line, "seconds ", 8) == 0) sec = strtod(line + 8, &end);
	if (strncmp(line, "seconds ", 8) != 0 || *end || !(sec >= 0) || !isfinite(sec)) {
		snprintf(what, sizeof what, "expected 'seconds S' (S >= 0), got '%.60s'", line);
		return mkExternal_Fail(s, "garbage", what);
	}
	s->seconds = sec;
	return 0;
}

static void mkExternal_Params2(mkBody2 b, char *buf, size_t len)
{
	snprintf(buf, len, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", b.shape.a, b.shape.b, b.shape.eps,
		b.M.m[0][0], b.M.m[0][1], b.M.m[1][0], b.M.m[1][1], b.t.x, b.t.y);
}

static void mkExternal_Params3(mkBody3 b, char *buf, size_t len)
{
	const double *m = &b.M.m[0][0];
	snprintf(buf, len, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
		"%.17g %.17g", b.shape.a, b.shape.b, b.shape.c, b.shape.eps1, b.shape.eps2, m[0], m[1], m[2], m[3], m[4],
		m[5], m[6], m[7], m[8], b.t.x, b.t.y, b.t.z);
}

/* One call: the job (bodies already as SPEC and parameter text) out, the
 * answer in. */
static mkResult mkExternal_CallLocked(mkExternal_Slot *s, int dim, mkSet set, int n, const char *const text[4],
	mkPointSet *out)
{
	s->seconds = NAN;
	if (n < 1) return MK_ERR_RANGE;
	int fresh = s->pid <= 0;
	if (fresh && mkExternal_Start(s) != 0) {
		mkExternal_Fail(s, "crashed", "the process could not be started");
		return MK_ERR_UNSUPPORTED;
	}
	char job[8192];
	snprintf(job, sizeof job, "job %ld\ndim %d\nset %s\nn %d\nbody1 %s\nbody2 %s\nparams1 %s\nparams2 %s\nend\n",
		++s->jobs, dim, set == MK_SET_PLUS ? "plus" : "contact", n, text[0], text[1], text[2], text[3]);
	/* The first job of a process also waits for its start-up. */
	double deadline = mkExternal_Now() + mkExternal_Limit + (fresh ? mkExternal_Startup : 0.0);
	if (mkExternal_Write(s, job) || mkExternal_Answer(s, dim, deadline, out)) {
		out->count = 0;
		return MK_ERR_UNSUPPORTED;
	}
	s->status = "ok";
	s->message[0] = '\0';
	return MK_OK;
}

static mkResult mkExternal_Call(mkExternal_Slot *s, int dim, mkSet set, int n, const char *const text[4],
	mkPointSet *out)
{
	pthread_mutex_lock(&s->lock);
	mkResult r = mkExternal_CallLocked(s, dim, set, n, text, out);
	pthread_mutex_unlock(&s->lock);
	return r;
}

static mkResult mkExternal_Run2(int slot, mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	char t[4][1024];
	mkSpec2_Format(b1, t[0], sizeof t[0]);
	mkSpec2_Format(b2, t[1], sizeof t[1]);
	mkExternal_Params2(b1, t[2], sizeof t[2]);
	mkExternal_Params2(b2, t[3], sizeof t[3]);
	const char *text[4] = {t[0], t[1], t[2], t[3]};
	return mkExternal_Call(&mkExternal_Slots[slot], 2, set, n, text, out);
}

static mkResult mkExternal_Run3(int slot, mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	char t[4][1024];
	mkSpec3_Format(b1, t[0], sizeof t[0]);
	mkSpec3_Format(b2, t[1], sizeof t[1]);
	mkExternal_Params3(b1, t[2], sizeof t[2]);
	mkExternal_Params3(b2, t[3], sizeof t[3]);
	const char *text[4] = {t[0], t[1], t[2], t[3]};
	return mkExternal_Call(&mkExternal_Slots[slot], 3, set, n, text, out);
}

/* An mkMethod's run functions take no context: one pair per slot. */
static mkResult mkExt2_0(mkBody2 a, mkBody2 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run2(0, a, b, s, n, o); }
static mkResult mkExt2_1(mkBody2 a, mkBody2 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run2(1, a, b, s, n, o); }
static mkResult mkExt2_2(mkBody2 a, mkBody2 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run2(2, a, b, s, n, o); }
static mkResult mkExt2_3(mkBody2 a, mkBody2 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run2(3, a, b, s, n, o); }
static mkResult mkExt2_4(mkBody2 a, mkBody2 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run2(4, a, b, s, n, o); }
static mkResult mkExt2_5(mkBody2 a, mkBody2 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run2(5, a, b, s, n, o); }
static mkResult mkExt2_6(mkBody2 a, mkBody2 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run2(6, a, b, s, n, o); }
static mkResult mkExt2_7(mkBody2 a, mkBody2 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run2(7, a, b, s, n, o); }
static mkResult mkExt3_0(mkBody3 a, mkBody3 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run3(0, a, b, s, n, o); }
static mkResult mkExt3_1(mkBody3 a, mkBody3 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run3(1, a, b, s, n, o); }
static mkResult mkExt3_2(mkBody3 a, mkBody3 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run3(2, a, b, s, n, o); }
static mkResult mkExt3_3(mkBody3 a, mkBody3 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run3(3, a, b, s, n, o); }
static mkResult mkExt3_4(mkBody3 a, mkBody3 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run3(4, a, b, s, n, o); }
static mkResult mkExt3_5(mkBody3 a, mkBody3 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run3(5, a, b, s, n, o); }
static mkResult mkExt3_6(mkBody3 a, mkBody3 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run3(6, a, b, s, n, o); }
static mkResult mkExt3_7(mkBody3 a, mkBody3 b, mkSet s, int n, mkPointSet *o) { return mkExternal_Run3(7, a, b, s, n, o); }

typedef mkResult (*mkExt2Fn)(mkBody2, mkBody2, mkSet, int, mkPointSet *);
typedef mkResult (*mkExt3Fn)(mkBody3, mkBody3, mkSet, int, mkPointSet *);
static const mkExt2Fn mkExt2[MK_EXTERNAL_MAX] = {mkExt2_0, mkExt2_1, mkExt2_2, mkExt2_3, mkExt2_4, mkExt2_5, mkExt2_6, mkExt2_7};
static const mkExt3Fn mkExt3[MK_EXTERNAL_MAX] = {mkExt3_0, mkExt3_1, mkExt3_2, mkExt3_3, mkExt3_4, mkExt3_5, mkExt3_6, mkExt3_7};

/* ---- registration ------------------------------------------------------------ */

static int mkExternal_NameChar(int c)
{
	return isalnum(c) || c == '.' || c == '_' || c == '-';
}

/* "NAME=COMMAND" or COMMAND: the name into s->name, s->command set. */
static int mkExternal_Name(mkExternal_Slot *s, char *msg, size_t msglen)
{
	const char *body = s->spec + 5, *eq = body;
	while (mkExternal_NameChar((unsigned char)*eq)) ++eq;
	if (*eq == '=' && eq > body) {
		size_t len = (size_t)(eq - body) < sizeof s->name - 1 ? (size_t)(eq - body) : sizeof s->name - 1;
		memcpy(s->name, body, len);
		s->name[len] = '\0';
		s->command = eq + 1;
	} else {
		s->command = body;
		const char *end = body + strlen(body);
		while (end > body && isspace((unsigned char)end[-1])) --end;
		const char *word = end;
		while (word > body && !isspace((unsigned char)word[-1])) --word;
		const char *slash = word;
		for (const char *p = word; p < end; ++p)
			if (*p == '/') slash = p + 1;
		const char *dot = end;
		for (const char *p = slash; p < end; ++p)
			if (*p == '.') dot = p;
		size_t k = strlen(strcpy(s->name, "exec-"));
		for (const char *p = slash; p < (dot > slash ? dot : end) && k + 1 < sizeof s->name; ++p)
			s->name[k++] = mkExternal_NameChar((unsigned char)*p) ? (char)tolower((unsigned char)*p) : '_';
		s->name[k] = '\0';
	}
	const char *c = s->command;
	while (isspace((unsigned char)*c)) ++c;
	if (!*c) return mkRefuse(msg, msglen, "%s: the command is empty (use exec:COMMAND or exec:NAME=COMMAND)", s->spec);
	return 1;
}

const mkMethod *mkExternal_Find(const char *name, char *msg, size_t msglen)
{
	if (!name || strncmp(name, "exec:", 5) != 0) {
		mkRefuse(msg, msglen, "an external method is named exec:COMMAND or exec:NAME=COMMAND");
		return NULL;
	}
	for (int i = 0; i < mkExternal_Used; ++i)
		if (strcmp(mkExternal_Slots[i].spec, name) == 0 || strcmp(mkExternal_Slots[i].name, name) == 0)
			return &mkExternal_Slots[i].method;
	if (mkExternal_Used == MK_EXTERNAL_MAX) {
		mkRefuse(msg, msglen, "%s: at most %d external methods", name, MK_EXTERNAL_MAX);
		return NULL;
	}
	if (strlen(name) >= sizeof mkExternal_Slots[0].spec) {
		mkRefuse(msg, msglen, "%.40s...: the command is too long", name);
		return NULL;
	}
	mkExternal_Slot *s = &mkExternal_Slots[mkExternal_Used];
	memset(s, 0, sizeof *s);
	strcpy(s->spec, name);
	if (!mkExternal_Name(s, msg, msglen)) return NULL;
	for (int i = 0; i < mkExternal_Used; ++i)
		if (strcmp(mkExternal_Slots[i].name, s->name) == 0) {
			mkRefuse(msg, msglen, "%s: the name %s is taken by %s; give one with exec:NAME=COMMAND", name, s->name,
				mkExternal_Slots[i].spec);
			return NULL;
		}
	s->status = "ok";
	s->seconds = NAN;
	pthread_mutex_init(&s->lock, NULL);
	const char *limit = getenv("MINK_EXEC_TIMEOUT");
	if (limit && mkExternal_Used == 0) mkExternal_SetTimeLimit(atof(limit));
	const char *startup = getenv("MINK_EXEC_STARTUP");
	if (startup && mkExternal_Used == 0 && atof(startup) >= 0) mkExternal_Startup = atof(startup);
	s->method = (mkMethod){s->name, "external method (mink/external.h)", s->spec, MK_METHOD_2D | MK_METHOD_3D,
		mkAcceptAny2, mkAcceptAny3, mkExt2[mkExternal_Used], mkExt3[mkExternal_Used]};
	++mkExternal_Used;
	if (msg && msglen) msg[0] = '\0';
	return &s->method;
}

static mkExternal_Slot *mkExternal_SlotOf(const mkMethod *m)
{
	for (int i = 0; i < mkExternal_Used; ++i)
		if (m == &mkExternal_Slots[i].method) return &mkExternal_Slots[i];
	return NULL;
}

int mkExternal_Count(void)
{
	return mkExternal_Used;
}

const mkMethod *mkExternal_At(int i)
{
	return i >= 0 && i < mkExternal_Used ? &mkExternal_Slots[i].method : NULL;
}

int mkExternal_Is(const mkMethod *m)
{
	return mkExternal_SlotOf(m) != NULL;
}

double mkExternal_Seconds(const mkMethod *m)
{
	mkExternal_Slot *s = mkExternal_SlotOf(m);
	return s ? s->seconds : NAN;
}

const char *mkExternal_Status(const mkMethod *m)
{
	mkExternal_Slot *s = mkExternal_SlotOf(m);
	return s ? s->status : "ok";
}

const char *mkExternal_Message(const mkMethod *m)
{
	mkExternal_Slot *s = mkExternal_SlotOf(m);
	return s ? s->message : "";
}

void mkExternal_SetTimeLimit(double seconds)
{
	if (seconds > 0) mkExternal_Limit = seconds;
}

void mkExternal_StopAll(void)
{
	for (int i = 0; i < mkExternal_Used; ++i) mkExternal_Stop(&mkExternal_Slots[i]);
}

/* ---- SPEC text ---------------------------------------------------------------- */

void mkSpec2_Format(mkBody2 b, char *buf, size_t len)
{
	snprintf(buf, len, "superellipse a=%.17g b=%.17g eps=%.17g M=%.17g,%.17g,%.17g,%.17g at=%.17g,%.17g",
		b.shape.a, b.shape.b, b.shape.eps, b.M.m[0][0], b.M.m[0][1], b.M.m[1][0], b.M.m[1][1], b.t.x, b.t.y);
}

void mkSpec3_Format(mkBody3 b, char *buf, size_t len)
{
	const double *m = &b.M.m[0][0];
	snprintf(buf, len, "superquadric a=%.17g b=%.17g c=%.17g eps1=%.17g eps2=%.17g "
		"M=%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g at=%.17g,%.17g,%.17g",
		b.shape.a, b.shape.b, b.shape.c, b.shape.eps1, b.shape.eps2, m[0], m[1], m[2], m[3], m[4], m[5], m[6],
		m[7], m[8], b.t.x, b.t.y, b.t.z);
}
