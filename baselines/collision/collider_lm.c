/* collider_lm.c - the paper's Levenberg-Marquardt queries (cminpack lmder
 * with central-difference Jacobians, mink/collide.h): MinkSum (Normal) and
 * (Ray) on B1's surface angles, and Common Normal on both bodies' angles. A
 * solve counts as converged when its residual norm is below the paper's
 * 1e-10; otherwise the entry reports MK_ERR_CONVERGENCE and no verdict. */
#include <math.h>

#include "colliders_internal.h"

static mkResult mkFinish(mkCollide c, mkCollision3 *out)
{
	mkCollision3_FromLegacy(c, out);
	if (!(c.residual < MK_COLLIDE_SUCCESS_RESIDUAL)) {
		out->status = MK_CONTACT_UNKNOWN;
		return MK_ERR_CONVERGENCE;
	}
	return MK_OK;
}

static mkResult mkRunNormalLm(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	return mkFinish(mkCollide_NormalLm(b1, b2, MK_COLLIDE_LM_MAX_ITER), out);
}

static mkResult mkRunRayLm(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	return mkFinish(mkCollide_RayLm(b1, b2, MK_COLLIDE_LM_MAX_ITER), out);
}

static mkResult mkRunCommon(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	mkCollide c = mkCollide_CommonNormal(b1, b2, MK_COLLIDE_LM_MAX_ITER);
	mkResult r = mkFinish(c, out);
	if (r == MK_OK) {
		out->p1 = c.p1;
		out->p2 = c.p2;
		/* A converged common-normal pair of a separated pair: its distance
		 * (the closest pair when the solve found it; nothing forces it). */
		if (out->status == MK_CONTACT_SEPARATED)
			out->distance = mkVec3_Length(mkVec3_Sub(c.p2, c.p1));
	}
	return r;
}

static const char *mkCminpack(void) { return mkCollide_CminpackVersion(); }

#define MK_LM_PARAMS "cminpack lmder, central-difference Jacobian (step 1e-6 rad), ftol=xtol=1e-15, gtol=0, " \
	"max 100 Jacobians, converged iff residual norm < 1e-10"

const mkCollider mkCollider_MinkNormalLm = {
	"minksum-normal-lm", "MinkSum (Normal) as the paper solves it: LM on B1's surface angles (cminpack)",
	MK_LM_PARAMS, MK_GIVES_STATUS, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 0, NULL, mkRunNormalLm, mkCminpack
};

const mkCollider mkCollider_MinkRayLm = {
	"minksum-ray-lm", "MinkSum (Ray) as the paper solves it: LM on B1's surface angles (cminpack)",
	MK_LM_PARAMS, MK_GIVES_STATUS, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 0, NULL, mkRunRayLm, mkCminpack
};

const mkCollider mkCollider_CommonNormal = {
	"common-normal", "Common Normal: LM on both bodies' surface angles, 4 unknowns (cminpack)",
	MK_LM_PARAMS, MK_GIVES_STATUS | MK_GIVES_DISTANCE | MK_GIVES_WITNESS, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS,
	0, NULL, mkRunCommon, mkCminpack
};
