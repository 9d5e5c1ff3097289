/* hull.c - convex hull volume through qhull (reentrant API). */
#include "hull.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <libqhull_r/qhull_ra.h>

mkResult mkHull3_Volume(const double *x, const double *y, const double *z, int n,
	double *volume, int *vertexCount, int *isVertex)
{
	if (x == NULL || y == NULL || z == NULL || volume == NULL || n < 4) {
		return MK_ERR_ARGUMENT;
	}
	for (int k = 0; k < n; ++k) {
		if (!isfinite(x[k]) || !isfinite(y[k]) || !isfinite(z[k])) {
			return MK_ERR_UNSUPPORTED;
		}
	}

	/* qhull wants an interleaved array it may keep while it runs. */
	coordT *pts = malloc(sizeof(coordT) * 3 * (size_t)n);
	if (pts == NULL) {
		return MK_ERR_MEMORY;
	}
	for (int k = 0; k < n; ++k) {
		pts[3 * k + 0] = x[k];
		pts[3 * k + 1] = y[k];
		pts[3 * k + 2] = z[k];
	}

	/* "FA" asks for the total area and volume; "Pp" keeps precision
	 * warnings quiet (facets are merged by default in 3D, which is what
	 * makes coplanar grid points safe). Errors still go to stderr. */
	char cmd[] = "qhull FA Pp";
	qhT qhStorage;
	qhT *qh = &qhStorage;
	qh_zero(qh, stderr);
	int exitcode = qh_new_qhull(qh, 3, n, pts, False, cmd, NULL, stderr);

	mkResult result = MK_OK;
	if (exitcode != 0) {
		result = MK_ERR_UNSUPPORTED;
	} else {
		if (!qh->hasAreaVolume) {
			qh_getarea(qh, qh->facet_list);
		}
		*volume = qh->totvol;
		if (isVertex != NULL) {
			for (int k = 0; k < n; ++k) {
				isVertex[k] = 0;
			}
		}
		int count = 0;
		vertexT *vertex;
		FORALLvertices {
			int id = qh_pointid(qh, vertex->point);
			if (id >= 0 && id < n) {
				if (isVertex != NULL) {
					isVertex[id] = 1;
				}
				++count;
			}
		}
		if (vertexCount != NULL) {
			*vertexCount = count;
		}
		if (!(*volume > 0.0) || !isfinite(*volume)) {
			result = MK_ERR_UNSUPPORTED;
		}
	}

	int curlong, totlong;
	qh_freeqhull(qh, !qh_ALL);
	qh_memfreeshort(qh, &curlong, &totlong);
	free(pts);
	return result;
}
