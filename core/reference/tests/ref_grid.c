/* ref_grid.c - the extremes grid (mink/mpref_grid.h) and the SPEC text of a
 * reference body.
 *
 * References: the cell counts and the eps axis are the documented grid's
 * (docs/experiments/extremes.md) written out here by hand (13 exponents; sweeps of 7 axis ratios, 5 shears,
 * 7 size ratios, 5 translations at 3 exponents; quick: 5 exponents and the
 * two ends of each sweep at eps = 1); the valid ranges are the core's
 * (mink/body.h); the SPEC round trip is judged by the core's own parser
 * (mkSpec_Parse), which shares no code with the writer, bit for bit. */
#include <mink/mpref_grid.h>
#include <mink/mink.h>
#include "reftest.h"

#include <math.h>
#include <string.h>

/* Derived values (ratios, products) agree to a few roundings. */
#define ENSURE_NEARLY(a, b, ctx) ENSURE_MSG(fabs((double)(a) - (double)(b)) <= 1e-14 * fabs((double)(b)), \
	"%s: %.17g vs %.17g", ctx, (double)(a), (double)(b))

static int sameBits(double a, double b)
{
	return memcmp(&a, &b, sizeof a) == 0;
}

/* Parse b's SPEC with the core and compare every double bit for bit. */
static void checkRoundTrip(const refBody *b, const char *spec, const char *ctx)
{
	mkSpec s;
	char msg[256] = "";
	int dim = b->s.dim;
	mkResult r = mkSpec_Parse(spec, dim, "body", &s, msg, sizeof msg);
	ENSURE_MSG(r == MK_OK, "%s: '%s' does not parse: %s", ctx, spec, msg);
	if (r != MK_OK)
		return;
	int same = 1;
	if (dim == 2) {
		mkBody2 c = s.body2;
		same &= sameBits(c.shape.a, b->s.a[0]) && sameBits(c.shape.b, b->s.a[1]) && sameBits(c.shape.eps, b->s.e1);
		for (int i = 0; i < 2; ++i)
			for (int j = 0; j < 2; ++j)
				same &= sameBits(c.M.m[i][j], b->M.m[i][j]);
		same &= sameBits(c.t.x, b->t[0]) && sameBits(c.t.y, b->t[1]);
	} else {
		mkBody3 c = s.body3;
		same &= sameBits(c.shape.a, b->s.a[0]) && sameBits(c.shape.b, b->s.a[1]) && sameBits(c.shape.c, b->s.a[2]);
		same &= sameBits(c.shape.eps1, b->s.e1) && sameBits(c.shape.eps2, b->s.e2);
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				same &= sameBits(c.M.m[i][j], b->M.m[i][j]);
		same &= sameBits(c.t.x, b->t[0]) && sameBits(c.t.y, b->t[1]) && sameBits(c.t.z, b->t[2]);
	}
	ENSURE_MSG(same, "%s: '%s' parses to different doubles", ctx, spec);
}

static int valid(const refBody *b, const char *spec, int dim)
{
	mkSpec s;
	char msg[256] = "";
	if (mkSpec_Parse(spec, dim, "body", &s, msg, sizeof msg) != MK_OK)
		return 0;
	return dim == 2 ? mkBody2_IsValid(s.body2, "body", msg, sizeof msg)
	                : mkBody3_IsValid(s.body3, "body", msg, sizeof msg);
	(void)b;
}

