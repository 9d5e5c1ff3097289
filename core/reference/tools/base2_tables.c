/* base2_tables.c - writes core/src/base/base2_tables.h, the tables of the inline
 * base-2 functions of core/src/base/base2.h, from 256-bit MPFR:
 *
 *  - mkExp2_Tab: 2^(j/128), j = 0 .. 127, rounded, with the relative
 *    rounding error (2^(j/128) - T) / T beside it, and MK_EXP2_C1 .. C5,
 *    the Taylor coefficients (ln 2)^k / k! of 2^r - 1;
 *  - mkSp2_Tab: sp(x) = log2(1 + 2^x) on [-MK_SP2_X, 0] cut into segments
 *    of width 1/MK_SP2_W centred on x_j = -j / MK_SP2_W. On each, in
 *    u = MK_SP2_W x + j in [-1/2, 1/2], sp is interpolated at the
 *    MK_SP2_DEG + 1 Chebyshev nodes (close to the minimax polynomial), and
 *    the interpolant's monomial coefficients in u are rounded to double.
 *
 * core.ref.base2 regenerates the file and compares it with the committed one,
 * and checks the functions themselves against MPFR.
 *
 * Usage: base2_tables [OUT]   (standard output without OUT) */
#include <mpfr.h>
#include <stdio.h>

#define PREC 256
#define SP2_W 8
#define SP2_X 16
#define SP2_DEG 7
#define EXP2_N 128
#define EXP2_DEG 5
enum { N = SP2_DEG + 1 };

/* sp(x) = log2(1 + 2^x) */
static void sp(mpfr_t r, const mpfr_t x, const mpfr_t ln2)
{
	mpfr_exp2(r, x, MPFR_RNDN);
	mpfr_log1p(r, r, MPFR_RNDN);
	mpfr_div(r, r, ln2, MPFR_RNDN);
}

static void exp2Table(FILE *out, const mpfr_t ln2)
{
	mpfr_t v, e;
	mpfr_inits2(PREC, v, e, (mpfr_ptr)0);
	fprintf(out, "/* 2^(j/%d) rounded (T), and (2^(j/%d) - T) / T */\n", EXP2_N, EXP2_N);
	fprintf(out, "#define MK_EXP2_N %d\n", EXP2_N);
	fprintf(out, "static const double mkExp2_Tab[%d][2] = {\n", EXP2_N);
	for (int j = 0; j < EXP2_N; ++j) {
		mpfr_set_si(v, j, MPFR_RNDN);
		mpfr_div_ui(v, v, EXP2_N, MPFR_RNDN);
		mpfr_exp2(v, v, MPFR_RNDN);
		double hi = mpfr_get_d(v, MPFR_RNDN);
		mpfr_sub_d(e, v, hi, MPFR_RNDN);
		mpfr_div_d(e, e, hi, MPFR_RNDN);
		fprintf(out, "\t{ %a, %a },\n", hi, mpfr_get_d(e, MPFR_RNDN));
	}
	fprintf(out, "};\n/* (ln 2)^k / k!: 2^r - 1 = sum_k C_k r^k */\n");
	mpfr_set_ui(v, 1, MPFR_RNDN);
	for (int k = 1; k <= EXP2_DEG; ++k) {
		mpfr_mul(v, v, ln2, MPFR_RNDN);
		mpfr_div_ui(v, v, (unsigned long)k, MPFR_RNDN);
		fprintf(out, "#define MK_EXP2_C%d %a\n", k, mpfr_get_d(v, MPFR_RNDN));
	}
	mpfr_clears(v, e, (mpfr_ptr)0);
}

