/* mink/external.h - methods defined at run time by a command: an algorithm
 * in any language enters every study as a registry method.
 *
 * A method name "exec:COMMAND" or "exec:NAME=COMMAND" (NAME of letters,
 * digits, '.', '_', '-') given to mkRegistry_Find registers an external
 * method that runs COMMAND with /bin/sh -c. Its name in tables and figures
 * is NAME, or "exec-STEM" with STEM the file name (without directory and
 * extension) of the command's last word: "exec:python3 tools/grid.py" is
 * "exec-grid". At most MK_EXTERNAL_MAX external methods per process. It is
 * flagged MK_METHOD_2D | MK_METHOD_3D, promises nothing else (not exact,
 * not sampled) and its points are unordered (MK_INDEX_UNORDERED): the
 * referee cannot judge them, `mink score` and the error measure can.
 *
 * The protocol (docs/compare.md). The process is started at the first call
 * and kept: every call writes one job to its standard input and reads one
 * answer from its standard output, so process start-up is paid once and
 * never timed. A job is text lines:
 *   job K            (K = 1, 2, ... per process)
 *   dim D            (2 or 3)
 *   set contact|plus
 *   n N              (the resolution asked for)
 *   body1 SPEC       (mink/spec.h, every number %.17g: parses back exactly)
 *   body2 SPEC
 *   params1 a b eps M11 M12 M21 M22 tx ty          (3D: a b c eps1 eps2 M11..M33 tx ty tz)
 *   params2 ...
 *   end
 * The answer: "points COUNT", COUNT lines of D numbers (space- or
 * comma-separated), then "seconds S", the method's own measured time for
 * the job (what the studies report as its time); or one line "error TEXT".
 * Lines before "points" that start with # are skipped.
 *
 * Failures are the method's, never the caller's: a process that exits or
 * closes its output (crash), answers nothing within the time limit (hang;
 * the process is killed), or answers what the protocol does not allow
 * (garbage: a bad count, a missing or non-numeric value, a negative or
 * missing time) makes the call return MK_ERR_UNSUPPORTED, with
 * mkExternal_Status (crashed, timeout, garbage, error) and
 * mkExternal_Message saying what happened; the next call starts the
 * process again. Not thread-safe: one caller thread per process. */
#ifndef MINK_EXTERNAL_H
#define MINK_EXTERNAL_H

#include <stddef.h>
#include <mink/mink.h>

MK_EXTERN_C_BEGIN

#define MK_EXTERNAL_MAX 8
/* Seconds a process's first answer may take on top of the time limit, for
 * its start-up (an interpreter's can take seconds on a loaded machine);
 * the environment variable MINK_EXEC_STARTUP, when set at the first
 * registration, replaces it. */
#define MK_EXTERNAL_STARTUP 30.0

/* The external method of this name (registered on first use; see above);
 * NULL when name does not start with "exec:", the command is empty, the
 * NAME is not allowed, or MK_EXTERNAL_MAX are already registered (then msg
 * says why). mkRegistry_Find calls it for names starting with "exec:". */
MK_API const mkMethod *mkExternal_Find(const char *name, char *msg, size_t msglen);

/* The external methods registered so far, in order (mkRegistry_Count and
 * mkRegistry_At list them after the table), and the i-th (NULL when out of
 * range). */
MK_API int mkExternal_Count(void);
MK_API const mkMethod *mkExternal_At(int i);

/* 1 when m is an external method. */
MK_API int mkExternal_Is(const mkMethod *m);

/* The seconds the method reported for its last successful call (NaN when
 * there is none or m is not external). */
MK_API double mkExternal_Seconds(const mkMethod *m);

/* The last call's status: "ok", "crashed", "timeout", "garbage" or "error"
 * (the method answered "error TEXT"), and a one-line message saying what
 * happened (e.g. "the process died of signal 11"). */
MK_API const char *mkExternal_Status(const mkMethod *m);
MK_API const char *mkExternal_Message(const mkMethod *m);

/* The time limit for one answer, in seconds (> 0; default 60, or the
 * environment variable MINK_EXEC_TIMEOUT when it is set at the first
 * registration). */
MK_API void mkExternal_SetTimeLimit(double seconds);

/* Stop every external process (they also stop when the caller exits:
 * their input closes). */
MK_API void mkExternal_StopAll(void);

/* A placed body as SPEC text that parses back to the same doubles:
 * "superellipse a=.. b=.. eps=.. M=m11,m12,m21,m22 at=x,y" ("%.17g"), 3D
 * "superquadric a=.. b=.. c=.. eps1=.. eps2=.. M=(9) at=x,y,z". */
MK_API void mkSpec2_Format(mkBody2 b, char *buf, size_t len);
MK_API void mkSpec3_Format(mkBody3 b, char *buf, size_t len);

MK_EXTERN_C_END

#endif