static void checkGrid(refGridKind kind, const char *name)
{
	static const double issueEps[13] = { 1e-6, 1e-4, 1e-3, 1e-2, 0.1, 0.5, 1.0, 1.5, 1.9, 1.99, 1.999,
		2.0 - 1e-4, 2.0 - 1e-6 };
	const double *ev, *sv;
	int ne = refGrid_Eps(kind, &ev), ns = refGrid_SweepEps(kind, &sv);
	if (kind == REF_GRID_FULL) {
		ENSURE(ne == 13);
		for (int i = 0; i < 13 && i < ne; ++i)
			ENSURE_MSG(ev[i] == issueEps[i], "eps axis %d: %.17g, issue %.17g", i, ev[i], issueEps[i]);
		ENSURE(ns == 3);
		ENSURE(refGrid_Count(kind, 2) == 13 * 13 + (7 + 5 + 7 + 5) * 3);
		ENSURE(refGrid_Count(kind, 3) == 13 * 13 + (7 + 5 + 7 + 5) * 3);
	} else {
		ENSURE(ne == 5 && ns == 1);
		ENSURE(refGrid_Count(kind, 2) == 5 * 5 + 8);
		ENSURE(refGrid_Count(kind, 3) == 5 * 5 + 8);
	}
	/* Both ends of the valid range, exactly. */
	ENSURE(ev[0] == MK_EPS_MIN && ev[ne - 1] == MK_EPS_MAX);
	ENSURE(refGrid_Count(kind, 1) == 0 && refGrid_Count(kind, 4) == 0);

	for (int dim = 2; dim <= 3; ++dim) {
		int n = refGrid_Count(kind, dim);
		refCell c;
		ENSURE(refGrid_Cell(kind, dim, -1, &c) == -1);
		ENSURE(refGrid_Cell(kind, dim, n, &c) == -1);
		ENSURE(refGrid_Cell(kind, 4, 0, &c) == -1);
		/* seen[i][j]: eps pair (i, j) of the eps family met; the sweeps'
		 * extreme values met. */
		int seen[13][13] = { { 0 } }, epsCells = 0;
		double axisMax = 0.0, shearMax = 0.0, sizeMin = 1.0, sizeMax = 1.0, shiftMax = 0.0;
		int axisOne = 0, shearZero = 0, shiftZero = 0;
		for (int i = 0; i < n; ++i) {
			ENSURE(refGrid_Cell(kind, dim, i, &c) == 0);
			char ctx[96];
			snprintf(ctx, sizeof ctx, "%s %dD cell %d (%s)", name, dim, i, c.family);
			ENSURE(c.index == i && c.dim == dim && c.b1.s.dim == dim && c.b2.s.dim == dim);
			checkRoundTrip(&c.b1, c.spec1, ctx);
			checkRoundTrip(&c.b2, c.spec2, ctx);
			ENSURE_MSG(valid(&c.b1, c.spec1, dim) && valid(&c.b2, c.spec2, dim),
				"%s: a body is outside the core's valid range: %s | %s", ctx, c.spec1, c.spec2);
			/* The bodies carry the cell's exponents. */
			ENSURE(c.b1.s.e1 == c.eps[0][0] && c.b2.s.e1 == c.eps[1][0]);
			if (dim == 3)
				ENSURE(c.b1.s.e2 == c.eps[0][1] && c.b2.s.e2 == c.eps[1][1]);
			if (strcmp(c.family, "eps") == 0) {
				int a = -1, b = -1;
				for (int k = 0; k < ne; ++k) {
					if (dim == 2 ? c.eps[0][0] == ev[k] : c.eps[0][0] == ev[k])
						a = k;
					if (dim == 2 ? c.eps[1][0] == ev[k] : c.eps[0][1] == ev[k])
						b = k;
				}
				ENSURE_MSG(a >= 0 && b >= 0, "%s: exponents not on the axis", ctx);
				if (a >= 0 && b >= 0)
					seen[a][b]++;
				epsCells++;
			} else {
				int onAxis = 0;
				for (int k = 0; k < ns; ++k)
					onAxis |= c.eps[0][0] == sv[k];
				ENSURE_MSG(onAxis, "%s: sweep exponent %.17g not a sweep exponent", ctx, c.eps[0][0]);
				if (strcmp(c.family, "axis") == 0) {
					axisMax = c.axis > axisMax ? c.axis : axisMax;
					axisOne |= c.axis == 1.0;
					/* the ratio is really the body's long-to-short ratio */
					ENSURE_NEARLY(c.b1.s.a[0] / c.b1.s.a[1], 2.0 * c.axis, ctx);
				} else if (strcmp(c.family, "shear") == 0) {
					shearMax = c.shear > shearMax ? c.shear : shearMax;
					shearZero |= c.shear == 0.0;
				} else if (strcmp(c.family, "size") == 0) {
					sizeMin = c.size < sizeMin ? c.size : sizeMin;
					sizeMax = c.size > sizeMax ? c.size : sizeMax;
					ENSURE_NEARLY(c.b2.s.a[0], 0.8 * c.size * (dim == 2 ? 1.0 : 0.875), ctx);
				} else {
					ENSURE(strcmp(c.family, "shift") == 0);
					shiftMax = c.shift > shiftMax ? c.shift : shiftMax;
					shiftZero |= c.shift == 0.0;
					ENSURE_NEARLY(hypot(c.b1.t[0], c.b1.t[1]), c.shift, ctx);
				}
			}
		}
		ENSURE(epsCells == ne * ne);
		for (int a = 0; a < ne; ++a)
			for (int b = 0; b < ne; ++b)
				ENSURE_MSG(seen[a][b] == 1, "%s %dD: eps pair (%g, %g) met %d times", name, dim, ev[a], ev[b], seen[a][b]);
		ENSURE(axisOne && axisMax == 1e6);
		ENSURE(shearZero && shearMax == 100.0);
		ENSURE(sizeMin == 1e-6 && sizeMax == 1e6);
		ENSURE(shiftZero && shiftMax == 1e9);
	}
}

