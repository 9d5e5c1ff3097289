/* kernel_body.h - the closed-form kernels, written once over a lane type.
 *
 * Included by kernel_scalar.c (one double per lane, libm), kernel_avx2.c
 * (4 lanes, SLEEF) and kernel_avx512.c (8 lanes, SLEEF), each of which first
 * defines:
 *   KV           lane type;  KM  mask type (result of a comparison of KV)
 *   KW           lanes per KV
 *   KEXP KLOG KSQRT             elementwise functions
 *   KABS(v) KCOPYSIGN(mag, s) KSEL(mask, a, b)   (mask ? a : b)
 *   KLOAD(p) KSTORE(p, v)       unaligned load / store of KW doubles
 *   KSPLAT(s)    a lane value with every lane equal to the double s
 *   KALL(mask)   nonzero when the mask holds in every lane
 *   KFN(name)    appends the ISA suffix to a function name
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

#define KTINY 1e-300 /* floor of a divisor that may be exactly zero */
#define KUNIT_TOL 1e-15 /* |u|^2 - 1 of a unit vector rounded to double, with room */

/* log(1 + t) for t in [0, 1]: through log rather than log1p (twice as fast
 * in SLEEF). Rounding 1 + t costs at most half an ulp of 1 in absolute
 * terms, and every such logarithm here only ever enters exp() with a
 * coefficient of at most 1 times the scale of its companions, so the
 * relative error it adds to a point is about 1e-16. */
#define KLOG1P1(t) KLOG(1.0 + (t))

static inline KV KFN(kmax)(KV a, KV b) { return KSEL(a >= b, a, b); }
static inline KV KFN(kmin)(KV a, KV b) { return KSEL(a >= b, b, a); }

/* For a, b >= 0 (not both zero) and q > 1: the dual-norm ratios
 * ra = (a / |(a,b)|_q)^(q-1), rb likewise, and the pieces of the norm,
 * |(a,b)|_q = mx * exp(L / q). With r = min/max <= 1 the ratios are
 * (1 + r^q)^(-(q-1)/q) for the larger and r^(q-1) times that for the
 * smaller: one log, two exp and one log1p. */
static inline void KFN(pair_dual)(KV a, KV b, double qm1, double k,
	KV *ra, KV *rb, KV *mx_out, KV *L_out)
{
	KM agb = a >= b;
	KV mx = KSEL(agb, a, b), mn = KSEL(agb, b, a);
	KV r = mn / KFN(kmax)(mx, KSPLAT(KTINY));
	KV s = KEXP(qm1 * KLOG(r));     /* r^(q-1); 0 for r = 0 */
	KV L = KLOG1P1(s * r);           /* log(1 + r^q) */
	KV cmax = KEXP(-k * L);         /* (1 + r^q)^(-(q-1)/q) */
	*ra = KSEL(agb, cmax, s * cmax);
	*rb = KSEL(agb, s * cmax, cmax);
	*mx_out = mx;
	*L_out = L;
}

/* ---- 2D ------------------------------------------------------------------ */

/* B1's point f(u) and a positive multiple of its gradient g(u). */
static inline void KFN(se_surface)(const mkKShape2 *s, KV u1, KV u2,
	KV *x1, KV *x2, KV *m1, KV *m2)
{
	if (s->ellipse) {
		*x1 = s->a * u1; *x2 = s->b * u2;
		*m1 = u1 / s->a; *m2 = u2 / s->b;
		return;
	}
	KV l1 = KLOG(KABS(u1)), l2 = KLOG(KABS(u2));
	*x1 = s->a * KCOPYSIGN(KEXP(s->eps * l1), u1);
	*x2 = s->b * KCOPYSIGN(KEXP(s->eps * l2), u2);
	/* g_i = sp(u_i, 2-eps)/a_i = u_i^2 / x_i: a division instead of a power.
	 * Where x_i is zero (u_i = 0, or |u_i|^eps below the double range, a
	 * direction within 1e-150 of an axis) the component is taken as 0. */
	KM z1 = *x1 == 0.0, z2 = *x2 == 0.0;
	*m1 = KSEL(z1, KSPLAT(0.0), (u1 / KSEL(z1, KSPLAT(1.0), *x1)) * u1);
	*m2 = KSEL(z2, KSPLAT(0.0), (u2 / KSEL(z2, KSPLAT(1.0), *x2)) * u2);
}

