// hull_epick.cpp - convex hulls on CGAL's Exact_predicates_inexact_
// constructions_kernel: exact decisions on double coordinates.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdlib>

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

extern "C" int mkCgalHull3_Mesh(const double *xyz, int count, double **vertices, int *nv, int **triangles, int *nt)
{
	typedef Epick::Point_3 Point;
	typedef CGAL::Surface_mesh<Point> Mesh;
	*vertices = nullptr;
	*triangles = nullptr;
	*nv = *nt = 0;
	try {
		std::vector<Point> pts;
		pts.reserve(static_cast<std::size_t>(count));
		for (int k = 0; k < count; ++k) pts.emplace_back(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
		if (!mkcgal::SpansVolume(pts)) return -2;
		Mesh mesh;
		CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
		// Index the vertices 0..nv-1 in the mesh's order (no vertex was
		// removed from a fresh mesh, so the indices are already dense).
		*nv = static_cast<int>(mesh.number_of_vertices());
		*nt = static_cast<int>(mesh.number_of_faces());
		*vertices = static_cast<double *>(std::malloc(3 * static_cast<std::size_t>(*nv) * sizeof(double)));
		*triangles = static_cast<int *>(std::malloc(3 * static_cast<std::size_t>(*nt) * sizeof(int)));
		if (!*vertices || !*triangles) throw std::bad_alloc();
		for (Mesh::Vertex_index v : mesh.vertices()) {
			const Point &p = mesh.point(v);
			std::size_t i = static_cast<std::size_t>(v);
			(*vertices)[3 * i] = p.x(), (*vertices)[3 * i + 1] = p.y(), (*vertices)[3 * i + 2] = p.z();
		}
		int f = 0;
		for (Mesh::Face_index fi : mesh.faces()) {
			int c = 0;
			for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(fi), mesh)) {
				if (c == 3) return -3;
				(*triangles)[3 * f + c++] = static_cast<int>(static_cast<std::size_t>(v));
			}
			if (c != 3) return -3;
			++f;
		}
		return 0;
	} catch (const std::bad_alloc &) {
		std::free(*vertices);
		std::free(*triangles);
		*vertices = nullptr;
		*triangles = nullptr;
		return -1;
	}
}
