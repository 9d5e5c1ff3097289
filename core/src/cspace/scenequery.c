/* scenequery.c - a robot at many poses against a scene (mink/scenequery.h):
 * exact boxes of the bodies, the eight-way hierarchy of the obstacles
 * (cspace/scenewide.h) walked nearest first or by box queries, or with a
 * cap the obstacles' spheres tested side by side (all of them in a scene of
 * few, those of the part's cell in a larger one), and the narrow phase on
 * the models of each pair. */
#include "mink/scenequery.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/geom_inline.h"
#include "base/message.h"
#include "cspace/scenecache.h"
#include "cspace/scenepair.h"
#include "cspace/sceneprep.h"
#include "cspace/scenewide.h"
#include "cspace/work.h"
#include "mink/batch.h"
#include "mink/collision.h"

#define MK_SQ_ROUND 1e-12   /* rounding allowance of a pair's bound, times its size */
#define MK_SQ_CHUNK MK_SQ_PREP   /* poses per pool task (prepared together: cspace/sceneprep.h) */
#define MK_SQ_WAITING 16    /* poses of a task whose groups wait for one batch call (finite max_clearance) */
#define MK_SQ_BATCH 8       /* candidate pairs screened per batch call */
#define MK_SQ_LEFT 32       /* pairs a part leaves to the one-pair query before they are answered */
#define MK_SQ_SPHERE_NODES 2  /* inner nodes a part's sphere opens before its exact box is computed */
#define MK_SQ_FLAT 128     /* scenes of at most this many obstacles: their spheres tested side by side, 32 to a mask (mkSqPrep_Near's vector builds), no hierarchy (finite max_clearance) */
#define MK_SQ_FLAT_PORTABLE 24   /* the same with mkSqPrep_Near's portable build */
#define MK_SQ_WORDS (MK_SQ_FLAT / 32)
#define MK_SQ_CELL_BYTES (1L << 20)   /* the cells of the spheres in place of the hierarchy's walk (a finite max_clearance), at most: a core's second-level cache */
_Static_assert(MK_SQ_WORDS <= MK_SQ_PREP_WORDS, "the preparation holds the masks of a scene of few obstacles");

typedef mkSwBox mkSqBox;

