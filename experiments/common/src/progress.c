/* progress.c - the progress line. */
#define _POSIX_C_SOURCE 200809L

#include "mink_exp/clock.h"
#include "mink_exp/progress.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static void mkProgress_Draw(mkProgress *p, double now, int final)
{
	double elapsed = now - p->start;
	double frac = p->total > 0 ? (double)p->done / (double)p->total : 1.0;
	char eta[32] = "";
	if (!final && p->done > 0 && p->done < p->total)
		snprintf(eta, sizeof eta, "  eta %.0f s", elapsed * (1.0 - frac) / frac);
	fprintf(stderr, "%s%s  %ld/%ld  %3.0f%%  %.1f s%s%s",
		p->mode == 1 ? "\r" : "", p->label, p->done, p->total, 100.0 * frac,
		elapsed, eta, p->mode == 1 ? "\033[K" : "");
	if (p->mode == 2 || final)
		fputc('\n', stderr);
	fflush(stderr);
	p->last = now;
}

void mkProgress_Begin(mkProgress *p, const char *label, long total)
{
	p->label = label;
	p->total = total;
	p->done = 0;
	p->start = mkClock_Wall();
	p->last = p->start;
	const char *env = getenv("MINK_PROGRESS");
	if (env && strcmp(env, "never") == 0)
		p->mode = 0;
	else if (env && strcmp(env, "always") == 0)
		p->mode = isatty(STDERR_FILENO) ? 1 : 2;
	else
		p->mode = isatty(STDERR_FILENO) ? 1 : 0;
	if (p->mode == 1)
		mkProgress_Draw(p, p->start, 0);
}

void mkProgress_Add(mkProgress *p, long steps)
{
	p->done += steps;
	if (p->mode == 0)
		return;
	double now = mkClock_Wall();
	double every = p->mode == 1 ? 0.1 : 10.0;
	if (now - p->last >= every)
		mkProgress_Draw(p, now, 0);
}

void mkProgress_End(mkProgress *p)
{
	if (p->mode != 0)
		mkProgress_Draw(p, mkClock_Wall(), 1);
	p->mode = 0;
}
