/* collide.c - the collision queries of mink/collide.h except ASC (asc.cpp).
 *
 * The three Levenberg-Marquardt queries share one driver around cminpack's
 * lmder. Their Jacobians are central differences in the angles with step
 * MK_LM_FD_STEP: the residuals are smooth in the angles away from the
 * poles, and a central difference has truncation error O(h^2 |F'''|),
 * about 1e-12 relative here, with a rounding error of about eps |F| / h,
 * 1e-10 relative: far below the changes LM needs to converge (the
 * residual itself is driven to zero, the Jacobian only steers). */
#include <mink/collide.h>

#include <ccd/ccd.h>
#include <ccd/vec3.h>
#include <cminpack.h>
#include <IpStdCInterface.h>

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#define MK_LM_FD_STEP 1e-6
/* Relative tolerances of lmder on the residual and the step: a few ulps,
 * so that LM stops on the residual criterion or the iteration limit, not
 * earlier. */
#define MK_LM_TOL 1e-15

static mkVec3 mkNaN3(void) { return mkVec3_Make(NAN, NAN, NAN); }

static mkCollide mkCollide_Empty(void)
{
	mkCollide c;
	c.collide = -1;
	c.residual = NAN;
	c.iterations = -1;
	c.status = -1;
	c.p1 = c.p2 = c.x = mkNaN3();
	return c;
}

mkVec3 mkCollide_AnglesToUnit(double eta, double omega)
{
	double ce = cos(eta);
	return mkVec3_Make(ce * cos(omega), ce * sin(omega), sin(eta));
}

void mkCollide_UnitToAngles(mkVec3 v, double *eta, double *omega)
{
	*eta = atan2(v.z, hypot(v.x, v.y));
	*omega = atan2(v.y, v.x);
}

/* The world unit outward normal of a placed body at its surface parameter u. */
static mkVec3 mkBodyNormal(mkBody3 b, mkMat3 Minv, mkVec3 u)
{
	return mkVec3_Normalize(mkMat3_MulTVec(Minv, mkShape3_PointGradient(b.shape, u)));
}

/* ---- Levenberg-Marquardt through lmder ----------------------------------- */

typedef void (*mkResidualFn)(const void *ctx, const double *x, double *f);

typedef struct mkLm {
	mkResidualFn fn;
	const void *ctx;
	int m, n;
	int jacobians;
	int max_iter;
} mkLm;

static int mkLm_Callback(void *p, int m, int n, const double *x, double *fvec, double *fjac,
	int ldfjac, int iflag)
{
	mkLm *lm = p;
	if (iflag == 1) {
		lm->fn(lm->ctx, x, fvec);
		return 0;
	}
	if (iflag != 2)
		return 0;
	/* One Jacobian per LM iteration: stop before the (max_iter + 1)-st. */
	if (lm->jacobians >= lm->max_iter)
		return -1;
	lm->jacobians += 1;
	double xs[8], fp[8], fm[8];
	assert(n <= 8 && m <= 8);
	memcpy(xs, x, (size_t)n * sizeof(double));
	for (int j = 0; j < n; ++j) {
		xs[j] = x[j] + MK_LM_FD_STEP;
		lm->fn(lm->ctx, xs, fp);
		xs[j] = x[j] - MK_LM_FD_STEP;
		lm->fn(lm->ctx, xs, fm);
		xs[j] = x[j];
		for (int i = 0; i < m; ++i)
			fjac[i + (size_t)j * (size_t)ldfjac] = (fp[i] - fm[i]) / (2.0 * MK_LM_FD_STEP);
	}
	return 0;
}

/* Solve from x (in place); returns lmder's info, the residual norm at the
 * final x and the iterations (Jacobian evaluations). */