struct mkSceneQuery {
	const mkScene *scene;
	mkSceneQueryOptions opt;
	int dim, nob, parts;
	const mkSceneBody *part_body;
	mkBody3 *obs;      /* [i * 2 + bound]: inner, outer models */
	mkBody3 *part;     /* [j * 2 + bound], in the robot's frame */
	mkSqBox *obox;     /* outer models' boxes */
	double *reach;     /* part j's outer model lies within reach[j] of its centre */
	double *prad;      /* part j's outer model's mkSq_BodyRadius (the motion checks') */
	double (*osphere)[4];  /* obstacle i's outer model's centre and mkSq_BodyRadius */
	mkSqQuick *oquick, *oquick_in;   /* the obstacles' outer and inner models' data for the quick certificates */
	mkSqQuick *pquick;   /* [j * 2 + bound]: the parts' */
	double *oerr, *perr; /* the inner models' Hausdorff distance to the declared obstacles and parts (0: smooth) */
	mkSwTree wide;     /* the hierarchy of the obstacles' boxes */
	mkSwCells cells;   /* in place of its walk: a finite max_clearance, many obstacles (scenewide.h) */
	mkSqPrepFn prep;   /* the poses' preparation (cspace/sceneprep.h) */
	mkSqFirstBadFn firstbad;   /* its test of 3D poses */
	mkSqNearFn near;   /* its build of mkSqPrep_Near */
	int flat;          /* a scene of few obstacles (MK_SQ_FLAT): their spheres tested side by side (mkSqPrep_Near) */
	double *sx, *sy, *sz, *sr;   /* the obstacles' spheres (osphere), axis by axis */
	double *srr;       /* part j's squared radii of mkSqPrep_Near's test at max_clearance: srr[j * (nob + 1) + i] */
	mkSqPrepSpheres spheres;   /* the same for the preparation of the poses (its masks of the first parts) */
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
static mkResult mkSq_Model(const mkSceneBody *d, double rel, mkBound side, mkBody3 *out, double *err, char *msg,
	size_t msglen)
{
	double f = 0.0, s2 = 0.0;
	if (d->dim == 2) {
		const mkMat2 *M = &d->spec.body2.M;
		for (int i = 0; i < 4; ++i) f += M->m[i / 2][i % 2] * M->m[i / 2][i % 2];
		s2 = d->kind == MK_SCENE_BOX ? 0.25 * (d->size[0] * d->size[0] + d->size[1] * d->size[1]) : 0.0;
		mkBody2 b;
		mkResult r = mkSceneBody2_Model(d, rel * sqrt(f * s2) + (s2 > 0.0 ? 0.0 : 1.0), side, &b, err, msg, msglen);
		if (r == MK_OK) *out = mkSq_Lift(b);
		return r;
	}
	const mkMat3 *M = &d->spec.body3.M;
	for (int i = 0; i < 9; ++i) f += M->m[i / 3][i % 3] * M->m[i / 3][i % 3];
	if (d->kind == MK_SCENE_BOX) s2 = 0.25 * (d->size[0] * d->size[0] + d->size[1] * d->size[1] + d->size[2] * d->size[2]);
	else if (d->kind == MK_SCENE_CYLINDER) s2 = d->size[0] * d->size[0] + 0.25 * d->size[1] * d->size[1];
	return mkSceneBody3_Model(d, rel * sqrt(f * s2) + (s2 > 0.0 ? 0.0 : 1.0), side, out, err, msg, msglen);
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

/* An upper bound of |u| over the canonical shape (in its first dim axes):
 * the ellipsoid's largest semi-axis where an exponent is >= 1 (the shape
 * lies in the ellipsoid), the box's half diagonal where it is < 1. */
static double mkSq_ShapeRadius(mkShape3 s, int dim)
{
	double xy = s.eps2 >= 1.0 ? fmax(s.a, s.b) * fmax(s.a, s.b) : s.a * s.a + s.b * s.b;
	if (dim == 2) return sqrt(xy);
	return sqrt(s.eps1 >= 1.0 ? fmax(xy, s.c * s.c) : xy + s.c * s.c);
}

/* An upper bound of the body's distance from its centre t (the motion
 * checks' radius of a part, mkSq_PartRadius): the smaller of
 * the half diagonal of its exact box and |M|_2 (by Gershgorin on M^T M, exact
 * for a rotation times a diagonal) times the shape's radius. */
static double mkSq_BodyRadius(mkBody3 b, int dim)
{
	double h2 = 0.0, g = 0.0;
	for (int i = 0; i < dim; ++i) {
		mkVec3 e = {i == 0, i == 1, i == 2};
		double h = mkShape3_SupportValue(b.shape, mkMat3_MulTVec(b.M, e));
		h2 += h * h;
		double row = 0.0;
		for (int j = 0; j < dim; ++j) {
			double mtm = 0.0;
			for (int k = 0; k < dim; ++k) mtm += b.M.m[k][i] * b.M.m[k][j];
			row += fabs(mtm);
		}
		g = fmax(g, row);
	}
	return fmin(sqrt(h2), sqrt(g) * mkSq_ShapeRadius(b.shape, dim)) * (1.0 + 1e-12);
}

/* An upper bound of the distance of part j's outer model from its centre
 * at any rotation: the half diagonal of its exact box (over the scene's
 * dimensions: a 2D body's distances are planar), with a rounding allowance. */
static double mkSq_Reach(const mkSceneQuery *q, int j)
{
	mkSqBox x = mkSq_BodyBox(q->part[2 * j + 1]);
	double h2 = 0.0;
	for (int i = 0; i < q->dim; ++i) h2 += 0.25 * (x.hi[i] - x.lo[i]) * (x.hi[i] - x.lo[i]);
	return sqrt(h2) * (1.0 + 1e-12);
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
	if (!(opt->clearance_rel >= 0.0 && opt->clearance_rel <= 0.5))
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "clearance_rel = %g is out of range: must be in [0, 0.5]",
			opt->clearance_rel);
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
	q->prep = mkSqPrep_Pick(MK_IMPL_AUTO);
	q->firstbad = mkSqPrep_PickFirstBad(MK_IMPL_AUTO);
	q->near = mkSqPrep_PickNear(MK_IMPL_AUTO);
	q->flat = q->nob <= (q->near == mkSqPrep_Near ? MK_SQ_FLAT_PORTABLE : MK_SQ_FLAT);
	size_t nb = (size_t)q->nob + 1;
	q->obs = malloc(2 * nb * sizeof *q->obs);
	q->part = malloc(2 * (size_t)q->parts * sizeof *q->part);
	q->obox = malloc(nb * sizeof *q->obox);
	q->reach = malloc((size_t)q->parts * sizeof *q->reach);
	q->prad = malloc((size_t)q->parts * sizeof *q->prad);
	q->osphere = malloc(nb * sizeof *q->osphere);
	q->oquick = malloc(nb * sizeof *q->oquick);
	q->oquick_in = malloc(nb * sizeof *q->oquick_in);
	q->pquick = malloc(2 * (size_t)q->parts * sizeof *q->pquick);
	q->oerr = malloc(nb * sizeof *q->oerr);
	q->perr = malloc((size_t)q->parts * sizeof *q->perr);
	mkResult r = MK_OK;
	if (!q->obs || !q->part || !q->obox || !q->reach || !q->prad || !q->osphere || !q->oquick || !q->oquick_in || !q->pquick
		|| !q->oerr || !q->perr)
		r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	char sub[512];
	for (int k = 0; k < 2 && r == MK_OK; ++k) {
		double err;
		for (int i = 0; i < q->nob && r == MK_OK; ++i) {
			if ((r = mkSq_Model(&scene->obstacles[i], opt->model_rel, (mkBound)k, &q->obs[2 * i + k], &err, sub,
				sizeof sub)) != MK_OK)
				mkFail(r, msg, msglen, "obstacle %d: %s", i, sub);
			else if (k == MK_BOUND_INNER) q->oerr[i] = err;
		}
		for (int j = 0; j < q->parts && r == MK_OK; ++j) {
			if ((r = mkSq_Model(&q->part_body[j], opt->model_rel, (mkBound)k, &q->part[2 * j + k], &err, sub,
				sizeof sub)) != MK_OK)
				mkFail(r, msg, msglen, "part %d: %s", j, sub);
			else if (k == MK_BOUND_INNER) q->perr[j] = err;
		}
	}
	if (r == MK_OK && scene->part_count == 0) /* a hand-built scene's robot: its at= unused */
		for (int k = 0; k < 2; ++k) q->part[k].t = mkVec3_Make(0.0, 0.0, 0.0);
	for (int j = 0; j < q->parts && r == MK_OK; ++j) {
		q->reach[j] = mkSq_Reach(q, j);
		q->prad[j] = mkSq_BodyRadius(q->part[2 * j + 1], q->dim);
		for (int k = 0; k < 2; ++k) q->pquick[2 * j + k] = mkSqQuick_Make(q->part[2 * j + k]);
	}
	for (int i = 0; i < q->nob && r == MK_OK; ++i) {
		const mkBody3 *o = &q->obs[2 * i + 1];
		q->oquick[i] = mkSqQuick_Make(q->obs[2 * i + 1]);
		q->oquick_in[i] = mkSqQuick_Make(q->obs[2 * i]);
		q->osphere[i][0] = o->t.x;
		q->osphere[i][1] = o->t.y;
		q->osphere[i][2] = o->t.z;
		q->osphere[i][3] = mkSq_BodyRadius(*o, q->dim);
	}
	if (r == MK_OK && q->flat) {
		q->sx = malloc(4 * nb * sizeof *q->sx);
		if (!q->sx) r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
		else {
			q->sy = q->sx + nb;
			q->sz = q->sy + nb;
			q->sr = q->sz + nb;
			for (int i = 0; i < q->nob; ++i) {
				q->sx[i] = q->osphere[i][0];
				q->sy[i] = q->osphere[i][1];
				q->sz[i] = q->osphere[i][2];
				q->sr[i] = q->osphere[i][3];
			}
		}
		/* the tests' squared radii at max_clearance (where a part starts: mkSq_Advance) */
		q->srr = r == MK_OK ? malloc((size_t)q->parts * nb * sizeof *q->srr) : NULL;
		if (r == MK_OK && !q->srr) r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
		for (int j = 0; r == MK_OK && j < q->parts; ++j)
			for (int i = 0; i < q->nob; ++i) q->srr[(size_t)j * nb + i] = mkSqPrep_Radius2(q->prad[j], q->sr[i], q->opt.max_clearance);
		mkSqPrepSpheres sp = {q->sx, q->sy, q->sz, q->srr, q->nob, (int)nb};
		q->spheres = sp;
	}
	if (r == MK_OK) {
		for (int i = 0; i < q->nob; ++i) q->obox[i] = mkSq_BodyBox(q->obs[2 * i + 1]);
		if (mkSwTree_Build(&q->wide, q->obox, q->nob) != MK_OK) r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
	}
	if (r == MK_OK && !q->flat && isfinite(q->opt.max_clearance)) {
		/* the spheres near a part's (mkSq_SpheresApart) by cells */
		double rad = 0.0;
		for (int j = 0; j < q->parts; ++j) rad = fmax(rad, q->prad[j]);
		rad += q->opt.max_clearance;
		if (mkSwCells_Build(&q->cells, &q->wide, (const double (*)[4])q->osphere, rad, 4.0 * rad, MK_SQ_CELL_BYTES) != MK_OK)
			r = mkFail(MK_ERR_MEMORY, msg, msglen, "out of memory");
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
	free(q->obs); free(q->part); free(q->obox); free(q->reach); free(q->prad); free(q->osphere);
	free(q->oquick); free(q->oquick_in); free(q->pquick); free(q->oerr); free(q->perr); free(q->sx); free(q->srr);
	mkSwTree_Free(&q->wide);
	mkSwCells_Free(&q->cells);
	free(q);
}

int mkSceneQuery_PoseSize(const mkSceneQuery *q) { return q->dim == 2 ? 3 : 7; }

int mkSq_ObstacleBox(const mkSceneQuery *q, int i, double lo[3], double hi[3])
{
	if (i < 0 || i >= q->nob) return 0;
	memcpy(lo, q->obox[i].lo, sizeof q->obox[i].lo);
	memcpy(hi, q->obox[i].hi, sizeof q->obox[i].hi);
	return 1;
}

double mkSq_PartRadius(const mkSceneQuery *q, int j) { return q->prad[j]; }

/* ---- poses ---- */

/* What a pose must be: finite values of magnitude at most 1e150 and, in
 * 3D, a quaternion whose squared norm is positive (its rotation is then
 * finite: the squared norm lies between the least subnormal and 4e300). */
static int mkSq_PoseOk(const mkSceneQuery *q, const double *p)
{
	int n = mkSceneQuery_PoseSize(q);
	for (int k = 0; k < n; ++k)
		if (!isfinite(p[k]) || fabs(p[k]) > 1e150) return 0;
	return q->dim == 2 || p[3] * p[3] + p[4] * p[4] + p[5] * p[5] + p[6] * p[6] > 0.0;
}

/* The rotation and position of a pose mkSq_PoseOk accepts. */
static void mkSq_Rotation(const mkSceneQuery *q, const double *p, mkMat3 *R, mkVec3 *c)
{
	if (q->dim == 2) {
		double cs = cos(p[2]), sn = sin(p[2]);
		mkMat3 r = {{{cs, -sn, 0.0}, {sn, cs, 0.0}, {0.0, 0.0, 1.0}}};
		*R = r;
		*c = mkVec3_Make(p[0], p[1], 0.0);
		return;
	}
	*R = mkMat3_FromQuatInline(p[3], p[4], p[5], p[6]);
	*c = mkVec3_Make(p[0], p[1], p[2]);
}

/* The pose's rotation and position; 0 when mkSq_PoseOk refuses it. */
static int mkSq_Pose(const mkSceneQuery *q, const double *p, mkMat3 *R, mkVec3 *c)
{
	if (!mkSq_PoseOk(q, p)) return 0;
	mkSq_Rotation(q, p, R, c);
	return mkMat3_IsFiniteInline(*R);
}

static mkBody3 mkSq_Place(mkBody3 b, const mkMat3 *R, mkVec3 c)
{
	b.M = mkMat3_MulInline(*R, b.M);
	b.t = mkVec3_Add(c, mkMat3_MulVecInline(*R, b.t));
	return b;
}

int mkSceneQuery_PartBody(const mkSceneQuery *q, const double *pose, int j, int bound, mkBody3 *out)
{
	mkMat3 R;
	mkVec3 c;
	if (!q || !out || j < 0 || j >= q->parts || (bound != 0 && bound != 1) || !mkSq_Pose(q, pose, &R, &c)) return 0;
	*out = mkSq_Place(q->part[2 * j + bound], &R, c);
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
 * value as the header defines them (free: a lower bound of the distance;
 * colliding: an upper bound of the signed distance, <= 0). outer_lb: NaN,
 * or the outer models' certified lower bound, already rounded down and not
 * positive (the batch asked the one-pair query already; never for two
 * smooth bodies, whose overlap is read from the outer query's answer):
 * then only the inner models are asked. */
static mkPoseStatus mkSq_Pair(const mkSceneQuery *q, int i, mkBody3 inner, mkBody3 outer, int smooth, double outer_lb,
	double *value)
{
	mkCollision3 c;
	mkCollision3_Clear(&c);
	double tol, lb = outer_lb;
	if (isnan(lb)) {
		if (mkCollide3_Normal(q->obs[2 * i + 1], outer, &c) != MK_OK) { *value = -INFINITY; return MK_POSE_UNCERTAIN; }
		tol = MK_SQ_ROUND * c.scale;
		lb = c.bound - tol;
	} else {
		tol = MK_SQ_ROUND * mkCollide3_PairSize(q->obs[2 * i + 1], outer);
	}
	*value = lb;
	if (lb > 0.0) return MK_POSE_FREE;
	if ((!smooth || q->scene->obstacles[i].kind != MK_SCENE_SMOOTH) && mkCollide3_Normal(q->obs[2 * i], inner, &c) != MK_OK)
		return MK_POSE_UNCERTAIN;
	if (!mkSq_Overlap(q->obs[2 * i], inner, &c, tol)) return MK_POSE_UNCERTAIN;
	*value = c.certified == 1 && c.bound + c.gap < 0.0 ? c.bound + c.gap : 0.0;
	return MK_POSE_COLLIDING;
}

/* A robot part at the pose, tested against boxes by its centre c and,
 * first, the sphere about c that holds its outer model (radius reach, the
 * same at every rotation; h = 0), then its exact box (half-widths h,
 * reach = 0), computed once the sphere has not settled a leaf's obstacle
 * or has opened MK_SQ_SPHERE_NODES inner nodes (mkSq_BoxMode). Its models
 * are placed when first needed (mkSq_Placed). */
typedef struct mkSqPart {
	const mkBody3 *rest;   /* its inner and outer models in the robot's frame */
	const mkMat3 *R;       /* the pose */
	mkVec3 at;
	double c[3], reach, h[3];
	mkBody3 outer, inner;  /* once placed */
	int placed, has_box, opened, smooth, j;
} mkSqPart;

/* The part's models at the pose (computed once). */
static void mkSq_Placed(mkSqPart *p)
{
	if (p->placed) return;
	p->outer = p->rest[1];
	p->outer.M = mkMat3_MulInline(*p->R, p->rest[1].M);
	p->outer.t = mkVec3_Make(p->c[0], p->c[1], p->c[2]);   /* (mkSq_Place's c + R t, formed already) */
	p->inner = p->smooth ? p->outer : mkSq_Place(p->rest[0], p->R, p->at);   /* a smooth part's models are the body */
	p->placed = 1;
}

/* The square of the gap between c and [lo, hi] (branch-free: one of the
 * two terms is 0). */
static inline double mkSq_Gap2(double c, double lo, double hi)
{
	double u = lo - c, v = c - hi;
	u = u > 0.0 ? u : 0.0;
	v = v > 0.0 ? v : 0.0;
	return u * u + v * v;
}

/* The squared distance from the part's centre to a box grown by h: with
 * the exact box, the squared distance between the boxes. */
static inline double mkSq_CentreDistance2(const mkSqPart *p, const mkSqBox *x)
{
	return mkSq_Gap2(p->c[0], x->lo[0] - p->h[0], x->hi[0] + p->h[0])
		+ mkSq_Gap2(p->c[1], x->lo[1] - p->h[1], x->hi[1] + p->h[1])
		+ mkSq_Gap2(p->c[2], x->lo[2] - p->h[2], x->hi[2] + p->h[2]);
}

/* The same for child k of node nd (its float box). */
static inline double mkSq_ChildDistance2(const mkSqPart *p, const mkSwNode *nd, int k)
{
	return mkSq_Gap2(p->c[0], nd->lo[0][k] - p->h[0], nd->hi[0][k] + p->h[0])
		+ mkSq_Gap2(p->c[1], nd->lo[1][k] - p->h[1], nd->hi[1][k] + p->h[1])
		+ mkSq_Gap2(p->c[2], nd->lo[2][k] - p->h[2], nd->hi[2][k] + p->h[2]);
}

/* Boxes whose squared distance (mkSq_CentreDistance2) is at least this are
 * at least best from the part (-1 when best <= 0: all). */
static inline double mkSq_Limit2(const mkSqPart *p, double best)
{
	double lim = best + p->reach;
	return best > 0.0 ? lim * lim : -1.0;
}

/* 1 when the part is certainly at least best away from everything in box
 * x (by its sphere or its exact box, whichever it is tested by). */
static inline int mkSq_Far(const mkSqPart *p, const mkSqBox *x, double best)
{
	return mkSq_CentreDistance2(p, x) >= mkSq_Limit2(p, best);
}

/* 1 when part p and obstacle i are certainly at least b apart by their
 * spheres: centres farther apart than the sum of their radii (bounds of
 * their outer models' distances from their centres) and b, with a
 * rounding allowance. */
static inline int mkSq_SpheresApart(const mkSceneQuery *q, const mkSqPart *p, int i, double b)
{
	const double *o = q->osphere[i];
	return mkSqPrep_Apart(p->c[0] - o[0], p->c[1] - o[1], p->c[2] - o[2], q->prad[p->j], o[3], b);
}

/* The part's box (its sphere's or its exact box) grown by b on every side,
 * rounded outwards to floats. */
static void mkSq_QueryBox(const mkSqPart *p, double b, float lo[3], float hi[3])
{
	for (int i = 0; i < 3; ++i) {
		double half = mkSqPrep_Half(p->h[i], p->reach, b);
		lo[i] = mkSw_Down(p->c[i] - half);
		hi[i] = mkSw_Up(p->c[i] + half);
	}
}

/* A part's walk of the hierarchy, nearest child first: the stack of the
 * children to visit, each as node * MK_SW_WIDTH + its slot in node, with
 * its squared distance from the part (mkSq_ChildDistance2), the root as -1
 * (distance 0), and the leaf being read (positions k .. end). */
typedef struct mkSqWalk {
	int entry[MK_SW_STACK], top, k, end;
	double d2[MK_SW_STACK];
} mkSqWalk;

/* Part j is a smooth ellipsoid (its exact box without placing it). */
static int mkSq_EllipsoidBody(const mkSceneQuery *q, int j)
{
	return q->part_body[j].kind == MK_SCENE_SMOOTH && q->part[2 * j + 1].shape.eps1 == 1.0 && q->part[2 * j + 1].shape.eps2 == 1.0;
}

/* The same from the part at the pose (its own fields, at hand on the
 * walk's hot path). */
static int mkSq_EllipsoidPart(const mkSqPart *p)
{
	return p->smooth && p->rest[1].shape.eps1 == 1.0 && p->rest[1].shape.eps2 == 1.0;
}

/* The box mkSq_EllipsoidBox gives, from the prepared poses (lane l). */
static void mkSq_EllipsoidBoxAt(mkSqPart *p, const mkSqPrep *x, int l)
{
	for (int i = 0; i < 3; ++i) p->h[i] = x->eh[3 * p->j + i][l];
	p->reach = 0.0;
	p->has_box = 1;
}

/* A smooth ellipsoid part's exact box without placing it: half-width i is
 * |diag(a, b, c) (R M)^T e_i|, its support value at e_i, rounded up as
 * mkSq_ExactBox's (R M as mkSq_Place forms it). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void mkSq_EllipsoidBox(mkSqPart *p)
{
	const mkBody3 *b = &p->rest[1];
	mkMat3 M = mkMat3_MulInline(*p->R, b->M);
	double s[3] = {b->shape.a, b->shape.b, b->shape.c};
	for (int i = 0; i < 3; ++i) {
		double x = M.m[i][0] * s[0], y = M.m[i][1] * s[1], z = M.m[i][2] * s[2];
		p->h[i] = sqrt(x * x + y * y + z * z) * (1.0 + 1e-13);
	}
	p->reach = 0.0;
	p->has_box = 1;
}

/* Switch the part to its exact box: its half-widths, the support values
 * at +-e_i (the rows of M, by the dual norms) rounded up (mkSq_ExactBox),
 * and the stacked children's distances again (mkSq_BoxMode). */
static void mkSq_ExactBox(mkSqPart *p)
{
	mkSq_Placed(p);
	for (int i = 0; i < 3; ++i) {
		mkVec3 row = {p->outer.M.m[i][0], p->outer.M.m[i][1], p->outer.M.m[i][2]};
		p->h[i] = mkSq_ShapeNorm(p->outer.shape, row, 1) * (1.0 + 1e-13);
	}
	p->reach = 0.0;
	p->has_box = 1;
}

static void mkSq_BoxMode(const mkSceneQuery *q, mkSqPart *p, mkSqWalk *w)
{
	mkSq_ExactBox(p);
	for (int k = 0; k < w->top; ++k)
		if (w->entry[k] >= 0)
			w->d2[k] = mkSq_ChildDistance2(p, &q->wide.node[w->entry[k] / MK_SW_WIDTH], w->entry[k] % MK_SW_WIDTH);
}

/* Node e's children nearer than lim2 stacked, the nearest on top (first
 * those whose boxes meet [lo, hi], the part's box grown by the best
 * clearance on every side, by mkSwNode_Meet). */
static void mkSq_Open(const mkSceneQuery *q, mkSqWalk *w, const mkSqPart *p, int e, const float lo[3],
	const float hi[3], double lim2)
{
	const mkSwNode *nd = &q->wide.node[e];
	double d[MK_SW_WIDTH];
	int at[MK_SW_WIDTH], n = 0;
	for (unsigned bits = mkSwNode_Meet(nd, lo, hi); bits; bits &= bits - 1) {
		int k = mkSw_Low(bits);
		if (nd->first[k] < 0) continue;
		double dk = mkSq_ChildDistance2(p, nd, k);
		if (!(dk < lim2)) continue;
		int m = n++;
		for (; m > 0 && d[m - 1] < dk; --m) { d[m] = d[m - 1]; at[m] = at[m - 1]; }   /* farthest first */
		d[m] = dk;
		at[m] = e * MK_SW_WIDTH + k;
	}
	for (int m = 0; m < n; ++m) { w->entry[w->top] = at[m]; w->d2[w->top++] = d[m]; }
}

/* The walk's next candidates (at most max): the obstacles not
 * certainly at least best away (mkSq_Far by the exact box), in the walk's
 * order (the nearer child first; it does not depend on best: best only
 * prunes). The part is switched to its exact box when its sphere does not
 * rule out an obstacle or has opened MK_SQ_SPHERE_NODES inner nodes.
 * Returns their number, 0 when the walk is over. */
static int mkSq_Collect(const mkSceneQuery *q, mkSqWalk *w, mkSqPart *p, double best, int *pos, int max)
{
	int n = 0;
	double lim2 = mkSq_Limit2(p, best);
	float lo[3], hi[3];
	mkSq_QueryBox(p, best, lo, hi);
	while (n < max) {
		if (w->k < w->end) {
			int k = w->k++;
			if (mkSq_Far(p, &q->wide.box[k], best)) continue;
			if (!p->has_box) {
				mkSq_BoxMode(q, p, w);
				lim2 = mkSq_Limit2(p, best);
				mkSq_QueryBox(p, best, lo, hi);
				if (mkSq_Far(p, &q->wide.box[k], best)) continue;
			}
			pos[n++] = q->wide.order[k];
			continue;
		}
		if (w->top == 0) break;
		--w->top;
		if (w->d2[w->top] >= lim2) continue;
		int e = w->entry[w->top];
		if (e < 0) { /* the root */
			mkSq_Open(q, w, p, 0, lo, hi, lim2);
			continue;
		}
		const mkSwNode *nd = &q->wide.node[e / MK_SW_WIDTH];
		int slot = e % MK_SW_WIDTH;
		if (nd->count[slot] > 0) {
			w->k = nd->first[slot];
			w->end = w->k + nd->count[slot];
			continue;
		}
		if (!p->has_box && ++p->opened > MK_SQ_SPHERE_NODES) {
			mkSq_BoxMode(q, p, w);
			lim2 = mkSq_Limit2(p, best);
			mkSq_QueryBox(p, best, lo, hi);
		}
		mkSq_Open(q, w, p, nd->first[slot], lo, hi, lim2);
	}
	return n;
}

/* Obstacle i's and the part's models for the quick certificates (a smooth
 * body's inner model is its outer one: the same data). */
static mkSqModels mkSq_ObstacleModels(const mkSceneQuery *q, int i)
{
	int smooth = q->scene->obstacles[i].kind == MK_SCENE_SMOOTH;
	mkSqModels m = {&q->obs[2 * i + 1], &q->obs[2 * i + smooth], &q->oquick[i], smooth ? &q->oquick[i] : &q->oquick_in[i]};
	return m;
}

static mkSqModels mkSq_PartModels(const mkSceneQuery *q, const mkSqPart *p)
{
	mkSqModels m = {&p->outer, &p->inner, &q->pquick[2 * p->j + 1], &q->pquick[2 * p->j + p->smooth]};
	return m;
}

/* A pair whose outer models the batch certified to overlap at the point
 * x: colliding when the inner models overlap for certain (the same bodies
 * for two smooth ones; else x inside both by their gauges, or the batch's
 * status on the inner models), *value then minus the certified depth.
 * With a finite max_clearance, -1 when the batch certifies the inner
 * models apart instead (the pair lies in the models' band: neither free
 * nor colliding, whatever the one-pair query finds), *value then a lower
 * bound of the declared bodies' signed distance (<= 0): the inner models'
 * less the inner models' errors (the declared bodies lie within them of
 * the inner models). 0 when the one-pair query must decide. */
static int mkSq_Contact(const mkSceneQuery *q, const mkSqPart *p, int i, double upper, mkVec3 x, double *value)
{
	if (p->smooth && q->scene->obstacles[i].kind == MK_SCENE_SMOOTH) { *value = upper; return 1; }
	mkSqModels om = mkSq_ObstacleModels(q, i), pm = mkSq_PartModels(q, p);
	double depth = mkSqQuick_PointDepth(&om, &pm, p->R, x);
	if (depth > MK_BATCH_MARGIN * mkCollide3_PairSize(q->obs[2 * i], p->inner)) {
		*value = -depth;
		return 1;
	}
	int i1 = 2 * i, i2 = 0;
	mkContact st;
	unsigned char path;
	double up, lo;
	mkBatchPairs3 pairs = {1, q->obs, &p->inner, &i1, &i2};
	mkBatchOut3 out = {.status = &st, .lower = &lo, .upper = &up, .path = &path};
	if (mkCollide3_Batch(&pairs, MK_BATCH_STATUS, 0.0, &out, NULL) != MK_OK) return 0;
	if (path == MK_PATH_SEPARATING && isfinite(q->opt.max_clearance) && lo > 0.0) {
		double v = lo - q->oerr[i] - q->perr[p->j] - MK_SQ_ROUND * mkCollide3_PairSize(q->obs[2 * i], p->inner);
		*value = v < 0.0 ? v : 0.0;
		return -1;
	}
	if (path != MK_PATH_OVERLAP_POINT) return 0;
	*value = up;
	return 1;
}

/* Pair i's answer s with its value v (mkSq_Pair's; or its overlap already
 * certified: s colliding; a certified lower bound v of its distance: s
 * free) into the pose's answer. Returns 1 when colliding. */
static int mkSq_Take(const mkSqPart *p, int i, mkPoseStatus s, double v, double *best, mkPoseAnswer *out)
{
	if (s == MK_POSE_UNCERTAIN) out->status = MK_POSE_UNCERTAIN;
	if (v < *best || s == MK_POSE_COLLIDING) {
		*best = v;
		out->obstacle = i;
		out->part = p->j;
	}
	if (s != MK_POSE_COLLIDING) return 0;
	out->status = MK_POSE_COLLIDING;
	out->clearance = v;
	return 1;
}

/* The pairs of a part left to the one-pair query: their obstacles,
 * certified lower bounds of their distances and margins, the lowest bound
 * first, and the outer models' answer where the batch asked the one-pair
 * query already (mkSq_Pair's outer_lb; else NaN). */
typedef struct mkSqLeft {
	int n, i[MK_SQ_LEFT];
	double lower[MK_SQ_LEFT], margin[MK_SQ_LEFT], outer[MK_SQ_LEFT];
} mkSqLeft;

/* The pairs left, lowest bound first, by the one-pair query, each skipped
 * when its bound exceeds the clearance found by then by its margin (it
 * cannot lower it). Returns 1 when colliding. */
static int mkSq_Resolve(const mkSceneQuery *q, const mkSqPart *p, mkSqLeft *l, double *best, mkPoseAnswer *out)
{
	int n = l->n;
	l->n = 0;
	for (int e = 0; e < n; ++e) {
		if (l->lower[e] > *best + l->margin[e]) continue;
		double v;
		mkPoseStatus s = mkSq_Pair(q, l->i[e], p->inner, p->outer, p->smooth, l->outer[e], &v);
		if (mkSq_Take(p, l->i[e], s, v, best, out)) return 1;
	}
	return 0;
}

/* Pair i left to the one-pair query with the certified lower bound lo and
 * the outer models' answer outer (mkSqLeft), answering the pairs left when
 * full. Returns 1 when colliding. */
static int mkSq_Leave(const mkSceneQuery *q, const mkSqPart *p, mkSqLeft *l, int i, double lo, double outer,
	double *best, mkPoseAnswer *out)
{
	if (l->n == MK_SQ_LEFT && mkSq_Resolve(q, p, l, best, out)) return 1;
	mkVec3 d = mkVec3_Sub(p->outer.t, q->obs[2 * i + 1].t);
	int at = l->n++;
	for (; at > 0 && l->lower[at - 1] > lo; --at) {
		l->i[at] = l->i[at - 1];
		l->lower[at] = l->lower[at - 1];
		l->margin[at] = l->margin[at - 1];
		l->outer[at] = l->outer[at - 1];
	}
	l->i[at] = i;
	l->lower[at] = lo;
	l->outer[at] = outer;
	l->margin[at] = 4e-12 * (sqrt(mkVec3_Dot(d, d)) + q->oquick[i].r + q->pquick[2 * p->j + 1].r);
	return 0;
}

/* A group of candidate pairs of one part in the narrow phase: the
 * obstacles, the quick certificates' answers and depths, the pairs left
 * for the batch (slot: a candidate's place among them, -1 none) with the
 * call's mode, and the batch's answers once it has run. */
typedef struct mkSqGroup {
	int n, ids[MK_SQ_BATCH], quick[MK_SQ_BATCH], slot[MK_SQ_BATCH];
	double depth[MK_SQ_BATCH];
	int nb, i1[MK_SQ_BATCH];  /* the batch's pairs: obstacle models (outer), against the part's outer model */
	int known;                /* b was finite: clearance mode with delta (else status mode) */
	double delta;
	int ok;                   /* the batch ran (MK_OK or MK_ERR_CONVERGENCE) */
	mkContact status[MK_SQ_BATCH];
	double lower[MK_SQ_BATCH], upper[MK_SQ_BATCH];
	mkVec3 point[MK_SQ_BATCH];   /* the batch's witness p1 (an overlap's point) */
	unsigned char clear[MK_SQ_BATCH], path[MK_SQ_BATCH];
} mkSqGroup;

/* The narrow phase of the candidate obstacles ids[0 .. n) in the walk's
 * order, against the bound b = min(best, bound): best the smallest one-pair
 * value, bound the smallest certified upper bound of a pair's distance
 * found (the pose's clearance is at most either). First the quick
 * certificates (mkSqQuick_Pair) and the pairs they leave for the batch
 * (mkSq_NarrowPrep; clearance mode with delta = b, or status mode while b
 * is infinite; with clearance_rel, brackets that narrow, also for the pairs
 * the quick certificates found separated before any clearance was known);
 * the batch then runs on them (mkSq_NarrowBatch, or one call for the groups
 * of many poses: mkSq_Flush). */
static void mkSq_NarrowPrep(const mkSceneQuery *q, mkSqPart *p, const int *ids, int n, double best, double bound,
	mkSqGroup *g)
{
	double b = fmin(best, bound), rel = q->opt.clearance_rel;
	mkSq_Placed(p);
	mkSqModels pm = mkSq_PartModels(q, p);
	g->n = n;
	g->nb = 0;
	g->known = isfinite(b);
	g->delta = g->known ? fmax(b, 0.0) : 0.0;
	for (int m = 0; m < n; ++m) {
		int i = ids[m];
		g->ids[m] = i;
		g->depth[m] = 0.0;
		mkSqModels o = mkSq_ObstacleModels(q, i);
		g->quick[m] = mkSqQuick_Pair(&o, &pm, p->R, b, &g->depth[m]);
		/* (separated with no clearance known yet: a bracket serves where it may be rel wide) */
		int batch = g->quick[m] == 0 || (g->quick[m] == 3 && rel > 0.0);
		g->slot[m] = batch ? g->nb : -1;
		if (batch) g->i1[g->nb++] = 2 * i + 1;
	}
}

/* The batch call of pairs (the obstacles' outer models against parts)
 * in the group's mode; returns whether it ran. */
static int mkSq_BatchCall(const mkSceneQuery *q, const mkBatchPairs3 *pairs, int known, double delta, mkBatchOut3 *bo)
{
	double rel = q->opt.clearance_rel;
	mkResult r = rel > 0.0 ? mkCollide3_BatchBracket(pairs, rel, bo, NULL)
		: mkCollide3_Batch(pairs, known ? MK_BATCH_CLEARANCE : MK_BATCH_STATUS, delta, bo, NULL);
	return r == MK_OK || r == MK_ERR_CONVERGENCE;
}

/* The group's batch on its own. */
static void mkSq_NarrowBatch(const mkSceneQuery *q, const mkSqPart *p, mkSqGroup *g)
{
	int i2[MK_SQ_BATCH] = {0};
	mkBatchPairs3 pairs = {g->nb, q->obs, &p->outer, g->i1, i2};
	mkBatchOut3 bo = {.status = g->status, .lower = g->lower, .upper = g->upper, .p1 = g->point, .clear = g->clear,
		.path = g->path};
	g->ok = g->nb == 0 || mkSq_BatchCall(q, &pairs, g->known, g->delta, &bo);
}

/* The group's answers, in the walk's order: each pair not certainly at
 * least b away (by the boxes) is set aside when certified at least b away,
 * is colliding when an overlap is certified (mkSq_Contact for the batch's),
 * takes the lower end of its bracket (clearance_rel) or of the one-pair
 * query's bracket (where the batch asked it) as its value when that is
 * positive, else it is left to the one-pair query (mkSq_Leave: for the
 * inner models only where the batch asked it already) and its certified
 * upper bound lowers bound. Returns 1 when colliding. */
static int mkSq_NarrowFinish(const mkSceneQuery *q, mkSqPart *p, const mkSqGroup *g, double *best, double *bound,
	mkSqLeft *left, mkPoseAnswer *out)
{
	double rel = q->opt.clearance_rel;
	int ok = g->ok, known = g->known;
	const double *lower = g->lower, *upper = g->upper;
	const unsigned char *clear = g->clear, *path = g->path;
	for (int m = 0; m < g->n; ++m) {
		int i = g->ids[m], k = g->slot[m], quick = g->quick[m];
		if (mkSq_Far(p, &q->obox[i], fmin(*best, *bound))) continue;
		++out->pairs;
		if (quick == 1 || (k >= 0 && ok && known && rel == 0.0 && path[k] == MK_PATH_SEPARATING && clear[k])) continue;
		/* the outer models' certified lower bound where the one-pair query gave it (rounded down) */
		double outer = NAN;
		if (k >= 0 && ok && (path[k] == MK_PATH_ONE_PAIR || (rel > 0.0 && path[k] == MK_PATH_SEPARATING))) {
			/* (a bracket at most rel wide, or the one-pair query's: its lower end is the pair's value) */
			outer = lower[k] - MK_SQ_ROUND * mkCollide3_PairSize(q->obs[2 * i + 1], p->outer);
			if (upper[k] < *bound) *bound = upper[k];
			if (outer > 0.0) {
				mkSq_Take(p, i, MK_POSE_FREE, outer, best, out);
				continue;
			}
			/* (two smooth bodies: mkSq_Pair reads the one-pair query's answer, so it asks again) */
			if (path[k] != MK_PATH_ONE_PAIR || !isfinite(outer) || (p->smooth && q->scene->obstacles[i].kind == MK_SCENE_SMOOTH))
				outer = NAN;
		}
		double v = -g->depth[m];
		int contact = quick == 2 ? 1 : k >= 0 && ok && path[k] == MK_PATH_OVERLAP_POINT
			? mkSq_Contact(q, p, i, upper[k], g->point[k], &v) : 0;
		if (contact == 1) return mkSq_Take(p, i, MK_POSE_COLLIDING, v, best, out);
		int got = k >= 0 && ok;
		if (got && upper[k] < *bound) *bound = upper[k];
		if (contact == -1) { /* the models' band: uncertain */
			mkSq_Take(p, i, MK_POSE_UNCERTAIN, v, best, out);
			continue;
		}
		if (mkSq_Leave(q, p, left, i, got && !isnan(lower[k]) ? lower[k] : -INFINITY, outer, best, out)) return 1;
	}
	return 0;
}

/* The three steps at once. Returns 1 when colliding. */
static int mkSq_Narrow(const mkSceneQuery *q, mkSqPart *p, const int *ids, int n, double *best, double *bound,
	mkSqLeft *left, mkPoseAnswer *out)
{
	mkSqGroup g;
	mkSq_NarrowPrep(q, p, ids, n, *best, *bound, &g);
	mkSq_NarrowBatch(q, p, &g);
	return mkSq_NarrowFinish(q, p, &g, best, bound, left, out);
}

/* Part j at the pose, tested by its sphere at first (mkSqPart), its
 * outer model's centre pc. */
static void mkSq_PartAt(const mkSceneQuery *q, int j, const mkMat3 *R, mkVec3 c, mkVec3 pc, mkSqPart *p)
{
	p->smooth = q->part_body[j].kind == MK_SCENE_SMOOTH;
	p->rest = &q->part[2 * j];
	p->R = R;
	p->at = c;
	p->c[0] = pc.x;
	p->c[1] = pc.y;
	p->c[2] = pc.z;
	p->placed = 0;
	p->reach = q->reach[j];
	p->h[0] = p->h[1] = p->h[2] = 0.0;
	p->has_box = p->opened = 0;
	p->j = j;
}

/* The same at the pose (the centre as mkSq_Place places it). */
static void mkSq_PartInit(const mkSceneQuery *q, int j, const mkMat3 *R, mkVec3 c, mkSqPart *p)
{
	mkSq_PartAt(q, j, R, c, mkVec3_Add(c, mkMat3_MulVecInline(*R, q->part[2 * j + 1].t)), p);
}

/* One part against the scene: the walk's candidates, MK_SQ_BATCH at a time
 * (one, answered at once, while no clearance is known, so that the first
 * pair sets it), each group through mkSq_Narrow, then the pairs left by
 * the one-pair query (mkSq_Resolve). Returns 1 when colliding. */
static int mkSq_PartPose(const mkSceneQuery *q, int j, const mkMat3 *R, mkVec3 c, double *best, double *bound,
	mkPoseAnswer *out)
{
	mkSqPart p;
	mkSq_PartInit(q, j, R, c, &p);
	mkSqWalk w;
	w.k = w.end = 0;
	w.top = 1;
	w.entry[0] = -1;
	w.d2[0] = 0.0;
	mkSqLeft left;
	left.n = 0;
	int pos[MK_SQ_BATCH];
	for (;;) {
		double b = fmin(*best, *bound);
		int n = mkSq_Collect(q, &w, &p, b, pos, isfinite(b) ? MK_SQ_BATCH : 1);
		if (n == 0) return mkSq_Resolve(q, &p, &left, best, out);
		if (mkSq_Narrow(q, &p, pos, n, best, bound, &left, out)) return 1;
		if (!isfinite(*best) && mkSq_Resolve(q, &p, &left, best, out)) return 1;   /* the first pair sets best */
	}
}

/* A pose with a finite max_clearance, walked part by part by box queries
 * of the eight-way hierarchy instead of the walk nearest first: the
 * obstacles whose boxes meet the part's box grown by the bound b =
 * min(best, bound) on every side (its sphere's box, an ellipsoid part's
 * exact box from the start (mkSq_EllipsoidBox); its exact box when b
 * changes after the exact box was computed), each tested by mkSq_Far and
 * mkSq_SpheresApart, by the exact box once the sphere does not rule out an
 * obstacle, and the rest as in mkSq_PartPose. In a scene of few obstacles
 * (q->flat) every obstacle's sphere is tested instead of the walk, in a
 * larger one with cells (q->cells) those of the part's cell (in the walk's
 * order): both keep every obstacle the walk's tests keep (an obstacle
 * mkSq_Far keeps meets the part's query box), so the answers are the
 * walk's (with few obstacles, in index order). The pose stops where its
 * group of candidates needs the batch (mkSq_Advance), so that the groups of
 * many poses go to the batch in one call (mkSq_Flush); its state is
 * self-contained but for p.R, which points at R. */
typedef enum mkSqStep { MK_SQ_NEXT_PART, MK_SQ_WALK, MK_SQ_WAIT } mkSqStep;

typedef struct mkSqPose {
	mkMat3 R;
	mkVec3 c;
	double best, bound, bq;   /* bq: the bound of the query box */
	mkPoseAnswer *out;
	int j;                    /* the part walked (MK_SQ_WALK, MK_SQ_WAIT) or next */
	mkSqStep step;
	mkSqPart p;
	mkSwWalk w;
	float lo[3], hi[3];
	const mkSwCellBlock *cb;  /* the blocks of the part's cell (mkSwCells), cn of them (-1: the walk), ck taken; */
	int cn, ck;               /* cm: the near places of block ck; cf: the part's centre in the cell's units */
	unsigned cm;
	float cf[3];
	mkSqLeft left;
	mkSqGroup g;              /* MK_SQ_WAIT: the group whose batch is awaited */
	uint32_t near[MK_SQ_WORDS];   /* a scene of few obstacles: those near the part not yet taken, 32 to a word (mkSqPrep_Near) */
	int word;                 /* the first word of near not yet empty */
	const mkSqPrep *prep;     /* the task's prepared poses (NULL: none), this one in lane */
	int lane, prepared;       /* prepared: the parts whose centres and first query boxes are there */
} mkSqPose;

/* The answer before any pair: free, no obstacle nearer than max_clearance. */
static void mkSq_AnswerInit(const mkSceneQuery *q, mkPoseAnswer *out)
{
	out->status = MK_POSE_FREE;
	out->obstacle = out->part = -1;
	out->clearance = q->opt.max_clearance;
	out->pairs = 0;
}

/* The pose's state before its first part; 0 when there is nothing to walk
 * (no obstacles: *out is then the answer). */
static int mkSq_PoseBegin(const mkSceneQuery *q, const mkMat3 *R, mkVec3 c, mkPoseAnswer *out, mkSqPose *s)
{
	mkSq_AnswerInit(q, out);
	if (q->nob == 0) return 0;
	s->R = *R;
	s->c = c;
	s->best = q->opt.max_clearance;
	s->bound = INFINITY;
	s->out = out;
	s->j = 0;
	s->step = MK_SQ_NEXT_PART;
	s->prep = NULL;
	s->lane = s->prepared = 0;
	return 1;
}

/* A scene of few obstacles: those near part j (centre c) for the bound b by
 * their spheres, into near (mkSqPrep_Near); returns whether there is any. */
static uint32_t mkSq_NearMasks(const mkSceneQuery *q, int j, const double c[3], double b, uint32_t *near)
{
	uint32_t any = 0;
	const double *rr = q->srr + (size_t)j * (size_t)(q->nob + 1);   /* (formed once for max_clearance) */
	double own[MK_SQ_FLAT];
	if (b != q->opt.max_clearance) {
		for (int i = 0; i < q->nob; ++i) own[i] = mkSqPrep_Radius2(q->prad[j], q->sr[i], b);
		rr = own;
	}
	for (int w = 0, at = 0; at < q->nob; ++w, at += 32)
		any |= near[w] = q->near(q->sx + at, q->sy + at, q->sz + at, rr + at, q->nob - at < 32 ? q->nob - at : 32, c);
	return any;
}

/* The data the tests below and the certificates read of the obstacle at
 * the hierarchy's position `at`, fetched at once (the obstacles of a large
 * scene are rarely in the cache). */
static inline void mkSq_Fetch(const mkSceneQuery *q, int at)
{
#if defined(__GNUC__)
	int i = q->wide.order[at];
	__builtin_prefetch(&q->wide.box[at]);
	__builtin_prefetch(&q->osphere[i]);
	__builtin_prefetch(&q->obs[2 * i]);
	__builtin_prefetch((const char *)&q->obs[2 * i] + 64);
	__builtin_prefetch((const char *)&q->obs[2 * i] + 128);
	__builtin_prefetch((const char *)&q->obs[2 * i] + 192);
	__builtin_prefetch(&q->oquick[i]);
	__builtin_prefetch((const char *)&q->oquick[i] + 64);
	__builtin_prefetch(&q->oquick_in[i]);
	__builtin_prefetch((const char *)&q->oquick_in[i] + 64);
#else
	(void)q;
	(void)at;
#endif
}

/* The places of cell block b near a part's sphere about cf (mkSwCells_Near),
 * the obstacles' data the tests and the certificates read fetched at once. */
static unsigned mkSq_CellNear(const mkSceneQuery *q, const mkSwCellBlock *b, const float cf[3])
{
	unsigned m = mkSwCells_Near(b, cf);
	for (unsigned k = m; k; k &= k - 1) mkSq_Fetch(q, b->pos[mkSw_Low(k)]);
	return m;
}

/* Run the pose on (after the awaited batch, in MK_SQ_WAIT) until it is
 * answered (returns 1; *s->out is the answer) or a group of candidates
 * waits for the batch (returns 0, step MK_SQ_WAIT). */
static int mkSq_Advance(const mkSceneQuery *q, mkSqPose *s)
{
	mkSqPart *p = &s->p;
	int pos[MK_SQ_BATCH], cand[MK_SQ_BATCH];
	for (;;) {
		if (s->step == MK_SQ_WAIT) {
			s->step = MK_SQ_WALK;
			if (mkSq_NarrowFinish(q, p, &s->g, &s->best, &s->bound, &s->left, s->out)) return 1;
		}
		if (s->step == MK_SQ_NEXT_PART) {
			if (s->j == q->parts) {
				s->out->clearance = s->best;
				return 1;
			}
			int j = s->j, l = s->lane;
			const mkSqPrep *x = j < s->prepared ? s->prep : NULL;
			s->bq = fmin(s->best, s->bound);
			if (x) mkSq_PartAt(q, j, &s->R, s->c, mkVec3_Make(x->pc[3 * j][l], x->pc[3 * j + 1][l], x->pc[3 * j + 2][l]), p);
			else mkSq_PartInit(q, j, &s->R, s->c, p);
			if (q->flat) { /* few obstacles: their spheres side by side, no query box */
				uint32_t any = 0;
				if (x && s->bq == q->opt.max_clearance) { /* (prepared) */
					for (int w = 0; w < (q->nob + 31) / 32; ++w) any |= s->near[w] = x->near[j][w][l];
				} else {
					any = mkSq_NearMasks(q, j, p->c, s->bq, s->near);
				}
				s->word = 0;
				if (mkSq_EllipsoidPart(p)) { /* (an ellipsoid part's exact box is cheap: prepared, read at once) */
					if (x) mkSq_EllipsoidBoxAt(p, x, l);
					else if (any) mkSq_EllipsoidBox(p);
				}
			} else {
				int ell = mkSq_EllipsoidPart(p);
				if (ell) { /* an ellipsoid part's exact box is cheap: the walk by it from the root */
					if (x) mkSq_EllipsoidBoxAt(p, x, l);
					else mkSq_EllipsoidBox(p);
				}
				s->ck = 0;
				s->cn = mkSwCells_Find(&q->cells, p->c, &s->cb, s->cf);
				s->cm = s->cn > 0 ? mkSq_CellNear(q, s->cb, s->cf) : 0u;
				if (s->cn < 0) { /* no cells: the walk, by the part's query box */
					if (!ell && x && s->bq == q->opt.max_clearance) {
						for (int i = 0; i < 3; ++i) {
							s->lo[i] = x->lo[3 * j + i][l];
							s->hi[i] = x->hi[3 * j + i][l];
						}
					} else {
						mkSq_QueryBox(p, s->bq, s->lo, s->hi);
					}
					mkSwWalk_Begin(&q->wide, &s->w, s->lo, s->hi);
				}
			}
			s->left.n = 0;
			s->step = MK_SQ_WALK;
		}
		double b = s->best < s->bound ? s->best : s->bound;
		int got = 0, n = 0;
		if (q->flat) { /* the near obstacles in index order (their boxes obox[i]) */
			for (int words = (q->nob + 31) / 32; got < MK_SQ_BATCH && s->word < words;) {
				uint32_t m = s->near[s->word];
				if (m == 0) {
					++s->word;
					continue;
				}
				pos[got++] = 32 * s->word + mkSw_Low(m);
				s->near[s->word] = m & (m - 1);
			}
		} else if (s->cn >= 0) { /* the positions of the part's cell near it */
			while (got < MK_SQ_BATCH && s->ck < s->cn) {
				if (s->cm == 0) {
					if (++s->ck < s->cn) s->cm = mkSq_CellNear(q, s->cb + s->ck, s->cf);
					continue;
				}
				pos[got++] = s->cb[s->ck].pos[mkSw_Low(s->cm)];
				s->cm &= s->cm - 1;
			}
		} else {
			if (b != s->bq) {
				s->bq = b;
				mkSq_QueryBox(p, b, s->lo, s->hi);
			}
			got = mkSwWalk_Next(&q->wide, &s->w, s->lo, s->hi, pos, MK_SQ_BATCH);
			for (int m = 0; m < got; ++m) mkSq_Fetch(q, pos[m]);
		}
		if (got == 0) {
			if (mkSq_Resolve(q, p, &s->left, &s->best, s->out)) return 1;
			++s->j;
			s->step = MK_SQ_NEXT_PART;
			continue;
		}
		for (int m = 0; m < got; ++m) {
			const mkSqBox *x = q->flat ? &q->obox[pos[m]] : &q->wide.box[pos[m]];
			int i = q->flat ? pos[m] : q->wide.order[pos[m]];
			/* (a few obstacles' spheres were tested at bq already) */
			if (mkSq_Far(p, x, b) || ((!q->flat || b != s->bq) && mkSq_SpheresApart(q, p, i, b))) continue;
			if (!p->has_box) {
				mkSq_ExactBox(p);
				if (mkSq_Far(p, x, b)) continue;
			}
			cand[n++] = i;
		}
		if (n == 0) continue;
		mkSq_NarrowPrep(q, p, cand, n, s->best, s->bound, &s->g);
		if (s->g.nb > 0) {
			s->step = MK_SQ_WAIT;
			return 0;
		}
		s->g.ok = 1;
		if (mkSq_NarrowFinish(q, p, &s->g, &s->best, &s->bound, &s->left, s->out)) return 1;
	}
}

/* The pose's answer from its rotation and position. */
static void mkSq_Answer(const mkSceneQuery *q, const mkMat3 *R, mkVec3 c, mkPoseAnswer *out)
{
	if (isfinite(q->opt.max_clearance)) {
		mkSqPose s;
		if (!mkSq_PoseBegin(q, R, c, out, &s)) return;
		while (!mkSq_Advance(q, &s)) mkSq_NarrowBatch(q, &s.p, &s.g);
		return;
	}
	mkSq_AnswerInit(q, out);
	if (q->nob == 0) return;
	double best = q->opt.max_clearance, bound = INFINITY;
	for (int j = 0; j < q->parts; ++j)
		if (mkSq_PartPose(q, j, R, c, &best, &bound, out)) return;
	out->clearance = best;
}

mkResult mkSceneQuery_Pose(const mkSceneQuery *q, const double *pose, mkPoseAnswer *out)
{
	mkMat3 R;
	mkVec3 c;
	if (!mkSq_Pose(q, pose, &R, &c)) {
		mkSq_AnswerInit(q, out);
		out->status = MK_POSE_UNCERTAIN;
		out->clearance = NAN;
		return MK_ERR_ARGUMENT;
	}
	mkSq_Answer(q, &R, c, out);
	return MK_OK;
}

/* ---- many poses ---- */

typedef struct mkSqJob {
	const mkSceneQuery *q;
	const double *poses;
	long n;
	mkPoseAnswer *out;
} mkSqJob;

/* The batch of the waiting poses pend[0 .. n): one call per mode and
 * delta over all their groups (the pairs are independent: each pair's
 * answer is the one it gets alone), the answers back into each group,
 * each pose advanced again. Returns how many still wait (moved to the
 * front). */
static int mkSq_Flush(const mkSceneQuery *q, mkSqPose *pend, int n)
{
	mkBody3 parts[MK_SQ_WAITING];
	int i1[MK_SQ_WAITING * MK_SQ_BATCH], i2[MK_SQ_WAITING * MK_SQ_BATCH], done[MK_SQ_WAITING] = {0};
	mkContact status[MK_SQ_WAITING * MK_SQ_BATCH];
	double lower[MK_SQ_WAITING * MK_SQ_BATCH], upper[MK_SQ_WAITING * MK_SQ_BATCH];
	mkVec3 point[MK_SQ_WAITING * MK_SQ_BATCH];
	unsigned char clear[MK_SQ_WAITING * MK_SQ_BATCH], path[MK_SQ_WAITING * MK_SQ_BATCH];
	for (int first = 0; first < n; ++first) {
		if (done[first]) continue;
		/* the waiting groups of first's mode and delta */
		const mkSqGroup *f = &pend[first].g;
		int np = 0, members[MK_SQ_WAITING], m = 0;
		for (int k = first; k < n; ++k) {
			const mkSqGroup *g = &pend[k].g;
			if (done[k] || g->known != f->known || g->delta != f->delta) continue;
			done[k] = 1;
			members[m] = k;
			parts[m] = pend[k].p.outer;
			for (int e = 0; e < g->nb; ++e) { i1[np] = g->i1[e]; i2[np++] = m; }
			++m;
		}
		mkBatchPairs3 pairs = {np, q->obs, parts, i1, i2};
		mkBatchOut3 bo = {.status = status, .lower = lower, .upper = upper, .p1 = point, .clear = clear, .path = path};
		int ok = mkSq_BatchCall(q, &pairs, f->known, f->delta, &bo);
		for (int e = 0, at = 0; e < m; ++e) {
			mkSqGroup *g = &pend[members[e]].g;
			g->ok = ok;
			size_t nb = (size_t)g->nb;
			memcpy(g->status, status + at, nb * sizeof *status);
			memcpy(g->lower, lower + at, nb * sizeof *lower);
			memcpy(g->upper, upper + at, nb * sizeof *upper);
			memcpy(g->point, point + at, nb * sizeof *point);
			memcpy(g->clear, clear + at, nb * sizeof *clear);
			memcpy(g->path, path + at, nb * sizeof *path);
			at += g->nb;
		}
	}
	int left = 0;
	for (int k = 0; k < n; ++k) {
		if (mkSq_Advance(q, &pend[k])) continue;
		if (left != k) {
			pend[left] = pend[k];
			pend[left].p.R = &pend[left].R;
		}
		++left;
	}
	return left;
}

/* A scene of few obstacles, all the parts prepared: whether any part of
 * prepared pose `lane` is near any obstacle at max_clearance (the
 * preparation's masks). */
static uint32_t mkSq_NearAny(const mkSceneQuery *q, const mkSqPrep *x, int lane)
{
	uint32_t any = 0;
	for (int j = 0; j < q->parts; ++j)
		for (int w = 0; w < (q->nob + 31) / 32; ++w) any |= x->near[j][w][lane];
	return any;
}

/* Pose `lane` of the prepared ones: its rotation and position. */
static void mkSq_PreparedPose(const mkSqPrep *x, int lane, const double *p, mkMat3 *R, mkVec3 *c)
{
	for (int i = 0; i < 9; ++i) R->m[i / 3][i % 3] = x->R[i][lane];
	*c = mkVec3_Make(p[0], p[1], p[2]);
}

static mkResult mkSqJob_Task(void *ctx, mkCSpaceWork *w, long task)
{
	const mkSqJob *J = ctx;
	const mkSceneQuery *q = J->q;
	int ps = mkSceneQuery_PoseSize(q), box = isfinite(q->opt.max_clearance), waiting = 0;
	/* the waiting poses and the prepared ones in the thread's block (64-byte aligned offsets) */
	size_t at_prep = (MK_SQ_WAITING * sizeof(mkSqPose) + 63) / 64 * 64;
	char *block = box ? mkCSpaceWork_Scratch(w, at_prep + sizeof(mkSqPrep)) : NULL;
	mkSqPose *pend = block ? (mkSqPose *)block : NULL;
	long first = task * MK_SQ_CHUNK, e = (task + 1) * MK_SQ_CHUNK < J->n ? (task + 1) * MK_SQ_CHUNK : J->n;
	/* 3D poses with a finite max_clearance prepared side by side: their rotations, the first parts' centres
	 * and query boxes for the bound max_clearance, as mkSq_Rotation, mkSq_PartInit and mkSq_QueryBox give
	 * them (without memory for it: one pose at a time) */
	mkSqPrep *x = pend && q->dim == 3 && q->nob > 0 ? (mkSqPrep *)(block + at_prep) : NULL;
	int prepared = q->parts < MK_SQ_PREP_PARTS ? q->parts : MK_SQ_PREP_PARTS;
	if (x) {
		mkVec3 t[MK_SQ_PREP_PARTS];
		mkMat3 M[MK_SQ_PREP_PARTS];
		double half[MK_SQ_PREP_PARTS], abc[MK_SQ_PREP_PARTS][3];
		unsigned ell = 0;
		for (int j = 0; j < prepared; ++j) {
			const mkBody3 *b = &q->part[2 * j + 1];
			t[j] = b->t;
			M[j] = b->M;
			abc[j][0] = b->shape.a;
			abc[j][1] = b->shape.b;
			abc[j][2] = b->shape.c;
			half[j] = mkSqPrep_Half(0.0, q->reach[j], q->opt.max_clearance);
			ell |= (unsigned)mkSq_EllipsoidBody(q, j) << j;
		}
		q->prep(J->poses + first * 7, (int)(e - first), q->parts, t, q->flat ? NULL : half, M, (const double (*)[3])abc, ell,
			q->flat ? &q->spheres : NULL, x);
	}
	for (long k = first; k < e; ++k) {
		if (x && q->flat && prepared == q->parts && !mkSq_NearAny(q, x, (int)(k - first))) {
			mkSq_AnswerInit(q, &J->out[k]);   /* (near no obstacle by the spheres: free) */
			continue;
		}
		mkMat3 R;
		mkVec3 c;
		if (x) mkSq_PreparedPose(x, (int)(k - first), J->poses + k * 7, &R, &c);
		else mkSq_Rotation(q, J->poses + k * ps, &R, &c);   /* (mkSceneQuery_Run checked every pose with mkSq_PoseOk) */
		if (!pend) { /* the walk nearest first, or no memory for waiting poses: one pose at a time */
			mkSq_Answer(q, &R, c, &J->out[k]);
			continue;
		}
		mkSqPose *s = &pend[waiting];
		if (!mkSq_PoseBegin(q, &R, c, &J->out[k], s)) continue;
		if (x) {
			s->prep = x;
			s->lane = (int)(k - first);
			s->prepared = prepared;
		}
		if (mkSq_Advance(q, s)) continue;
		for (++waiting; waiting == MK_SQ_WAITING;) waiting = mkSq_Flush(q, pend, waiting);
	}
	while (waiting > 0) waiting = mkSq_Flush(q, pend, waiting);
	return MK_OK;
}

mkResult mkSceneQuery_Run(const mkSceneQuery *q, const double *poses, long n, mkPoseAnswer *out, char *msg, size_t msglen)
{
	if (!q || (n > 0 && (!poses || !out)) || n < 0) return mkFail(MK_ERR_ARGUMENT, msg, msglen, "no query, poses or answers");
	int ps = mkSceneQuery_PoseSize(q);
	long bad = 0;   /* the first pose mkSq_PoseOk refuses (3D: its test side by side) */
	if (q->dim == 3) bad = q->firstbad(poses, n);
	else while (bad < n && mkSq_PoseOk(q, poses + bad * ps)) ++bad;
	if (bad < n)
		return mkFail(MK_ERR_ARGUMENT, msg, msglen, "pose %ld is out of range: its %d values must be finite numbers of "
			"magnitude at most 1e150%s", bad, ps, q->dim == 3 ? " and its quaternion nonzero" : "");
	mkSqJob J = {q, poses, n, out};
	mkResult r = mkCSpacePool_Run(mkSqJob_Task, &J, (n + MK_SQ_CHUNK - 1) / MK_SQ_CHUNK, q->opt.threads);
	if (r != MK_OK) mkFail(r, msg, msglen, "%s while checking poses", mkResult_Name(r));
	return r;
}
