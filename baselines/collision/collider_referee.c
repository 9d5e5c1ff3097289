/* collider_referee.c - the referee: the signed distance of two placed
 * superquadrics with a bracket, from the closed-form support maps
 * (mkBody3_Support, verified against MPFR in the core's tests) and nothing
 * else of the core: no Newton solver, no Hessian.
 *
 * With D = B2 - B1 (Minkowski difference; a point of D is p2 - p1, p1 in B1,
 * p2 in B2) and, for a unit n, w(n) = S2(-n) - S1(n) (the point of D
 * farthest towards -n), every unit n gives the lower bound
 *     f(n) = <n, w(n)> = -(h1(n) + h2(-n)) <= sd,
 * and every point z = p2 - p1 of D (convex combinations of support points
 * included) gives, when the bodies are separated, the upper bound |z| >= sd.
 *
 * Separated pairs: Gilbert's algorithm (GJK's distance iteration) on D. It
 * keeps at most 4 points of D, takes z = the point of least norm of their
 * convex hull (every subset tried, the smallest valid one kept), adds
 * w(z/|z|), and stops when the bracket [max f, min |z|] is narrower than
 * 1e-14 of the scale or stops shrinking (no 1e-3 gain in 8 steps once within
 * 1e-11 of the scale, 40 before). Since D's faces and edges are met
 * by hulls of support points (nearly flat faces of superquadrics with
 * exponents near 0.1 included), it does not stall where a search over n on
 * the nearly kinked f does. When the bracket is still wide, a pattern search
 * with directions rotated at every step (8 directions in the tangent plane
 * and the ascent direction of f) raises the lower bound and GJK restarts
 * from its best normal (twice at most).
 *
 * Overlapping pairs: overlap is certified when the origin lies inside a
 * tetrahedron of points of D (all barycentric coordinates >= 1e-12; when GJK
 * meets the origin on a segment or triangle, as in symmetric placements,
 * with 12 more support points in general position). The
 * penetration depth has several local optima on the sphere; the referee
 * evaluates f on a 2000-point Fibonacci sphere, the centre line, the bodies'
 * face normals and GJK's last directions, and refines the best 6 apart from
 * each other by BFGS on f (gradient: the tangential part of w(n)), the
 * rotating pattern search and BFGS again; the answer is the best f found, a
 * certified lower bound of sd (an upper bound of the depth), but that no
 * deeper optimum was missed is not certified (gap NaN).
 *
 * Output: distance = the certified lower bound max f, bound = the same, gap
 * = the bracket width min |z| - max f (separated; NaN for overlaps),
 * residual = gap / scale (separated), 0 for a certified overlap and NaN for
 * an uncertified one (so a pair is decided with certainty iff residual <=
 * some width), normal = argmax f, p1/p2 = the body points of the
 * least |z| (convex combinations of support points; separated), or the
 * support points at the normal (overlaps), iterations = support-map pairs
 * evaluated. Status: max f under the touching band (mkContact_FromDistance);
 * MK_ERR_CONVERGENCE when no finite f was found. */
#include <float.h>
#include <math.h>

#include "colliders_internal.h"

#define MK_REF_TOL 1e-14         /* bracket target, times the scale */
#define MK_REF_GJK_ITER 2000     /* GJK iterations at most */
#define MK_REF_FIB 2000          /* overlap: directions of the global sweep */
#define MK_REF_STARTS 6          /* overlap: starts of the local search */
#define MK_REF_PATTERN_EVAL 3000 /* evaluations of one pattern search at most */
#define MK_REF_BFGS_EVAL 300     /* evaluations of one BFGS ascent at most */

typedef struct mkRefPoint {
	mkVec3 z, p1, p2; /* z = p2 - p1 */
} mkRefPoint;

typedef struct mkRefState {
	mkBody3 b1, b2;
	double lb;      /* max f found */
	mkVec3 lbn;     /* its normal */
	int evals;      /* support-map pairs */
} mkRefState;

