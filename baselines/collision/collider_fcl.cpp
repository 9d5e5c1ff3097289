// collider_fcl.cpp - FCL 0.7's ellipsoid signed distance (fcl::distance with
// enable_signed_distance and nearest points, GJK/EPA through its libccd
// solver, FCL's default distance tolerance 1e-6). FCL is C++ with Eigen; it
// stays in this one file behind the C entry below. Ellipsoid pairs only
// (FCL has no superquadric).
//
// Debian's libfcl is built with assertions on, and its GJK (libccd
// extension, doSimplex2) and EPA assert on some ellipsoid pairs: abort()
// would end the process. The call is therefore guarded: SIGABRT is caught
// around it and the handler jumps back (sigsetjmp/siglongjmp), the pair is
// reported as a failure (no verdict), and whatever FCL had allocated in that
// call is leaked. Not thread safe; the assertion message still reaches
// stderr.
#include <fcl/fcl.h>

#include <csetjmp>
#include <csignal>
#include <cmath>
#include <cstring>
#include <memory>

#include "colliders_internal.h"

namespace {

fcl::Transform3d mkTransform(const mkBody3 &b)
{
	fcl::Transform3d T = fcl::Transform3d::Identity();
	fcl::Matrix3d R;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			R(i, j) = b.M.m[i][j];
	T.linear() = R;
	T.translation() = fcl::Vector3d(b.t.x, b.t.y, b.t.z);
	return T;
}

bool mkIsRotation(const mkMat3 &M)
{
	// FCL places a shape by a rigid motion only: M must be a rotation.
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			double s = 0.0;
			for (int k = 0; k < 3; ++k)
				s += M.m[k][i] * M.m[k][j];
			if (std::fabs(s - (i == j ? 1.0 : 0.0)) > 1e-12)
				return false;
		}
	return mkMat3_Det(M) > 0.0;
}

sigjmp_buf mkFclJump;

extern "C" void mkFclOnAbort(int)
{
	siglongjmp(mkFclJump, 1);
}

// The query itself; false when FCL asserted. Never inlined, so that its name
// is on the stack of everything allocated inside it (see the suppression).
__attribute__((noinline)) bool mkFclQuery(const mkBody3 &b1, const mkBody3 &b2, fcl::DistanceResultd *res);

mkResult mkRunFcl(mkBody3 b1, mkBody3 b2, mkColliderScratch *, mkCollision3 *out)
{
	if (!mkIsRotation(b1.M) || !mkIsRotation(b2.M))
		return MK_ERR_UNSUPPORTED;
	fcl::DistanceResultd res;
	struct sigaction act, old;
	std::memset(&act, 0, sizeof act);
	act.sa_handler = mkFclOnAbort;
	sigemptyset(&act.sa_mask);
	sigaction(SIGABRT, &act, &old);
	bool ok = false;
	if (sigsetjmp(mkFclJump, 1) == 0)
		ok = mkFclQuery(b1, b2, &res);
	sigaction(SIGABRT, &old, nullptr);
	if (!ok)
		return MK_ERR_CONVERGENCE;
	double d = res.min_distance;
	if (!std::isfinite(d))
		return MK_ERR_CONVERGENCE;
	out->scale = mkCollide3_PairSize(b1, b2);
	out->distance = d;
	out->p1 = mkVec3{ res.nearest_points[0](0), res.nearest_points[0](1), res.nearest_points[0](2) };
	out->p2 = mkVec3{ res.nearest_points[1](0), res.nearest_points[1](1), res.nearest_points[1](2) };
	out->status = mkContact_FromDistance(d, out->scale);
	return MK_OK;
}

#if defined(__SANITIZE_ADDRESS__)
// LeakSanitizer: when FCL asserts, the jump out of mkFclQuery skips the
// destructors of what FCL and this function had allocated for that pair, so
// it leaks by design (544 bytes per asserting pair). The suppressions name
// mkFclQuery, and FCL's GJK objects of the two shapes (createGJKObject),
// whose allocation stacks stop inside libfcl (built without frame pointers)
// before they reach mkFclQuery; FCL frees those objects itself at the end
// of every call that returns. A leak anywhere else is still reported. They
// apply to every program that links this collider.
extern "C" const char *__lsan_default_suppressions();
extern "C" const char *__lsan_default_suppressions()
{
	return "leak:mkFclQuery\n"
	       "leak:fcl::detail::GJKInitializer*createGJKObject\n";
}
#endif

bool mkFclQuery(const mkBody3 &b1, const mkBody3 &b2, fcl::DistanceResultd *res)
{
	auto g1 = std::make_shared<fcl::Ellipsoidd>(b1.shape.a, b1.shape.b, b1.shape.c);
	auto g2 = std::make_shared<fcl::Ellipsoidd>(b2.shape.a, b2.shape.b, b2.shape.c);
	fcl::CollisionObjectd o1(g1, mkTransform(b1)), o2(g2, mkTransform(b2));
	fcl::DistanceRequestd req;
	req.enable_nearest_points = true;
	req.enable_signed_distance = true;
	fcl::distance(&o1, &o2, req, *res);
	return true;
}

const char *mkFclVersion() { return FCL_VERSION; }

} // namespace

extern "C" const mkCollider mkCollider_Fcl = {
	"fcl", "FCL 0.7 ellipsoid signed distance and nearest points (GJK/EPA via its libccd solver)",
	"fcl::distance, enable_signed_distance, enable_nearest_points, distance_tolerance 1e-6, GST_LIBCCD; "
	"bodies placed by rotations only",
	MK_GIVES_STATUS | MK_GIVES_DISTANCE | MK_GIVES_PENETRATION | MK_GIVES_WITNESS, MK_PAIRS_ELLIPSOIDS, 0, nullptr,
	mkRunFcl, mkFclVersion
};
