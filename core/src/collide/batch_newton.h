/* batch_newton.h - Newton's iteration for the signed distance of pairs of
 * ellipsoids in lanes (the distance mode of batch.c): the same
 * steps as the one-pair solver's ellipsoid loop (mkNormal_Ellipsoids of
 * newton.h), one pair per lane, all lanes in lock-step under masks.
 *
 * For an ellipsoid Q = P P^T: h(n) = sqrt(n^T Q n), s(n) = Q n / h, its
 * Jacobian (Q - s s^T) / h. At a unit n: s1 = s_1(n), s2 = s_2(-n),
 * f = <n, d - (s1 - s2)>, g = the part of d - (s1 - s2) orthogonal to n
 * (the tangential gradient of f; |d - (s1 - s2)|^2 = f^2 + |g|^2). A step
 * solves
 *   (J1 + J2 + f I + (h1 + h2 - f) n n^T) z = g
 * (the tangent plane kept invariant, n's eigenvalue h1 + h2 > 0; Sylvester's
 * criterion for positive definiteness), projects z onto the tangent plane
 * and moves to normalize(n + z). A lane stops converged when |g| <=
 * MK_COLLIDE3_RESIDUAL_TOL * scale, when f > 0 and |g|^2 <= 2 f
 * MK_BATCH_NEWTON_SETTLE * scale (then the witnesses' distance
 * sqrt(f^2 + |g|^2) exceeds f by at most MK_BATCH_NEWTON_SETTLE * scale: the
 * distance is settled, the step quadratic convergence would take after it
 * is saved), or when the step cannot move n by more than 1e-14 or gain
 * more than 1e-17 of the scale. The step is cut to at most
 * MK_TR_MAX long; a step that does not gain 1e-4 of its slope (Armijo, as
 * the one-pair solver's plain Newton) is tried again at half its length, and
 * after a cut the next step starts from the fraction accepted, doubling back
 * towards 1. A lane stops unconverged (left to the scalar path) when the
 * matrix is not positive definite, after MK_BATCH_NEWTON_CUTS cuts of one
 * step, or when MK_BATCH_NEWTON_STEPS steps (tries) did not converge. A
 * stopped lane keeps its state (later steps compute on it but do not
 * store).
 *
 * The including unit provides the lane type mkBV (MK_BX_W doubles), the
 * mask type mkBM (all bits set / clear per lane) and mkB_Load, mkB_Store,
 * mkB_Splat, mkB_Sqrt, mkB_Abs, mkB_Sel(mask, a, b), mkB_Lt(a, b),
 * mkB_Le(a, b), mkB_Any(mask). The operations are +, -, *, / and sqrt only
 * (correctly rounded, contraction off), so every build gives the same bits
 * as the scalar one (MK_BX_W 1, batch_scalar.c). */
#ifndef MINK_COLLIDE_BATCH_NEWTON_H
#define MINK_COLLIDE_BATCH_NEWTON_H

#include <float.h>

#include "collide/collision_impl.h"
#include "collide/steps.h"

typedef struct mkBN3 {
	mkBV x, y, z;
} mkBN3;

/* One lane's state at a unit normal: the products Q n, the support points
 * (about the centres), the support values, f and the tangential gradient. */
typedef struct mkBNAt {
	mkBN3 v1, v2, s1, s2, g;
	mkBV h1, h2, f;
} mkBNAt;