static int mkLm_Solve(mkLm *lm, double *x, double *residual, int *iterations)
{
	double fvec[8], fjac[64], diag[8], qtf[8], wa1[8], wa2[8], wa3[8], wa4[8];
	int ipvt[8], nfev = 0, njev = 0;
	lm->jacobians = 0;
	int info = lmder(mkLm_Callback, lm, lm->m, lm->n, x, fvec, fjac, lm->m, MK_LM_TOL, MK_LM_TOL, 0.0,
		20 * lm->max_iter + 20, diag, 1, 100.0, 0, &nfev, &njev, ipvt, qtf, wa1, wa2, wa3, wa4);
	lm->fn(lm->ctx, x, fvec);
	double s = 0.0;
	for (int i = 0; i < lm->m; ++i)
		s += fvec[i] * fvec[i];
	*residual = sqrt(s);
	*iterations = lm->jacobians;
	return info;
}

/* ---- MinkSum (Ray) and MinkSum (Normal) ---------------------------------- */

typedef struct mkMinkCtx {
	mkBody3 b1, b2;
	mkMat3 M1inv;
	mkVec3 d;  /* c2 - c1 */
	int normal;
} mkMinkCtx;

/* The contact-space point at B1's angles, its kissing point and normal. */
static mkVec3 mkMinkPoint(const mkMinkCtx *c, const double *phi, mkVec3 *kiss, mkVec3 *normal)
{
	mkVec3 u = mkCollide_AnglesToUnit(phi[0], phi[1]);
	mkVec3 x = mkSum3_Point(c->b1, c->b2, MK_SET_CONTACT, MK_FORM_GRADIENT, MK_PARAM_SURFACE, u, kiss);
	if (normal)
		*normal = mkBodyNormal(c->b1, c->M1inv, u);
	return x;
}

static void mkMink_Residual(const void *ctx, const double *phi, double *f)
{
	const mkMinkCtx *c = ctx;
	mkVec3 n;
	mkVec3 x = mkMinkPoint(c, phi, NULL, c->normal ? &n : NULL);
	mkVec3 r = c->normal
		? mkVec3_Cross(n, mkVec3_Sub(mkVec3_Add(c->b1.t, c->d), x))  /* n x (c2 - x) */
		: mkVec3_Cross(mkVec3_Sub(x, c->b1.t), c->d);            /* (x - c1) x d */
	f[0] = r.x;
	f[1] = r.y;
	f[2] = r.z;
}

static mkCollide mkCollide_Mink(mkBody3 b1, mkBody3 b2, int max_iter, int normal)
{
	mkMinkCtx ctx;
	ctx.b1 = b1;
	ctx.b2 = b2;
	ctx.M1inv = mkMat3_Inverse(b1.M);
	ctx.d = mkVec3_Sub(b2.t, b1.t);
	ctx.normal = normal;
	/* Initial guess: the angles of d seen in B1's frame. */
	double phi[2];
	mkCollide_UnitToAngles(mkMat3_MulVec(ctx.M1inv, ctx.d), &phi[0], &phi[1]);
	mkLm lm = { mkMink_Residual, &ctx, 3, 2, 0, max_iter };
	mkCollide out = mkCollide_Empty();
	out.status = mkLm_Solve(&lm, phi, &out.residual, &out.iterations);
	mkVec3 kiss, n;
	mkVec3 x = mkMinkPoint(&ctx, phi, &kiss, &n);
	mkVec3 c2 = b2.t;
	out.x = x;
	out.p1 = kiss;
	out.p2 = mkVec3_Add(kiss, mkVec3_Sub(c2, x));  /* B2 moved so that its centre is at x touches B1 at kiss */
	if (normal) {
		out.collide = mkVec3_Dot(n, mkVec3_Sub(c2, x)) <= 0.0;
	} else {
		mkVec3 r = mkVec3_Sub(x, b1.t);
		out.collide = mkVec3_Dot(r, ctx.d) > 0.0 && mkVec3_Length(ctx.d) <= mkVec3_Length(r);
	}
	return out;
}

mkCollide mkCollide_RayLm(mkBody3 b1, mkBody3 b2, int max_iter)
{
	return mkCollide_Mink(b1, b2, max_iter, 0);
}

