/* test_demos.c - the geometry the demos driver wrote, checked against the
 * bodies' own implicit functions, written here from the definitions in
 * mink/body.h and independent of the core's closed forms.
 *
 * Usage: test_demos <index CSV of a demos run>
 *
 * The check uses the gauge of a body, g(x) = Psi(M^-1 (x - t))^(eps1 / 2),
 * which is 1 on the boundary, below 1 inside, above outside, and grows
 * linearly with the distance (it is a norm of M^-1 (x - t)). A boundary
 * point computed in double precision carries a relative position error of
 * a few 1e-15 (the core's own tests bound the closed forms near 1e-13 of the
 * body's size), and the maps here have condition numbers below 5, so its
 * gauge is 1 within about 1e-12. TOL = 1e-9 leaves a wide margin and still
 * fails at once for a wrong body, a wrong pose or a point off the boundary
 * (those move the gauge by 1e-2 or more). A body that merely touches
 * another (B2 placed on the sum) has all its points at gauge >= 1 - TOL with
 * respect to the other. */
#include "ensure.h"
#include "exp_testing.h"

#include <mink/mink.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOL 1e-9

/* ---- gauges from the definitions ----------------------------------------- */

/* pnorm2 (exp_testing.h): the p-norm of (u, v), scaled against overflow. */

static mkVec2 inv2(mkMat2 M, mkVec2 x)
{
	double det = M.m[0][0] * M.m[1][1] - M.m[0][1] * M.m[1][0];
	mkVec2 r = { (M.m[1][1] * x.x - M.m[0][1] * x.y) / det, (-M.m[1][0] * x.x + M.m[0][0] * x.y) / det };
	return r;
}

static mkVec3 inv3(mkMat3 M, mkVec3 x)
{
	double m[3][3];
	memcpy(m, M.m, sizeof m);
	double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
	double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
	double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
	double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
	/* Rows of the inverse are the columns of the cofactor matrix / det. */
	double i00 = c00, i01 = m[0][2] * m[2][1] - m[0][1] * m[2][2], i02 = m[0][1] * m[1][2] - m[0][2] * m[1][1];
	double i10 = c01, i11 = m[0][0] * m[2][2] - m[0][2] * m[2][0], i12 = m[0][2] * m[1][0] - m[0][0] * m[1][2];
	double i20 = c02, i21 = m[0][1] * m[2][0] - m[0][0] * m[2][1], i22 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
	mkVec3 r = { (i00 * x.x + i01 * x.y + i02 * x.z) / det, (i10 * x.x + i11 * x.y + i12 * x.z) / det,
		(i20 * x.x + i21 * x.y + i22 * x.z) / det };
	return r;
}

/* Superellipse: Psi = |x/a|^(2/e) + |y/b|^(2/e); gauge = Psi^(e/2), the
 * (2/e)-norm of (x/a, y/b). `c` is where the body's centre is placed. */
static double gauge2(mkBody2 b, mkVec2 c, mkVec2 x)
{
	mkVec2 d = { x.x - c.x, x.y - c.y };
	mkVec2 v = inv2(b.M, d);
	return pnorm2(v.x / b.shape.a, v.y / b.shape.b, 2.0 / b.shape.eps);
}

/* Superquadric: Psi = (|x/a|^(2/e2) + |y/b|^(2/e2))^(e2/e1) + |z/c|^(2/e1);
 * gauge = Psi^(e1/2) = || ( ||(x/a, y/b)||_{2/e2}, z/c ) ||_{2/e1}. */
static double gauge3(mkBody3 b, mkVec3 c, mkVec3 x)
{
	mkVec3 d = { x.x - c.x, x.y - c.y, x.z - c.z };
	mkVec3 v = inv3(b.M, d);
	double r = pnorm2(v.x / b.shape.a, v.y / b.shape.b, 2.0 / b.shape.eps2);
	return pnorm2(r, v.z / b.shape.c, 2.0 / b.shape.eps1);
}

/* The body of a SPEC text into *out: an mkBody2 when dim is 2, an mkBody3
 * when 3. Returns 0, or -1 with a message. */
static int parseBody(const char *text, int dim, void *out)
{
	mkSpec s;
	char msg[256];
	if (mkSpec_Parse(text, dim, "body", &s, msg, sizeof msg) != MK_OK) {
		fprintf(stderr, "SPEC '%s': %s\n", text, msg);
		return -1;
	}
	if (dim == 2)
		*(mkBody2 *)out = s.body2;
	else
		*(mkBody3 *)out = s.body3;
	return 0;
}

