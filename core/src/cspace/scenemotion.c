/* scenemotion.c - motions of the robot against a scene (mink/scenequery.h):
 * interpolation between poses and the certified motion checks, on top of
 * the pose query.
 *
 * A motion check first probes the motion for contact with cheap witnesses
 * (points inside a part and an obstacle at once, at up to MK_SM_PROBES
 * evenly spaced poses in coarse to fine order), then covers [0, 1] by bisection: the
 * pose at an interval's midpoint, its certified clearance c and the bound L
 * on how far any robot point moves per unit of t cover an interval around
 * it on both sides; what is left is split again. A cheap lower bound of
 * the clearance (each part's bounding sphere and exact box at the pose
 * against the obstacles' exact boxes) covers an interval without the pose
 * query when it is large enough. */
#include "mink/scenequery.h"

#include <math.h>
#include <string.h>

#include "cspace/scenecache.h"

#define MK_SM_PARTS 16      /* parts handled by the cheap layer at most */
#define MK_SM_NEAR 32       /* obstacles near the motion handled by the cheap layer at most */
#define MK_SM_PROBES 8      /* witness probes per motion at most */
#define MK_SM_STACK 256     /* bisection intervals pending at most */
#define MK_SM_INSIDE 1e-9   /* a witness point's margin inside both bodies (implicit < 1 - this), as the pose query's */
#define MK_SM_ROUND 1e-12   /* relative rounding allowance of the cheap bounds */

/* The pose is valid (finite, nonzero quaternion): the pose query's own test. */
static int mkSq_PoseOk(const mkSceneQuery *q, const double *p)
{
	mkBody3 b;
	return mkSceneQuery_PartBody(q, p, 0, 1, &b);
}

static int mkSq_Dim(const mkSceneQuery *q) { return mkSceneQuery_PoseSize(q) == 3 ? 2 : 3; }

double mkSceneQuery_RobotRadius(const mkSceneQuery *q)
{
	static const double origin[7] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0};   /* 2D: x, y, theta = 0 */
	int dim = mkSq_Dim(q);
	double r = 0.0;
	mkBody3 b;
	for (int j = 0; mkSceneQuery_PartBody(q, origin, j, 1, &b); ++j) {   /* the part's outer model in the robot's frame */
		double c = dim == 2 ? hypot(b.t.x, b.t.y) : mkVec3_Length(b.t);
		r = fmax(r, (c + mkSq_PartRadius(q, j)) * (1.0 + MK_SM_ROUND));
	}
	return r;
}

/* The heading difference b - a wrapped into [-pi, pi]. */
static double mkSq_AngleStep(double a, double b)
{
	double d = remainder(b - a, 2.0 * MK_PI);
	return d;
}

/* The unit quaternions of a and b, b negated when nearer, and their angle. */
static double mkSq_QuatPair(const double *a, const double *b, double qa[4], double qb[4])
{
	double na = 0.0, nb = 0.0, dot = 0.0;
	for (int k = 0; k < 4; ++k) { na += a[3 + k] * a[3 + k]; nb += b[3 + k] * b[3 + k]; }
	na = sqrt(na); nb = sqrt(nb);
	for (int k = 0; k < 4; ++k) { qa[k] = a[3 + k] / na; qb[k] = b[3 + k] / nb; dot += qa[k] * qb[k]; }
	if (dot < 0.0) { for (int k = 0; k < 4; ++k) qb[k] = -qb[k]; dot = -dot; }
	return 2.0 * acos(fmin(dot, 1.0));
}

void mkSceneQuery_Interpolate(const mkSceneQuery *q, const double *a, const double *b, double t, double *out)
{
	for (int d = 0; d < mkSq_Dim(q); ++d) out[d] = a[d] + t * (b[d] - a[d]);
	if (mkSq_Dim(q) == 2) {
		out[2] = remainder(a[2] + t * mkSq_AngleStep(a[2], b[2]), 2.0 * MK_PI);
		return;
	}
	double qa[4], qb[4];
	double th = 0.5 * mkSq_QuatPair(a, b, qa, qb), wa = 1.0 - t, wb = t;
	if (th > 1e-9) { wa = sin((1.0 - t) * th) / sin(th); wb = sin(t * th) / sin(th); }
	for (int k = 0; k < 4; ++k) out[3 + k] = wa * qa[k] + wb * qb[k];
}


