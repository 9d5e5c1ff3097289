/* pointset.c - growing and releasing a method's point set (mink/method.h,
 * declared in mink/registry.h). It lives with the registry because every
 * method fills one and the core library never allocates. */
#include <stdlib.h>

#include <mink/registry.h>

static int mkPointSet_Grow(double **p, int cap)
{
	double *q = realloc(*p, (size_t)(cap > 0 ? cap : 1) * sizeof *q);
	if (!q) return 0;
	*p = q;
	return 1;
}

mkResult mkPointSet_Resize(mkPointSet *set, int dim, int count)
{
	if (!set || (dim != 2 && dim != 3) || count < 0) return MK_ERR_ARGUMENT;
	int cap = count > set->capacity ? count : set->capacity;
	int ok = 1;
	if (cap > set->capacity || !set->x) {
		ok = mkPointSet_Grow(&set->x, cap) && mkPointSet_Grow(&set->y, cap);
		if (ok && set->z) ok = mkPointSet_Grow(&set->z, cap);
	}
	if (ok && dim == 3 && !set->z) ok = mkPointSet_Grow(&set->z, cap);
	if (!ok) {
		mkPointSet_Free(set);
		return MK_ERR_MEMORY;
	}
	set->capacity = cap;
	set->dim = dim;
	set->count = count;
	return MK_OK;
}

void mkPointSet_Free(mkPointSet *set)
{
	if (!set) return;
	free(set->x);
	free(set->y);
	free(set->z);
	set->x = set->y = set->z = NULL;
	set->count = set->capacity = 0;
}