/* ---- the files ------------------------------------------------------------ */

static char dir[2048];

/* A geometry file of the run (blank lines separate its blocks; *blank,
 * when not NULL, receives their number). Returns 0, or -1 when missing or
 * malformed. */
static int readFile(mkTable *t, const char *name, long *blank)
{
	char path[4096];
	long b = 0;
	snprintf(path, sizeof path, "%s/%s", dir, name);
	mkTable_LoadBlocks(t, path, &b);
	if (blank)
		*blank = b;
	return t->present ? 0 : -1;
}

/* The sidecar exists and its "rows:" equals the index's count. */
static void checkSidecar(const char *name, long rows)
{
	char path[4096], line[4096];
	snprintf(path, sizeof path, "%s/%s.meta", dir, name);
	FILE *fp = fopen(path, "r");
	ENSURE(fp != NULL);
	if (!fp)
		return;
	long got = -1;
	while (fgets(line, sizeof line, fp))
		if (strncmp(line, "rows: ", 6) == 0)
			got = strtol(line + 6, NULL, 10);
	fclose(fp);
	ENSURE(got == rows);
}

static long findIndexRow(const mkTable *ix, const char *file)
{
	for (long r = 0; r < ix->rows; ++r)
		if (strcmp(str(ix, r, "file"), file) == 0)
			return r;
	return -1;
}

/* The index row of `file` and the two bodies of its SPEC texts, which must
 * have the paper's parameters want1, want2 (a, b, eps) exactly; -1 when
 * the row is missing. */
static long findPair2(const mkTable *ix, const char *file, const double want1[3], const double want2[3],
	mkBody2 *b1, mkBody2 *b2)
{
	long r = findIndexRow(ix, file);
	ENSURE(r >= 0);
	if (r < 0)
		return -1;
	ENSURE(parseBody(str(ix, r, "body1"), 2, b1) == 0);
	ENSURE(parseBody(str(ix, r, "body2"), 2, b2) == 0);
	ENSURE(b1->shape.a == want1[0] && b1->shape.b == want1[1] && b1->shape.eps == want1[2]);
	ENSURE(b2->shape.a == want2[0] && b2->shape.b == want2[1] && b2->shape.eps == want2[2]);
	return r;
}

/* ---- Fig. 1 --------------------------------------------------------------- */

static void checkFigure1(const mkTable *ix)
{
	/* The paper's parameters. */
	static const double want1[3] = { 10.0, 8.6, 0.36 }, want2[3] = { 9.4, 6.8, 1.28 };
	mkBody2 b1, b2;
	if (findPair2(ix, "fig1-closed.csv", want1, want2, &b1, &b2) < 0)
		return;

	mkTable bodies, pairs, closed;
	ENSURE(readFile(&bodies, "fig1-bodies.csv", NULL) == 0);
	ENSURE(readFile(&pairs, "fig1-pairwise.csv", NULL) == 0);
	ENSURE(readFile(&closed, "fig1-closed.csv", NULL) == 0);
	ENSURE(bodies.rows == 102 && pairs.rows == 2500 && closed.rows == 51);
	if (bodies.rows != 102 || pairs.rows != 2500 || closed.rows != 51)
		return;
	/* Samples on their bodies (-B2's samples are the negated B2 points). */
	mkVec2 zero = { 0.0, 0.0 };
	double worst = 0.0;
	for (long k = 0; k < 102; ++k) {
		mkVec2 p = { num(&bodies, k, "x"), num(&bodies, k, "y") };
		int minus = strcmp(str(&bodies, k, "body"), "minus_b2") == 0;
		mkVec2 q = { minus ? -p.x : p.x, minus ? -p.y : p.y };
		worst = fmax(worst, fabs(gauge2(minus ? b2 : b1, zero, q) - 1.0));
	}
	ENSURE(worst <= TOL);
	/* The definition: row i*50 + j is x1_i - x2_j, i.e. the sum of the two
	 * samples written in the bodies file (negation is exact, so a - b and
	 * a + (-b) are the same double). */
	int exact = 1;
	for (int i = 0; i < 50; ++i)
		for (int j = 0; j < 50; ++j) {
			long row = i * 50 + j;
			double x = num(&bodies, i, "x") + num(&bodies, 51 + j, "x");
			double y = num(&bodies, i, "y") + num(&bodies, 51 + j, "y");
			exact = exact && num(&pairs, row, "x") == x && num(&pairs, row, "y") == y;
		}
	ENSURE(exact);
	/* The closed form: B1's point at the same parameter is the sample k
	 * (computed by the batch kernel, which may use SLEEF's 1-ulp powers,
	 * while the sample came from the scalar mkBody2_Point: coordinates near
	 * 15 then differ by a few 1e-15; 1e-12 bounds it), and B2 centred at x
	 * touches B1 there. */
	double wb1 = 0.0, wb2 = 0.0;
	int same = 1;
	for (int k = 0; k <= 50; ++k) {
		mkVec2 x = { num(&closed, k, "x"), num(&closed, k, "y") };
		mkVec2 p = { num(&closed, k, "x1"), num(&closed, k, "y1") };
		same = same && fabs(p.x - num(&bodies, k, "x")) <= 1e-12
			&& fabs(p.y - num(&bodies, k, "y")) <= 1e-12;
		wb1 = fmax(wb1, fabs(gauge2(b1, zero, p) - 1.0));
		wb2 = fmax(wb2, fabs(gauge2(b2, x, p) - 1.0));
	}
	printf("fig1: |g-1| samples %.3g, kissing points on B1 %.3g, on B2 at the sum point %.3g\n", worst, wb1, wb2);
	ENSURE(same);
	ENSURE(wb1 <= TOL);
	ENSURE(wb2 <= TOL);
	mkTable_Free(&bodies);
	mkTable_Free(&pairs);
	mkTable_Free(&closed);
}

