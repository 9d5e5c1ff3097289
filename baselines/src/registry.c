/* registry.c - the table of methods. To add a method, define its mkMethod
 * in a file of its own and add one line below with its resolution limits. */
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include <mink/registry.h>

#include "registry_internal.h"

typedef struct Entry {
	const mkMethod *method;
	int nmin2, nmax2; /* resolution range in 2D */
	int nmin3, nmax3; /* and in 3D (grid side) */
	double tol;       /* stated accuracy of an MK_METHOD_APPROX method */
} Entry;

static const Entry table[] = {
	{&mkMethod_ClosedNormal, 1, INT_MAX, 2, MK_CLOSED3_N_MAX, 0},
	{&mkMethod_ClosedGradient, 1, INT_MAX, 2, MK_CLOSED3_N_MAX, 0},
	{&mkMethod_ClosedNormalF32, 1, INT_MAX, 2, MK_CLOSED3_N_MAX, MK_F32_TOL},
	{&mkMethod_ClosedGradientF32, 1, INT_MAX, 2, MK_CLOSED3_N_MAX, MK_F32_TOL},
	{&mkMethod_ClosedPaper, 1, INT_MAX, 2, MK_CLOSED3_N_MAX, 0},
	{&mkMethod_Geometric, 1, INT_MAX, 2, MK_CLOSED3_N_MAX, 0},
	{&mkMethod_HullCgalEpick, MK_SAMPLED_N_MIN, MK_HULL2_N_MAX, MK_SAMPLED_N_MIN, MK_HULL3_N_MAX, 0},
	{&mkMethod_HullCgalEpeck, MK_SAMPLED_N_MIN, MK_HULL2_N_MAX, MK_SAMPLED_N_MIN, MK_HULL3_N_MAX, 0},
	{&mkMethod_HullQhull, MK_SAMPLED_N_MIN, MK_HULL2_N_MAX, MK_SAMPLED_N_MIN, MK_HULL3_N_MAX, 0},
	{&mkMethod_EdgeSort, MK_SAMPLED_N_MIN, MK_EDGESORT_N_MAX, 0, 0, 0},
};

enum { COUNT = (int)(sizeof table / sizeof table[0]) };

int mkRegistry_Count(void)
{
	return COUNT;
}

const mkMethod *mkRegistry_At(int i)
{
	return i >= 0 && i < COUNT ? table[i].method : NULL;
}

const mkMethod *mkRegistry_Find(const char *name)
{
	if (!name) return NULL;
	for (int i = 0; i < COUNT; ++i)
		if (strcmp(table[i].method->name, name) == 0) return table[i].method;
	return NULL;
}

static int runs_in(const mkMethod *m, int dim)
{
	return (dim == 2 && (m->flags & MK_METHOD_2D) && m->run2)
		|| (dim == 3 && (m->flags & MK_METHOD_3D) && m->run3);
}

double mkMethod_Tolerance(const mkMethod *m)
{
	for (int i = 0; i < COUNT; ++i)
		if (table[i].method == m) return (m->flags & MK_METHOD_APPROX) ? table[i].tol : 0.0;
	return 0.0;
}

int mkMethod_CheckN(const mkMethod *m, int dim, int n, char *msg, size_t msglen)
{
	if (!m) {
		if (msg && msglen) snprintf(msg, msglen, "no method given");
		return 0;
	}
	if (!runs_in(m, dim)) {
		if (msg && msglen) snprintf(msg, msglen, "method %s does not run in %dD", m->name, dim);
		return 0;
	}
	int lo = 1, hi = INT_MAX;
	for (int i = 0; i < COUNT; ++i)
		if (table[i].method == m) {
			lo = dim == 2 ? table[i].nmin2 : table[i].nmin3;
			hi = dim == 2 ? table[i].nmax2 : table[i].nmax3;
		}
	if (n >= lo && n <= hi) return 1;
	if (msg && msglen) {
		const char *unit = (m->flags & MK_METHOD_SAMPLED) ? (dim == 2 ? "samples per body" : "grid side per body")
			: (dim == 2 ? "points" : "grid side");
		snprintf(msg, msglen, "n = %d is out of range for method %s in %dD: n (%s) must be in [%d, %d]",
			n, m->name, dim, unit, lo, hi);
	}
	return 0;
}

int mkMethod_Accepts2(const mkMethod *m, mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen)
{
	if (!m || !runs_in(m, 2) || !m->accepts2) {
		if (msg && msglen) snprintf(msg, msglen, "method %s does not run in 2D", m ? m->name : "(none)");
		return 0;
	}
	return m->accepts2(b1, b2, set, msg, msglen);
}

int mkMethod_Accepts3(const mkMethod *m, mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen)
{
	if (!m || !runs_in(m, 3) || !m->accepts3) {
		if (msg && msglen) snprintf(msg, msglen, "method %s does not run in 3D", m ? m->name : "(none)");
		return 0;
	}
	return m->accepts3(b1, b2, set, msg, msglen);
}

int mkAcceptAny2(mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen)
{
	(void)b1;
	(void)b2;
	(void)set;
	if (msg && msglen) msg[0] = '\0';
	return 1;
}

int mkAcceptAny3(mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen)
{
	(void)b1;
	(void)b2;
	(void)set;
	if (msg && msglen) msg[0] = '\0';
	return 1;
}
