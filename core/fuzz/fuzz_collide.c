/* fuzz_collide.c - libFuzzer harness over the collision queries of one pair
 * (mkCollide3_Normal, mkCollide3_NormalFrom, mkCollide3_Ray) and of the
 * batch (mkCollide3_Batch, in every mode), with an oracle that shares no code
 * with the solver.
 *
 * The input bytes are decoded (never rejected: missing bytes read as zero)
 * into two superquadrics: per body the semi-axes a, b, c in [0.05, 5]
 * (logarithmically), the exponents e1, e2 in [0.02, 1.98], a map M = R S
 * (R a rotation from a quaternion, S a diagonal scale in [0.2, 5]) and a
 * centre; body 2's centre is body 1's plus an offset of length 1e-6 ... 30
 * (logarithmically) in any direction, so that deep overlaps, touching pairs
 * and far pairs are all met. The next byte picks a start direction for
 * mkCollide3_NormalFrom, the next the batch's mode and clearance delta, and
 * the last one's low bits make either body of the batch an ellipsoid
 * (e1 = e2 = 1: the batch's ellipsoid paths).
 *
 * The oracle evaluates, with its own code (the nested l_p dual norms below,
 * not mkBody3_SupportValue), the support functions h1, h2 and the bound
 *     f(n) = <n, c2 - c1> - h1(n) - h2(-n) <= sd
 * over 26 lattice directions, the centre line, the solver's normal and
 * perturbations of it: L = max f is a certified lower bound of the signed
 * distance sd. It tests membership in a body with the implicit function
 * Psi(S^-1 R^-1 M ...) of body.h, again its own code. Checked, with a
 * tolerance of 1e-7 of the pair's size (far above the rounding of both
 * computations, far below any real disagreement):
 *  - the answer's bound is f at its normal (the oracle's f);
 *  - Normal, certified: sd lies in [bound, bound + gap], so L <= bound + gap;
 *    separated: the witnesses lie in their bodies and L <= |p2 - p1|;
 *  - a status "overlapping" (any query) has no separating direction:
 *    L <= tol; a status "separated" has no point common to both bodies
 *    among 65 points of the centre line;
 *  - the batch, on the pair both ways round (twice, through index arrays):
 *    a lower bound is at most L, an upper bound at least L, a separating
 *    direction's f is its lower bound, an overlap point lies in both bodies,
 *    a "not clear" answer has L <= delta, a certified distance lies in its
 *    bracket and is at least L (less the bracket's width), every distance
 *    at most its witnesses' distance; the same three status checks as above;
 *    and a certain status (separated or overlapping) equals the swapped
 *    pair's and the one-pair query's where those are certain too.
 * A violation aborts, which libFuzzer reports as a crash with its input. */
#include <mink/mink.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_CHECK(expr, what) do { \
	if (!(expr)) { \
		fprintf(stderr, "fuzz_collide: %s: check failed: %s\n", what, #expr); \
		abort(); \
	} \
} while (0)

typedef struct fuzzReader { const uint8_t *p; size_t n; } fuzzReader;

static uint8_t fuzzTake(fuzzReader *r)
{
	if (r->n == 0) return 0;
	r->n--;
	return *r->p++;
}

/* In [0, 1], from two bytes. */
static double fuzzUnit(fuzzReader *r)
{
	unsigned v = (unsigned)fuzzTake(r) << 8;
	v |= fuzzTake(r);
	return (double)v / 65535.0;
}

static double fuzzLog(fuzzReader *r, double lo, double hi)
{
	return lo * pow(hi / lo, fuzzUnit(r));
}

/* ---- the oracle's own geometry ---- */

typedef struct fuzzBody { double ax[3], e1, e2, M[3][3], Minv[3][3], t[3]; } fuzzBody;

/* (|x|^p + |y|^p)^(1/p), scaled so that no power overflows; p >= 1. */
static double fuzzNorm2(double x, double y, double p)
{
	double m = fmax(fabs(x), fabs(y));
	if (m == 0.0) return 0.0;
	return m * pow(pow(fabs(x) / m, p) + pow(fabs(y) / m, p), 1.0 / p);
}

