/* run.c - mkCSpace_Run: the boundaries of a prepared scene over a range of
 * orientations, one task per (orientation, obstacle) or, in paper mode, per
 * (obstacle, chunk of orientations), on the pool of pool.c; each boundary
 * stored once, in the layout the options ask for. */
#define _POSIX_C_SOURCE 200809L
#include "cspace/work.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/message.h"
#include "kernels/kernel.h"

/* One run: the prepared scene, the orientations [begin, begin + nor) and
 * the result. Paper mode: a task is one obstacle and `chunk` orientations,
 * whose robot maps R_o M are poses2/poses3 (relative o), computed once. */
typedef struct mkCSpaceJob {
	const mkCSpace *cs;
	int begin, nor;
	int chunk, nchunks, group;
	mkMat2 *poses2;
	mkMat3 *poses3;
	mkCSpaceResult *res;
	/* streaming: task t's boundaries in slot t % window of res */
	long window;
	mkCSpaceSink *sink;
	void *user;
	int stopped;             /* the sink returned nonzero */
} mkCSpaceJob;

static double mkCSpace_Now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Keep boundary b's points (store = 1) in the result's layout. */
static mkResult mkCSpaceJob_Store(mkCSpaceResult *res, long b, const double *px, const double *py,
	const double *pz, int count)
{
	int dim = res->dim;
	double *s = malloc((size_t)count * (size_t)dim * sizeof(double) + 1);
	if (!s) return MK_ERR_MEMORY;
	if (res->interleaved) {
		for (int j = 0; j < count; ++j) {
			s[dim * j] = px[j];
			s[dim * j + 1] = py[j];
			if (dim == 3) s[3 * j + 2] = pz[j];
		}
	} else {
		memcpy(s, px, (size_t)count * sizeof(double));
		memcpy(s + count, py, (size_t)count * sizeof(double));
		if (dim == 3) memcpy(s + 2 * (long)count, pz, (size_t)count * sizeof(double));
	}
	res->points[b] = s;
	return MK_OK;
}

/* One 2D boundary of obstacle i against robot part j at scene orientation
 * ori, bound k: its points in w->q, *count and *err. The part's offset R t_j
 * moves the obstacle by -R t_j (the C-obstacle of the robot's position). */
static mkResult mkCSpaceJob_Boundary2(const mkCSpace *cs, mkCSpaceWork *w, int ori, int i, int j, int k, int *count,
	double *err)
{
	const mkCSpaceOptions *o = &cs->opt;
	mkBody2 rob = cs->part2[2 * j + k], ob = cs->obs2[2 * i + k];
	mkMat2 R = mkScene2_Orientation(cs->scene, ori);
	rob.M = mkMat2_Mul(R, rob.M);
	ob.t = mkVec2_Sub(ob.t, mkMat2_MulVec(R, rob.t));
	rob.t = mkVec2_Make(0.0, 0.0);
	if (o->mode == MK_CSPACE_PAPER) {
		*count = cs->paper_n;
		if (!mkCSpaceWork_Batch(w, *count, 2)) return MK_ERR_MEMORY;
		mkSumOptions so = {MK_SET_CONTACT, o->form, MK_PARAM_SURFACE, o->impl, MK_PRECISION_DOUBLE};
		return mkSum2_Batch(ob, rob, &so, cs->paper_u[0], cs->paper_u[1], *count, w->q[0], w->q[1], NULL, NULL);
	}
	double tol = o->tol - cs->obs_err[2 * i + k] - cs->part_err[2 * j + k];
	mkResult r = mkBoundary2_Run(w, ob, rob, o->impl, (mkBound)k, tol, o->max_points,
		o->mode == MK_CSPACE_UNIFORM ? o->uniform : 0, NULL, NULL, count, err);
	if (r != MK_OK) return r;
	if (!mkCSpaceWork_Batch(w, *count, 2)) return MK_ERR_MEMORY;
	mkBoundary2_Emit(w, (mkBound)k, *count, w->q[0], w->q[1]);
	return MK_OK;
}

/* One 3D boundary likewise: its points in p[0..2] (pointers into w), its
 * faces (store = 1) kept in the result. */
