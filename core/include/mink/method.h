/* mink/method.h - the interface every way of computing a Minkowski-sum
 * boundary fills: the core's closed forms and every baseline alike.
 *
 * A method sees two placed bodies, the set wanted (contact space or plain
 * sum) and a resolution n, and fills a point set:
 *  - closed forms: n parameter values (2D) or an n x n parameter grid (3D),
 *    one boundary point each;
 *  - sampled methods: n samples per body (3D: an n x n grid per body), and
 *    the output is the vertex set of the resulting convex polygon (in
 *    counter-clockwise order in 2D) or polyhedron.
 * The registry that lists the methods lives in the baselines layer
 * (mink/registry.h); the core only defines the type. */
#ifndef MINK_METHOD_H
#define MINK_METHOD_H

#include <stddef.h>
#include "sum.h"

MK_EXTERN_C_BEGIN

/* A growable structure-of-arrays point set owned by the caller. z is NULL
 * for dim == 2. Zero-initialise, then reuse across calls to avoid
 * reallocation. The functions that grow and release it, mkPointSet_Resize
 * and mkPointSet_Free, are the method registry's (mink/registry.h,
 * libmink_baselines): libmink itself never allocates. */
typedef struct mkPointSet {
	int dim;
	int count;
	int capacity;
	double *x, *y, *z;
} mkPointSet;

typedef enum mkMethodFlags {
	MK_METHOD_2D = 1,       /* runs in 2D */
	MK_METHOD_3D = 2,       /* runs in 3D */
	MK_METHOD_EXACT = 4,    /* its points lie exactly on the smooth boundary */
	MK_METHOD_SAMPLED = 8,  /* n is samples per body, output is a hull */
	MK_METHOD_APPROX = 16,  /* a faster, less accurate tier of an exact method: its points lie
	                           within a stated distance of the smooth boundary (relative to the
	                           sum's size, mkSum2_Size; mkMethod_Tolerance in mink/registry.h) */
	MK_METHOD_BASELINE = 32 /* a published peer the closed form is compared with, though it returns
	                           boundary points (the ellipsoid "geometric" formula); every sampled
	                           method is a baseline too */
} mkMethodFlags;

typedef struct mkMethod {
	const char *name;      /* unique, lower-case, e.g. "closed-gradient" */
	const char *summary;   /* one line for `mink methods` */
	const char *reference; /* where it comes from (paper, library) */
	unsigned flags;        /* mkMethodFlags */
	/* Return 1 if the method handles this pair; otherwise 0 and a one-line
	 * message (which body, why). NULL when the dimension is not supported. */
	int (*accepts2)(mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen);
	int (*accepts3)(mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen);
	/* Compute into out (resized as needed). Bodies are valid and accepted. */
	mkResult (*run2)(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out);
	mkResult (*run3)(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out);
} mkMethod;

MK_EXTERN_C_END

#endif