/* ---- one motion's context ---- */

typedef struct mkSmObstacle {
	int index;
	mkBody3 inner;   /* the inner model (witnesses) and its map's inverse */
	mkMat3 inv;
	double lo[3], hi[3];   /* the outer model's exact box */
} mkSmObstacle;

typedef struct mkSmMotion {
	const mkSceneQuery *q;
	const double *a, *b;
	double margin, L, stall, rad_min, far;
	long max_poses;
	int dim, parts, near;         /* parts 0: the cheap layer is off */
	double rad[MK_SM_PARTS];      /* each part's outer model's radius about its centre */
	mkSmObstacle ob[MK_SM_NEAR];  /* the obstacles nearest the motion's swept box */
	double far_dist[MK_SM_NEAR];
	mkMotionAnswer *out;
} mkSmMotion;

/* The distance from the point x to the box [lo, hi] in the first dim axes. */
static double mkSm_PointBox(const double *x, const double *lo, const double *hi, int dim)
{
	double d2 = 0.0;
	for (int i = 0; i < dim; ++i) {
		double g = fmax(lo[i] - x[i], x[i] - hi[i]);
		if (g > 0.0) d2 += g * g;
	}
	return sqrt(d2);
}

/* The distance between the boxes [alo, ahi] and [blo, bhi] in the first dim axes. */
static double mkSm_BoxBox(const double *alo, const double *ahi, const double *blo, const double *bhi, int dim)
{
	double d2 = 0.0;
	for (int i = 0; i < dim; ++i) {
		double g = fmax(blo[i] - ahi[i], alo[i] - bhi[i]);
		if (g > 0.0) d2 += g * g;
	}
	return sqrt(d2);
}

/* The exact box of body b in its first dim axes (grown by the rounding allowance). */
static void mkSm_Box(const mkBody3 *b, int dim, double *lo, double *hi)
{
	for (int c = 0; c < dim; ++c) {
		mkVec3 e = {c == 0, c == 1, c == 2};
		double h = mkShape3_SupportValue(b->shape, mkMat3_MulTVec(b->M, e)) * (1.0 + MK_SM_ROUND);
		double t = c == 0 ? b->t.x : c == 1 ? b->t.y : b->t.z;
		lo[c] = t - h;
		hi[c] = t + h;
	}
}

/* Keep obstacle i (its outer box at distance d from the swept box) among
 * the MK_SM_NEAR nearest; the one it displaces, or i itself, lowers far. */
static void mkSm_AddObstacle(mkSmMotion *m, int i, const double *lo, const double *hi, double d)
{
	int k = m->near;
	if (k == MK_SM_NEAR) {
		k = 0;
		for (int j = 1; j < MK_SM_NEAR; ++j)
			if (m->far_dist[j] > m->far_dist[k]) k = j;
		if (d >= m->far_dist[k]) { m->far = fmin(m->far, d); return; }
		m->far = fmin(m->far, m->far_dist[k]);
	} else ++m->near;
	mkSmObstacle *o = &m->ob[k];
	o->index = i;
	memcpy(o->lo, lo, sizeof o->lo);
	memcpy(o->hi, hi, sizeof o->hi);
	m->far_dist[k] = d;
}

/* The cheap layer: each part's radius, the obstacles nearest the box that
 * holds every robot point along the motion (positions' box grown by the
 * robot's radius), and far, a lower bound of the distance to the others. */
