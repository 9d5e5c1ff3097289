/* test_teeth.c - the referee fails wrong outputs: boundary points moved off
 * the boundary by far less than anything a plotted figure would show,
 * points judged against the wrong set or in the wrong order, hulls with a
 * vertex missing, added, rounded differently or in the wrong order, and
 * points paired with body 2's support point for a slightly wrong normal. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/referee.h>
#include <mink/registry.h>

#include "cases.h"

static mkPointSet copy(const mkPointSet *p)
{
	mkPointSet c = {0};
	mkPointSet_Resize(&c, p->dim, p->count);
	memcpy(c.x, p->x, (size_t)p->count * sizeof *c.x);
	memcpy(c.y, p->y, (size_t)p->count * sizeof *c.y);
	if (p->dim == 3) memcpy(c.z, p->z, (size_t)p->count * sizeof *c.z);
	return c;
}

static int judge2(const mkMethod *m, const Case2 *c, mkSet set, int n, const mkPointSet *p)
{
	mkVerdict v;
	mkRefereeOptions opt = {2048, 0, 0, 0};
	if (mkReferee2_Check(m, c->a, c->b, set, n, p, &opt, &v) != MK_OK) return -1;
	return v.pass;
}

static int judge3(const mkMethod *m, const Case3 *c, mkSet set, int n, const mkPointSet *p)
{
	mkVerdict v;
	mkRefereeOptions opt = {32, 0, 0, 0};
	if (mkReferee3_Check(m, c->a, c->b, set, n, p, &opt, &v) != MK_OK) return -1;
	return v.pass;
}

/* Boundary points in 2D: moved out or in along the normal, slid along the
 * tangent, NaN, the wrong set, the wrong order. */
static void teethBoundary2(const Case2 *c)
{
	const int n = 200, k = 37;
	mkPointSet good = {0}, bad;
	ENSURE(mkMethod_ClosedGradient.run2(c->a, c->b, MK_SET_CONTACT, n, &good) == MK_OK);
	ENSURE(judge2(&mkMethod_ClosedGradient, c, MK_SET_CONTACT, n, &good) == 1);
	double *u = malloc(2 * (size_t)n * sizeof *u);
	mkSample2_Angles(n, u, u + n);
	mkVec2 nrm;
	mkReferee2_Point(c->a, (mkVec2){u[k], u[n + k]}, &nrm);
	mkVerdict v;
	ENSURE(mkReferee2_Check(&mkMethod_ClosedGradient, c->a, c->b, MK_SET_CONTACT, n, &good, NULL, &v) == MK_OK);
	/* A move of 1e-11 of the extent, some twenty times the allowance: out
	 * along the normal, then in. */
	double d = 1e-11 * v.extent;
	bad = copy(&good);
	bad.x[k] += d * nrm.x;
	bad.y[k] += d * nrm.y;
	ENSURE(judge2(&mkMethod_ClosedGradient, c, MK_SET_CONTACT, n, &bad) == 0);
	bad.x[k] = good.x[k] - d * nrm.x;
	bad.y[k] = good.y[k] - d * nrm.y;
	ENSURE(judge2(&mkMethod_ClosedGradient, c, MK_SET_CONTACT, n, &bad) == 0);
	/* A slide along the tangent by 5% of the extent leaves the point on the
	 * tangent line, so the normal alone cannot see it; it lies outside the
	 * set by about slide^2 / (2 rho), which the fan of nearby directions
	 * does see. */
	bad.x[k] = good.x[k] - 0.05 * v.extent * nrm.y;
	bad.y[k] = good.y[k] + 0.05 * v.extent * nrm.x;
	ENSURE(judge2(&mkMethod_ClosedGradient, c, MK_SET_CONTACT, n, &bad) == 0);
	mkRefereeOptions nofan = {2048, 0, 1, 0};
	ENSURE(mkReferee2_Check(&mkMethod_ClosedGradient, c->a, c->b, MK_SET_CONTACT, n, &bad, &nofan, &v) == MK_OK);
	ENSURE(v.pass); /* without the fan it escapes: the fan is what catches it */
	/* A NaN. */
	bad.x[k] = NAN;
	ENSURE(judge2(&mkMethod_ClosedGradient, c, MK_SET_CONTACT, n, &bad) == 0);
	mkPointSet_Free(&bad);
	/* The contact set judged as the plus set (body 2 is off the origin). */
	ENSURE(judge2(&mkMethod_ClosedGradient, c, MK_SET_PLUS, n, &good) == 0);
	/* The points in reverse order: each judged against another normal. */
	bad = copy(&good);
	for (int i = 0; i < n; ++i) bad.x[i] = good.x[n - 1 - i], bad.y[i] = good.y[n - 1 - i];
	ENSURE(judge2(&mkMethod_ClosedGradient, c, MK_SET_CONTACT, n, &bad) == 0);
	mkPointSet_Free(&bad);
	free(u);

	mkPointSet_Free(&good);
}

