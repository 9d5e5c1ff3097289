/* mink_exp/clock.h - the clocks of the experiments.
 *
 * Wall time is CLOCK_MONOTONIC (never jumps with the date); the thread's CPU
 * time is CLOCK_THREAD_CPUTIME_ID: beside the wall time it shows whether
 * other processes of a shared machine took the processor away during a
 * measurement (then wall > CPU). Both in seconds. */
#ifndef MINK_EXP_CLOCK_H
#define MINK_EXP_CLOCK_H

#include <stddef.h>

double mkClock_Wall(void);
double mkClock_ThreadCpu(void);
/* The system's load averages over 1, 5 and 15 minutes ("0.12 0.30 0.25",
 * from /proc/loadavg), or "unknown", for a sidecar. */
void mkClock_LoadAverage(char *buf, size_t len);

#endif