/* Theorem 1's f~(d): the support point in direction d (any nonzero d). */
static inline void KFN(se_support)(const mkKShape2 *s, KV d1, KV d2, KV *x1, KV *x2)
{
	if (s->ellipse) { /* A^2 d / |A d| */
		KV v1 = s->a * d1, v2 = s->b * d2;
		KV inv = 1.0 / KSQRT(v1 * v1 + v2 * v2);
		*x1 = s->a * v1 * inv; *x2 = s->b * v2 * inv;
		return;
	}
	KV r1, r2, mx, L;
	KFN(pair_dual)(KABS(s->a * d1), KABS(s->b * d2), s->qm1, s->k, &r1, &r2, &mx, &L);
	*x1 = s->a * KCOPYSIGN(r1, d1);
	*x2 = s->b * KCOPYSIGN(r2, d2);
}

/* Theorem 2's f~~(m) for a gradient direction m: u = g^-1(m)/|g^-1(m)|,
 * x = f(u), with g^-1(m)_i proportional to (a_i |m_i|)^(1/(2-eps)). */
static inline void KFN(se_gradinv)(const mkKShape2 *s, KV m1, KV m2, KV *x1, KV *x2)
{
	if (s->ellipse) { KFN(se_support)(s, m1, m2, x1, x2); return; }
	KV p1 = KABS(s->a * m1), p2 = KABS(s->b * m2);
	KM pg = p1 >= p2;
	KV mx = KSEL(pg, p1, p2), mn = KSEL(pg, p2, p1);
	KV lr = KLOG(mn / KFN(kmax)(mx, KSPLAT(KTINY)));
	KV al = lr * s->inv2me;              /* log(w_min / w_max) */
	KV L = KLOG1P1(KEXP(2.0 * al));       /* log(|w|^2 / w_max^2) */
	KV xmax = KEXP(-0.5 * s->eps * L);   /* u_max^eps */
	KV xmin = KEXP(s->eps * (al - 0.5 * L));
	*x1 = s->a * KCOPYSIGN(KSEL(pg, xmax, xmin), m1);
	*x2 = s->b * KCOPYSIGN(KSEL(pg, xmin, xmax), m2);
}

/* log |u_i| of the unit parameter u = g^-1(m)/|g^-1(m)| of the point that
 * se_gradinv finds (Lemma 1's Phi is |g(u)|, whose powers 2-eps must act on
 * these logarithms: u_i itself may underflow where u_i^(2-eps) does not). */
static inline void KFN(se_gradinv_logs)(const mkKShape2 *s, KV m1, KV m2, KV *l1, KV *l2)
{
	KV p1 = KABS(s->a * m1), p2 = KABS(s->b * m2);
	KM pg = p1 >= p2;
	KV mx = KSEL(pg, p1, p2), mn = KSEL(pg, p2, p1);
	KV al = KLOG(mn / KFN(kmax)(mx, KSPLAT(KTINY))) * s->inv2me; /* log(w_min / w_max) */
	KV lmax = -0.5 * KLOG1P1(KEXP(2.0 * al));
	*l1 = KSEL(pg, lmax, al + lmax);
	*l2 = KSEL(pg, al + lmax, lmax);
}

static inline void KFN(se_dir)(const mkKShape2 *s, int form, KV d1, KV d2, KV *x1, KV *x2)
{
	if (form == MK_FORM_NORMAL) KFN(se_support)(s, d1, d2, x1, x2);
	else KFN(se_gradinv)(s, d1, d2, x1, x2);
}

