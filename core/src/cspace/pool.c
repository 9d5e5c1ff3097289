/* pool.c - the thread pool of a run: `threads` POSIX threads (the caller's
 * among them) take tasks in order from a shared counter, each with its own
 * scratch space; a failure stops the handing out of tasks. */
#define _POSIX_C_SOURCE 200809L
#include "cspace/work.h"

#include <pthread.h>
#include <string.h>

typedef struct mkCSpacePool {
	mkCSpaceTaskFn *fn;
	void *ctx;
	long ntasks;
	long next_task;          /* guarded by lock */
	pthread_mutex_t lock;
	mkResult failed;         /* guarded by lock */
} mkCSpacePool;

static void *mkCSpacePool_Worker(void *arg)
{
	mkCSpacePool *P = arg;
	mkCSpaceWork w;
	memset(&w, 0, sizeof w);
	for (;;) {
		pthread_mutex_lock(&P->lock);
		long t = P->failed ? P->ntasks : P->next_task;
		/* tasks in small blocks: fewer lock round trips, same results */
		long blk = P->ntasks / 4096 > 0 ? 16 : 1;
		P->next_task = t + blk;
		pthread_mutex_unlock(&P->lock);
		if (t >= P->ntasks) break;
		long e = t + blk < P->ntasks ? t + blk : P->ntasks;
		for (; t < e; ++t) {
			mkResult r = P->fn(P->ctx, &w, t);
			if (r != MK_OK) {
				pthread_mutex_lock(&P->lock);
				if (!P->failed) P->failed = r;
				pthread_mutex_unlock(&P->lock);
				break;
			}
		}
	}
	mkCSpaceWork_Free(&w);
	return NULL;
}

mkResult mkCSpacePool_Run(mkCSpaceTaskFn *fn, void *ctx, long ntasks, int threads)
{
	mkCSpacePool P;
	memset(&P, 0, sizeof P);
	P.fn = fn;
	P.ctx = ctx;
	P.ntasks = ntasks;
	pthread_mutex_init(&P.lock, NULL);
	int nth = threads;
	if (nth > ntasks) nth = ntasks > 0 ? (int)ntasks : 1;
	pthread_t th[1024];
	int started = 0;
	for (int t = 1; t < nth && t < 1024; ++t) {
		if (pthread_create(&th[started], NULL, mkCSpacePool_Worker, &P) != 0) break;
		++started;
	}
	mkCSpacePool_Worker(&P);
	for (int t = 0; t < started; ++t) pthread_join(th[t], NULL);
	pthread_mutex_destroy(&P.lock);
	return P.failed;
}