/* ---- Fig. 2 --------------------------------------------------------------- */

static void checkFigure2(const mkTable *ix)
{
	static const double want1[3] = { 3.3, 2.6, 0.73 }, want2[3] = { 2.4, 2.0, 1.28 };
	mkBody2 b1, b2;
	if (findPair2(ix, "fig2-contact.csv", want1, want2, &b1, &b2) < 0)
		return;
	mkTable c;
	ENSURE(readFile(&c, "fig2-contact.csv", NULL) == 0);
	ENSURE(c.rows == 2);
	mkVec2 zero = { 0.0, 0.0 };
	for (long k = 0; k < c.rows; ++k) {
		mkVec2 p = { num(&c, k, "px"), num(&c, k, "py") };
		mkVec2 c2 = { num(&c, k, "c2x"), num(&c, k, "c2y") };
		mkVec2 v1 = { num(&c, k, "v1x"), num(&c, k, "v1y") };
		mkVec2 v2 = { num(&c, k, "v2x"), num(&c, k, "v2y") };
		/* The contact point is on both bodies. */
		ENSURE_NEAR(gauge2(b1, zero, p), 1.0, TOL);
		ENSURE_NEAR(gauge2(b2, c2, p), 1.0, TOL);
		/* The paired vectors are anti-parallel: a touching pair of smooth
		 * convex bodies has opposite normals at the contact. The sine of
		 * the angle between them is at rounding level for exact points;
		 * 1e-9 as for the gauges. */
		double n1 = hypot(v1.x, v1.y), n2 = hypot(v2.x, v2.y);
		ENSURE(fabs(v1.x * v2.y - v1.y * v2.x) / (n1 * n2) <= TOL);
		ENSURE(v1.x * v2.x + v1.y * v2.y < 0.0);
		if (k == 0) {
			/* Theorem 1: unit normals. */
			ENSURE_NEAR(n1, 1.0, 1e-12);
			ENSURE_NEAR(n2, 1.0, 1e-12);
		}
		/* Both theorems find the same sum point: the distance is a few
		 * units of rounding of coordinates near 5. */
		ENSURE(num(&c, k, "x_difference") <= 1e-12);
		printf("fig2 theorem %ld: |g-1| contact on B1 %.3g, on B2 %.3g; sin(v1, v2) %.3g\n", k + 1,
			fabs(gauge2(b1, zero, p) - 1.0), fabs(gauge2(b2, c2, p) - 1.0),
			fabs(v1.x * v2.y - v1.y * v2.x) / (n1 * n2));
	}
	mkTable_Free(&c);
}

