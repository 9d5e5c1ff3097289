// hull_cgal.hpp - the convex hull of a point array with CGAL, for one kernel.
// Included by hull_epick.cpp and hull_epeck.cpp only, so that each kernel is
// compiled once, in its own translation unit (each costs seconds and about a
// gigabyte to compile).
#ifndef MINK_HULL_CGAL_HPP
#define MINK_HULL_CGAL_HPP

#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>

#include <vector>

#include <mink/baselines.h>

#include "cgal_common.hpp"

namespace mkcgal {

template <class K>
mkResult Hull2(const double *xy, int count, mkPointSet *out)
{
	typedef typename K::Point_2 Point;
	if (!xy || !out || count < 1) return MK_ERR_ARGUMENT;
	return Guarded([&]() -> mkResult {
		std::vector<Point> pts;
		pts.reserve(static_cast<std::size_t>(count));
		for (int k = 0; k < count; ++k) pts.emplace_back(xy[2 * k], xy[2 * k + 1]);
		std::vector<Point> h;
		CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(h));
		if (h.size() < 3) return MK_ERR_ARGUMENT; // no area
		return PolygonOut(h, out);
	});
}

// 1 when four of the points span a volume (exact tests).
template <class Point>
bool SpansVolume(const std::vector<Point> &pts)
{
	std::size_t a = 0, b = 1, c, d;
	while (b < pts.size() && pts[b] == pts[a]) ++b;
	for (c = b + 1; c < pts.size() && CGAL::collinear(pts[a], pts[b], pts[c]); ++c) {}
	for (d = c + 1; d < pts.size() && CGAL::coplanar(pts[a], pts[b], pts[c], pts[d]); ++d) {}
	return d < pts.size();
}

template <class K>
mkResult Hull3(const double *xyz, int count, mkPointSet *out)
{
	typedef typename K::Point_3 Point;
	typedef CGAL::Surface_mesh<Point> Mesh;
	if (!xyz || !out || count < 1) return MK_ERR_ARGUMENT;
	return Guarded([&]() -> mkResult {
		std::vector<Point> pts;
		pts.reserve(static_cast<std::size_t>(count));
		for (int k = 0; k < count; ++k) pts.emplace_back(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
		if (!SpansVolume(pts)) return MK_ERR_ARGUMENT; // flat: no hull
		Mesh mesh;
		// The Surface_mesh overload: CGAL 5.5's (vertices, faces) overload
		// returns wrong hulls with the inexact-constructions kernel.
		CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
		mkResult r = mkPointSet_Resize(out, 3, static_cast<int>(mesh.number_of_vertices()));
		if (r != MK_OK) return r;
		int k = 0;
		for (typename Mesh::Vertex_index v : mesh.vertices()) {
			const Point &p = mesh.point(v);
			out->x[k] = CGAL::to_double(p.x());
			out->y[k] = CGAL::to_double(p.y());
			out->z[k] = CGAL::to_double(p.z());
			++k;
		}
		out->count = k;
		return MK_OK;
	});
}

} // namespace mkcgal

#endif
