/* fuzz_sum.c - libFuzzer harness over mkSum2_Batch and mkSum3_Batch.
 *
 * The input bytes are decoded (never rejected: missing bytes read as zero)
 * into a valid pair of bodies, options and parameter vectors:
 *   byte 0        bit 0: dimension (2 or 3); bits 1-7: options, see below
 *   then per body the exponent(s), semi-axes, map and centre, each drawn from
 *                 a selector byte (special values: the ends of the documented
 *                 ranges, eps = 1 exactly, the values 1e-3 and 2 - 1e-3 of the
 *                 issue) or from 8 bytes spread over the whole range
 *                 (logarithmically for magnitudes);
 *   then a count (1 ... 32) and the parameter vectors, each component either
 *                 a unit-interval value, an exact 0/1, or raw bytes taken as a
 *                 double (any finite one: sum.h accepts any nonzero vector).
 * Bodies outside the ranges of body.h (a map whose condition number exceeds
 * MK_MAP_COND_MAX, say) are not valid input; for them only
 * mkBody*_IsValid runs, and must say no without crashing.
 *
 * Contract checked (sum.h): the return code (MK_OK, or MK_ERR_UNSUPPORTED
 * for the paper form with normal parameters or a vector kernel, and for a
 * kernel this CPU lacks), and, for the normal and gradient forms, every
 * output point and kissing point finite. The paper form runs for the
 * sanitizers only: it is documented to fail near the poles. A violation
 * aborts, which libFuzzer reports as a crash with its input. */
#include <mink/mink.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct fuzzReader { const uint8_t *p; size_t n; } fuzzReader;

static uint8_t takeByte(fuzzReader *r)
{
	if (r->n == 0)
		return 0;
	r->n--;
	return *r->p++;
}

static uint64_t take64(fuzzReader *r)
{
	uint64_t v = 0;
	for (int i = 0; i < 8; ++i)
		v = (v << 8) | takeByte(r);
	return v;
}

/* In [0, 1]. */
static double takeUnit(fuzzReader *r)
{
	return (double)(take64(r) >> 11) * 0x1p-53;
}

/* lo (hi/lo)^t, t in [0, 1]: every order of magnitude equally likely. */
static double takeLog(fuzzReader *r, double lo, double hi)
{
	double v = lo * pow(hi / lo, takeUnit(r));
	return v < lo ? lo : v > hi ? hi : v;
}

static double takeSigned(fuzzReader *r, double lo, double hi)
{
	uint8_t s = takeByte(r);
	if (s % 8 == 0)
		return 0.0;
	double v = takeLog(r, lo, hi);
	return (s & 8) ? -v : v;
}

static double takeEps(fuzzReader *r)
{
	switch (takeByte(r) % 8) {
	case 0: return MK_EPS_MIN;
	case 1: return MK_EPS_MAX;
	case 2: return 1.0;
	case 3: return 1e-3;
	case 4: return 2.0 - 1e-3;
	case 5: return takeLog(r, MK_EPS_MIN, 1.0);
	case 6: return 2.0 - takeLog(r, 2.0 - MK_EPS_MAX, 1.0);
	default: return MK_EPS_MIN + (MK_EPS_MAX - MK_EPS_MIN) * takeUnit(r);
	}
}

static double takeAxis(fuzzReader *r)
{
	switch (takeByte(r) % 6) {
	case 0: return MK_AXIS_MIN;
	case 1: return MK_AXIS_MAX;
	case 2: return 1.0;
	case 3: return takeLog(r, 1e-2, 1e2);
	default: return takeLog(r, MK_AXIS_MIN, MK_AXIS_MAX);
	}
}

static double takePos(fuzzReader *r)
{
	return takeSigned(r, 1e-12, MK_POS_MAX);
}

/* A map entry: mostly moderate, sometimes anywhere in the allowed range. */
static double takeEntry(fuzzReader *r)
{
	uint8_t s = takeByte(r);
	if (s % 4 == 0)
		return takeSigned(r, 1e-9, MK_MAP_ENTRY_MAX);
	return -10.0 + 20.0 * takeUnit(r);
}

