/* scenequery.c - a robot at many poses against a scene (mink/scenequery.h):
 * exact boxes of the bodies, a bounding volume hierarchy of the obstacles
 * walked nearest first, and the narrow phase on the models of each pair. */
#include "mink/scenequery.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/message.h"
#include "cspace/work.h"
#include "mink/batch.h"
#include "mink/collision.h"

#define MK_SQ_ROUND 1e-12   /* rounding allowance of a pair's bound, times its size */
#define MK_SQ_LEAF 2        /* obstacles per leaf at most */
#define MK_SQ_STACK 128     /* traversal stack (depth ~ 2 log2 n) */
#define MK_SQ_CHUNK 32      /* poses per pool task */
#define MK_SQ_BATCH 8       /* candidate pairs screened per batch call */

typedef struct mkSqBox { double lo[3], hi[3]; } mkSqBox;

typedef struct mkSqNode {
	mkSqBox box;
	int left, right;   /* children, or -1 for a leaf */
	int first, count;  /* leaf: obstacles order[first .. first + count) */
} mkSqNode;

struct mkSceneQuery {
	const mkScene *scene;
	mkSceneQueryOptions opt;
	int dim, nob, parts;
	const mkSceneBody *part_body;
	mkBody3 *obs;      /* [i * 2 + bound]: inner, outer models */
	mkBody3 *part;     /* [j * 2 + bound], in the robot's frame */
	mkSqBox *obox;     /* outer models' boxes */
	int *order;
	mkSqNode *node;
	int nnode;
	struct mkSqKey *keys;   /* building only */
};

const char *mkPoseStatus_Name(mkPoseStatus s)
{
	return s == MK_POSE_FREE ? "free" : s == MK_POSE_COLLIDING ? "colliding" : s == MK_POSE_UNCERTAIN ? "uncertain" : "?";
}

mkSceneQueryOptions mkSceneQueryOptions_Default(void)
{
	mkSceneQueryOptions o;
	memset(&o, 0, sizeof o);
	o.threads = 1;
	o.model_rel = 1e-4;
	o.max_clearance = INFINITY;
	return o;
}

/* ---- bodies ---- */

/* A 2D body as the superquadric whose z = 0 section it is (eps1 = 1). */
static mkBody3 mkSq_Lift(mkBody2 b)
{
	mkShape3 s = {b.shape.a, b.shape.b, b.shape.a > b.shape.b ? b.shape.a : b.shape.b, 1.0, b.shape.eps};
	mkMat3 M = {{{b.M.m[0][0], b.M.m[0][1], 0.0}, {b.M.m[1][0], b.M.m[1][1], 0.0}, {0.0, 0.0, 1.0}}};
	return mkBody3_Make(s, M, mkVec3_Make(b.t.x, b.t.y, 0.0));
}

/* A scene body's model for the side, in 3D form; delta relative to an
 * upper bound of its reach (|M|_F times the half diagonal). */
static mkResult mkSq_Model(const mkSceneBody *d, double rel, mkBound side, mkBody3 *out, char *msg, size_t msglen)
{
	double err, f = 0.0, s2 = 0.0;
	if (d->dim == 2) {
		const mkMat2 *M = &d->spec.body2.M;
		for (int i = 0; i < 4; ++i) f += M->m[i / 2][i % 2] * M->m[i / 2][i % 2];
		s2 = d->kind == MK_SCENE_BOX ? 0.25 * (d->size[0] * d->size[0] + d->size[1] * d->size[1]) : 0.0;
		mkBody2 b;
		mkResult r = mkSceneBody2_Model(d, rel * sqrt(f * s2) + (s2 > 0.0 ? 0.0 : 1.0), side, &b, &err, msg, msglen);
		if (r == MK_OK) *out = mkSq_Lift(b);
		return r;
	}
	const mkMat3 *M = &d->spec.body3.M;
	for (int i = 0; i < 9; ++i) f += M->m[i / 3][i % 3] * M->m[i / 3][i % 3];
	if (d->kind == MK_SCENE_BOX) s2 = 0.25 * (d->size[0] * d->size[0] + d->size[1] * d->size[1] + d->size[2] * d->size[2]);
	else if (d->kind == MK_SCENE_CYLINDER) s2 = d->size[0] * d->size[0] + 0.25 * d->size[1] * d->size[1];
	return mkSceneBody3_Model(d, rel * sqrt(f * s2) + (s2 > 0.0 ? 0.0 : 1.0), side, out, &err, msg, msglen);
}

