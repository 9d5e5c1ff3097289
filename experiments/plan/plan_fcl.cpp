// plan_fcl.cpp - OMPL's planners with FCL 0.7 as the state validity checker
// and OMPL's default DiscreteMotionValidator (mink_plan/plan_fcl.h): the
// peer of mink's certified checks in the experiment `planning`.
#include "mink_plan/plan_fcl.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <fcl/fcl.h>
#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>

#include <mink/fcl_mesh.hpp>

#include "plan_internal.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace mkplan;

namespace {

using Geometry = std::shared_ptr<fcl::CollisionGeometryd>;

// A body as FCL geometry with its pose: in world coordinates for an
// obstacle, in the robot's frame for a part.
struct mkFclBody {
	Geometry geometry;
	fcl::Transform3d pose = fcl::Transform3d::Identity();
};

bool mkFclIsRotation(const mkMat3 &M)
{
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			double s = 0.0;
			for (int k = 0; k < 3; ++k) s += M.m[k][i] * M.m[k][j];
			if (std::fabs(s - (i == j ? 1.0 : 0.0)) > 1e-12) return false;
		}
	return mkMat3_Det(M) > 0.0;
}

fcl::Vector3d mkFclVec(mkVec3 p) { return fcl::Vector3d(p.x, p.y, p.z); }

mkFclBody mkFclBody3(const mkSceneBody &sb, int res)
{
	const mkBody3 &b = sb.spec.body3;
	mkFclBody out;
	if (sb.kind == MK_SCENE_SMOOTH && mkShape3_IsEllipsoid(b.shape) && mkFclIsRotation(b.M)) {
		out.geometry = std::make_shared<fcl::Ellipsoidd>(b.shape.a, b.shape.b, b.shape.c);
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j) out.pose.linear()(i, j) = b.M.m[i][j];
		out.pose.translation() = mkFclVec(b.t);
		return out;
	}
	// res longitudes on res/2 rings (mink/fcl_mesh.hpp)
	if (sb.kind == MK_SCENE_SMOOTH) { out.geometry = mkFclMesh_Convex(mkFclMesh_Superquadric(b, res / 2)); return out; }
	if (sb.kind == MK_SCENE_BOX) {
		mkVec3 h = { sb.size[0] / 2, sb.size[1] / 2, sb.size[2] / 2 };
		out.geometry = mkFclMesh_Convex(mkFclMesh_Box(b.M, b.t, h));
		return out;
	}
	auto map = [&](double x, double y, double z) { return mkFclVec(mkVec3_Add(mkMat3_MulVec(b.M, mkVec3{ x, y, z }), b.t)); };
	std::vector<fcl::Vector3d> ring;
	double r = sb.size[0], h = sb.size[1];
	for (int j = 0; j < res; ++j)
		ring.push_back(map(r * std::cos(2 * M_PI * j / res), r * std::sin(2 * M_PI * j / res), -h / 2));
	out.geometry = mkFclMesh_Convex(mkFclMesh_Prism(ring, map(0, 0, h / 2) - map(0, 0, -h / 2)));
	return out;
}

// 2D: the prism z in [-1, 1] over the outline.
mkFclBody mkFclBody2(const mkSceneBody &sb, int res)
{
	const mkBody2 &b = sb.spec.body2;
	auto map = [&](mkVec2 p) {
		mkVec2 q = mkVec2_Add(mkMat2_MulVec(b.M, p), b.t);
		return fcl::Vector3d(q.x, q.y, -1.0);
	};
	std::vector<fcl::Vector3d> ring;
	if (sb.kind == MK_SCENE_BOX) {
		double l = sb.size[0] / 2, w = sb.size[1] / 2;
		ring = { map(mkVec2{ -l, -w }), map(mkVec2{ l, -w }), map(mkVec2{ l, w }), map(mkVec2{ -l, w }) };
	} else {
		for (int j = 0; j < res; ++j) {
			double a = 2 * M_PI * j / res;
			ring.push_back(map(mkShape2_Point(b.shape, mkVec2{ std::cos(a), std::sin(a) })));
		}
	}
	mkFclBody out;
	out.geometry = mkFclMesh_Convex(mkFclMesh_Prism(ring, fcl::Vector3d(0, 0, 2)));
	return out;
}

struct mkFclWorld {
	int dim = 2;
	std::vector<mkFclBody> parts, obstacles;
	std::vector<std::unique_ptr<fcl::CollisionObjectd>> obstacle_objects;
	mutable long states = 0;

	mkFclWorld(const mkScene *s, int res) : dim(s->dim)
	{
		int np = s->part_count > 0 ? s->part_count : 1;
		for (int j = 0; j < np; ++j) {
			const mkSceneBody &b = s->part_count > 0 ? s->parts[j] : s->robot;
			parts.push_back(dim == 2 ? mkFclBody2(b, res) : mkFclBody3(b, res));
		}
		for (int i = 0; i < s->obstacle_count; ++i) {
			obstacles.push_back(dim == 2 ? mkFclBody2(s->obstacles[i], res) : mkFclBody3(s->obstacles[i], res));
			obstacle_objects.push_back(std::make_unique<fcl::CollisionObjectd>(obstacles.back().geometry,
				obstacles.back().pose));
		}
	}

