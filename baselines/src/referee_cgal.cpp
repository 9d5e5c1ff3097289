// referee_cgal.cpp - the referee's exact decisions: is a sampled method's
// output exactly the set of extreme points of its input? Every test is one
// of CGAL's exact predicates on the double coordinates (Epick filters them
// through interval arithmetic and falls back to exact number types), so no
// tolerance enters a yes/no answer. Distances are only reported. The hull
// of a 3D output is built by hull_epick.cpp (mkCgalHull3_Mesh) and then
// certified here, face by face, against every input point.
// Also here, as the other exact reference: CGAL's minkowski_sum_2 on the
// exact kernel, the cross-check of edge sorting (collinear vertices, which
// minkowski_sum_2 keeps where parallel edges meet, removed).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <new>
#include <vector>

#include <mink/baselines.h>

#include "cgal_common.hpp"
#include "referee_cgal.h"

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 P2;
typedef K::Point_3 P3;

void Why(mkHullReport *r, const char *text)
{
	if (!r->why[0]) std::snprintf(r->why, sizeof r->why, "%s", text);
}

// 0 for edge directions with angle in [0, pi), 1 for [pi, 2 pi). The sign of
// a difference of doubles is exact.
int Half(const P2 &a, const P2 &b)
{
	double dx = b.x() - a.x(), dy = b.y() - a.y();
	return !(dy > 0 || (dy == 0 && dx > 0));
}

typedef std::array<double, 2> Key2;
typedef std::array<double, 3> Key3;

// 1 when p lies in the closed strictly convex counter-clockwise polygon v.
bool InConvexPolygon(const std::vector<P2> &v, const P2 &p)
{
	const std::size_t h = v.size();
	if (CGAL::orientation(v[0], v[1], p) == CGAL::RIGHT_TURN) return false;
	if (CGAL::orientation(v[0], v[h - 1], p) == CGAL::LEFT_TURN) return false;
	// The wedge v0 v_k v_{k+1} that holds p: the largest k whose ray from v0
	// does not have p on its right.
	std::size_t lo = 1, hi = h - 1;
	while (hi - lo > 1) {
		std::size_t mid = (lo + hi) / 2;
		if (CGAL::orientation(v[0], v[mid], p) != CGAL::RIGHT_TURN) lo = mid;
		else hi = mid;
	}
	if (lo == h - 1) lo = h - 2;
	return CGAL::orientation(v[lo], v[lo + 1], p) != CGAL::RIGHT_TURN;
}

double DistanceToPolygon(const std::vector<P2> &v, const P2 &p)
{
	double best = HUGE_VAL;
	for (std::size_t k = 0; k < v.size(); ++k) {
		K::Segment_2 e(v[k], v[(k + 1) % v.size()]);
		best = std::min(best, CGAL::to_double(CGAL::squared_distance(e, p)));
	}
	return std::sqrt(best);
}

// check()'s result (0) for the hull checks, with *r cleared first; -1 when
// memory ran out, -2 with *r cleared again and r->why saying so when CGAL
// raised any other error.
template <class Check>
int Checked(mkHullReport *r, Check check)
{
	*r = mkHullReport();
	try {
		return check();
	} catch (const std::bad_alloc &) {
		return -1;
	} catch (const std::exception &e) {
		*r = mkHullReport();
		std::snprintf(r->why, sizeof r->why, "CGAL failed: %s", e.what());
		return -2;
	}
}

} // namespace

extern "C" int mkRefereeCgal2_Orient(const double *a, const double *b, const double *c)
{
	CGAL::Orientation o = CGAL::orientation(P2(a[0], a[1]), P2(b[0], b[1]), P2(c[0], c[1]));
	return o == CGAL::LEFT_TURN ? 1 : o == CGAL::RIGHT_TURN ? -1 : 0;
}

