/* reftest.c - the shared test helpers of reftest.h. */
#include "reftest.h"

long refFailures = 0;

int refTest_Result(const char *name)
{
	if (refFailures) {
		printf("%s: FAILED (%ld failed checks)\n", name, refFailures);
		return 1;
	}
	printf("%s: passed\n", name);
	return 0;
}

uint64_t refRng_Next(refRng *r)
{
	uint64_t z = (r->state += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

double refRng_Uniform(refRng *r, double lo, double hi)
{
	double v = (double)(refRng_Next(r) >> 11) * 0x1p-53;
	return lo + (hi - lo) * v;
}

void refStat_Add(refStat *s, double v)
{
	if (!(v <= s->max)) /* also takes a NaN, so that it shows */
		s->max = v;
	s->sum += v;
	s->count += 1;
}

double refStat_Mean(const refStat *s)
{
	return s->count ? s->sum / (double)s->count : 0.0;
}

void refRng_Unit(refRng *r, int dim, double *u)
{
	double n;
	do {
		n = 0.0;
		for (int i = 0; i < dim; ++i) {
			u[i] = refRng_Uniform(r, -1.0, 1.0);
			n += u[i] * u[i];
		}
	} while (n < 1e-4 || n > 1.0);
	for (int i = 0; i < dim; ++i)
		u[i] /= sqrt(n);
}