static void softplusTable(FILE *out, const mpfr_t ln2)
{
	/* T_k(s) = sum_m T[k][m] s^m: integer coefficients, exact */
	long long T[N][N] = { { 0 } };
	T[0][0] = 1;
	T[1][1] = 1;
	for (int k = 2; k < N; ++k)
		for (int m = 0; m < N; ++m)
			T[k][m] = (m > 0 ? 2 * T[k - 1][m - 1] : 0) - T[k - 2][m];
	mpfr_t s[N], f[N], a[N], c, x, v, pi;
	for (int i = 0; i < N; ++i)
		mpfr_inits2(PREC, s[i], f[i], a[i], (mpfr_ptr)0);
	mpfr_inits2(PREC, c, x, v, pi, (mpfr_ptr)0);
	mpfr_const_pi(pi, MPFR_RNDN);
	for (int i = 0; i < N; ++i) { /* nodes s_i = cos(pi (i + 1/2) / N) in [-1, 1] */
		mpfr_mul_d(s[i], pi, (i + 0.5) / N, MPFR_RNDN);
		mpfr_cos(s[i], s[i], MPFR_RNDN);
	}
	fprintf(out, "/* log2(1 + 2^x): row j holds the coefficients of u^0 .. u^%d near x = -j / %d,\n"
		" * u = %d x + j in [-1/2, 1/2] */\n", SP2_DEG, SP2_W, SP2_W);
	fprintf(out, "#define MK_SP2_W %d\n#define MK_SP2_X %d\n#define MK_SP2_DEG %d\n", SP2_W, SP2_X, SP2_DEG);
	fprintf(out, "static const double mkSp2_Tab[%d][%d] = {\n", SP2_W * SP2_X + 1, N);
	for (int j = 0; j <= SP2_W * SP2_X; ++j) {
		for (int i = 0; i < N; ++i) { /* u = s / 2, x = (u - j) / W */
			mpfr_div_ui(x, s[i], 2, MPFR_RNDN);
			mpfr_sub_si(x, x, j, MPFR_RNDN);
			mpfr_div_ui(x, x, SP2_W, MPFR_RNDN);
			sp(f[i], x, ln2);
		}
		/* Chebyshev coefficients a_k = (2 - [k = 0]) / N sum_i f_i T_k(s_i) */
		for (int k = 0; k < N; ++k) {
			mpfr_set_zero(a[k], 1);
			for (int i = 0; i < N; ++i) {
				mpfr_mul_d(v, pi, k * (i + 0.5) / N, MPFR_RNDN);
				mpfr_cos(v, v, MPFR_RNDN);
				mpfr_mul(v, v, f[i], MPFR_RNDN);
				mpfr_add(a[k], a[k], v, MPFR_RNDN);
			}
			mpfr_mul_d(a[k], a[k], (k == 0 ? 1.0 : 2.0) / N, MPFR_RNDN);
		}
		/* in u = s / 2 the coefficient of u^m is 2^m sum_k a_k T[k][m] */
		fprintf(out, "\t{ ");
		for (int m = 0; m < N; ++m) {
			mpfr_set_zero(c, 1);
			for (int k = m; k < N; ++k) {
				mpfr_mul_si(v, a[k], (long)T[k][m], MPFR_RNDN);
				mpfr_add(c, c, v, MPFR_RNDN);
			}
			mpfr_mul_2ui(c, c, (unsigned long)m, MPFR_RNDN);
			/* the odd terms of row 0 vanish (sp(x) - x/2 is even): 0, not
			 * the rounding of the 256-bit sums */
			if (!mpfr_zero_p(c) && mpfr_get_exp(c) < -200)
				mpfr_set_zero(c, 1);
			fprintf(out, "%a%s", mpfr_get_d(c, MPFR_RNDN), m + 1 < N ? ", " : " },\n");
		}
	}
	fprintf(out, "};\n");
	for (int i = 0; i < N; ++i)
		mpfr_clears(s[i], f[i], a[i], (mpfr_ptr)0);
	mpfr_clears(c, x, v, pi, (mpfr_ptr)0);
}

int main(int argc, char **argv)
{
	if (argc > 2 || (argc == 2 && (argv[1][0] == '-'))) {
		fprintf(stderr, "usage: base2_tables [OUT]\n"
			"Writes the tables of core/src/base/base2.h (base2_tables.h) from 256-bit MPFR\n"
			"to OUT, or to standard output.\n");
		return argc == 2 && (argv[1][1] == 'h' || argv[1][1] == '-') ? 0 : 2;
	}
	FILE *out = argc > 1 ? fopen(argv[1], "w") : stdout;
	if (!out) {
		perror(argv[1]);
		return 1;
	}
	mpfr_t ln2;
	mpfr_init2(ln2, PREC);
	mpfr_const_log2(ln2, MPFR_RNDN);
	fprintf(out, "/* base2_tables.h - the tables of base2.h, written by\n"
		" * core/reference/tools/base2_tables.c from 256-bit MPFR: do not edit. */\n"
		"#ifndef MINK_BASE2_TABLES_H\n#define MINK_BASE2_TABLES_H\n\n");
	exp2Table(out, ln2);
	fprintf(out, "\n");
	softplusTable(out, ln2);
	fprintf(out, "\n#endif\n");
	mpfr_clear(ln2);
	mpfr_free_cache();
	if (out != stdout && fclose(out) != 0) {
		perror(argv[1]);
		return 1;
	}
	return 0;
}
