// cgal_common.hpp - what the CGAL units share: the one place where an
// exception from CGAL (or the standard library under it) becomes the
// suite's result code, so that none crosses into C, and the hand-over of a
// 2D polygon in the suite's order.
#ifndef MINK_CGAL_COMMON_HPP
#define MINK_CGAL_COMMON_HPP

#include <CGAL/number_utils.h>

#include <algorithm>
#include <exception>
#include <new>
#include <vector>

#include <mink/method.h>
#include <mink/registry.h>

namespace mkcgal {

// body()'s result; MK_ERR_MEMORY when it ran out of memory, and
// MK_ERR_UNSUPPORTED for any other error it raised.
template <class Body>
mkResult Guarded(Body body)
{
	try {
		return body();
	} catch (const std::bad_alloc &) {
		return MK_ERR_MEMORY;
	} catch (const std::exception &) {
		return MK_ERR_UNSUPPORTED;
	}
}

// The lowest (then leftmost) of a counter-clockwise polygon comes first.
template <class Point>
void RotateToLowest(std::vector<Point> &h)
{
	std::size_t best = 0;
	for (std::size_t k = 1; k < h.size(); ++k)
		if (h[k].y() < h[best].y() || (h[k].y() == h[best].y() && h[k].x() < h[best].x())) best = k;
	std::rotate(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(best), h.end());
}

// A counter-clockwise polygon into out, from its lowest (then leftmost)
// vertex, each coordinate converted to the nearest double.
template <class Point>
mkResult PolygonOut(std::vector<Point> &v, mkPointSet *out)
{
	RotateToLowest(v);
	mkResult r = mkPointSet_Resize(out, 2, static_cast<int>(v.size()));
	if (r != MK_OK) return r;
	for (std::size_t k = 0; k < v.size(); ++k) {
		out->x[k] = CGAL::to_double(v[k].x());
		out->y[k] = CGAL::to_double(v[k].y());
	}
	return MK_OK;
}

} // namespace mkcgal

#endif