static mkResult mkCSpaceJob_Boundary3(mkCSpaceJob *J, mkCSpaceWork *w, long b, int ori, int i, int j, int k,
	int *count, double *err, double *p[3])
{
	const mkCSpace *cs = J->cs;
	const mkCSpaceOptions *o = &cs->opt;
	mkBody3 rob = cs->part3[2 * j + k], ob = cs->obs3[2 * i + k];
	mkMat3 R = mkScene3_Orientation(cs->scene, ori);
	rob.M = mkMat3_Mul(R, rob.M);
	ob.t = mkVec3_Sub(ob.t, mkMat3_MulVec(R, rob.t));
	rob.t = mkVec3_Make(0.0, 0.0, 0.0);
	mkResult r;
	if (o->mode == MK_CSPACE_PAPER) {
		*count = cs->paper_n * cs->paper_n;
		if (!mkCSpaceWork_Batch(w, *count, 3)) return MK_ERR_MEMORY;
		mkSumOptions so = {MK_SET_CONTACT, o->form, MK_PARAM_SURFACE, o->impl, MK_PRECISION_DOUBLE};
		r = mkSum3_Batch(ob, rob, &so, cs->paper_u[0], cs->paper_u[1], cs->paper_u[2], *count, w->q[0], w->q[1],
			w->q[2], NULL, NULL, NULL);
		for (int d = 0; d < 3; ++d) p[d] = w->q[d];
		return r;
	}
	int nf = 0;
	double tol = o->tol - cs->obs_err[2 * i + k] - cs->part_err[2 * j + k];
	r = mkBoundary3_Compute(w, ob, rob, o->impl, (mkBound)k, tol, o->max_points,
		o->mode == MK_CSPACE_UNIFORM ? o->uniform : -1, o->store, count, &nf, &w->tri2, &w->t2cap, err);
	if (r != MK_OK) return r;
	for (int d = 0; d < 3; ++d) p[d] = k == MK_BOUND_INNER ? w->p[d] : w->o[d];
	if (o->store) {
		int *faces = malloc((size_t)nf * 3 * sizeof(int) + 1);
		if (!faces) return MK_ERR_MEMORY;
		memcpy(faces, w->tri2, (size_t)nf * 3 * sizeof(int));
		J->res->faces[b] = faces;
		J->res->face_count[b] = nf;
	}
	return MK_OK;
}

/* Task (orientation, obstacle, part): its boundaries, errors and checksums. */
static mkResult mkCSpaceJob_Task(void *ctx, mkCSpaceWork *w, long task)
{
	mkCSpaceJob *J = ctx;
	const mkCSpace *cs = J->cs;
	mkCSpaceResult *res = J->res;
	int pj = (int)(task % cs->parts), i = (int)(task / cs->parts % cs->nob);
	int orel = (int)(task / cs->parts / cs->nob), ori = J->begin + orel;
	long slot = J->window ? task % J->window : task;
	double t0 = mkCSpace_Now();
	for (int k = 0; k < cs->bounds; ++k) {
		long b = slot * cs->bounds + k;
		int count = 0;
		double err = NAN, sum = 0.0, *p[3] = {NULL, NULL, NULL};
		mkResult r;
		if (cs->dim == 2) {
			r = mkCSpaceJob_Boundary2(cs, w, ori, i, pj, k, &count, &err);
			p[0] = w->q[0]; p[1] = w->q[1];
		} else {
			r = mkCSpaceJob_Boundary3(J, w, b, ori, i, pj, k, &count, &err, p);
		}
		if (r != MK_OK) return r;
		for (int j = 0; j < count; ++j) sum += p[0][j] + p[1][j] + (p[2] ? p[2][j] : 0.0);
		if (cs->opt.store && (r = mkCSpaceJob_Store(res, b, p[0], p[1], p[2], count)) != MK_OK) return r;
		res->count[b] = count;
		res->model_error[b] = cs->obs_err[2 * i + k] + cs->part_err[2 * pj + k];
		res->error[b] = cs->opt.mode == MK_CSPACE_PAPER ? NAN : err + res->model_error[b];
		res->checksum[b] = sum;
		res->seconds[b] = 0.0;
	}
	res->seconds[slot * cs->bounds] = mkCSpace_Now() - t0;
	return MK_OK;
}

/* Paper mode: obstacle i against the orientations of chunk c. The
 * obstacle's half of the batch is computed once (mkKOne*_Init) and the
 * robot's half over `group` orientations per kernel call (mkKOne*_Run);
 * the points are, bit for bit, those of one mkSum*_Batch call per
 * orientation (kernel.h). Each boundary's seconds are the task's wall time
 * shared equally among its orientations. */