static void mkSm_SetupCheap(mkSmMotion *m, double r)
{
	static const double origin[7] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0};
	mkBody3 b;
	m->parts = m->near = 0;
	m->far = INFINITY;
	m->rad_min = INFINITY;
	for (int j = 0; mkSceneQuery_PartBody(m->q, origin, j, 1, &b); ++j) {
		if (j == MK_SM_PARTS) { m->parts = 0; return; }
		m->rad[j] = mkSq_PartRadius(m->q, j);
		m->rad_min = fmin(m->rad_min, m->rad[j]);
		m->parts = j + 1;
	}
	double slo[3], shi[3];
	for (int c = 0; c < m->dim; ++c) {
		slo[c] = fmin(m->a[c], m->b[c]) - r;
		shi[c] = fmax(m->a[c], m->b[c]) + r;
	}
	double lo[3], hi[3];
	for (int i = 0; mkSq_ObstacleBox(m->q, i, lo, hi); ++i) {
		double s = 0.0;
		for (int c = 0; c < 3; ++c) {   /* grown by the rounding allowance, as mkSm_Box */
			double g = 0.5 * (hi[c] - lo[c]) * MK_SM_ROUND;
			lo[c] -= g;
			hi[c] += g;
		}
		for (int c = 0; c < m->dim; ++c) s += fabs(lo[c]) + fabs(hi[c]) + fabs(slo[c]) + fabs(shi[c]);
		mkSm_AddObstacle(m, i, lo, hi, mkSm_BoxBox(slo, shi, lo, hi, m->dim) - MK_SM_ROUND * s);
	}
	for (int k = 0; k < m->near; ++k) {
		mkSceneQuery_ObstacleBody(m->q, m->ob[k].index, 0, &m->ob[k].inner);
		m->ob[k].inv = mkMat3_Inverse(m->ob[k].inner.M);
	}
}

/* A certified lower bound of the clearance at pose p: per pair of a part
 * and a near obstacle, the larger of the distances from the part's bounding
 * sphere and from its exact box at the pose to the obstacle's box; far for
 * the others (-inf when the cheap layer is off). */
static double mkSm_Cheap(const mkSmMotion *m, const double *p)
{
	if (m->parts == 0) return -INFINITY;
	double lo = m->far;
	mkBody3 b;
	for (int j = 0; j < m->parts; ++j) {
		mkSceneQuery_PartBody(m->q, p, j, 1, &b);
		double x[3] = {b.t.x, b.t.y, b.t.z}, plo[3] = {0.0, 0.0, 0.0}, phi[3] = {0.0, 0.0, 0.0};
		mkSm_Box(&b, m->dim, plo, phi);
		for (int k = 0; k < m->near; ++k) {
			const mkSmObstacle *o = &m->ob[k];
			double s = m->rad[j];
			for (int c = 0; c < m->dim; ++c) s += fabs(plo[c]) + fabs(phi[c]) + fabs(o->lo[c]) + fabs(o->hi[c]);
			double d = fmax(mkSm_PointBox(x, o->lo, o->hi, m->dim) - m->rad[j], mkSm_BoxBox(plo, phi, o->lo, o->hi, m->dim));
			lo = fmin(lo, d - MK_SM_ROUND * s);
		}
	}
	return lo;
}

/* ---- witnesses of contact ---- */

/* x lies inside the body (map inverse inv) by the pose query's margin:
 * the implicit function F = g^(2 / eps1) below 1 - MK_SM_INSIDE, g the
 * gauge, the nested norm |(|(y1/a, y2/b)|_p2, y3/c)|_p1 with p = 2 / eps >=
 * 1. Decided first without pow where it can be: g >= 1 when a coordinate
 * over its semi-axis is >= 1 (outside); g is at most the nested l2 / l1
 * norm (l2 where p >= 2), and F <= g when g < 1, so such a bound below
 * 1 - MK_SM_INSIDE (less a rounding allowance) is inside. */
static int mkSm_Inside(const mkBody3 *b, mkMat3 inv, mkVec3 x)
{
	mkVec3 y = mkMat3_MulVec(inv, mkVec3_Sub(x, b->t));
	const mkShape3 *s = &b->shape;
	double u = fabs(y.x / s->a), v = fabs(y.y / s->b), w = fabs(y.z / s->c);
	if (u >= 1.0 || v >= 1.0 || w >= 1.0) return 0;
	double in = s->eps2 <= 1.0 ? sqrt(u * u + v * v) : u + v;
	double g = s->eps1 <= 1.0 ? sqrt(in * in + w * w) : in + w;
	if (g * (1.0 + 1e-14) < 1.0 - MK_SM_INSIDE) return 1;
	return mkShape3_Implicit(b->shape, y) < 1.0 - MK_SM_INSIDE;
}

/* The witness points of body b: its centre and the points at 0.5 and 0.9
 * of each semi-axis (both signs), in its first dim axes: all inside it. */
