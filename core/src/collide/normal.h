/* normal.h - MinkSum (Normal), the whole query (mkCollide3_Normal): Newton
 * from the centre line or a given start (newton.h), Gilbert's bracket or
 * restarts where that does not settle it (fallback.h), the certificate of an
 * overlap's depth (certify.h), and the answer with its witnesses.
 *
 * Static definitions: each build of the solver is a unit that includes this
 * header and names its entry (normal_portable.c, normal_fma.c, compiled with
 * different flags); collision.c picks the build at run time. */
#ifndef MINK_COLLIDE_NORMAL_H
#define MINK_COLLIDE_NORMAL_H

#include "collide/certify.h"
#include "collide/collision_impl.h"
#include "collide/fallback.h"

/* The branch and bound on an overlap (or touching): the depth certified
 * global, or said not to be. When no start converged (a ridge of a nearly
 * kinked support function), the branch and bound runs from the best state
 * met at the tighter MK_ANSWER_TOL (its restarts climb the ridge), and the
 * answer stands only when it completes; the residual reported is then the
 * width of its bracket. Returns 1 when certified; *upper receives the
 * upper bound of sd. */
MK_PAIR_INLINE int mkNormal_CertifyBest(const mkPairCtx *c, mkNormalBest *b, int *iters, double *upper, mkCollision3 *out)
{
	int evals = 0;
	int done = mkNormal_Certify(c, &b->st, &b->res, iters,
		(b->ok ? MK_COLLIDE3_GLOBAL_TOL : MK_ANSWER_TOL) * c->scale, upper, &evals) == 1;
	out->cert_evals = evals;
	if (b->ok)
		return done;
	if (done) {
		b->ok = 1;
		b->res = *upper - b->st.f;
	}
	return 1;
}

/* The query from the centre line (start NULL) or from a given unit start,
 * as mkCollide3_Normal and mkCollide3_NormalFrom describe. */
MK_PAIR_INLINE mkResult mkNormal_Query(mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out)
{
	mkCollision3_Clear(out);
	mkPairCtx c;
	if (mkPairCtx_Begin(&c, &b1, &b2, out) != MK_OK)
		return MK_ERR_UNSUPPORTED;
	double dl = mkVec3_LengthInline(c.d);
	mkVec3 n0 = dl > 0.0 ? mkVec3_Scale(c.d, 1.0 / dl) : mkVec3_Make(0.0, 0.0, 1.0);
	mkNormalBest b;
	int iters = 0;
	b.res = NAN;
	b.ok = mkNormal_Solve(&c, start ? *start : n0, &b.st, &iters, &b.res);
	b.stalled = b.ok == 2;
	out->restarts = 0;
	/* A given start that did not end at a separation (an overlap, or a start
	 * that did not converge): the centre line as without one, counted as a
	 * restart. */
	if (start && !(b.ok && b.st.f > 0.0))
		mkNormal_Restart(&c, n0, &b, &iters, out);
	mkVec3 gp1, gp2;
	int gilbert = mkNormal_Gilbert(&c, &b, &iters, &gp1, &gp2);
	if (!(b.ok && b.st.f > 0.0))
		mkNormal_Restarts(&c, n0, &b, &iters, out);
	double upper = NAN;
	int certified = 1;
	if (isfinite(b.st.f) && b.st.f <= 0.0 && mkIsFinite3(b.st.n))
		certified = mkNormal_CertifyBest(&c, &b, &iters, &upper, out);
	const mkNormalState *best = &b.st;
	out->iterations = iters;
	out->normal = best->n;
	out->bound = best->f;
	out->p1 = mkVec3_Add(b1.t, best->e.a1.s);
	out->p2 = mkVec3_Add(b2.t, best->e.a2.s);
	if (gilbert && mkIsFinite3(gp1) && mkIsFinite3(gp2)
		&& mkVec3_LengthInline(mkVec3_Sub(gp2, gp1)) < mkVec3_LengthInline(mkVec3_Sub(out->p2, out->p1))) {
		/* the fallback's hull already placed them on the faces */
		out->p1 = gp1;
		out->p2 = gp2;
	}
	out->residual = b.res / c.scale;
	if (!b.ok || !isfinite(best->f) || !mkIsFinite3(out->p1) || !mkIsFinite3(out->p2))
		return MK_ERR_CONVERGENCE;
	out->distance = best->f;
	double span = mkNormal_Witnesses(&c, &b.st, out);
	if (best->f > 0.0) {
		out->gap = span - best->f;
		out->certified = 1;
	} else {
		out->gap = upper - best->f;
		out->certified = certified;
	}
	out->status = mkContact_FromDistance(best->f, c.scale);
	return MK_OK;
}

#endif