static mkResult mkCSpaceJob_PaperTask(void *ctx, mkCSpaceWork *w, long task)
{
	mkCSpaceJob *J = ctx;
	const mkCSpace *cs = J->cs;
	const mkCSpaceOptions *o = &cs->opt;
	mkCSpaceResult *res = J->res;
	int c = (int)(task / cs->nob), i = (int)(task % cs->nob), dim = cs->dim;
	int ob = c * J->chunk, oe = ob + J->chunk < J->nor ? ob + J->chunk : J->nor;
	double t0 = mkCSpace_Now();
	int n = dim == 2 ? cs->paper_n : cs->paper_n * cs->paper_n, G = J->group;
	long need = (long)dim * n * (2 + 2 * (long)G);
	if (need > 0x7fffffffL || !mkGrow_Doubles(&w->pb, &w->pbcap, (int)need)) return MK_ERR_MEMORY;
	double *scratch = w->pb + (long)2 * dim * n, *pts = scratch + (long)dim * n * G;
	double *px = pts, *py = pts + (long)n * G, *pz = pts + (long)2 * n * G;
	mkSumOptions so = {MK_SET_CONTACT, o->form, MK_PARAM_SURFACE, o->impl, MK_PRECISION_DOUBLE};
	mkKOne2 one2;
	mkKOne3 one3;
	mkResult r = dim == 2
		? mkKOne2_Init(&one2, cs->obs2[2 * i], cs->robot2[0].shape, &so, cs->paper_u[0], cs->paper_u[1], n, w->pb)
		: mkKOne3_Init(&one3, cs->obs3[2 * i], cs->robot3[0].shape, &so, cs->paper_u[0], cs->paper_u[1], cs->paper_u[2],
			n, w->pb);
	if (r != MK_OK) return r;
	for (int o0 = ob; o0 < oe; o0 += G) {
		int m = oe - o0 < G ? oe - o0 : G;
		if (dim == 2) mkKOne2_Run(&one2, J->poses2 + o0, m, scratch, px, py);
		else mkKOne3_Run(&one3, J->poses3 + o0, m, scratch, px, py, pz);
		/* checksums: each boundary's coordinates summed in order, as
		 * mkCSpaceJob_Task sums them; the m sums are independent chains,
		 * advanced together */
		double sums[MK_KONE_POSES];
		for (int k = 0; k < m; ++k) sums[k] = 0.0;
		for (int j = 0; j < n; ++j)
			for (int k = 0; k < m; ++k) {
				long q = (long)k * n + j;
				sums[k] += px[q] + py[q] + (dim == 3 ? pz[q] : 0.0);
			}
		for (int k = 0; k < m; ++k) {
			long b = (long)(o0 + k) * cs->nob + i; /* one bound: the inner */
			if (o->store && (r = mkCSpaceJob_Store(res, b, px + (long)k * n, py + (long)k * n,
				dim == 3 ? pz + (long)k * n : NULL, n)) != MK_OK)
				return r;
			res->count[b] = n;
			res->model_error[b] = cs->obs_err[2 * i] + cs->robot_err[0];
			res->error[b] = NAN;
			res->checksum[b] = sums[k];
		}
	}
	double each = (mkCSpace_Now() - t0) / (double)(oe - ob);
	for (int k = ob; k < oe; ++k) res->seconds[(long)k * cs->nob + i] = each;
	return MK_OK;
}

/* Paper mode: the robot's maps once per orientation (not per obstacle);
 * group: orientations per kernel call, so that group * points is a
 * multiple of 32 (the widest kernel's block: no padded lanes) and at least
 * 512; chunk: 16 groups per task, so that the obstacle's half (once per
 * task) is a small part of it. */
static mkResult mkCSpaceJob_PaperPlan(mkCSpaceJob *J)
{
	const mkCSpace *cs = J->cs;
	int dim = cs->dim;
	long np = dim == 2 ? cs->paper_n : (long)cs->paper_n * cs->paper_n;
	if (dim == 2) J->poses2 = malloc((size_t)J->nor * sizeof *J->poses2 + 1);
	else J->poses3 = malloc((size_t)J->nor * sizeof *J->poses3 + 1);
	if (dim == 2 ? !J->poses2 : !J->poses3) return MK_ERR_MEMORY;
	for (int k = 0; k < J->nor; ++k) {
		if (dim == 2) J->poses2[k] = mkMat2_Mul(mkScene2_Orientation(cs->scene, J->begin + k), cs->robot2[0].M);
		else J->poses3[k] = mkMat3_Mul(mkScene3_Orientation(cs->scene, J->begin + k), cs->robot3[0].M);
	}
	int g0 = 32;
	for (long m = np; g0 > 1 && m % 2 == 0; m /= 2) g0 /= 2;   /* 32 / gcd(np, 32) */
	J->group = np >= 512 ? 1 : g0 * (int)((512 + g0 * np - 1) / (g0 * np));
	if (J->group > MK_KONE_POSES) J->group = MK_KONE_POSES / g0 * g0;
	J->chunk = 16 * J->group < J->nor ? 16 * J->group : (J->nor > 0 ? J->nor : 1);
	J->nchunks = (J->nor + J->chunk - 1) / J->chunk;
	return MK_OK;
}

