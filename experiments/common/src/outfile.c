/* outfile.c - temporary file + rename, with the registry that the signal
 * handler and the atexit hook clean up. */
#define _POSIX_C_SOURCE 200809L

#include "mink_exp/outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#include <zlib.h>

/* The registry. A slot is published by writing its path first and then
 * setting `used` behind a signal fence, so the handler never reads a half
 * written path. `owner` keeps a forked child from removing its parent's
 * files. */
static char mkSlotPath[MK_OUTFILE_SLOTS][MK_PATH_MAX];
static volatile sig_atomic_t mkSlotUsed[MK_OUTFILE_SLOTS];
static volatile pid_t mkSlotOwner[MK_OUTFILE_SLOTS];
static int mkHooksInstalled = 0;

static const int mkCleanSignals[] = { SIGINT, SIGTERM, SIGHUP };
#define MK_CLEAN_SIGNAL_COUNT ((int)(sizeof mkCleanSignals / sizeof mkCleanSignals[0]))

static void mkRemoveRegistered(void)
{
	pid_t self = getpid();
	for (int i = 0; i < MK_OUTFILE_SLOTS; ++i) {
		if (mkSlotUsed[i] && mkSlotOwner[i] == self)
			unlink(mkSlotPath[i]);
	}
}

static void mkOnSignal(int sig)
{
	int saved = errno;
	mkRemoveRegistered();
	signal(sig, SIG_DFL);
	raise(sig);
	errno = saved;
}

static void mkOnExit(void)
{
	mkRemoveRegistered();
	for (int i = 0; i < MK_OUTFILE_SLOTS; ++i)
		mkSlotUsed[i] = 0;
}