/* The support function of the canonical superquadric at u: the dual of the
 * nested norm ((|x/a|^p2 + |y/b|^p2)^(p1/p2) + |z/c|^p1)^(1/p1), p = 2/e,
 * which is the nested norm with the conjugate exponents 2/(2 - e). */
static double fuzzDual(const fuzzBody *b, const double u[3])
{
	double q1 = 2.0 / (2.0 - b->e1), q2 = 2.0 / (2.0 - b->e2);
	double inner = fuzzNorm2(b->ax[0] * u[0], b->ax[1] * u[1], q2);
	return fuzzNorm2(inner, b->ax[2] * u[2], q1);
}

/* h(n) = <n, t> + h_S(M^T n), without the centre when `centred`. */
static double fuzzSupport(const fuzzBody *b, const double n[3], int centred)
{
	double u[3];
	for (int i = 0; i < 3; ++i) u[i] = b->M[0][i] * n[0] + b->M[1][i] * n[1] + b->M[2][i] * n[2];
	double h = fuzzDual(b, u);
	return centred ? h : h + n[0] * b->t[0] + n[1] * b->t[1] + n[2] * b->t[2];
}

/* The body's norm of x: <= 1 inside. */
static double fuzzGauge(const fuzzBody *b, const double x[3])
{
	double d[3], y[3];
	for (int i = 0; i < 3; ++i) d[i] = x[i] - b->t[i];
	for (int i = 0; i < 3; ++i) y[i] = (b->Minv[i][0] * d[0] + b->Minv[i][1] * d[1] + b->Minv[i][2] * d[2]) / b->ax[i];
	double p1 = 2.0 / b->e1, p2 = 2.0 / b->e2;
	return fuzzNorm2(fuzzNorm2(y[0], y[1], p2), y[2], p1);
}

/* f(n) for n normalised here; -inf for n = 0. */
static double fuzzBound(const fuzzBody *b1, const fuzzBody *b2, const double n0[3])
{
	double len = sqrt(n0[0] * n0[0] + n0[1] * n0[1] + n0[2] * n0[2]);
	if (!(len > 0.0)) return -INFINITY;
	double n[3] = { n0[0] / len, n0[1] / len, n0[2] / len }, m[3] = { -n[0], -n[1], -n[2] };
	double d = 0.0;
	for (int i = 0; i < 3; ++i) d += n[i] * (b2->t[i] - b1->t[i]);
	return d - fuzzSupport(b1, n, 1) - fuzzSupport(b2, m, 1);
}

static void fuzzInvert(const double a[3][3], double inv[3][3])
{
	double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
		+ a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
			inv[i][j] = (a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0]) / det;
		}
}

/* A body from the input: fills the oracle's copy and the library's. */
static void fuzzTakeBody(fuzzReader *r, fuzzBody *fb, mkBody3 *mb, const double *centre)
{
	for (int i = 0; i < 3; ++i) fb->ax[i] = fuzzLog(r, 0.05, 5.0);
	fb->e1 = 0.02 + 1.96 * fuzzUnit(r);
	fb->e2 = 0.02 + 1.96 * fuzzUnit(r);
	double q[4], qn = 0.0;
	for (int i = 0; i < 4; ++i) { q[i] = 2.0 * fuzzUnit(r) - 1.0; qn += q[i] * q[i]; }
	if (qn < 1e-6) { q[0] = 1.0; q[1] = q[2] = q[3] = 0.0; qn = 1.0; }
	qn = sqrt(qn);
	double w = q[0] / qn, x = q[1] / qn, y = q[2] / qn, z = q[3] / qn;
	double R[3][3] = {
		{ 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y) },
		{ 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x) },
		{ 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y) } };
	double s[3];
	for (int i = 0; i < 3; ++i) s[i] = fuzzLog(r, 0.2, 5.0);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) fb->M[i][j] = R[i][j] * s[j];
	fuzzInvert(fb->M, fb->Minv);
	if (centre) {
		double dir[3], len = 0.0, dist = fuzzLog(r, 1e-6, 30.0);
		for (int i = 0; i < 3; ++i) { dir[i] = 2.0 * fuzzUnit(r) - 1.0; len += dir[i] * dir[i]; }
		if (len < 1e-6) { dir[0] = 1.0; len = 1.0; }
		for (int i = 0; i < 3; ++i) fb->t[i] = centre[i] + dist * dir[i] / sqrt(len);
	} else {
		for (int i = 0; i < 3; ++i) fb->t[i] = 20.0 * fuzzUnit(r) - 10.0;
	}
	mb->shape = (mkShape3){ fb->ax[0], fb->ax[1], fb->ax[2], fb->e1, fb->e2 };
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) mb->M.m[i][j] = fb->M[i][j];
	mb->t = mkVec3_Make(fb->t[0], fb->t[1], fb->t[2]);
}

