/* kernel_body.h - the closed-form kernels, written once over a lane type.
 *
 * Included by kernel_scalar.c (one double per lane, libm), kernel_avx2.c
 * (4 lanes, SLEEF) and kernel_avx512.c (8 lanes, SLEEF), each of which first
 * defines:
 *   KV           lane type;  KM  mask type (result of a comparison of KV)
 *   KW           lanes per KV
 *   KEXP KLOG KSQRT             elementwise functions
 *   KABS(v) KCOPYSIGN(mag, s) KSEL(mask, a, b)   (mask ? a : b)
 *   KLOAD(p) KSTORE(p, v)       unaligned load / store of KW values of type KIO
 *   KSPLAT(s)    a lane value with every lane equal to the double s
 *   KALL(mask)   nonzero when the mask holds in every lane
 *   KFN(name)    appends the ISA suffix to a function name
 *   KP           (optional, default 1) lane vectors processed together
 * and, for a build whose lanes are not doubles (the single-precision tier,
 * kernel_f32*.c), optionally:
 *   KS           scalar type of the lanes (default double); KC(x) converts a
 *                double constant to it (default: x unchanged)
 *   KSHAPE2 KSHAPE3 KPLAN2 KPLAN3   the prepared constants in that type
 *                (default mkKShape2 ... mkKPlan3)
 *   KTINY KUNIT_TOL   the two thresholds below, for that type's range
 *   KIO          type of the caller's arrays of mkK2_Run/mkK3_Run (default
 *                double; float for the tier's float-buffer builds)
 *   KRSQRT(v)    1/sqrt(v) of lanes that are positive and normal (default
 *                1.0 / KSQRT(v); a build may use a faster approximation
 *                whose error it states)
 *   KDIV_AXIS(v, s, ax)   v divided by the semi-axis s->ax (default the
 *                division; a build may multiply by a prepared reciprocal)
 *   KLOAD_UNIT2(s, px, py, u1, u2) / KLOAD_UNIT3(...)   load KW parameter
 *                vectors from doubles at px[s], py[s] and make them unit
 *                length (default: the load-and-normalise below, on KV)
 * A double build defines none of these, and its arithmetic is exactly the
 * same as before they existed.
 *
 * Interleaving. The elementary functions are out-of-line calls whose
 * latency, not their throughput, bounds a single chain of them: on this
 * code's reference machine (Zen 4) one 8-lane log followed by an exp costs
 * about 31 ns as a dependent chain, but 10.6 ns each when four independent
 * chains are interleaved. Every helper below therefore works on KP lane
 * vectors at once, and each loop over them (KFOR) holds at most one call,
 * so that the calls of the KP independent groups follow each other and
 * overlap in the processor. Each lane's arithmetic is unchanged: the result
 * does not depend on KP.
 *
 * Numerics (see NUMERICS notes in the README). Every power is taken in the
 * log domain on ratios that are at most 1, after dividing by the largest
 * component, so that exponents from 5e-7 to 2e6 neither overflow nor lose
 * the dominant components' digits; the small complement that the published
 * 3D gradient formula computes as 1 - (k m3)^(2/(2-e1)) is instead built from
 * the other components (the hypotenuse of the inner pair). A zero component
 * gives log 0 = -inf, which only ever meets multiplication by a positive
 * constant or addition of a finite value, so it yields exp(-inf) = 0 and
 * never NaN. */

#ifndef KP
#define KP 1
#endif
#define KFOR(j) _Pragma("GCC unroll 8") for (int j = 0; j < KP; ++j)

#ifndef KTINY
#define KTINY 1e-300 /* floor of a divisor that may be exactly zero */
#endif
#ifndef KUNIT_TOL
#define KUNIT_TOL 1e-15 /* |u|^2 - 1 of a unit vector rounded to double, with room */
#endif
#ifndef KIO
#define KIO double
#endif
#ifndef KRSQRT
#define KRSQRT(v) (1.0 / KSQRT(v))
#endif
#ifndef KDIV_AXIS
#define KDIV_AXIS(v, s, ax) ((v) / (s)->ax)
#endif
#ifndef KS
#define KS double
#endif
#ifndef KC
#define KC(x) (x)
#endif
#ifndef KSHAPE2
#define KSHAPE2 mkKShape2
#define KSHAPE3 mkKShape3
#define KPLAN2 mkKPlan2
#define KPLAN3 mkKPlan3
#endif

/* log(1 + t) for t in [0, 1]: through log rather than log1p (twice as fast
 * in SLEEF). Rounding 1 + t costs at most half an ulp of 1 in absolute
 * terms, and every such logarithm here only ever enters exp() with a
 * coefficient of at most 1 times the scale of its companions, so the
 * relative error it adds to a point is about 1e-16. */
#define KLOG1P1(t) KLOG(1.0 + (t))

static inline KV KFN(kmax)(KV a, KV b) { return KSEL(a >= b, a, b); }
static inline KV KFN(kmin)(KV a, KV b) { return KSEL(a >= b, b, a); }

/* Every helper takes and returns arrays of KP lane vectors; no output array
 * may be one of the input arrays. */

/* For a, b >= 0 (not both zero) and q > 1: the dual-norm ratios
 * ra = (a / |(a,b)|_q)^(q-1), rb likewise, and the pieces of the norm,
 * |(a,b)|_q = mx * exp(L / q). With r = min/max <= 1 the ratios are
 * (1 + r^q)^(-(q-1)/q) for the larger and r^(q-1) times that for the
 * smaller: two logs and two exps. */
static inline void KFN(pair_dual)(const KV *a, const KV *b, KS qm1, KS k,
	KV *ra, KV *rb, KV *mx, KV *L)
{
	KM agb[KP];
	KV r[KP], s[KP], cmax[KP];
	KFOR(j) {
		agb[j] = a[j] >= b[j];
		mx[j] = KSEL(agb[j], a[j], b[j]);
		KV mn = KSEL(agb[j], b[j], a[j]);
		r[j] = mn / KFN(kmax)(mx[j], KSPLAT(KTINY));
	}
	KFOR(j) s[j] = KLOG(r[j]);
	KFOR(j) s[j] = KEXP(qm1 * s[j]);       /* r^(q-1); 0 for r = 0 */
	KFOR(j) L[j] = KLOG1P1(s[j] * r[j]);   /* log(1 + r^q) */
	KFOR(j) cmax[j] = KEXP(-k * L[j]);     /* (1 + r^q)^(-(q-1)/q) */
	KFOR(j) {
		ra[j] = KSEL(agb[j], cmax[j], s[j] * cmax[j]);
		rb[j] = KSEL(agb[j], s[j] * cmax[j], cmax[j]);
	}
}

