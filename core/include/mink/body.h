/* mink/body.h - the convex bodies: superellipses (2D) and superquadrics (3D),
 * in canonical form and placed by an invertible linear map and a translation.
 *
 * Canonical superellipse (paper, Sec. 5.2.1):
 *   Psi(x) = |x1/a|^(2/eps) + |x2/b|^(2/eps) <= 1,   f(u) = (a sp(u1,eps), b sp(u2,eps))
 * Canonical superquadric (paper, Sec. 5.2.2):
 *   Psi(x) = (|x1/a|^(2/e2) + |x2/b|^(2/e2))^(e2/e1) + |x3/c|^(2/e1) <= 1
 *   f(u)   = (a rho^e1 sp(u1/rho,e2), b rho^e1 sp(u2/rho,e2), c sp(u3,e1)),  rho = |(u1,u2)|
 * where sp(v, e) = sign(v)|v|^e and u is a unit vector (u = (cos t, sin t) in 2D,
 * u = (cos eta cos w, cos eta sin w, sin eta) in 3D: the paper's angles).
 * eps = 1 (eps1 = eps2 = 1) is the ellipse (ellipsoid); circles and spheres
 * are ellipses with equal semi-axes. Such shapes are computed by the cheaper
 * exact ellipse formulas automatically.
 *
 * A body is  B = t + M * B_canonical  with M invertible (M = R S in the paper).
 *
 * Functions named ..._IsValid check user input and write the message a user
 * sees; the other functions assume valid input (checked by assert in debug and
 * RelWithDebInfo builds) and never allocate. */
#ifndef MINK_BODY_H
#define MINK_BODY_H

#include <stddef.h>
#include "geom.h"

MK_EXTERN_C_BEGIN

/* Allowed ranges of user input, inclusive. The exponent range keeps 2/eps and
 * 1/(2-eps) below 1e6; the others keep every intermediate of the closed forms
 * and of the metrics inside the double range. */
#define MK_EPS_MIN 1e-6
#define MK_EPS_MAX (2.0 - 1e-6)
#define MK_AXIS_MIN 1e-9
#define MK_AXIS_MAX 1e9
#define MK_MAP_ENTRY_MAX 1e9
#define MK_MAP_COND_MAX 1e12
#define MK_POS_MAX 1e12

typedef struct mkShape2 { double a, b, eps; } mkShape2;
typedef struct mkShape3 { double a, b, c, eps1, eps2; } mkShape3;

typedef struct mkBody2 { mkShape2 shape; mkMat2 M; mkVec2 t; } mkBody2;
typedef struct mkBody3 { mkShape3 shape; mkMat3 M; mkVec3 t; } mkBody3;

/* ---- validation ---------------------------------------------------------
 * Return 1 when valid. Otherwise return 0 and, when msg is not NULL, write a
 * one-line message naming the field ("<what>.eps"), the value and the
 * allowed range. `what` prefixes field names, e.g. "body1". */
MK_API int mkShape2_IsValid(mkShape2 s, const char *what, char *msg, size_t msglen);
MK_API int mkShape3_IsValid(mkShape3 s, const char *what, char *msg, size_t msglen);
MK_API int mkBody2_IsValid(mkBody2 b, const char *what, char *msg, size_t msglen);
MK_API int mkBody3_IsValid(mkBody3 b, const char *what, char *msg, size_t msglen);

/* 1 when the shape is an ellipse/ellipsoid (eps == 1 exactly), so that the
 * cheaper exact formulas apply. */
MK_API int mkShape2_IsEllipse(mkShape2 s);
MK_API int mkShape3_IsEllipsoid(mkShape3 s);

/* ---- canonical shapes ---------------------------------------------------
 * Implicit function Psi and its gradient at any point (gradient: x != 0). */
MK_API double mkShape2_Implicit(mkShape2 s, mkVec2 x);
MK_API mkVec2 mkShape2_Gradient(mkShape2 s, mkVec2 x);
MK_API double mkShape3_Implicit(mkShape3 s, mkVec3 x);
MK_API mkVec3 mkShape3_Gradient(mkShape3 s, mkVec3 x);

/* Parametric point f(u), u a unit vector (any nonzero vector is normalised
 * first in effect: f(u) depends only on the direction of u). */
MK_API mkVec2 mkShape2_Point(mkShape2 s, mkVec2 u);
MK_API mkVec3 mkShape3_Point(mkShape3 s, mkVec3 u);
/* The gradient of Psi at f(u), in closed form from u (paper eqs. 2d_sq_m_u,
 * 3d_sq_m_u): the map g(u). */