/* The exact axis-aligned box of a (centrally symmetric) body. */
static mkSqBox mkSq_BodyBox(mkBody3 b)
{
	mkSqBox x;
	for (int i = 0; i < 3; ++i) {
		mkVec3 e = {i == 0, i == 1, i == 2};
		double h = mkShape3_SupportValue(b.shape, mkMat3_MulTVec(b.M, e));
		double c = i == 0 ? b.t.x : i == 1 ? b.t.y : b.t.z;
		x.lo[i] = c - h;
		x.hi[i] = c + h;
	}
	return x;
}

static double mkSq_BoxDistance(const mkSqBox *a, const mkSqBox *b)
{
	double d2 = 0.0;
	for (int i = 0; i < 3; ++i) {
		double g = fmax(a->lo[i] - b->hi[i], b->lo[i] - a->hi[i]);
		if (g > 0.0) d2 += g * g;
	}
	return sqrt(d2);
}

/* ---- the hierarchy ---- */

typedef struct mkSqKey { double key; int idx; } mkSqKey;

static int mkSq_CompareKey(const void *pa, const void *pb)
{
	const mkSqKey *a = pa, *b = pb;
	if (a->key != b->key) return a->key < b->key ? -1 : 1;
	return a->idx - b->idx;
}

/* Node over order[first .. first + count): its box, then a median split on
 * the longest axis of the box. Returns the node's index. */
static int mkSq_Build(mkSceneQuery *q, int first, int count)
{
	int id = q->nnode++;
	mkSqNode *n = &q->node[id];
	for (int i = 0; i < 3; ++i) { n->box.lo[i] = INFINITY; n->box.hi[i] = -INFINITY; }
	for (int k = first; k < first + count; ++k)
		for (int i = 0; i < 3; ++i) {
			n->box.lo[i] = fmin(n->box.lo[i], q->obox[q->order[k]].lo[i]);
			n->box.hi[i] = fmax(n->box.hi[i], q->obox[q->order[k]].hi[i]);
		}
	n->first = first;
	n->count = count;
	n->left = n->right = -1;
	if (count <= MK_SQ_LEAF) return id;
	int axis = 0;
	for (int i = 1; i < 3; ++i)
		if (n->box.hi[i] - n->box.lo[i] > n->box.hi[axis] - n->box.lo[axis]) axis = i;
	for (int k = 0; k < count; ++k) {
		int i = q->order[first + k];
		q->keys[k] = (mkSqKey){q->obox[i].lo[axis] + q->obox[i].hi[axis], i};
	}
	qsort(q->keys, (size_t)count, sizeof *q->keys, mkSq_CompareKey);
	for (int k = 0; k < count; ++k) q->order[first + k] = q->keys[k].idx;
	int half = count / 2;
	int l = mkSq_Build(q, first, half);
	int r = mkSq_Build(q, first + half, count - half);
	q->node[id].left = l;
	q->node[id].right = r;
	return id;
}

/* ---- create ---- */

mkResult mkSceneQuery_Create(const mkScene *scene, const mkSceneQueryOptions *opt, mkSceneQuery **out,
	char *msg, size_t msglen)
{
	if (!out) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no result");
	*out = NULL;
	if (!scene || !opt || (scene->dim != 2 && scene->dim != 3)) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no scene or options");
	if (opt->threads < 1 || opt->threads > 1024)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "threads = %d is out of range: must be in [1, 1024]", opt->threads);
	if (!(opt->model_rel >= 1e-6 && opt->model_rel <= 0.1))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "model_rel = %g is out of range: must be in [1e-06, 0.1]", opt->model_rel);
	if (!(opt->max_clearance > 0.0))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "max_clearance = %g is out of range: must be positive (or inf)",
			opt->max_clearance);
	mkSceneQuery *q = calloc(1, sizeof *q);
	if (!q) return mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	q->scene = scene;
	q->opt = *opt;
	q->dim = scene->dim;
	q->nob = scene->obstacle_count;
	q->parts = scene->part_count > 0 ? scene->part_count : 1;
	q->part_body = scene->part_count > 0 ? scene->parts : &scene->robot;
	size_t nb = (size_t)q->nob + 1;
	q->obs = malloc(2 * nb * sizeof *q->obs);
	q->part = malloc(2 * (size_t)q->parts * sizeof *q->part);
	q->obox = malloc(nb * sizeof *q->obox);
	q->order = malloc(nb * sizeof *q->order);
	q->node = malloc(2 * nb * sizeof *q->node);
	mkResult r = MK_OK;
	if (!q->obs || !q->part || !q->obox || !q->order || !q->node) r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	char sub[512];
	for (int k = 0; k < 2 && r == MK_OK; ++k) {
		for (int i = 0; i < q->nob && r == MK_OK; ++i)
			if ((r = mkSq_Model(&scene->obstacles[i], opt->model_rel, (mkBound)k, &q->obs[2 * i + k], sub, sizeof sub)) != MK_OK)
				mkFail(r, msg, msglen, "obstacle %d: %s", i, sub);
		for (int j = 0; j < q->parts && r == MK_OK; ++j)
			if ((r = mkSq_Model(&q->part_body[j], opt->model_rel, (mkBound)k, &q->part[2 * j + k], sub, sizeof sub)) != MK_OK)
				mkFail(r, msg, msglen, "part %d: %s", j, sub);
	}
	if (r == MK_OK && scene->part_count == 0) /* a hand-built scene's robot: its at= unused */
		for (int k = 0; k < 2; ++k) q->part[k].t = mkVec3_Make(0.0, 0.0, 0.0);
	if (r == MK_OK && q->nob > 0 && !(q->keys = malloc(nb * sizeof *q->keys))) r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	if (r == MK_OK && q->nob > 0) {
		for (int i = 0; i < q->nob; ++i) {
			q->obox[i] = mkSq_BodyBox(q->obs[2 * i + 1]);
			q->order[i] = i;
		}
		mkSq_Build(q, 0, q->nob);
		free(q->keys);
		q->keys = NULL;
	}
	if (r != MK_OK) {
		mkSceneQuery_Destroy(q);
		return r;
	}
	*out = q;
	return MK_OK;
}