/* L: the largest f over the oracle's directions and the answer's normal
 * with its perturbations. */
static double fuzzLowerBound(const fuzzBody *b1, const fuzzBody *b2, const mkCollision3 *c)
{
	double L = -INFINITY;
	for (int i = -1; i <= 1; ++i)
		for (int j = -1; j <= 1; ++j)
			for (int k = -1; k <= 1; ++k) {
				double n[3] = { i, j, k };
				L = fmax(L, fuzzBound(b1, b2, n));
			}
	double d[3] = { b2->t[0] - b1->t[0], b2->t[1] - b1->t[1], b2->t[2] - b1->t[2] };
	L = fmax(L, fuzzBound(b1, b2, d));
	double n[3] = { c->normal.x, c->normal.y, c->normal.z };
	if (isfinite(n[0]) && isfinite(n[1]) && isfinite(n[2])) {
		L = fmax(L, fuzzBound(b1, b2, n));
		for (int a = 0; a < 3; ++a)
			for (int sgn = -1; sgn <= 1; sgn += 2) {
				double m[3] = { n[0], n[1], n[2] };
				m[a] += sgn * 1e-3;
				L = fmax(L, fuzzBound(b1, b2, m));
			}
	}
	return L;
}

/* 1 when some point of the centre line lies inside both bodies by a margin. */
static int fuzzCommonPoint(const fuzzBody *b1, const fuzzBody *b2)
{
	for (int k = 0; k <= 64; ++k) {
		double s = k / 64.0, x[3];
		for (int i = 0; i < 3; ++i) x[i] = (1.0 - s) * b1->t[i] + s * b2->t[i];
		if (fuzzGauge(b1, x) < 1.0 - 1e-6 && fuzzGauge(b2, x) < 1.0 - 1e-6) return 1;
	}
	return 0;
}

static void fuzzCheck(const char *what, mkResult rc, const mkCollision3 *c, const fuzzBody *b1, const fuzzBody *b2,
	double scale)
{
	FUZZ_CHECK(rc == MK_OK || rc == MK_ERR_CONVERGENCE, what);
	if (rc != MK_OK) {
		FUZZ_CHECK(c->status == MK_CONTACT_UNKNOWN, what);
		return;
	}
	double tol = 1e-7 * scale;
	double L = fuzzLowerBound(b1, b2, c);
	FUZZ_CHECK(isfinite(L), what);
	int normal = strcmp(what, "ray") != 0;
	if (normal) {
		double n[3] = { c->normal.x, c->normal.y, c->normal.z };
		FUZZ_CHECK(fabs(fuzzBound(b1, b2, n) - c->bound) <= tol, what);
		FUZZ_CHECK(c->certified == 0 || c->certified == 1, what);
	}
	if (normal && c->certified == 1) {
		FUZZ_CHECK(c->gap >= -tol && L <= c->bound + c->gap + tol, what);
		FUZZ_CHECK(c->distance >= c->bound - tol && c->distance <= c->bound + c->gap + tol, what);
		if (c->status == MK_CONTACT_SEPARATED) {
			double p1[3] = { c->p1.x, c->p1.y, c->p1.z }, p2[3] = { c->p2.x, c->p2.y, c->p2.z };
			/* the bodies are at least 0.01 thick and at most 25 * 5 * sqrt 3 wide: a witness
			 * off its body by a few ulps of the scale moves the gauge by far less than 1e-6 */
			FUZZ_CHECK(fuzzGauge(b1, p1) <= 1.0 + 1e-6 && fuzzGauge(b2, p2) <= 1.0 + 1e-6, what);
			double w = sqrt((p2[0] - p1[0]) * (p2[0] - p1[0]) + (p2[1] - p1[1]) * (p2[1] - p1[1])
				+ (p2[2] - p1[2]) * (p2[2] - p1[2]));
			FUZZ_CHECK(L <= w + tol, what);
		}
	}
	if (c->status == MK_CONTACT_OVERLAPPING) FUZZ_CHECK(L <= tol, what);
	if (c->status == MK_CONTACT_SEPARATED) FUZZ_CHECK(!fuzzCommonPoint(b1, b2), what);
}