MK_API mkVec2 mkShape2_PointGradient(mkShape2 s, mkVec2 u);
MK_API mkVec3 mkShape3_PointGradient(mkShape3 s, mkVec3 u);

/* Support point f~(n): the boundary point whose outward normal is n (any
 * nonzero n; only its direction matters). Theorem 1's map, evaluated as the
 * gradient of the dual-norm support function. */
MK_API mkVec2 mkShape2_Support(mkShape2 s, mkVec2 n);
MK_API mkVec3 mkShape3_Support(mkShape3 s, mkVec3 n);
/* Support function h(n) = max over the body of <n, x>. */
MK_API double mkShape2_SupportValue(mkShape2 s, mkVec2 n);
MK_API double mkShape3_SupportValue(mkShape3 s, mkVec3 n);

/* f~~(m): the boundary point whose gradient is m (Theorem 2's map). Evaluated
 * stably as f(g^-1(m)/|g^-1(m)|), which equals the paper's formula
 * (eqs. 2d_sq_f_m, 3d_sq_f_m) whenever m is a gradient of Psi, and depends
 * only on the direction of m. */
MK_API mkVec2 mkShape2_FromGradient(mkShape2 s, mkVec2 m);
MK_API mkVec3 mkShape3_FromGradient(mkShape3 s, mkVec3 m);
/* The paper's formulas for f~~(m) as printed (eqs. 2d_sq_f_m, 3d_sq_f_m), in
 * double precision. Correct only for true gradients m; the 3D one computes
 * gamma(m3) = 1 - (c e1 m3/2)^(2/(2-e1)), which cancels near the poles. Kept
 * as the reference of what the published code computes. */
MK_API mkVec2 mkShape2_FromGradientPaper(mkShape2 s, mkVec2 m);
MK_API mkVec3 mkShape3_FromGradientPaper(mkShape3 s, mkVec3 m);

/* Lemma 1's Phi: the norm of the gradient of shape s at the boundary point
 * whose gradient is parallel to m (paper eq. Phi_m1_general). */
MK_API double mkShape2_Phi(mkShape2 s, mkVec2 m);
MK_API double mkShape3_Phi(mkShape3 s, mkVec3 m);

/* Area of the superellipse, 4ab Gamma(1+eps/2)^2 / Gamma(1+eps), and volume of
 * the superquadric, 2abc e1 e2 B(e1/2+1, e1) B(e2/2, e2/2) (Jaklic et al.). */
MK_API double mkShape2_Area(mkShape2 s);
MK_API double mkShape3_Volume(mkShape3 s);

/* ---- placed bodies ------------------------------------------------------
 * The same maps for B = t + M B_canonical: Psi_B(x) = Psi(M^-1 (x - t)),
 * gradients transform by M^-T (paper eq. gradient_trans). */
MK_API mkBody2 mkBody2_Make(mkShape2 s, mkMat2 M, mkVec2 t);
MK_API mkBody3 mkBody3_Make(mkShape3 s, mkMat3 M, mkVec3 t);
MK_API double mkBody2_Implicit(mkBody2 b, mkVec2 x);
MK_API double mkBody3_Implicit(mkBody3 b, mkVec3 x);
MK_API mkVec2 mkBody2_Gradient(mkBody2 b, mkVec2 x);
MK_API mkVec3 mkBody3_Gradient(mkBody3 b, mkVec3 x);
MK_API mkVec2 mkBody2_Point(mkBody2 b, mkVec2 u);
MK_API mkVec3 mkBody3_Point(mkBody3 b, mkVec3 u);
/* Support point of the placed body in direction n (any nonzero vector,
 * not necessarily unit): t + M x_C(M^T n), the translation t included; the
 * support value is <n, that point>, so it includes <n, t>. (For the contact
 * set B1 (+) (-B2), where B2's translation drops out, body 2's part in
 * direction n is b2.t - mkBody2_Support(b2, -n).) */
MK_API mkVec2 mkBody2_Support(mkBody2 b, mkVec2 n);
MK_API mkVec3 mkBody3_Support(mkBody3 b, mkVec3 n);
MK_API double mkBody2_SupportValue(mkBody2 b, mkVec2 n);
MK_API double mkBody3_SupportValue(mkBody3 b, mkVec3 n);
MK_API double mkBody2_Area(mkBody2 b);
MK_API double mkBody3_Volume(mkBody3 b);

MK_EXTERN_C_END

#endif
