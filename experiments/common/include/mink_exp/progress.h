/* mink_exp/progress.h - a progress line on stderr for long runs.
 *
 * "label  123/1000  12%  4.1 s  eta 30 s", redrawn in place at most ten
 * times a second, only when stderr is a terminal, so logs and pipes stay
 * clean. The environment variable MINK_PROGRESS=always forces it on (one
 * line per redraw, at most one every 10 s, for batch logs) and
 * MINK_PROGRESS=never turns it off. */
#ifndef MINK_EXP_PROGRESS_H
#define MINK_EXP_PROGRESS_H

typedef struct mkProgress {
	const char *label;
	long total;
	long done;
	double start;    /* monotonic seconds */
	double last;     /* time of the last redraw */
	int mode;        /* 0 quiet, 1 terminal, 2 log lines */
} mkProgress;

void mkProgress_Begin(mkProgress *p, const char *label, long total);
/* Count `steps` more units done and redraw when due. */
void mkProgress_Add(mkProgress *p, long steps);
/* Final line (terminal: ends the line in place). */
void mkProgress_End(mkProgress *p);

#endif