/* The batch (mkCollide3_Batch) on the pair both ways round, twice, in one
 * mode: every answer against the oracle, as for the one-pair queries, and
 * every certain status (separated or overlapping) against the one-pair
 * query's and the swapped pair's. */
static void fuzzCheckBatch(const mkBody3 *m, const fuzzBody *f, mkBatchMode mode, double delta, mkContact single,
	double scale)
{
	enum { N = 4 };
	const int i1[N] = { 0, 1, 0, 1 }, i2[N] = { 1, 0, 1, 0 };
	mkContact st[N];
	double dist[N], lo[N], up[N];
	mkVec3 nrm[N], p1[N], p2[N];
	unsigned char clear[N], path[N];
	mkBatchPairs3 pairs = { N, m, m, i1, i2 };
	mkBatchOut3 out = { st, dist, lo, up, nrm, p1, p2, clear, path };
	mkBatchStats3 stats;
	mkResult rc = mkCollide3_Batch(&pairs, mode, delta, &out, &stats);
	FUZZ_CHECK(rc == MK_OK || rc == MK_ERR_CONVERGENCE, "batch");
	FUZZ_CHECK(stats.separating + stats.overlap_point + stats.one_pair + stats.failed == N, "batch");
	double tol = 1e-7 * scale;
	for (int k = 0; k < N; ++k) {
		const fuzzBody *a = &f[i1[k]], *b = &f[i2[k]];
		if (path[k] == MK_PATH_FAILED) { FUZZ_CHECK(rc != MK_OK && st[k] == MK_CONTACT_UNKNOWN, "batch"); continue; }
		double n[3] = { nrm[k].x, nrm[k].y, nrm[k].z };
		mkCollision3 c = { 0 };
		c.normal = nrm[k];
		double L = fuzzLowerBound(a, b, &c);
		FUZZ_CHECK(isfinite(L), "batch");
		if (isfinite(lo[k])) FUZZ_CHECK(lo[k] <= L + tol, "batch lower");
		if (!isnan(up[k]) && up[k] < INFINITY) FUZZ_CHECK(L <= up[k] + tol, "batch upper");
		if (path[k] == MK_PATH_SEPARATING) {
			double fn = fuzzBound(a, b, n);
			/* lower: f(n), or a bound below it (bounds of the support functions) */
			FUZZ_CHECK(fn >= -tol && (!isfinite(lo[k]) || lo[k] <= fn + tol), "batch separating");
		}
		if (path[k] == MK_PATH_OVERLAP_POINT) {
			double x[3] = { p1[k].x, p1[k].y, p1[k].z };
			FUZZ_CHECK(fuzzGauge(a, x) <= 1.0 + 1e-6 && fuzzGauge(b, x) <= 1.0 + 1e-6, "batch overlap point");
		}
		if (st[k] == MK_CONTACT_OVERLAPPING) FUZZ_CHECK(L <= tol, "batch overlapping");
		if (st[k] == MK_CONTACT_SEPARATED) FUZZ_CHECK(!fuzzCommonPoint(a, b), "batch separated");
		if (mode == MK_BATCH_CLEARANCE && clear[k] == 0) FUZZ_CHECK(L <= delta + tol, "batch clearance");
		if ((mode == MK_BATCH_DISTANCE || mode == MK_BATCH_FULL) && isfinite(dist[k])) {
			/* certified (a finite bracket): the distance lies in it, so no direction does better; an
			 * overlap whose depth search ran out of budget has a local optimum and no bracket */
			if (isfinite(lo[k]) && isfinite(up[k]))
				FUZZ_CHECK(dist[k] >= lo[k] - tol && dist[k] <= up[k] + tol && L <= dist[k] + (up[k] - lo[k]) + tol,
					"batch distance");
			if (st[k] == MK_CONTACT_SEPARATED) {
				double w1[3] = { p1[k].x, p1[k].y, p1[k].z }, w2[3] = { p2[k].x, p2[k].y, p2[k].z };
				FUZZ_CHECK(fuzzGauge(a, w1) <= 1.0 + 1e-6 && fuzzGauge(b, w2) <= 1.0 + 1e-6, "batch witnesses");
				double w = sqrt((w2[0] - w1[0]) * (w2[0] - w1[0]) + (w2[1] - w1[1]) * (w2[1] - w1[1])
					+ (w2[2] - w1[2]) * (w2[2] - w1[2]));
				FUZZ_CHECK(w >= dist[k] - tol, "batch witnesses");
			}
		}
		int certain = st[k] == MK_CONTACT_SEPARATED || st[k] == MK_CONTACT_OVERLAPPING;
		if (certain && (single == MK_CONTACT_SEPARATED || single == MK_CONTACT_OVERLAPPING))
			FUZZ_CHECK(st[k] == single, "batch against one pair");
		if (certain && (st[k ^ 1] == MK_CONTACT_SEPARATED || st[k ^ 1] == MK_CONTACT_OVERLAPPING))
			FUZZ_CHECK(st[k] == st[k ^ 1], "batch swapped");
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fuzzReader r = { data, size };
	fuzzBody f1, f2;
	mkBody3 m1, m2;
	fuzzTakeBody(&r, &f1, &m1, NULL);
	fuzzTakeBody(&r, &f2, &m2, f1.t);
	FUZZ_CHECK(mkBody3_IsValid(m1, "body1", NULL, 0) && mkBody3_IsValid(m2, "body2", NULL, 0), "input");
	/* the oracle's own pair size: |d| + r1 + r2, r = max axis times |M|_F */
	double scale = 0.0, r1 = 0.0, r2 = 0.0;
	for (int i = 0; i < 3; ++i) {
		scale += (f2.t[i] - f1.t[i]) * (f2.t[i] - f1.t[i]);
		for (int j = 0; j < 3; ++j) { r1 += f1.M[i][j] * f1.M[i][j]; r2 += f2.M[i][j] * f2.M[i][j]; }
	}
	scale = sqrt(scale) + fmax(f1.ax[0], fmax(f1.ax[1], f1.ax[2])) * sqrt(r1)
		+ fmax(f2.ax[0], fmax(f2.ax[1], f2.ax[2])) * sqrt(r2);

	mkCollision3 c;
	mkResult rc = mkCollide3_Normal(m1, m2, &c);
	fuzzCheck("normal", rc, &c, &f1, &f2, scale);
	mkContact single = c.status;
	uint8_t pick = fuzzTake(&r);
	mkVec3 start = mkVec3_Make((pick & 3) - 1.5, ((pick >> 2) & 3) - 1.5, ((pick >> 4) & 3) - 1.5);
	rc = mkCollide3_NormalFrom(m1, m2, start, &c);
	fuzzCheck("normal-from", rc, &c, &f1, &f2, scale);
	rc = mkCollide3_Ray(m1, m2, &c);
	fuzzCheck("ray", rc, &c, &f1, &f2, scale);
	uint8_t how = fuzzTake(&r), kind = fuzzTake(&r);
	mkBody3 mm[2] = { m1, m2 };
	fuzzBody ff[2] = { f1, f2 };
	/* the batch's ellipsoid paths need exponents of exactly 1, which the
	 * decoded exponents never are: the last byte's low bits make them so */
	for (int i = 0; i < 2; ++i)
		if (kind & (1u << i)) {
			ff[i].e1 = ff[i].e2 = 1.0;
			mm[i].shape.eps1 = mm[i].shape.eps2 = 1.0;
		}
	if (kind & 3u) {
		mkCollision3 ce;
		mkResult re = mkCollide3_Normal(mm[0], mm[1], &ce);
		fuzzCheck("normal (ellipsoids)", re, &ce, &ff[0], &ff[1], scale);
		single = ce.status;
	}
	fuzzCheckBatch(mm, ff, (mkBatchMode)(how & 3), 0.5 * scale * (how >> 2) / 63.0, single, scale);
	return 0;
}