/* Hulls in 2D: rotated (passes), clockwise, a vertex missing, twice, or one
 * ulp off. */
static void teethHulls2(const Case2 *c)
{
	mkPointSet good = {0}, bad;
	const int ns = 64;
	ENSURE(mkMethod_HullCgalEpick.run2(c->a, c->b, MK_SET_CONTACT, ns, &good) == MK_OK);
	ENSURE(judge2(&mkMethod_HullCgalEpick, c, MK_SET_CONTACT, ns, &good) == 1);
	int h = good.count;
	/* Rotated to start elsewhere: still the same polygon. */
	bad = copy(&good);
	for (int i = 0; i < h; ++i) bad.x[i] = good.x[(i + 5) % h], bad.y[i] = good.y[(i + 5) % h];
	ENSURE(judge2(&mkMethod_HullCgalEpick, c, MK_SET_CONTACT, ns, &bad) == 1);
	/* Clockwise. */
	for (int i = 0; i < h; ++i) bad.x[i] = good.x[h - 1 - i], bad.y[i] = good.y[h - 1 - i];
	ENSURE(judge2(&mkMethod_HullCgalEpick, c, MK_SET_CONTACT, ns, &bad) == 0);
	/* A vertex missing. */
	for (int i = 0; i + 1 < h; ++i) bad.x[i] = good.x[i + (i >= 10)], bad.y[i] = good.y[i + (i >= 10)];
	bad.count = h - 1;
	ENSURE(judge2(&mkMethod_HullCgalEpick, c, MK_SET_CONTACT, ns, &bad) == 0);
	/* A vertex given twice. */
	mkPointSet_Resize(&bad, 2, h + 1);
	for (int i = 0; i <= h; ++i) bad.x[i] = good.x[i - (i > 10)], bad.y[i] = good.y[i - (i > 10)];
	ENSURE(judge2(&mkMethod_HullCgalEpick, c, MK_SET_CONTACT, ns, &bad) == 0);
	mkPointSet_Free(&bad);
	/* A vertex one ulp off: no longer an input sum. */
	bad = copy(&good);
	bad.x[3] = nextafter(bad.x[3], HUGE_VAL);
	ENSURE(judge2(&mkMethod_HullCgalEpick, c, MK_SET_CONTACT, ns, &bad) == 0);
	mkPointSet_Free(&bad);

	mkPointSet_Free(&good);
}

/* Boundary points in 3D: moved out or in along the normal. */
static void teethBoundary3(const Case3 *e)
{
	mkPointSet good = {0}, bad;
	const int n3 = 12, k3 = 5 * 12 + 7;
	ENSURE(mkMethod_ClosedNormal.run3(e->a, e->b, MK_SET_PLUS, n3, &good) == MK_OK);
	ENSURE(judge3(&mkMethod_ClosedNormal, e, MK_SET_PLUS, n3, &good) == 1);
	mkVerdict v;
	ENSURE(mkReferee3_Check(&mkMethod_ClosedNormal, e->a, e->b, MK_SET_PLUS, n3, &good, NULL, &v) == MK_OK);
	double *u3 = malloc(3 * (size_t)n3 * n3 * sizeof *u3);
	mkSample3_Grid(n3, u3, u3 + n3 * n3, u3 + 2 * n3 * n3);
	mkVec3 nn;
	mkReferee3_Point(e->a, (mkVec3){u3[k3], u3[n3 * n3 + k3], u3[2 * n3 * n3 + k3]}, &nn);
	bad = copy(&good);
	double d = 1e-11 * v.extent;
	bad.x[k3] += d * nn.x;
	bad.y[k3] += d * nn.y;
	bad.z[k3] += d * nn.z;
	ENSURE(judge3(&mkMethod_ClosedNormal, e, MK_SET_PLUS, n3, &bad) == 0);
	bad.x[k3] = good.x[k3] - d * nn.x;
	bad.y[k3] = good.y[k3] - d * nn.y;
	bad.z[k3] = good.z[k3] - d * nn.z;
	ENSURE(judge3(&mkMethod_ClosedNormal, e, MK_SET_PLUS, n3, &bad) == 0);
	mkPointSet_Free(&bad);

	free(u3);
	mkPointSet_Free(&good);
}

/* Hulls in 3D: a vertex missing, one ulp off, an input sum that is not
 * extreme added. */
