/* geometric.c - the closed-form geometric method (Yan & Chirikjian 2015;
 * Ruan et al. 2018): when body 2 is an ellipse / ellipsoid
 * B2 = t2 + E S^(d-1) with E = M2 diag(r), the map E^-1 turns it into the
 * unit sphere, so the sum becomes body 1's image offset by 1 along its
 * normals; mapping back gives, for body 1's point x1 with world normal n,
 *     x = x1 + E E^T n / |E^T n|          (+ t2 for B1 (+) B2).
 * The contact set uses -B2, which is the same ellipse: an ellipse is
 * centrally symmetric. Body 1 may be any smooth body; it is sampled at its
 * surface parameters, as the closed forms are. Its registry entry is in
 * registry.c. */
#include <math.h>
#include <stdlib.h>

#include <mink/registry.h>

#include "registry_internal.h"

/* A vector parallel to M^-T g with the same sense: the cofactor matrix of M
 * times g, times the sign of det M (no division, no inverse). */
static mkVec2 cof2(mkMat2 M, mkVec2 g)
{
	double(*m)[2] = M.m;
	double s = mkMat2_Det(M) < 0 ? -1.0 : 1.0;
	mkVec2 n = {s * (m[1][1] * g.x - m[1][0] * g.y), s * (-m[0][1] * g.x + m[0][0] * g.y)};
	return n;
}

static mkVec3 cof3(mkMat3 M, mkVec3 g)
{
	double(*m)[3] = M.m;
	double c[3][3] = {
		{m[1][1] * m[2][2] - m[1][2] * m[2][1], m[1][2] * m[2][0] - m[1][0] * m[2][2],
			m[1][0] * m[2][1] - m[1][1] * m[2][0]},
		{m[0][2] * m[2][1] - m[0][1] * m[2][2], m[0][0] * m[2][2] - m[0][2] * m[2][0],
			m[0][1] * m[2][0] - m[0][0] * m[2][1]},
		{m[0][1] * m[1][2] - m[0][2] * m[1][1], m[0][2] * m[1][0] - m[0][0] * m[1][2],
			m[0][0] * m[1][1] - m[0][1] * m[1][0]},
	};
	double det = m[0][0] * c[0][0] + m[0][1] * c[0][1] + m[0][2] * c[0][2];
	double s = det < 0 ? -1.0 : 1.0;
	mkVec3 n = {s * (c[0][0] * g.x + c[0][1] * g.y + c[0][2] * g.z),
		s * (c[1][0] * g.x + c[1][1] * g.y + c[1][2] * g.z),
		s * (c[2][0] * g.x + c[2][1] * g.y + c[2][2] * g.z)};
	return n;
}

/* E E^T n / |E^T n| with E = M diag(r), n any nonzero vector. */
static mkVec2 offset2(mkMat2 M, double r0, double r1, mkVec2 n)
{
	double big = fmax(fabs(n.x), fabs(n.y));
	n.x /= big;
	n.y /= big;
	mkVec2 w = mkMat2_MulTVec(M, n);
	w.x *= r0;
	w.y *= r1;
	double len = hypot(w.x, w.y);
	mkVec2 v = {r0 * w.x / len, r1 * w.y / len};
	return mkMat2_MulVec(M, v);
}

static mkVec3 offset3(mkMat3 M, double r0, double r1, double r2, mkVec3 n)
{
	double big = fmax(fabs(n.x), fmax(fabs(n.y), fabs(n.z)));
	n.x /= big;
	n.y /= big;
	n.z /= big;
	mkVec3 w = mkMat3_MulTVec(M, n);
	w.x *= r0;
	w.y *= r1;
	w.z *= r2;
	double wb = fmax(fabs(w.x), fmax(fabs(w.y), fabs(w.z)));
	double len = wb * sqrt((w.x / wb) * (w.x / wb) + (w.y / wb) * (w.y / wb) + (w.z / wb) * (w.z / wb));
	mkVec3 v = {r0 * w.x / len, r1 * w.y / len, r2 * w.z / len};
	return mkMat3_MulVec(M, v);
}

int mkGeometric2_Accepts(mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen)
{
	(void)b1;
	(void)set;
	return mkShape2_IsEllipse(b2.shape) || mkRefuse(msg, msglen, "body2.eps = %g: the geometric formula needs body2 "
		"to be an ellipse or circle (eps = 1); body1 may be any superellipse", b2.shape.eps);
}

int mkGeometric3_Accepts(mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen)
{
	(void)b1;
	(void)set;
	return mkShape3_IsEllipsoid(b2.shape) || mkRefuse(msg, msglen, "body2.eps1 = %g, body2.eps2 = %g: the geometric "
		"formula needs body2 to be an ellipsoid or sphere (eps1 = eps2 = 1); body1 may be any superquadric",
		b2.shape.eps1, b2.shape.eps2);
}

mkResult mkGeometric2_Run(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out)
{
	if (!out || (set != MK_SET_CONTACT && set != MK_SET_PLUS)) return MK_ERR_ARGUMENT;
	if (n < 1) return MK_ERR_RANGE;
	if (!mkShape2_IsEllipse(b2.shape)) return MK_ERR_UNSUPPORTED;
	double *u;
	mkResult r = mkSurface2_Params(n, out, &u);
	if (r == MK_OK) {
		mkVec2 shift = set == MK_SET_PLUS ? b2.t : (mkVec2){0, 0};
		for (int k = 0; k < n; ++k) {
			mkVec2 uk = {u[k], u[n + k]};
			mkVec2 x1 = mkBody2_Point(b1, uk);
			mkVec2 nrm = cof2(b1.M, mkShape2_PointGradient(b1.shape, uk));
			mkVec2 d = offset2(b2.M, b2.shape.a, b2.shape.b, nrm);
			out->x[k] = x1.x + shift.x + d.x;
			out->y[k] = x1.y + shift.y + d.y;
		}
	}
	free(u);
	return r;
}

mkResult mkGeometric3_Run(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out)
{
	if (!out || (set != MK_SET_CONTACT && set != MK_SET_PLUS)) return MK_ERR_ARGUMENT;
	if (n < 2 || n > MK_CLOSED3_N_MAX) return MK_ERR_RANGE;
	if (!mkShape3_IsEllipsoid(b2.shape)) return MK_ERR_UNSUPPORTED;
	double *u;
	mkResult r = mkSurface3_Params(n, out, &u);
	if (r == MK_OK) {
		int count = n * n;
		mkVec3 shift = set == MK_SET_PLUS ? b2.t : (mkVec3){0, 0, 0};
		for (int k = 0; k < count; ++k) {
			mkVec3 uk = {u[k], u[count + k], u[2 * count + k]};
			mkVec3 x1 = mkBody3_Point(b1, uk);
			mkVec3 nrm = cof3(b1.M, mkShape3_PointGradient(b1.shape, uk));
			mkVec3 d = offset3(b2.M, b2.shape.a, b2.shape.b, b2.shape.c, nrm);
			out->x[k] = x1.x + shift.x + d.x;
			out->y[k] = x1.y + shift.y + d.y;
			out->z[k] = x1.z + shift.z + d.z;
		}
	}
	free(u);
	return r;
}
