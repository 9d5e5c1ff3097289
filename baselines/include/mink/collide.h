/* mink/collide.h - collision queries between two placed superquadrics (paper
 * Sec. 7.2, Table 3): the paper's two closed-form Minkowski-sum queries and
 * the four algorithms it compares them with, plus a referee that decides
 * the answer by a separate code path (the support functions).
 *
 * Every query takes two valid bodies (mkBody3_IsValid) and returns an
 * mkCollide by value. Fields that a method does not produce are NaN (reals)
 * or -1 (integers). Nothing is allocated except inside Ipopt and libccd.
 *
 *  RayLm         MinkSum (Ray) as the paper solves it (the core's is
 *                mkCollide3_Ray): LM over B1's two surface angles phi:
 *                (x(phi) - c1) x d = 0, x(phi) the closed-form
 *                contact-space point, d = c2 - c1.
 *  NormalLm      MinkSum (Normal) as the paper solves it (the core's is
 *                mkCollide3_Normal): LM over the same angles:
 *                n(phi) x (c2 - x(phi)) = 0, n the unit outward normal
 *                of the contact space at x(phi).
 *  CommonNormal  LM over both bodies' angles (4 unknowns, 6 residuals):
 *                n1 x n2 = 0, n1 x (x2 - x1) = 0.
 *  Implicit      Ipopt: min |x1 - x2|^2 s.t. Psi1(x1)^eps1 <= 1,
 *                Psi2(x2)^eps1 <= 1 (6 unknowns).
 *  GJK           libccd's GJK on two vertex sets (support = max over vertices).
 *  ASC           the algebraic separation condition of two ellipsoids
 *                (Wang, Wang & Kim 2001); ellipsoids only.
 *  Referee       min over unit n of g(n) = h1(n) + h2(-n), h the support
 *                functions of the placed bodies: the bodies intersect iff
 *                min g >= 0; |min g| is the distance (separated) or the
 *                penetration depth (overlapping). */
#ifndef MINK_COLLIDE_H
#define MINK_COLLIDE_H

#include <mink/mink.h>

MK_EXTERN_C_BEGIN

/* The answer of one query. */
typedef struct mkCollide {
	int collide;      /* 1 the bodies overlap or touch, 0 they are separated */
	double residual;  /* norm of the solved equations at the answer (LM), or
	                     Ipopt's final max(primal, dual) infeasibility */
	int iterations;   /* solver iterations (LM: Jacobian evaluations) */
	int status;       /* the solver's own return code (cminpack info, Ipopt
	                     ApplicationReturnStatus, libccd's result); -1 none */
	mkVec3 p1, p2;    /* witness points on B1 and B2 (B2's for RayLm and
	                     NormalLm: B1's kissing point moved by c2 - x) */
	mkVec3 x;         /* RayLm/NormalLm: the contact-space point */
} mkCollide;

/* Iteration limit of the LM queries (the paper's fsolve MaxIterations). */
#define MK_COLLIDE_LM_MAX_ITER 100
/* The paper's success criterion for a solve: residual norm below this. */
#define MK_COLLIDE_SUCCESS_RESIDUAL 1e-10
/* Implicit: the bodies are reported as overlapping when the distance of the
 * two optimal points is at most this (the reference code's threshold). */
#define MK_COLLIDE_IMPLICIT_DIST_TOL 1e-3

/* The paper's spherical angles (eta, omega) to a unit vector and back. */
MK_API mkVec3 mkCollide_AnglesToUnit(double eta, double omega);
MK_API void mkCollide_UnitToAngles(mkVec3 v, double *eta, double *omega);

MK_API mkCollide mkCollide_RayLm(mkBody3 b1, mkBody3 b2, int max_iter);
MK_API mkCollide mkCollide_NormalLm(mkBody3 b1, mkBody3 b2, int max_iter);
MK_API mkCollide mkCollide_CommonNormal(mkBody3 b1, mkBody3 b2, int max_iter);
/* tol: Ipopt's convergence tolerance (its scaled NLP error). */
MK_API mkCollide mkCollide_Implicit(mkBody3 b1, mkBody3 b2, double tol);

/* A vertex set in structure-of-arrays form. */
typedef struct mkVertices3 {
	const double *x, *y, *z;
	int count;
} mkVertices3;

/* The boundary points of b at the n x n parameter grid of mkSample3_Grid
 * (the paper's polytope for GJK): x, y, z and the scratch arrays ux, uy, uz
 * hold n*n values each. Fails (MK_ERR_ARGUMENT) on n < 2 or NULL arrays. */
MK_API mkResult mkCollide_GridVertices(mkBody3 b, int n, double *ux, double *uy, double *uz,
	double *x, double *y, double *z);
/* GJK on the convex hulls of two vertex sets (count >= 1). */
MK_API mkCollide mkCollide_GJK(mkVertices3 v1, mkVertices3 v2, int max_iter);

/* ASC; both shapes must be ellipsoids (mkShape3_IsEllipsoid), otherwise
 * the answer has status -2 and collide -1. status: the number of real
 * positive roots of det(lambda A + B) found. The residual field holds the
 * gap |lambda1 - lambda2| / max(lambda1, lambda2) of the two positive roots
 * when there are two, else NaN. */
MK_API mkCollide mkCollide_ASC(mkBody3 b1, mkBody3 b2);

/* The referee: min over unit n of h1(n) + h2(-n), by a grid of
 * grid x 2 grid directions and a pattern search around the best few. The
 * minimising direction goes to *n when n is not NULL. grid >= 4. */
MK_API double mkCollide_Referee(mkBody3 b1, mkBody3 b2, int grid, mkVec3 *n);

/* Versions of the libraries the queries run on, as text ("unknown" when the
 * library does not say). */
MK_API const char *mkCollide_IpoptVersion(void);
MK_API const char *mkCollide_CcdVersion(void);
MK_API const char *mkCollide_CminpackVersion(void);
MK_API const char *mkCollide_EigenVersion(void);

MK_EXTERN_C_END

#endif