extern "C" int mkRefereeCgal_Polygon(const double *vx, const double *vy, int nv, const double *s, long ns,
	mkHullReport *r)
{
	return Checked(r, [&] {
		std::vector<P2> v;
		v.reserve(static_cast<std::size_t>(nv));
		for (int k = 0; k < nv; ++k) v.emplace_back(vx[k], vy[k]);

		// convex: every turn strictly left, and the edge direction passes
		// angle 0 exactly once (one winding).
		r->convex = nv >= 3;
		if (!r->convex) Why(r, "fewer than 3 vertices");
		int wraps = 0;
		for (int k = 0; r->convex && k < nv; ++k) {
			const P2 &a = v[(k + nv - 1) % nv], &b = v[k], &c = v[(k + 1) % nv];
			if (CGAL::orientation(a, b, c) != CGAL::LEFT_TURN) {
				char text[160];
				std::snprintf(text, sizeof text, "vertex %d is not a strict left turn", k);
				Why(r, text);
				r->convex = 0;
			}
			if (Half(a, b) == 1 && Half(b, c) == 0) ++wraps;
		}
		if (r->convex && wraps != 1) {
			char text[160];
			std::snprintf(text, sizeof text, "the polygon winds %d times", wraps);
			Why(r, text);
			r->convex = 0;
		}

		// subset: bit-for-bit membership in the input.
		std::vector<Key2> in(static_cast<std::size_t>(ns));
		for (long k = 0; k < ns; ++k) in[static_cast<std::size_t>(k)] = Key2{s[2 * k], s[2 * k + 1]};
		std::sort(in.begin(), in.end());
		r->subset = 1;
		for (int k = 0; k < nv; ++k)
			if (!std::binary_search(in.begin(), in.end(), Key2{vx[k], vy[k]})) {
				char text[160];
				std::snprintf(text, sizeof text, "vertex %d (%.17g, %.17g) is not an input point", k, vx[k], vy[k]);
				Why(r, text);
				r->subset = 0;
				break;
			}

		// extreme: every input point in the closed output polygon (needs a
		// convex output to be decided this way).
		if (r->convex) {
			for (long k = 0; k < ns; ++k) {
				P2 p(s[2 * k], s[2 * k + 1]);
				if (InConvexPolygon(v, p)) continue;
				if (r->measured < MK_HULL_MEASURE_MAX) {
					r->outside_max = std::max(r->outside_max, DistanceToPolygon(v, p));
					++r->measured;
				}
				++r->outside;
			}
			r->extreme = r->outside == 0;
			if (!r->extreme) {
				char text[160];
				std::snprintf(text, sizeof text, "%d input points lie outside the output polygon", r->outside);
				Why(r, text);
			}
		}
		return 0;
	});
}