/* ---- 2D ------------------------------------------------------------------ */

/* B1's point f(u) and a positive multiple of its gradient g(u). */
static inline void KFN(se_surface)(const KSHAPE2 *s, const KV *u1, const KV *u2,
	KV *x1, KV *x2, KV *m1, KV *m2)
{
	if (s->ellipse) {
		KFOR(j) {
			x1[j] = s->a * u1[j]; x2[j] = s->b * u2[j];
			m1[j] = KDIV_AXIS(u1[j], s, a); m2[j] = KDIV_AXIS(u2[j], s, b);
		}
		return;
	}
	KV l1[KP], l2[KP];
	KFOR(j) l1[j] = KLOG(KABS(u1[j]));
	KFOR(j) l2[j] = KLOG(KABS(u2[j]));
	KFOR(j) x1[j] = s->a * KCOPYSIGN(KEXP(s->eps * l1[j]), u1[j]);
	KFOR(j) x2[j] = s->b * KCOPYSIGN(KEXP(s->eps * l2[j]), u2[j]);
	/* g_i = sp(u_i, 2-eps)/a_i = u_i^2 / x_i: a division instead of a power.
	 * Where x_i is zero (u_i = 0, or |u_i|^eps below the double range, a
	 * direction within 1e-150 of an axis) the component is taken as 0. */
	KFOR(j) {
		KM z1 = x1[j] == 0.0, z2 = x2[j] == 0.0;
		m1[j] = KSEL(z1, KSPLAT(0.0), (u1[j] / KSEL(z1, KSPLAT(1.0), x1[j])) * u1[j]);
		m2[j] = KSEL(z2, KSPLAT(0.0), (u2[j] / KSEL(z2, KSPLAT(1.0), x2[j])) * u2[j]);
	}
}

/* The lanes of an ellipse or ellipsoid support point whose |A d|^2 = ss
 * left the range where 1/sqrt is exact enough (below KTINY or above its
 * reciprocal): v = A d is divided by its largest component first, and a
 * zero d (B2's direction, B1's gradient through D2, can round to exactly 0
 * when the two maps together are close to singular) takes the convention of
 * the superquadric support map, the point (a, 0, 0). Other lanes keep x. */
static inline void KFN(ell_fix)(KS a, KS b, KS c, KV ss, KV v1, KV v2, KV v3, KV *x1, KV *x2, KV *x3)
{
	KV m = KFN(kmax)(KFN(kmax)(KABS(v1), KABS(v2)), KABS(v3));
	KM zero = m == 0.0;
	KV md = KSEL(zero, KSPLAT(1.0), m);
	KV w1 = v1 / md, w2 = v2 / md, w3 = v3 / md;
	KV inv = KRSQRT(KSEL(zero, KSPLAT(1.0), w1 * w1 + w2 * w2 + w3 * w3));
	KV f1 = KSEL(zero, KSPLAT(a), a * w1 * inv), f2 = KSEL(zero, KSPLAT(0.0), b * w2 * inv);
	KV f3 = KSEL(zero, KSPLAT(0.0), c * w3 * inv);
	KM lo = ss >= KSPLAT(KTINY), hi = ss <= KSPLAT(1.0 / KTINY);
	*x1 = KSEL(lo, *x1, f1); *x2 = KSEL(lo, *x2, f2); *x3 = KSEL(lo, *x3, f3);
	*x1 = KSEL(hi, *x1, f1); *x2 = KSEL(hi, *x2, f2); *x3 = KSEL(hi, *x3, f3);
}

/* Theorem 1's f~(d): the support point in direction d (a zero d gives the
 * point (a, 0), as pair_dual's convention for equal components does). */
static inline void KFN(se_support)(const KSHAPE2 *s, const KV *d1, const KV *d2, KV *x1, KV *x2)
{
	if (s->ellipse) { /* A^2 d / |A d|; ell_fix for lanes out of range */
		KFOR(j) {
			KV v1 = s->a * d1[j], v2 = s->b * d2[j];
			KV ss = v1 * v1 + v2 * v2;
			KV inv = KRSQRT(ss);
			x1[j] = s->a * v1 * inv; x2[j] = s->b * v2 * inv;
			if (!KALL(ss >= KSPLAT(KTINY)) || !KALL(ss <= KSPLAT(1.0 / KTINY))) {
				KV x3 = KSPLAT(0.0);
				KFN(ell_fix)(s->a, s->b, KC(1.0), ss, v1, v2, KSPLAT(0.0), &x1[j], &x2[j], &x3);
			}
		}
		return;
	}
	KV p1[KP], p2[KP], r1[KP], r2[KP], mx[KP], L[KP];
	KFOR(j) { p1[j] = KABS(s->a * d1[j]); p2[j] = KABS(s->b * d2[j]); }
	KFN(pair_dual)(p1, p2, s->qm1, s->k, r1, r2, mx, L);
	KFOR(j) {
		x1[j] = s->a * KCOPYSIGN(r1[j], d1[j]);
		x2[j] = s->b * KCOPYSIGN(r2[j], d2[j]);
	}
}

/* log(w_min / w_max) of g^-1(m) (below) and which component is larger. */
static inline void KFN(se_gradinv_ratio)(const KSHAPE2 *s, const KV *m1, const KV *m2, KM *pg, KV *al)
{
	KV q[KP];
	KFOR(j) {
		KV p1 = KABS(s->a * m1[j]), p2 = KABS(s->b * m2[j]);
		pg[j] = p1 >= p2;
		KV mx = KSEL(pg[j], p1, p2), mn = KSEL(pg[j], p2, p1);
		q[j] = mn / KFN(kmax)(mx, KSPLAT(KTINY));
	}
	KFOR(j) al[j] = KLOG(q[j]) * s->inv2me;
}

/* Theorem 2's f~~(m) for a gradient direction m: u = g^-1(m)/|g^-1(m)|,
 * x = f(u), with g^-1(m)_i proportional to (a_i |m_i|)^(1/(2-eps)). */
