/* mink_exp/outfile.h - result files that appear whole or not at all.
 *
 * A result file is written under a temporary name in the same directory
 * ("<path>.tmp.XXXXXX", from mkstemp) and renamed onto its final name only
 * when the writer commits. rename() within one file system is atomic, so a
 * reader sees either the previous file or the complete new one.
 *
 * Interruption. While a temporary file is open its name is registered; on
 * SIGINT, SIGTERM or SIGHUP a handler removes every registered temporary
 * file of this process (unlink is async-signal-safe), restores the default
 * action and raises the signal again, so the process still ends as killed
 * by that signal. A normal exit (exit() or return from main) without a
 * commit removes them too (atexit). Only SIGKILL or a crash leaves a
 * "*.tmp.*" file behind, never a file under the final name. A signal whose
 * action was SIG_IGN when the first file was opened (nohup) stays ignored.
 *
 * Compression. A path ending in ".gz" is written as gzip (zlib's deflate at
 * level MK_GZ_LEVEL, a header with no file name and no time stamp), so that
 * the same text always gives the same bytes. The writer still writes plain
 * text through `fp`: it goes to a scratch file that is unlinked as soon as
 * it is created (nothing is left behind, even after SIGKILL), and the commit
 * compresses it into the temporary file before the rename. */
#ifndef MINK_EXP_OUTFILE_H
#define MINK_EXP_OUTFILE_H

#include <stddef.h>
#include <stdio.h>

#define MK_PATH_MAX 4096
/* At most this many temporary files may be open at once in one process. */
#define MK_OUTFILE_SLOTS 16
/* The deflate level of ".gz" results: zlib's default, half the time of 9
 * for 3 % more bytes. Changing it changes the bytes of every .gz result. */
#define MK_GZ_LEVEL 6

typedef struct mkOutFile {
	FILE *fp;      /* write through this; NULL when not open */
	int slot;      /* registry slot, -1 when not registered */
	int gz;        /* the path ends in ".gz": fp is the plain scratch file */
	int fd;        /* gz: the registered temporary file, -1 when closed */
	char path[MK_PATH_MAX];
	char temp[MK_PATH_MAX];
} mkOutFile;

/* Create the temporary file for `path`. Fails (returns -1 and writes a
 * one-line message) when the path is too long, the directory does not exist
 * or is not writable, or all slots are in use. Returns 0 on success. The
 * final file is created with mode 0666 minus the umask, like fopen. */
int mkOutFile_Open(mkOutFile *f, const char *path, char *msg, size_t msglen);

/* Flush, sync, close and rename onto the final name (replacing any file
 * there). Fails on any write error seen so far (the temporary file is then
 * removed and the final name untouched). Returns 0 on success. */
int mkOutFile_Commit(mkOutFile *f, char *msg, size_t msglen);

/* Commit several files together: every file is flushed, synced and closed
 * first; only when all of them succeeded are they renamed, in the given
 * order, with the cleaning signals held, so that an interruption cannot
 * publish some of them and not the others. On failure every file that was
 * not yet renamed is removed. Returns 0, or -1 with a message. */
int mkOutFile_CommitAll(mkOutFile *const *files, int count, char *msg, size_t msglen);

/* Close and remove the temporary file; the final name is untouched. Safe on
 * a file that is not open. */
void mkOutFile_Discard(mkOutFile *f);

/* Create the missing parent directories of `path` (mode 0777 minus the
 * umask). Returns 0 on success or when there is nothing to create. */
int mkPath_MakeParents(const char *path, char *msg, size_t msglen);

/* 1 when path ends in ".gz" (the result is written compressed). */
int mkPath_IsGz(const char *path);

/* 1 when a file (of any kind) exists at path. */
int mkPath_Exists(const char *path);

/* A driver's check of its --out before any work: refuses an existing file
 * unless `force`, then creates the missing parent directories. Returns 0,
 * or 1 after printing "<prog>: <why>" on stderr (the driver's exit status). */
int mkPath_PrepareOutput(const char *prog, const char *path, int force);

#endif
