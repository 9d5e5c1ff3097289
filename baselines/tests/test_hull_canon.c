/* test_hull_canon.c - the 3D hull the error measure uses (mkCgalHull3_Mesh)
 * and the measure itself do not depend on anything but the point set, also
 * where many points are exactly coplanar.
 *
 * CGAL's quickhull keeps the border of the visible region in a map ordered
 * by vertex address, so the triangles it picks for a planar face can follow
 * malloc addresses, which differ between threads (per-thread arenas) and
 * after other allocations. Here the same point sets go through the hull and
 * the measure in several orders, after allocating garbage of varied sizes,
 * and on two threads at once; every output must equal the first one bit
 * for bit. The reference is the first run itself: the property is equality,
 * so there is no tolerance. A second check, independent of the hull code,
 * asks of the seven constructed sets that every triangle lies in a face
 * plane of the point set (all points on one side; exact, the coordinates
 * being multiples of 1/16 below 10), that no triangle is degenerate and
 * that the triangles enclose the volume worked out by hand. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mink/baselines.h>
#include <mink/error.h>
#include <mink/registry.h>

#include "ensure.h"
#include "referee_cgal.h"

enum { SETS = 9, ORDERS = 4, MAXP = 4096 };

typedef struct Set { int n; double xyz[3 * MAXP]; mkBody3 b1, b2; } Set;
static Set sets[SETS];

/* 0: the 3 x 3 x 3 grid; 1: a cube's corners and face centres; 2: a
 * triangular prism with its edges' midpoints, three layers; 3: a 7 x 7 x 7
 * grid; 4: a box with 5 x 4 x 6 points per side (grid points on its faces
 * only); 5, 6: lattice points of a ball and an ellipsoid; all sheared (M
 * below). 7, 8: the output of a hull method. The coordinates of 0..6 are
 * small integers times 1/16, so the tests on them are exact in double. */