static inline void KFN(se_gradinv)(const KSHAPE2 *s, const KV *m1, const KV *m2, KV *x1, KV *x2)
{
	if (s->ellipse) { KFN(se_support)(s, m1, m2, x1, x2); return; }
	KM pg[KP];
	KV al[KP], L[KP], xmax[KP], xmin[KP];
	KFN(se_gradinv_ratio)(s, m1, m2, pg, al);      /* log(w_min / w_max) */
	KFOR(j) L[j] = KEXP(2.0 * al[j]);
	KFOR(j) L[j] = KLOG1P1(L[j]);                 /* log(|w|^2 / w_max^2) */
	KFOR(j) xmax[j] = KEXP(KC(-0.5 * s->eps) * L[j]); /* u_max^eps */
	KFOR(j) xmin[j] = KEXP(s->eps * (al[j] - 0.5 * L[j]));
	KFOR(j) {
		x1[j] = s->a * KCOPYSIGN(KSEL(pg[j], xmax[j], xmin[j]), m1[j]);
		x2[j] = s->b * KCOPYSIGN(KSEL(pg[j], xmin[j], xmax[j]), m2[j]);
	}
}

/* log |u_i| of the unit parameter u = g^-1(m)/|g^-1(m)| of the point that
 * se_gradinv finds (Lemma 1's Phi is |g(u)|, whose powers 2-eps must act on
 * these logarithms: u_i itself may underflow where u_i^(2-eps) does not). */
static inline void KFN(se_gradinv_logs)(const KSHAPE2 *s, const KV *m1, const KV *m2, KV *l1, KV *l2)
{
	KM pg[KP];
	KV al[KP], lmax[KP];
	KFN(se_gradinv_ratio)(s, m1, m2, pg, al);
	KFOR(j) lmax[j] = KEXP(2.0 * al[j]);
	KFOR(j) lmax[j] = KC(-0.5) * KLOG1P1(lmax[j]);
	KFOR(j) {
		l1[j] = KSEL(pg[j], lmax[j], al[j] + lmax[j]);
		l2[j] = KSEL(pg[j], al[j] + lmax[j], lmax[j]);
	}
}

static inline void KFN(se_dir)(const KSHAPE2 *s, int form, const KV *d1, const KV *d2, KV *x1, KV *x2)
{
	if (form == MK_FORM_NORMAL) KFN(se_support)(s, d1, d2, x1, x2);
	else KFN(se_gradinv)(s, d1, d2, x1, x2);
}

/* Load KP lane vectors of parameters and make them unit length. */
static inline void KFN(load_unit2)(const KIO *pux, const KIO *puy, KV *u1, KV *u2)
{
#ifdef KLOAD_UNIT2
	KFOR(j) KLOAD_UNIT2(j * KW, pux, puy, u1[j], u2[j]);
#else
	KFOR(j) {
		u1[j] = KLOAD(pux + j * KW); u2[j] = KLOAD(puy + j * KW);
		/* Only the direction of u counts. A unit vector (to rounding) is
		 * used as given, so the caller's parameters are not moved by an
		 * ulp; others are scaled, by the largest component first so that
		 * no square under- or overflows. */
		KM unit = KABS(u1[j] * u1[j] + u2[j] * u2[j] - KC(1.0)) <= KSPLAT(KUNIT_TOL);
		if (!KALL(unit)) {
			KV m = KFN(kmax)(KABS(u1[j]), KABS(u2[j]));
			KV v1 = u1[j] / m, v2 = u2[j] / m;
			KV inv = KC(1.0) / KSQRT(v1 * v1 + v2 * v2);
			u1[j] = KSEL(unit, u1[j], v1 * inv); u2[j] = KSEL(unit, u2[j], v2 * inv);
		}
	}
#endif
}

/* KP * KW points: pux[0 .. KP*KW) and so on. */
static inline void KFN(block2)(const KPLAN2 *p, const KIO *pux, const KIO *puy,
	KIO *px, KIO *py, KIO *pkx, KIO *pky)
{
	KV u1[KP], u2[KP];
	KFN(load_unit2)(pux, puy, u1, u2);
	KV x1[KP], x2[KP], v1[KP], v2[KP]; /* v: B1's gradient (surface) or the normal */
	if (p->param == MK_PARAM_SURFACE) {
		KFN(se_surface)(&p->s1, u1, u2, x1, x2, v1, v2);
	} else {
		KV d1[KP], d2[KP];
		KFOR(j) {
			d1[j] = p->M1T[0][0] * u1[j] + p->M1T[0][1] * u2[j];
			d2[j] = p->M1T[1][0] * u1[j] + p->M1T[1][1] * u2[j];
			v1[j] = u1[j]; v2[j] = u2[j];
		}
		KFN(se_dir)(&p->s1, p->form, d1, d2, x1, x2);
	}
	KV e1[KP], e2[KP], y1[KP], y2[KP];
	KFOR(j) {
		e1[j] = p->D2[0][0] * v1[j] + p->D2[0][1] * v2[j];
		e2[j] = p->D2[1][0] * v1[j] + p->D2[1][1] * v2[j];
	}
	KFN(se_dir)(&p->s2, p->form, e1, e2, y1, y2);
	KFOR(j) {
		KV k1 = p->t1[0] + (p->M1[0][0] * x1[j] + p->M1[0][1] * x2[j]);
		KV k2 = p->t1[1] + (p->M1[1][0] * x1[j] + p->M1[1][1] * x2[j]);
		KV o1 = p->sigma * (p->M2[0][0] * y1[j] + p->M2[0][1] * y2[j]) + p->t2p[0];
		KV o2 = p->sigma * (p->M2[1][0] * y1[j] + p->M2[1][1] * y2[j]) + p->t2p[1];
		KSTORE(px + j * KW, k1 + o1);
		KSTORE(py + j * KW, k2 + o2);
		if (pkx) { KSTORE(pkx + j * KW, k1); KSTORE(pky + j * KW, k2); }
	}
}

#define KBLK (KW * KP) /* points per block */

void KFN(mkK2_Run)(const KPLAN2 *p, const KIO *ux, const KIO *uy, int n,
	KIO *x, KIO *y, KIO *kx, KIO *ky)
{
	int i = 0;
	for (; i + KBLK <= n; i += KBLK)
		KFN(block2)(p, ux + i, uy + i, x + i, y + i, kx ? kx + i : NULL, ky ? ky + i : NULL);
	int r = n - i;
	if (r > 0) { /* tail: pad a block with copies of the last input */
		KIO bu[2][KBLK], bo[4][KBLK];
		for (int j = 0; j < KBLK; ++j) {
			int s = i + (j < r ? j : r - 1);
			bu[0][j] = ux[s]; bu[1][j] = uy[s];
		}
		KFN(block2)(p, bu[0], bu[1], bo[0], bo[1], bo[2], bo[3]);
		for (int j = 0; j < r; ++j) {
			x[i + j] = bo[0][j]; y[i + j] = bo[1][j];
			if (kx) { kx[i + j] = bo[2][j]; ky[i + j] = bo[3][j]; }
		}
	}
}

