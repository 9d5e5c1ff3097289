// fcl_mesh.cpp - closed triangle meshes of superquadrics, boxes and prisms,
// and FCL's geometries of them (mink/fcl_mesh.hpp).
#include "mink/fcl_mesh.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

// cos and sin of the angle 2 pi j / n, exact at multiples of a quarter turn
// (so that poles and axis planes get exact zeros: |cos(pi/2)|^0.1 in
// floating point would be 0.023, not 0).
void mkFclTurn(long j, long n, double *c, double *s)
{
	j = ((j % n) + n) % n;
	if ((4 * j) % n == 0) {
		static const double C[4] = { 1.0, 0.0, -1.0, 0.0 }, S[4] = { 0.0, 1.0, 0.0, -1.0 };
		*c = C[4 * j / n];
		*s = S[4 * j / n];
		return;
	}
	double a = 2.0 * 3.14159265358979323846 * (double)j / (double)n;
	*c = std::cos(a);
	*s = std::sin(a);
}

// sign(c) |c|^e
double mkFclSignPow(double c, double e) { return std::copysign(std::pow(std::fabs(c), e), c); }

fcl::Vector3d mkFclPlaced(const mkMat3 &M, const mkVec3 &t, double x, double y, double z)
{
	mkVec3 p = mkVec3_Add(t, mkMat3_MulVec(M, mkVec3_Make(x, y, z)));
	return fcl::Vector3d(p.x, p.y, p.z);
}

} // namespace

mkFclMesh mkFclMesh_Superquadric(const mkBody3 &b, int res)
{
	char msg[256];
	if (res < MK_FCL_MESH_RES_MIN || res > MK_FCL_MESH_RES_MAX)
		throw std::invalid_argument("mesh res = " + std::to_string(res) + " is out of range: must be in [" +
			std::to_string(MK_FCL_MESH_RES_MIN) + ", " + std::to_string(MK_FCL_MESH_RES_MAX) + "]");
	if (!mkBody3_IsValid(b, "body", msg, sizeof msg)) throw std::invalid_argument(msg);
	double det = mkMat3_Det(b.M);
	if (!(det != 0.0)) throw std::invalid_argument("body.M is singular: a mesh needs a nonsingular map");
	const mkShape3 &s = b.shape;
	mkFclMesh m;
	int nl = 2 * res;
	m.vertices.reserve((size_t)(nl * res + 2));
	m.triangles.reserve((size_t)(2 * nl * res));
	// eta = -pi/2 + pi r / (res + 1) = 2 pi (2 r - res - 1) / (4 (res + 1))
	auto put = [&](int r, int k) {
		double ce, se, co, so;
		mkFclTurn(2L * r - res - 1, 4L * (res + 1), &ce, &se);
		mkFclTurn(k, nl, &co, &so);
		double h = mkFclSignPow(ce, s.eps1);
		m.vertices.push_back(mkFclPlaced(b.M, b.t, s.a * h * mkFclSignPow(co, s.eps2),
			s.b * h * mkFclSignPow(so, s.eps2), s.c * mkFclSignPow(se, s.eps1)));
	};
	put(0, 0);
	for (int r = 1; r <= res; ++r)
		for (int k = 0; k < nl; ++k) put(r, k);
	put(res + 1, 0);
	int top = (int)m.vertices.size() - 1;
	// counter-clockwise from outside in the body's own frame; a reflecting
	// M turns them, so two corners are swapped back
	auto tri = [&](int i, int j, int k) {
		if (det > 0.0) m.triangles.emplace_back(i, j, k);
		else m.triangles.emplace_back(i, k, j);
	};
	for (int k = 0; k < nl; ++k) {
		int k1 = (k + 1) % nl;
		tri(0, 1 + k1, 1 + k);
		tri(top, 1 + (res - 1) * nl + k, 1 + (res - 1) * nl + k1);
		for (int r = 0; r + 1 < res; ++r) {
			int a = 1 + r * nl, c = a + nl;
			tri(a + k, a + k1, c + k1);
			tri(a + k, c + k1, c + k);
		}
	}
	return m;
}

mkFclMesh mkFclMesh_Prism(const std::vector<fcl::Vector3d> &outline, const fcl::Vector3d &up)
{
	int n = (int)outline.size();
	if (n < 3) throw std::invalid_argument("a prism's outline needs at least 3 corners, got " + std::to_string(n));
	// Newell's normal of the outline: it points to the side from which the
	// outline runs counter-clockwise
	fcl::Vector3d N = fcl::Vector3d::Zero();
	for (int i = 0; i < n; ++i) N += outline[i].cross(outline[(i + 1) % n]);
	double side = N.dot(up);
	if (!(std::fabs(side) > 1e-12 * N.norm() * up.norm()))
		throw std::invalid_argument("a prism's direction must leave the outline's plane");
	mkFclMesh m;
	m.vertices.reserve((size_t)(2 * n));
	for (int i = 0; i < n; ++i) m.vertices.push_back(outline[side > 0.0 ? i : n - 1 - i]);
	for (int i = 0; i < n; ++i) m.vertices.push_back(m.vertices[(size_t)i] + up);
	// now counter-clockwise seen from the top cap (the outline + up)
	for (int i = 0; i < n; ++i) {
		int j = (i + 1) % n;
		m.triangles.emplace_back(i, j, n + j);
		m.triangles.emplace_back(i, n + j, n + i);
	}
	for (int i = 1; i + 1 < n; ++i) {
		m.triangles.emplace_back(0, i + 1, i);
		m.triangles.emplace_back(n, n + i, n + i + 1);
	}
	return m;
}

mkFclMesh mkFclMesh_Box(const mkMat3 &M, const mkVec3 &t, const mkVec3 &h)
{
	if (!(h.x > 0.0 && h.y > 0.0 && h.z > 0.0)) throw std::invalid_argument("a box's half sizes must be > 0");
	std::vector<fcl::Vector3d> ring = { mkFclPlaced(M, t, -h.x, -h.y, -h.z), mkFclPlaced(M, t, h.x, -h.y, -h.z),
		mkFclPlaced(M, t, h.x, h.y, -h.z), mkFclPlaced(M, t, -h.x, h.y, -h.z) };
	mkVec3 up = mkMat3_MulVec(M, mkVec3_Make(0.0, 0.0, 2.0 * h.z));
	return mkFclMesh_Prism(ring, fcl::Vector3d(up.x, up.y, up.z));
}

std::shared_ptr<fcl::Convexd> mkFclMesh_Convex(const mkFclMesh &m)
{
	auto verts = std::make_shared<std::vector<fcl::Vector3d>>(m.vertices);
	auto faces = std::make_shared<std::vector<int>>();
	faces->reserve(4 * m.triangles.size());
	for (const auto &f : m.triangles) {
		faces->push_back(3);
		for (int i = 0; i < 3; ++i) faces->push_back((int)f[i]);
	}
	return std::make_shared<fcl::Convexd>(verts, (int)m.triangles.size(), faces);
}