static void mkInstallHooks(void)
{
	if (mkHooksInstalled)
		return;
	mkHooksInstalled = 1;
	atexit(mkOnExit);
	for (int i = 0; i < MK_CLEAN_SIGNAL_COUNT; ++i) {
		struct sigaction old;
		if (sigaction(mkCleanSignals[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
			continue;
		struct sigaction sa;
		memset(&sa, 0, sizeof sa);
		sa.sa_handler = mkOnSignal;
		sigemptyset(&sa.sa_mask);
		/* Hold the other cleaning signals while one is handled. */
		for (int j = 0; j < MK_CLEAN_SIGNAL_COUNT; ++j)
			sigaddset(&sa.sa_mask, mkCleanSignals[j]);
		sigaction(mkCleanSignals[i], &sa, NULL);
	}
}

static int mkRegister(const char *temp)
{
	for (int i = 0; i < MK_OUTFILE_SLOTS; ++i) {
		if (!mkSlotUsed[i]) {
			memcpy(mkSlotPath[i], temp, strlen(temp) + 1);
			mkSlotOwner[i] = getpid();
			atomic_signal_fence(memory_order_seq_cst);
			mkSlotUsed[i] = 1;
			return i;
		}
	}
	return -1;
}

static void mkUnregister(int slot)
{
	if (slot >= 0 && slot < MK_OUTFILE_SLOTS) {
		mkSlotUsed[slot] = 0;
		atomic_signal_fence(memory_order_seq_cst);
	}
}

static void mkMessage(char *msg, size_t msglen, const char *what, const char *path, int err)
{
	if (msg && msglen > 0)
		snprintf(msg, msglen, "%s %s: %s", what, path, strerror(err));
}

int mkPath_IsGz(const char *path)
{
	size_t n = strlen(path);
	return n > 3 && strcmp(path + n - 3, ".gz") == 0;
}

/* A gz result's plain text: a scratch file beside it, unlinked at once so
 * that nothing is left behind whatever ends the process. Returns its fd or
 * -1. Called with the cleaning signals held. */
static int mkScratch_Open(const char *path)
{
	char name[MK_PATH_MAX];
	snprintf(name, sizeof name, "%s.tmp.XXXXXX", path);
	int fd = mkstemp(name);
	if (fd >= 0)
		unlink(name);
	return fd;
}

int mkOutFile_Open(mkOutFile *f, const char *path, char *msg, size_t msglen)
{
	f->fp = NULL;
	f->slot = -1;
	f->gz = mkPath_IsGz(path);
	f->fd = -1;
	f->path[0] = '\0';
	f->temp[0] = '\0';
	size_t len = strlen(path);
	if (len == 0 || len + 12 >= MK_PATH_MAX) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "output path is empty or longer than %d bytes", MK_PATH_MAX - 13);
		return -1;
	}
	memcpy(f->path, path, len + 1);
	snprintf(f->temp, sizeof f->temp, "%s.tmp.XXXXXX", path);

	mkInstallHooks();
	/* Hold the cleaning signals while the file is created and registered,
	 * so that none can arrive between the two and leave it unregistered. */
	sigset_t block, old;
	sigemptyset(&block);
	for (int i = 0; i < MK_CLEAN_SIGNAL_COUNT; ++i)
		sigaddset(&block, mkCleanSignals[i]);
	sigprocmask(SIG_BLOCK, &block, &old);
	int fd = mkstemp(f->temp);
	int err = errno;
	if (fd >= 0) {
		f->slot = mkRegister(f->temp);
		if (f->slot < 0) {
			close(fd);
			unlink(f->temp);
			sigprocmask(SIG_SETMASK, &old, NULL);
			if (msg && msglen > 0)
				snprintf(msg, msglen, "too many result files open at once (at most %d)", MK_OUTFILE_SLOTS);
			return -1;
		}
	}
	int text = fd >= 0 && f->gz ? mkScratch_Open(path) : fd;
	int text_err = errno;
	sigprocmask(SIG_SETMASK, &old, NULL);
	if (fd < 0) {
		mkMessage(msg, msglen, "cannot create a temporary file beside", path, err);
		return -1;
	}
	if (f->gz)
		f->fd = fd;

	/* mkstemp makes the file 0600; give it the mode fopen would. */
	mode_t mask = umask(0);
	umask(mask);
	if (text < 0 || fchmod(fd, 0666 & ~mask) != 0) {
		err = text < 0 ? text_err : errno;
		if (text >= 0)
			close(text); /* fd itself when not gz; else f->fd is closed below */
		mkOutFile_Discard(f);
		mkMessage(msg, msglen, text < 0 ? "cannot create a scratch file beside" : "cannot set the mode of",
			text < 0 ? path : f->temp, err);
		return -1;
	}
	f->fp = fdopen(text, f->gz ? "w+" : "w");
	if (!f->fp) {
		err = errno;
		close(text);
		mkOutFile_Discard(f);
		mkMessage(msg, msglen, "cannot open", f->temp, err);
		return -1;
	}
	return 0;
}

void mkOutFile_Discard(mkOutFile *f)
{
	if (f->fp) {
		fclose(f->fp);
		f->fp = NULL;
	}
	if (f->fd >= 0) {
		close(f->fd);
		f->fd = -1;
	}
	if (f->slot >= 0) {
		unlink(f->temp);
		mkUnregister(f->slot);
		f->slot = -1;
	}
}

/* Make the rename itself durable: sync the directory that holds the file.
 * Best effort; some file systems refuse fsync on a directory. */
static void mkSyncParent(const char *path)
{
	char dir[MK_PATH_MAX];
	const char *slash = strrchr(path, '/');
	if (!slash) {
		strcpy(dir, ".");
	} else if (slash == path) {
		strcpy(dir, "/");
	} else {
		size_t n = (size_t)(slash - path);
		memcpy(dir, path, n);
		dir[n] = '\0';
	}
	int fd = open(dir, O_RDONLY);
	if (fd >= 0) {
		(void)fsync(fd);
		close(fd);
	}
}

/* Deflate the plain text `in` (from its start) into `out` as gzip: zlib's
 * default header (no name, time 0), level MK_GZ_LEVEL. Returns 0, or -1
 * (errno set, EIO when zlib failed). */
static int mkGz_Deflate(FILE *in, FILE *out)
{
	unsigned char src[1 << 15], dst[1 << 15];
	z_stream z;
	memset(&z, 0, sizeof z);
	if (fseek(in, 0, SEEK_SET) != 0)
		return -1;
	if (deflateInit2(&z, MK_GZ_LEVEL, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
		errno = ENOMEM;
		return -1;
	}
	int flush = Z_NO_FLUSH, ok = 1;
	while (ok && flush != Z_FINISH) {
		z.avail_in = (uInt)fread(src, 1, sizeof src, in);
		z.next_in = src;
		ok = !ferror(in);
		flush = feof(in) ? Z_FINISH : Z_NO_FLUSH;
		do {
			z.avail_out = sizeof dst;
			z.next_out = dst;
			int rc = deflate(&z, flush);
			size_t have = sizeof dst - z.avail_out;
			ok = ok && rc != Z_STREAM_ERROR && fwrite(dst, 1, have, out) == have;
		} while (ok && z.avail_out == 0);
	}
	deflateEnd(&z);
	if (ok)
		return 0;
	if (errno == 0)
		errno = EIO;
	return -1;
}

/* A gz result: the plain text compressed into the temporary file, which
 * then becomes f->fp (the scratch file is closed, and so gone). */
static int mkOutFile_Compress(mkOutFile *f)
{
	if (ferror(f->fp) || fflush(f->fp) != 0)
		return -1;
	FILE *out = fdopen(f->fd, "w");
	if (!out)
		return -1;
	f->fd = -1;
	int bad = mkGz_Deflate(f->fp, out) != 0;
	int err = errno;
	fclose(f->fp);
	f->fp = out;
	errno = err;
	return bad ? -1 : 0;
}

/* Flush, sync and close; on failure remove the temporary file. */
static int mkOutFile_Finish(mkOutFile *f, char *msg, size_t msglen)
{
	if (!f->fp || f->slot < 0) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "commit of a result file that is not open");
		return -1;
	}
	errno = 0;
	int bad = (f->gz && mkOutFile_Compress(f) != 0) || ferror(f->fp) || fflush(f->fp) != 0;
	int err = errno;
	if (!bad && fsync(fileno(f->fp)) != 0) {
		bad = 1;
		err = errno;
	}
	if (fclose(f->fp) != 0 && !bad) {
		bad = 1;
		err = errno;
	}
	f->fp = NULL;
	if (bad) {
		mkMessage(msg, msglen, "write error on", f->temp, err ? err : EIO);
		mkOutFile_Discard(f);
		return -1;
	}
	return 0;
}