extern "C" int mkRefereeCgal_Polytope(const double *vx, const double *vy, const double *vz, int nv,
	const double *s, long ns, mkHullReport *r)
{
	return Checked(r, [&] {
		std::vector<P3> v;
		v.reserve(static_cast<std::size_t>(nv));
		for (int k = 0; k < nv; ++k) v.emplace_back(vx[k], vy[k], vz[k]);

		// subset, and no point given twice.
		std::vector<Key3> in(static_cast<std::size_t>(ns));
		for (long k = 0; k < ns; ++k) in[static_cast<std::size_t>(k)] = Key3{s[3 * k], s[3 * k + 1], s[3 * k + 2]};
		std::sort(in.begin(), in.end());
		r->subset = 1;
		std::vector<Key3> out(static_cast<std::size_t>(nv));
		for (int k = 0; k < nv; ++k) {
			out[static_cast<std::size_t>(k)] = Key3{vx[k], vy[k], vz[k]};
			if (r->subset && !std::binary_search(in.begin(), in.end(), out[static_cast<std::size_t>(k)])) {
				char text[160];
				std::snprintf(text, sizeof text, "vertex %d (%.17g, %.17g, %.17g) is not an input point", k, vx[k],
					vy[k], vz[k]);
				Why(r, text);
				r->subset = 0;
			}
		}
		std::sort(out.begin(), out.end());
		bool twice = std::adjacent_find(out.begin(), out.end()) != out.end();

		// convex: the hull of the output has every output point as a vertex.
		r->convex = 0;
		int hv = 0, ht = 0;
		double *hxyz = nullptr;
		int *tri = nullptr;
		if (twice) Why(r, "an output point is given twice");
		else if (nv < 4) Why(r, "fewer than 4 vertices");
		else {
			std::vector<double> flat(3 * static_cast<std::size_t>(nv));
			for (int k = 0; k < nv; ++k) flat[3 * k] = vx[k], flat[3 * k + 1] = vy[k], flat[3 * k + 2] = vz[k];
			int rc = mkCgalHull3_Mesh(flat.data(), nv, &hxyz, &hv, &tri, &ht);
			if (rc == -1) throw std::bad_alloc();
			if (rc == -2) Why(r, "the output spans no volume");
			else if (rc) Why(r, "a hull face is not a triangle");
			else if (hv != nv) {
				char text[160];
				std::snprintf(text, sizeof text, "%d of %d output points are not vertices of their hull", nv - hv, nv);
				Why(r, text);
			} else r->convex = 1;
		}
		std::unique_ptr<double, void (*)(void *)> own_xyz(hxyz, std::free);
		std::unique_ptr<int, void (*)(void *)> own_tri(tri, std::free);

		// extreme: every input point on the inner side of (or on) every face
		// plane of that hull.
		if (r->convex) {
			std::vector<unsigned char> outside(static_cast<std::size_t>(ns), 0);
			std::vector<K::Triangle_3> faces;
			std::size_t probe = 0;
			for (int f = 0; f < ht; ++f) {
				std::array<P3, 3> t;
				for (int c = 0; c < 3; ++c) {
					const double *p = hxyz + 3 * tri[3 * f + c];
					t[static_cast<std::size_t>(c)] = P3(p[0], p[1], p[2]);
				}
				faces.emplace_back(t[0], t[1], t[2]);
				// Which side is inside: that of any output vertex off the plane.
				CGAL::Orientation inside = CGAL::COPLANAR;
				for (int tries = 0; tries < nv && inside == CGAL::COPLANAR; ++tries, ++probe)
					inside = CGAL::orientation(t[0], t[1], t[2], v[probe % v.size()]);
				if (inside == CGAL::COPLANAR) {
					Why(r, "a hull face has every vertex on its plane");
					r->convex = 0;
					break;
				}
				for (long k = 0; k < ns; ++k) {
					P3 p(s[3 * k], s[3 * k + 1], s[3 * k + 2]);
					CGAL::Orientation o = CGAL::orientation(t[0], t[1], t[2], p);
					if (o != CGAL::COPLANAR && o != inside) outside[static_cast<std::size_t>(k)] = 1;
				}
			}
			// The distance of an outside point to the hull is its distance to
			// the nearest boundary triangle.
			for (long k = 0; r->convex && k < ns; ++k) {
				if (!outside[static_cast<std::size_t>(k)]) continue;
				++r->outside;
				if (r->measured >= MK_HULL_MEASURE_MAX) continue;
				P3 p(s[3 * k], s[3 * k + 1], s[3 * k + 2]);
				double best = HUGE_VAL;
				for (const K::Triangle_3 &t : faces) best = std::min(best, CGAL::to_double(CGAL::squared_distance(t, p)));
				r->outside_max = std::max(r->outside_max, std::sqrt(best));
				++r->measured;
			}
			r->extreme = r->convex && r->outside == 0;
			if (r->convex && !r->extreme) {
				char text[160];
				std::snprintf(text, sizeof text, "%d input points lie outside the output's hull", r->outside);
				Why(r, text);
			}
		}
		return 0;
	});
}

extern "C" mkResult mkMinkowski2_CgalEpeck(const double *P, int m, const double *Q, int n, mkPointSet *out)
{
	typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
	typedef Epeck::Point_2 Point;
	typedef CGAL::Polygon_2<Epeck> Polygon;
	if (!P || !Q || !out || m < 1 || n < 1) return MK_ERR_ARGUMENT;
	return mkcgal::Guarded([&]() -> mkResult {
		Polygon a, b;
		for (int k = 0; k < m; ++k) a.push_back(Point(P[2 * k], P[2 * k + 1]));
		for (int k = 0; k < n; ++k) b.push_back(Point(Q[2 * k], Q[2 * k + 1]));
		if (!a.is_simple() || !b.is_simple()) return MK_ERR_ARGUMENT;
		CGAL::Polygon_with_holes_2<Epeck> sum = CGAL::minkowski_sum_2(a, b);
		std::vector<Point> v(sum.outer_boundary().vertices_begin(), sum.outer_boundary().vertices_end());
		if (sum.outer_boundary().orientation() == CGAL::CLOCKWISE) std::reverse(v.begin(), v.end());
		// minkowski_sum_2 keeps a vertex where two parallel edges meet; drop
		// such collinear vertices (exact test), starting from a true corner.
		const std::size_t nv = v.size();
		std::size_t start = 0;
		while (start < nv && CGAL::orientation(v[(start + nv - 1) % nv], v[start], v[(start + 1) % nv]) == CGAL::COLLINEAR)
			++start;
		if (start < nv) {
			std::vector<Point> kept{v[start]};
			for (std::size_t k = 1; k < nv; ++k) {
				const Point &p = v[(start + k) % nv], &q = v[(start + k + 1) % nv];
				if (CGAL::orientation(kept.back(), p, q) != CGAL::COLLINEAR) kept.push_back(p);
			}
			v.swap(kept);
		}
		return mkcgal::PolygonOut(v, out);
	});
}