/* ---- 3D ------------------------------------------------------------------ */

/* An ellipsoid's point f(u) = A u and a positive multiple of its gradient,
 * A^-1 u, on one lane vector (A = diag(a, b, c)). */
static inline void KFN(ell_surface3)(const KSHAPE3 *s, KV u1, KV u2, KV u3,
	KV *x1, KV *x2, KV *x3, KV *m1, KV *m2, KV *m3)
{
	*x1 = s->a * u1; *x2 = s->b * u2; *x3 = s->c * u3;
	*m1 = KDIV_AXIS(u1, s, a); *m2 = KDIV_AXIS(u2, s, b); *m3 = KDIV_AXIS(u3, s, c);
}

/* An ellipsoid's support point A^2 d / |A d| on one lane vector (any d:
 * ell_fix for the rare lanes out of range). */
static inline void KFN(ell_support3)(const KSHAPE3 *s, KV d1, KV d2, KV d3, KV *x1, KV *x2, KV *x3)
{
	KV v1 = s->a * d1, v2 = s->b * d2, v3 = s->c * d3;
	KV ss = v1 * v1 + v2 * v2 + v3 * v3;
	KV inv = KRSQRT(ss);
	*x1 = s->a * v1 * inv; *x2 = s->b * v2 * inv; *x3 = s->c * v3 * inv;
	if (!KALL(ss >= KSPLAT(KTINY)) || !KALL(ss <= KSPLAT(1.0 / KTINY)))
		KFN(ell_fix)(s->a, s->b, s->c, ss, v1, v2, v3, x1, x2, x3);
}

static inline void KFN(sq_surface)(const KSHAPE3 *s, const KV *u1, const KV *u2, const KV *u3,
	KV *x1, KV *x2, KV *x3, KV *m1, KV *m2, KV *m3)
{
	if (s->ellipse) {
		KFOR(j) KFN(ell_surface3)(s, u1[j], u2[j], u3[j], &x1[j], &x2[j], &x3[j], &m1[j], &m2[j], &m3[j]);
		return;
	}
	/* rho = cos(eta) and (cw, sw) = (cos, sin)(omega) come from u1, u2 directly,
	 * never as 1 - u3^2. */
	KV rho[KP], cw[KP], sw[KP], lrho[KP], lc[KP], ls[KP], l3[KP];
	KFOR(j) {
		rho[j] = KSQRT(u1[j] * u1[j] + u2[j] * u2[j]);
		KV rs = KFN(kmax)(rho[j], KSPLAT(KTINY));
		cw[j] = KABS(u1[j]) / rs; sw[j] = KABS(u2[j]) / rs;
	}
	KFOR(j) lrho[j] = KLOG(rho[j]);
	KFOR(j) lc[j] = KLOG(cw[j]);
	KFOR(j) ls[j] = KLOG(sw[j]);
	KFOR(j) l3[j] = KLOG(KABS(u3[j]));
	KFOR(j) x1[j] = s->a * KCOPYSIGN(KEXP(s->e1 * lrho[j] + s->e2 * lc[j]), u1[j]);
	KFOR(j) x2[j] = s->b * KCOPYSIGN(KEXP(s->e1 * lrho[j] + s->e2 * ls[j]), u2[j]);
	KFOR(j) x3[j] = s->c * KCOPYSIGN(KEXP(s->e1 * l3[j]), u3[j]);
	/* g(u) (paper eq. 3d_sq_m_u up to the factor 2/e1): its components are
	 * rho^(2-e1) cw^(2-e2)/a = u1^2/x1, likewise u2^2/x2 and u3^2/x3, as in
	 * 2D; a zero x_i (an axis or a pole) gives a zero component. */
	KFOR(j) {
		KM z1 = x1[j] == 0.0, z2 = x2[j] == 0.0, z3 = x3[j] == 0.0;
		m1[j] = KSEL(z1, KSPLAT(0.0), (u1[j] / KSEL(z1, KSPLAT(1.0), x1[j])) * u1[j]);
		m2[j] = KSEL(z2, KSPLAT(0.0), (u2[j] / KSEL(z2, KSPLAT(1.0), x2[j])) * u2[j]);
		m3[j] = KSEL(z3, KSPLAT(0.0), (u3[j] / KSEL(z3, KSPLAT(1.0), x3[j])) * u3[j]);
	}
}

/* Support point of the nested norm: inner l_q2 over (x, y), outer l_q1. */
static inline void KFN(sq_support)(const KSHAPE3 *s, const KV *d1, const KV *d2, const KV *d3,
	KV *x1, KV *x2, KV *x3)
{
	if (s->ellipse) {
		KFOR(j) KFN(ell_support3)(s, d1[j], d2[j], d3[j], &x1[j], &x2[j], &x3[j]);
		return;
	}
	KV p1[KP], p2[KP], p3[KP], r1[KP], r2[KP], mx[KP], L[KP], g[KP], rg[KP], r3[KP], mxo[KP], Lo[KP];
	KFOR(j) { p1[j] = KABS(s->a * d1[j]); p2[j] = KABS(s->b * d2[j]); p3[j] = KABS(s->c * d3[j]); }
	KFN(pair_dual)(p1, p2, s->q2m1, s->k2, r1, r2, mx, L);
	KFOR(j) g[j] = mx[j] * KEXP(L[j] * s->invq2); /* |(u1, u2)|_q2 */
	KFN(pair_dual)(g, p3, s->q1m1, s->k1, rg, r3, mxo, Lo);
	KFOR(j) {
		x1[j] = s->a * KCOPYSIGN(rg[j] * r1[j], d1[j]);
		x2[j] = s->b * KCOPYSIGN(rg[j] * r2[j], d2[j]);
		x3[j] = s->c * KCOPYSIGN(r3[j], d3[j]);
	}
}

/* f~~(m) through g^-1 (paper eq. 3d_sq_u_m), normalised, then f. With
 * p = (a|m1|, b|m2|, c|m3|): w12 = |(w1, w2)| and w3 are compared in the log
 * domain, D = log(w12/w3), and cos(eta), sin(eta) follow from D alone. */
/* The logarithms of the unit parameter of the point whose gradient is
 * parallel to m: log cos(eta), log |sin(eta)|, log |cos(omega)|, log |sin(omega)|. */
