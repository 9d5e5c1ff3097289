/* arc2.c - the certificate of one 2D arc: between consecutive normals ni,
 * nj with boundary points pi, pj, how far the true boundary can be from the
 * polygon's edge (inner bound) or the tangent lines' corner (outer bound),
 * Proofs 1-3 of docs/scene.md. Both 2D samplers (boundary2.c, walk2.c)
 * certify their arcs here. */
#include "cspace/work.h"

#include <math.h>

#include "base/geom_inline.h"

static double mkDistSegment2(mkVec2 v, mkVec2 a, mkVec2 b)
{
	mkVec2 d = mkVec2_Sub(b, a), e = mkVec2_Sub(v, a);
	double dd = mkVec2_Dot(d, d), t = dd > 0.0 ? mkVec2_Dot(e, d) / dd : 0.0;
	if (t < 0.0) t = 0.0;
	if (t > 1.0) t = 1.0;
	return mkVec2_LengthInline(mkVec2_Sub(e, mkVec2_Scale(d, t)));
}

/* The vertex of the tangent lines at (ni, pi) and (nj, pj): pi + s tau_i with
 * tau_i = ni turned by +90 degrees (Proof 2 of docs/scene.md). */
mkVec2 mkBoundary2_TangentVertex(mkVec2 ni, mkVec2 pi, mkVec2 nj, mkVec2 pj)
{
	mkVec2 tau = {-ni.y, ni.x};
	double s = mkVec2_Dot(nj, mkVec2_Sub(pj, pi)) / mkVec2_Cross(ni, nj);
	return mkVec2_Add(pi, mkVec2_Scale(tau, s));
}

static double mkBoundary2_Size(mkVec2 a) { return fabs(a.x) + fabs(a.y); }


/* The normal at which the chord p_i p_j is split: the chord's outward
 * normal when it lies between the two normals (always, in exact
 * arithmetic), else the bisector. */
mkVec2 mkBoundary2_SplitNormal(mkVec2 ni, mkVec2 nj, mkVec2 pi, mkVec2 pj)
{
	mkVec2 d = mkVec2_Sub(pj, pi);
	mkVec2 m = mkVec2_NormalizeInline(mkVec2_Make(d.y, -d.x));
	if (!(mkVec2_Cross(ni, m) > 0.0 && mkVec2_Cross(m, nj) > 0.0))
		m = mkVec2_NormalizeInline(mkVec2_Add(ni, nj));
	return m;
}

/* The certified error of the arc between consecutive normals ni, nj (points
 * pi, pj), given the split normal m and its point xm = x(m). */
double mkBoundary2_EdgeError(mkBound bound, mkVec2 ni, mkVec2 nj, mkVec2 pi, mkVec2 pj, mkVec2 m, mkVec2 xm)
{
	double rnd = MK_CSPACE_ROUND_REL * (mkBoundary2_Size(pi) + mkBoundary2_Size(pj) + mkBoundary2_Size(xm));
	/* Proof 3: for normals u between ni and nj, h_K(u) minus the
	 * best of <u, pi>, <u, pj> is at most g3 = c / (4 cos(theta/2)) */
	double c = mkVec2_Dot(mkVec2_Sub(ni, nj), mkVec2_Sub(pi, pj));
	c = c > 0.0 ? c : 0.0;
	if (!(mkVec2_Cross(ni, nj) > 0.0)) return INFINITY + rnd; /* 180 degrees or more (or clockwise): nothing certified */
	double other = INFINITY; /* Proof 1 or 2, where it applies */
	if (!(mkVec2_Dot(ni, nj) >= 0.0)) {
		/* a step over 90 degrees: Proof 3 only */
	} else if (bound == MK_BOUND_INNER) {
		/* Proof 1: the chord gap h_K(m) - <m, p>, m the chord normal */
		mkVec2 d = mkVec2_Sub(pj, pi);
		mkVec2 chord = mkVec2_NormalizeInline(mkVec2_Make(d.y, -d.x));
		if (mkVec2_Dot(chord, m) == 1.0 || (chord.x == m.x && chord.y == m.y)) {
			double lo = fmin(mkVec2_Dot(m, pi), mkVec2_Dot(m, pj));
			other = mkVec2_Dot(m, xm) - lo;
			if (other < 0.0) other = 0.0;
		}
	} else {
		/* Proof 2: the tangent vertex's distance to conv{pi, x(m), pj} */
		mkVec2 v = mkBoundary2_TangentVertex(ni, pi, nj, pj);
		other = fmin(mkDistSegment2(v, pi, xm), mkDistSegment2(v, xm, pj));
	}
	/* the smaller of the two; g3 >= c / (4 (1 + 1e-9)) for unit normals, so
	 * g3 is only formed when the other bound might exceed it */
	if (other * (4.0 * (1.0 + 1e-9)) < c) return other + rnd;
	double g3 = c / (4.0 * (0.5 * mkVec2_LengthInline(mkVec2_Add(ni, nj))));
	return (other < g3 ? other : g3) + rnd;
}
