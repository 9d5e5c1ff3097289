/* ray.c - mink/collision.h: MinkSum (Ray), the boundary of the
 * contact space on the centre line by a trust-region Newton method on the
 * closed-form support map (pair.h, steps.h). */
#include "collide/pair.h"
#include "collide/steps.h"

/* ---- MinkSum (Ray) ------------------------------------------------------ */

/* psi(s) = H(u + s1 t1 + s2 t2) and its pieces at s. */
typedef struct mkRayState {
	double s[2], H, g[2];
	mkVec3 m;
	mkPairAt e;      /* supports at m and -m, x = e.x */
} mkRayState;

/* The frame of the ray, and the contact-space points seen so far (a ring):
 * every one is a point of K, the material of the lower bound. */
enum { MK_RAY_KEEP = 24 };
typedef struct mkRayFrame {
	mkVec3 u, t1, t2;
	double p[MK_RAY_KEEP][2], r[MK_RAY_KEEP]; /* tangential coordinates, radial part */
	int count;
} mkRayFrame;

static void mkRay_Keep(mkRayFrame *f, mkVec3 x)
{
	int k = f->count++ % MK_RAY_KEEP;
	f->p[k][0] = mkVec3_Dot(f->t1, x);
	f->p[k][1] = mkVec3_Dot(f->t2, x);
	f->r[k] = mkVec3_Dot(f->u, x);
}

/* A lower bound of the boundary distance psi* along u: a convex combination
 * of three kept points of K whose tangential parts surround 0 lies on the
 * ray, at t = sum w_i r_i, so t u is in K and psi* >= t. -inf when no kept
 * triangle surrounds 0. */
