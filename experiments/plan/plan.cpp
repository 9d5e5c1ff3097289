// plan.cpp - OMPL's geometric planners on a mink scene (mink_plan/plan.h):
// SE(2) or SE(3) with the scene's bounds, mink's scene query as the state
// validity checker, and its certified motion test (mkSceneQuery_MotionTest)
// as the motion validator: a motion is valid only when certified free with
// the asked clearance, never by sampling it at a resolution.
#include "mink_plan/plan.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "plan_internal.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mkplan {

const std::map<std::string, Factory> &mkPlanners()
{
	static const std::map<std::string, Factory> planners = {
		{"RRTConnect", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::RRTConnect>(si); }},
		{"RRT", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::RRT>(si); }},
		{"RRTstar", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::RRTstar>(si); }},
		{"PRM", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::PRM>(si); }},
		{"PRMstar", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::PRMstar>(si); }},
		{"LazyPRM", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::LazyPRM>(si); }},
		{"KPIECE1", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::KPIECE1>(si); }},
		{"BKPIECE1", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::BKPIECE1>(si); }},
		{"BITstar", [](const ob::SpaceInformationPtr &si) { return std::make_shared<og::BITstar>(si); }},
	};
	return planners;
}

// A state as a mink pose: 2D x, y, theta; 3D x, y, z, qw, qx, qy, qz.
void mkPlanToPose(int dim, const ob::State *s, double *p)
{
	if (dim == 2) {
		const auto *st = s->as<ob::SE2StateSpace::StateType>();
		p[0] = st->getX(); p[1] = st->getY(); p[2] = st->getYaw();
		return;
	}
	const auto *st = s->as<ob::SE3StateSpace::StateType>();
	const auto &r = st->rotation();
	p[0] = st->getX(); p[1] = st->getY(); p[2] = st->getZ();
	p[3] = r.w; p[4] = r.x; p[5] = r.y; p[6] = r.z;
}

void mkPlanFromPose(int dim, const double *p, ob::State *s)
{
	if (dim == 2) {
		auto *st = s->as<ob::SE2StateSpace::StateType>();
		st->setXY(p[0], p[1]);
		st->setYaw(p[2]);
		return;
	}
	auto *st = s->as<ob::SE3StateSpace::StateType>();
	st->setXYZ(p[0], p[1], p[2]);
	double n = std::sqrt(p[3] * p[3] + p[4] * p[4] + p[5] * p[5] + p[6] * p[6]);
	auto &r = st->rotation();
	r.w = p[3] / n; r.x = p[4] / n; r.y = p[5] / n; r.z = p[6] / n;
}

int mkPlanFail(int code, char *msg, size_t len, const std::string &text)
{
	if (msg && len) std::snprintf(msg, len, "%s", text.c_str());
	return code;
}

void mkPlanSeedOnce(unsigned long seed)
{
	static bool seeded = false;   // OMPL takes a seed only before its first random number
	if (!seeded) { ompl::RNG::setSeed(seed); seeded = true; }
}

ob::StateSpacePtr mkPlanSpace(const mkScene *scene)
{
	int dim = scene->dim;
	ob::RealVectorBounds bounds(dim);
	for (int d = 0; d < dim; ++d) { bounds.setLow(d, scene->bounds_lo[d]); bounds.setHigh(d, scene->bounds_hi[d]); }
	if (dim == 2) { auto s = std::make_shared<ob::SE2StateSpace>(); s->setBounds(bounds); return s; }
	auto s = std::make_shared<ob::SE3StateSpace>();
	s->setBounds(bounds);
	return s;
}

int mkPlanCopyPath(int dim, og::PathGeometric &path, mkPlanPath *out)
{
	int n = (int)path.getStateCount(), ps = dim == 2 ? 3 : 7;
	out->count = n;
	out->pose_size = ps;
	out->poses = static_cast<double *>(std::malloc((size_t)n * ps * sizeof(double) + 1));
	out->clearance = static_cast<double *>(std::malloc((size_t)n * sizeof(double) + 1));
	if (!out->poses || !out->clearance) return 0;
	for (int i = 0; i < n; ++i) mkPlanToPose(dim, path.getState(i), out->poses + (size_t)i * ps);
	return 1;
}

