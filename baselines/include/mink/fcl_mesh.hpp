/* mink/fcl_mesh.hpp - FCL's view of mink's bodies: closed triangle meshes
 * of a placed superquadric (at a stated resolution) and of boxes and prisms
 * (exact), and the two FCL geometries built from them. C++17; the one
 * builder of the scene checks' peer (scene_fcl.cpp) and of the planning
 * experiment's FCL checker (experiments/plan/plan_fcl.cpp).
 *
 * Every mesh is closed (each edge in exactly two triangles, once in each
 * direction), its triangles counter-clockwise seen from outside, every
 * vertex on the body's boundary. For a curved body the mesh is inscribed:
 * it misses a thin layer of the body (measured in docs/notes.md).
 *
 * Superquadric: the parametric map x(eta, omega) = t + M (a c(eta)^e1
 * c(omega)^e2, b c(eta)^e1 s(omega)^e2, c s(eta)^e1) (c^e = sign(c) |c|^e,
 * the same point as mkShape3_Point of u = (cos eta cos omega, cos eta
 * sin omega, sin eta)) on res rings of 2 res longitudes, eta = -pi/2 +
 * pi r / (res + 1), r = 1..res, omega = 2 pi k / (2 res), plus the two
 * poles: 2 res^2 + 2 vertices, 4 res^2 triangles (res = 16: 514 vertices,
 * 1024 triangles). This map is kept over the Gauss map (the vertices where
 * the outward normal takes the same directions): at 16 rings the Gauss
 * map's mesh lay 1.3 to 15 times as far from the surface and missed 1.7 to
 * 16 times the volume on the non-spherical bodies measured (docs/notes.md). */
#ifndef MINK_FCL_MESH_HPP
#define MINK_FCL_MESH_HPP

#include <memory>
#include <vector>

#include <fcl/fcl.h>

#include <mink/body.h>

/* Vertices and triangles (indices into vertices). */
struct mkFclMesh {
	std::vector<fcl::Vector3d> vertices;
	std::vector<fcl::Triangle> triangles;
};

/* Resolutions accepted by mkFclMesh_Superquadric. */
enum { MK_FCL_MESH_RES_MIN = 2, MK_FCL_MESH_RES_MAX = 1000 };

/* The surface mesh of body b (world coordinates: t + M x) at res rings
 * (above). Throws std::invalid_argument for res out of
 * [MK_FCL_MESH_RES_MIN, MK_FCL_MESH_RES_MAX] or a singular M. */
mkFclMesh mkFclMesh_Superquadric(const mkBody3 &b, int res);

/* The prism swept by the convex polygon outline (n >= 3 corners, in one
 * plane, in either order) along up: 2n vertices (the outline, then the
 * outline + up), 4n - 4 triangles (caps fanned from their first corner).
 * Throws std::invalid_argument when n < 3 or up is parallel to the
 * outline's plane. */
mkFclMesh mkFclMesh_Prism(const std::vector<fcl::Vector3d> &outline, const fcl::Vector3d &up);

/* The box t + M [-h, h] (h: half sizes > 0, M nonsingular): the prism over
 * its four corners z = -h.z, 8 vertices, 12 triangles. */
mkFclMesh mkFclMesh_Box(const mkMat3 &M, const mkVec3 &t, const mkVec3 &h);

/* FCL's convex polytope of the mesh (fcl::Convex: GJK through libccd on its
 * vertices, the extreme vertex found by walking the mesh's edges; a solid,
 * so a body inside another collides). The mesh's vertices must be in
 * convex position, as the builders' are. The one FCL geometry of the
 * meshes: fcl::BVHModel<OBBRSS> of the same triangles (a surface only,
 * blind to a body wholly inside another) gave the same verdicts in
 * mink_bench_scene --kind sq and took 3.1 to 7.5 times FCL's CPU time per
 * pose (docs/notes.md). */
std::shared_ptr<fcl::Convexd> mkFclMesh_Convex(const mkFclMesh &m);

#endif
