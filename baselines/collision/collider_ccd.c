/* collider_ccd.c - libccd on the exact smooth support functions of the two
 * bodies (mkBody3_Support, the closed-form support point): GJK
 * (ccdGJKIntersect), MPR (ccdMPRPenetration) and GJK+EPA
 * (ccdGJKPenetration). libccd (Debian's build is double precision) has no
 * distance query for separated bodies, so these give the status and, when
 * overlapping, the penetration depth. The tolerances are libccd's defaults
 * (CCD_INIT): epa 1e-4, mpr 1e-4, dist 1e-6; max_iterations 1000.
 *
 * ccd-gjk-epa-1e-6, -1e-8, -1e-10: GJK+EPA with its tolerances tightened to
 * reach a depth error of about k = 1e-6, 1e-8, 1e-10 of the pair's scale
 * (mkCollide3_PairSize). libccd's EPA stops when the new support point is
 * within epa_tolerance of the nearest face in *squared* distance (its
 * second test, ccdVec3PointTriDist2 < epa_tolerance; the first, on
 * <v, w> - |w|^2 with w the unnormalised nearest point, is squared too),
 * so epa_tolerance = (k * scale)^2 for a depth error of k * scale;
 * dist_tolerance = k * scale. Its EPA loop has no iteration limit, and
 * below about 1e-11 of the scale it did not end (rounding of squared
 * distances near 50; at 1e-10 on one deep overlap of 10^4); these entries
 * cap the support calls at
 * MK_CCD_TIGHT_CALLS: past it the support map returns the origin for both
 * bodies, which ends EPA at once, and the run is a failure
 * (MK_ERR_CONVERGENCE), never an answer. */
#include <ccd/ccd.h>
#include <ccd/vec3.h>

#include "colliders_internal.h"

#define MK_CCD_MAX_ITER 1000

static void mkSupport(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
	const mkBody3 *b = obj;
	mkVec3 p = mkBody3_Support(*b, mkVec3_Make(ccdVec3X(dir), ccdVec3Y(dir), ccdVec3Z(dir)));
	ccdVec3Set(out, p.x, p.y, p.z);
}

static void mkCenter(const void *obj, ccd_vec3_t *out)
{
	const mkBody3 *b = obj;
	ccdVec3Set(out, b->t.x, b->t.y, b->t.z);
}

static void mkInit(ccd_t *ccd)
{
	CCD_INIT(ccd);
	ccd->support1 = mkSupport;
	ccd->support2 = mkSupport;
	ccd->center1 = mkCenter;
	ccd->center2 = mkCenter;
	ccd->max_iterations = MK_CCD_MAX_ITER;
}

static mkResult mkRunGjk(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	ccd_t ccd;
	mkInit(&ccd);
	int hit = ccdGJKIntersect(&b1, &b2, &ccd);
	out->status = hit ? MK_CONTACT_OVERLAPPING : MK_CONTACT_SEPARATED;
	return MK_OK;
}

/* MPR and EPA: 0 = intersect (depth, dir, pos filled), -1 = separated,
 * -2 = allocation failure (EPA). dir: the direction to move B2 by depth. */
static mkResult mkFinishPenetration(int rc, double depth, ccd_vec3_t *dir, mkCollision3 *out)
{
	if (rc == -1) {
		out->status = MK_CONTACT_SEPARATED;
		return MK_OK;
	}
	if (rc != 0)
		return MK_ERR_MEMORY;
	out->status = MK_CONTACT_OVERLAPPING;
	out->distance = -depth;
	out->normal = mkVec3_Make(-ccdVec3X(dir), -ccdVec3Y(dir), -ccdVec3Z(dir));
	return MK_OK;
}

typedef int (*mkCcdPenetration)(const void *, const void *, const ccd_t *, ccd_real_t *, ccd_vec3_t *,
	ccd_vec3_t *);

/* A libccd penetration query (MPR or GJK+EPA) on the two bodies. */
static mkResult mkRunPenetration(mkCcdPenetration query, mkBody3 b1, mkBody3 b2, mkCollision3 *out)
{
	ccd_t ccd;
	mkInit(&ccd);
	ccd_real_t depth = 0;
	ccd_vec3_t dir, pos;
	int rc = query(&b1, &b2, &ccd, &depth, &dir, &pos);
	return mkFinishPenetration(rc, depth, &dir, out);
}

static mkResult mkRunMpr(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	return mkRunPenetration(ccdMPRPenetration, b1, b2, out);
}

static mkResult mkRunEpa(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	return mkRunPenetration(ccdGJKPenetration, b1, b2, out);
}

/* ---- tightened GJK+EPA ------------------------------------------------------ */

