/* mink/collision.h - signed distance and contact status of two placed
 * superquadrics, solved on the closed-form support map (paper Theorem 1,
 * Sec. 7.2): the queries MinkSum (Normal) and MinkSum (Ray).
 *
 * With h1, h2 the support functions of B1 - c1 and B2 - c2 (about the
 * centres), d = c2 - c1 and K = (B1 - c1) (+) (-(B2 - c2)) the centred
 * contact space, every unit n gives the bound
 *     f(n) = <n, d> - h1(n) - h2(-n)  <=  sd,
 * where sd is the signed distance: the Euclidean distance of the bodies when
 * they are separated, minus the penetration depth (the shortest translation
 * that separates them) when they overlap. sd = max over unit n of f(n), the
 * signed distance of the point d from K. At the maximiser d - x(n) is
 * parallel to n, x(n) = s1(n) - s2(-n) the contact-space point of Theorem 1.
 *
 *  mkCollide3_Normal  maximises f over the unit sphere by a trust-region
 *                     Newton method with the exact Hessian of the closed
 *                     forms (2 unknowns: a step in the tangent plane of n).
 *                     Separated bodies: f has a single local maximum, so the
 *                     answer is global and certified two-sided: f(n) <= sd <=
 *                     |p2 - p1| for the witness points p1 in B1, p2 in B2.
 *                     Overlapping bodies: the depth is the distance from d to
 *                     the boundary of K, which can have several local optima;
 *                     the solver restarts once from the best of a few
 *                     directions (the reversed centre line, the bodies' axes,
 *                     a lattice) and keeps the better answer, then a branch
 *                     and bound over the sphere of normals certifies it
 *                     global: sd <= f(n) + gap with gap <=
 *                     MK_COLLIDE3_GLOBAL_TOL * scale (restarting Newton from
 *                     any direction it meets 1e-10 * scale above the best),
 *                     or says it could not within its budget (certified 0,
 *                     gap wider).
 *                     Where the support function is nearly kinked (exponents
 *                     near 0 or 2) Newton can stall on a ridge; a separated
 *                     pair is then answered by Gilbert's distance iteration
 *                     on B2 - B1 (a two-sided bracket of sd), an overlap on
 *                     which no start converged by the branch and bound at
 *                     1e-10 of the scale.
 *  mkCollide3_Ray     finds the boundary point of K on the centre line (the
 *                     paper's MinkSum (Ray)): minimises the convex function
 *                     H(u + s) = h1(u + s) + h2(-(u + s)) over s orthogonal to
 *                     u = d / |d| (its minimum is the distance from c1 to that
 *                     boundary point); separated iff it is below |d|. Gives
 *                     the status and the translation along the centre line
 *                     that makes the bodies touch, not the Euclidean
 *                     distance.
 *
 * Both work on any valid bodies (mkBody3_IsValid); ellipsoids take the
 * ellipsoid formulas. Nothing is allocated. */
#ifndef MINK_COLLISION_H
#define MINK_COLLISION_H

#include "body.h"

MK_EXTERN_C_BEGIN

typedef enum mkContact {
	MK_CONTACT_UNKNOWN = -1,    /* no verdict (the solver did not converge) */
	MK_CONTACT_SEPARATED = 0,
	MK_CONTACT_TOUCHING = 1,    /* |sd| <= MK_COLLIDE3_TOUCH_TOL * scale */
	MK_CONTACT_OVERLAPPING = 2
} mkContact;

/* "separated", "touching", "overlapping", "unknown". */
MK_API const char *mkContact_Name(mkContact c);

/* The answer of one query. Fields a query does not produce are NaN (reals)
 * or -1 (integers). */
typedef struct mkCollision3 {
	mkContact status;
	double distance;    /* signed distance sd (Normal): > 0 the Euclidean
	                       distance, < 0 minus the penetration depth */
	double directional; /* Ray: the translation of B2 along the centre line
	                       c2 - c1 that makes the bodies touch (> 0 separated);
	                       Normal: NaN */
	mkVec3 normal;      /* unit n, pointing from B1 towards B2 */
	mkVec3 p1, p2;      /* witness points on the boundaries of B1 and B2
	                       (p2 - p1 = sd n at the optimum; Normal on a
	                       separated pair: the nearest points, found on
	                       nearly flat faces by Gilbert's iteration from the
	                       answer, within gap of the distance) */
	double bound;       /* f(n) at the answer: a lower bound of sd */
	double gap;         /* certificate width: separated (Normal), |p2 - p1| -
	                       f(n) >= 0 (up to rounding, a few ulps of the
	                       scale; up to about 1e-10 of it when Gilbert's
	                       iteration answered) and sd lies in [f(n),
	                       |p2 - p1|]; overlaps: see certified; NaN when no
	                       two-sided bound is known (Ray) */
	double residual;    /* optimality residual at the answer, relative to
	                       scale: |tangential part of d - x(n)| / scale
	                       (Normal), |x(n) off the centre line| / scale (Ray);
	                       a Ray whose iteration stalled but whose status is
	                       certain by bounds reports the width of its bracket
	                       of the boundary distance instead, and a Normal
	                       answered by a fallback (Gilbert's iteration, or
	                       the branch and bound when no start converged) the
	                       width of its bracket of sd */
	double scale;       /* the pair's size (mkCollide3_PairSize): |d| + r1 + r2,
	                       r the bodies' circumradius bounds */
	int iterations;     /* Newton iterations (all restarts), and the pair
	                       evaluations of Gilbert's iteration when it ran */
	int restarts;       /* extra starts tried (Normal, overlap only) */
	int certified;      /* Normal: 1 when sd is certified to lie in
	                       [bound, bound + gap]: always for separated bodies,
	                       and for overlaps when the branch and bound over
	                       the sphere of normals finished within its budget
	                       (gap <= MK_COLLIDE3_GLOBAL_TOL * scale up to
	                       rounding); 0 when it did not (an overlap whose
	                       depth is then a local optimum only, gap NaN);
	                       -1 on failure and for Ray */
	int cert_evals;     /* Normal, overlaps: pair evaluations the branch and
	                       bound used (patch centres and the Newton
	                       iterations of its restarts); -1 otherwise */
} mkCollision3;