static void make_sets(void)
{
	Set *s = &sets[0];
	for (int i = 0; i < 27; ++i) {
		double *p = s->xyz + 3 * s->n++;
		p[0] = i % 3 - 1, p[1] = (i / 3) % 3 - 1, p[2] = i / 9 - 1;
	}
	s = &sets[1];
	for (int i = 0; i < 8; ++i) {
		double *p = s->xyz + 3 * s->n++;
		p[0] = (i & 1) ? 1 : -1, p[1] = (i & 2) ? 1 : -1, p[2] = (i & 4) ? 1 : -1;
	}
	for (int a = 0; a < 3; ++a)
		for (int sg = -1; sg <= 1; sg += 2) {
			double *p = s->xyz + 3 * s->n++;
			p[0] = p[1] = p[2] = 0;
			p[a] = sg;
		}
	s = &sets[2];
	static const double tri[6][2] = {{0, 0}, {4, 0}, {0, 4}, {2, 0}, {2, 2}, {0, 2}};
	for (int z = 0; z < 3; ++z)
		for (int k = 0; k < 6; ++k) {
			double *p = s->xyz + 3 * s->n++;
			p[0] = 0.25 * tri[k][0], p[1] = 0.25 * tri[k][1], p[2] = 0.5 * z;
		}
	s = &sets[3];
	for (int i = 0; i < 343; ++i) {
		double *p = s->xyz + 3 * s->n++;
		p[0] = 0.25 * (i % 7 - 3), p[1] = 0.25 * ((i / 7) % 7 - 3), p[2] = 0.25 * (i / 49 - 3);
	}
	s = &sets[4];
	for (int i = 0; i < 5 * 4 * 6; ++i) {
		int x = i % 5, y = (i / 5) % 4, z = i / 20;
		if (x % 4 && y % 3 && z % 5) continue;
		double *p = s->xyz + 3 * s->n++;
		p[0] = 0.5 * x - 1, p[1] = 0.25 * y - 0.25, p[2] = 0.25 * z - 0.75;
	}
	/* The integer points of a ball of radius 5 and of an ellipsoid with
	 * semi-axes 5, 3.5, 2.5: hulls with many vertices (CGAL's vertex
	 * handles then span several blocks, whose address order malloc
	 * decides) and many faces holding several lattice points. */
	for (int e = 0; e < 2; ++e) {
		s = &sets[5 + e];
		double ax = 5, ay = e ? 3.5 : 5, az = e ? 2.5 : 5;
		for (int x = -5; x <= 5; ++x)
			for (int y = -5; y <= 5; ++y)
				for (int z = -5; z <= 5; ++z)
					if (x * x / (ax * ax) + y * y / (ay * ay) + z * z / (az * az) <= 1.0) {
						double *p = s->xyz + 3 * s->n++;
						p[0] = x, p[1] = y, p[2] = z;
					}
	}
	/* Sheared by M, so that no face is axis-aligned (the two triangulations
	 * of an axis-aligned square give the same normals, hiding the defect).
	 * M's entries are multiples of 1/4, so the images stay exact and
	 * coplanar points stay exactly coplanar; det M = 49/64. */
	static const double M[3][3] = {{1, 0.5, 0.25}, {0.25, 1, 0.5}, {0.5, 0.25, 1}};
	for (int si = 0; si < SETS; ++si)
		for (int k = 0; k < sets[si].n; ++k) {
			double *p = sets[si].xyz + 3 * k, q[3];
			for (int i = 0; i < 3; ++i) q[i] = M[i][0] * p[0] + M[i][1] * p[1] + M[i][2] * p[2];
			memcpy(p, q, sizeof q);
		}
	/* Two real cases: the output of the CGAL hull method (pairwise sums of
	 * each body's n x n grid, n = 8) for an axis-aligned pair and for the
	 * rotated pair of test_error's order test. The other sets are measured
	 * against a unit sphere plus a small superquadric; which K does not
	 * matter here, only that the figures repeat. */
	for (int si = 0; si < SETS; ++si) {
		sets[si].b1 = mkBody3_Make((mkShape3){1, 1, 1, 1, 1}, mkMat3_Identity(), (mkVec3){0, 0, 0});
		sets[si].b2 = mkBody3_Make((mkShape3){0.5, 0.25, 0.5, 0.6, 1.2}, mkMat3_Identity(), (mkVec3){0, 0, 0});
	}
	sets[7].b1 = mkBody3_Make((mkShape3){2, 1, 1.5, 1, 1}, mkMat3_Identity(), (mkVec3){0, 0, 0});
	sets[7].b2 = mkBody3_Make((mkShape3){0.5, 0.75, 1, 0.5, 1}, mkMat3_Identity(), (mkVec3){1, 0, 0});
	sets[8].b1 = mkBody3_Make((mkShape3){2, 1.2, 0.9, 0.4, 0.7}, mkMat3_FromQuat(0.3, 0.5, -0.2, 0.7), (mkVec3){0, 1, 0});
	sets[8].b2 = mkBody3_Make((mkShape3){0.8, 0.5, 0.6, 1.3, 0.9}, mkMat3_Identity(), (mkVec3){0, 0, 0});
	for (int si = 7; si < SETS; ++si) {
		mkPointSet out = {0};
		ENSURE(mkMethod_HullCgalEpick.run3(sets[si].b1, sets[si].b2, MK_SET_CONTACT, 8, &out) == MK_OK);
		ENSURE(out.count > 0 && out.count <= MAXP);
		sets[si].n = out.count <= MAXP ? out.count : 0;
		for (int k = 0; k < sets[si].n; ++k) {
			double *p = sets[si].xyz + 3 * k;
			p[0] = out.x[k], p[1] = out.y[k], p[2] = out.z[k];
		}
		mkPointSet_Free(&out);
	}
}

/* One run's output for one set: the hull (vertices, then triangles as
 * vertex triples) and the measure's figures, all as bytes. */
typedef struct Out {
	int rc, nv, nt;
	double V[3 * MAXP];
	int T[6 * MAXP];
	mkDeviation e;
	int mrc;
} Out;

/* Order 0: as made; 1: reversed; 2: k -> m k mod n for the smallest m >= 5
 * prime to n; 3: every third point first, then the others. */
static void permute(const Set *s, int order, double *xyz)
{
	int n = s->n, m = 5, c = 0;
	for (;; ++m) {
		int a = m, b = n;
		while (b) {
			int t = a % b;
			a = b, b = t;
		}
		if (a == 1) break;
	}
	for (int k = 0; k < n; ++k) {
		int j = order == 1 ? n - 1 - k : order == 2 ? (int)((long)m * k % n) : k;
		if (order == 3) {
			if (k % 3) continue;
			j = k;
		}
		memcpy(xyz + 3 * c++, s->xyz + 3 * j, 3 * sizeof *xyz);
	}
	if (order == 3)
		for (int k = 0; k < n; ++k)
			if (k % 3) memcpy(xyz + 3 * c++, s->xyz + 3 * k, 3 * sizeof *xyz);
}

