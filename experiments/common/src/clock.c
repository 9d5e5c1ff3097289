/* clock.c - wall and thread CPU clocks. */
#define _POSIX_C_SOURCE 200809L

#include "mink_exp/clock.h"

#include <stdio.h>
#include <time.h>

static double mkSeconds(clockid_t id)
{
	struct timespec ts;
	clock_gettime(id, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double mkClock_Wall(void)
{
	return mkSeconds(CLOCK_MONOTONIC);
}

double mkClock_ThreadCpu(void)
{
	return mkSeconds(CLOCK_THREAD_CPUTIME_ID);
}

void mkClock_LoadAverage(char *buf, size_t len)
{
	FILE *fp = fopen("/proc/loadavg", "r");
	double a = 0, b = 0, c = 0;
	if (fp && fscanf(fp, "%lf %lf %lf", &a, &b, &c) == 3)
		snprintf(buf, len, "%.2f %.2f %.2f", a, b, c);
	else
		snprintf(buf, len, "unknown");
	if (fp)
		fclose(fp);
}