/* ---- Fig. 3 --------------------------------------------------------------- */

/* The k-th " | "-separated part of text into buf. */
static void part(const char *text, int k, char *buf, size_t len)
{
	const char *p = text;
	for (int i = 0; i < k && p; ++i) {
		p = strstr(p, " | ");
		if (p)
			p += 3;
	}
	if (!p) {
		buf[0] = '\0';
		return;
	}
	const char *e = strstr(p, " | ");
	size_t n = e ? (size_t)(e - p) : strlen(p);
	if (n >= len)
		n = len - 1;
	memcpy(buf, p, n);
	buf[n] = '\0';
}

static void checkFigure3(const mkTable *ix)
{
	static const char *const panels[4] = { "canonical", "rotated", "sheared", "rotated+sheared" };
	long r = findIndexRow(ix, "fig3.csv");
	ENSURE(r >= 0);
	if (r < 0)
		return;
	mkTable t;
	ENSURE(readFile(&t, "fig3.csv", NULL) == 0);
	mkVec2 zero = { 0.0, 0.0 };
	for (int p = 0; p < 4; ++p) {
		char s1[512], s2[512];
		part(str(ix, r, "body1"), p, s1, sizeof s1);
		part(str(ix, r, "body2"), p, s2, sizeof s2);
		mkBody2 b1, b2;
		ENSURE(parseBody(s1, 2, &b1) == 0);
		ENSURE(parseBody(s2, 2, &b2) == 0);
		/* The sum's 100 points (and the closing row) with their centres. */
		mkVec2 sum[101];
		int nsum = 0, places = 0;
		double on1 = 0.0, on2 = 0.0, b2on = 0.0, b1on = 0.0, outside = 2.0;
		for (long k = 0; k < t.rows; ++k) {
			if (strcmp(str(&t, k, "panel"), panels[p]) != 0)
				continue;
			const char *curve = str(&t, k, "curve");
			mkVec2 x = { num(&t, k, "x"), num(&t, k, "y") };
			if (strcmp(curve, "sum") == 0 && nsum < 101) {
				mkVec2 kiss = { num(&t, k, "kx"), num(&t, k, "ky") };
				sum[nsum++] = x;
				on1 = fmax(on1, fabs(gauge2(b1, zero, kiss) - 1.0));
				on2 = fmax(on2, fabs(gauge2(b2, x, kiss) - 1.0));
			} else if (strcmp(curve, "b1") == 0) {
				b1on = fmax(b1on, fabs(gauge2(b1, zero, x) - 1.0));
			} else if (strcmp(curve, "b2") == 0) {
				/* B2 at place q is centred at the sum point k = 10 q (the
				 * sum rows come before the B2 rows). */
				int q = (int)num(&t, k, "place");
				places = q + 1 > places ? q + 1 : places;
				ENSURE(nsum == 101 && q >= 0 && q < 10);
				if (nsum == 101 && q >= 0 && q < 10) {
					b2on = fmax(b2on, fabs(gauge2(b2, sum[10 * q], x) - 1.0));
					outside = fmin(outside, gauge2(b1, zero, x));
				}
			}
		}
		printf("fig3 %s: |g-1| kiss on B1 %.3g, on B2 %.3g, B1 outline %.3g, B2 outlines %.3g; min g1 on B2 %.6f\n",
			panels[p], on1, on2, b1on, b2on, outside);
		ENSURE(nsum == 101);
		ENSURE(places == 10);
		ENSURE(on1 <= TOL);      /* kissing points on B1 */
		ENSURE(on2 <= TOL);      /* ... and on B2 centred at the sum point */
		ENSURE(b1on <= TOL);     /* B1's outline on B1 */
		ENSURE(b2on <= TOL);     /* B2's outlines on B2 at their centres */
		ENSURE(outside >= 1.0 - TOL);   /* no placed B2 enters B1 */
		ENSURE(outside <= 1.05); /* ... but each comes close: it touches */
	}
	mkTable_Free(&t);
}

/* ---- Fig. 4 --------------------------------------------------------------- */

/* Surface points of one block of a fig4 file: rows i = 0..49, j = 0..50. */
typedef struct mkGrid { long count; mkVec3 p[50 * 51]; int i[50 * 51], j[50 * 51]; } mkGrid;