	// 1 when no part touches any obstacle at the pose.
	bool free(const double *p) const
	{
		++states;
		fcl::Transform3d T = fcl::Transform3d::Identity();
		if (dim == 2) {
			T.linear() = fcl::AngleAxisd(p[2], fcl::Vector3d::UnitZ()).toRotationMatrix();
			T.translation() = fcl::Vector3d(p[0], p[1], 0);
		} else {
			T.linear() = fcl::Quaterniond(p[3], p[4], p[5], p[6]).normalized().toRotationMatrix();
			T.translation() = fcl::Vector3d(p[0], p[1], p[2]);
		}
		fcl::CollisionRequestd req;
		for (const auto &part : parts) {
			fcl::CollisionObjectd robot(part.geometry, T * part.pose);
			for (const auto &o : obstacle_objects) {
				fcl::CollisionResultd res;
				if (fcl::collide(&robot, o.get(), req, res) > 0) return false;
			}
		}
		return true;
	}
};

class mkFclValidity : public ob::StateValidityChecker {
public:
	mkFclValidity(const ob::SpaceInformationPtr &si, const mkFclWorld *w) : ob::StateValidityChecker(si), w_(w) {}
	bool isValid(const ob::State *s) const override
	{
		double p[7];
		mkPlanToPose(w_->dim, s, p);
		return si_->satisfiesBounds(s) && w_->free(p);
	}
private:
	const mkFclWorld *w_;
};

// OMPL's default motion validator, counting its calls.
class mkFclMotion : public ob::DiscreteMotionValidator {
public:
	mkFclMotion(const ob::SpaceInformationPtr &si, long *n) : ob::DiscreteMotionValidator(si), n_(n) {}
	bool checkMotion(const ob::State *s1, const ob::State *s2) const override
	{
		++*n_;
		return ob::DiscreteMotionValidator::checkMotion(s1, s2);
	}
	bool checkMotion(const ob::State *s1, const ob::State *s2, std::pair<ob::State *, double> &last) const override
	{
		++*n_;
		return ob::DiscreteMotionValidator::checkMotion(s1, s2, last);
	}
private:
	long *n_;
};

}  // namespace

extern "C" {

const char *mkPlanFcl_Version(void) { return FCL_VERSION; }

int mkPlanFcl_Solve(const mkScene *scene, int k, const mkPlanOptions *o, int res, mkPlanPath *out, char *msg,
	size_t msglen)
{
	*out = mkPlanPath{};
	if (!scene || !o || k < 0 || k >= scene->query_count) return mkPlanFail(2, msg, msglen, "no such query");
	if (!scene->bounds_line) return mkPlanFail(2, msg, msglen, "the scene has no 'bounds' line: planning needs them");
	if (!mkPlan_PlannerKnown(o->planner))
		return mkPlanFail(2, msg, msglen, std::string("unknown planner '") + (o->planner ? o->planner : "") +
			"': must be one of " + mkPlan_PlannerNames());
	if (res < MK_PLAN_FCL_RES_MIN || res > MK_PLAN_FCL_RES_MAX)
		return mkPlanFail(2, msg, msglen, "res = " + std::to_string(res) + " is out of range: must be in [" +
			std::to_string(MK_PLAN_FCL_RES_MIN) + ", " + std::to_string(MK_PLAN_FCL_RES_MAX) + "]");
	if (o->clearance != 0.0)
		return mkPlanFail(2, msg, msglen, "clearance must be 0 with FCL's boolean collision check");
	const mkScenePlanQuery &pq = scene->queries[k];
	int dim = scene->dim;
	mkFclWorld world(scene, res);
	if (!world.free(pq.start) || !world.free(pq.goal))
		return mkPlanFail(2, msg, msglen, "line " + std::to_string(world.free(pq.start) ? pq.goal_line : pq.start_line) +
			": " + (world.free(pq.start) ? "goal" : "start") + " is in collision for FCL");
	world.states = 0;
	ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
	mkPlanSeedOnce(o->seed);
	ob::StateSpacePtr space = mkPlanSpace(scene);
	og::SimpleSetup ss(space);
	auto si = ss.getSpaceInformation();
	long motions = 0;
	ss.setStateValidityChecker(std::make_shared<mkFclValidity>(si, &world));
	si->setMotionValidator(std::make_shared<mkFclMotion>(si, &motions));
	ob::PlannerStatus st = mkPlanRun(ss, dim, pq, o, &out->seconds, [&] { world.states = 0; motions = 0; });
	out->states_checked = world.states;
	out->motions_checked = motions;
	if (st != ob::PlannerStatus::EXACT_SOLUTION) return mkPlanNoPath(k, pq, o, " with FCL", st, msg, msglen);
	if (o->simplify) ss.simplifySolution();
	if (!mkPlanCopyPath(dim, ss.getSolutionPath(), out)) {
		mkPlanPath_Free(out);
		return mkPlanFail(3, msg, msglen, "out of memory");
	}
	for (int i = 0; i < out->count; ++i) out->clearance[i] = NAN;
	return 0;
}

}  // extern "C"