/* w(n) and f(n) = <n, w(n)>; raises the lower bound. */
static double mkRefEval(mkRefState *st, mkVec3 n, mkRefPoint *out)
{
	mkRefPoint q;
	q.p1 = mkBody3_Support(st->b1, n);
	q.p2 = mkBody3_Support(st->b2, mkVec3_Neg(n));
	q.z = mkVec3_Sub(q.p2, q.p1);
	st->evals += 1;
	double f = mkVec3_Dot(n, q.p2) - mkVec3_Dot(n, q.p1);
	if (f > st->lb) {
		st->lb = f;
		st->lbn = n;
	}
	if (out)
		*out = q;
	return f;
}

/* Solve the k x k system M x = r (k <= 3) by Gaussian elimination with
 * partial pivoting; 0 when singular. */
static int mkSolve(double M[3][3], double r[3], int k, double x[3])
{
	for (int c = 0; c < k; ++c) {
		int p = c;
		for (int i = c + 1; i < k; ++i)
			if (fabs(M[i][c]) > fabs(M[p][c]))
				p = i;
		if (!(fabs(M[p][c]) > 0.0))
			return 0;
		if (p != c) {
			for (int j = 0; j < k; ++j) {
				double t = M[c][j];
				M[c][j] = M[p][j];
				M[p][j] = t;
			}
			double t = r[c];
			r[c] = r[p];
			r[p] = t;
		}
		for (int i = c + 1; i < k; ++i) {
			double m = M[i][c] / M[c][c];
			for (int j = c; j < k; ++j)
				M[i][j] -= m * M[c][j];
			r[i] -= m * r[c];
		}
	}
	for (int c = k - 1; c >= 0; --c) {
		double s = r[c];
		for (int j = c + 1; j < k; ++j)
			s -= M[c][j] * x[j];
		x[c] = s / M[c][c];
	}
	for (int c = 0; c < k; ++c)
		if (!isfinite(x[c]))
			return 0;
	return 1;
}

/* The point of least norm of the convex hull of y[0..n), n <= 4: every
 * nonempty subset whose affine least-norm point has barycentric coordinates
 * >= 0 is a candidate; the smallest |z| wins. Writes the coordinates lam
 * (0 outside the winning subset) and returns the winning subset's mask. */
static unsigned mkMinNorm(const mkRefPoint *y, int n, double lam[4])
{
	unsigned best_mask = 0;
	double best = INFINITY;
	int best_k = 5;
	for (unsigned mask = 1; mask < (1u << n); ++mask) {
		int idx[4], k = 0;
		for (int i = 0; i < n; ++i)
			if (mask & (1u << i))
				idx[k++] = i;
		double l[4] = { 1.0, 0.0, 0.0, 0.0 };
		if (k > 1) {
			/* z = y0 + sum mu_j (y_j - y0), E^T E mu = -E^T y0. */
			mkVec3 e[3];
			for (int j = 1; j < k; ++j)
				e[j - 1] = mkVec3_Sub(y[idx[j]].z, y[idx[0]].z);
			double M[3][3], r[3], mu[3];
			for (int a = 0; a < k - 1; ++a) {
				for (int b = 0; b < k - 1; ++b)
					M[a][b] = mkVec3_Dot(e[a], e[b]);
				r[a] = -mkVec3_Dot(e[a], y[idx[0]].z);
			}
			if (!mkSolve(M, r, k - 1, mu))
				continue;
			l[0] = 1.0;
			for (int j = 1; j < k; ++j) {
				l[j] = mu[j - 1];
				l[0] -= mu[j - 1];
			}
		}
		int ok = 1;
		for (int j = 0; j < k; ++j)
			ok &= l[j] >= 0.0;
		if (!ok)
			continue;
		mkVec3 z = mkVec3_Make(0, 0, 0);
		for (int j = 0; j < k; ++j)
			z = mkVec3_Add(z, mkVec3_Scale(y[idx[j]].z, l[j]));
		double nz = mkVec3_Length(z);
		/* Prefer the smaller subset on ties (rounding). */
		if (nz < best * (1.0 - 1e-15) || (nz <= best && k < best_k)) {
			best = nz;
			best_k = k;
			best_mask = mask;
			for (int i = 0; i < 4; ++i)
				lam[i] = 0.0;
			for (int j = 0; j < k; ++j)
				lam[idx[j]] = l[j];
		}
	}
	return best_mask;
}

