/* mink/scenequery.h - a robot (one body or several parts) at given poses
 * against a scene's obstacles: free / colliding, the nearest obstacle and a
 * certified lower bound of the clearance, per pose, on every core.
 *
 * A pose is 2D (x, y, theta): the robot's position and heading; 3D
 * (x, y, z, qw, qx, qy, qz): its position and orientation as a quaternion
 * (normalised here). Part j of the robot (mink/scene.h) is then the body
 * c + R t_j + R M_j B_j.
 *
 * Broad phase: a bounding volume hierarchy of eight children per node over
 * the obstacles' exact axis-aligned boxes (from the closed-form support
 * function at +-e_i), built once by median splits, its boxes rounded
 * outwards to floats and tested four at a time. Each part tests it with
 * the sphere about its centre that holds it at every rotation
 * (precomputed) and, once the sphere does not settle it, its exact box at
 * the pose: walked nearest child first, pruning every child no nearer than
 * the best clearance found; with a finite max_clearance, by box queries
 * instead (every obstacle whose box comes within the cap of the part's,
 * in no order: the cap prunes as well as a best clearance would; an
 * obstacle whose centre is farther from the part's than their two radii
 * and the cap is set aside at once). Narrow
 * phase: the candidates, 8 at a time in the walk's order: quick
 * certificates first (a support-function bound along the centre line,
 * then, where no overlap is certified, along the normal of the sum of the
 * bodies' semi-axes' ellipsoids and a box-like obstacle's face normals; a
 * common point of two smooth bodies on the centre segment, by their
 * gauges; a superquadric's norms bounded first without powers), then mkCollide3_Batch on the rest (clearance mode, delta = the
 * clearance found so far; status mode while none is known; with a finite
 * max_clearance, one call for the pairs of up to 16 poses of a task, each
 * pose resumed from its pairs' answers, which are those each pair gets
 * alone): a pair
 * certified at least that far is set aside, a pair whose overlap is
 * certified is colliding (for boxes and cylinders: the batch's status on
 * the inner models certifies it), and every other pair gets
 * mkCollide3_Normal on the pair when the part's walk is over, lowest
 * certified lower bound first (2D bodies
 * enter as superquadrics whose z = 0 section is the superellipse, eps1 = 1:
 * both are symmetric about z = 0, so the distance of separated pairs is the
 * 2D distance, and overlapping sections overlap in 3D).
 *
 * Certificates (the declared shapes): a box or cylinder is replaced by its
 * outer model (which contains it, mink/scene.h) to certify freedom and by
 * its inner model (inside it) to certify contact. A pair is
 *  - free when the support-function bound f(n) of the outer models at the
 *    solver's answer, less a rounding allowance of 1e-12 of the pair's size,
 *    is positive: it is then a lower bound of the pair's distance;
 *  - colliding when the inner models (the declared shapes for smooth
 *    bodies) overlap for certain: a point of both bodies (the quick
 *    certificate's or the batch's) with balls inside each whose radii add
 *    to more than 4e-12 of the pair's size (a lower bound of the depth), a
 *    point inside both (the centres,
 *    their midpoint or the solver's witnesses' midpoint, by the implicit
 *    functions with a margin of 1e-9), or the solver's certified bracket
 *    of their signed distance below minus the allowance;
 *  - uncertain otherwise (touching within the allowance and the model
 *    error, or a solver that did not converge), never reported free.
 * A pose is colliding when some pair is (the search stops at the first
 * colliding pair found), else uncertain when some pair is, else free, with
 * clearance the smallest lower bound over all pairs, capped at
 * max_clearance.
 *
 * Threads: poses are independent; each is computed the same way by
 * whichever thread, so the answers do not depend on the thread count.
 * Memory: mkSceneQuery_Create allocates the prepared query
 * (mkSceneQuery_Destroy); the answers go into the caller's array. */
#ifndef MINK_SCENEQUERY_H
#define MINK_SCENEQUERY_H

#include "scene.h"

MK_EXTERN_C_BEGIN

