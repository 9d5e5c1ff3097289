// scene_fcl.cpp - the scene query's peers behind plain C functions
// (mink/scene_fcl.h): FCL 0.7's DynamicAABBTreeCollisionManager with FCL's
// narrow phase (native ellipsoids, meshes of superquadrics) or libccd's GJK
// on the exact bodies.
#include "mink/scene_fcl.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/fcl.h>

#include <cmath>
#include <memory>
#include <new>
#include <stdexcept>
#include <vector>

#include <mink/colliders.h>
#include <mink/fcl_mesh.hpp>

struct mkFclScene {
	int narrow = MK_FCL_NARROW_FCL;
	std::vector<mkBody3> obs, robot, placed;   // exact bodies (the ccd narrow phase)
	std::vector<char> box;                     // obstacle i is a box
	std::vector<std::shared_ptr<fcl::CollisionObjectd>> obstacles, parts;
	std::vector<fcl::Transform3d> rest;   // each part's placement in the robot's frame
	fcl::DynamicAABBTreeCollisionManagerd manager;
	const mkCollider *ccd = nullptr;
	long triangles = 0;
};

namespace {

// The body's M = Q diag(1) with Q a rotation (within 1e-9): Q, else false.
bool mkFclRotation(const mkBody3 &b)
{
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			double g = 0.0;
			for (int k = 0; k < 3; ++k) g += b.M.m[k][i] * b.M.m[k][j];
			if (std::fabs(g - (i == j ? 1.0 : 0.0)) > 1e-9) return false;
		}
	return mkMat3_Det(b.M) > 0.0;
}

fcl::Transform3d mkFclPlace(const mkMat3 &R, const mkVec3 &t)
{
	fcl::Transform3d T = fcl::Transform3d::Identity();
	fcl::Matrix3d M;
	for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = R.m[i / 3][i % 3];
	T.linear() = M;
	T.translation() = fcl::Vector3d(t.x, t.y, t.z);
	return T;
}

// FCL's geometry of b (of the box t + M [-half, half] when half is not
// null) and the transform that places it (b's frame when a mesh or the
// centre's rotation when a shape).
std::shared_ptr<fcl::CollisionObjectd> mkFclObject(const mkBody3 &b, const double *half, mkFclScene *s, int res)
{
	bool rot = mkFclRotation(b), ell = b.shape.eps1 == 1.0 && b.shape.eps2 == 1.0;
	std::shared_ptr<fcl::CollisionGeometryd> g;
	fcl::Transform3d T = mkFclPlace(b.M, b.t);
	if (half && s->narrow == MK_FCL_NARROW_FCL) {
		mkFclMesh m = mkFclMesh_Box(b.M, b.t, mkVec3_Make(half[0], half[1], half[2]));
		s->triangles += (long)m.triangles.size();
		g = mkFclMesh_Convex(m);
		T = fcl::Transform3d::Identity();
	} else if (half) {
		if (!rot) throw std::invalid_argument("a box for FCL's native box must be placed by a rotation");
		g = std::make_shared<fcl::Boxd>(2.0 * half[0], 2.0 * half[1], 2.0 * half[2]);
	} else if (rot && ell) {
		g = std::make_shared<fcl::Ellipsoidd>(b.shape.a, b.shape.b, b.shape.c);
	} else if (s->narrow == MK_FCL_NARROW_FCL) {
		mkFclMesh m = mkFclMesh_Superquadric(b, res);
		s->triangles += (long)m.triangles.size();
		g = mkFclMesh_Convex(m);
		T = fcl::Transform3d::Identity();
	} else if (rot) {
		g = std::make_shared<fcl::Boxd>(2.0 * b.shape.a, 2.0 * b.shape.b, 2.0 * b.shape.c);
	} else {
		double f = 0.0;
		for (int i = 0; i < 9; ++i) f += b.M.m[i / 3][i % 3] * b.M.m[i / 3][i % 3];
		g = std::make_shared<fcl::Sphered>(std::fmax(b.shape.a, std::fmax(b.shape.b, b.shape.c)) * std::sqrt(f));
		T = mkFclPlace(mkMat3_Identity(), b.t);
	}
	auto o = std::make_shared<fcl::CollisionObjectd>(g, T);
	o->computeAABB();
	return o;
}

struct mkFclHit {
	mkFclScene *s;
	bool hit;
};