/* A unit vector orthogonal to unit n. */
static mkVec3 mkRefOrtho(mkVec3 n)
{
	mkVec3 a = fabs(n.x) < 0.6 ? mkVec3_Make(1, 0, 0) : mkVec3_Make(0, 1, 0);
	return mkVec3_Normalize(mkVec3_Cross(n, a));
}

/* Pattern search for max f from n with initial step `step` (radians), at
 * most `budget` evaluations: 8 directions in the tangent plane, turned by
 * the golden angle at every step, and first the ascent direction (f's
 * gradient on the sphere is the tangential part of w(n)); a step that raises
 * f is taken and doubles (up to the initial step), otherwise the step halves,
 * down to 1e-15 rad. Returns the best f of this search; n is moved to its
 * normal. */
static double mkRefPattern(mkRefState *st, mkVec3 *n, double step, int budget)
{
	mkRefPoint q;
	double best = mkRefEval(st, *n, &q), init = step, turn = 0.0;
	int evals = 1;
	while (step > 1e-15 && evals < budget) {
		mkVec3 t1 = mkRefOrtho(*n), t2 = mkVec3_Cross(*n, t1);
		/* The ascent direction: the tangential part of w(n). */
		mkVec3 g = mkVec3_Sub(q.z, mkVec3_Scale(*n, mkVec3_Dot(q.z, *n)));
		double gl = mkVec3_Length(g);
		int moved = 0;
		for (int k = -1; k < 8 && !moved; ++k) {
			mkVec3 t;
			if (k < 0) {
				if (!(gl > 0.0))
					continue;
				t = mkVec3_Scale(g, 1.0 / gl);
			} else {
				double a = turn + MK_PI * k / 4.0;
				t = mkVec3_Add(mkVec3_Scale(t1, cos(a)), mkVec3_Scale(t2, sin(a)));
			}
			mkVec3 c = mkVec3_Normalize(mkVec3_Add(*n, mkVec3_Scale(t, step)));
			mkRefPoint qc;
			double v = mkRefEval(st, c, &qc);
			evals += 1;
			if (v > best) {
				best = v;
				*n = c;
				q = qc;
				moved = 1;
			}
		}
		turn += 2.399963229728653; /* the golden angle */
		step = moved ? fmin(2.0 * step, init) : 0.5 * step;
	}
	return best;
}

/* f and its gradient in the chart n(u) = normalize(n0 + u1 t1 + u2 t2):
 * with v = n0 + U u and n = v / |v|, d f / d u = U^T (w(n) - f n) / |v|
 * (Danskin: the gradient of <v, w(v)> is w(v)). */
static double mkRefChart(mkRefState *st, mkVec3 n0, mkVec3 t1, mkVec3 t2, const double u[2], double g[2], mkVec3 *n)
{
	mkVec3 v = mkVec3_Add(n0, mkVec3_Add(mkVec3_Scale(t1, u[0]), mkVec3_Scale(t2, u[1])));
	double vl = mkVec3_Length(v);
	*n = mkVec3_Scale(v, 1.0 / vl);
	mkRefPoint q;
	double f = mkRefEval(st, *n, &q);
	mkVec3 r = mkVec3_Scale(mkVec3_Sub(q.z, mkVec3_Scale(*n, f)), 1.0 / vl);
	g[0] = mkVec3_Dot(t1, r);
	g[1] = mkVec3_Dot(t2, r);
	return f;
}

/* BFGS ascent of f in the chart around *n (Armijo backtracking; the chart
 * is recentred when |u| > 0.3); at most `budget` evaluations. Moves *n to
 * the best normal and returns its f. Only raises the lower bound: every
 * value it keeps is an evaluated f. */
