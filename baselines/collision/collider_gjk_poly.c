/* collider_gjk_poly.c - GJK as the paper runs it: libccd's ccdGJKIntersect
 * on the 10 x 10 parameter-grid vertex sets of both bodies (100 vertices
 * each), built in the untimed preparation. */
#include "colliders_internal.h"

#define MK_GRID 10
enum { MK_NV = MK_GRID * MK_GRID };

/* Scratch layout: x1 y1 z1 x2 y2 z2 ux uy uz, MK_NV doubles each. */
static mkResult mkPrepare(mkBody3 b1, mkBody3 b2, mkColliderScratch *s)
{
	double *d = s->d;
	double *u = d + 6 * MK_NV;
	mkResult r = mkCollide_GridVertices(b1, MK_GRID, u, u + MK_NV, u + 2 * MK_NV, d, d + MK_NV, d + 2 * MK_NV);
	if (r == MK_OK)
		r = mkCollide_GridVertices(b2, MK_GRID, u, u + MK_NV, u + 2 * MK_NV, d + 3 * MK_NV, d + 4 * MK_NV, d + 5 * MK_NV);
	return r;
}

static mkResult mkRun(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)b1; (void)b2;
	const double *d = s->d;
	mkVertices3 v1 = { d, d + MK_NV, d + 2 * MK_NV, MK_NV }, v2 = { d + 3 * MK_NV, d + 4 * MK_NV, d + 5 * MK_NV, MK_NV };
	mkCollide c = mkCollide_GJK(v1, v2, MK_COLLIDE_LM_MAX_ITER);
	mkCollision3_FromLegacy(c, out);
	return MK_OK;
}

static const char *mkCcd(void) { return mkCollide_CcdVersion(); }

_Static_assert(9 * MK_NV <= MK_COLLIDER_SCRATCH_DOUBLES, "scratch too small for the GJK vertex sets");

const mkCollider mkCollider_GjkPoly = {
	"gjk-poly", "GJK on 100-vertex polytopes of the bodies, the paper's baseline (libccd)",
	"libccd ccdGJKIntersect on 10x10 grid vertex sets (mkSample3_Grid), max 100 iterations; vertex sets built untimed",
	MK_GIVES_STATUS, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 0, mkPrepare, mkRun, mkCcd
};