ob::PlannerStatus mkPlanRun(og::SimpleSetup &ss, int dim, const mkScenePlanQuery &pq, const mkPlanOptions *o,
	double *seconds, const std::function<void()> &zero_counts)
{
	auto space = ss.getStateSpace();
	ob::ScopedState<> start(space), goal(space);
	mkPlanFromPose(dim, pq.start, start.get());
	mkPlanFromPose(dim, pq.goal, goal.get());
	ss.setStartAndGoalStates(start, goal);
	ss.setPlanner(mkPlanners().at(o->planner)(ss.getSpaceInformation()));
	ss.setup();
	if (o->warm) {
		// The same for every checker and planner: the checks' code and data paged in, a thread's stack and
		// malloc arena, which glibc keeps for the next thread (PRM's search thread), and the unwinder's tables
		// (PRM's search ends by throwing).
		auto si = ss.getSpaceInformation();
		si->isValid(start.get());
		si->checkMotion(start.get(), goal.get());
		std::thread([] { std::free(std::malloc(64)); }).join();
		try { throw std::runtime_error("warm"); } catch (const std::exception &) {}
		zero_counts();
	}
	// The budget checked by reading the clock at each check: OMPL's solve(seconds) checks budgets of
	// a second or more from a thread it starts for each solve, and that thread's start and join
	// added up to 2 ms to a solve of a few motions, with either checker.
	auto t0 = std::chrono::steady_clock::now();
	ob::PlannerStatus st = ss.solve(ob::timedPlannerTerminationCondition(o->time));
	*seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return st;
}

int mkPlanNoPath(int k, const mkScenePlanQuery &pq, const mkPlanOptions *o, const char *with, ob::PlannerStatus st,
	char *msg, size_t len)
{
	char buf[256];
	std::snprintf(buf, sizeof buf, "query %d (lines %d-%d): no path found by %s%s in %g s (%s)", k, pq.start_line,
		pq.goal_line, o->planner, with, o->time, st.asString().c_str());
	return mkPlanFail(1, msg, len, buf);
}

}  // namespace mkplan

using namespace mkplan;

namespace {

constexpr long kMaxPoses = 1000000;  // poses per certified motion at most

struct mkPlanCounts { long states = 0, motions = 0; };

class mkPlanValidity : public ob::StateValidityChecker {
public:
	mkPlanValidity(const ob::SpaceInformationPtr &si, const mkSceneQuery *q, int dim, double margin, mkPlanCounts *n)
		: ob::StateValidityChecker(si), q_(q), dim_(dim), margin_(margin), n_(n) {}
	bool isValid(const ob::State *s) const override
	{
		double p[7];
		mkPlanToPose(dim_, s, p);
		mkPoseAnswer a;
		++n_->states;
		return mkSceneQuery_Pose(q_, p, &a) == MK_OK && a.status == MK_POSE_FREE && a.clearance >= margin_;
	}
private:
	const mkSceneQuery *q_;
	int dim_;
	double margin_;
	mkPlanCounts *n_;
};

// The certified motion check: valid only when mkSceneQuery_MotionTest says free.
class mkPlanMotion : public ob::MotionValidator {
public:
	mkPlanMotion(const ob::SpaceInformationPtr &si, const mkSceneQuery *q, int dim, double margin, mkPlanCounts *n)
		: ob::MotionValidator(si), q_(q), dim_(dim), margin_(margin), n_(n) {}
	bool checkMotion(const ob::State *s1, const ob::State *s2) const override
	{
		mkMotionAnswer m;
		return run(s1, s2, &m);
	}
	bool checkMotion(const ob::State *s1, const ob::State *s2, std::pair<ob::State *, double> &last) const override
	{
		mkMotionAnswer m;
		if (run(s1, s2, &m)) return true;
		if (last.first) si_->getStateSpace()->interpolate(s1, s2, m.free_until, last.first);
		last.second = m.free_until;
		return false;
	}
private:
	bool run(const ob::State *s1, const ob::State *s2, mkMotionAnswer *m) const
	{
		double a[7], b[7];
		mkPlanToPose(dim_, s1, a);
		mkPlanToPose(dim_, s2, b);
		++n_->motions;
		bool ok = mkSceneQuery_MotionTest(q_, a, b, margin_, kMaxPoses, m) == MK_OK && m->status == MK_POSE_FREE;
		return ok;
	}
	const mkSceneQuery *q_;
	int dim_;
	double margin_;
	mkPlanCounts *n_;
};

// Start or goal: in collision or too close is bad input, named by its line.
int mkPlanCheckEnd(const mkSceneQuery *q, const double *p, const char *what, int line, double margin, char *msg,
	size_t len)
{
	mkPoseAnswer a;
	mkSceneQuery_Pose(q, p, &a);
	if (a.status == MK_POSE_FREE && a.clearance >= margin) return 0;
	char buf[512];
	if (a.status == MK_POSE_FREE)
		std::snprintf(buf, sizeof buf, "line %d: %s: certified clearance %.6g is below --clearance %.6g (nearest: "
			"obstacle %d, robot part %d)", line, what, a.clearance, margin, a.obstacle, a.part);
	else
		std::snprintf(buf, sizeof buf, "line %d: %s is %s: obstacle %d, robot part %d", line, what,
			a.status == MK_POSE_COLLIDING ? "in collision" : "not certified free (touching or uncertain)", a.obstacle,
			a.part);
	return mkPlanFail(2, msg, len, buf);
}

}  // namespace