void mkSceneQuery_Destroy(mkSceneQuery *q)
{
	if (!q) return;
	free(q->obs); free(q->part); free(q->obox); free(q->order); free(q->node); free(q->keys);
	free(q);
}

int mkSceneQuery_PoseSize(const mkSceneQuery *q) { return q->dim == 2 ? 3 : 7; }

/* ---- poses ---- */

/* The pose's rotation and position; 0 when not finite or a zero quaternion. */
static int mkSq_Pose(const mkSceneQuery *q, const double *p, mkMat3 *R, mkVec3 *c)
{
	int n = mkSceneQuery_PoseSize(q);
	for (int k = 0; k < n; ++k)
		if (!isfinite(p[k]) || fabs(p[k]) > 1e150) return 0;
	if (q->dim == 2) {
		double cs = cos(p[2]), sn = sin(p[2]);
		mkMat3 r = {{{cs, -sn, 0.0}, {sn, cs, 0.0}, {0.0, 0.0, 1.0}}};
		*R = r;
		*c = mkVec3_Make(p[0], p[1], 0.0);
		return 1;
	}
	*R = mkMat3_FromQuat(p[3], p[4], p[5], p[6]);
	*c = mkVec3_Make(p[0], p[1], p[2]);
	return mkMat3_IsFinite(*R);
}

static mkBody3 mkSq_Place(mkBody3 b, mkMat3 R, mkVec3 c)
{
	b.M = mkMat3_Mul(R, b.M);
	b.t = mkVec3_Add(c, mkMat3_MulVec(R, b.t));
	return b;
}

int mkSceneQuery_PartBody(const mkSceneQuery *q, const double *pose, int j, int bound, mkBody3 *out)
{
	mkMat3 R;
	mkVec3 c;
	if (!q || !out || j < 0 || j >= q->parts || (bound != 0 && bound != 1) || !mkSq_Pose(q, pose, &R, &c)) return 0;
	*out = mkSq_Place(q->part[2 * j + bound], R, c);
	return 1;
}

int mkSceneQuery_ObstacleBody(const mkSceneQuery *q, int i, int bound, mkBody3 *out)
{
	if (!q || !out || i < 0 || i >= q->nob || (bound != 0 && bound != 1)) return 0;
	*out = q->obs[2 * i + bound];
	return 1;
}

/* x lies inside b, beyond rounding. */
static int mkSq_Inside(mkBody3 b, mkVec3 x)
{
	mkVec3 l = mkMat3_MulVec(mkMat3_Inverse(b.M), mkVec3_Sub(x, b.t));
	return mkShape3_Implicit(b.shape, l) < 1.0 - 1e-9;
}

/* A certificate of overlap: a point inside both bodies among the centres,
 * their midpoint and the solver's witnesses' midpoint, else the solver's
 * certified bracket of the signed distance below -tol. */