typedef enum mkPoseStatus {
	MK_POSE_FREE = 0,
	MK_POSE_COLLIDING = 1,
	MK_POSE_UNCERTAIN = 2
} mkPoseStatus;

/* "free", "colliding", "uncertain". */
MK_API const char *mkPoseStatus_Name(mkPoseStatus s);

typedef struct mkSceneQueryOptions {
	int threads;          /* >= 1 */
	double model_rel;     /* boxes and cylinders: model error as a fraction of the body's reach, in [1e-6, 0.1] */
	double max_clearance; /* > 0: clearances beyond it are reported as max_clearance (INFINITY: exact nearest) */
	double clearance_rel; /* in [0, 0.5]: 0, the clearance is the one-pair query's certified lower bound (exact to
	                       * about 1e-12 of the pair's size); > 0, a certified lower bound within this fraction of
	                       * it, from the batch's brackets (mkCollide3_BatchBracket) where they suffice, the one-pair
	                       * query elsewhere: what a motion check needs, much sooner near box-like bodies. The
	                       * statuses are the same. */
} mkSceneQueryOptions;

/* 1 thread, model_rel 1e-4, max_clearance INFINITY, clearance_rel 0. */
MK_API mkSceneQueryOptions mkSceneQueryOptions_Default(void);

typedef struct mkPoseAnswer {
	mkPoseStatus status;
	int obstacle;     /* free: the nearest obstacle; colliding: one in contact; -1: none nearer than max_clearance */
	int part;         /* the robot part of that pair; -1 with obstacle */
	double clearance; /* free: certified lower bound of the distance from the robot to every obstacle (capped);
	                   * colliding: an upper bound of that pair's signed distance (<= 0): minus a certified lower
	                   * bound of its depth, 0 when only a common point certifies the contact; uncertain: the
	                   * smallest lower bound found (<= 0, -inf when a solver failed; with a finite max_clearance,
	                   * a pair whose outer models overlap and whose inner ones are apart for certain takes the
	                   * inner models' lower bound less their model errors, with no one-pair query) */
	int pairs;        /* narrow-phase pairs computed (batch screen or one-pair query) */
} mkPoseAnswer;

typedef struct mkSceneQuery mkSceneQuery;

/* Prepare the scene's obstacles (models, boxes, hierarchy) and robot parts.
 * The scene must outlive the query. Fails with MK_ERR_ARGUMENT on bad
 * options (message names the field and range), MK_ERR_RANGE when a model
 * cannot be made ("obstacle I: ..."), MK_ERR_MEMORY. */
MK_API mkResult mkSceneQuery_Create(const mkScene *scene, const mkSceneQueryOptions *opt, mkSceneQuery **out,
	char *msg, size_t msglen);
MK_API void mkSceneQuery_Destroy(mkSceneQuery *q);

/* Values per pose: 3 in 2D (x, y, theta), 7 in 3D (x, y, z, qw, qx, qy, qz). */
MK_API int mkSceneQuery_PoseSize(const mkSceneQuery *q);

/* One pose on the calling thread (no allocation): MK_OK, or MK_ERR_ARGUMENT
 * for a non-finite pose or a zero quaternion. */
MK_API mkResult mkSceneQuery_Pose(const mkSceneQuery *q, const double *pose, mkPoseAnswer *out);

/* n poses (pose k at poses + k * PoseSize) on the options' threads into
 * out[0 .. n). Fails with MK_ERR_ARGUMENT naming the first bad pose. */
MK_API mkResult mkSceneQuery_Run(const mkSceneQuery *q, const double *poses, long n, mkPoseAnswer *out,
	char *msg, size_t msglen);

/* The body of robot part j at a pose (3D form; a 2D part as the
 * superquadric described above) with its inner (bound 0) or outer (1) model:
 * what the narrow phase uses. 0 on a bad pose or part. */
MK_API int mkSceneQuery_PartBody(const mkSceneQuery *q, const double *pose, int j, int bound, mkBody3 *out);
/* Obstacle i's body likewise. */
MK_API int mkSceneQuery_ObstacleBody(const mkSceneQuery *q, int i, int bound, mkBody3 *out);