static int mkSm_Points(const mkBody3 *b, int dim, mkVec3 *x)
{
	int n = 0;
	x[n++] = b->t;
	double axis[3] = {b->shape.a, b->shape.b, b->shape.c};
	for (int c = 0; c < dim; ++c)
		for (int k = 0; k < 4; ++k) {
			double s = (k & 1 ? -1.0 : 1.0) * (k & 2 ? 0.9 : 0.5) * axis[c];
			mkVec3 u = {c == 0 ? s : 0.0, c == 1 ? s : 0.0, c == 2 ? s : 0.0};
			x[n++] = mkVec3_Add(b->t, mkMat3_MulVec(b->M, u));
		}
	return n;
}

/* A witness of contact at pose p: a point inside the inner models of a
 * part and a near obstacle whose boxes (the part's bounding sphere) meet.
 * Returns 1 and the pair when found. */
static int mkSm_Witness(const mkSmMotion *m, const double *p, int *obstacle, int *part)
{
	mkBody3 outer, inner;
	mkVec3 x[1 + 4 * 3];
	for (int j = 0; j < m->parts; ++j) {
		mkSceneQuery_PartBody(m->q, p, j, 1, &outer);
		mkSceneQuery_PartBody(m->q, p, j, 0, &inner);
		double c[3] = {outer.t.x, outer.t.y, outer.t.z};
		mkMat3 inv = mkMat3_Inverse(inner.M);
		int nx = -1;
		for (int k = 0; k < m->near; ++k) {
			const mkSmObstacle *o = &m->ob[k];
			if (mkSm_PointBox(c, o->lo, o->hi, m->dim) > m->rad[j]) continue;
			if (nx < 0) nx = mkSm_Points(&inner, m->dim, x);
			mkVec3 y[1 + 4 * 3];
			int ny = mkSm_Points(&o->inner, m->dim, y);
			int hit = 0;
			for (int i = 0; i < nx && !hit; ++i) hit = mkSm_Inside(&o->inner, o->inv, x[i]) && mkSm_Inside(&inner, inv, x[i]);
			for (int i = 0; i < ny && !hit; ++i) hit = mkSm_Inside(&inner, inv, y[i]) && mkSm_Inside(&o->inner, o->inv, y[i]);
			if (hit) { *obstacle = o->index; *part = j; return 1; }
		}
	}
	return 0;
}

/* Reject first: witnesses at up to MK_SM_PROBES evenly spaced poses inside
 * (0, 1), coarse to fine, spaced so that no robot point moves more than
 * half the smallest part's radius between them. A witness makes the motion
 * colliding (certified) at that time. */
static int mkSm_Probe(mkSmMotion *m)
{
	if (m->parts == 0 || m->near == 0 || !(m->L > 0.0)) return 0;
	double want = 2.0 * m->L / m->rad_min;
	int n = 2;
	while (n < MK_SM_PROBES && n < want) n *= 2;
	double p[7];
	for (int step = n; step > 1; step /= 2)
		for (int k = step / 2; k < n; k += step) {
			double t = (double)k / n;
			int obstacle, part;
			mkSceneQuery_Interpolate(m->q, m->a, m->b, t, p);
			if (mkSm_Witness(m, p, &obstacle, &part)) {
				m->out->status = MK_POSE_COLLIDING;
				m->out->contact_time = t;
				m->out->obstacle = obstacle;
				m->out->part = part;
				return 1;
			}
		}
	return 0;
}

/* ---- certified cover and advancement ---- */

/* The pose query at p (counted): its room above the margin, -inf unless free. */
static double mkSm_Pose(const mkSmMotion *m, const double *p, mkPoseAnswer *pa)
{
	mkSceneQuery_Pose(m->q, p, pa);
	++m->out->poses;
	m->out->obstacle = pa->obstacle;
	m->out->part = pa->part;
	return pa->status == MK_POSE_FREE ? pa->clearance - m->margin : -INFINITY;
}

