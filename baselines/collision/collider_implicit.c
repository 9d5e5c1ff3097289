/* collider_implicit.c - Implicit: the closest points of the two bodies'
 * implicit descriptions by Ipopt (mink/collide.h, mkCollide_Implicit). */
#include <math.h>

#include "colliders_internal.h"

/* Ipopt's tolerance on its scaled NLP error: the paper's success level. */
#define MK_IMPLICIT_TOL 1e-10

static mkResult mkRunImplicit(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	mkCollide c = mkCollide_Implicit(b1, b2, MK_IMPLICIT_TOL);
	mkCollision3_FromLegacy(c, out);
	/* Ipopt's Solve_Succeeded (0) or Solved_To_Acceptable_Level (1). */
	if (c.status != 0 && c.status != 1) {
		out->status = MK_CONTACT_UNKNOWN;
		return MK_ERR_CONVERGENCE;
	}
	out->p1 = c.p1;
	out->p2 = c.p2;
	if (out->status == MK_CONTACT_SEPARATED)
		out->distance = mkVec3_Length(mkVec3_Sub(c.p2, c.p1));
	return MK_OK;
}

static const char *mkIpopt(void) { return mkCollide_IpoptVersion(); }

const mkCollider mkCollider_Implicit = {
	"implicit", "Implicit: min |x1 - x2|^2 s.t. both implicit constraints (Ipopt)",
	"Ipopt, limited-memory BFGS Hessian, tol=1e-10, max_iter=1000, constraints Psi^eps1<=1, "
	"overlapping iff the optimal points are at most 1e-3 apart, converged iff Ipopt status 0 or 1",
	MK_GIVES_STATUS | MK_GIVES_DISTANCE | MK_GIVES_WITNESS, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS,
	0, NULL, mkRunImplicit, mkIpopt
};
