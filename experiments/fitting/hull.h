/* hull.h - volume and vertices of the convex hull of a 3D point set.
 *
 * A thin wrapper over qhull's reentrant library: the fitting experiment
 * measures every polyhedron by the volume of the hull of its points, and
 * case 1 needs to know which of the random points are hull vertices. */
#ifndef MK_FIT_HULL_H
#define MK_FIT_HULL_H

#include <mink/base.h>

/* Volume of the convex hull of the n points (x[k], y[k], z[k]).
 * On MK_OK writes *volume; when vertexCount is not NULL, the number of hull
 * vertices; when isVertex is not NULL (n ints), 1 for each input point that is
 * a hull vertex and 0 otherwise. Duplicate and coplanar points are allowed.
 * Fails with MK_ERR_ARGUMENT on n < 4 or NULL coordinates or volume,
 * MK_ERR_MEMORY when the copy for qhull cannot be allocated, and
 * MK_ERR_UNSUPPORTED when qhull cannot build a full-dimensional hull (all
 * points coplanar, non-finite input). Allocates while it runs; frees all. */
mkResult mkHull3_Volume(const double *x, const double *y, const double *z, int n,
	double *volume, int *vertexCount, int *isVertex);

#endif