static double mkRefBfgs(mkRefState *st, mkVec3 *n, int budget)
{
	int evals = 0;
	while (evals < budget) {
		mkVec3 n0 = *n, t1 = mkRefOrtho(n0), t2 = mkVec3_Cross(n0, t1), nn;
		double u[2] = { 0.0, 0.0 }, g[2], H[2][2] = { { 0.0, 0.0 }, { 0.0, 0.0 } };
		double f = mkRefChart(st, n0, t1, t2, u, g, &nn);
		++evals;
		double gl = hypot(g[0], g[1]);
		if (!(gl > 0.0))
			return f;
		/* First step 1e-3 rad along the gradient. */
		H[0][0] = H[1][1] = 1e-3 / gl;
		int recentre = 0;
		while (evals < budget && !recentre) {
			double p[2] = { H[0][0] * g[0] + H[0][1] * g[1], H[1][0] * g[0] + H[1][1] * g[1] };
			double slope = p[0] * g[0] + p[1] * g[1];
			if (!(slope > 0.0)) {
				H[0][0] = H[1][1] = 1e-3 / hypot(g[0], g[1]);
				H[0][1] = H[1][0] = 0.0;
				p[0] = H[0][0] * g[0];
				p[1] = H[1][1] * g[1];
				slope = p[0] * g[0] + p[1] * g[1];
				if (!(slope > 0.0))
					return f;
			}
			double a = 1.0, un[2], gn[2], fn = -INFINITY;
			int ok = 0;
			while (evals < budget && a * hypot(p[0], p[1]) > 1e-17) {
				un[0] = u[0] + a * p[0];
				un[1] = u[1] + a * p[1];
				fn = mkRefChart(st, n0, t1, t2, un, gn, &nn);
				++evals;
				if (fn >= f + 1e-4 * a * slope && fn > f) {
					ok = 1;
					break;
				}
				a *= 0.5;
			}
			if (!ok) {
				*n = st->lbn;
				return st->lb;
			}
			double sv[2] = { un[0] - u[0], un[1] - u[1] }, yv[2] = { g[0] - gn[0], g[1] - gn[1] };
			double sy = sv[0] * yv[0] + sv[1] * yv[1];
			if (sy > 0.0) {
				/* H <- (I - r s y^T) H (I - r y s^T) + r s s^T, r = 1 / s^T y. */
				double r = 1.0 / sy, A[2][2], B[2][2];
				for (int i = 0; i < 2; ++i)
					for (int j = 0; j < 2; ++j)
						A[i][j] = (i == j) - r * sv[i] * yv[j];
				for (int i = 0; i < 2; ++i)
					for (int j = 0; j < 2; ++j)
						B[i][j] = A[i][0] * H[0][j] + A[i][1] * H[1][j];
				for (int i = 0; i < 2; ++i)
					for (int j = 0; j < 2; ++j)
						H[i][j] = B[i][0] * A[j][0] + B[i][1] * A[j][1] + r * sv[i] * sv[j];
			}
			u[0] = un[0];
			u[1] = un[1];
			g[0] = gn[0];
			g[1] = gn[1];
			f = fn;
			*n = nn;
			recentre = hypot(u[0], u[1]) > 0.3;
		}
	}
	*n = st->lbn;
	return st->lb;
}

/* 1 when the origin lies inside a tetrahedron of the points y[0..n) with
 * every barycentric coordinate >= 1e-12 (all 4-subsets tried): then a ball
 * around the origin lies in D, so the bodies overlap. */
static int mkRefEncloses(const mkVec3 *y, int n)
{
	for (int a = 0; a < n; ++a)
		for (int b = a + 1; b < n; ++b)
			for (int c = b + 1; c < n; ++c)
				for (int d = c + 1; d < n; ++d) {
					/* -y_a = sum_j mu_j (y_j - y_a), j in b, c, d. */
					mkVec3 e1 = mkVec3_Sub(y[b], y[a]), e2 = mkVec3_Sub(y[c], y[a]), e3 = mkVec3_Sub(y[d], y[a]);
					double M[3][3] = { { e1.x, e2.x, e3.x }, { e1.y, e2.y, e3.y }, { e1.z, e2.z, e3.z } };
					double r[3] = { -y[a].x, -y[a].y, -y[a].z }, mu[3];
					if (!mkSolve(M, r, 3, mu))
						continue;
					double l0 = 1.0 - mu[0] - mu[1] - mu[2];
					if (fmin(fmin(l0, mu[0]), fmin(mu[1], mu[2])) >= 1e-12)
						return 1;
				}
	return 0;
}

/* Overlap certificate when GJK met the origin on a segment or triangle (or
 * at a point) of its hull, as happens for pairs placed symmetrically along
 * an axis: the kept points and the points of D towards 12 directions in
 * general position (an icosahedron turned by a fixed rotation). */