// The broad phase's callback: the pair's narrow phase, stopping at the
// first contact. Obstacles carry user data 1 + i, parts -(1 + j).
bool mkFclOnPair(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *data)
{
	mkFclHit *h = static_cast<mkFclHit *>(data);
	long u1 = (long)(intptr_t)o1->getUserData(), u2 = (long)(intptr_t)o2->getUserData();
	bool box = (u1 > 0 && h->s->box[u1 - 1]) || (u2 > 0 && h->s->box[u2 - 1]);
	if (h->s->narrow == MK_FCL_NARROW_FCL || box) {
		fcl::CollisionRequestd req;
		fcl::CollisionResultd res;
		fcl::collide(o1, o2, req, res);
		h->hit = h->hit || res.isCollision();
		return h->hit;
	}
	const mkBody3 &a = u1 > 0 ? h->s->obs[u1 - 1] : h->s->placed[-u1 - 1];
	const mkBody3 &b = u2 > 0 ? h->s->obs[u2 - 1] : h->s->placed[-u2 - 1];
	mkColliderScratch scratch;
	mkCollision3 c;
	if (mkCollider_Run(h->s->ccd, a, b, &scratch, &c) == MK_OK && c.status == MK_CONTACT_OVERLAPPING) h->hit = true;
	return h->hit;
}

} // namespace

extern "C" mkFclScene *mkFclScene_Create(int n, const mkBody3 *obstacles, int parts, const mkBody3 *robot, int mesh_res,
	int narrow)
{
	return mkFclScene_CreateBoxes(n, obstacles, nullptr, parts, robot, mesh_res, narrow);
}

extern "C" mkFclScene *mkFclScene_CreateBoxes(int n, const mkBody3 *obstacles, const double *box_half, int parts,
	const mkBody3 *robot, int mesh_res, int narrow)
{
	if (n < 0 || parts < 1 || mesh_res < 2 || mesh_res > 1000 || (narrow != MK_FCL_NARROW_FCL && narrow != MK_FCL_NARROW_CCD))
		return nullptr;
	mkFclScene *s = new (std::nothrow) mkFclScene;
	if (!s) return nullptr;
	try {
		s->narrow = narrow;
		s->ccd = mkColliders_Find("ccd-gjk");
		s->obs.assign(obstacles, obstacles + n);
		s->robot.assign(robot, robot + parts);
		s->placed = s->robot;
		std::vector<fcl::CollisionObjectd *> objs;
		for (int i = 0; i < n; ++i) {
			const double *half = box_half && box_half[3 * i] > 0.0 ? box_half + 3 * i : nullptr;
			s->box.push_back(half != nullptr);
			s->obstacles.push_back(mkFclObject(obstacles[i], half, s, mesh_res));
			s->obstacles.back()->setUserData((void *)(intptr_t)(1 + i));
			objs.push_back(s->obstacles.back().get());
		}
		s->manager.registerObjects(objs);
		s->manager.setup();
		// a part's object in the robot's frame: its own placement, composed
		// with the pose at each check
		for (int j = 0; j < parts; ++j) {
			s->parts.push_back(mkFclObject(robot[j], nullptr, s, mesh_res));
			s->parts.back()->setUserData((void *)(intptr_t)(-(1 + j)));
			s->rest.push_back(s->parts.back()->getTransform());
		}
	} catch (...) {
		delete s;
		return nullptr;
	}
	if (!s->ccd) { delete s; return nullptr; }
	return s;
}

extern "C" int mkFclScene_Check(mkFclScene *s, const double *R, const double *c)
{
	mkMat3 Rm;
	for (int i = 0; i < 9; ++i) Rm.m[i / 3][i % 3] = R[i];
	mkVec3 cv = mkVec3_Make(c[0], c[1], c[2]);
	fcl::Transform3d P = mkFclPlace(Rm, cv);
	mkFclHit h = {s, false};
	for (size_t j = 0; j < s->parts.size() && !h.hit; ++j) {
		const mkBody3 &b = s->robot[j];
		s->placed[j].M = mkMat3_Mul(Rm, b.M);
		s->placed[j].t = mkVec3_Add(cv, mkMat3_MulVec(Rm, b.t));
		fcl::CollisionObjectd &o = *s->parts[j];
		o.setTransform(P * s->rest[j]);
		o.computeAABB();
		s->manager.collide(&o, &h, mkFclOnPair);
	}
	return h.hit ? 1 : 0;
}

extern "C" long mkFclScene_Triangles(const mkFclScene *s) { return s->triangles; }

extern "C" void mkFclScene_Destroy(mkFclScene *s) { delete s; }
