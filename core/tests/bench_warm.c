/* bench_warm.c - MinkSum (Normal) along trajectories: each query started
 * from the previous pose's normal (mkCollide3_NormalFrom) against the same
 * query from the centre line (mkCollide3_Normal), timed alternately on the
 * same poses. Not a test: it prints figures (docs/collide.md quotes them).
 *
 *   bench_warm [PAIRS [STEPS [STEP]]]
 *
 * PAIRS superquadric pairs from the paper's distributions (B1 semi-axes
 * U(1,11)^3, centre U(-5,5)^3; B2 semi-axes U(1,6)^3, centre U(5,15)^3;
 * exponents U(0.1,1.9); rotations from four U(0,1) quaternion components),
 * drawn with SplitMix64 from seed 2022; each pair then
 * moves STEPS times: B2 translated by STEP times the pair's scale in a
 * random direction and turned by about STEP radians about a random axis.
 * Per step both queries run (order alternating), each timed alone with
 * CLOCK_MONOTONIC; prints the medians, the median of the per-query ratios
 * and the largest |difference| of the two answers over the scale. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <mink/mink.h>

#include "ensure.h"

static double now_s(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static unsigned long long state = 2022;
static double unit(void) { return mk_test_unit(&state); }
static double uniform(double a, double b) { return mk_test_uniform(&state, a, b); }

/* One body; the draws in a fixed order (an initializer's or an argument
 * list's order of evaluation is unspecified in C). */
static mkBody3 draw(double amax, double clo, double chi)
{
	mkShape3 s;
	s.a = uniform(1, amax);
	s.b = uniform(1, amax);
	s.c = uniform(1, amax);
	s.eps1 = uniform(0.1, 1.9);
	s.eps2 = uniform(0.1, 1.9);
	mkVec3 t;
	t.x = uniform(clo, chi);
	t.y = uniform(clo, chi);
	t.z = uniform(clo, chi);
	double q[4];
	for (int i = 0; i < 4; ++i)
		q[i] = unit();
	return mkBody3_Make(s, mkMat3_FromQuat(q[0], q[1], q[2], q[3]), t);
}

static int cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static long arg(const char *name, const char *text, long lo, long hi)
{
	char *end;
	long v = strtol(text, &end, 10);
	if (end == text || *end || v < lo || v > hi) {
		fprintf(stderr, "bench_warm: %s = '%s' is out of range: must be an integer in [%ld, %ld]\n", name, text, lo, hi);
		exit(2);
	}
	return v;
}

int main(int argc, char **argv)
{
	if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
		puts("usage: bench_warm [PAIRS [STEPS [STEP]]]\n"
		     "MinkSum (Normal) along trajectories of the paper's superquadric draws: started from the\n"
		     "previous pose's normal against started from the centre line, timed alternately.\n"
		     "  PAIRS  pairs, an integer in [1, 100000] (default 2000)\n"
		     "  STEPS  moves per pair, an integer in [1, 1000] (default 5)\n"
		     "  STEP   move per step as a fraction of the scale (and about as many radians of\n"
		     "         turn), a number in (0, 1] (default 0.01)");
		return 0;
	}
	if (argc > 4) {
		fprintf(stderr, "usage: bench_warm [PAIRS [STEPS [STEP]]] (see --help)\n");
		return 2;
	}
	int pairs = argc > 1 ? (int)arg("PAIRS", argv[1], 1, 100000) : 2000;
	int steps = argc > 2 ? (int)arg("STEPS", argv[2], 1, 1000) : 5;
	double step = 0.01;
	if (argc > 3) {
		char *end;
		step = strtod(argv[3], &end);
		if (end == argv[3] || *end || !(step > 0.0 && step <= 1.0)) {
			fprintf(stderr, "bench_warm: STEP = '%s' is out of range: must be a number in (0, 1]\n", argv[3]);
			return 2;
		}
	}
	size_t n = (size_t)pairs * (size_t)steps;
	double *tc = malloc(n * sizeof *tc), *tw = malloc(n * sizeof *tw), *ratio = malloc(n * sizeof *ratio);
	if (!tc || !tw || !ratio) {
		fprintf(stderr, "bench_warm: out of memory\n");
		return 1;
	}
	size_t k = 0;
	int failed = 0, separated = 0;
	double worst = 0.0;
	for (int p = 0; p < pairs; ++p) {
		mkBody3 b1 = draw(11.0, -5.0, 5.0), b2 = draw(6.0, 5.0, 15.0);
		mkCollision3 prev;
		if (mkCollide3_Normal(b1, b2, &prev) != MK_OK) {
			++failed;
			continue;
		}
		for (int s = 0; s < steps; ++s) {
			double sc = mkCollide3_PairSize(b1, b2);
			mkVec3 dir = mkVec3_Normalize(mkVec3_Make(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
			mkVec3 ax = mkVec3_Normalize(mkVec3_Make(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
			double h = 0.5 * step;
			mkMat3 turn = mkMat3_FromQuat(cos(h), sin(h) * ax.x, sin(h) * ax.y, sin(h) * ax.z);
			b2 = mkBody3_Make(b2.shape, mkMat3_Mul(turn, b2.M), mkVec3_Add(b2.t, mkVec3_Scale(dir, step * sc)));
			mkCollision3 cold, warm;
			double t0, t1, t2;
			mkResult rc, rw;
			if ((k & 1) == 0) {
				t0 = now_s();
				rc = mkCollide3_Normal(b1, b2, &cold);
				t1 = now_s();
				rw = mkCollide3_NormalFrom(b1, b2, prev.normal, &warm);
				t2 = now_s();
				tc[k] = t1 - t0;
				tw[k] = t2 - t1;
			} else {
				t0 = now_s();
				rw = mkCollide3_NormalFrom(b1, b2, prev.normal, &warm);
				t1 = now_s();
				rc = mkCollide3_Normal(b1, b2, &cold);
				t2 = now_s();
				tw[k] = t1 - t0;
				tc[k] = t2 - t1;
			}
			if (rc != MK_OK || rw != MK_OK) {
				++failed;
				continue;
			}
			separated += cold.status == MK_CONTACT_SEPARATED;
			double d = fabs(warm.distance - cold.distance) / cold.scale;
			if (d > worst)
				worst = d;
			ratio[k] = tc[k] / tw[k];
			++k;
			prev = warm;
		}
	}
	qsort(tc, k, sizeof *tc, cmp);
	qsort(tw, k, sizeof *tw, cmp);
	qsort(ratio, k, sizeof *ratio, cmp);
	printf("bench_warm: %d superquadric pairs x %d steps of %g of the scale (and ~%g rad), %zu queries (%d separated), "
	       "%d failed\n", pairs, steps, step, step, k, separated, failed);
	printf("median us: from the centre line %.3f, from the previous normal %.3f; median ratio %.2f; "
	       "largest |difference| / scale %.1e\n", 1e6 * tc[k / 2], 1e6 * tw[k / 2], ratio[k / 2], worst);
	free(tc);
	free(tw);
	free(ratio);
	return 0;
}