static inline void KFN(block2)(const mkKPlan2 *p, const double *pux, const double *puy,
	double *px, double *py, double *pkx, double *pky)
{
	KV u1 = KLOAD(pux), u2 = KLOAD(puy);
	{ /* Only the direction of u counts. A unit vector (to rounding) is used
	   * as given, so the caller's parameters are not moved by an ulp;
	   * others are scaled, by the largest component first so that no square
	   * under- or overflows. */
		KM unit = KABS(u1 * u1 + u2 * u2 - 1.0) <= KSPLAT(KUNIT_TOL);
		if (!KALL(unit)) {
			KV m = KFN(kmax)(KABS(u1), KABS(u2));
			KV v1 = u1 / m, v2 = u2 / m;
			KV inv = 1.0 / KSQRT(v1 * v1 + v2 * v2);
			u1 = KSEL(unit, u1, v1 * inv); u2 = KSEL(unit, u2, v2 * inv);
		}
	}
	KV x1, x2, v1 = u1, v2 = u2; /* v: B1's gradient (surface) or the normal */
	if (p->param == MK_PARAM_SURFACE) {
		KFN(se_surface)(&p->s1, u1, u2, &x1, &x2, &v1, &v2);
	} else {
		KV d1 = p->M1T[0][0] * u1 + p->M1T[0][1] * u2;
		KV d2 = p->M1T[1][0] * u1 + p->M1T[1][1] * u2;
		KFN(se_dir)(&p->s1, p->form, d1, d2, &x1, &x2);
	}
	KV k1 = p->t1[0] + (p->M1[0][0] * x1 + p->M1[0][1] * x2);
	KV k2 = p->t1[1] + (p->M1[1][0] * x1 + p->M1[1][1] * x2);
	KV e1 = p->D2[0][0] * v1 + p->D2[0][1] * v2;
	KV e2 = p->D2[1][0] * v1 + p->D2[1][1] * v2;
	KV y1, y2;
	KFN(se_dir)(&p->s2, p->form, e1, e2, &y1, &y2);
	KV o1 = p->sigma * (p->M2[0][0] * y1 + p->M2[0][1] * y2) + p->t2p[0];
	KV o2 = p->sigma * (p->M2[1][0] * y1 + p->M2[1][1] * y2) + p->t2p[1];
	KSTORE(px, k1 + o1);
	KSTORE(py, k2 + o2);
	if (pkx) { KSTORE(pkx, k1); KSTORE(pky, k2); }
}

