/* ref_phi.c - Lemma 1: Phi(m) is the norm of the gradient of B2 at the
 * boundary point whose gradient is parallel to m. mkShape2_Phi and
 * mkShape3_Phi against the 256-bit MPFR value |grad Psi(s(m))|, with s(m)
 * mpref's support point (Hoelder's maximiser, derived apart from g^-1).
 *
 * Shapes: every exponent (pair) from {1e-3, 0.01, 0.5, 1, 1.5, 1.99,
 * 2 - 1e-3}, semi-axes (1, 1, 1), (1e4, 1, 30) and (3, 0.5, 2); directions:
 * the axes, 1e-8 off them, the diagonal and random ones.
 *
 * Tolerance (relative). Phi = |g(u*)| with u* = g^-1(m) / |g^-1(m)|. The
 * components of g^-1(m) take the powers 1/(2 - eps_i) of a_i m_i, so one
 * rounding of a_i m_i becomes a relative error of at most 1/(2 - eps_i) u in
 * them (up to 1000 u at eps = 2 - 1e-3); g raises them to 2 - eps_i again
 * and the 3D factor r^(e2 - e1) to at most 2 (|e2 - e1| < 2). Allowing 32
 * roundings along the chain, each amplified by the largest of these factors:
 * 32 u (2 + 1/(2 - e1) + 1/(2 - e2)). (In exact arithmetic the powers undo
 * each other, so the measured error is much smaller; the bound holds for any
 * order of evaluation.) */
#include <mink/mpref.h>
#include "reftest.h"

#include <mink/mink.h>

#include <math.h>

static const double E[] = { 1e-3, 0.01, 0.5, 1.0, 1.5, 1.99, 2.0 - 1e-3 };
static const double axes[3][3] = { { 1.0, 1.0, 1.0 }, { 1e4, 1.0, 30.0 }, { 3.0, 0.5, 2.0 } };

enum { NDIR = 12 };

static void directions(refRng *rng, int dim, double d[NDIR][3])
{
	int k = 0;
	for (int i = 0; i < dim; ++i, ++k) {
		d[k][0] = d[k][1] = d[k][2] = 0.0;
		d[k][i] = i % 2 ? -1.0 : 1.0;
	}
	for (int i = 0; i < dim; ++i, ++k) {
		d[k][0] = d[k][1] = d[k][2] = 1e-8;
		d[k][i] = 1.0;
	}
	d[k][0] = d[k][1] = d[k][2] = 1.0;
	if (dim == 2)
		d[k][2] = 0.0;
	++k;
	for (; k < NDIR; ++k)
		for (int i = 0; i < 3; ++i)
			d[k][i] = i < dim ? refRng_Uniform(rng, -1.0, 1.0) : 0.0;
}

static double refPhi(refShape s, const double *md)
{
	refVec m, x, g;
	refVec_Init(&m);
	refVec_Init(&x);
	refVec_Init(&g);
	refVec_FromD(&m, s.dim, md);
	refShape_Support(s, &m, &x);
	refShape_Gradient(s, &x, &g);
	/* the norm, kept in MPFR until the relative difference is taken */
	double r = refVec_NormD(&g, s.dim);
	refVec_Clear(&m);
	refVec_Clear(&x);
	refVec_Clear(&g);
	return r;
}

int main(void)
{
	refRng rng = { 6401u };
	refStat st2 = { 0 }, st3 = { 0 };
	double d[NDIR][3];
	for (int ia = 0; ia < 3; ++ia)
		for (int i = 0; i < 7; ++i) {
			mkShape2 s = { axes[ia][0], axes[ia][1], E[i] };
			refShape rs = { 2, { s.a, s.b, 0.0 }, s.eps, 0.0 };
			double tol = 32.0 * REF_U * (2.0 + 2.0 / (2.0 - s.eps));
			directions(&rng, 2, d);
			for (int k = 0; k < NDIR; ++k) {
				double ref = refPhi(rs, d[k]);
				double phi = mkShape2_Phi(s, (mkVec2){ d[k][0], d[k][1] });
				double e = fabs(phi - ref) / ref;
				ENSURE_LE(e, tol, "2D Phi a=(%g,%g) eps %g m=(%.17g, %.17g)", s.a, s.b, s.eps, d[k][0], d[k][1]);
				refStat_Add(&st2, e);
			}
			for (int j = 0; j < 7; ++j) {
				mkShape3 t = { axes[ia][0], axes[ia][1], axes[ia][2], E[i], E[j] };
				refShape rt = { 3, { t.a, t.b, t.c }, t.eps1, t.eps2 };
				double tol3 = 32.0 * REF_U * (2.0 + 1.0 / (2.0 - t.eps1) + 1.0 / (2.0 - t.eps2));
				directions(&rng, 3, d);
				for (int k = 0; k < NDIR; ++k) {
					double ref = refPhi(rt, d[k]);
					double phi = mkShape3_Phi(t, (mkVec3){ d[k][0], d[k][1], d[k][2] });
					double e = fabs(phi - ref) / ref;
					ENSURE_LE(e, tol3, "3D Phi a=(%g,%g,%g) eps %g,%g m=(%.17g, %.17g, %.17g)",
						t.a, t.b, t.c, t.eps1, t.eps2, d[k][0], d[k][1], d[k][2]);
					refStat_Add(&st3, e);
				}
			}
		}
	printf("ref_phi 2D: %ld directions, |Phi - Phi_ref|/Phi_ref max %.2e mean %.2e\n",
		st2.count, st2.max, refStat_Mean(&st2));
	printf("ref_phi 3D: %ld directions, |Phi - Phi_ref|/Phi_ref max %.2e mean %.2e\n",
		st3.count, st3.max, refStat_Mean(&st3));
	return refTest_Result("ref_phi");
}