static inline mkBV mkBN_Dot(mkBN3 a, mkBN3 b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

static inline mkBN3 mkBN_Scale(mkBN3 a, mkBV k)
{
	return (mkBN3){ a.x * k, a.y * k, a.z * k };
}

static inline mkBN3 mkBN_Sub(mkBN3 a, mkBN3 b)
{
	return (mkBN3){ a.x - b.x, a.y - b.y, a.z - b.z };
}

static inline mkBN3 mkBN_Sel(mkBM k, mkBN3 a, mkBN3 b)
{
	return (mkBN3){ mkB_Sel(k, a.x, b.x), mkB_Sel(k, a.y, b.y), mkB_Sel(k, a.z, b.z) };
}

/* Q n for the symmetric Q stored as (Q00, Q01, Q02, Q11, Q12, Q22). */
static inline mkBN3 mkBN_Sym(const mkBV Q[6], mkBN3 n)
{
	return (mkBN3){ Q[0] * n.x + Q[1] * n.y + Q[2] * n.z, Q[1] * n.x + Q[3] * n.y + Q[4] * n.z,
		Q[2] * n.x + Q[4] * n.y + Q[5] * n.z };
}

static inline void mkBN_Eval(const mkBV Q1[6], const mkBV Q2[6], mkBN3 d, mkBN3 n, mkBNAt *e)
{
	mkBV one = mkB_Splat(1.0);
	e->v1 = mkBN_Sym(Q1, n);
	e->v2 = mkBN_Sym(Q2, n);
	e->s1 = mkBN_Scale(e->v1, one / mkB_Sqrt(mkBN_Dot(n, e->v1)));
	e->s2 = mkBN_Scale(e->v2, -one / mkB_Sqrt(mkBN_Dot(n, e->v2)));
	e->h1 = mkBN_Dot(n, e->s1);
	e->h2 = mkB_Splat(0.0) - mkBN_Dot(n, e->s2);
	mkBN3 x = mkBN_Sub(e->s1, e->s2), r = mkBN_Sub(d, x);
	e->f = mkBN_Dot(n, d) - mkBN_Dot(n, x);
	e->g = mkBN_Sub(r, mkBN_Scale(n, mkBN_Dot(n, r)));
}

static inline void mkBN_SelAt(mkBM k, const mkBNAt *a, mkBNAt *b)
{
	b->v1 = mkBN_Sel(k, a->v1, b->v1);
	b->v2 = mkBN_Sel(k, a->v2, b->v2);
	b->s1 = mkBN_Sel(k, a->s1, b->s1);
	b->s2 = mkBN_Sel(k, a->s2, b->s2);
	b->g = mkBN_Sel(k, a->g, b->g);
	b->h1 = mkB_Sel(k, a->h1, b->h1);
	b->h2 = mkB_Sel(k, a->h2, b->h2);
	b->f = mkB_Sel(k, a->f, b->f);
}

/* The step z at e (unprojected) and the mask of lanes where the shifted
 * matrix is positive definite (mkSolveSym3 of newton.h). */
static inline mkBM mkBN_Step(const mkBV Q1[6], const mkBV Q2[6], mkBN3 n, const mkBNAt *e, mkBN3 *z)
{
	mkBV one = mkB_Splat(1.0), i1 = one / e->h1, i2 = one / e->h2, f = e->f, w = e->h1 + e->h2 - f;
	mkBN3 a = e->s1, b = e->s2;
	mkBV c00 = (Q1[0] - a.x * a.x) * i1 + (Q2[0] - b.x * b.x) * i2 + f + w * n.x * n.x;
	mkBV c11 = (Q1[3] - a.y * a.y) * i1 + (Q2[3] - b.y * b.y) * i2 + f + w * n.y * n.y;
	mkBV c22 = (Q1[5] - a.z * a.z) * i1 + (Q2[5] - b.z * b.z) * i2 + f + w * n.z * n.z;
	mkBV c01 = (Q1[1] - a.x * a.y) * i1 + (Q2[1] - b.x * b.y) * i2 + w * n.x * n.y;
	mkBV c02 = (Q1[2] - a.x * a.z) * i1 + (Q2[2] - b.x * b.z) * i2 + w * n.x * n.z;
	mkBV c12 = (Q1[4] - a.y * a.z) * i1 + (Q2[4] - b.y * b.z) * i2 + w * n.y * n.z;
	mkBV k00 = c11 * c22 - c12 * c12, k01 = c02 * c12 - c01 * c22, k02 = c01 * c12 - c02 * c11;
	mkBV k11 = c00 * c22 - c02 * c02, k12 = c02 * c01 - c00 * c12, k22 = c00 * c11 - c01 * c01;
	mkBV det = c00 * k00 + c01 * k01 + c02 * k02, tr = c00 + c11 + c22;
	mkBV zero = mkB_Splat(0.0);
	mkBM ok = mkB_Lt(zero, c00) & mkB_Lt(zero, k22) & mkB_Lt(mkB_Splat(1e-12) * tr * tr * tr, det);
	mkBV inv = one / det;
	mkBN3 g = e->g;
	z->x = (k00 * g.x + k01 * g.y + k02 * g.z) * inv;
	z->y = (k01 * g.x + k11 * g.y + k12 * g.z) * inv;
	z->z = (k02 * g.x + k12 * g.y + k22 * g.z) * inv;
	return ok;
}

/* One block of MK_BX_W lanes: the bodies, the state at the current normal
 * and the masks. */
typedef struct mkBNBlock {
	mkBV Q1[6], Q2[6], scale, tol, tiny, settle, res, steps, damp;
	mkBN3 d, n;
	mkBNAt e;
	mkBM active, done;
} mkBNBlock;

static inline void mkBN_Start(const mkBatchEllIn *in, int o, mkBNBlock *b)
{
	for (int i = 0; i < 6; ++i) {
		b->Q1[i] = mkB_Load(in->Q1[i] + o);
		b->Q2[i] = mkB_Load(in->Q2[i] + o);
	}
	b->d = (mkBN3){ mkB_Load(in->d[0] + o), mkB_Load(in->d[1] + o), mkB_Load(in->d[2] + o) };
	b->n = (mkBN3){ mkB_Load(in->n[0] + o), mkB_Load(in->n[1] + o), mkB_Load(in->n[2] + o) };
	b->scale = mkB_Load(in->scale + o);
	b->tol = mkB_Splat(MK_COLLIDE3_RESIDUAL_TOL) * b->scale;
	b->tiny = mkB_Splat(1e-17) * b->scale;
	b->settle = mkB_Splat(2.0 * MK_BATCH_NEWTON_SETTLE) * b->scale;
	mkBN_Eval(b->Q1, b->Q2, b->d, b->n, &b->e);
	b->active = mkB_Le(b->scale, b->scale); /* every lane active, none done */
	b->done = ~b->active;
	b->res = mkB_Sqrt(mkBN_Dot(b->e.g, b->e.g));
	b->steps = mkB_Splat(0.0);
	b->damp = mkB_Splat(1.0);
}

/* The lanes of b that converged at the current point (|g| <= tol, or the
 * distance settled). */
static inline mkBM mkBN_Converged(const mkBNBlock *b)
{
	mkBV f = b->e.f;
	return mkB_Le(b->res, b->tol) | (mkB_Lt(mkB_Splat(0.0), f) & mkB_Le(b->res * b->res, b->settle * f));
}

/* One iteration of the active lanes of b. Returns 0 when none is active. */
static inline int mkBN_Iterate(mkBNBlock *b)
{
	mkBV one = mkB_Splat(1.0);
	mkBNAt *e = &b->e, t;
	mkBN3 n = b->n;
	b->res = mkB_Sel(b->active, mkB_Sqrt(mkBN_Dot(e->g, e->g)), b->res);
	mkBM conv = b->active & mkBN_Converged(b);
	b->done |= conv;
	b->active &= ~conv;
	if (!mkB_Any(b->active))
		return 0;
	mkBN3 z;
	mkBM ok = mkBN_Step(b->Q1, b->Q2, n, e, &z);
	z = mkBN_Sub(z, mkBN_Scale(n, mkBN_Dot(n, z)));
	mkBV zlen = mkB_Sqrt(mkBN_Dot(z, z)), slope = mkBN_Dot(e->g, z), pred = mkB_Splat(0.5) * slope;
	b->active &= ok & mkB_Le(zlen, mkB_Splat(1e300));
	b->steps = mkB_Sel(b->active, b->steps + one, b->steps);
	conv = b->active & (mkB_Le(zlen, mkB_Splat(1e-14)) | mkB_Le(pred, b->tiny));
	b->done |= conv;
	b->active &= ~conv;
	if (!mkB_Any(b->active))
		return 0;
	/* the step's fraction: at most MK_TR_MAX long, at most damp */
	mkBV cap = mkB_Splat(MK_TR_MAX) / zlen;
	mkBV frac = mkB_Sel(mkB_Lt(cap, b->damp), cap, b->damp);
	z = mkBN_Scale(z, frac);
	mkBN3 m = { n.x + z.x, n.y + z.y, n.z + z.z };
	m = mkBN_Scale(m, one / mkB_Sqrt(mkBN_Dot(m, m)));
	mkBN_Eval(b->Q1, b->Q2, b->d, m, &t);
	mkBV gain = t.f - e->f, noise = mkB_Splat(64.0 * DBL_EPSILON) * (mkB_Abs(e->f) + b->scale);
	mkBV want = frac * slope;
	mkBM big = mkB_Lt(noise, want);
	mkBM taken = b->active
		& ((big & mkB_Le(mkB_Splat(1e-4) * want, gain)) | (~big & mkB_Le(mkB_Splat(0.0) - noise, gain)));
	/* a rejected step is tried again at half the fraction, up to
	 * MK_BATCH_NEWTON_CUTS times; a taken one lets the next step grow back
	 * to twice its fraction */
	mkBV half = mkB_Splat(0.5) * frac, twice = frac + frac;
	b->damp = mkB_Sel(taken, mkB_Sel(mkB_Lt(twice, one), twice, one), half);
	b->active &= taken | mkB_Le(mkB_Splat(1.0 / (1 << MK_BATCH_NEWTON_CUTS)), half);
	b->n = mkBN_Sel(taken, m, n);
	mkBN_SelAt(taken, &t, e);
	return 1;
}

/* The last step's point, where the iterations ran out, and the outputs. */
static inline void mkBN_Finish(mkBNBlock *b, int o, mkBatchEllOut *out)
{
	const mkBNAt *e = &b->e;
	b->res = mkB_Sel(b->active, mkB_Sqrt(mkBN_Dot(e->g, e->g)), b->res);
	b->done |= b->active & mkBN_Converged(b);
	mkB_Store(out->n[0] + o, b->n.x);
	mkB_Store(out->n[1] + o, b->n.y);
	mkB_Store(out->n[2] + o, b->n.z);
	mkBN3 s[2] = { e->s1, e->s2 };
	for (int k = 0; k < 2; ++k) {
		mkB_Store((k ? out->s2 : out->s1)[0] + o, s[k].x);
		mkB_Store((k ? out->s2 : out->s1)[1] + o, s[k].y);
		mkB_Store((k ? out->s2 : out->s1)[2] + o, s[k].z);
	}
	mkB_Store(out->f + o, e->f);
	mkB_Store(out->res + o, b->res);
	mkB_Store(out->steps + o, b->steps);
	mkB_Store(out->done + o, mkB_Sel(b->done, mkB_Splat(1.0), mkB_Splat(0.0)));
}

/* The first in->count lanes of in (rounded up to whole blocks), in blocks
 * of MK_BX_W, into out. The blocks
 * iterate in turn within each step: their chains of square roots and
 * divisions are independent, so the processor overlaps them (one block
 * alone waits on their latency). */
static void mkBN_Run(const mkBatchEllIn *in, mkBatchEllOut *out)
{
	enum { MK_BN_BLOCKS = MK_BATCH_NLANES / MK_BX_W };
	mkBNBlock b[MK_BN_BLOCKS];
	int live[MK_BN_BLOCKS], nb = (in->count + MK_BX_W - 1) / MK_BX_W;
	nb = nb < 0 ? 0 : nb > MK_BN_BLOCKS ? MK_BN_BLOCKS : nb;
	for (int i = 0; i < nb; ++i) {
		mkBN_Start(in, i * MK_BX_W, &b[i]);
		live[i] = 1;
	}
	for (int it = 0, any = 1; it < MK_BATCH_NEWTON_STEPS && any; ++it) {
		any = 0;
		for (int i = 0; i < nb; ++i)
			if (live[i])
				any |= live[i] = mkBN_Iterate(&b[i]);
	}
	for (int i = 0; i < nb; ++i)
		mkBN_Finish(&b[i], i * MK_BX_W, out);
}

#endif