static inline void KFN(sq_gradinv_logs)(const KSHAPE3 *s, const KV *m1, const KV *m2, const KV *m3,
	KV *lrho, KV *l3, KV *lc1, KV *lc2)
{
	KM pg[KP];
	KV P12[KP], P[KP], p3[KP], q[KP], al[KP], L12[KP], t12[KP], t3[KP], D[KP], le[KP];
	KFOR(j) {
		KV p1 = KABS(s->a * m1[j]), p2 = KABS(s->b * m2[j]);
		p3[j] = KABS(s->c * m3[j]);
		pg[j] = p1 >= p2;
		P12[j] = KSEL(pg[j], p1, p2);
		KV mn = KSEL(pg[j], p2, p1);
		P[j] = KFN(kmax)(P12[j], p3[j]);
		q[j] = mn / KFN(kmax)(P12[j], KSPLAT(KTINY));
	}
	KFOR(j) al[j] = KLOG(q[j]) * s->inv2me2;  /* log(w_min / w_max) in the inner pair */
	KFOR(j) L12[j] = KEXP(2.0 * al[j]);
	KFOR(j) L12[j] = KLOG1P1(L12[j]);
	/* A zero direction (possible: B2's direction is B1's gradient through
	 * D2, which can round to 0 when the two maps together are close to
	 * singular) takes sq_support's convention, the larger of two equal
	 * components being the first: P12 counts as the larger, t12 = 0,
	 * t3 = -inf (the point (a, 0, 0)); for P > 0 both are unchanged. */
	KFOR(j) P[j] = KSEL(P[j] > 0.0, P[j], KSPLAT(1.0));
	KFOR(j) t12[j] = KLOG(P12[j] / P[j]);
	KFOR(j) t3[j] = KLOG(p3[j] / P[j]);
	KFOR(j) {
		t12[j] = KSEL(P12[j] >= p3[j], KSPLAT(0.0), t12[j]);
		D[j] = (t12[j] - t3[j] + KC(0.5 * s->twome2) * L12[j]) * s->inv2me1;
		le[j] = KC(-2.0) * KABS(D[j]);
	}
	KFOR(j) le[j] = KEXP(le[j]);
	KFOR(j) le[j] = KLOG1P1(le[j]);
	KFOR(j) {
		KM dpos = D[j] >= 0.0;
		lrho[j] = KSEL(dpos, KC(-0.5) * le[j], D[j] - 0.5 * le[j]); /* log cos(eta) */
		l3[j] = KSEL(dpos, -D[j] - 0.5 * le[j], KC(-0.5) * le[j]);  /* log |sin(eta)| */
		KV lcmax = KC(-0.5) * L12[j], lcmin = al[j] - 0.5 * L12[j]; /* log cos/sin(omega) */
		lc1[j] = KSEL(pg[j], lcmax, lcmin);
		lc2[j] = KSEL(pg[j], lcmin, lcmax);
	}
}

static inline void KFN(sq_gradinv)(const KSHAPE3 *s, const KV *m1, const KV *m2, const KV *m3,
	KV *x1, KV *x2, KV *x3)
{
	if (s->ellipse) { KFN(sq_support)(s, m1, m2, m3, x1, x2, x3); return; }
	KV lrho[KP], l3[KP], lc1[KP], lc2[KP];
	KFN(sq_gradinv_logs)(s, m1, m2, m3, lrho, l3, lc1, lc2);
	KFOR(j) x1[j] = s->a * KCOPYSIGN(KEXP(s->e1 * lrho[j] + s->e2 * lc1[j]), m1[j]);
	KFOR(j) x2[j] = s->b * KCOPYSIGN(KEXP(s->e1 * lrho[j] + s->e2 * lc2[j]), m2[j]);
	KFOR(j) x3[j] = s->c * KCOPYSIGN(KEXP(s->e1 * l3[j]), m3[j]);
}

static inline void KFN(sq_dir)(const KSHAPE3 *s, int form, const KV *d1, const KV *d2, const KV *d3,
	KV *x1, KV *x2, KV *x3)
{
	if (form == MK_FORM_NORMAL) KFN(sq_support)(s, d1, d2, d3, x1, x2, x3);
	else KFN(sq_gradinv)(s, d1, d2, d3, x1, x2, x3);
}

#define KMV3(A, v1, v2, v3, i) ((A)[i][0] * (v1) + (A)[i][1] * (v2) + (A)[i][2] * (v3))

/* As load_unit2, for one lane vector. */
static inline void KFN(load_unit3_one)(const KIO *pux, const KIO *puy, const KIO *puz, KV *u1, KV *u2, KV *u3)
{
#ifdef KLOAD_UNIT3
	KLOAD_UNIT3(0, pux, puy, puz, *u1, *u2, *u3);
#else
	*u1 = KLOAD(pux); *u2 = KLOAD(puy); *u3 = KLOAD(puz);
	KM unit = KABS(*u1 * *u1 + *u2 * *u2 + *u3 * *u3 - KC(1.0)) <= KSPLAT(KUNIT_TOL);
	if (!KALL(unit)) {
		KV m = KFN(kmax)(KFN(kmax)(KABS(*u1), KABS(*u2)), KABS(*u3));
		KV v1 = *u1 / m, v2 = *u2 / m, v3 = *u3 / m;
		KV inv = KC(1.0) / KSQRT(v1 * v1 + v2 * v2 + v3 * v3);
		*u1 = KSEL(unit, *u1, v1 * inv);
		*u2 = KSEL(unit, *u2, v2 * inv);
		*u3 = KSEL(unit, *u3, v3 * inv);
	}
#endif
}

static inline void KFN(load_unit3)(const KIO *pux, const KIO *puy, const KIO *puz, KV *u1, KV *u2, KV *u3)
{
	KFOR(j) KFN(load_unit3_one)(pux + j * KW, puy + j * KW, puz + j * KW, &u1[j], &u2[j], &u3[j]);
}

/* block3 for a pair of ellipsoids: nothing out of line to overlap, so each
 * lane vector goes through the whole pipeline before the next, which keeps
 * its values in registers (the interleaved block spills them with 16 float
 * lanes). Per lane the same operations in the same order as block3. Its
 * sums and stores repeat block3's on purpose: as a shared inline helper
 * GCC 12 did not inline them here in the f32 build, and 3D EE on double
 * arrays went from 2.25 to 2.75 ns per point. */