/* The result's arrays for nb boundaries; 0 when out of memory. */
static int mkCSpaceResult_Alloc(mkCSpaceResult *out, const mkCSpace *cs, long nb)
{
	out->count = calloc((size_t)nb + 1, sizeof(int));
	out->error = calloc((size_t)nb + 1, sizeof(double));
	out->model_error = calloc((size_t)nb + 1, sizeof(double));
	out->seconds = calloc((size_t)nb + 1, sizeof(double));
	out->checksum = calloc((size_t)nb + 1, sizeof(double));
	if (!out->count || !out->error || !out->model_error || !out->seconds || !out->checksum) return 0;
	if (!cs->opt.store) return 1;
	out->points = calloc((size_t)nb + 1, sizeof *out->points);
	if (cs->dim == 3) {
		out->faces = calloc((size_t)nb + 1, sizeof *out->faces);
		out->face_count = calloc((size_t)nb + 1, sizeof *out->face_count);
	}
	return out->points && (cs->dim == 2 || (out->faces && out->face_count));
}

mkResult mkCSpace_Run(const mkCSpace *cs, int begin, int end, mkCSpaceResult *out, char *msg, size_t msglen)
{
	if (!out) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no result");
	memset(out, 0, sizeof *out);
	if (!cs) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no prepared scene");
	if (begin < 0 || end > cs->scene->orientation_count || begin > end)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "orientations [%d, %d) are out of range: the scene has %d",
			begin, end, cs->scene->orientation_count);
	mkCSpaceJob J;
	memset(&J, 0, sizeof J);
	J.cs = cs; J.begin = begin; J.nor = end - begin; J.res = out;
	long nb = (long)cs->nob * cs->parts * J.nor * cs->bounds;
	out->dim = cs->dim; out->obstacles = cs->nob; out->orientations = J.nor; out->bounds = cs->bounds;
	out->parts = cs->parts;
	out->orientation_begin = begin;
	out->tol = cs->opt.tol;
	out->interleaved = cs->opt.interleaved != 0;
	mkResult r = MK_OK;
	int paper = cs->opt.mode == MK_CSPACE_PAPER;
	if (!mkCSpaceResult_Alloc(out, cs, nb) || (paper && mkCSpaceJob_PaperPlan(&J) != MK_OK)) {
		r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	} else {
		long ntasks = paper ? (long)cs->nob * J.nchunks : (long)cs->nob * cs->parts * J.nor;
		r = mkCSpacePool_Run(paper ? mkCSpaceJob_PaperTask : mkCSpaceJob_Task, &J, ntasks, cs->opt.threads);
		if (r != MK_OK) mkFail(r, msg, msglen, "%s while computing boundaries", mkResult_Name(r));
	}
	free(J.poses2);
	free(J.poses3);
	if (r != MK_OK) mkCSpaceResult_Free(out);
	return r;
}

/* Streaming: hand task t's boundaries to the sink and release them. */
static mkResult mkCSpaceJob_Emit(void *ctx, mkCSpaceWork *w, long task)
{
	(void)w;
	mkCSpaceJob *J = ctx;
	const mkCSpace *cs = J->cs;
	mkCSpaceResult *res = J->res;
	long slot = task % J->window;
	int pj = (int)(task % cs->parts), i = (int)(task / cs->parts % cs->nob);
	int ori = J->begin + (int)(task / cs->parts / cs->nob);
	for (int k = 0; k < cs->bounds; ++k) {
		long b = slot * cs->bounds + k;
		mkCSpaceBoundary v = mkCSpaceResult_At(res, b);
		if (!J->stopped && J->sink(J->user, ori, i, pj, (mkBound)k, &v) != 0) J->stopped = 1;
		free(res->points[b]);
		res->points[b] = NULL;
		if (res->faces) {
			free(res->faces[b]);
			res->faces[b] = NULL;
		}
	}
	return J->stopped ? MK_ERR_ARGUMENT : MK_OK;
}