static void run(const Set *s, int order, Out *o, int tid)
{
	static double xyzs[3][3 * MAXP]; /* one per thread (ids 0, 1, 2) */
	double *xyz = xyzs[tid];
	memset(o, 0, sizeof *o);
	permute(s, order, xyz);
	double *V = NULL;
	int *T = NULL;
	o->rc = mkCgalHull3_Mesh(xyz, s->n, &V, &o->nv, &T, &o->nt);
	if (o->rc == 0 && o->nv <= MAXP && o->nt <= 2 * MAXP) {
		memcpy(o->V, V, 3 * (size_t)o->nv * sizeof *V);
		memcpy(o->T, T, 3 * (size_t)o->nt * sizeof *T);
	}
	free(V);
	free(T);
	mkPointSet p = {0};
	mkPointSet_Resize(&p, 3, s->n);
	for (int k = 0; k < s->n; ++k) p.x[k] = xyz[3 * k], p.y[k] = xyz[3 * k + 1], p.z[k] = xyz[3 * k + 2];
	mkDeviationOptions opt = {0, 1.0, 0.0}; /* the volume of K given: only P's figures matter here */
	o->mrc = mkDeviation3_Measure(s->b1, s->b2, MK_SET_CONTACT, &p, &opt, &o->e);
	mkPointSet_Free(&p);
}

/* Allocate (and keep) blocks of varied sizes, so that the hull's
 * allocations land elsewhere; the caller frees them after the run. */
static void **garbage(int seed)
{
	enum { G = 200 };
	void **g = malloc((G + 1) * sizeof *g);
	unsigned x = 2463534242u + 977u * (unsigned)seed;
	for (int i = 0; i < G; ++i) {
		x ^= x << 13, x ^= x >> 17, x ^= x << 5;
		g[i] = malloc(16 + x % 3000);
		if (g[i]) memset(g[i], i, 16);
	}
	for (int i = 0; i < G; i += 3) { /* holes of varied sizes */
		free(g[i]);
		g[i] = NULL;
	}
	g[G] = NULL;
	return g;
}

static void drop(void **g)
{
	for (int i = 0; i < 200; ++i) free(g[i]);
	free(g);
}

/* 0 when equal to the last bit; else 1 when the hull differs, 2 when the
 * measure's figures do, 3 both. */
static int differ(const Out *a, const Out *b)
{
	int hull = a->rc != b->rc || a->nv != b->nv || a->nt != b->nt
		|| memcmp(a->V, b->V, 3 * (size_t)a->nv * sizeof a->V[0])
		|| memcmp(a->T, b->T, 3 * (size_t)a->nt * sizeof a->T[0]);
	const mkDeviation *x = &a->e, *y = &b->e;
	double fx[] = {x->gap_in, x->gap_out, x->hausdorff_abs, x->hausdorff_bound, x->off_boundary_max,
		x->off_boundary_bound, x->area_p, x->area_rel, x->area_bound};
	double fy[] = {y->gap_in, y->gap_out, y->hausdorff_abs, y->hausdorff_bound, y->off_boundary_max,
		y->off_boundary_bound, y->area_p, y->area_rel, y->area_bound};
	int fig = a->mrc != b->mrc || memcmp(fx, fy, sizeof fx) || x->vertices != y->vertices
		|| strcmp(x->message, y->message);
	return hull | 2 * fig;
}

static Out ref[SETS];

typedef struct Job { int id, rounds, bad, badfig; } Job;

/* Every set in every order, each after fresh garbage; count outputs that
 * differ from the reference. */
