// test_fcl_mesh.cpp - the meshes of mink/fcl_mesh.hpp against what the test
// computes itself from the formulas:
//  - every superquadric vertex mapped back by M^-1 (inverted here by
//    cofactors) satisfies the inside-outside function
//    F = (|x/a|^(2/e2) + |y/b|^(2/e2))^(e2/e1) + |z/c|^(2/e1) = 1 within
//    1e-12; every box vertex is a corner (each |coordinate| = half size);
//  - the mesh is closed: each directed edge once, its reverse once;
//  - the triangles are outward: every tetrahedron from the body's centre has
//    positive volume, and their sum equals the divergence-theorem volume;
//  - the volume: a box's and a prism's exactly (8 h.x h.y h.z |det M|, the
//    n-gon's area times the height), a superquadric's at most the closed
//    form 2 a b c e1 e2 B(e1/2 + 1, e1) B(e2/2, e2/2) |det M| (Jaklic et
//    al.) and at least (1 - 4 / res^2) of it; the closed form itself checked
//    by hand on a sphere, an ellipsoid and the limits of a box, a cylinder
//    (e1 -> 0) and a body of square sections (e2 -> 0, volume 16/3);
//  - FCL's verdicts on the Convex geometry: boxes 1e-3 apart or
//    overlapping by 1e-3, and a small sphere wholly inside a superquadric
//    mesh (a solid: it collides);
//  - bad arguments throw.
#include <mink/fcl_mesh.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <utility>

#include "ensure.h"