static void loadSurface(const mkTable *t, const char *name, mkGrid *g)
{
	g->count = 0;
	for (long k = 0; k < t->rows && g->count < 50 * 51; ++k) {
		if (strcmp(str(t, k, "surface"), name) != 0)
			continue;
		mkVec3 x = { num(t, k, "x"), num(t, k, "y"), num(t, k, "z") };
		g->p[g->count] = x;
		g->i[g->count] = (int)num(t, k, "i");
		g->j[g->count] = (int)num(t, k, "j");
		g->count += 1;
	}
}

static mkGrid gb1, gsum, gb2;

/* The rotation of a unit quaternion (w, x, y, z), written out. */
static mkMat3 quatRot(double w, double x, double y, double z)
{
	double n = sqrt(w * w + x * x + y * y + z * z);
	w /= n; x /= n; y /= n; z /= n;
	mkMat3 R = { { { 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y) },
		{ 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x) },
		{ 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y) } } };
	return R;
}

static void checkFigure4(const mkTable *ix)
{
	static const char *const panels = "abcdefgh";
	for (int p = 0; p < 8; ++p) {
		char file[32];
		snprintf(file, sizeof file, "fig4-%c.csv", panels[p]);
		long r = findIndexRow(ix, file);
		ENSURE(r >= 0);
		if (r < 0)
			continue;
		mkBody3 b1, b2;
		ENSURE(parseBody(str(ix, r, "body1"), 3, &b1) == 0);
		ENSURE(parseBody(str(ix, r, "body2"), 3, &b2) == 0);
		mkTable t;
		long blank = 0;
		ENSURE(readFile(&t, file, &blank) == 0);
		/* Three surfaces of 50 rows of 51 points; a blank line after each
		 * grid row and one more after each surface. */
		ENSURE(t.rows == 3 * 50 * 51);
		ENSURE(blank == 3 * 50 + 3);
		loadSurface(&t, "b1", &gb1);
		loadSurface(&t, "sum", &gsum);
		loadSurface(&t, "b2", &gb2);
		ENSURE(gb1.count == 50 * 51 && gsum.count == 50 * 51 && gb2.count == 50 * 51);
		/* Where B2 was placed: the grid index in the note. */
		int ci = -1, cj = -1;
		const char *note = strstr(str(ix, r, "note"), "(i, j) = (");
		ENSURE(note && sscanf(note, "(i, j) = (%d, %d)", &ci, &cj) == 2);
		mkVec3 c2 = { NAN, NAN, NAN };
		for (long k = 0; k < gsum.count; ++k)
			if (gsum.i[k] == ci && gsum.j[k] == cj)
				c2 = gsum.p[k];
		ENSURE(isfinite(c2.x));
		mkVec3 zero = { 0.0, 0.0, 0.0 };
		double on1 = 0.0, kiss2 = 0.0, on2 = 0.0, outside = 2.0;
		for (long k = 0; k < gb1.count; ++k) {
			on1 = fmax(on1, fabs(gauge3(b1, zero, gb1.p[k]) - 1.0));
			/* With the surface parameters, B1's point at the same (i, j)
			 * is the kissing point: B2 centred at the sum point touches it
			 * (the poles included). */
			kiss2 = fmax(kiss2, fabs(gauge3(b2, gsum.p[k], gb1.p[k]) - 1.0));
			on2 = fmax(on2, fabs(gauge3(b2, c2, gb2.p[k]) - 1.0));
			outside = fmin(outside, gauge3(b1, zero, gb2.p[k]));
		}
		printf("fig4-%c: |g1 - 1| %.3g, kiss |g2 - 1| %.3g, B2 |g2 - 1| %.3g, min g1 on B2 %.6f\n",
			panels[p], on1, kiss2, on2, outside);
		ENSURE(on1 <= TOL);
		ENSURE(kiss2 <= TOL);
		ENSURE(on2 <= TOL);
		ENSURE(outside >= 1.0 - TOL);

		if (panels[p] == 'h') {
			/* Two ellipsoids: the paper's closed form (eq.
			 * ellipsoid_mink_sum_phi) written out here: with B1 = R1 D1 u
			 * and the outward normal n ~ R1 D1^-1 u at it, the contact
			 * point is x = R1 D1 u + A2^2 n / |A2 n|, A2 = R2 D2 R2^T. The
			 * grid directions are recomputed from (i, j). Both sides are
			 * O(10) operations on numbers near 10: agreement to 1e-9 of
			 * the size leaves a wide margin over rounding. */
			const char *q1 = strstr(str(ix, r, "body1"), "quat=");
			const char *q2 = strstr(str(ix, r, "body2"), "quat=");
			double w1[4], w2[4];
			ENSURE(q1 && sscanf(q1, "quat=%lf,%lf,%lf,%lf", &w1[0], &w1[1], &w1[2], &w1[3]) == 4);
			ENSURE(q2 && sscanf(q2, "quat=%lf,%lf,%lf,%lf", &w2[0], &w2[1], &w2[2], &w2[3]) == 4);
			mkMat3 R1 = quatRot(w1[0], w1[1], w1[2], w1[3]), R2 = quatRot(w2[0], w2[1], w2[2], w2[3]);
			double D1[3] = { b1.shape.a, b1.shape.b, b1.shape.c }, D2[3] = { b2.shape.a, b2.shape.b, b2.shape.c };
			double worst = 0.0;
			for (long k = 0; k < gsum.count; ++k) {
				int i = gsum.i[k], j = gsum.j[k];
				double u[3];
				if (i < 0 || i == 50) {
					u[0] = 0.0; u[1] = 0.0; u[2] = i < 0 ? -1.0 : 1.0;
				} else {
					double eta = -MK_PI / 2 + MK_PI * i / 49.0, om = -MK_PI + 2 * MK_PI * (j % 50) / 50.0;
					u[0] = cos(eta) * cos(om); u[1] = cos(eta) * sin(om); u[2] = sin(eta);
				}
				double p1[3], n[3], nl[3], n2l[3], x[3];
				for (int a = 0; a < 3; ++a) {
					p1[a] = 0.0;
					n[a] = 0.0;
				}
				for (int a = 0; a < 3; ++a)
					for (int b = 0; b < 3; ++b) {
						p1[a] += R1.m[a][b] * D1[b] * u[b];
						n[a] += R1.m[a][b] * u[b] / D1[b];
					}
				/* nl = D2 R2^T n; A2^2 n / |A2 n| = R2 D2 nl / |nl|. */
				for (int a = 0; a < 3; ++a) {
					nl[a] = 0.0;
					for (int b = 0; b < 3; ++b)
						nl[a] += R2.m[b][a] * n[b];
					nl[a] *= D2[a];
				}
				double len = sqrt(nl[0] * nl[0] + nl[1] * nl[1] + nl[2] * nl[2]);
				for (int a = 0; a < 3; ++a)
					n2l[a] = D2[a] * nl[a] / len;
				for (int a = 0; a < 3; ++a) {
					x[a] = p1[a];
					for (int b = 0; b < 3; ++b)
						x[a] += R2.m[a][b] * n2l[b];
				}
				double d = sqrt((x[0] - gsum.p[k].x) * (x[0] - gsum.p[k].x) + (x[1] - gsum.p[k].y) * (x[1] - gsum.p[k].y)
					+ (x[2] - gsum.p[k].z) * (x[2] - gsum.p[k].z));
				worst = fmax(worst, d);
			}
			printf("fig4-h: largest distance from the ellipsoid formula %.3g\n", worst);
			ENSURE(worst <= 1e-8);   /* 1e-9 of the size, about 12 */
		}
		mkTable_Free(&t);
	}
}

int main(int argc, char **argv)
{
	if (argc != 2) {
		fprintf(stderr, "usage: test_demos <index CSV of a demos run>\n");
		return 2;
	}
	const char *index = argv[1];
	size_t n = strlen(index);
	ENSURE(n > 4 && strcmp(index + n - 4, ".csv") == 0);
	snprintf(dir, sizeof dir, "%.*s", (int)(n - 4), index);

	mkTable ix;
	mkTable_Load(&ix, index);
	ENSURE(ix.present);
	/* Three files for Fig. 1, three for Fig. 2, one for Fig. 3, eight for
	 * Fig. 4; each has its sidecar with the same row count. */
	ENSURE(ix.rows == 15);
	for (long r = 0; r < ix.rows; ++r)
		checkSidecar(str(&ix, r, "file"), (long)num(&ix, r, "rows"));
	checkFigure1(&ix);
	checkFigure2(&ix);
	checkFigure3(&ix);
	checkFigure4(&ix);
	mkTable_Free(&ix);
	return mk_summary("demos");
}