static int mkRefEncloseGeneric(mkRefState *st, const mkVec3 *kept, int m)
{
	static const double ico[6][3] = { { 0, 1, 1.618033988749895 }, { 0, -1, 1.618033988749895 },
		{ 1, 1.618033988749895, 0 }, { -1, 1.618033988749895, 0 }, { 1.618033988749895, 0, 1 },
		{ -1.618033988749895, 0, 1 } };
	mkVec3 y[16];
	int n = 0;
	for (int i = 0; i < m; ++i)
		y[n++] = kept[i];
	mkMat3 R = mkMat3_FromQuat(0.9, 0.31, -0.22, 0.17);
	for (int i = 0; i < 12; ++i) {
		mkVec3 v = mkVec3_Make(ico[i % 6][0], ico[i % 6][1], ico[i % 6][2]);
		v = mkVec3_Normalize(mkMat3_MulVec(R, i < 6 ? v : mkVec3_Neg(v)));
		mkRefPoint q;
		mkRefEval(st, v, &q);
		y[n++] = q.z;
	}
	return mkRefEncloses(y, n);
}

/* GJK on D from the unit direction n0. Fills the least |z| found (ub, its
 * body points) and returns 1 when the origin was enclosed (overlap
 * certified), 0 otherwise. */
static int mkRefGjk(mkRefState *st, mkVec3 n0, double scale, double *ub, mkVec3 *p1, mkVec3 *p2, mkVec3 *nlast)
{
	mkRefPoint y[5];
	int n = 1;
	mkRefEval(st, n0, &y[0]);
	*ub = INFINITY;
	*nlast = n0;
	double prev_bracket = INFINITY;
	int stall = 0;
	for (int it = 0; it < MK_REF_GJK_ITER; ++it) {
		double lam[4];
		unsigned mask = mkMinNorm(y, n, lam);
		if (!mask)
			break;
		mkRefPoint keep[4];
		int m = 0;
		double lk[4];
		mkVec3 a = mkVec3_Make(0, 0, 0), b = mkVec3_Make(0, 0, 0);
		for (int i = 0; i < n; ++i)
			if (mask & (1u << i)) {
				keep[m] = y[i];
				lk[m++] = lam[i];
				a = mkVec3_Add(a, mkVec3_Scale(y[i].p1, lam[i]));
				b = mkVec3_Add(b, mkVec3_Scale(y[i].p2, lam[i]));
			}
		if (m == 4) {
			double lmin = fmin(fmin(lk[0], lk[1]), fmin(lk[2], lk[3]));
			if (lmin >= 1e-12)
				return 1;
		}
		mkVec3 z = mkVec3_Sub(b, a);
		double nz = mkVec3_Length(z);
		if (nz < *ub) {
			*ub = nz;
			*p1 = a;
			*p2 = b;
		}
		for (int i = 0; i < m; ++i)
			y[i] = keep[i];
		n = m;
		if (!(nz > 1e-15 * scale) || m == 4) {
			/* The origin on a segment or triangle of the hull (or a
			 * flat tetrahedron): D holds it; certify a ball around it. */
			mkVec3 kz[4];
			for (int i = 0; i < m; ++i)
				kz[i] = y[i].z;
			return mkRefEncloseGeneric(st, kz, m);
		}
		/* The direction: for a triangle, its plane's normal (accurate when
		 * the triangle is wide and z small); else z / |z|. */
		mkVec3 dir = mkVec3_Scale(z, 1.0 / nz);
		if (m == 3) {
			mkVec3 c = mkVec3_Cross(mkVec3_Sub(y[1].z, y[0].z), mkVec3_Sub(y[2].z, y[0].z));
			double cl = mkVec3_Length(c);
			if (cl > 0.0) {
				c = mkVec3_Scale(c, 1.0 / cl);
				dir = mkVec3_Dot(c, dir) >= 0.0 ? c : mkVec3_Neg(c);
			}
		}
		*nlast = dir;
		mkRefPoint w;
		mkRefEval(st, dir, &w);
		double bracket = *ub - st->lb;
		if (bracket <= MK_REF_TOL * scale)
			break;
		if (bracket >= prev_bracket * (1.0 - 1e-3)) {
			/* Stalled: 8 steps without a 1e-3 gain once the bracket is
			 * within 1e-11 of the scale (rounding), 40 before (slow
			 * progress on needles and plates, aspect ratios ~1e5). */
			if (++stall >= (bracket <= 1e-11 * scale ? 8 : 40))
				break;
		} else {
			stall = 0;
		}
		prev_bracket = fmin(prev_bracket, bracket);
		/* w duplicates a kept point: no progress possible. */
		int dup = 0;
		for (int i = 0; i < n; ++i)
			dup |= y[i].z.x == w.z.x && y[i].z.y == w.z.y && y[i].z.z == w.z.z;
		if (dup)
			break;
		y[n++] = w;
	}
	return 0;
}

