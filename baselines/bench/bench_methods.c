/* bench_methods.c - the cost of every registered method at the paper's
 * sizes (Sec. 6.3, Table 1, Figs. 5-8), as CSV: one row per method, case,
 * size and trial, in nanoseconds per call. A benchmark, not a test: it
 * prints figures and asserts nothing.
 *
 * Pairs are drawn as in the paper: 2D a, b ~ U(1, 11), eps ~ U(0.1, 1.9),
 * M = rot(2 pi U) [1 s; 0 1] with s ~ U(-2, 2); 3D body 1 semi-axes
 * ~ U(1, 10)^3, body 2 ~ U(1, 6)^3, eps1, eps2 ~ U(0.2, 2.0) (capped at
 * MK_EPS_MAX), uniform random rotations. Cases: EE (two ellipses), ES (body 1
 * a superellipse, body 2 an ellipse: the geometric method needs body 2 an
 * ellipse), SQ (two superellipses). Every method runs on the same pair in a
 * trial. A call is repeated until 2 ms have passed and the time divided by
 * the repetitions. In 2D, a row "edge-sort(merge)" times the O(m + n) merge
 * alone on the two sample polygons, without sampling the bodies. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <mink/baselines.h>
#include <mink/registry.h>

#define PI 3.14159265358979323846
#define MAX_SIZES 128
#define MAX_METHODS 32

typedef struct Rng { unsigned long long s; } Rng;

static double unit(Rng *r)
{
	unsigned long long z = (r->s += 0x9E3779B97F4A7C15ULL);
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	z ^= z >> 31;
	return (double)(z >> 11) * 0x1.0p-53;
}

static double uni(Rng *r, double a, double b)
{
	return a + (b - a) * unit(r);
}

static double gauss(Rng *r)
{
	double u = unit(r), v = unit(r);
	return sqrt(-2.0 * log(1.0 - u)) * cos(2.0 * PI * v);
}

static mkBody2 draw2(Rng *r, int super)
{
	mkShape2 s = {uni(r, 1, 11), uni(r, 1, 11), super ? uni(r, 0.1, 1.9) : 1.0};
	mkMat2 M = mkMat2_Mul(mkMat2_Rotation(2 * PI * unit(r)), mkMat2_Shear(uni(r, -2, 2)));
	mkVec2 t = {uni(r, -5, 5), uni(r, -5, 5)};
	return mkBody2_Make(s, M, t);
}

static mkBody3 draw3(Rng *r, int super, double amax)
{
	double e1 = super ? fmin(uni(r, 0.2, 2.0), MK_EPS_MAX) : 1.0;
	double e2 = super ? fmin(uni(r, 0.2, 2.0), MK_EPS_MAX) : 1.0;
	mkShape3 s = {uni(r, 1, amax), uni(r, 1, amax), uni(r, 1, amax), e1, e2};
	mkMat3 M = mkMat3_FromQuat(gauss(r), gauss(r), gauss(r), gauss(r));
	mkVec3 t = {uni(r, -5, 5), uni(r, -5, 5), uni(r, -5, 5)};
	return mkBody3_Make(s, M, t);
}

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int parse_list(const char *s, int *out, int max)
{
	int k = 0;
	while (*s && k < max) {
		char *end;
		long v = strtol(s, &end, 10);
		if (end == s || v < 1 || v > 100000) return -1;
		out[k++] = (int)v;
		s = *end == ',' ? end + 1 : end;
		if (*end && *end != ',') return -1;
	}
	return k;
}

static void help(void)
{
	printf("usage: mink_bench_methods [options]\n"
		"\n"
		"Cost per call of each registered method on the paper's random pairs, as CSV\n"
		"(method,dim,case,n,trial,reps,ns_per_call,outputs), or one row per method, case\n"
		"and size with --summary (mean, population std, min).\n"
		"\n"
		"  --dim 2|3           dimension (default 2)\n"
		"  --case EE|ES|SQ|all pair type (default all)\n"
		"  --methods a,b,...   method names (default all that run in --dim)\n"
		"  --sizes n1,n2,...   n per body (2D samples / 3D grid side); default\n"
		"                      2D 20,50,100,200,300,400,500; 3D 5,10,20,30,40,50\n"
		"  --trials T          random pairs per size (default 10; the paper used 100)\n"
		"  --seed S            seed of the draws (default 1)\n"
		"  --max-call SECONDS  once a method's call takes longer than this, its larger\n"
		"                      sizes are left out and a '# skipped' line says so\n"
		"                      (default 10)\n"
		"  --summary           aggregate over trials\n");
}

typedef struct Stat { double sum, sum2, min; int count; } Stat;

int main(int argc, char **argv)
{
	int dim = 2, trials = 10, summary = 0, nsizes = 0, nmethods = 0;
	int sizes[MAX_SIZES];
	unsigned long long seed = 1;
	double max_call = 10.0;
	const char *cases = "all";
	const mkMethod *methods[MAX_METHODS];
	for (int i = 1; i < argc; ++i) {
		const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
		if (!strcmp(o, "-h") || !strcmp(o, "--help")) { help(); return 0; }
		if (!strcmp(o, "--summary")) { summary = 1; continue; }
		if (!v) { fprintf(stderr, "mink_bench_methods: %s needs a value (see --help)\n", o); return 2; }
		++i;
		if (!strcmp(o, "--dim")) dim = atoi(v);
		else if (!strcmp(o, "--case")) cases = v;
		else if (!strcmp(o, "--trials")) trials = atoi(v);
		else if (!strcmp(o, "--seed")) seed = strtoull(v, NULL, 10);
		else if (!strcmp(o, "--max-call")) max_call = atof(v);
		else if (!strcmp(o, "--sizes")) {
			if ((nsizes = parse_list(v, sizes, MAX_SIZES)) <= 0) {
				fprintf(stderr, "mink_bench_methods: --sizes '%s': give positive integers separated by commas\n", v);
				return 2;
			}
		} else if (!strcmp(o, "--methods")) {
			char buf[1024];
			snprintf(buf, sizeof buf, "%s", v);
			for (char *t = strtok(buf, ","); t && nmethods < MAX_METHODS; t = strtok(NULL, ",")) {
				const mkMethod *m = mkRegistry_Find(t);
				if (!m) { fprintf(stderr, "mink_bench_methods: unknown method '%s'\n", t); return 2; }
				methods[nmethods++] = m;
			}
		} else { fprintf(stderr, "mink_bench_methods: unknown option %s (see --help)\n", o); return 2; }
	}
	if (dim != 2 && dim != 3) { fprintf(stderr, "mink_bench_methods: --dim must be 2 or 3\n"); return 2; }
	if (trials < 1) { fprintf(stderr, "mink_bench_methods: --trials must be >= 1\n"); return 2; }
	if (strcmp(cases, "all") && strcmp(cases, "EE") && strcmp(cases, "ES") && strcmp(cases, "SQ")) {
		fprintf(stderr, "mink_bench_methods: --case must be EE, ES, SQ or all\n");
		return 2;
	}
	if (!nsizes) {
		static const int d2[] = {20, 50, 100, 200, 300, 400, 500}, d3[] = {5, 10, 20, 30, 40, 50};
		const int *d = dim == 2 ? d2 : d3;
		nsizes = dim == 2 ? 7 : 6;
		memcpy(sizes, d, (size_t)nsizes * sizeof *d);
	}
	if (!nmethods)
		for (int i = 0; i < mkRegistry_Count() && nmethods < MAX_METHODS; ++i) {
			const mkMethod *m = mkRegistry_At(i);
			if (m->flags & (dim == 2 ? MK_METHOD_2D : MK_METHOD_3D)) methods[nmethods++] = m;
		}

	/* What the figures were measured on. */
	char cpu[256] = "unknown";
	FILE *fp = fopen("/proc/cpuinfo", "r");
	if (fp) {
		char line[512];
		while (fgets(line, sizeof line, fp))
			if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
				snprintf(cpu, sizeof cpu, "%s", strchr(line, ':') + 2);
				cpu[strcspn(cpu, "\n")] = 0;
				break;
			}
		fclose(fp);
	}
	printf("# mink_bench_methods: mink %s, dim %d, trials %d, seed %llu, closed-form kernel %s\n", mkVersion(),
		dim, trials, seed, mkImpl_Name(mkImpl_Resolve(MK_IMPL_AUTO)));
	printf("# cpu: %s; compiler: %s\n", cpu,
#ifdef __VERSION__
		__VERSION__
#else
		"unknown"
#endif
	);
	printf(summary ? "method,dim,case,n,trials,mean_ns,std_ns,min_ns,outputs\n"
		: "method,dim,case,n,trial,reps,ns_per_call,outputs\n");
	fflush(stdout);

	int merge_row = 0;
	for (int m = 0; m < nmethods; ++m) merge_row |= methods[m] == &mkMethod_EdgeSort;
	static const char *const case_names[3] = {"EE", "ES", "SQ"};
	mkPointSet out = {0};
	int status = 0;
	for (int c = 0; c < 3; ++c) {
		if (strcmp(cases, "all") && strcmp(cases, case_names[c])) continue;
		int skip[MAX_METHODS] = {0}, slow[MAX_METHODS] = {0};
		for (int z = 0; z < nsizes; ++z) {
			int n = sizes[z];
			Stat st[MAX_METHODS] = {{0}}, merge = {0};
			int merge_out = 0;
			int outputs[MAX_METHODS] = {0};
			int applicable[MAX_METHODS];
			for (int m = 0; m < nmethods; ++m) {
				char msg[256];
				applicable[m] = !skip[m] && mkMethod_CheckN(methods[m], dim, n, msg, sizeof msg);
				if (!skip[m] && !applicable[m])
					printf("# skipped %s %s n=%d: %s\n", methods[m]->name, case_names[c], n, msg);
			}
			for (int t = 0; t < trials; ++t) {
				/* The pair of trial t at size n does not depend on the methods run. */
				Rng rng = {seed * 1000003ULL + (unsigned long long)(c * 7919 + n) * 104729ULL + (unsigned long long)t};
				mkBody2 a2 = {0}, b2 = {0};
				mkBody3 a3 = {0}, b3 = {0};
				if (dim == 2) {
					a2 = draw2(&rng, c >= 1);
					b2 = draw2(&rng, c == 2);
				} else {
					a3 = draw3(&rng, c >= 1, 10.0);
					b3 = draw3(&rng, c == 2, 6.0);
				}
				for (int m = 0; m < nmethods; ++m) {
					const mkMethod *me = methods[m];
					if (!applicable[m]) continue;
					char msg[256];
					int ok = dim == 2 ? mkMethod2_Accepts(me, a2, b2, MK_SET_CONTACT, msg, sizeof msg)
						: mkMethod3_Accepts(me, a3, b3, MK_SET_CONTACT, msg, sizeof msg);
					if (!ok) {
						if (t == 0 && z == 0) printf("# %s does not apply to case %s: %s\n", me->name, case_names[c], msg);
						applicable[m] = 0;
						continue;
					}
					long reps = 0;
					double t0 = now(), t1;
					mkResult r;
					do {
						r = dim == 2 ? me->run2(a2, b2, MK_SET_CONTACT, n, &out) : me->run3(a3, b3, MK_SET_CONTACT, n, &out);
						++reps;
						t1 = now();
					} while (r == MK_OK && t1 - t0 < 2e-3);
					if (r != MK_OK) {
						printf("# %s %s n=%d trial %d failed: %s\n", me->name, case_names[c], n, t, mkResult_Name(r));
						status = 1;
						continue;
					}
					double ns = (t1 - t0) * 1e9 / (double)reps;
					outputs[m] = out.count;
					if (summary) {
						Stat *s = &st[m];
						s->sum += ns;
						s->sum2 += ns * ns;
						s->min = s->count ? fmin(s->min, ns) : ns;
						++s->count;
					} else
						printf("%s,%d,%s,%d,%d,%ld,%.1f,%d\n", me->name, dim, case_names[c], n, t, reps, ns, out.count);
					if (ns * 1e-9 > max_call) slow[m] = 1; /* finish this size, then stop */
				}
				if (dim == 2 && merge_row) {
					/* The merge alone, on polygons prepared outside the clock. */
					double *pq = malloc(4 * (size_t)n * sizeof *pq), *poly = malloc(4 * (size_t)n * sizeof *poly);
					int m1 = -1, m2 = -1;
					if (pq && poly && mkSampled2_Bodies(a2, b2, MK_SET_CONTACT, n, pq, pq + 2 * n) == MK_OK) {
						m1 = mkPolygon2_Convex(pq, n, poly);
						m2 = mkPolygon2_Convex(pq + 2 * n, n, poly + 2 * n);
					}
					if (m1 > 0 && m2 > 0) {
						long reps = 0;
						double t0 = now(), t1;
						do {
							mkEdgeSort2_Merge(poly, m1, poly + 2 * n, m2, &out);
							++reps;
							t1 = now();
						} while (t1 - t0 < 2e-3);
						double ns = (t1 - t0) * 1e9 / (double)reps;
						merge_out = out.count;
						if (summary) {
							merge.sum += ns;
							merge.sum2 += ns * ns;
							merge.min = merge.count ? fmin(merge.min, ns) : ns;
							++merge.count;
						} else
							printf("edge-sort(merge),2,%s,%d,%d,%ld,%.1f,%d\n", case_names[c], n, t, reps, ns, out.count);
					}
					free(pq);
					free(poly);
				}
				fflush(stdout);
			}
			if (summary && merge.count) {
				double mean = merge.sum / merge.count;
				printf("edge-sort(merge),2,%s,%d,%d,%.1f,%.1f,%.1f,%d\n", case_names[c], n, merge.count, mean,
					sqrt(fmax(0.0, merge.sum2 / merge.count - mean * mean)), merge.min, merge_out);
			}
			for (int m = 0; m < nmethods; ++m) {
				if (summary && st[m].count) {
					double mean = st[m].sum / st[m].count;
					double var = fmax(0.0, st[m].sum2 / st[m].count - mean * mean);
					printf("%s,%d,%s,%d,%d,%.1f,%.1f,%.1f,%d\n", methods[m]->name, dim, case_names[c], n, st[m].count,
						mean, sqrt(var), st[m].min, outputs[m]);
				}
				if (slow[m] && !skip[m]) {
					skip[m] = 1;
					if (z + 1 < nsizes)
						printf("# skipped %s %s n>=%d: a call at n=%d took more than --max-call %g s\n",
							methods[m]->name, case_names[c], sizes[z + 1], n, max_call);
				}
			}
			fflush(stdout);
		}
	}
	mkPointSet_Free(&out);
	return status;
}