extern "C" {

mkPlanOptions mkPlanOptions_Default(void)
{
	mkPlanOptions o;
	o.planner = "RRTConnect";
	o.time = 1.0;
	o.seed = 1;
	o.clearance = 0.0;
	o.simplify = 1;
	o.warm = 0;
	return o;
}

const char *mkPlan_PlannerNames(void)
{
	static std::string names;
	if (names.empty())
		for (const auto &p : mkPlanners()) names += (names.empty() ? "" : ", ") + p.first;
	return names.c_str();
}

int mkPlan_PlannerKnown(const char *name) { return name && mkPlanners().count(name) ? 1 : 0; }

void mkPlanPath_Free(mkPlanPath *p)
{
	if (!p) return;
	std::free(p->poses);
	std::free(p->clearance);
	std::memset(p, 0, sizeof *p);
}

int mkPlan_Solve(const mkScene *scene, const mkSceneQuery *q, int k, const mkPlanOptions *o, mkPlanPath *out,
	char *msg, size_t msglen)
{
	std::memset(out, 0, sizeof *out);
	if (!scene || !q || !o || k < 0 || k >= scene->query_count) return mkPlanFail(2, msg, msglen, "no such query");
	if (!scene->bounds_line) return mkPlanFail(2, msg, msglen, "the scene has no 'bounds' line: planning needs them");
	if (!mkPlan_PlannerKnown(o->planner))
		return mkPlanFail(2, msg, msglen, std::string("unknown planner '") + (o->planner ? o->planner : "") +
			"': must be one of " + mkPlan_PlannerNames());
	const mkScenePlanQuery &pq = scene->queries[k];
	int dim = scene->dim, ps = dim == 2 ? 3 : 7;
	int bad = mkPlanCheckEnd(q, pq.start, "start", pq.start_line, o->clearance, msg, msglen);
	if (!bad) bad = mkPlanCheckEnd(q, pq.goal, "goal", pq.goal_line, o->clearance, msg, msglen);
	if (bad) return bad;
	ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
	mkPlanSeedOnce(o->seed);
	ob::StateSpacePtr space = mkPlanSpace(scene);
	og::SimpleSetup ss(space);
	auto si = ss.getSpaceInformation();
	mkPlanCounts counts;
	ss.setStateValidityChecker(std::make_shared<mkPlanValidity>(si, q, dim, o->clearance, &counts));
	si->setMotionValidator(std::make_shared<mkPlanMotion>(si, q, dim, o->clearance, &counts));
	ob::PlannerStatus st = mkPlanRun(ss, dim, pq, o, &out->seconds, [&counts] { counts = mkPlanCounts(); });
	out->states_checked = counts.states;
	out->motions_checked = counts.motions;
	if (st != ob::PlannerStatus::EXACT_SOLUTION) return mkPlanNoPath(k, pq, o, "", st, msg, msglen);
	if (o->simplify) ss.simplifySolution();
	og::PathGeometric &path = ss.getSolutionPath();
	if (!mkPlanCopyPath(dim, path, out)) { mkPlanPath_Free(out); return mkPlanFail(3, msg, msglen, "out of memory"); }
	int n = out->count;
	for (int i = 0; i + 1 < n; ++i) {
		mkMotionAnswer m;
		mkSceneQuery_Motion(q, out->poses + (size_t)i * ps, out->poses + (size_t)(i + 1) * ps, o->clearance, kMaxPoses, &m);
		if (m.status != MK_POSE_FREE) {
			mkPlanPath_Free(out);
			return mkPlanFail(3, msg, msglen, "internal: a segment of the returned path is not certified free");
		}
		out->clearance[i] = m.clearance;
	}
	return 0;
}

}  // extern "C"
