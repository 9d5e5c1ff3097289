/* scenemotion.c - motions of the robot against a scene (mink/scenequery.h):
 * interpolation between poses and the certified motion check by
 * conservative advancement, on top of the pose query. */
#include "mink/scenequery.h"

#include <math.h>

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
		double h2 = 0.0;
		for (int i = 0; i < dim; ++i) {   /* the half extents of its exact box */
			mkVec3 e = {i == 0, i == 1, i == 2};
			double h = mkShape3_SupportValue(b.shape, mkMat3_MulTVec(b.M, e));
			h2 += h * h;
		}
		double c = dim == 2 ? hypot(b.t.x, b.t.y) : mkVec3_Length(b.t);
		r = fmax(r, c + sqrt(h2));
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

/* After a stall at t: a pose in contact at t or among 1000 evenly spaced on [t, 1]. */
static int mkSq_FindContact(const mkSceneQuery *q, const double *a, const double *b, double t, mkMotionAnswer *out)
{
	double p[7];
	mkPoseAnswer pa;
	for (int k = 0; k <= 1000; ++k) {
		double s = t + (1.0 - t) * k / 1000.0;
		mkSceneQuery_Interpolate(q, a, b, s, p);
		mkSceneQuery_Pose(q, p, &pa);
		++out->poses;
		if (pa.status == MK_POSE_COLLIDING) {
			out->status = MK_POSE_COLLIDING;
			out->contact_time = s;
			out->obstacle = pa.obstacle;
			out->part = pa.part;
			return 1;
		}
	}
	return 0;
}

mkResult mkSceneQuery_Motion(const mkSceneQuery *q, const double *a, const double *b, double margin, long max_poses,
	mkMotionAnswer *out)
{
	out->status = MK_POSE_UNCERTAIN;
	out->clearance = -INFINITY;
	out->free_until = 0.0;
	out->contact_time = NAN;
	out->obstacle = out->part = -1;
	out->poses = 0;
	if (!mkSq_PoseOk(q, a) || !mkSq_PoseOk(q, b) || !(margin >= 0.0) || !isfinite(margin))
		return MK_ERR_ARGUMENT;
	double len2 = 0.0, angle;
	for (int d = 0; d < mkSq_Dim(q); ++d) len2 += (b[d] - a[d]) * (b[d] - a[d]);
	if (mkSq_Dim(q) == 2) angle = fabs(mkSq_AngleStep(a[2], b[2]));
	else { double qa[4], qb[4]; angle = mkSq_QuatPair(a, b, qa, qb); }
	double r = mkSceneQuery_RobotRadius(q), L = sqrt(len2) + r * angle, stall = 1e-9 * (r + sqrt(len2));
	double t = 0.0, lowest = INFINITY, p[7];
	mkPoseAnswer pa;
	for (;;) {
		mkSceneQuery_Interpolate(q, a, b, t, p);
		mkSceneQuery_Pose(q, p, &pa);
		++out->poses;
		out->obstacle = pa.obstacle;
		out->part = pa.part;
		double room = pa.status == MK_POSE_FREE ? pa.clearance - margin : -INFINITY;
		if (!(room > stall) || out->poses >= max_poses) break;
		double dt = L > 0.0 ? 0.5 * room / L : 2.0;   /* [t, t + dt] keeps (c + margin) / 2 */
		lowest = fmin(lowest, 0.5 * (pa.clearance + margin));
		if (t + dt >= 1.0) {
			out->status = MK_POSE_FREE;
			out->free_until = 1.0;
			out->clearance = lowest;
			return MK_OK;
		}
		t += dt;
		out->free_until = t;
	}
	out->clearance = lowest;
	if (pa.status == MK_POSE_COLLIDING) {
		out->status = MK_POSE_COLLIDING;
		out->contact_time = t;
		return MK_OK;
	}
	mkSq_FindContact(q, a, b, t, out);
	return MK_OK;
}
