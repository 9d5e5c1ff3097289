/* mink_plan/plan_fcl.h - the same planning queries with the usual
 * alternative to mink's certified checks: FCL 0.7 as OMPL's state validity
 * checker and OMPL's default DiscreteMotionValidator (each motion sampled at
 * OMPL's default resolution, 1 % of the state space's extent). A peer to
 * compare with (the experiment `planning`), not a certified planner: its
 * paths may cut through thin obstacles or corners between samples, and the
 * meshes are inscribed in the curved shapes.
 *
 * Geometry (the declared shapes of the scene):
 *   3D ellipsoids and spheres placed by a rotation: fcl::Ellipsoid (native);
 *   3D superquadrics (and ellipsoids under a non-rigid map): convex meshes
 *     (fcl::Convex, GJK through libccd) of the surface points at res
 *     longitudes x res/2 latitudes plus the poles (mkFclMesh_Superquadric
 *     of mink/fcl_mesh.hpp at res/2 rings: res = 32 gives 1024 triangles);
 *   3D boxes: the convex mesh of their 8 corners (exact, 12 triangles);
 *   3D cylinders: prisms over a regular res-gon inscribed in the circle;
 *   2D bodies: prisms z in [-1, 1] over their outline (boxes: the 4
 *     corners; curved bodies: res boundary points); the robot moves in the
 *     plane z = 0, so prisms overlap exactly when the outlines do.
 * Every mesh is an fcl::Convex (solid: a body inside another collides)
 * whose vertices lie on the declared boundary: the meshes are inside the
 * curved shapes they stand for. */
#ifndef MINK_PLAN_PLAN_FCL_H
#define MINK_PLAN_PLAN_FCL_H

#include "plan.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MK_PLAN_FCL_RES_MIN 8
#define MK_PLAN_FCL_RES_MAX 1024

/* Plan query k of the scene with FCL's collision checks and OMPL's discrete
 * motion check; o->clearance must be 0 (FCL's boolean collision check has
 * no clearance). res: mesh resolution, in [MK_PLAN_FCL_RES_MIN,
 * MK_PLAN_FCL_RES_MAX]. Returns as mkPlan_Solve: 0 with a path (its
 * clearance array is NaN: nothing certified), 1 when none was found in the
 * time, 2 on bad input (start or goal in collision for FCL, a bad res or
 * clearance), 3 on another failure. motions_checked counts the discrete
 * motion checks, states_checked every FCL state check (also those inside
 * motions). */
int mkPlanFcl_Solve(const mkScene *scene, int k, const mkPlanOptions *o, int res, mkPlanPath *out, char *msg,
	size_t msglen);

/* FCL's version string. */
const char *mkPlanFcl_Version(void);

#ifdef __cplusplus
}
#endif

#endif