/* ---- motions -------------------------------------------------------------
 * The motion from pose a to pose b moves the position linearly and the
 * rotation at constant angular velocity along the shorter way (2D: the
 * heading by the wrapped difference in [-pi, pi]; 3D: slerp between the
 * unit quaternions, the nearer of q and -q), as OMPL's SE2 and SE3 state
 * spaces interpolate. Pose a(t), t in [0, 1]. */
MK_API void mkSceneQuery_Interpolate(const mkSceneQuery *q, const double *a, const double *b, double t, double *out);

/* An upper bound of the distance of every robot point from the robot's
 * origin (over the parts' outer models). */
MK_API double mkSceneQuery_RobotRadius(const mkSceneQuery *q);

typedef struct mkMotionAnswer {
	mkPoseStatus status;   /* free: clearance >= margin certified on all of [0, 1]; colliding: a certified
	                        * contact at contact_time; uncertain: neither */
	double clearance;      /* a certified lower bound of the clearance on [0, free_until] */
	double free_until;     /* the motion is certified to keep clearance >= margin on [0, free_until] */
	double contact_time;   /* colliding: the first pose found in contact (the first contact is in
	                        * [free_until, contact_time]); NaN otherwise */
	int obstacle, part;    /* colliding: the pair in contact; otherwise the nearest pair at the last pose */
	int poses;             /* poses checked */
} mkMotionAnswer;

/* Certify the motion a -> b, never by sampling it at a resolution. The
 * bound L = |b_pos - a_pos| + r * angle on how far any robot point moves per
 * unit of t (r = mkSceneQuery_RobotRadius, angle the total rotation) turns
 * a certified clearance c at time t (a lower bound, from the pose query or
 * from the parts' bounding spheres and exact boxes against the obstacles'
 * exact boxes) into an interval around t on which the clearance stays
 * above margin. The
 * motion is first probed for a witness of contact (a point inside a part's
 * and an obstacle's inner models, at up to 64 evenly spaced poses, coarse
 * to fine); then [0, 1], or [0, the witness's time], is covered by
 * bisection, each pose covering (c - margin) / (2 L) on both sides (the
 * clearance stays at least (c + margin) / 2 there); a pose with c - margin
 * at most the stall value below (touching, or left uncertain by the pose
 * query) splits its interval at it for its neighbours to cover, until the
 * interval is too short for any robot point to move more than that value
 * within it. Where that does not
 * cover the motion, conservative advancement from the covered prefix
 * (steps dt = (c(t) - margin) / (2 L)) locates the first contact: it stops
 * when c(t) - margin falls below 1e-9 of the robot's radius plus the
 * motion's length or after max_poses poses; then a pose in contact at t,
 * or among 1000 poses evenly spaced on (t, end] (end the witness's time or
 * 1), makes the motion colliding (a witness, never a certificate of
 * freedom); else mkSceneQuery_MotionTest's coarser cover is tried (it may
 * pass by the pose that stalled this one): free when it certifies the
 * motion free (with its weaker clearance bound), else uncertain. margin >= 0.
 * Returns MK_ERR_ARGUMENT on a bad pose or margin (out->status uncertain). */
MK_API mkResult mkSceneQuery_Motion(const mkSceneQuery *q, const double *a, const double *b, double margin,
	long max_poses, mkMotionAnswer *out);

/* The verdict alone, sooner: the same certificates as mkSceneQuery_Motion
 * (free: clearance > margin certified on all of [0, 1]; colliding: a
 * certified contact at contact_time), but the first witness or colliding
 * pose found ends the check (contact_time is a contact, not the first one;
 * free_until the covered prefix), each pose covers 0.9 (c - margin) / L on
 * both sides (clearance reported: at least margin + (c - margin) / 10), and
 * a stall (as above) ends it as uncertain without the search for contact.
 * What a motion validator of a planner needs. */
MK_API mkResult mkSceneQuery_MotionTest(const mkSceneQuery *q, const double *a, const double *b, double margin,
	long max_poses, mkMotionAnswer *out);

MK_EXTERN_C_END

#endif