static inline void KFN(block3_ee)(const KPLAN3 *p, const KIO *pux, const KIO *puy, const KIO *puz,
	KIO *px, KIO *py, KIO *pz, KIO *pkx, KIO *pky, KIO *pkz)
{
	_Pragma("GCC unroll 1") for (int j = 0; j < KP; ++j) {
		int o = j * KW;
		KV u1, u2, u3, x1, x2, x3, v1, v2, v3, y1, y2, y3;
		KFN(load_unit3_one)(pux + o, puy + o, puz + o, &u1, &u2, &u3);
		if (p->param == MK_PARAM_SURFACE) {
			KFN(ell_surface3)(&p->s1, u1, u2, u3, &x1, &x2, &x3, &v1, &v2, &v3);
		} else {
			KFN(ell_support3)(&p->s1, KMV3(p->M1T, u1, u2, u3, 0), KMV3(p->M1T, u1, u2, u3, 1),
				KMV3(p->M1T, u1, u2, u3, 2), &x1, &x2, &x3);
			v1 = u1; v2 = u2; v3 = u3;
		}
		KFN(ell_support3)(&p->s2, KMV3(p->D2, v1, v2, v3, 0), KMV3(p->D2, v1, v2, v3, 1),
			KMV3(p->D2, v1, v2, v3, 2), &y1, &y2, &y3);
		KV k1 = p->t1[0] + KMV3(p->M1, x1, x2, x3, 0);
		KV k2 = p->t1[1] + KMV3(p->M1, x1, x2, x3, 1);
		KV k3 = p->t1[2] + KMV3(p->M1, x1, x2, x3, 2);
		KSTORE(px + o, k1 + (p->sigma * KMV3(p->M2, y1, y2, y3, 0) + p->t2p[0]));
		KSTORE(py + o, k2 + (p->sigma * KMV3(p->M2, y1, y2, y3, 1) + p->t2p[1]));
		KSTORE(pz + o, k3 + (p->sigma * KMV3(p->M2, y1, y2, y3, 2) + p->t2p[2]));
		if (pkx) { KSTORE(pkx + o, k1); KSTORE(pky + o, k2); KSTORE(pkz + o, k3); }
	}
}

static inline void KFN(block3)(const KPLAN3 *p, const KIO *pux, const KIO *puy, const KIO *puz,
	KIO *px, KIO *py, KIO *pz, KIO *pkx, KIO *pky, KIO *pkz)
{
	if (p->s1.ellipse && p->s2.ellipse) {
		KFN(block3_ee)(p, pux, puy, puz, px, py, pz, pkx, pky, pkz);
		return;
	}
	KV u1[KP], u2[KP], u3[KP];
	KFN(load_unit3)(pux, puy, puz, u1, u2, u3);
	KV x1[KP], x2[KP], x3[KP], v1[KP], v2[KP], v3[KP];
	if (p->param == MK_PARAM_SURFACE) {
		KFN(sq_surface)(&p->s1, u1, u2, u3, x1, x2, x3, v1, v2, v3);
	} else {
		KV d1[KP], d2[KP], d3[KP];
		KFOR(j) {
			d1[j] = KMV3(p->M1T, u1[j], u2[j], u3[j], 0);
			d2[j] = KMV3(p->M1T, u1[j], u2[j], u3[j], 1);
			d3[j] = KMV3(p->M1T, u1[j], u2[j], u3[j], 2);
			v1[j] = u1[j]; v2[j] = u2[j]; v3[j] = u3[j];
		}
		KFN(sq_dir)(&p->s1, p->form, d1, d2, d3, x1, x2, x3);
	}
	KV e1[KP], e2[KP], e3[KP], y1[KP], y2[KP], y3[KP];
	KFOR(j) {
		e1[j] = KMV3(p->D2, v1[j], v2[j], v3[j], 0);
		e2[j] = KMV3(p->D2, v1[j], v2[j], v3[j], 1);
		e3[j] = KMV3(p->D2, v1[j], v2[j], v3[j], 2);
	}
	KFN(sq_dir)(&p->s2, p->form, e1, e2, e3, y1, y2, y3);
	KFOR(j) {
		KV k1 = p->t1[0] + KMV3(p->M1, x1[j], x2[j], x3[j], 0);
		KV k2 = p->t1[1] + KMV3(p->M1, x1[j], x2[j], x3[j], 1);
		KV k3 = p->t1[2] + KMV3(p->M1, x1[j], x2[j], x3[j], 2);
		KSTORE(px + j * KW, k1 + (p->sigma * KMV3(p->M2, y1[j], y2[j], y3[j], 0) + p->t2p[0]));
		KSTORE(py + j * KW, k2 + (p->sigma * KMV3(p->M2, y1[j], y2[j], y3[j], 1) + p->t2p[1]));
		KSTORE(pz + j * KW, k3 + (p->sigma * KMV3(p->M2, y1[j], y2[j], y3[j], 2) + p->t2p[2]));
		if (pkx) { KSTORE(pkx + j * KW, k1); KSTORE(pky + j * KW, k2); KSTORE(pkz + j * KW, k3); }
	}
}

void KFN(mkK3_Run)(const KPLAN3 *p, const KIO *ux, const KIO *uy, const KIO *uz, int n,
	KIO *x, KIO *y, KIO *z, KIO *kx, KIO *ky, KIO *kz)
{
	int i = 0;
	for (; i + KBLK <= n; i += KBLK)
		KFN(block3)(p, ux + i, uy + i, uz + i, x + i, y + i, z + i,
			kx ? kx + i : NULL, ky ? ky + i : NULL, kz ? kz + i : NULL);
	int r = n - i;
	if (r > 0) {
		KIO bu[3][KBLK], bo[6][KBLK];
		for (int j = 0; j < KBLK; ++j) {
			int s = i + (j < r ? j : r - 1);
			bu[0][j] = ux[s]; bu[1][j] = uy[s]; bu[2][j] = uz[s];
		}
		KFN(block3)(p, bu[0], bu[1], bu[2], bo[0], bo[1], bo[2], bo[3], bo[4], bo[5]);
		for (int j = 0; j < r; ++j) {
			x[i + j] = bo[0][j]; y[i + j] = bo[1][j]; z[i + j] = bo[2][j];
			if (kx) { kx[i + j] = bo[3][j]; ky[i + j] = bo[4][j]; kz[i + j] = bo[5][j]; }
		}
	}
}

/* ---- the two halves of a surface-parameter batch --------------------------
 * For a caller that sums one body B1 against many poses of B2 (Table 2's
 * workload: one obstacle, thousands of robot orientations): B1's half of
 * block2/block3 (the unit parameter, B1's point f(u) and gradient g(u), in
 * its own frame) is computed once per body, and B2's half (f~ or f~~ of
 * given directions, `form`) over long arrays that hold many poses back to
 * back, so that the tail block's padding is paid once per array instead of
 * once per pose. Per lane the arithmetic is exactly block2's/block3's: a
 * caller that forms the directions D2 g and the sums t1 + M1 x +
 * (sigma M2 y + t2p) with the same products in the same order gets the same
 * bits as mkSum2_Batch/mkSum3_Batch (tested in core.test_sum_split). Only
 * the double builds (KHALVES) have them. A tail shorter than a block is
 * padded with copies of the last input, as in mkK2_Run. */