/* A component of a parameter vector. */
static double takeComponent(fuzzReader *r)
{
	switch (takeByte(r) % 6) {
	case 0: return 0.0;
	case 1: return 1.0;
	case 2: return -1.0;
	case 3: {
		uint64_t bits = take64(r);
		double v;
		memcpy(&v, &bits, sizeof v);
		return isfinite(v) ? v : 0.5;
	}
	default: return -1.0 + 2.0 * takeUnit(r);
	}
}

static mkBody2 takeBody2(fuzzReader *r)
{
	mkShape2 s;
	s.eps = takeEps(r);
	s.a = takeAxis(r);
	s.b = takeAxis(r);
	mkMat2 M;
	if (takeByte(r) % 2)
		M = mkMat2_Mul(mkMat2_Rotation(2.0 * MK_PI * takeUnit(r)),
			mkMat2_Shear(-10.0 + 20.0 * takeUnit(r)));
	else
		for (int i = 0; i < 2; ++i)
			for (int j = 0; j < 2; ++j)
				M.m[i][j] = takeEntry(r);
	mkVec2 t = { takePos(r), takePos(r) };
	return mkBody2_Make(s, M, t);
}

static mkBody3 takeBody3(fuzzReader *r)
{
	mkShape3 s;
	s.eps1 = takeEps(r);
	s.eps2 = takeEps(r);
	s.a = takeAxis(r);
	s.b = takeAxis(r);
	s.c = takeAxis(r);
	mkMat3 M;
	if (takeByte(r) % 2) {
		double q[4];
		for (int i = 0; i < 4; ++i)
			q[i] = -1.0 + 2.0 * takeUnit(r);
		int ok = 0;
		M = mkMat3_FromQuat(q[0], q[1], q[2], q[3]);
		ok = mkMat3_IsFinite(M);
		mkMat3 S = mkMat3_Identity();
		S.m[0][1] = -10.0 + 20.0 * takeUnit(r);
		S.m[1][2] = -10.0 + 20.0 * takeUnit(r);
		S.m[0][2] = -10.0 + 20.0 * takeUnit(r);
		M = mkMat3_Mul(M, S);
	} else {
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				M.m[i][j] = takeEntry(r);
	}
	mkVec3 t = { takePos(r), takePos(r), takePos(r) };
	return mkBody3_Make(s, M, t);
}

static void printBody2(const char *name, mkBody2 b)
{
	fprintf(stderr, "  %s: a=%.17g b=%.17g eps=%.17g M=[%.17g %.17g; %.17g %.17g] t=(%.17g, %.17g)\n",
		name, b.shape.a, b.shape.b, b.shape.eps, b.M.m[0][0], b.M.m[0][1], b.M.m[1][0], b.M.m[1][1], b.t.x, b.t.y);
}

static void printBody3(const char *name, mkBody3 b)
{
	fprintf(stderr, "  %s: a=%.17g b=%.17g c=%.17g eps1=%.17g eps2=%.17g\n", name,
		b.shape.a, b.shape.b, b.shape.c, b.shape.eps1, b.shape.eps2);
	fprintf(stderr, "  M=[%.17g %.17g %.17g; %.17g %.17g %.17g; %.17g %.17g %.17g] t=(%.17g, %.17g, %.17g)\n",
		b.M.m[0][0], b.M.m[0][1], b.M.m[0][2], b.M.m[1][0], b.M.m[1][1], b.M.m[1][2],
		b.M.m[2][0], b.M.m[2][1], b.M.m[2][2], b.t.x, b.t.y, b.t.z);
}

/* The decoded case, so that a report can be reproduced without the fuzzer. */
typedef struct fuzzCase {
	int dim;
	mkBody2 a2, b2;
	mkBody3 a3, b3;
	mkSumOptions opt;
} fuzzCase;

