/* collider_referee.c - the referee: sd = -min over unit n of h1(n) + h2(-n)
 * (support functions of the placed bodies, mkBody3_SupportValue) by a grid
 * of directions and a pattern search (mkCollide_Referee): slow, and sharing
 * nothing with the Newton queries but the support function itself. */
#include "colliders_internal.h"

#define MK_REFEREE_GRID 24

static mkResult mkRun(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	mkVec3 n;
	double g = mkCollide_Referee(b1, b2, MK_REFEREE_GRID, &n);
	out->scale = mkCollide3_Scale(b1, b2);
	out->distance = -g;
	out->bound = -g;
	/* With the placed bodies' support functions, h1(n) + h2(-n) = -f(n)
	 * (mink/collision.h), so the minimiser is the normal from B1 to B2. */
	out->normal = n;
	out->p1 = mkBody3_Support(b1, n);
	out->p2 = mkBody3_Support(b2, mkVec3_Neg(n));
	out->status = mkContact_FromDistance(out->distance, out->scale);
	return MK_OK;
}

const mkCollider mkCollider_Referee = {
	"referee", "Referee: -min over unit n of h1(n) + h2(-n), grid and pattern search (support functions only)",
	"24 x 48 direction grid, pattern search from the best 3 (steps to 1e-11 rad, at most 4000 evaluations each)",
	MK_GIVES_STATUS | MK_GIVES_DISTANCE | MK_GIVES_PENETRATION | MK_GIVES_WITNESS,
	MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 1, NULL, mkRun, NULL
};