/* Status band: |sd| <= MK_COLLIDE3_TOUCH_TOL * scale is "touching". */
#define MK_COLLIDE3_TOUCH_TOL 1e-12
/* Converged when the residual (see mkCollision3) is at most this. */
#define MK_COLLIDE3_RESIDUAL_TOL 1e-12
/* Overlaps: the depth is certified global within this (times the scale). */
#define MK_COLLIDE3_GLOBAL_TOL 1e-8
/* Overlaps: the branch and bound's budget of pair evaluations. */
#define MK_COLLIDE3_CERT_EVALS 20000
/* Newton iterations per start before giving up. */
#define MK_COLLIDE3_MAX_ITER 100

/* An empty answer: status unknown, NaN reals, counts -1. out must not be
 * NULL. */
MK_API void mkCollision3_Clear(mkCollision3 *out);

/* The status of a signed distance sd under the touching band
 * MK_COLLIDE3_TOUCH_TOL * scale; MK_CONTACT_UNKNOWN when sd is NaN. */
MK_API mkContact mkContact_FromDistance(double sd, double scale);

/* MinkSum (Normal): signed distance, witnesses, status. Returns MK_OK, or
 * MK_ERR_CONVERGENCE when no start converged within MK_COLLIDE3_MAX_ITER
 * iterations and the fallback (Gilbert's iteration on a separated pair, the
 * branch and bound on an overlap) did not bracket sd within 1e-10 of the
 * scale, or the iterate became non-finite (a degenerate pose; coincident
 * centres are fine), and MK_ERR_UNSUPPORTED when the scale is not finite;
 * the answer then has status MK_CONTACT_UNKNOWN, distance NaN, and the last
 * iterate's numbers (bound, residual, witnesses) for diagnosis. out must not
 * be NULL. */
MK_API mkResult mkCollide3_Normal(mkBody3 b1, mkBody3 b2, mkCollision3 *out);

/* mkCollide3_Normal started from the direction start (any nonzero finite
 * vector, normalised here) instead of the centre line: for a sequence of
 * nearby poses, the previous answer's normal. The answer is
 * mkCollide3_Normal's within the solver's tolerance (for a separated pair
 * every local maximum of f with f > 0 is the global one, since f is concave
 * and positively homogeneous on the ball; when the start does not end at a
 * separation, the centre line is tried next, counted in restarts, and an
 * overlap's restarts and certificate follow as without a start); only the
 * work to reach it differs. Returns
 * MK_ERR_ARGUMENT (and a cleared answer) for a zero or non-finite start,
 * otherwise as mkCollide3_Normal. */
MK_API mkResult mkCollide3_NormalFrom(mkBody3 b1, mkBody3 b2, mkVec3 start, mkCollision3 *out);

/* Which build of mkCollide3_Normal's solver runs on this processor: "fma"
 * (compiled with -mavx2 -mfma and contraction, picked where the processor
 * has AVX2 and FMA, about 7 % faster) or "portable". The two answer alike
 * to rounding (a few ulps of the scale); a build configured with
 * -DMINK_FMA_SOLVER=OFF has only the portable one. For the metadata of
 * results. */
MK_API const char *mkCollide3_Build(void);

/* MinkSum (Ray): status, directional gap and witnesses. Failure as
 * mkCollide3_Normal; coincident centres are overlapping (no solve). */
MK_API mkResult mkCollide3_Ray(mkBody3 b1, mkBody3 b2, mkCollision3 *out);

/* f(n) = <n, c2 - c1> - h1(n) - h2(-n) for any nonzero n (normalised first):
 * the support-function lower bound of the signed distance, evaluated with
 * mkBody3_SupportValue. NaN for n = 0. */
MK_API double mkCollide3_Bound(mkBody3 b1, mkBody3 b2, mkVec3 n);

/* The pair's size, the unit every tolerance here is relative to (the
 * `scale` of mkCollision3): |c2 - c1| + r1 + r2 with r = max(a, b, c) |M|_F,
 * an upper bound of the body's distance from its centre. Not the sum's size
 * of mink/sum.h (mkSum3_Size), which bounds the sum's points instead. */
MK_API double mkCollide3_PairSize(mkBody3 b1, mkBody3 b2);

/* The support point s(n) = argmax over B of <n, x> of the centred body B - t
 * and its Jacobian ds/dn (the Hessian of the support function, symmetric
 * positive semi-definite, J n = 0) for nonzero n, computed from the closed
 * form. Returns the support point; J may be NULL. At normals where a
 * superquadric's support function is not twice differentiable (n along a
 * body axis with an exponent below 1) the curvature terms are clamped to
 * large finite values. */
MK_API mkVec3 mkBody3_SupportJacobian(mkBody3 b, mkVec3 n, mkMat3 *J);

MK_EXTERN_C_END

#endif