static int mkSq_Overlap(mkBody3 a, mkBody3 b, const mkCollision3 *c, double tol)
{
	mkVec3 cand[4] = {a.t, b.t, mkVec3_Scale(mkVec3_Add(a.t, b.t), 0.5), mkVec3_Scale(mkVec3_Add(c->p1, c->p2), 0.5)};
	for (int k = 0; k < 4; ++k)
		if (isfinite(cand[k].x + cand[k].y + cand[k].z) && mkSq_Inside(a, cand[k]) && mkSq_Inside(b, cand[k])) return 1;
	return c->certified == 1 && c->bound + c->gap < -tol;
}

/* The narrow phase of one pair (the one-pair query): the pair's status and
 * value as the header defines them. */
static mkPoseStatus mkSq_Pair(const mkSceneQuery *q, int i, mkBody3 inner, mkBody3 outer, int smooth, double *value)
{
	mkCollision3 c;
	mkResult r = mkCollide3_Normal(q->obs[2 * i + 1], outer, &c);
	if (r != MK_OK) { *value = -INFINITY; return MK_POSE_UNCERTAIN; }
	double tol = MK_SQ_ROUND * c.scale, lb = c.bound - tol;
	*value = lb;
	if (lb > 0.0) return MK_POSE_FREE;
	if ((!smooth || q->scene->obstacles[i].kind != MK_SCENE_SMOOTH) && mkCollide3_Normal(q->obs[2 * i], inner, &c) != MK_OK)
		return MK_POSE_UNCERTAIN;
	return mkSq_Overlap(q->obs[2 * i], inner, &c, tol) ? MK_POSE_COLLIDING : MK_POSE_UNCERTAIN;
}

/* A part's walk of the hierarchy, nearest child first: the stack of nodes
 * and the leaf being read (order[k .. end)). */
typedef struct mkSqWalk {
	int stack[MK_SQ_STACK], top, k, end;
} mkSqWalk;

/* The walk's next candidates (at most max): obstacles whose box is nearer
 * than best, in the walk's order (which does not depend on best: best only
 * prunes). Returns their number, 0 when the walk is over. */
static int mkSq_Collect(const mkSceneQuery *q, mkSqWalk *w, const mkSqBox *pb, double best, int *idx, int max)
{
	int n = 0;
	while (n < max) {
		if (w->k < w->end) {
			int i = q->order[w->k++];
			if (mkSq_BoxDistance(pb, &q->obox[i]) < best) idx[n++] = i;
			continue;
		}
		if (w->top == 0) break;
		const mkSqNode *nd = &q->node[w->stack[--w->top]];
		if (mkSq_BoxDistance(pb, &nd->box) >= best) continue;
		if (nd->left >= 0) { /* the nearer child is walked first: pushed last */
			double dl = mkSq_BoxDistance(pb, &q->node[nd->left].box), dr = mkSq_BoxDistance(pb, &q->node[nd->right].box);
			w->stack[w->top++] = dl <= dr ? nd->right : nd->left;
			w->stack[w->top++] = dl <= dr ? nd->left : nd->right;
			continue;
		}
		w->k = nd->first;
		w->end = nd->first + nd->count;
	}
	return n;
}

/* The batch's screen of n candidate pairs (outer models) against the
 * clearance best: far[m] = 1 when the pair's distance is certified at least
 * best (a separating direction, MK_PATH_SEPARATING), so that it cannot lower
 * the pose's clearance; 0 when the one-pair narrow phase must decide. */
static void mkSq_Screen(const mkSceneQuery *q, const int *idx, int n, const mkBody3 *outer, double best,
	unsigned char *far)
{
	int i1[MK_SQ_BATCH], i2[MK_SQ_BATCH];
	mkContact status[MK_SQ_BATCH];
	unsigned char clear[MK_SQ_BATCH], path[MK_SQ_BATCH];
	for (int m = 0; m < n; ++m) { i1[m] = 2 * idx[m] + 1; i2[m] = 0; }
	mkBatchPairs3 pairs = {n, q->obs, outer, i1, i2};
	mkBatchOut3 out;
	memset(&out, 0, sizeof out);
	out.status = status;
	out.clear = clear;
	out.path = path;
	mkResult r = mkCollide3_Batch(&pairs, MK_BATCH_CLEARANCE, fmax(best, 0.0), &out, NULL);
	for (int m = 0; m < n; ++m)
		far[m] = (unsigned char)((r == MK_OK || r == MK_ERR_CONVERGENCE) && path[m] == MK_PATH_SEPARATING && clear[m]);
}

/* One part against the scene: the pairs in the walk's order, each screened
 * by the batch (MK_SQ_BATCH at a time, against the clearance found so far)
 * and, unless certified no nearer than it, answered by mkSq_Pair. The
 * answers are those of mkSq_Pair on every pair in the walk's order: a pair
 * the screen set aside cannot change them. Returns 1 when colliding. */