/* Cover [0, end] by bisection, leftmost interval first, so that [0, x] is
 * covered when [x, y] is taken: its midpoint t with room rho covers
 * [t - f rho / L, t + f rho / L], on which the clearance stays at least
 * margin + (1 - f) rho; the cheap bound covers the whole interval when large
 * enough, and when it reaches a quarter of that, it covers its own interval
 * around t without the pose query. A midpoint with room <= stall (touching,
 * or left uncertain by the narrow phase) splits its interval in two at t. Returns 1 when [0, end] is
 * covered (free_until = end), else 0 with free_until = x of the interval
 * where a pose was colliding (status set), an interval with room <= stall
 * at its midpoint became too short to split (L (y - x) / 2 <= stall), or
 * the poses ran out. */
static int mkSm_Cover(mkSmMotion *m, double f, double end, double *lowest)
{
	double xs[MK_SM_STACK], ys[MK_SM_STACK], p[7];
	int top = 0;
	xs[top] = 0.0; ys[top++] = end;
	mkPoseAnswer pa;
	while (top > 0) {
		double x = xs[--top], y = ys[top], t = 0.5 * (x + y), need = 0.5 * (y - x);
		m->out->free_until = x;
		mkSceneQuery_Interpolate(m->q, m->a, m->b, t, p);
		double cheap = mkSm_Cheap(m, p) - m->margin;
		if (cheap > 0.0 && m->L * need <= f * cheap) {
			*lowest = fmin(*lowest, cheap + m->margin - m->L * need);
			continue;
		}
		if (cheap > 0.0 && 4.0 * f * cheap >= m->L * need && top + 2 <= MK_SM_STACK) {
			/* the cheap bound covers a good part: its rest is split, no pose query */
			double r = f * cheap / m->L;
			*lowest = fmin(*lowest, cheap + m->margin - m->L * r);
			xs[top] = t + r; ys[top++] = y;
			xs[top] = x; ys[top++] = t - r;
			continue;
		}
		if (m->out->poses >= m->max_poses) return 0;
		double room = mkSm_Pose(m, p, &pa);
		if (pa.status == MK_POSE_COLLIDING) {
			m->out->status = MK_POSE_COLLIDING;
			m->out->contact_time = t;
			return 0;
		}
		if (top + 2 > MK_SM_STACK) return 0;
		if (!(room > m->stall)) {
			/* touching, or a pose the narrow phase left uncertain: its
			 * neighbours may still cover t, until no robot point moves
			 * more than stall within the interval */
			if (m->L * need <= m->stall) return 0;
			xs[top] = t; ys[top++] = y;
			xs[top] = x; ys[top++] = t;
			continue;
		}
		double r = m->L > 0.0 ? f * room / m->L : INFINITY;
		*lowest = fmin(*lowest, pa.clearance - m->L * fmin(r, need));
		if (t + r < y) { xs[top] = t + r; ys[top++] = y; }
		if (t - r > x) { xs[top] = x; ys[top++] = t - r; }
	}
	m->out->free_until = end;
	return 1;
}

/* Conservative advancement from free_until towards end: steps of room / (2 L)
 * (the clearance stays at least (c + margin) / 2) until end (1: returns 1)
 * or a pose with room <= stall (its time in *t; colliding sets status). */
static int mkSm_March(mkSmMotion *m, double end, double *lowest, double *t)
{
	double p[7];
	mkPoseAnswer pa;
	*t = m->out->free_until;
	for (;;) {
		mkSceneQuery_Interpolate(m->q, m->a, m->b, *t, p);
		double room = mkSm_Pose(m, p, &pa);
		if (pa.status == MK_POSE_COLLIDING) {
			m->out->status = MK_POSE_COLLIDING;
			m->out->contact_time = *t;
			return 0;
		}
		if (!(room > m->stall) || m->out->poses >= m->max_poses) return 0;
		double dt = m->L > 0.0 ? 0.5 * room / m->L : 2.0;
		*lowest = fmin(*lowest, 0.5 * (pa.clearance + m->margin));
		if (*t + dt >= end) {
			m->out->free_until = end;
			return end >= 1.0;
		}
		*t += dt;
		m->out->free_until = *t;
	}
}