mkCollide mkCollide_NormalLm(mkBody3 b1, mkBody3 b2, int max_iter)
{
	return mkCollide_Mink(b1, b2, max_iter, 1);
}

/* ---- Common Normal -------------------------------------------------------- */

typedef struct mkCommonCtx {
	mkBody3 b1, b2;
	mkMat3 M1inv, M2inv;
} mkCommonCtx;

static void mkCommon_Eval(const mkCommonCtx *c, const double *phi, mkVec3 *x1, mkVec3 *x2, mkVec3 *n1, mkVec3 *n2)
{
	mkVec3 u1 = mkCollide_AnglesToUnit(phi[0], phi[1]);
	mkVec3 u2 = mkCollide_AnglesToUnit(phi[2], phi[3]);
	*x1 = mkBody3_Point(c->b1, u1);
	*x2 = mkBody3_Point(c->b2, u2);
	*n1 = mkBodyNormal(c->b1, c->M1inv, u1);
	*n2 = mkBodyNormal(c->b2, c->M2inv, u2);
}

static void mkCommon_Residual(const void *ctx, const double *phi, double *f)
{
	mkVec3 x1, x2, n1, n2;
	mkCommon_Eval(ctx, phi, &x1, &x2, &n1, &n2);
	mkVec3 a = mkVec3_Cross(n1, n2), b = mkVec3_Cross(n1, mkVec3_Sub(x2, x1));
	f[0] = a.x;
	f[1] = a.y;
	f[2] = a.z;
	f[3] = b.x;
	f[4] = b.y;
	f[5] = b.z;
}

mkCollide mkCollide_CommonNormal(mkBody3 b1, mkBody3 b2, int max_iter)
{
	mkCommonCtx ctx;
	ctx.b1 = b1;
	ctx.b2 = b2;
	ctx.M1inv = mkMat3_Inverse(b1.M);
	ctx.M2inv = mkMat3_Inverse(b2.M);
	mkVec3 d = mkVec3_Sub(b2.t, b1.t);
	double phi[4];
	mkCollide_UnitToAngles(mkMat3_MulVec(ctx.M1inv, d), &phi[0], &phi[1]);
	mkCollide_UnitToAngles(mkMat3_MulVec(ctx.M2inv, mkVec3_Scale(d, -1.0)), &phi[2], &phi[3]);
	mkLm lm = { mkCommon_Residual, &ctx, 6, 4, 0, max_iter };
	mkCollide out = mkCollide_Empty();
	out.status = mkLm_Solve(&lm, phi, &out.residual, &out.iterations);
	mkVec3 x1, x2, n1, n2;
	mkCommon_Eval(&ctx, phi, &x1, &x2, &n1, &n2);
	out.p1 = x1;
	out.p2 = x2;
	/* As the reference code decides: separated when B2's point lies on the
	 * outer side of B1's tangent plane at B1's point. */
	out.collide = !(mkVec3_Dot(n1, mkVec3_Sub(x2, x1)) > 0.0);
	return out;
}

/* ---- Implicit (Ipopt) ------------------------------------------------------
 * The constraints are Psi(x)^eps1 <= 1 rather than Psi(x) <= 1: Psi^eps1 is
 * homogeneous of degree 2 in the body frame for every exponent, so its
 * gradient grows linearly across the body, whereas Psi itself grows like
 * |x|^(2/eps1), |x|^20 at eps1 = 0.1, which makes the constraint's
 * Jacobian range over many orders of magnitude near the boundary. Both
 * describe the same set. */

typedef struct mkImplicitCtx {
	mkBody3 b[2];
	double last_pr, last_du;
	int last_iter;
} mkImplicitCtx;

static double mkScaledImplicit(mkBody3 b, mkVec3 x, mkVec3 *grad)
{
	double psi = mkBody3_Implicit(b, x);
	double e = b.shape.eps1;
	if (grad) {
		if (psi > 0.0)
			*grad = mkVec3_Scale(mkBody3_Gradient(b, x), e * pow(psi, e - 1.0));
		else
			*grad = mkVec3_Make(0.0, 0.0, 0.0);
	}
	return pow(psi, e);
}