static int mkSq_PartPose(const mkSceneQuery *q, int j, mkMat3 R, mkVec3 c, double *best, mkPoseAnswer *out)
{
	mkBody3 outer = mkSq_Place(q->part[2 * j + 1], R, c), inner = mkSq_Place(q->part[2 * j], R, c);
	int smooth = q->part_body[j].kind == MK_SCENE_SMOOTH;
	mkSqBox pb = mkSq_BodyBox(outer);
	mkSqWalk w;
	w.top = w.k = w.end = 0;
	w.stack[w.top++] = 0;
	int idx[MK_SQ_BATCH];
	unsigned char far[MK_SQ_BATCH];
	for (;;) {
		/* no clearance yet (max_clearance infinite): the first pair alone */
		int n = mkSq_Collect(q, &w, &pb, *best, idx, isfinite(*best) ? MK_SQ_BATCH : 1);
		if (n == 0) return 0;
		if (isfinite(*best)) mkSq_Screen(q, idx, n, &outer, *best, far);
		else memset(far, 0, sizeof far);
		for (int m = 0; m < n; ++m) {
			int i = idx[m];
			if (mkSq_BoxDistance(&pb, &q->obox[i]) >= *best) continue;
			++out->pairs;
			if (far[m]) continue;
			double v;
			mkPoseStatus s = mkSq_Pair(q, i, inner, outer, smooth, &v);
			if (s == MK_POSE_UNCERTAIN) out->status = MK_POSE_UNCERTAIN;
			if (v < *best || s == MK_POSE_COLLIDING) {
				*best = v;
				out->obstacle = i;
				out->part = j;
			}
			if (s == MK_POSE_COLLIDING) {
				out->status = MK_POSE_COLLIDING;
				out->clearance = v;
				return 1;
			}
		}
	}
}

mkResult mkSceneQuery_Pose(const mkSceneQuery *q, const double *pose, mkPoseAnswer *out)
{
	mkMat3 R;
	mkVec3 c;
	out->status = MK_POSE_FREE;
	out->obstacle = out->part = -1;
	out->clearance = q->opt.max_clearance;
	out->pairs = 0;
	if (!mkSq_Pose(q, pose, &R, &c)) { out->status = MK_POSE_UNCERTAIN; out->clearance = NAN; return MK_ERR_ARGUMENT; }
	if (q->nob == 0) return MK_OK;
	double best = q->opt.max_clearance;
	for (int j = 0; j < q->parts; ++j)
		if (mkSq_PartPose(q, j, R, c, &best, out)) return MK_OK;
	out->clearance = best;
	return MK_OK;
}

/* ---- many poses ---- */

typedef struct mkSqJob {
	const mkSceneQuery *q;
	const double *poses;
	long n;
	mkPoseAnswer *out;
} mkSqJob;

static mkResult mkSqJob_Task(void *ctx, mkCSpaceWork *w, long task)
{
	(void)w;
	const mkSqJob *J = ctx;
	int ps = mkSceneQuery_PoseSize(J->q);
	long e = (task + 1) * MK_SQ_CHUNK < J->n ? (task + 1) * MK_SQ_CHUNK : J->n;
	for (long k = task * MK_SQ_CHUNK; k < e; ++k) mkSceneQuery_Pose(J->q, J->poses + k * ps, &J->out[k]);
	return MK_OK;
}

mkResult mkSceneQuery_Run(const mkSceneQuery *q, const double *poses, long n, mkPoseAnswer *out, char *msg, size_t msglen)
{
	if (!q || (n > 0 && (!poses || !out)) || n < 0) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no query, poses or answers");
	int ps = mkSceneQuery_PoseSize(q);
	mkMat3 R;
	mkVec3 c;
	for (long k = 0; k < n; ++k)
		if (!mkSq_Pose(q, poses + k * ps, &R, &c))
			return mkFail(MK_ERR_ARGUMENT, msg, msglen, "pose %ld is out of range: its %d values must be finite numbers of "
				"magnitude at most 1e150%s", k, ps, q->dim == 3 ? " and its quaternion nonzero" : "");
	mkSqJob J = {q, poses, n, out};
	mkResult r = mkCSpacePool_Run(mkSqJob_Task, &J, (n + MK_SQ_CHUNK - 1) / MK_SQ_CHUNK, q->opt.threads);
	if (r != MK_OK) mkFail(r, msg, msglen, "%s while checking poses", mkResult_Name(r));
	return r;
}