#ifdef KHALVES

void KFN(mkK2_SurfaceRun)(const KSHAPE2 *s, const double *ux, const double *uy, int n,
	double *x1, double *x2, double *g1, double *g2)
{
	double bu[2][KBLK], bo[4][KBLK];
	for (int i = 0; i < n; i += KBLK) {
		int r = n - i < KBLK ? n - i : KBLK;
		const double *pu1 = ux + i, *pu2 = uy + i;
		if (r < KBLK) {
			for (int j = 0; j < KBLK; ++j) {
				int t = i + (j < r ? j : r - 1);
				bu[0][j] = ux[t]; bu[1][j] = uy[t];
			}
			pu1 = bu[0]; pu2 = bu[1];
		}
		KV u1[KP], u2[KP], a1[KP], a2[KP], m1[KP], m2[KP];
		KFN(load_unit2)(pu1, pu2, u1, u2);
		KFN(se_surface)(s, u1, u2, a1, a2, m1, m2);
		KFOR(j) {
			KSTORE(bo[0] + j * KW, a1[j]); KSTORE(bo[1] + j * KW, a2[j]);
			KSTORE(bo[2] + j * KW, m1[j]); KSTORE(bo[3] + j * KW, m2[j]);
		}
		for (int j = 0; j < r; ++j) {
			x1[i + j] = bo[0][j]; x2[i + j] = bo[1][j];
			g1[i + j] = bo[2][j]; g2[i + j] = bo[3][j];
		}
	}
}

void KFN(mkK2_DirRun)(const KSHAPE2 *s, int form, const double *d1, const double *d2, int n,
	double *x1, double *x2)
{
	int i = 0;
	for (; i + KBLK <= n; i += KBLK) {
		KV e1[KP], e2[KP], y1[KP], y2[KP];
		KFOR(j) { e1[j] = KLOAD(d1 + i + j * KW); e2[j] = KLOAD(d2 + i + j * KW); }
		KFN(se_dir)(s, form, e1, e2, y1, y2);
		KFOR(j) { KSTORE(x1 + i + j * KW, y1[j]); KSTORE(x2 + i + j * KW, y2[j]); }
	}
	int r = n - i;
	if (r > 0) {
		double bd[2][KBLK], bo[2][KBLK];
		for (int j = 0; j < KBLK; ++j) {
			int t = i + (j < r ? j : r - 1);
			bd[0][j] = d1[t]; bd[1][j] = d2[t];
		}
		KV e1[KP], e2[KP], y1[KP], y2[KP];
		KFOR(j) { e1[j] = KLOAD(bd[0] + j * KW); e2[j] = KLOAD(bd[1] + j * KW); }
		KFN(se_dir)(s, form, e1, e2, y1, y2);
		KFOR(j) { KSTORE(bo[0] + j * KW, y1[j]); KSTORE(bo[1] + j * KW, y2[j]); }
		for (int j = 0; j < r; ++j) { x1[i + j] = bo[0][j]; x2[i + j] = bo[1][j]; }
	}
}

void KFN(mkK3_SurfaceRun)(const KSHAPE3 *s, const double *ux, const double *uy, const double *uz, int n,
	double *x1, double *x2, double *x3, double *g1, double *g2, double *g3)
{
	double bu[3][KBLK], bo[6][KBLK];
	for (int i = 0; i < n; i += KBLK) {
		int r = n - i < KBLK ? n - i : KBLK;
		const double *pu1 = ux + i, *pu2 = uy + i, *pu3 = uz + i;
		if (r < KBLK) {
			for (int j = 0; j < KBLK; ++j) {
				int t = i + (j < r ? j : r - 1);
				bu[0][j] = ux[t]; bu[1][j] = uy[t]; bu[2][j] = uz[t];
			}
			pu1 = bu[0]; pu2 = bu[1]; pu3 = bu[2];
		}
		KV u1[KP], u2[KP], u3[KP], a1[KP], a2[KP], a3[KP], m1[KP], m2[KP], m3[KP];
		KFN(load_unit3)(pu1, pu2, pu3, u1, u2, u3);
		KFN(sq_surface)(s, u1, u2, u3, a1, a2, a3, m1, m2, m3);
		KFOR(j) {
			KSTORE(bo[0] + j * KW, a1[j]); KSTORE(bo[1] + j * KW, a2[j]); KSTORE(bo[2] + j * KW, a3[j]);
			KSTORE(bo[3] + j * KW, m1[j]); KSTORE(bo[4] + j * KW, m2[j]); KSTORE(bo[5] + j * KW, m3[j]);
		}
		for (int j = 0; j < r; ++j) {
			x1[i + j] = bo[0][j]; x2[i + j] = bo[1][j]; x3[i + j] = bo[2][j];
			g1[i + j] = bo[3][j]; g2[i + j] = bo[4][j]; g3[i + j] = bo[5][j];
		}
	}
}

void KFN(mkK3_DirRun)(const KSHAPE3 *s, int form, const double *d1, const double *d2, const double *d3, int n,
	double *x1, double *x2, double *x3)
{
	int i = 0;
	for (; i + KBLK <= n; i += KBLK) {
		KV e1[KP], e2[KP], e3[KP], y1[KP], y2[KP], y3[KP];
		KFOR(j) {
			e1[j] = KLOAD(d1 + i + j * KW); e2[j] = KLOAD(d2 + i + j * KW); e3[j] = KLOAD(d3 + i + j * KW);
		}
		KFN(sq_dir)(s, form, e1, e2, e3, y1, y2, y3);
		KFOR(j) {
			KSTORE(x1 + i + j * KW, y1[j]); KSTORE(x2 + i + j * KW, y2[j]); KSTORE(x3 + i + j * KW, y3[j]);
		}
	}
	int r = n - i;
	if (r > 0) {
		double bd[3][KBLK], bo[3][KBLK];
		for (int j = 0; j < KBLK; ++j) {
			int t = i + (j < r ? j : r - 1);
			bd[0][j] = d1[t]; bd[1][j] = d2[t]; bd[2][j] = d3[t];
		}
		KV e1[KP], e2[KP], e3[KP], y1[KP], y2[KP], y3[KP];
		KFOR(j) { e1[j] = KLOAD(bd[0] + j * KW); e2[j] = KLOAD(bd[1] + j * KW); e3[j] = KLOAD(bd[2] + j * KW); }
		KFN(sq_dir)(s, form, e1, e2, e3, y1, y2, y3);
		KFOR(j) { KSTORE(bo[0] + j * KW, y1[j]); KSTORE(bo[1] + j * KW, y2[j]); KSTORE(bo[2] + j * KW, y3[j]); }
		for (int j = 0; j < r; ++j) { x1[i + j] = bo[0][j]; x2[i + j] = bo[1][j]; x3[i + j] = bo[2][j]; }
	}
}