static Bool mkIp_F(Index n, Number *x, Bool new_x, Number *obj, UserDataPtr user)
{
	(void)n; (void)new_x; (void)user;
	double s = 0.0;
	for (int i = 0; i < 3; ++i)
		s += (x[i] - x[i + 3]) * (x[i] - x[i + 3]);
	*obj = s;
	return TRUE;
}

static Bool mkIp_GradF(Index n, Number *x, Bool new_x, Number *g, UserDataPtr user)
{
	(void)n; (void)new_x; (void)user;
	for (int i = 0; i < 3; ++i) {
		g[i] = 2.0 * (x[i] - x[i + 3]);
		g[i + 3] = -g[i];
	}
	return TRUE;
}

static Bool mkIp_G(Index n, Number *x, Bool new_x, Index m, Number *g, UserDataPtr user)
{
	(void)n; (void)new_x; (void)m;
	mkImplicitCtx *c = user;
	for (int k = 0; k < 2; ++k)
		g[k] = mkScaledImplicit(c->b[k], mkVec3_Make(x[3 * k], x[3 * k + 1], x[3 * k + 2]), NULL);
	return TRUE;
}

static Bool mkIp_JacG(Index n, Number *x, Bool new_x, Index m, Index nele, Index *iRow, Index *jCol,
	Number *values, UserDataPtr user)
{
	(void)n; (void)new_x; (void)m; (void)nele;
	mkImplicitCtx *c = user;
	if (!values) {
		for (int k = 0; k < 6; ++k) {
			iRow[k] = k / 3;
			jCol[k] = k;
		}
		return TRUE;
	}
	for (int k = 0; k < 2; ++k) {
		mkVec3 gr;
		mkScaledImplicit(c->b[k], mkVec3_Make(x[3 * k], x[3 * k + 1], x[3 * k + 2]), &gr);
		values[3 * k] = gr.x;
		values[3 * k + 1] = gr.y;
		values[3 * k + 2] = gr.z;
	}
	return TRUE;
}

/* Never called: the Hessian is approximated by limited-memory BFGS. */
static Bool mkIp_H(Index n, Number *x, Bool new_x, Number obj_factor, Index m, Number *lambda,
	Bool new_lambda, Index nele, Index *iRow, Index *jCol, Number *values, UserDataPtr user)
{
	(void)n; (void)x; (void)new_x; (void)obj_factor; (void)m; (void)lambda; (void)new_lambda;
	(void)nele; (void)iRow; (void)jCol; (void)values; (void)user;
	return FALSE;
}

static Bool mkIp_Intermediate(Index alg_mod, Index iter, Number obj, Number inf_pr, Number inf_du,
	Number mu, Number d_norm, Number reg, Number alpha_du, Number alpha_pr, Index ls, UserDataPtr user)
{
	(void)alg_mod; (void)obj; (void)mu; (void)d_norm; (void)reg; (void)alpha_du; (void)alpha_pr; (void)ls;
	mkImplicitCtx *c = user;
	c->last_pr = inf_pr;
	c->last_du = inf_du;
	c->last_iter = iter;
	return TRUE;
}