static void teethHulls3(const Case3 *e)
{
	mkPointSet good = {0}, bad;
	const int s3 = 6;
	ENSURE(mkMethod_HullCgalEpick.run3(e->a, e->b, MK_SET_CONTACT, s3, &good) == MK_OK);
	ENSURE(judge3(&mkMethod_HullCgalEpick, e, MK_SET_CONTACT, s3, &good) == 1);
	/* The vertex farthest along x missing (a vertex barely extreme could
	 * hide within the allowance; this one cannot). */
	bad = copy(&good);
	int far = 0;
	for (int i = 1; i < good.count; ++i)
		if (good.x[i] > good.x[far]) far = i;
	bad.x[far] = good.x[good.count - 1], bad.y[far] = good.y[good.count - 1], bad.z[far] = good.z[good.count - 1];
	bad.count = good.count - 1;
	ENSURE(judge3(&mkMethod_HullCgalEpick, e, MK_SET_CONTACT, s3, &bad) == 0);
	mkPointSet_Free(&bad);
	bad = copy(&good);
	bad.count = good.count;
	bad.z[2] = nextafter(bad.z[2], -HUGE_VAL); /* one ulp off */
	ENSURE(judge3(&mkMethod_HullCgalEpick, e, MK_SET_CONTACT, s3, &bad) == 0);
	mkPointSet_Free(&bad);
	/* An input sum that is not extreme added. */
	{
		int per = s3 * s3;
		double *pq = malloc(6 * (size_t)per * sizeof *pq);
		mkSampled3_Bodies(e->a, e->b, MK_SET_CONTACT, s3, pq, pq + 3 * per);
		/* The sum of body 1's sample on its equator (row 2) and body 2's
		 * sample on its own equator facing the other way lies well inside. */
		int i1 = 2 * s3, i2 = 3 * s3 + s3 / 2;
		bad = copy(&good);
		mkPointSet_Resize(&bad, 3, good.count + 1);
		bad.x[good.count] = pq[3 * i1] + pq[3 * per + 3 * i2];
		bad.y[good.count] = pq[3 * i1 + 1] + pq[3 * per + 3 * i2 + 1];
		bad.z[good.count] = pq[3 * i1 + 2] + pq[3 * per + 3 * i2 + 2];
		mkVerdict v;
		ENSURE(mkReferee3_Check(&mkMethod_HullCgalEpick, e->a, e->b, MK_SET_CONTACT, s3, &bad, NULL, &v) == MK_OK);
		ENSURE(!v.pass && v.subset && !v.convex);
		mkPointSet_Free(&bad);
		free(pq);
	}

	mkPointSet_Free(&good);
}

/* A wrong pairing, the mistake a wrong Phi or a wrong normal map makes:
 * body 1's point u_k paired with body 2's support point for a normal turned
 * by a small angle. Such points lie inside the sum by about rho angle^2 / 2; at
 * 1e-4 rad that is ~1e-9 of the extent, far above the allowance. The
 * correctly paired points, built the same way, pass. */
static void teethWrongPairing(const Case2 *w)
{
	const int n = 200;
	mkPointSet right = {0}, wrong = {0};
	mkPointSet_Resize(&right, 2, n);
	mkPointSet_Resize(&wrong, 2, n);
	double *uu = malloc(2 * (size_t)n * sizeof *uu);
	mkSample2_Angles(n, uu, uu + n);
	for (int i = 0; i < n; ++i) {
		mkVec2 nn2, x1 = mkReferee2_Point(w->a, (mkVec2){uu[i], uu[n + i]}, &nn2);
		double cs = cos(1e-4), sn = sin(1e-4);
		mkVec2 turned = {cs * nn2.x - sn * nn2.y, sn * nn2.x + cs * nn2.y};
		mkVec2 s0 = mkBody2_Support(w->b, (mkVec2){-nn2.x, -nn2.y});
		mkVec2 s1 = mkBody2_Support(w->b, (mkVec2){-turned.x, -turned.y});
		right.x[i] = x1.x - (s0.x - w->b.t.x), right.y[i] = x1.y - (s0.y - w->b.t.y);
		wrong.x[i] = x1.x - (s1.x - w->b.t.x), wrong.y[i] = x1.y - (s1.y - w->b.t.y);
	}
	ENSURE(judge2(&mkMethod_ClosedNormal, w, MK_SET_CONTACT, n, &right) == 1);
	ENSURE(judge2(&mkMethod_ClosedNormal, w, MK_SET_CONTACT, n, &wrong) == 0);
	free(uu);
	mkPointSet_Free(&right);
	mkPointSet_Free(&wrong);
}

int main(void)
{
	Case2 c2[16];
	Case3 c3[16];
	cases2(c2, 7);
	cases3(c3, 7);
	teethBoundary2(&c2[0]);
	teethHulls2(&c2[0]);
	teethBoundary3(&c3[0]);
	teethHulls3(&c3[0]);
	teethWrongPairing(&c2[1]);
	return mk_summary("test_teeth");
}
