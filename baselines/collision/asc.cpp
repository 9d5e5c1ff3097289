// asc.cpp - the algebraic separation condition of two ellipsoids (Wang,
// Wang & Kim, "An algebraic condition for the separation of two
// ellipsoids", CAGD 18(6), 2001).
//
// An ellipsoid B = t + M E, E = {u : (u1/a)^2 + (u2/b)^2 + (u3/c)^2 <= 1}, is
// {X : X^T Q X <= 0} in homogeneous coordinates X = (x, 1), with
// Q = T^-T D T^-1, T = [M t; 0 1], D = diag(a^-2, b^-2, c^-2, -1). For two
// such matrices A (body 1) and B (body 2), f(lambda) = det(lambda A + B)
// has two distinct positive roots iff the ellipsoids are separated, and a
// positive double root iff they touch from outside; otherwise they overlap.
// (Two unit spheres with centres d apart: f has the roots -1, -1 and the
// roots of lambda^2 - (d^2 - 2) lambda + 1, which are real, positive and
// distinct iff d > 2.)
//
// The roots are -mu for the eigenvalues mu of A^-1 B (det(lambda A + B) =
// det(A) det(lambda I + A^-1 B)), found by Eigen's real eigensolver.
#include <mink/collide.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>

namespace {

Eigen::Matrix4d mkQuadric(const mkBody3 &b)
{
	Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			T(i, j) = b.M.m[i][j];
	T(0, 3) = b.t.x;
	T(1, 3) = b.t.y;
	T(2, 3) = b.t.z;
	Eigen::Vector4d d(1.0 / (b.shape.a * b.shape.a), 1.0 / (b.shape.b * b.shape.b),
		1.0 / (b.shape.c * b.shape.c), -1.0);
	Eigen::Matrix4d Ti = T.inverse();
	return Ti.transpose() * d.asDiagonal() * Ti;
}

// Eigenvalues whose imaginary part is below this fraction of their modulus
// count as real: the eigensolver's backward error is a few ulps of |A^-1 B|,
// and a complex pair this close to the axis is a touching configuration
// within rounding.
constexpr double kRealTol = 1e-9;
// Two positive roots closer than this (relatively) are one double root.
constexpr double kDistinctTol = 1e-9;

} // namespace

extern "C" mkCollide mkCollide_ASC(mkBody3 b1, mkBody3 b2)
{
	mkCollide out;
	out.collide = -1;
	out.residual = NAN;
	out.iterations = -1;
	out.status = -2;
	out.p1 = out.p2 = out.x = mkVec3{ NAN, NAN, NAN };
	if (!mkShape3_IsEllipsoid(b1.shape) || !mkShape3_IsEllipsoid(b2.shape))
		return out;
	Eigen::Matrix4d A = mkQuadric(b1), B = mkQuadric(b2);
	Eigen::Matrix4d P = A.partialPivLu().solve(B);
	Eigen::EigenSolver<Eigen::Matrix4d> es(P, false);
	double pos[4];
	int npos = 0;
	for (int i = 0; i < 4; ++i) {
		std::complex<double> mu = es.eigenvalues()[i];
		double lambda = -mu.real();
		if (std::fabs(mu.imag()) <= kRealTol * std::abs(mu) && lambda > 0.0)
			pos[npos++] = lambda;
	}
	out.status = npos;
	if (npos == 2) {
		double gap = std::fabs(pos[0] - pos[1]) / std::fmax(pos[0], pos[1]);
		out.residual = gap;
		out.collide = gap > kDistinctTol ? 0 : 1;
	} else {
		out.collide = 1;
	}
	return out;
}

extern "C" const char *mkCollide_EigenVersion(void)
{
	static char text[32];
	std::snprintf(text, sizeof text, "%d.%d.%d", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
	return text;
}