/* Awkward doubles through the SPEC writer and the core's parser: random
 * bit patterns within the valid ranges, negative zeros, the range ends. */
static void checkRandomSpecs(void)
{
	refRng rng = { 12345 };
	for (int trial = 0; trial < 400; ++trial) {
		int dim = 2 + trial % 2;
		refBody b;
		memset(&b, 0, sizeof b);
		b.s.dim = dim;
		for (int i = 0; i < dim; ++i)
			b.s.a[i] = pow(10.0, refRng_Uniform(&rng, -9.0, 9.0));
		b.s.e1 = trial % 7 == 0 ? MK_EPS_MIN : trial % 7 == 1 ? MK_EPS_MAX : refRng_Uniform(&rng, MK_EPS_MIN, MK_EPS_MAX);
		if (dim == 3)
			b.s.e2 = refRng_Uniform(&rng, MK_EPS_MIN, MK_EPS_MAX);
		for (int i = 0; i < dim; ++i) {
			for (int j = 0; j < dim; ++j)
				b.M.m[i][j] = i == j ? refRng_Uniform(&rng, 1.0, 3.0) : refRng_Uniform(&rng, -0.1, 0.1);
			b.t[i] = trial % 5 == 0 ? -0.0 : refRng_Uniform(&rng, -1e12, 1e12) * pow(10.0, -refRng_Uniform(&rng, 0, 20));
		}
		char spec[REF_SPEC_MAX];
		int len = refBody_Spec(&b, spec, sizeof spec);
		ENSURE(len > 0 && (size_t)len == strlen(spec));
		checkRoundTrip(&b, spec, "random body");
	}
	/* A buffer too small is reported, never overrun. */
	refBody b;
	memset(&b, 0, sizeof b);
	b.s.dim = 2;
	b.s.a[0] = b.s.a[1] = b.s.e1 = 1.0;
	char small[16];
	memset(small, 'x', sizeof small);
	ENSURE(refBody_Spec(&b, small, sizeof small) == -1);
	ENSURE(small[15] == 0);
}

static void checkParse(void)
{
	refGridKind k = REF_GRID_FULL;
	char msg[160] = "";
	ENSURE(refGrid_Parse("quick", "--grid", &k, msg, sizeof msg) == 0 && k == REF_GRID_QUICK);
	ENSURE(refGrid_Parse("full", "--grid", &k, msg, sizeof msg) == 0 && k == REF_GRID_FULL);
	ENSURE(refGrid_Parse("medium", "--grid", &k, msg, sizeof msg) == -1 && k == REF_GRID_FULL);
	ENSURE_MSG(strstr(msg, "--grid") && strstr(msg, "medium") && strstr(msg, "quick, full"), "message: %s", msg);
	ENSURE(refGrid_Parse(NULL, "--grid", &k, msg, sizeof msg) == -1);
}

int main(void)
{
	checkGrid(REF_GRID_FULL, "full");
	checkGrid(REF_GRID_QUICK, "quick");
	checkRandomSpecs();
	checkParse();
	return refTest_Result("ref_grid");
}
