/* work.c - the scratch space of one thread (mkCSpaceWork), growable arrays
 * and the batch evaluation of the contact space's boundary points x(n)
 * (Theorem 1, through mkSum2_Batch/mkSum3_Batch) that every boundary of
 * this library is built from. */
#include "cspace/work.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Grow *p to at least `need` elements of `elem` bytes (doubling from 64). */
static int mkGrow_Elements(void **p, int *cap, int need, size_t elem)
{
	if (need <= *cap) return 1;
	int nc = *cap > 0 ? *cap : 64;
	while (nc < need) nc *= 2;
	void *q = realloc(*p, (size_t)nc * elem);
	if (!q) return 0;
	*p = q;
	*cap = nc;
	return 1;
}

int mkGrow_Doubles(double **p, int *cap, int need)
{
	void *q = *p;
	int ok = mkGrow_Elements(&q, cap, need, sizeof **p);
	*p = q;
	return ok;
}

int mkGrow_Ints(int **p, int *cap, int need)
{
	void *q = *p;
	int ok = mkGrow_Elements(&q, cap, need, sizeof **p);
	*p = q;
	return ok;
}

void mkCSpaceWork_Free(mkCSpaceWork *w)
{
	for (int i = 0; i < 3; ++i) { free(w->n[i]); free(w->p[i]); free(w->m[i]); free(w->q[i]); free(w->o[i]); }
	free(w->next); free(w->tri); free(w->tri2); free(w->leaf);
	mkEdgeHash_Free(&w->edges);
	mkEdgeHash_Free(&w->dedges);
	free(w->poly); free(w->fin); free(w->pb); free(w->err2); free(w->cp); free(w->scratch);
	memset(w, 0, sizeof *w);
}

void *mkCSpaceWork_Scratch(mkCSpaceWork *w, size_t need)
{
	if (need <= w->scap) return w->scratch;
	void *q = realloc(w->scratch, need);
	if (!q) return NULL;
	w->scratch = q;
	w->scap = need;
	return q;
}

int mkCSpaceWork_Verts(mkCSpaceWork *w, int need, int dim)
{
	for (int i = 0; i < dim; ++i)
		if (!mkGrow_Doubles(&w->n[i], &w->vcap[i], need) || !mkGrow_Doubles(&w->p[i], &w->vcap[3 + i], need)) return 0;
	return 1;
}

int mkCSpaceWork_Batch(mkCSpaceWork *w, int need, int dim)
{
	for (int i = 0; i < dim; ++i)
		if (!mkGrow_Doubles(&w->m[i], &w->mcap[i], need) || !mkGrow_Doubles(&w->q[i], &w->mcap[3 + i], need)) return 0;
	return 1;
}

void mkSinCosExact(double t, double *c, double *s)
{
	*c = cos(t);
	*s = sin(t);
	if (fabs(*c) < 1e-15) { *c = 0.0; *s = *s > 0 ? 1.0 : -1.0; }
	if (fabs(*s) < 1e-15) { *s = 0.0; *c = *c > 0 ? 1.0 : -1.0; }
}

mkResult mkContact2_Points(mkBody2 b1, mkBody2 b2, mkImpl impl, const double *ux, const double *uy, int n,
	double *x, double *y)
{
	mkSumOptions o = {MK_SET_CONTACT, MK_FORM_NORMAL, MK_PARAM_NORMAL, impl, MK_PRECISION_DOUBLE};
	return mkSum2_Batch(b1, b2, &o, ux, uy, n, x, y, NULL, NULL);
}

mkResult mkContact3_Points(mkBody3 b1, mkBody3 b2, mkImpl impl, const double *ux, const double *uy,
	const double *uz, int n, double *x, double *y, double *z)
{
	mkSumOptions o = {MK_SET_CONTACT, MK_FORM_NORMAL, MK_PARAM_NORMAL, impl, MK_PRECISION_DOUBLE};
	return mkSum3_Batch(b1, b2, &o, ux, uy, uz, n, x, y, z, NULL, NULL, NULL);
}