/* o = A v over n points (block2's/block3's e = D2 v), lane vectors while
 * KW points remain, then one point at a time: the same products either way. */
static void KFN(apply2)(const double A[2][2], const double *v1, const double *v2, int n, double *o1, double *o2)
{
	int i = 0;
	for (; i + KW <= n; i += KW) {
		KV a = KLOAD(v1 + i), b = KLOAD(v2 + i);
		KSTORE(o1 + i, A[0][0] * a + A[0][1] * b);
		KSTORE(o2 + i, A[1][0] * a + A[1][1] * b);
	}
	for (; i < n; ++i) {
		double a = v1[i], b = v2[i];
		o1[i] = A[0][0] * a + A[0][1] * b;
		o2[i] = A[1][0] * a + A[1][1] * b;
	}
}

static void KFN(apply3)(const double A[3][3], const double *v1, const double *v2, const double *v3, int n,
	double *o1, double *o2, double *o3)
{
	int i = 0;
	for (; i + KW <= n; i += KW) {
		KV a = KLOAD(v1 + i), b = KLOAD(v2 + i), c = KLOAD(v3 + i);
		KSTORE(o1 + i, KMV3(A, a, b, c, 0));
		KSTORE(o2 + i, KMV3(A, a, b, c, 1));
		KSTORE(o3 + i, KMV3(A, a, b, c, 2));
	}
	for (; i < n; ++i) {
		double a = v1[i], b = v2[i], c = v3[i];
		o1[i] = KMV3(A, a, b, c, 0);
		o2[i] = KMV3(A, a, b, c, 1);
		o3[i] = KMV3(A, a, b, c, 2);
	}
}

/* m poses of B2 against B1's half (k: t1 + M1 f(u), g: the gradients, n
 * each): pose o's directions D2[o] g, B2's half over all n m of them, and
 * the points k + (sigma M2[o] y + t2p), as block2 forms them, at
 * x[o n ..], y[o n ..]. scratch: 2 n m doubles. */
void KFN(mkK2_PoseRun)(const KSHAPE2 *s2, int form, const double *k1, const double *k2, const double *g1,
	const double *g2, int n, const double (*D2)[2][2], const double (*M2)[2][2], double sigma, const double *t2p,
	int m, double *scratch, double *x, double *y)
{
	const long nm = (long)n * m;
	double *e1 = scratch, *e2 = scratch + nm;
	for (int o = 0; o < m; ++o) KFN(apply2)(D2[o], g1, g2, n, e1 + (long)o * n, e2 + (long)o * n);
	KFN(mkK2_DirRun)(s2, form, e1, e2, (int)nm, e1, e2);
	for (int o = 0; o < m; ++o) {
		const double (*A)[2] = M2[o];
		const double *y1 = e1 + (long)o * n, *y2 = e2 + (long)o * n;
		double *px = x + (long)o * n, *py = y + (long)o * n;
		int i = 0;
		for (; i + KW <= n; i += KW) {
			KV a = KLOAD(y1 + i), b = KLOAD(y2 + i);
			KV o1 = sigma * (A[0][0] * a + A[0][1] * b) + t2p[0];
			KV o2 = sigma * (A[1][0] * a + A[1][1] * b) + t2p[1];
			KSTORE(px + i, KLOAD(k1 + i) + o1);
			KSTORE(py + i, KLOAD(k2 + i) + o2);
		}
		for (; i < n; ++i) {
			double a = y1[i], b = y2[i];
			double o1 = sigma * (A[0][0] * a + A[0][1] * b) + t2p[0];
			double o2 = sigma * (A[1][0] * a + A[1][1] * b) + t2p[1];
			px[i] = k1[i] + o1;
			py[i] = k2[i] + o2;
		}
	}
}

void KFN(mkK3_PoseRun)(const KSHAPE3 *s2, int form, const double *const k[3], const double *const g[3], int n,
	const double (*D2)[3][3], const double (*M2)[3][3], double sigma, const double *t2p, int m, double *scratch,
	double *x, double *y, double *z)
{
	const long nm = (long)n * m;
	double *e1 = scratch, *e2 = scratch + nm, *e3 = scratch + 2 * nm;
	for (int o = 0; o < m; ++o)
		KFN(apply3)(D2[o], g[0], g[1], g[2], n, e1 + (long)o * n, e2 + (long)o * n, e3 + (long)o * n);
	KFN(mkK3_DirRun)(s2, form, e1, e2, e3, (int)nm, e1, e2, e3);
	for (int o = 0; o < m; ++o) {
		const double (*A)[3] = M2[o];
		const double *y1 = e1 + (long)o * n, *y2 = e2 + (long)o * n, *y3 = e3 + (long)o * n;
		double *px = x + (long)o * n, *py = y + (long)o * n, *pz = z + (long)o * n;
		int i = 0;
		for (; i + KW <= n; i += KW) {
			KV a = KLOAD(y1 + i), b = KLOAD(y2 + i), c = KLOAD(y3 + i);
			KSTORE(px + i, KLOAD(k[0] + i) + (sigma * KMV3(A, a, b, c, 0) + t2p[0]));
			KSTORE(py + i, KLOAD(k[1] + i) + (sigma * KMV3(A, a, b, c, 1) + t2p[1]));
			KSTORE(pz + i, KLOAD(k[2] + i) + (sigma * KMV3(A, a, b, c, 2) + t2p[2]));
		}
		for (; i < n; ++i) {
			double a = y1[i], b = y2[i], c = y3[i];
			px[i] = k[0][i] + (sigma * KMV3(A, a, b, c, 0) + t2p[0]);
			py[i] = k[1][i] + (sigma * KMV3(A, a, b, c, 1) + t2p[1]);
			pz[i] = k[2][i] + (sigma * KMV3(A, a, b, c, 2) + t2p[2]);
		}
	}
}

#endif /* KHALVES */
