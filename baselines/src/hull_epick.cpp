// hull_epick.cpp - convex hulls on CGAL's Exact_predicates_inexact_
// constructions_kernel: exact decisions on double coordinates.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "hull_cgal.hpp"
#include "referee_cgal.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;

extern "C" mkResult mkHull2_CgalEpick(const double *xy, int count, mkPointSet *out)
{
	return mkcgal::Hull2<Epick>(xy, count, out);
}

extern "C" mkResult mkHull3_CgalEpick(const double *xyz, int count, mkPointSet *out)
{
	return mkcgal::Hull3<Epick>(xyz, count, out);
}

namespace {

typedef Epick::Point_3 Point3;
typedef CGAL::Surface_mesh<Point3> Mesh3;

// Lexicographic order of coordinates (x, then y, then z), the order the
// error measure sorts its points in.
bool LexLess(const Point3 &p, const Point3 &q)
{
	if (p.x() != q.x()) return p.x() < q.x();
	if (p.y() != q.y()) return p.y() < q.y();
	return p.z() < q.z();
}

int Root(std::vector<int> &up, int f)
{
	while (up[static_cast<std::size_t>(f)] != f) {
		int g = up[static_cast<std::size_t>(up[static_cast<std::size_t>(f)])];
		up[static_cast<std::size_t>(f)] = g; // path halving
		f = g;
	}
	return f;
}

// The triangles of a hull in a form that depends only on the hull, not on
// the order CGAL built it in. convex_hull_3 cuts a planar face with more
// than three corners into triangles in an order that follows memory
// addresses (the border of the visible region is a std::map keyed by vertex
// handle), so the same points can give different triangles on different
// threads. Here the faces are first merged back: adjacent triangles whose
// four vertices are exactly coplanar (Epick's orientation predicate is
// exact) belong to one face. Each face's boundary is walked into one cycle,
// counter-clockwise seen from outside; vertices exactly collinear with their
// two neighbours on it are left out (they lie on an edge of the face, and a
// fan through them would hold a degenerate triangle); the remaining corners
// are fanned from the lexicographically smallest one. Returns the triangles
// as triples of mesh vertex indices.
std::vector<std::array<std::size_t, 3>> CanonicalTriangles(const Mesh3 &mesh)
{
	typedef Mesh3::Halfedge_index H;
	std::vector<int> up(mesh.number_of_faces());
	for (std::size_t f = 0; f < up.size(); ++f) up[f] = static_cast<int>(f);
	auto fid = [&](H h) { return static_cast<int>(static_cast<std::size_t>(mesh.face(h))); };
	auto pt = [&](Mesh3::Vertex_index v) -> const Point3 & { return mesh.point(v); };
	for (Mesh3::Edge_index e : mesh.edges()) {
		H h = mesh.halfedge(e), o = mesh.opposite(h);
		if (CGAL::orientation(pt(mesh.source(h)), pt(mesh.target(h)), pt(mesh.target(mesh.next(h))),
			    pt(mesh.target(mesh.next(o))))
			== CGAL::COPLANAR) {
			int a = Root(up, fid(h)), b = Root(up, fid(o));
			if (a != b) up[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
		}
	}
	std::vector<int> group(up.size());
	for (std::size_t f = 0; f < up.size(); ++f) group[f] = Root(up, static_cast<int>(f));
	auto grp = [&](H h) { return group[static_cast<std::size_t>(fid(h))]; };
	std::vector<char> walked(mesh.number_of_halfedges(), 0);
	std::vector<std::array<std::size_t, 3>> tris;
	tris.reserve(mesh.number_of_faces());
	std::vector<Mesh3::Vertex_index> cycle, corner;
	for (H h : mesh.halfedges()) {
		if (walked[static_cast<std::size_t>(h)] || grp(h) == grp(mesh.opposite(h))) continue;
		// h is on the boundary of its face: walk that boundary. From the
		// end of a boundary halfedge, turn through the face's own
		// triangles until the next halfedge on the boundary.
		int g = grp(h);
		cycle.clear();
		H b = h;
		do {
			walked[static_cast<std::size_t>(b)] = 1;
			cycle.push_back(mesh.source(b));
			H n = mesh.next(b);
			while (grp(mesh.opposite(n)) == g) n = mesh.next(mesh.opposite(n));
			b = n;
		} while (b != h);
		corner.clear();
		std::size_t m = cycle.size();
		for (std::size_t i = 0; i < m; ++i)
			if (!CGAL::collinear(pt(cycle[(i + m - 1) % m]), pt(cycle[i]), pt(cycle[(i + 1) % m])))
				corner.push_back(cycle[i]);
		if (corner.size() < 3) throw std::logic_error("a hull face with fewer than 3 corners");
		std::size_t s = 0;
		for (std::size_t i = 1; i < corner.size(); ++i)
			if (LexLess(pt(corner[i]), pt(corner[s]))) s = i;
		std::rotate(corner.begin(), corner.begin() + static_cast<std::ptrdiff_t>(s), corner.end());
		for (std::size_t i = 1; i + 1 < corner.size(); ++i)
			tris.push_back({static_cast<std::size_t>(corner[0]), static_cast<std::size_t>(corner[i]),
				static_cast<std::size_t>(corner[i + 1])});
	}
	return tris;
}

} // namespace

extern "C" int mkCgalHull3_Mesh(const double *xyz, int count, double **vertices, int *nv, int **triangles, int *nt)
{
	*vertices = nullptr;
	*triangles = nullptr;
	*nv = *nt = 0;
	try {
		std::vector<Point3> pts;
		pts.reserve(static_cast<std::size_t>(count));
		for (int k = 0; k < count; ++k) pts.emplace_back(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
		if (!mkcgal::SpansVolume(pts)) return -2;
		Mesh3 mesh;
		CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
		for (Mesh3::Face_index f : mesh.faces())
			if (mesh.degree(f) != 3) throw std::logic_error("a hull face is not a triangle");
		std::vector<std::array<std::size_t, 3>> tris = CanonicalTriangles(mesh);
		// The vertices in lexicographic order (no vertex was removed from a
		// fresh mesh, so the mesh's indices are dense), the triangles
		// renumbered, each started at its smallest index (orientation
		// kept), and sorted.
		std::vector<std::size_t> order(mesh.number_of_vertices()), rank(order.size());
		for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
		std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
			return LexLess(mesh.point(Mesh3::Vertex_index(static_cast<Mesh3::size_type>(a))),
				mesh.point(Mesh3::Vertex_index(static_cast<Mesh3::size_type>(b))));
		});
		for (std::size_t i = 0; i < order.size(); ++i) rank[order[i]] = i;
		for (std::array<std::size_t, 3> &t : tris) {
			for (std::size_t &v : t) v = rank[v];
			std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
		}
		std::sort(tris.begin(), tris.end());
		*nv = static_cast<int>(order.size());
		*nt = static_cast<int>(tris.size());
		*vertices = static_cast<double *>(std::malloc(3 * order.size() * sizeof(double) + 1));
		*triangles = static_cast<int *>(std::malloc(3 * tris.size() * sizeof(int) + 1));
		if (!*vertices || !*triangles) throw std::bad_alloc();
		for (std::size_t i = 0; i < order.size(); ++i) {
			const Point3 &p = mesh.point(Mesh3::Vertex_index(static_cast<Mesh3::size_type>(order[i])));
			(*vertices)[3 * i] = p.x(), (*vertices)[3 * i + 1] = p.y(), (*vertices)[3 * i + 2] = p.z();
		}
		for (std::size_t f = 0; f < tris.size(); ++f)
			for (std::size_t c = 0; c < 3; ++c) (*triangles)[3 * f + c] = static_cast<int>(tris[f][c]);
		return 0;
	} catch (const std::exception &x) {
		// bad_alloc: memory; anything else (a CGAL precondition, a face
		// without 3 corners) means the faces could not be made triangles.
		std::free(*vertices);
		std::free(*triangles);
		*vertices = nullptr;
		*triangles = nullptr;
		*nv = *nt = 0;
		return dynamic_cast<const std::bad_alloc *>(&x) ? -1 : -3;
	}
}
