/* pool.c - the thread pool of a run: `threads` POSIX threads (the caller's
 * among them) take tasks in order from a shared counter, each with its own
 * scratch space; a failure stops the handing out of tasks. The ordered
 * pool also hands each finished task, in task order, to an emit function,
 * and keeps at most `window` tasks finished but not yet emitted. */
#define _POSIX_C_SOURCE 200809L
#include "cspace/work.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

typedef struct mkCSpacePool {
	mkCSpaceTaskFn *fn;
	void *ctx;
	long ntasks;
	long next_task;          /* guarded by lock */
	pthread_mutex_t lock;
	mkResult failed;         /* guarded by lock */
	/* ordered pool: task t's state in done[t % window] (guarded by lock) */
	mkCSpaceTaskFn *emit;
	long window, next_emit;
	char *done;
	int emitting;
	pthread_cond_t moved;    /* next_emit advanced or a failure */
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

/* Ordered: with P->lock held, emit every finished task from next_emit on,
 * unless another thread is doing so (it will see them). The lock is
 * released around each emit call, which are therefore never concurrent. */
static void mkCSpacePool_EmitReady(mkCSpacePool *P, mkCSpaceWork *w)
{
	if (P->emitting) return;
	P->emitting = 1;
	while (!P->failed && P->next_emit < P->ntasks && P->done[P->next_emit % P->window]) {
		long e = P->next_emit;
		pthread_mutex_unlock(&P->lock);
		mkResult r = P->emit(P->ctx, w, e);
		pthread_mutex_lock(&P->lock);
		P->done[e % P->window] = 0;
		P->next_emit = e + 1;
		if (r != MK_OK && !P->failed) P->failed = r;
		pthread_cond_broadcast(&P->moved);
	}
	P->emitting = 0;
}

static void *mkCSpacePool_OrderedWorker(void *arg)
{
	mkCSpacePool *P = arg;
	mkCSpaceWork w;
	memset(&w, 0, sizeof w);
	pthread_mutex_lock(&P->lock);
	for (;;) {
		while (!P->failed && P->next_task < P->ntasks && P->next_task >= P->next_emit + P->window)
			pthread_cond_wait(&P->moved, &P->lock);
		if (P->failed || P->next_task >= P->ntasks) break;
		long t = P->next_task++;
		pthread_mutex_unlock(&P->lock);
		mkResult r = P->fn(P->ctx, &w, t);
		pthread_mutex_lock(&P->lock);
		if (r != MK_OK) {
			if (!P->failed) P->failed = r;
			pthread_cond_broadcast(&P->moved);
			break;
		}
		P->done[t % P->window] = 1;
		mkCSpacePool_EmitReady(P, &w);
	}
	pthread_mutex_unlock(&P->lock);
	mkCSpaceWork_Free(&w);
	return NULL;
}

mkResult mkCSpacePool_Run(mkCSpaceTaskFn *fn, void *ctx, long ntasks, int threads)
{
	return mkCSpacePool_RunOrdered(fn, NULL, ctx, ntasks, threads, 0);
}

mkResult mkCSpacePool_RunOrdered(mkCSpaceTaskFn *fn, mkCSpaceTaskFn *emit, void *ctx, long ntasks, int threads,
	long window)
{
	mkCSpacePool P;
	memset(&P, 0, sizeof P);
	P.fn = fn;
	P.ctx = ctx;
	P.ntasks = ntasks;
	P.emit = emit;
	P.window = window;
	void *(*worker)(void *) = emit ? mkCSpacePool_OrderedWorker : mkCSpacePool_Worker;
	if (emit && !(P.done = calloc((size_t)window + 1, 1))) return MK_ERR_MEMORY;
	pthread_mutex_init(&P.lock, NULL);
	pthread_cond_init(&P.moved, NULL);
	int nth = threads;
	if (nth > ntasks) nth = ntasks > 0 ? (int)ntasks : 1;
	pthread_t th[1024];
	int started = 0;
	for (int t = 1; t < nth && t < 1024; ++t) {
		if (pthread_create(&th[started], NULL, worker, &P) != 0) break;
		++started;
	}
	worker(&P);
	for (int t = 0; t < started; ++t) pthread_join(th[t], NULL);
	pthread_cond_destroy(&P.moved);
	pthread_mutex_destroy(&P.lock);
	free(P.done);
	return P.failed;
}