static void *worker(void *arg)
{
	Job *j = arg;
	Out *o = malloc(sizeof *o);
	if (!o) {
		j->bad = -1;
		return NULL;
	}
	for (int r = 0; r < j->rounds; ++r)
		for (int s = 0; s < SETS; ++s)
			for (int order = 0; order < ORDERS; ++order) {
				void **g = garbage(1000 * j->id + 100 * r + 10 * s + order);
				run(&sets[s], order, o, j->id);
				int d = differ(o, &ref[s]);
				if (d && j->bad + j->badfig < 4)
					fprintf(stderr, "thread %d round %d set %d order %d differs:%s%s\n", j->id, r, s, order,
						d & 1 ? " hull" : "", d & 2 ? " figures" : "");
				j->bad += d & 1;
				j->badfig += d >> 1;
				drop(g);
			}
	free(o);
	return NULL;
}

/* Independent of the hull code: every triangle is non-degenerate and
 * wound outward, its plane has every point of the set on its inner side or
 * on it, and the triangles enclose the volume worked out by hand: before
 * the shear 2^3 (both cubes), 1/2 (prism), 1.5^3 (7-grid), 2 x 0.75 x 1.25
 * (box), times det M = 49/64; the lattice sets' volumes are not worked
 * out (NaN: that part is not checked for them). The products here are of
 * multiples of 1/16 below 20, exact in double, so only the volume sum
 * rounds (1e-14). */
static void check_geometry(int si, const Out *o, double volume)
{
	const Set *s = &sets[si];
	double vol = 0;
	int ok = 1;
	for (int f = 0; f < o->nt; ++f) {
		const double *a = o->V + 3 * o->T[3 * f], *b = o->V + 3 * o->T[3 * f + 1], *c = o->V + 3 * o->T[3 * f + 2];
		double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
		double nrm[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
		if (!(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2] > 0)) ok = 0;
		vol += (a[0] * nrm[0] + a[1] * nrm[1] + a[2] * nrm[2]) / 6.0;
		for (int k = 0; k < s->n; ++k) {
			const double *p = s->xyz + 3 * k;
			double d = nrm[0] * (p[0] - a[0]) + nrm[1] * (p[1] - a[1]) + nrm[2] * (p[2] - a[2]);
			if (d > 0) ok = 0;
		}
	}
	ENSURE(ok);
	if (volume == volume) ENSURE_NEAR(vol, volume * 49.0 / 64.0, 1e-14);
	printf("set %d: %d points, hull %d vertices, %d triangles, volume %.15g\n", si, s->n, o->nv, o->nt, vol);
}

int main(void)
{
	make_sets();
	for (int s = 0; s < SETS; ++s) {
		run(&sets[s], 0, &ref[s], 0);
		ENSURE(ref[s].rc == 0 && ref[s].mrc == MK_OK);
	}
	static const double volume[SETS] = {8, 8, 0.5, 1.5 * 1.5 * 1.5, 2 * 0.75 * 1.25, NAN, NAN, NAN, NAN};
	for (int s = 0; s < 7; ++s) check_geometry(s, &ref[s], volume[s]);
	for (int s = 7; s < SETS; ++s) {
		ENSURE(ref[s].e.vertices >= 4 && ref[s].e.vertices <= ref[s].nv);
		printf("set %d: %d points of the CGAL hull method, hull %d vertices (%d of them corners), %d triangles\n", s,
			sets[s].n, ref[s].nv, ref[s].e.vertices, ref[s].nt);
	}
	/* On this thread, in every order, with garbage between the calls. */
	Job solo = {0, 3, 0, 0};
	worker(&solo);
	ENSURE(solo.bad == 0 && solo.badfig == 0);
	/* Two threads at once (separate malloc arenas). */
	pthread_t th[2];
	Job jobs[2] = {{1, 3, 0, 0}, {2, 3, 0, 0}};
	int started = 0;
	for (int t = 0; t < 2; ++t)
		if (pthread_create(&th[t], NULL, worker, &jobs[t]) == 0) ++started;
	ENSURE(started == 2);
	for (int t = 0; t < started; ++t) pthread_join(th[t], NULL);
	ENSURE(jobs[0].bad == 0 && jobs[1].bad == 0 && jobs[0].badfig == 0 && jobs[1].badfig == 0);
	printf("of %d runs per thread, hulls / figures differing from the first run: %d / %d on this thread, "
		"%d / %d and %d / %d on two threads\n", 3 * SETS * ORDERS, solo.bad, solo.badfig, jobs[0].bad,
		jobs[0].badfig, jobs[1].bad, jobs[1].badfig);
	return mk_summary("test_hull_canon");
}