static void fail(const char *what, const fuzzCase *c, const double *u, const double *x)
{
	const mkSumOptions *o = &c->opt;
	fprintf(stderr, "fuzz_sum: %s (dim %d, set %s, form %s, param %s, impl %s)\n",
		what, c->dim, mkSet_Name(o->set), mkForm_Name(o->form), mkParam_Name(o->param), mkImpl_Name(o->impl));
	if (c->dim == 2) {
		printBody2("body1", c->a2);
		printBody2("body2", c->b2);
	} else {
		printBody3("body1", c->a3);
		printBody3("body2", c->b3);
	}
	if (u)
		fprintf(stderr, "  u=(%.17g, %.17g, %.17g) -> x=(%g, %g, %g) kiss=(%g, %g, %g)\n",
			u[0], u[1], u[2], x[0], x[1], x[2], x[3], x[4], x[5]);
	abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fuzzReader r = { data, size };
	uint8_t head = takeByte(&r);
	fuzzCase c;
	memset(&c, 0, sizeof c);
	c.dim = (head & 1) ? 3 : 2;
	c.opt.set = (head & 2) ? MK_SET_PLUS : MK_SET_CONTACT;
	c.opt.param = (head & 4) ? MK_PARAM_NORMAL : MK_PARAM_SURFACE;
	c.opt.form = (mkForm)((head >> 3) % 3);
	c.opt.impl = (mkImpl)((head >> 5) % 4);

	int valid;
	if (c.dim == 2) {
		c.a2 = takeBody2(&r);
		c.b2 = takeBody2(&r);
		valid = mkBody2_IsValid(c.a2, "body1", NULL, 0) & mkBody2_IsValid(c.b2, "body2", NULL, 0);
	} else {
		c.a3 = takeBody3(&r);
		c.b3 = takeBody3(&r);
		valid = mkBody3_IsValid(c.a3, "body1", NULL, 0) & mkBody3_IsValid(c.b3, "body2", NULL, 0);
	}
	if (!valid)
		return 0;

	enum { NMAX = 32 };
	int n = 1 + takeByte(&r) % NMAX;
	double u[3][NMAX], o[6][NMAX];
	for (int j = 0; j < n; ++j) {
		int nonzero = 0;
		for (int i = 0; i < 3; ++i) {
			u[i][j] = i < c.dim ? takeComponent(&r) : 0.0;
			nonzero |= u[i][j] != 0.0;
		}
		if (!nonzero)
			u[0][j] = 1.0;
	}
	for (int i = 0; i < 6; ++i)
		for (int j = 0; j < NMAX; ++j)
			o[i][j] = 0.0;

	const mkSumOptions *opt = &c.opt;
	mkResult res = c.dim == 2
		? mkSum2_Batch(c.a2, c.b2, opt, u[0], u[1], n, o[0], o[1], o[3], o[4])
		: mkSum3_Batch(c.a3, c.b3, opt, u[0], u[1], u[2], n, o[0], o[1], o[2], o[3], o[4], o[5]);

	int unsupported = !mkImpl_Available(opt->impl) || (opt->form == MK_FORM_PAPER
		&& (opt->param == MK_PARAM_NORMAL || opt->impl == MK_IMPL_AVX2 || opt->impl == MK_IMPL_AVX512));
	/* sum.h leaves open whether AUTO with the scalar-only paper form falls
	 * back to the scalar kernel or refuses: both are accepted. */
	if (opt->form == MK_FORM_PAPER && opt->impl == MK_IMPL_AUTO && !unsupported && res == MK_ERR_UNSUPPORTED)
		return 0;
	if (unsupported) {
		if (res != MK_ERR_UNSUPPORTED)
			fail("expected MK_ERR_UNSUPPORTED", &c, NULL, NULL);
		return 0;
	}
	if (res != MK_OK)
		fail("expected MK_OK", &c, NULL, NULL);
	if (opt->form == MK_FORM_PAPER)
		return 0;
	for (int j = 0; j < n; ++j) {
		double uj[3] = { u[0][j], u[1][j], u[2][j] }, xj[6];
		int finite = 1;
		for (int i = 0; i < 6; ++i) {
			xj[i] = o[i][j];
			finite &= isfinite(xj[i]);
		}
		if (!finite)
			fail("non-finite output for valid input", &c, uj, xj);
	}
	return 0;
}