namespace {

const double mkPi = 3.14159265358979323846;

double mkBeta(double x, double y) { return std::exp(std::lgamma(x) + std::lgamma(y) - std::lgamma(x + y)); }

// Jaklic et al.'s volume of the superquadric, written out here.
double mkSqVolume(double a, double b, double c, double e1, double e2)
{
	return 2.0 * a * b * c * e1 * e2 * mkBeta(e1 / 2.0 + 1.0, e1) * mkBeta(e2 / 2.0, e2 / 2.0);
}

double mkInsideOutside(const mkShape3 &s, const double x[3])
{
	double p = std::pow(std::fabs(x[0] / s.a), 2.0 / s.eps2) + std::pow(std::fabs(x[1] / s.b), 2.0 / s.eps2);
	return std::pow(p, s.eps2 / s.eps1) + std::pow(std::fabs(x[2] / s.c), 2.0 / s.eps1);
}

// x = M^-1 (p - t) by cofactors.
void mkUnmap(const mkMat3 &M, const mkVec3 &t, const fcl::Vector3d &p, double x[3])
{
	const double(*m)[3] = M.m;
	double C[3][3];
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
			C[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
		}
	double det = m[0][0] * C[0][0] + m[0][1] * C[0][1] + m[0][2] * C[0][2];
	double d[3] = { p[0] - t.x, p[1] - t.y, p[2] - t.z };
	for (int i = 0; i < 3; ++i) x[i] = (C[0][i] * d[0] + C[1][i] * d[1] + C[2][i] * d[2]) / det;
}

double mkDet3(const mkMat3 &M)
{
	const double(*m)[3] = M.m;
	return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
		m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Closed and outward around centre o; returns the divergence-theorem volume.
double mkCheckClosedOutward(const mkFclMesh &m, const fcl::Vector3d &o)
{
	std::map<std::pair<int, int>, int> directed;
	double vol = 0.0, tets = 0.0;
	int negative = 0;
	for (const auto &f : m.triangles) {
		const fcl::Vector3d &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
		for (int i = 0; i < 3; ++i) ++directed[{ (int)f[i], (int)f[(i + 1) % 3] }];
		vol += a.dot(b.cross(c)) / 6.0;
		double tet = (a - o).dot((b - o).cross(c - o)) / 6.0;
		tets += tet;
		if (!(tet > 0.0)) ++negative;
	}
	int bad = 0;
	for (const auto &e : directed) {
		auto r = directed.find({ e.first.second, e.first.first });
		if (e.second != 1 || r == directed.end() || r->second != 1) ++bad;
	}
	ENSURE(bad == 0);
	ENSURE(negative == 0);
	ENSURE(vol > 0.0);
	ENSURE_REL(tets, vol, 1e-12);
	return vol;
}

mkMat3 mkRotScale(double ax, double ay, double az, double sx, double sy, double sz, bool reflect)
{
	double cx = std::cos(ax), snx = std::sin(ax), cy = std::cos(ay), sny = std::sin(ay), cz = std::cos(az),
	       snz = std::sin(az);
	double R[3][3] = { { cz * cy, cz * sny * snx - snz * cx, cz * sny * cx + snz * snx },
		{ snz * cy, snz * sny * snx + cz * cx, snz * sny * cx - cz * snx }, { -sny, cy * snx, cy * cx } };
	double S[3] = { reflect ? -sx : sx, sy, sz };
	mkMat3 M;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) M.m[i][j] = R[i][j] * S[j];
	return M;
}

void mkTestVolumeByHand()
{
	ENSURE_REL(mkSqVolume(1, 1, 1, 1, 1), 4.0 * mkPi / 3.0, 1e-14);
	ENSURE_REL(mkSqVolume(1, 0.5, 0.3, 1, 1), 4.0 * mkPi / 3.0 * 0.15, 1e-14);
	// e -> 0: the box [-a, a] x [-b, b] x [-c, c]; error O(e)
	ENSURE_REL(mkSqVolume(1, 0.5, 0.3, 1e-6, 1e-6), 8.0 * 0.15, 1e-5);
	// e1 -> 0, e2 = 1: the cylinder of radius 1 and height 2
	ENSURE_REL(mkSqVolume(1, 1, 1, 1e-6, 1), 2.0 * mkPi, 1e-5);
	// e1 = 1, e2 -> 0: max(|x|, |y|)^2 + z^2 <= 1, sections squares of side
	// 2 sqrt(1 - z^2): the integral of 4 (1 - z^2) over [-1, 1] is 16/3
	ENSURE_REL(mkSqVolume(1, 1, 1, 1, 1e-6), 16.0 / 3.0, 1e-5);
}

void mkTestSuperquadrics()
{
	const mkShape3 shapes[] = { { 1, 1, 1, 1, 1 }, { 1, 0.5, 0.3, 1, 1 }, { 1, 0.7, 0.5, 0.1, 0.1 },
		{ 1, 1, 1, 1.9, 1.9 }, { 1, 0.6, 0.4, 0.1, 1.9 }, { 1, 0.8, 0.5, 1.9, 0.1 }, { 0.4, 1.3, 0.8, 0.3, 1.7 } };
	const int resolutions[] = { 2, 8, 16, 32 };
	double worst = 0.0;
	for (size_t i = 0; i < sizeof shapes / sizeof *shapes; ++i)
		for (int res : resolutions)
			for (int placed = 0; placed < 3; ++placed) {
				mkBody3 b;
				b.shape = shapes[i];
				b.M = placed == 0 ? mkMat3_Identity() : mkRotScale(0.3 * i, 1.1, -0.7, 1.3, 0.6, 0.9, placed == 2);
				b.t = placed == 0 ? mkVec3_Make(0, 0, 0) : mkVec3_Make(2.5, -1.0, 0.75);
				mkFclMesh m = mkFclMesh_Superquadric(b, res);
				ENSURE(m.vertices.size() == (size_t)(2 * res * res + 2));
				ENSURE(m.triangles.size() == (size_t)(4 * res * res));
				double dev = 0.0;
				for (const auto &p : m.vertices) {
					double x[3];
					mkUnmap(b.M, b.t, p, x);
					dev = std::fmax(dev, std::fabs(mkInsideOutside(b.shape, x) - 1.0));
				}
				ENSURE_LE(dev, 1e-12);
				double vol = mkCheckClosedOutward(m, fcl::Vector3d(b.t.x, b.t.y, b.t.z));
				double exact = mkSqVolume(b.shape.a, b.shape.b, b.shape.c, b.shape.eps1, b.shape.eps2) *
					std::fabs(mkDet3(b.M));
				ENSURE_LE(vol, exact * (1.0 + 1e-12));
				if (res >= 8) ENSURE_LE(1.0 - vol / exact, 4.0 / (res * res));
				if (res == 16) worst = std::fmax(worst, 1.0 - vol / exact);
			}
	std::printf("superquadrics at 16 rings: largest volume missed %.3g of the body's\n", worst);
}

void mkTestBoxesAndPrisms()
{
	for (int placed = 0; placed < 3; ++placed) {
		mkMat3 M = placed == 0 ? mkMat3_Identity() : mkRotScale(0.4, -0.2, 1.3, 1.0, 2.0, 0.5, placed == 2);
		mkVec3 t = mkVec3_Make(-1.0, 0.5, 3.0), h = mkVec3_Make(0.5, 0.25, 1.5);
		mkFclMesh m = mkFclMesh_Box(M, t, h);
		ENSURE(m.vertices.size() == 8 && m.triangles.size() == 12);
		for (const auto &p : m.vertices) {
			double x[3];
			mkUnmap(M, t, p, x);
			ENSURE_REL(std::fabs(x[0]), h.x, 1e-14);
			ENSURE_REL(std::fabs(x[1]), h.y, 1e-14);
			ENSURE_REL(std::fabs(x[2]), h.z, 1e-14);
		}
		double vol = mkCheckClosedOutward(m, fcl::Vector3d(t.x, t.y, t.z));
		ENSURE_REL(vol, 8.0 * h.x * h.y * h.z * std::fabs(mkDet3(M)), 1e-13);
	}
	// a regular n-gon of radius r, clockwise seen from up (reversed by the
	// builder), swept 2 along a slanted up: area n r^2 sin(2 pi / n) / 2
	// times the height 2
	for (int n : { 3, 4, 7, 32 }) {
		std::vector<fcl::Vector3d> ring;
		for (int j = 0; j < n; ++j)
			ring.emplace_back(0.8 * std::cos(-2.0 * mkPi * j / n), 0.8 * std::sin(-2.0 * mkPi * j / n), -1.0);
		mkFclMesh m = mkFclMesh_Prism(ring, fcl::Vector3d(0.3, -0.2, 2.0));
		ENSURE(m.vertices.size() == (size_t)(2 * n) && m.triangles.size() == (size_t)(4 * n - 4));
		double vol = mkCheckClosedOutward(m, fcl::Vector3d(0.15, -0.1, 0.0));
		ENSURE_REL(vol, n * 0.64 * std::sin(2.0 * mkPi / n) / 2.0 * 2.0, 1e-13);
	}
}

bool mkCollide(const std::shared_ptr<fcl::CollisionGeometryd> &g1, const fcl::Transform3d &T1,
	const std::shared_ptr<fcl::CollisionGeometryd> &g2, const fcl::Transform3d &T2)
{
	fcl::CollisionObjectd o1(g1, T1), o2(g2, T2);
	fcl::CollisionRequestd req;
	fcl::CollisionResultd res;
	return fcl::collide(&o1, &o2, req, res) > 0;
}

void mkTestFclVerdicts()
{
	// two unit cubes (half size 0.5), the second along x at 1 +- 1e-3, both
	// turned by the same rotation about the origin
	mkMat3 R = mkRotScale(0.7, 0.2, -0.4, 1, 1, 1, false);
	mkVec3 h = mkVec3_Make(0.5, 0.5, 0.5);
	for (int side = -1; side <= 1; side += 2) {
		mkVec3 c = mkMat3_MulVec(R, mkVec3_Make(1.0 + side * 1e-3, 0, 0));
		auto a = mkFclMesh_Convex(mkFclMesh_Box(R, mkVec3_Make(0, 0, 0), h));
		auto b = mkFclMesh_Convex(mkFclMesh_Box(R, c, h));
		bool hit = mkCollide(a, fcl::Transform3d::Identity(), b, fcl::Transform3d::Identity());
		ENSURE(hit == (side < 0));
	}
	// a sphere of radius 0.05 wholly inside a box-like superquadric's mesh
	mkBody3 b;
	b.shape = mkShape3{ 1, 0.7, 0.5, 0.1, 0.1 };
	b.M = mkRotScale(0.1, 0.2, 0.3, 1, 1, 1, false);
	b.t = mkVec3_Make(1, 2, 3);
	auto g = mkFclMesh_Convex(mkFclMesh_Superquadric(b, 16));
	fcl::Transform3d T = fcl::Transform3d::Identity();
	T.translation() = fcl::Vector3d(1.1, 2.0, 3.05);
	ENSURE(mkCollide(g, fcl::Transform3d::Identity(), std::make_shared<fcl::Sphered>(0.05), T));
	T.translation() = fcl::Vector3d(1.0, 2.0, 3.0) + 2.0 * fcl::Vector3d(b.M.m[0][2], b.M.m[1][2], b.M.m[2][2]);
	ENSURE(!mkCollide(g, fcl::Transform3d::Identity(), std::make_shared<fcl::Sphered>(0.05), T));
}

template <class F> void mkEnsureThrows(F f)
{
	bool thrown = false;
	try {
		f();
	} catch (const std::invalid_argument &) {
		thrown = true;
	}
	ENSURE(thrown);
}

void mkTestBadArguments()
{
	mkBody3 b = mkBody3_Make(mkShape3{ 1, 1, 1, 1, 1 }, mkMat3_Identity(), mkVec3_Make(0, 0, 0));
	mkEnsureThrows([&] { mkFclMesh_Superquadric(b, MK_FCL_MESH_RES_MIN - 1); });
	mkEnsureThrows([&] { mkFclMesh_Superquadric(b, MK_FCL_MESH_RES_MAX + 1); });
	mkBody3 flat = b;
	flat.M.m[2][2] = 0.0;
	mkEnsureThrows([&] { mkFclMesh_Superquadric(flat, 8); });
	mkEnsureThrows([&] { mkFclMesh_Prism({ fcl::Vector3d(0, 0, 0), fcl::Vector3d(1, 0, 0) }, fcl::Vector3d(0, 0, 1)); });
	mkEnsureThrows([&] {
		mkFclMesh_Prism({ fcl::Vector3d(0, 0, 0), fcl::Vector3d(1, 0, 0), fcl::Vector3d(0, 1, 0) }, fcl::Vector3d(1, 1, 0));
	});
	mkEnsureThrows([&] { mkFclMesh_Box(mkMat3_Identity(), mkVec3_Make(0, 0, 0), mkVec3_Make(1, 0, 1)); });
}

} // namespace

int main()
{
	mkTestVolumeByHand();
	mkTestSuperquadrics();
	mkTestBoxesAndPrisms();
	mkTestFclVerdicts();
	mkTestBadArguments();
	return mk_summary("test_fcl_mesh");
}