mkCollide mkCollide_Implicit(mkBody3 b1, mkBody3 b2, double tol)
{
	mkCollide out = mkCollide_Empty();
	mkImplicitCtx ctx;
	ctx.b[0] = b1;
	ctx.b[1] = b2;
	ctx.last_pr = ctx.last_du = NAN;
	ctx.last_iter = -1;
	double xl[6], xu[6], gl[2] = { -2e19, -2e19 }, gu[2] = { 1.0, 1.0 };
	for (int i = 0; i < 6; ++i) {
		xl[i] = -2e19;
		xu[i] = 2e19;
	}
	IpoptProblem p = CreateIpoptProblem(6, xl, xu, 2, gl, gu, 6, 0, 0, mkIp_F, mkIp_G, mkIp_GradF,
		mkIp_JacG, mkIp_H);
	if (!p)
		return out;
	AddIpoptIntOption(p, "print_level", 0);
	AddIpoptStrOption(p, "sb", "yes");
	AddIpoptStrOption(p, "hessian_approximation", "limited-memory");
	AddIpoptNumOption(p, "tol", tol);
	AddIpoptIntOption(p, "max_iter", 1000);
	SetIntermediateCallback(p, mkIp_Intermediate);
	/* Start halfway between each centre and its boundary point in the
	 * direction of the other body: strictly inside, away from the centre
	 * where the constraint's gradient vanishes. */
	mkVec3 d = mkVec3_Sub(b2.t, b1.t);
	mkVec3 k1 = mkBody3_Point(b1, mkVec3_Normalize(mkMat3_MulVec(mkMat3_Inverse(b1.M), d)));
	mkVec3 k2 = mkBody3_Point(b2, mkVec3_Normalize(mkMat3_MulVec(mkMat3_Inverse(b2.M), mkVec3_Scale(d, -1.0))));
	mkVec3 s1 = mkVec3_Scale(mkVec3_Add(b1.t, k1), 0.5), s2 = mkVec3_Scale(mkVec3_Add(b2.t, k2), 0.5);
	double x[6] = { s1.x, s1.y, s1.z, s2.x, s2.y, s2.z }, g[2], obj = NAN;
	enum ApplicationReturnStatus st = IpoptSolve(p, x, g, &obj, NULL, NULL, NULL, &ctx);
	FreeIpoptProblem(p);
	out.status = (int)st;
	out.iterations = ctx.last_iter;
	out.residual = fmax(ctx.last_pr, ctx.last_du);
	out.p1 = mkVec3_Make(x[0], x[1], x[2]);
	out.p2 = mkVec3_Make(x[3], x[4], x[5]);
	out.collide = mkVec3_Length(mkVec3_Sub(out.p1, out.p2)) <= MK_COLLIDE_IMPLICIT_DIST_TOL;
	return out;
}

/* ---- GJK (libccd) ---------------------------------------------------------- */

mkResult mkCollide_GridVertices(mkBody3 b, int n, double *ux, double *uy, double *uz,
	double *x, double *y, double *z)
{
	if (n < 2 || !ux || !uy || !uz || !x || !y || !z)
		return MK_ERR_ARGUMENT;
	mkResult rc = mkSample3_Grid(n, ux, uy, uz);
	if (rc != MK_OK)
		return rc;
	for (int i = 0; i < n * n; ++i) {
		mkVec3 p = mkBody3_Point(b, mkVec3_Make(ux[i], uy[i], uz[i]));
		x[i] = p.x;
		y[i] = p.y;
		z[i] = p.z;
	}
	return MK_OK;
}

static void mkCcd_Support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
	const mkVertices3 *v = obj;
	double dx = ccdVec3X(dir), dy = ccdVec3Y(dir), dz = ccdVec3Z(dir);
	int best = 0;
	double bestv = -DBL_MAX;
	for (int i = 0; i < v->count; ++i) {
		double s = v->x[i] * dx + v->y[i] * dy + v->z[i] * dz;
		if (s > bestv) {
			bestv = s;
			best = i;
		}
	}
	ccdVec3Set(out, v->x[best], v->y[best], v->z[best]);
}

mkCollide mkCollide_GJK(mkVertices3 v1, mkVertices3 v2, int max_iter)
{
	mkCollide out = mkCollide_Empty();
	assert(v1.count >= 1 && v2.count >= 1);
	ccd_t ccd;
	CCD_INIT(&ccd);
	ccd.support1 = mkCcd_Support;
	ccd.support2 = mkCcd_Support;
	ccd.max_iterations = (unsigned long)max_iter;
	int hit = ccdGJKIntersect(&v1, &v2, &ccd);
	out.status = hit;
	out.collide = hit != 0;
	return out;
}

/* ---- the referee ------------------------------------------------------------ */

static double mkRefG(mkBody3 b1, mkBody3 b2, mkVec3 n)
{
	return mkBody3_SupportValue(b1, n) + mkBody3_SupportValue(b2, mkVec3_Scale(n, -1.0));
}

