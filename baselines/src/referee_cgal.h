/* referee_cgal.h - the exact (CGAL) part of the referee: the hull checks of
 * sampled methods, on CGAL's exact predicates. Plain C interface. */
#ifndef MINK_REFEREE_CGAL_H
#define MINK_REFEREE_CGAL_H

#include <mink/base.h>

MK_EXTERN_C_BEGIN

typedef struct mkHullReport {
	int convex;         /* 2D: strictly convex, counter-clockwise, winds once;
	                       3D: every output point is a vertex of its hull */
	int subset;         /* every output point is one of the input points */
	int extreme;        /* no input point lies outside the output's hull */
	int outside;        /* input points outside it */
	double outside_max; /* largest distance of an outside point to the hull */
	int measured;       /* outside points whose distance was measured (at most
	                       MK_HULL_MEASURE_MAX; the others are only counted) */
	char why[200];      /* first failure, in words */
} mkHullReport;

#define MK_HULL_MEASURE_MAX 20000

/* Output polygon (vx, vy: nv vertices, claimed counter-clockwise) against
 * the input (s: ns interleaved points). Returns 0, -1 when memory ran out,
 * -2 when CGAL raised an error (r->why says which). Coordinates must be
 * finite. */
MK_API int mkRefereeCgal_Polygon(const double *vx, const double *vy, int nv, const double *s, long ns,
	mkHullReport *r);
/* Output vertex set against the input (s: ns interleaved triples). */
MK_API int mkRefereeCgal_Polytope(const double *vx, const double *vy, const double *vz, int nv,
	const double *s, long ns, mkHullReport *r);

/* The convex hull of count points as a triangle mesh (CGAL, Epick kernel,
 * Surface_mesh overload): *nv vertex coordinates (3 per vertex) and *nt
 * triangles (3 vertex indices each, counter-clockwise seen from outside),
 * both allocated with malloc for the caller to free. The output depends
 * only on the set of points, not on their order, memory addresses or the
 * thread: the vertices are CGAL's hull vertices (input points) sorted by
 * coordinates (x, then y, then z); each planar face of the hull, found with
 * exact predicates, is fanned from its lexicographically smallest corner
 * over its corners only; each triangle starts at its smallest index; the
 * triangles are sorted. A vertex CGAL kept on an edge or inside a planar
 * face is listed but belongs to no triangle. Returns 0, -1 when memory ran
 * out, -2 when the points span no volume, -3 when the faces could not be
 * made triangles (CGAL failed, or a face had fewer than 3 corners). Lives
 * in hull_epick.cpp, so that the referee's translation unit need not
 * compile the hull code again. */
MK_API int mkCgalHull3_Mesh(const double *xyz, int count, double **vertices, int *nv, int **triangles, int *nt);

/* CGAL's exact orientation of (a, b, c) in the plane (+1 left turn), for
 * cross-checking the suite's own predicate. */
MK_API int mkRefereeCgal2_Orient(const double *a, const double *b, const double *c);

MK_EXTERN_C_END

#endif