/* Support calls per query before a tight run is cut off: on the
 * experiment's 10^4 deep overlaps a converged run took at most 818, 940 and
 * 910 calls at 1e-6, 1e-8 and 1e-10 of the scale (median 72 to 100); one
 * run at 1e-10 (trial 9017) did not end. Each EPA step scans the whole
 * polytope for its nearest face, so a run cut off here costs about 0.1 s. */
#define MK_CCD_TIGHT_CALLS 20000

/* A body of a tight run and the run's count of support calls. The body
 * comes first, so mkCenter reads it through the same pointer. */
typedef struct mkCcdTight { mkBody3 b; long *calls; } mkCcdTight;

static void mkSupportTight(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
	const mkCcdTight *t = obj;
	if (++*t->calls > MK_CCD_TIGHT_CALLS) {
		ccdVec3Set(out, 0.0, 0.0, 0.0);
		return;
	}
	mkSupport(&t->b, dir, out);
}

static mkResult mkRunEpaTight(mkBody3 b1, mkBody3 b2, mkCollision3 *out, double k)
{
	long calls = 0;
	mkCcdTight t1 = { b1, &calls }, t2 = { b2, &calls };
	double tol = k * mkCollide3_PairSize(b1, b2);
	ccd_t ccd;
	mkInit(&ccd);
	ccd.support1 = ccd.support2 = mkSupportTight;
	ccd.epa_tolerance = tol * tol;
	ccd.dist_tolerance = tol;
	ccd_real_t depth = 0;
	ccd_vec3_t dir, pos;
	int rc = ccdGJKPenetration(&t1, &t2, &ccd, &depth, &dir, &pos);
	if (calls > MK_CCD_TIGHT_CALLS) {
		out->status = MK_CONTACT_UNKNOWN;
		return MK_ERR_CONVERGENCE;
	}
	return mkFinishPenetration(rc, depth, &dir, out);
}

static mkResult mkRunEpa6(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	return mkRunEpaTight(b1, b2, out, 1e-6);
}

static mkResult mkRunEpa8(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	return mkRunEpaTight(b1, b2, out, 1e-8);
}

static mkResult mkRunEpa10(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	return mkRunEpaTight(b1, b2, out, 1e-10);
}

static const char *mkCcd(void) { return mkCollide_CcdVersion(); }

#define MK_CCD_PARAMS "libccd on mkBody3_Support, CCD_INIT tolerances (epa 1e-4, mpr 1e-4, dist 1e-6), max_iterations 1000"

const mkCollider mkCollider_CcdGjk = {
	"ccd-gjk", "GJK intersection test on the exact smooth support functions (libccd)",
	MK_CCD_PARAMS, MK_GIVES_STATUS, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 0, NULL, mkRunGjk, mkCcd
};

const mkCollider mkCollider_CcdMpr = {
	"ccd-mpr", "MPR status and penetration depth on the exact smooth support functions (libccd)",
	MK_CCD_PARAMS, MK_GIVES_STATUS | MK_GIVES_PENETRATION, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 0, NULL,
	mkRunMpr, mkCcd
};

const mkCollider mkCollider_CcdGjkEpa = {
	"ccd-gjk-epa", "GJK+EPA status and penetration depth on the exact smooth support functions (libccd)",
	MK_CCD_PARAMS, MK_GIVES_STATUS | MK_GIVES_PENETRATION, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 0, NULL,
	mkRunEpa, mkCcd
};

#define MK_CCD_TIGHT_PARAMS(k) "libccd GJK+EPA on mkBody3_Support, tightened to a depth error of " k " of the " \
	"scale: epa_tolerance (" k " * scale)^2 (libccd compares squared distances), dist_tolerance " k " * scale, " \
	"max_iterations 1000 (GJK); support calls capped at 20000 (past it: a failure)"

const mkCollider mkCollider_CcdGjkEpa6 = {
	"ccd-gjk-epa-1e-6", "GJK+EPA (libccd) tightened to 1e-6 of the scale: status and penetration depth",
	MK_CCD_TIGHT_PARAMS("1e-6"), MK_GIVES_STATUS | MK_GIVES_PENETRATION, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS,
	0, NULL, mkRunEpa6, mkCcd
};

const mkCollider mkCollider_CcdGjkEpa8 = {
	"ccd-gjk-epa-1e-8", "GJK+EPA (libccd) tightened to 1e-8 of the scale: status and penetration depth",
	MK_CCD_TIGHT_PARAMS("1e-8"), MK_GIVES_STATUS | MK_GIVES_PENETRATION, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS,
	0, NULL, mkRunEpa8, mkCcd
};

const mkCollider mkCollider_CcdGjkEpa10 = {
	"ccd-gjk-epa-1e-10", "GJK+EPA (libccd) tightened to 1e-10 of the scale: status and penetration depth",
	MK_CCD_TIGHT_PARAMS("1e-10"), MK_GIVES_STATUS | MK_GIVES_PENETRATION, MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS,
	0, NULL, mkRunEpa10, mkCcd
};