int mkOutFile_CommitAll(mkOutFile *const *files, int count, char *msg, size_t msglen)
{
	int ok = 1;
	for (int i = 0; i < count && ok; ++i)
		ok = mkOutFile_Finish(files[i], msg, msglen) == 0;
	if (!ok) {
		for (int i = 0; i < count; ++i)
			mkOutFile_Discard(files[i]);
		return -1;
	}

	sigset_t block, old;
	sigemptyset(&block);
	for (int i = 0; i < MK_CLEAN_SIGNAL_COUNT; ++i)
		sigaddset(&block, mkCleanSignals[i]);
	sigprocmask(SIG_BLOCK, &block, &old);
	for (int i = 0; i < count; ++i) {
		mkOutFile *f = files[i];
		if (ok && rename(f->temp, f->path) != 0) {
			ok = 0;
			mkMessage(msg, msglen, "cannot rename the temporary file onto", f->path, errno);
		}
		if (ok) {
			mkUnregister(f->slot);
			f->slot = -1;
		} else {
			mkOutFile_Discard(f);
		}
	}
	sigprocmask(SIG_SETMASK, &old, NULL);
	for (int i = 0; ok && i < count; ++i)
		mkSyncParent(files[i]->path);
	return ok ? 0 : -1;
}

int mkOutFile_Commit(mkOutFile *f, char *msg, size_t msglen)
{
	mkOutFile *one[1] = { f };
	return mkOutFile_CommitAll(one, 1, msg, msglen);
}

int mkPath_MakeParents(const char *path, char *msg, size_t msglen)
{
	char buf[MK_PATH_MAX];
	size_t len = strlen(path);
	if (len >= sizeof buf) {
		if (msg && msglen > 0)
			snprintf(msg, msglen, "path longer than %d bytes", MK_PATH_MAX - 1);
		return -1;
	}
	memcpy(buf, path, len + 1);
	char *slash = strrchr(buf, '/');
	if (!slash || slash == buf)
		return 0;
	*slash = '\0';
	/* Walk forward, creating each missing component. */
	for (char *p = buf + 1; ; ++p) {
		if (*p == '/' || *p == '\0') {
			char keep = *p;
			*p = '\0';
			if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
				mkMessage(msg, msglen, "cannot create directory", buf, errno);
				return -1;
			}
			struct stat st;
			if (stat(buf, &st) != 0 || !S_ISDIR(st.st_mode)) {
				if (msg && msglen > 0)
					snprintf(msg, msglen, "%s exists and is not a directory", buf);
				return -1;
			}
			*p = keep;
			if (keep == '\0')
				break;
		}
	}
	return 0;
}

int mkPath_Exists(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0;
}

int mkPath_PrepareOutput(const char *prog, const char *path, int force)
{
	if (!force && mkPath_Exists(path)) {
		fprintf(stderr, "%s: %s exists; pass --force to replace it\n", prog, path);
		return 1;
	}
	char msg[1024];
	if (mkPath_MakeParents(path, msg, sizeof msg) != 0) {
		fprintf(stderr, "%s: %s\n", prog, msg);
		return 1;
	}
	return 0;
}