/* Fibonacci sphere point i of count. */
static mkVec3 mkRefFib(int i, int count)
{
	double z = 1.0 - (2.0 * i + 1.0) / count, r = sqrt(fmax(0.0, 1.0 - z * z));
	double phi = 2.399963229728653 * i;
	return mkVec3_Make(r * cos(phi), r * sin(phi), z);
}

/* The depth of an overlap (or the distance of a pair GJK could not
 * certify): a global sweep over a Fibonacci sphere, the bodies' face
 * normals, the centre line and the normals met so far, then BFGS and the
 * pattern search from the best MK_REF_STARTS starts apart; raises st->lb. */
static void mkRefDepth(mkRefState *st, mkVec3 n0, mkVec3 nlast)
{
	enum { CAND = MK_REF_FIB + 12 };
	mkVec3 bn[MK_REF_STARTS];
	double bv[MK_REF_STARTS];
	int nb = 0;
	for (int i = 0; i < CAND; ++i) {
		mkVec3 n;
		if (i < MK_REF_FIB) {
			n = mkRefFib(i, MK_REF_FIB);
		} else if (i < MK_REF_FIB + 6) {
			const mkBody3 *b = i < MK_REF_FIB + 3 ? &st->b1 : &st->b2;
			int k = (i - MK_REF_FIB) % 3;
			/* The body's axis k: the normal of its face k is M^-T e_k. */
			mkMat3 Mi = mkMat3_Inverse(b->M);
			n = mkVec3_Normalize(mkVec3_Make(Mi.m[k][0], Mi.m[k][1], Mi.m[k][2]));
		} else if (i == MK_REF_FIB + 6) {
			n = n0;
		} else if (i == MK_REF_FIB + 7) {
			n = mkVec3_Neg(n0);
		} else if (i == MK_REF_FIB + 8) {
			n = nlast;
		} else {
			n = st->lbn;
		}
		if (!(mkVec3_Length(n) > 0.0) || !isfinite(n.x + n.y + n.z))
			continue;
		double v = mkRefEval(st, n, NULL);
		/* Keep the best MK_REF_STARTS that are apart (angle > 0.05). */
		int near = -1;
		for (int k = 0; k < nb; ++k)
			if (mkVec3_Dot(bn[k], n) > cos(0.05))
				near = k;
		if (near >= 0) {
			if (v > bv[near]) {
				bv[near] = v;
				bn[near] = n;
			}
			continue;
		}
		if (nb < MK_REF_STARTS) {
			bv[nb] = v;
			bn[nb++] = n;
		} else {
			int w = 0;
			for (int k = 1; k < nb; ++k)
				if (bv[k] < bv[w])
					w = k;
			if (v > bv[w]) {
				bv[w] = v;
				bn[w] = n;
			}
		}
	}
	for (int k = 0; k < nb; ++k) {
		/* BFGS, then the pattern search where BFGS stalls (near
		 * kinks), then BFGS again; each keeps the best f of this start. */
		mkRefState one = *st;
		one.lb = -INFINITY;
		mkVec3 n = bn[k];
		mkRefBfgs(&one, &n, MK_REF_BFGS_EVAL);
		n = one.lbn;
		mkRefPattern(&one, &n, 1e-3, MK_REF_PATTERN_EVAL);
		n = one.lbn;
		mkRefBfgs(&one, &n, MK_REF_BFGS_EVAL);
		st->evals = one.evals;
		if (one.lb > st->lb) {
			st->lb = one.lb;
			st->lbn = one.lbn;
		}
	}
}

