/* latlong.h - a reference the fitting tests share, computed by hand without
 * qhull: the volume of the latitude-longitude polyhedron inscribed in the
 * unit sphere, with `rings` latitudes eta_i = -pi/2 + pi i/(rings-1) (poles
 * included) and `lon` longitudes 2 pi j/lon per ring. Its faces (trapezoids
 * between rings, triangles at the poles) are planar, so the volume is the
 * sum over the faces' triangles of the tetrahedra they span with the centre. */
#ifndef MK_FIT_TEST_LATLONG_H
#define MK_FIT_TEST_LATLONG_H

#include <math.h>

#include <mink/geom.h>

static double latLongVolume(int rings, int lon)
{
	double vol = 0.0;
	for (int i = 0; i + 1 < rings; ++i) {
		double e0 = -MK_PI / 2 + MK_PI * i / (rings - 1), e1 = -MK_PI / 2 + MK_PI * (i + 1) / (rings - 1);
		for (int j = 0; j < lon; ++j) {
			double w0 = 2 * MK_PI * j / lon, w1 = 2 * MK_PI * (j + 1) / lon;
			double p[4][3] = {
				{ cos(e0) * cos(w0), cos(e0) * sin(w0), sin(e0) },
				{ cos(e0) * cos(w1), cos(e0) * sin(w1), sin(e0) },
				{ cos(e1) * cos(w1), cos(e1) * sin(w1), sin(e1) },
				{ cos(e1) * cos(w0), cos(e1) * sin(w0), sin(e1) },
			};
			/* triangles (0,1,2) and (0,2,3), outward; det/6 each */
			for (int t = 0; t < 2; ++t) {
				const double *a = p[0], *b = p[1 + t], *c = p[2 + t];
				vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
					+ a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
			}
		}
	}
	return vol;
}

#endif
