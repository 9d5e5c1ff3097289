/* base.c - result names, version, and the point-set helper of method.h. */
#include "mink/method.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/message.h"

const char *mkResult_Name(mkResult r)
{
	switch (r) {
	case MK_OK: return "ok";
	case MK_ERR_ARGUMENT: return "invalid argument";
	case MK_ERR_RANGE: return "value out of range";
	case MK_ERR_UNSUPPORTED: return "unsupported";
	case MK_ERR_MEMORY: return "out of memory";
	case MK_ERR_CONVERGENCE: return "no convergence";
	}
	return "unknown result";
}

#define MK_STR2(x) #x
#define MK_STR(x) MK_STR2(x)

const char *mkVersion(void)
{
	return MK_STR(MK_VERSION_MAJOR) "." MK_STR(MK_VERSION_MINOR) "." MK_STR(MK_VERSION_PATCH);
}

static int grow(double **p, int cap)
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
		ok = grow(&set->x, cap) && grow(&set->y, cap);
		if (ok && set->z) ok = grow(&set->z, cap);
	}
	if (ok && dim == 3 && !set->z) ok = grow(&set->z, cap);
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
	free(set->x); free(set->y); free(set->z);
	set->x = set->y = set->z = NULL;
	set->count = set->capacity = 0;
}

mkResult mkFail(mkResult r, char *msg, size_t msglen, const char *fmt, ...)
{
	if (msg && msglen) {
		va_list ap;
		va_start(ap, fmt);
		vsnprintf(msg, msglen, fmt, ap);
		va_end(ap);
	}
	return r;
}