static mkResult mkRun(mkBody3 b1, mkBody3 b2, mkColliderScratch *s, mkCollision3 *out)
{
	(void)s;
	mkRefState st = { b1, b2, -INFINITY, mkVec3_Make(1, 0, 0), 0 };
	double scale = mkCollide3_PairSize(b1, b2);
	out->scale = scale;
	if (!isfinite(scale))
		return MK_ERR_UNSUPPORTED;
	mkVec3 d = mkVec3_Sub(b2.t, b1.t);
	double dl = mkVec3_Length(d);
	mkVec3 n0 = dl > 0.0 ? mkVec3_Scale(d, 1.0 / dl) : mkVec3_Make(1, 0, 0);
	double ub = INFINITY;
	mkVec3 p1 = b1.t, p2 = b2.t, nlast = n0;
	int inside = mkRefGjk(&st, n0, scale, &ub, &p1, &p2, &nlast);
	if (!inside && st.lb > 0.0 && ub - st.lb > MK_REF_TOL * scale) {
		/* Raise the lower bound by the pattern search, then give GJK the
		 * better normal; twice at most. */
		for (int round = 0; round < 2 && ub - st.lb > MK_REF_TOL * scale; ++round) {
			mkVec3 n = st.lbn;
			double step = fmin(0.1, fmax(1e-12, 10.0 * (ub - st.lb) / fmax(st.lb, 1e-300)));
			mkRefPattern(&st, &n, step, MK_REF_PATTERN_EVAL);
			double ub2;
			mkVec3 q1, q2, nl2;
			mkRefGjk(&st, st.lbn, scale, &ub2, &q1, &q2, &nl2);
			if (ub2 < ub) {
				ub = ub2;
				p1 = q1;
				p2 = q2;
			}
		}
	}
	if (!inside && st.lb <= 0.0) {
		/* Not certified separated, not enclosed: try the origin test again
		 * from the other directions met (touching or a hull on the origin). */
		inside = mkRefGjk(&st, mkVec3_Neg(nlast), scale, &ub, &p1, &p2, &nlast);
	}
	if (inside || st.lb <= 0.0) {
		/* The depth: global sweep, then local searches from the best starts. */
		mkRefDepth(&st, n0, nlast);
		p1 = mkBody3_Support(b1, st.lbn);
		p2 = mkBody3_Support(b2, mkVec3_Neg(st.lbn));
	}
	if (!isfinite(st.lb)) {
		out->status = MK_CONTACT_UNKNOWN;
		return MK_ERR_CONVERGENCE;
	}
	out->distance = st.lb;
	out->bound = st.lb;
	out->normal = st.lbn;
	out->p1 = p1;
	out->p2 = p2;
	out->iterations = st.evals;
	if (st.lb > 0.0) {
		out->gap = fmax(0.0, ub - st.lb);
		out->residual = out->gap / scale;
	} else {
		/* No two-sided bound of the depth; residual 0 says the overlap itself
		 * is certified (origin enclosed), NaN that it is not. */
		out->gap = NAN;
		out->residual = inside ? 0.0 : NAN;
	}
	out->status = mkContact_FromDistance(st.lb, scale);
	return MK_OK;
}

const mkCollider mkCollider_Referee = {
	"referee", "Referee: sd bracketed by GJK on B2 - B1 (upper) and max of <n, w(n)> (lower); support maps only",
	"separated: Gilbert/GJK distance on B2 - B1 with exact least-norm subsets, lower bound max f(n) at its directions, "
	"until the bracket is below 1e-14 of the scale or stalls (8 steps without a 1e-3 gain below 1e-11, 40 above; 2000 at most), then rotating pattern search (8 directions + "
	"ascent, <= 3000 evaluations, 2 rounds) and GJK again; overlap certified by a tetrahedron of support points "
	"around the origin (barycentric >= 1e-12); depth: 2000-point Fibonacci sweep + centre line + body axes, pattern "
	"search from the best 6 starts apart by 0.05 rad; distance = certified lower bound, gap = bracket (separated)",
	MK_GIVES_STATUS | MK_GIVES_DISTANCE | MK_GIVES_PENETRATION | MK_GIVES_WITNESS,
	MK_PAIRS_ELLIPSOIDS | MK_PAIRS_SUPERQUADRICS, 1, NULL, mkRun, NULL
};
