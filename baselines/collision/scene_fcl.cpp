// scene_fcl.cpp - FCL 0.7's broad phase (DynamicAABBTreeCollisionManager) and
// narrow phase over ellipsoids, behind plain C functions (mink/scene_fcl.h): the
// peer of mink's scene query in the scene-check benchmark.
#include "mink/scene_fcl.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/fcl.h>

#include <memory>
#include <new>
#include <vector>

struct mkFclScene {
	std::vector<std::shared_ptr<fcl::CollisionObjectd>> obstacles;
	fcl::DynamicAABBTreeCollisionManagerd manager;
	std::vector<std::shared_ptr<fcl::Ellipsoidd>> parts;
};

namespace {

fcl::Transform3d mkFclPlace(const double R[9], const double t[3])
{
	fcl::Transform3d T = fcl::Transform3d::Identity();
	fcl::Matrix3d M;
	for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = R[i];
	T.linear() = M;
	T.translation() = fcl::Vector3d(t[0], t[1], t[2]);
	return T;
}

// The broad phase's callback: the pair's narrow phase, stopping at the first contact.
bool mkFclOnPair(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *data)
{
	bool *hit = static_cast<bool *>(data);
	fcl::CollisionRequestd req;
	fcl::CollisionResultd res;
	fcl::collide(o1, o2, req, res);
	if (res.isCollision()) *hit = true;
	return *hit;
}

} // namespace

extern "C" mkFclScene *mkFclScene_Create(int n, const double *axes, const double *rot, const double *pos, int parts,
	const double *part_axes)
{
	mkFclScene *s = new (std::nothrow) mkFclScene;
	if (!s) return nullptr;
	std::vector<fcl::CollisionObjectd *> objs;
	for (int i = 0; i < n; ++i) {
		auto e = std::make_shared<fcl::Ellipsoidd>(axes[3 * i], axes[3 * i + 1], axes[3 * i + 2]);
		auto o = std::make_shared<fcl::CollisionObjectd>(e, mkFclPlace(rot + 9 * i, pos + 3 * i));
		o->computeAABB();
		s->obstacles.push_back(o);
		objs.push_back(o.get());
	}
	s->manager.registerObjects(objs);
	s->manager.setup();
	for (int j = 0; j < parts; ++j)
		s->parts.push_back(std::make_shared<fcl::Ellipsoidd>(part_axes[3 * j], part_axes[3 * j + 1], part_axes[3 * j + 2]));
	return s;
}

extern "C" int mkFclScene_Check(mkFclScene *s, const double *rot, const double *pos)
{
	bool hit = false;
	for (size_t j = 0; j < s->parts.size() && !hit; ++j) {
		fcl::CollisionObjectd o(s->parts[j], mkFclPlace(rot + 9 * j, pos + 3 * j));
		o.computeAABB();
		s->manager.collide(&o, &hit, mkFclOnPair);
	}
	return hit ? 1 : 0;
}

extern "C" void mkFclScene_Destroy(mkFclScene *s) { delete s; }
