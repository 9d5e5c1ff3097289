/* mpref.h - a 256-bit MPFR model of the bodies and of their Minkowski sums,
 * written from the definitions of the shapes, to judge the core's
 * double-precision closed forms.
 *
 * Nothing here calls or copies the core. The inputs are the same doubles the
 * core receives (converted exactly), so the reference is the exact answer to
 * the same question, up to 256-bit rounding (about 1e-77 relative), which is
 * far below anything a double can resolve.
 *
 * The shapes (canonical frame, u a unit vector):
 *  superellipse  Psi(x) = |x1/a|^p + |x2/b|^p,  p = 2/eps
 *                f(u)   = (a sp(u1,eps), b sp(u2,eps))
 *  superquadric  Psi(x) = (|x1/a|^p2 + |x2/b|^p2)^(p1/p2) + |x3/c|^p1,
 *                p1 = 2/eps1, p2 = 2/eps2
 *                f(u)   = (a r^e1 sp(u1/r,e2), b r^e1 sp(u2/r,e2), c sp(u3,e1)),
 *                r = |(u1,u2)|
 * with sp(v,e) = sign(v)|v|^e. Three derivations are kept apart so that they
 * can check each other (see refShape_*):
 *  - the gradient of Psi, differentiated from the implicit function;
 *  - the support point: the maximiser of <d,x> over the body. The body is the
 *    unit ball of the norm |x|_B = |(x1/a, x2/b)|_p (2D) or
 *    |(|(x1/a,x2/b)|_p2, x3/c)|_p1 (3D); its support function is the dual
 *    norm, found by Hoelder's inequality, and its maximiser is where
 *    Hoelder's inequality is an equality (derivation in mpref.c);
 *  - the inverse of the gradient of the parametric form, g(u) = grad Psi(f(u)),
 *    solved for the direction of u.
 *
 * A placed body is B = t + M B_canonical, M invertible. */
#ifndef MINK_MPREF_H
#define MINK_MPREF_H

#include <mpfr.h>

#define REF_PREC 256

/* A 2- or 3-vector of MPFR numbers (2D uses the first two). */
typedef struct refVec { mpfr_t c[3]; } refVec;

/* Shape parameters as the doubles given to the core. 2D: a[0], a[1], e1 = eps.
 * 3D: a[0..2] = a, b, c, e1 = eps1, e2 = eps2. */
typedef struct refShape { int dim; double a[3]; double e1, e2; } refShape;

/* A 2x2 or 3x3 matrix of doubles, row-major (2D uses the top-left block). */
typedef struct refMat { double m[3][3]; } refMat;

/* B = t + M B_canonical. */
typedef struct refBody { refShape s; refMat M; double t[3]; } refBody;

void refVec_Init(refVec *v);
void refVec_Clear(refVec *v);
void refVec_Set(refVec *dst, const refVec *src);
void refVec_FromD(refVec *v, int dim, const double *d);
void refVec_ToD(const refVec *v, int dim, double *d);
/* |v - d| (Euclidean), rounded to double at the end. */
double refVec_DistD(const refVec *v, int dim, const double *d);
double refVec_NormD(const refVec *v, int dim);
/* <v, d> rounded to double at the end. */
void refVec_Dot(mpfr_t out, const refVec *v, const refVec *w, int dim);
/* Scale to unit length (v != 0). */
void refVec_Normalize(refVec *v, int dim);

/* sp(v, e) = sign(v) |v|^e, sp(0, e) = 0 (e > 0). */
void refSp(mpfr_t out, const mpfr_t v, const mpfr_t e);

/* ---- canonical shape --------------------------------------------------- */
/* f(u) for any nonzero u (normalised first). */
void refShape_Point(refShape s, const refVec *u, refVec *x);
/* Psi(x). */
void refShape_Implicit(refShape s, const refVec *x, mpfr_t psi);
/* grad Psi(x), x != 0 (a vanishing block of coordinates gives 0 there). */
void refShape_Gradient(refShape s, const refVec *x, refVec *m);
/* The support point: the boundary point with outward normal along d != 0. */
void refShape_Support(refShape s, const refVec *d, refVec *x);
/* The same point by logarithms: each |a_i d_i| is taken to a logarithm once
 * and every power becomes one exponential (4 logarithms and 5 exponentials
 * in 3D instead of 10 powers). Exact to about |q log|a_i d_i|| 2^-256
 * relative (below 1e-68 for eps <= 2 - 1e-6 and |a_i d_i| in 1e-20 ... 1e20);
 * the searches of mpref_measure.c use it, checked against refShape_Support
 * by the tests. */
void refShape_SupportByLogs(refShape s, const refVec *d, refVec *x);
/* The support value h(d) = max over the body of <d, x>. */
void refShape_SupportValue(refShape s, const refVec *d, mpfr_t h);
/* The same boundary point as refShape_Support, reached the other way: solve
 * g(u) = lambda m for the direction of u, then x = f(u). */
void refShape_FromGradientInverse(refShape s, const refVec *m, refVec *x);

/* ---- placed body ------------------------------------------------------- */
/* t + M f(u). */
void refBody_Point(const refBody *b, const refVec *u, refVec *x);
/* The world gradient at t + M f(u): M^-T grad Psi(f(u)), and the same
 * scaled to unit length (the outward normal). */
void refBody_GradientAt(const refBody *b, const refVec *u, refVec *m);
void refBody_Normal(const refBody *b, const refVec *u, refVec *n);
/* t + M s(M^T n): the point of B with outward normal n. */
void refBody_Support(const refBody *b, const refVec *n, refVec *x);
/* <n, t> + h(M^T n). */
void refBody_SupportValue(const refBody *b, const refVec *n, mpfr_t h);

/* M v and M^T v for a double matrix and an MPFR vector. */
void refMat_MulVec(const refMat *M, int dim, const refVec *v, refVec *out);
void refMat_MulTVec(const refMat *M, int dim, const refVec *v, refVec *out);
void refMat_InvTVec(const refMat *M, int dim, const refVec *v, refVec *out);

/* ---- sums -------------------------------------------------------------- */
/* The boundary point of the contact space B1 (+) (-B2) (plus = 0) or of
 * B1 (+) B2 (plus = 1) at parameter u:
 *  surface = 1: u parameterises B1's surface, k = t1 + M1 f1(u), and n is
 *               the world normal there;
 *  surface = 0: n = u / |u| is the world normal, k = t1 + M1 s1(M1^T n).
 * Contact: x = k - M2 s2(-M2^T n).  Plus: x = k + t2 + M2 s2(M2^T n).
 * k and n may be NULL. */
void refSum_Point(const refBody *b1, const refBody *b2, int plus, int surface,
	const refVec *u, refVec *x, refVec *k, refVec *n);
/* The support value of the set in direction n (unit): h_B1(n) + h(-M2^T n)
 * for the contact space, h_B1(n) + h_B2(n) for the plus set. */
void refSum_SupportValue(const refBody *b1, const refBody *b2, int plus,
	const refVec *n, mpfr_t h);

/* ---- threads ----------------------------------------------------------- */
/* Frees the calling thread's MPFR caches (the constants such as pi and
 * log 2 that MPFR keeps per thread once computed). A thread that used the
 * reference calls it before it returns: the caches live in thread-local
 * storage, so nothing else can free them once the thread has ended. */
void refThread_Release(void);

#endif
