/* collider_minksum.c - the core's closed-form queries (mink/collision.h):
 * MinkSum (Normal) and MinkSum (Ray), trust-region Newton on the support
 * map of Theorem 1. */
#include "colliders_internal.h"

static mkResult mkRunNormal(mkBody3 b1, mkBody3 b2, mkColliderScratch *scratch, mkCollision3 *out)
{
	(void)scratch;
	return mkCollide3_Normal(b1, b2, out);
}

static mkResult mkRunRay(mkBody3 b1, mkBody3 b2, mkColliderScratch *scratch, mkCollision3 *out)
{
	(void)scratch;
	return mkCollide3_Ray(b1, b2, out);
}

#define MK_STR2(x) #x
#define MK_STR(x) MK_STR2(x)
#define MK_NEWTON_PARAMS "trust-region Newton, exact Hessian of the closed form, residual tol " \
	MK_STR(MK_COLLIDE3_RESIDUAL_TOL) " of scale, max " MK_STR(MK_COLLIDE3_MAX_ITER) \
	" iterations per start, touching band " MK_STR(MK_COLLIDE3_TOUCH_TOL) " of scale"

const mkCollider mkCollider_MinkNormal = {
	"minksum-normal",
	"MinkSum (Normal): signed distance by Newton on the unit normal (core, closed form)",
	MK_NEWTON_PARAMS "; a rejected step cut to the crossing of the tangent lines at its ends; overlap: one "
	"restart from the best of the reversed centre line, the body axes and diagonals and a lattice, then the depth "
	"certified global within " MK_STR(MK_COLLIDE3_GLOBAL_TOL) " of scale by a branch and bound over the sphere "
	"of normals (bounds from single planes and mixtures of two; Newton restarted from a centre 1e-10 of scale "
	"above the best; at most " MK_STR(MK_COLLIDE3_CERT_EVALS) " pair evaluations; past it: certified 0)",
	MK_GIVES_STATUS | MK_GIVES_DISTANCE | MK_GIVES_PENETRATION | MK_GIVES_WITNESS,
	MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 0, NULL, mkRunNormal, NULL
};

const mkCollider mkCollider_MinkRay = {
	"minksum-ray",
	"MinkSum (Ray): contact-space boundary on the centre line by Newton (core, closed form)",
	MK_NEWTON_PARAMS,
	MK_GIVES_STATUS | MK_GIVES_WITNESS,
	MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 0, NULL, mkRunRay, NULL
};
