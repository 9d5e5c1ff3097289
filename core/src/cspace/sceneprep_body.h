/* sceneprep_body.h - the loops of mkSqPrep_Run (cspace/sceneprep.h), one
 * source compiled for each instruction set (sceneprep.c, sceneprep_avx2.c,
 * sceneprep_avx512.c), each with -fno-math-errno (sqrt then need not set
 * errno, so that the loops run in vector registers; its values are the
 * same) and without contraction. */
#ifndef MINK_CSPACE_SCENEPREP_BODY_H
#define MINK_CSPACE_SCENEPREP_BODY_H

#include <math.h>

#include "cspace/sceneprep.h"
#include "cspace/scenewide.h"

/* Part j's masks of the spheres near it, lane by lane: mkSqPrep_Near's
 * test (c - x, its squares summed in its order, compared with rr) with
 * the lanes side by side. */
static void mkSqPrep_NearBody(const mkSqPrepSpheres *sp, int j, int n, mkSqPrep *out)
{
	const double *px = out->pc[3 * j], *py = out->pc[3 * j + 1], *pz = out->pc[3 * j + 2], *rr = sp->rr + (size_t)j * (size_t)sp->stride;
	for (int w = 0, at = 0; at < sp->n; ++w, at += 32) {
		uint32_t *m = out->near[j][w];
		int e = sp->n - at < 32 ? sp->n : at + 32;
		for (int k = 0; k < n; ++k) m[k] = 0;
		for (int i = at; i < e; ++i) {
			double x = sp->x[i], y = sp->y[i], z = sp->z[i], r = rr[i];
			uint32_t bit = 1u << (i - at);
			for (int k = 0; k < n; ++k) {
				double dx = px[k] - x, dy = py[k] - y, dz = pz[k] - z;
				m[k] |= dx * dx + dy * dy + dz * dz > r ? 0u : bit;
			}
		}
	}
}

static void mkSqPrep_Body(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *spheres, mkSqPrep *out)
{
	double qw[MK_SQ_PREP], qx[MK_SQ_PREP], qy[MK_SQ_PREP], qz[MK_SQ_PREP], c[3][MK_SQ_PREP];
	for (int k = 0; k < n; ++k) {
		const double *p = poses + 7 * k;
		c[0][k] = p[0];
		c[1][k] = p[1];
		c[2][k] = p[2];
		qw[k] = p[3];
		qx[k] = p[4];
		qy[k] = p[5];
		qz[k] = p[6];
	}
	/* the operations of mkMat3_FromQuatInline */
	for (int k = 0; k < n; ++k) {
		double w = qw[k], x = qx[k], y = qy[k], z = qz[k];
		double n2 = w * w + x * x + y * y + z * z;
		double s = 1.0 / sqrt(n2);
		w *= s; x *= s; y *= s; z *= s;
		out->R[0][k] = 1 - 2 * (y * y + z * z);
		out->R[1][k] = 2 * (x * y - w * z);
		out->R[2][k] = 2 * (x * z + w * y);
		out->R[3][k] = 2 * (x * y + w * z);
		out->R[4][k] = 1 - 2 * (x * x + z * z);
		out->R[5][k] = 2 * (y * z - w * x);
		out->R[6][k] = 2 * (x * z - w * y);
		out->R[7][k] = 2 * (y * z + w * x);
		out->R[8][k] = 1 - 2 * (x * x + y * y);
	}
	for (int j = 0; j < parts && j < MK_SQ_PREP_PARTS; ++j) {
		double tv[3] = {t[j].x, t[j].y, t[j].z};
		for (int i = 0; i < 3; ++i) {
			double *pc = out->pc[3 * j + i];
			const double *r0 = out->R[3 * i], *r1 = out->R[3 * i + 1], *r2 = out->R[3 * i + 2];
			/* c + R t as mkVec3_Add(c, mkMat3_MulVecInline(R, t)) */
			for (int k = 0; k < n; ++k) pc[k] = c[i][k] + (r0[k] * tv[0] + r1[k] * tv[1] + r2[k] * tv[2]);
			if (!half) continue;   /* (no query boxes wanted) */
			float *lo = out->lo[3 * j + i], *hi = out->hi[3 * j + i];
			for (int k = 0; k < n; ++k) {
				lo[k] = mkSw_Down(pc[k] - half[j]);
				hi[k] = mkSw_Up(pc[k] + half[j]);
			}
		}
		if (spheres) mkSqPrep_NearBody(spheres, j, n, out);
		if (!(ell >> j & 1u)) continue;
		/* an ellipsoid part's exact box: row i of R M (mkMat3_MulInline's operations) times the semi-axes */
		const double (*m)[3] = M[j].m;
		for (int i = 0; i < 3; ++i) {
			const double *r0 = out->R[3 * i], *r1 = out->R[3 * i + 1], *r2 = out->R[3 * i + 2];
			double *eh = out->eh[3 * j + i];
			for (int k = 0; k < n; ++k) {
				double x = (r0[k] * m[0][0] + r1[k] * m[1][0] + r2[k] * m[2][0]) * abc[j][0];
				double y = (r0[k] * m[0][1] + r1[k] * m[1][1] + r2[k] * m[2][1]) * abc[j][1];
				double z = (r0[k] * m[0][2] + r1[k] * m[1][2] + r2[k] * m[2][2]) * abc[j][2];
				eh[k] = sqrt(x * x + y * y + z * z) * (1.0 + 1e-13);
			}
		}
	}
}

/* The first of n 3D poses that mkSq_PoseOk refuses (a value not finite or
 * of magnitude above 1e150, or a zero squared quaternion norm), n when
 * none: blocks of MK_SQ_PREP tested without branches, a failing block then
 * pose by pose. */
static long mkSqPrep_FirstBadBody(const double *poses, long n)
{
	for (long b = 0; b < n; b += MK_SQ_PREP) {
		long e = n - b < MK_SQ_PREP ? n : b + MK_SQ_PREP;
		int ok = 1;
		for (long k = b; k < e; ++k) {
			const double *p = poses + 7 * k;
			int v = (fabs(p[0]) <= 1e150) & (fabs(p[1]) <= 1e150) & (fabs(p[2]) <= 1e150) & (fabs(p[3]) <= 1e150)
				& (fabs(p[4]) <= 1e150) & (fabs(p[5]) <= 1e150) & (fabs(p[6]) <= 1e150);
			ok &= v & (p[3] * p[3] + p[4] * p[4] + p[5] * p[5] + p[6] * p[6] > 0.0);
		}
		if (ok) continue;
		for (long k = b; k < e; ++k) {
			const double *p = poses + 7 * k;
			int v = 1;
			for (int d = 0; d < 7; ++d) v &= fabs(p[d]) <= 1e150;
			if (!(v && p[3] * p[3] + p[4] * p[4] + p[5] * p[5] + p[6] * p[6] > 0.0)) return k;
		}
	}
	return n;
}

#endif