mkResult mkCSpace_Stream(const mkCSpace *cs, int begin, int end, mkCSpaceSink *sink, void *user,
	char *msg, size_t msglen)
{
	if (!cs || !sink) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no prepared scene or sink");
	if (begin < 0 || end > cs->scene->orientation_count || begin > end)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "orientations [%d, %d) are out of range: the scene has %d",
			begin, end, cs->scene->orientation_count);
	if (!cs->opt.store || cs->opt.mode == MK_CSPACE_PAPER)
		return mkFail(MK_ERR_UNSUPPORTED, msg, msglen, "streaming needs stored points and the adaptive or uniform mode");
	mkCSpaceJob J;
	memset(&J, 0, sizeof J);
	mkCSpaceResult res;
	memset(&res, 0, sizeof res);
	J.cs = cs; J.begin = begin; J.nor = end - begin; J.res = &res;
	J.sink = sink; J.user = user;
	J.window = (long)MK_CSPACE_WINDOW * cs->opt.threads;
	/* window x 1 "obstacles x orientations": mkCSpaceResult_Free releases window * bounds boundaries */
	res.dim = cs->dim; res.obstacles = (int)J.window; res.orientations = 1; res.parts = 1; res.bounds = cs->bounds;
	res.tol = cs->opt.tol;
	res.interleaved = cs->opt.interleaved != 0;
	mkResult r;
	if (!mkCSpaceResult_Alloc(&res, cs, J.window * cs->bounds)) {
		r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	} else {
		r = mkCSpacePool_RunOrdered(mkCSpaceJob_Task, mkCSpaceJob_Emit, &J, (long)cs->nob * cs->parts * J.nor, cs->opt.threads,
			J.window);
		if (J.stopped) mkFail(r, msg, msglen, "stopped by the caller");
		else if (r != MK_OK) mkFail(r, msg, msglen, "%s while computing boundaries", mkResult_Name(r));
	}
	mkCSpaceResult_Free(&res);
	return r;
}

mkResult mkCSpace_Estimate(const mkCSpace *cs, int begin, int end, mkCSpaceEstimate *out, char *msg, size_t msglen)
{
	if (!cs || !out) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no prepared scene or estimate");
	memset(out, 0, sizeof *out);
	if (begin < 0 || end > cs->scene->orientation_count || begin > end)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "orientations [%d, %d) are out of range: the scene has %d",
			begin, end, cs->scene->orientation_count);
	if (begin == end || cs->nob == 0) return MK_OK;
	enum { SAMPLE_OBSTACLES = 32, SAMPLE_CAP = 2000 };
	mkCSpace tmp = *cs;
	int adaptive = cs->opt.mode == MK_CSPACE_ADAPTIVE;
	if (adaptive && tmp.opt.max_points > SAMPLE_CAP) tmp.opt.max_points = SAMPLE_CAP;
	tmp.opt.store = 0;
	mkCSpaceJob J;
	memset(&J, 0, sizeof J);
	J.cs = &tmp;
	mkCSpaceWork w;
	memset(&w, 0, sizeof w);
	int ns = cs->nob < SAMPLE_OBSTACLES ? cs->nob : SAMPLE_OBSTACLES;
	double sum = 0.0;
	mkResult r = MK_OK;
	for (int s = 0; s < ns && r == MK_OK; ++s) {
		int i = (int)((long)s * cs->nob / ns), j = s % cs->parts;
		for (int k = 0; k < cs->bounds && r == MK_OK; ++k) {
			int count = 0;
			double err = NAN, *p[3];
			r = cs->dim == 2 ? mkCSpaceJob_Boundary2(&tmp, &w, begin, i, j, k, &count, &err)
				: mkCSpaceJob_Boundary3(&J, &w, 0, begin, i, j, k, &count, &err, p);
			double ts = cs->opt.tol - cs->obs_err[2 * i + k] - cs->part_err[2 * j + k], n = count;
			if (adaptive && err > ts)
				n = fmin(count * (cs->dim == 3 ? err / ts : sqrt(err / ts)), (double)cs->opt.max_points);
			sum += n;
			if (n > out->largest) out->largest = n;
			++out->sampled;
		}
	}
	mkCSpaceWork_Free(&w);
	if (r != MK_OK) return mkFail(r, msg, msglen, "%s while estimating the run", mkResult_Name(r));
	double boundaries = (double)cs->nob * cs->parts * (double)(end - begin) * cs->bounds;
	out->points = sum / (double)out->sampled * boundaries;
	out->faces = cs->dim == 3 ? 2.0 * out->points - 4.0 * boundaries : 0.0;
	return MK_OK;
}