static double mkRay_Lower(const mkRayFrame *f)
{
	int n = f->count < MK_RAY_KEEP ? f->count : MK_RAY_KEEP;
	double best = -INFINITY;
	for (int i = 0; i < n; ++i)
		for (int j = i + 1; j < n; ++j)
			for (int k = j + 1; k < n; ++k) {
				const double *a = f->p[i], *b = f->p[j], *c = f->p[k];
				double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
				if (det == 0.0)
					continue;
				/* barycentric weights of the origin */
				double wb = ((-a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (-a[1])) / det;
				double wc = ((b[0] - a[0]) * (-a[1]) - (-a[0]) * (b[1] - a[1])) / det;
				double wa = 1.0 - wb - wc;
				if (wa < 0.0 || wb < 0.0 || wc < 0.0)
					continue;
				double t = wa * f->r[i] + wb * f->r[j] + wc * f->r[k];
				if (t > best)
					best = t;
			}
	return best;
}

static mkVec3 mkRay_Point(const mkRayFrame *f, const double s[2])
{
	return mkVec3_Add(f->u, mkVec3_Add(mkVec3_Scale(f->t1, s[0]), mkVec3_Scale(f->t2, s[1])));
}

static void mkRay_Eval(const mkPairCtx *c, mkRayFrame *f, const double s[2], mkRayState *st)
{
	st->s[0] = s[0];
	st->s[1] = s[1];
	st->m = mkRay_Point(f, s);
	st->H = mkPair_Eval(c, st->m, &st->e);
	mkRay_Keep(f, st->e.x);
	/* Gradient of -psi (the solver maximises -psi). */
	st->g[0] = -mkVec3_Dot(f->t1, st->e.x);
	st->g[1] = -mkVec3_Dot(f->t2, st->e.x);
}

static double mkRay_Value(const mkPairCtx *c, mkRayFrame *f, const double s[2])
{
	mkPairAt e;
	double H = mkPair_Eval(c, mkRay_Point(f, s), &e);
	mkRay_Keep(f, e.x);
	return H;
}

/* -psi along s + t e (e a unit vector of the plane), concave in t: the
 * value and the derivative -<e, x> (e in 3D); every probe's contact-space
 * point is kept for the lower bound, and the best probe's supports. */
typedef struct mkRayLine {
	const mkPairCtx *c;
	mkRayFrame *f;
	double base[2], e[2];
	mkVec3 ew;
	double best, sbest;
	mkPairAt at;
} mkRayLine;

static void mkRay_LineAt(void *p, double t, double *v, double *dv)
{
	mkRayLine *L = p;
	double s[2] = { L->base[0] + t * L->e[0], L->base[1] + t * L->e[1] };
	mkPairAt pe;
	double H = mkPair_Eval(L->c, mkRay_Point(L->f, s), &pe);
	mkRay_Keep(L->f, pe.x);
	*v = -H;
	*dv = -mkVec3_Dot(L->ew, pe.x);
	if (*v > L->best) {
		L->best = *v;
		L->sbest = t;
		L->at = pe;
	}
}

/* Minimise psi exactly along s + t e (mkLine_Max on -psi); st moves to the
 * best point found. Returns 1 when the search converged. */
static int mkRay_LineSearch(const mkPairCtx *c, mkRayFrame *f, mkRayState *st, const double e0[2], double h)
{
	mkRayLine L;
	L.c = c;
	L.f = f;
	L.base[0] = st->s[0];
	L.base[1] = st->s[1];
	L.e[0] = e0[0];
	L.e[1] = e0[1];
	L.ew = mkVec3_Add(mkVec3_Scale(f->t1, e0[0]), mkVec3_Scale(f->t2, e0[1]));
	double slope = -mkVec3_Dot(L.ew, st->e.x);
	if (slope == 0.0)
		return 1;
	if (slope < 0.0) {
		L.e[0] = -L.e[0];
		L.e[1] = -L.e[1];
		L.ew = mkVec3_Neg(L.ew);
		slope = -slope;
	}
	L.best = -st->H;
	int done = mkLine_Max(mkRay_LineAt, &L, h, -st->H, slope, c->scale);
	if (L.best > -st->H) {
		st->s[0] = L.base[0] + L.sbest * L.e[0];
		st->s[1] = L.base[1] + L.sbest * L.e[1];
		st->m = mkRay_Point(f, st->s);
		st->e = L.at;
		st->H = -L.best;
		st->g[0] = -mkVec3_Dot(f->t1, st->e.x);
		st->g[1] = -mkVec3_Dot(f->t2, st->e.x);
	}
	return done;
}

mkResult mkCollide3_Ray(mkBody3 b1, mkBody3 b2, mkCollision3 *out)
{
	mkCollision3_Clear(out);
	mkPairCtx c;
	if (mkPairCtx_Begin(&c, &b1, &b2, out) != MK_OK)
		return MK_ERR_UNSUPPORTED;
	double dl = mkVec3_LengthInline(c.d);
	out->restarts = 0;
	if (dl == 0.0) {
		/* Coincident centres: both bodies contain the point. */
		out->status = MK_CONTACT_OVERLAPPING;
		out->residual = 0.0;
		out->iterations = 0;
		return MK_OK;
	}
	mkRayFrame fr;
	fr.count = 0;
	fr.u = mkVec3_Scale(c.d, 1.0 / dl);
	mkTangents(fr.u, &fr.t1, &fr.t2);
	/* psi(s) = H(u + s t): convex in s in R^2, gradient the tangential part
	 * of x(u + s t), Hessian t^T J t (J homogeneous of degree -1 in m).
	 * The trust region maximises -psi. */
	double zero[2] = { 0.0, 0.0 };
	mkRayState st;
	mkRay_Eval(&c, &fr, zero, &st);
	double radius = MK_TR_INIT, tol = MK_COLLIDE3_RESIDUAL_TOL * c.scale;
	double res = NAN;
	int ok = 0, iters = 0, rejects = 0;
	double hist[3] = { INFINITY, INFINITY, INFINITY };
	for (int it = 0; it < MK_COLLIDE3_MAX_ITER && !ok; ++it) {
		hist[it % 3] = st.H;
		res = mkLen2(st.g[0], st.g[1]);
		if (res <= tol) {
			ok = 1;
			break;
		}
		iters += 1;
		double A[2][2];
		mkPair_Tangent(&c, &st.e, fr.t1, fr.t2, A);
		double step[2];
		double sn = mkLen2(st.s[0], st.s[1]);
		double pred = mkTrustStep(st.g, A, radius * (1.0 + sn), step);
		double slen = mkLen2(step[0], step[1]);
		if (slen < radius * (1.0 + sn) && (slen <= 1e-14 * (1.0 + sn) || pred <= 1e-17 * c.scale)) {
			ok = 1;
			break;
		}
		double s_new[2] = { st.s[0] + step[0], st.s[1] + step[1] };
		mkRayState trial;
		mkRay_Eval(&c, &fr, s_new, &trial);
		double gain = st.H - trial.H;
		double noise = 64.0 * DBL_EPSILON * (fabs(st.H) + c.scale);
		double rho = pred > noise ? gain / pred : (gain >= -noise ? 1.0 : -1.0);
		double rel = slen / (1.0 + sn);
		if (rho < 0.25)
			radius = 0.25 * rel;
		else if (rho > 0.75 && rel > 0.99 * radius)
			radius = fmin(2.0 * radius, MK_TR_MAX);
		if (rho > 1e-4) {
			st = trial;
			rejects = rho < 0.25 ? rejects + 1 : 0;
		} else {
			rejects += 1;
		}
		if (rejects >= 2 || radius < 1e-12 || (it >= MK_LINE_AFTER && rho < 0.75)) {
			double lam[2], v0[2], v1[2];
			mkPair_Tangent(&c, &st.e, fr.t1, fr.t2, A);
			mkEig2(A, lam, v0, v1);
			double before = st.H;
			int tight = mkRay_LineSearch(&c, &fr, &st, v1, fmax(radius, 1e-6) * (1.0 + sn));
			int moved = st.H < before;
			mkPair_Tangent(&c, &st.e, fr.t1, fr.t2, A);
			mkEig2(A, lam, v0, v1);
			double flat = fabs(v0[0] * st.g[0] + v0[1] * st.g[1]);
			double oldest = fmax(hist[0], fmax(hist[1], hist[2]));
			if (tight && (flat <= tol || (oldest - st.H <= 1e-13 * c.scale && radius < 1e-10))) {
				res = flat <= tol ? flat : mkLen2(st.g[0], st.g[1]);
				ok = 1;
				break;
			}
			rejects = 0;
			if (moved)
				radius = fmax(radius, 1e-3);
		}
	}
	out->iterations = iters;
	mkVec3 n = mkVec3_NormalizeInline(st.m);
	out->normal = n;
	out->p1 = mkVec3_Add(b1.t, st.e.a1.s);
	out->p2 = mkVec3_Add(b2.t, st.e.a2.s);
	out->residual = res / c.scale;
	/* H = |m| (h1(n) + h2(-n)); f(n) = <n, d> - H / |m|. */
	double ml = mkVec3_LengthInline(st.m);
	out->bound = mkVec3_Dot(n, c.d) - st.H / ml;
	if (!isfinite(st.H) || !mkIsFinite3(out->p1) || !mkIsFinite3(out->p2))
		return MK_ERR_CONVERGENCE;
	if (!ok) {
		/* Not converged (a support function nearly kinked along a curve,
		 * where the iterates zigzag): the status may still be certain.
		 * H >= psi* always, and a kept triangle gives psi* >= lower. */
		/* Probes around the last iterate in three directions, at two radii,
		 * so that some kept points surround the ray. */
		for (int k = 0; k < 6; ++k) {
			double ang = 2.0 * MK_PI * (k % 3) / 3.0, rad = k < 3 ? 1e-2 : 0.3;
			double sp[2] = { st.s[0] + rad * cos(ang), st.s[1] + rad * sin(ang) };
			mkRay_Value(&c, &fr, sp);
		}
		double lower = mkRay_Lower(&fr);
		double band = MK_COLLIDE3_TOUCH_TOL * c.scale;
		if (st.H < dl - band || lower > dl + band) {
			out->directional = dl - st.H;
			out->residual = (st.H - lower) / c.scale; /* the bracket of psi*, relative */
			out->status = st.H < dl - band ? MK_CONTACT_SEPARATED : MK_CONTACT_OVERLAPPING;
			return MK_OK;
		}
		return MK_ERR_CONVERGENCE;
	}
	/* The minimum of psi is the distance from c1 to the boundary of the
	 * contact space along u. */
	out->directional = dl - st.H;
	out->status = mkContact_FromDistance(out->directional, c.scale);
	return MK_OK;
}