/* After a stall at t: a pose in contact among 1000 evenly spaced on (t, end]. */
static int mkSm_FindContact(mkSmMotion *m, double t, double end)
{
	double p[7];
	mkPoseAnswer pa;
	for (int k = 1; k <= 1000; ++k) {
		double s = k == 1000 ? end : t + (end - t) * k / 1000.0;
		mkSceneQuery_Interpolate(m->q, m->a, m->b, s, p);
		mkSm_Pose(m, p, &pa);
		if (pa.status == MK_POSE_COLLIDING) {
			m->out->status = MK_POSE_COLLIDING;
			m->out->contact_time = s;
			return 1;
		}
	}
	return 0;
}

/* Check the arguments, clear the answer, and set up the motion's bounds. */
static mkResult mkSm_Setup(mkSmMotion *m, const mkSceneQuery *q, const double *a, const double *b, double margin,
	long max_poses, mkMotionAnswer *out)
{
	out->status = MK_POSE_UNCERTAIN;
	out->clearance = -INFINITY;
	out->free_until = 0.0;
	out->contact_time = NAN;
	out->obstacle = out->part = -1;
	out->poses = 0;
	if (!mkSq_PoseOk(q, a) || !mkSq_PoseOk(q, b) || !(margin >= 0.0) || !isfinite(margin))
		return MK_ERR_ARGUMENT;
	m->q = q;
	m->a = a;
	m->b = b;
	m->margin = margin;
	m->max_poses = max_poses;
	m->out = out;
	m->dim = mkSq_Dim(q);
	double len2 = 0.0, angle;
	for (int d = 0; d < m->dim; ++d) len2 += (b[d] - a[d]) * (b[d] - a[d]);
	if (m->dim == 2) angle = fabs(mkSq_AngleStep(a[2], b[2]));
	else { double qa[4], qb[4]; angle = mkSq_QuatPair(a, b, qa, qb); }
	double r = mkSceneQuery_RobotRadius(q);
	m->L = (sqrt(len2) + r * angle) * (1.0 + MK_SM_ROUND);
	m->stall = 1e-9 * (r + sqrt(len2));
	mkSm_SetupCheap(m, r);
	return MK_OK;
}

mkResult mkSceneQuery_MotionTest(const mkSceneQuery *q, const double *a, const double *b, double margin, long max_poses,
	mkMotionAnswer *out)
{
	mkSmMotion m;
	mkResult r = mkSm_Setup(&m, q, a, b, margin, max_poses, out);
	if (r != MK_OK || mkSm_Probe(&m)) return r;
	double lowest = INFINITY;
	if (mkSm_Cover(&m, 0.9, 1.0, &lowest)) out->status = MK_POSE_FREE;
	out->clearance = lowest;
	return MK_OK;
}

mkResult mkSceneQuery_Motion(const mkSceneQuery *q, const double *a, const double *b, double margin, long max_poses,
	mkMotionAnswer *out)
{
	mkSmMotion m;
	mkResult r = mkSm_Setup(&m, q, a, b, margin, max_poses, out);
	if (r != MK_OK) return r;
	/* a witness at s bounds the search for the first contact to [0, s] */
	double end = mkSm_Probe(&m) ? out->contact_time : 1.0, lowest = INFINITY, t;
	out->status = MK_POSE_UNCERTAIN;
	int covered = mkSm_Cover(&m, 0.5, end, &lowest);
	if (covered && end >= 1.0) out->status = MK_POSE_FREE;
	else if (out->status != MK_POSE_COLLIDING || out->contact_time > out->free_until) {
		/* locate the first contact: advance from the covered prefix to the stall */
		if (out->status == MK_POSE_COLLIDING) end = out->contact_time;
		out->status = MK_POSE_UNCERTAIN;
		if (mkSm_March(&m, end, &lowest, &t)) out->status = MK_POSE_FREE;
		else if (out->status != MK_POSE_COLLIDING && end > t) mkSm_FindContact(&m, t, end);
	}
	out->clearance = lowest;
	if (out->status == MK_POSE_UNCERTAIN) {
		/* a stall (a pose the pose query left uncertain): the test's coarser
		 * cover may pass by it, and certifies as soundly */
		mkMotionAnswer test;
		if (mkSceneQuery_MotionTest(q, a, b, margin, max_poses, &test) == MK_OK && test.status == MK_POSE_FREE) {
			test.poses += out->poses;
			*out = test;
		}
	}
	return MK_OK;
}
