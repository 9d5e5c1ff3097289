// plan_internal.h - what the two planning units (plan.cpp: mink's certified
// checks; plan_fcl.cpp: FCL with OMPL's discrete motion check) share: the
// planners by name, the state space of a scene, states as mink poses.
#ifndef MINK_PLAN_INTERNAL_H
#define MINK_PLAN_INTERNAL_H

#include <functional>
#include <map>
#include <string>

#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>

#include "mink_plan/plan.h"

namespace mkplan {

using Factory = std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr &)>;

const std::map<std::string, Factory> &mkPlanners();
// A state as a mink pose: 2D x, y, theta; 3D x, y, z, qw, qx, qy, qz.
void mkPlanToPose(int dim, const ompl::base::State *s, double *p);
void mkPlanFromPose(int dim, const double *p, ompl::base::State *s);
// Writes text into msg and returns code.
int mkPlanFail(int code, char *msg, size_t len, const std::string &text);
// OMPL's random seed: honoured on the first call of the process only (OMPL
// takes a seed only before its first random number).
void mkPlanSeedOnce(unsigned long seed);
// SE(2) or SE(3) with the scene's bounds.
ompl::base::StateSpacePtr mkPlanSpace(const mkScene *scene);
// The path's states into out (count, pose_size, poses; clearance allocated,
// unset); 0 when out of memory.
int mkPlanCopyPath(int dim, ompl::geometric::PathGeometric &path, mkPlanPath *out);

// Plan query pq with o's planner and time on the set-up ss (space, checkers
// set); *seconds: the wall time of the solve. With o->warm, the warm-up
// first (mkPlanOptions), then zero_counts.
ompl::base::PlannerStatus mkPlanRun(ompl::geometric::SimpleSetup &ss, int dim, const mkScenePlanQuery &pq,
	const mkPlanOptions *o, double *seconds, const std::function<void()> &zero_counts);
// "query k (lines ...): no path found by PLANNER<with> in T s (status)"; returns 1.
int mkPlanNoPath(int k, const mkScenePlanQuery &pq, const mkPlanOptions *o, const char *with,
	ompl::base::PlannerStatus st, char *msg, size_t len);

}  // namespace mkplan

#endif