void KFN(mkK2_Run)(const mkKPlan2 *p, const double *ux, const double *uy, int n,
	double *x, double *y, double *kx, double *ky)
{
	int i = 0;
	for (; i + KW <= n; i += KW)
		KFN(block2)(p, ux + i, uy + i, x + i, y + i, kx ? kx + i : NULL, ky ? ky + i : NULL);
	int r = n - i;
	if (r > 0) { /* tail: pad a lane block with copies of the last input */
		double bu[2][KW], bo[4][KW];
		for (int j = 0; j < KW; ++j) {
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

static inline void KFN(sq_surface)(const mkKShape3 *s, KV u1, KV u2, KV u3,
	KV *x1, KV *x2, KV *x3, KV *m1, KV *m2, KV *m3)
{
	if (s->ellipse) {
		*x1 = s->a * u1; *x2 = s->b * u2; *x3 = s->c * u3;
		*m1 = u1 / s->a; *m2 = u2 / s->b; *m3 = u3 / s->c;
		return;
	}
	/* rho = cos(eta) and (cw, sw) = (cos, sin)(omega) come from u1, u2 directly,
	 * never as 1 - u3^2. */
	KV rho = KSQRT(u1 * u1 + u2 * u2);
	KV rs = KFN(kmax)(rho, KSPLAT(KTINY));
	KV lrho = KLOG(rho);
	KV lc = KLOG(KABS(u1) / rs), ls = KLOG(KABS(u2) / rs);
	KV l3 = KLOG(KABS(u3));
	*x1 = s->a * KCOPYSIGN(KEXP(s->e1 * lrho + s->e2 * lc), u1);
	*x2 = s->b * KCOPYSIGN(KEXP(s->e1 * lrho + s->e2 * ls), u2);
	*x3 = s->c * KCOPYSIGN(KEXP(s->e1 * l3), u3);
	/* g(u) (paper eq. 3d_sq_m_u up to the factor 2/e1): its components are
	 * rho^(2-e1) cw^(2-e2)/a = u1^2/x1, likewise u2^2/x2 and u3^2/x3, as in
	 * 2D; a zero x_i (an axis or a pole) gives a zero component. */
	KM z1 = *x1 == 0.0, z2 = *x2 == 0.0, z3 = *x3 == 0.0;
	*m1 = KSEL(z1, KSPLAT(0.0), (u1 / KSEL(z1, KSPLAT(1.0), *x1)) * u1);
	*m2 = KSEL(z2, KSPLAT(0.0), (u2 / KSEL(z2, KSPLAT(1.0), *x2)) * u2);
	*m3 = KSEL(z3, KSPLAT(0.0), (u3 / KSEL(z3, KSPLAT(1.0), *x3)) * u3);
}

/* Support point of the nested norm: inner l_q2 over (x, y), outer l_q1. */
static inline void KFN(sq_support)(const mkKShape3 *s, KV d1, KV d2, KV d3, KV *x1, KV *x2, KV *x3)
{
	if (s->ellipse) {
		KV v1 = s->a * d1, v2 = s->b * d2, v3 = s->c * d3;
		KV inv = 1.0 / KSQRT(v1 * v1 + v2 * v2 + v3 * v3);
		*x1 = s->a * v1 * inv; *x2 = s->b * v2 * inv; *x3 = s->c * v3 * inv;
		return;
	}
	KV r1, r2, mx, L, rg, r3, mxo, Lo;
	KFN(pair_dual)(KABS(s->a * d1), KABS(s->b * d2), s->q2m1, s->k2, &r1, &r2, &mx, &L);
	KV g = mx * KEXP(L * s->invq2); /* |(u1, u2)|_q2 */
	KFN(pair_dual)(g, KABS(s->c * d3), s->q1m1, s->k1, &rg, &r3, &mxo, &Lo);
	*x1 = s->a * KCOPYSIGN(rg * r1, d1);
	*x2 = s->b * KCOPYSIGN(rg * r2, d2);
	*x3 = s->c * KCOPYSIGN(r3, d3);
}

/* f~~(m) through g^-1 (paper eq. 3d_sq_u_m), normalised, then f. With
 * p = (a|m1|, b|m2|, c|m3|): w12 = |(w1, w2)| and w3 are compared in the log
 * domain, D = log(w12/w3), and cos(eta), sin(eta) follow from D alone. */
/* The logarithms of the unit parameter of the point whose gradient is
 * parallel to m: log cos(eta), log |sin(eta)|, log |cos(omega)|, log |sin(omega)|. */
static inline void KFN(sq_gradinv_logs)(const mkKShape3 *s, KV m1, KV m2, KV m3,
	KV *lrho_out, KV *l3_out, KV *lc1_out, KV *lc2_out)
{
	KV p1 = KABS(s->a * m1), p2 = KABS(s->b * m2), p3 = KABS(s->c * m3);
	KM pg = p1 >= p2;
	KV P12 = KSEL(pg, p1, p2), mn = KSEL(pg, p2, p1);
	KV P = KFN(kmax)(P12, p3);
	KV lr = KLOG(mn / KFN(kmax)(P12, KSPLAT(KTINY)));
	KV al = lr * s->inv2me2;            /* log(w_min / w_max) in the inner pair */
	KV L12 = KLOG1P1(KEXP(2.0 * al));
	KV D = (KLOG(P12 / P) - KLOG(p3 / P) + 0.5 * s->twome2 * L12) * s->inv2me1;
	KV aD = KABS(D);
	KV le = KLOG1P1(KEXP(-2.0 * aD));
	KM dpos = D >= 0.0;
	KV lrho = KSEL(dpos, -0.5 * le, D - 0.5 * le);  /* log cos(eta) */
	KV l3 = KSEL(dpos, -D - 0.5 * le, -0.5 * le);    /* log |sin(eta)| */
	KV lcmax = -0.5 * L12, lcmin = al - 0.5 * L12;  /* log cos/sin(omega) */
	*lc1_out = KSEL(pg, lcmax, lcmin);
	*lc2_out = KSEL(pg, lcmin, lcmax);
	*lrho_out = lrho;
	*l3_out = l3;
}

static inline void KFN(sq_gradinv)(const mkKShape3 *s, KV m1, KV m2, KV m3, KV *x1, KV *x2, KV *x3)
{
	if (s->ellipse) { KFN(sq_support)(s, m1, m2, m3, x1, x2, x3); return; }
	KV lrho, l3, lc1, lc2;
	KFN(sq_gradinv_logs)(s, m1, m2, m3, &lrho, &l3, &lc1, &lc2);
	*x1 = s->a * KCOPYSIGN(KEXP(s->e1 * lrho + s->e2 * lc1), m1);
	*x2 = s->b * KCOPYSIGN(KEXP(s->e1 * lrho + s->e2 * lc2), m2);
	*x3 = s->c * KCOPYSIGN(KEXP(s->e1 * l3), m3);
}

static inline void KFN(sq_dir)(const mkKShape3 *s, int form, KV d1, KV d2, KV d3, KV *x1, KV *x2, KV *x3)
{
	if (form == MK_FORM_NORMAL) KFN(sq_support)(s, d1, d2, d3, x1, x2, x3);
	else KFN(sq_gradinv)(s, d1, d2, d3, x1, x2, x3);
}

#define KMV3(A, v1, v2, v3, i) ((A)[i][0] * (v1) + (A)[i][1] * (v2) + (A)[i][2] * (v3))

static inline void KFN(block3)(const mkKPlan3 *p, const double *pux, const double *puy, const double *puz,
	double *px, double *py, double *pz, double *pkx, double *pky, double *pkz)
{
	KV u1 = KLOAD(pux), u2 = KLOAD(puy), u3 = KLOAD(puz);
	{ /* as in block2 */
		KM unit = KABS(u1 * u1 + u2 * u2 + u3 * u3 - 1.0) <= KSPLAT(KUNIT_TOL);
		if (!KALL(unit)) {
			KV m = KFN(kmax)(KFN(kmax)(KABS(u1), KABS(u2)), KABS(u3));
			KV v1 = u1 / m, v2 = u2 / m, v3 = u3 / m;
			KV inv = 1.0 / KSQRT(v1 * v1 + v2 * v2 + v3 * v3);
			u1 = KSEL(unit, u1, v1 * inv); u2 = KSEL(unit, u2, v2 * inv); u3 = KSEL(unit, u3, v3 * inv);
		}
	}
	KV x1, x2, x3, v1 = u1, v2 = u2, v3 = u3;
	if (p->param == MK_PARAM_SURFACE) {
		KFN(sq_surface)(&p->s1, u1, u2, u3, &x1, &x2, &x3, &v1, &v2, &v3);
	} else {
		KV d1 = KMV3(p->M1T, u1, u2, u3, 0);
		KV d2 = KMV3(p->M1T, u1, u2, u3, 1);
		KV d3 = KMV3(p->M1T, u1, u2, u3, 2);
		KFN(sq_dir)(&p->s1, p->form, d1, d2, d3, &x1, &x2, &x3);
	}
	KV k1 = p->t1[0] + KMV3(p->M1, x1, x2, x3, 0);
	KV k2 = p->t1[1] + KMV3(p->M1, x1, x2, x3, 1);
	KV k3 = p->t1[2] + KMV3(p->M1, x1, x2, x3, 2);
	KV e1 = KMV3(p->D2, v1, v2, v3, 0);
	KV e2 = KMV3(p->D2, v1, v2, v3, 1);
	KV e3 = KMV3(p->D2, v1, v2, v3, 2);
	KV y1, y2, y3;
	KFN(sq_dir)(&p->s2, p->form, e1, e2, e3, &y1, &y2, &y3);
	KSTORE(px, k1 + (p->sigma * KMV3(p->M2, y1, y2, y3, 0) + p->t2p[0]));
	KSTORE(py, k2 + (p->sigma * KMV3(p->M2, y1, y2, y3, 1) + p->t2p[1]));
	KSTORE(pz, k3 + (p->sigma * KMV3(p->M2, y1, y2, y3, 2) + p->t2p[2]));
	if (pkx) { KSTORE(pkx, k1); KSTORE(pky, k2); KSTORE(pkz, k3); }
}

void KFN(mkK3_Run)(const mkKPlan3 *p, const double *ux, const double *uy, const double *uz, int n,
	double *x, double *y, double *z, double *kx, double *ky, double *kz)
{
	int i = 0;
	for (; i + KW <= n; i += KW)
		KFN(block3)(p, ux + i, uy + i, uz + i, x + i, y + i, z + i,
			kx ? kx + i : NULL, ky ? ky + i : NULL, kz ? kz + i : NULL);
	int r = n - i;
	if (r > 0) {
		double bu[3][KW], bo[6][KW];
		for (int j = 0; j < KW; ++j) {
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