/* Pattern search on the sphere around n: steps in the tangent plane, the
 * point renormalised; a step that improves g by more than rounding noise
 * (1e-14 relative) is taken and the step doubles, otherwise it halves. At
 * most MK_REF_MAX_EVAL evaluations. */
#define MK_REF_MAX_EVAL 4000
static double mkRefSearch(mkBody3 b1, mkBody3 b2, mkVec3 *n, double step)
{
	double best = mkRefG(b1, b2, *n), init = step;
	int evals = 1;
	while (step > 1e-11 && evals < MK_REF_MAX_EVAL) {
		mkVec3 a = fabs(n->x) < 0.6 ? mkVec3_Make(1, 0, 0) : mkVec3_Make(0, 1, 0);
		mkVec3 t1 = mkVec3_Normalize(mkVec3_Cross(*n, a)), t2 = mkVec3_Cross(*n, t1);
		int moved = 0;
		for (int k = 0; k < 4 && !moved; ++k) {
			mkVec3 t = k < 2 ? t1 : t2;
			double s = (k % 2 == 0) ? step : -step;
			mkVec3 c = mkVec3_Normalize(mkVec3_Add(*n, mkVec3_Scale(t, s)));
			double v = mkRefG(b1, b2, c);
			evals += 1;
			if (v < best - 1e-14 * (1.0 + fabs(best))) {
				best = v;
				*n = c;
				moved = 1;
			}
		}
		step = moved ? fmin(2.0 * step, init) : 0.5 * step;
	}
	return best;
}

double mkCollide_Referee(mkBody3 b1, mkBody3 b2, int grid, mkVec3 *nout)
{
	assert(grid >= 4);
	enum { KEEP = 3 };
	double bestv[KEEP];
	mkVec3 bestn[KEEP];
	for (int k = 0; k < KEEP; ++k) {
		bestv[k] = INFINITY;
		bestn[k] = mkVec3_Make(0, 0, 1);
	}
	int nw = 2 * grid;
	for (int i = 0; i < grid; ++i) {
		double eta = -MK_PI / 2 + MK_PI * (i + 0.5) / grid;
		for (int j = 0; j < nw; ++j) {
			mkVec3 n = mkCollide_AnglesToUnit(eta, -MK_PI + 2.0 * MK_PI * j / nw);
			double v = mkRefG(b1, b2, n);
			if (v < bestv[KEEP - 1]) {
				int k = KEEP - 1;
				while (k > 0 && v < bestv[k - 1]) {
					bestv[k] = bestv[k - 1];
					bestn[k] = bestn[k - 1];
					--k;
				}
				bestv[k] = v;
				bestn[k] = n;
			}
		}
	}
	double best = INFINITY;
	mkVec3 bn = bestn[0];
	for (int k = 0; k < KEEP; ++k) {
		if (!isfinite(bestv[k]))
			continue;
		mkVec3 n = bestn[k];
		double v = mkRefSearch(b1, b2, &n, MK_PI / grid);
		if (v < best) {
			best = v;
			bn = n;
		}
	}
	if (nout)
		*nout = bn;
	return best;
}

/* ---- versions ----------------------------------------------------------- */

#ifndef MK_COLLIDE_IPOPT_VERSION
#define MK_COLLIDE_IPOPT_VERSION "unknown"
#endif
#ifndef MK_COLLIDE_CCD_VERSION
#define MK_COLLIDE_CCD_VERSION "unknown"
#endif
#ifndef MK_COLLIDE_CMINPACK_VERSION
#define MK_COLLIDE_CMINPACK_VERSION "unknown"
#endif

const char *mkCollide_IpoptVersion(void) { return MK_COLLIDE_IPOPT_VERSION; }
const char *mkCollide_CcdVersion(void) { return MK_COLLIDE_CCD_VERSION; }
const char *mkCollide_CminpackVersion(void) { return MK_COLLIDE_CMINPACK_VERSION; }
