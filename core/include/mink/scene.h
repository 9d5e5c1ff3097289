/* mink/scene.h - a motion-planning scene: one robot, obstacles, the robot's
 * orientations, and the model of each declared body that a tolerance needs.
 *
 * Declared bodies are the SPEC kinds of mink/spec.h plus two that the closed
 * forms cannot take directly:
 *   box size=l,w        (2D)  or  box size=l,w,h  (3D): full side lengths
 *   cylinder r=R h=H    (3D): radius and full height, axis along z
 * with the pose keys of the dimension (2D: rot, shear, M, at; 3D: quat, M,
 * at). A box or cylinder is modelled by a superellipse/superquadric whose
 * exponent comes from the tolerance (mkSceneBody2_Model, mkSceneBody3_Model;
 * derivation in docs/scene.md): inscribed for inner bounds, scaled to
 * enclose the shape for outer ones. Every other kind is its own exact model.
 *
 * The scene file (docs/scene.md):
 *   # comment (anywhere on a line)
 *   dim 2|3                      first line
 *   robot SPEC                   once; its `at` is ignored
 *   part SPEC                    instead of robot: one part of a robot of
 *                                several bodies, placed by its own pose
 *                                (rot/quat/M, at) in the robot's frame
 *   object NAME                  the obstacles that follow form object NAME
 *   obstacle SPEC                any number; index 0, 1, ... in order
 *   headings N | headings a1,a2,...       2D: 2 pi k / N, or these radians
 *   quaternions w,x,y,z;w,x,y,z;...       3D
 *   rotations FILE                        3D: rotations read by the caller
 *   bounds xlo,xhi,ylo,yhi[,zlo,zhi]      planning: the box of the robot's position
 *   start POSE                            planning: the start of the next queries
 *   goal POSE                             planning: a query from the last start to POSE
 * POSE: x,y,theta (2D) or x,y,z,qw,qx,qy,qz (3D). A scene with queries may
 * omit the orientations.
 * The robot at orientation R (2D: the rotation by the heading) is the body
 * whose map is R M, M the robot's own map; a robot of parts at orientation R
 * and position c has part j at c + R t_j with map R M_j (t_j, M_j the part's
 * pose). Its C-obstacles are the union over parts and obstacles of the
 * pairs' C-obstacles O (+) (-R M_j B_j) - R t_j.
 *
 * Memory: mkScene_Parse allocates the obstacle and orientation arrays;
 * mkScene_Free releases them. Nothing else here allocates. */
#ifndef MINK_SCENE_H
#define MINK_SCENE_H

#include <stddef.h>
#include "spec.h"

MK_EXTERN_C_BEGIN

/* Which boundary of a C-obstacle: inner (inside it) or outer (enclosing it). */
typedef enum mkBound { MK_BOUND_INNER = 0, MK_BOUND_OUTER = 1 } mkBound;

typedef enum mkSceneKind {
	MK_SCENE_SMOOTH = 0, /* a SPEC kind: circle ... superquadric (spec.kind) */
	MK_SCENE_BOX = 1,
	MK_SCENE_CYLINDER = 2
} mkSceneKind;

/* Limits of scene input, inclusive. */
#define MK_SCENE_SIZE_MIN (2.0 * MK_AXIS_MIN) /* box sides, cylinder height */
#define MK_SCENE_SIZE_MAX (2.0 * MK_AXIS_MAX)
#define MK_SCENE_HEADINGS_MAX 10000000
#define MK_SCENE_ANGLE_MAX 1e6
#define MK_SCENE_LINE_MAX 65536
#define MK_SCENE_PARTS_MAX 1024
#define MK_SCENE_NAME_MAX 64   /* object names: 1 .. 63 of [A-Za-z0-9_.-] */

typedef struct mkSceneBody {
	int dim;
	mkSceneKind kind;
	/* SMOOTH: the body. BOX/CYLINDER: spec.body2/body3 carry the pose (M, t);
	 * their shape fields are unused. */
	mkSpec spec;
	/* BOX: full side lengths l, w[, h]. CYLINDER: radius, full height. */
	double size[3];
} mkSceneBody;

/* A group of obstacles that form one object (a table of a top and legs). */
typedef struct mkSceneObject {
	char name[MK_SCENE_NAME_MAX];
	int line;   /* the `object` line; 0 for an obstacle that is its own object */
} mkSceneObject;

/* A planning query: start and goal poses (3 or 7 values, mink/scenequery.h)
 * and their lines. */
typedef struct mkScenePlanQuery {
	double start[7], goal[7];
	int start_line, goal_line;
} mkScenePlanQuery;

typedef struct mkScene {
	int dim;
	mkSceneBody robot;   /* parts[0]; from `robot SPEC` as written (its at= unused) */
	/* The robot's parts (part_count >= 1): `robot SPEC` gives one part at
	 * the robot's frame (its at= set to 0), `part SPEC` lines one each,
	 * their at= and map their pose in the robot's frame. A scene built
	 * by hand may leave part_count 0: the robot is then its one part. */
	mkSceneBody *parts;
	int part_count;
	mkSceneBody *obstacles;
	int obstacle_count;
	/* obstacle i belongs to objects[obstacle_object[i]]; an obstacle
	 * before any `object` line is an object of its own, named obstacleI */
	int *obstacle_object;
	mkSceneObject *objects;
	int object_count;
	int orientation_count;
	double *headings;    /* 2D: orientation_count angles (radians) */
	mkMat3 *rotations;   /* 3D: orientation_count rotation matrices */
	/* 3D `rotations FILE`: the file name as written (the caller reads it
	 * with mkScene_SetRotations); empty when the scene lists quaternions. */
	char rotations_file[1024];
	int rotations_line;  /* the line of `rotations FILE`, for messages */
	/* planning: bounds (bounds_line 0: none) and queries */
	double bounds_lo[3], bounds_hi[3];
	int bounds_line;
	mkScenePlanQuery *queries;
	int query_count;
} mkScene;

/* The kind's name: "box", "cylinder" or the SPEC kind's name. */
MK_API const char *mkSceneBody_KindName(const mkSceneBody *b);

/* Parse one body: a SPEC kind, or box/cylinder as above. `what` names it
 * in messages ("obstacle3"). Fails with MK_ERR_ARGUMENT (unknown kind or
 * key, a missing key, a malformed number) or MK_ERR_RANGE (a value out of
 * range) and one line in msg naming the field, the value and the allowed
 * range. */
MK_API mkResult mkSceneBody_Parse(const char *text, int dim, const char *what, mkSceneBody *out,
	char *msg, size_t msglen);

/* The model of a declared body for a model tolerance delta > 0 and a side:
 * SMOOTH bodies are returned as they are, with *error = 0; a box or
 * cylinder becomes a superellipse/superquadric inside it (MK_BOUND_INNER) or
 * containing it (MK_BOUND_OUTER) whose Hausdorff distance to the declared
 * shape (placed by its map) is at most *error <= delta. *error is the
 * derived bound, not a measurement. Fails with MK_ERR_RANGE when delta is
 * too small for the exponent range (eps >= MK_EPS_MIN), with a message, and
 * MK_ERR_ARGUMENT on a dimension mismatch or a bad delta. */
MK_API mkResult mkSceneBody2_Model(const mkSceneBody *b, double delta, mkBound side, mkBody2 *out,
	double *error, char *msg, size_t msglen);
MK_API mkResult mkSceneBody3_Model(const mkSceneBody *b, double delta, mkBound side, mkBody3 *out,
	double *error, char *msg, size_t msglen);

/* Parse a whole scene file's text. On failure returns MK_ERR_ARGUMENT or
 * MK_ERR_RANGE, leaves *out empty (nothing to free) and writes one line
 * "line L: <what is wrong, the field, the allowed range>". A 3D scene with
 * `rotations FILE` has orientation_count 0 until mkScene_SetRotations. */
MK_API mkResult mkScene_Parse(const char *text, mkScene *out, char *msg, size_t msglen);

/* Read the text of a rotations file into a parsed 3D scene: one rotation
 * per line, either 9 numbers r11,r12,...,r33 (row-major) or a quaternion
 * w,x,y,z; a first line that is not numeric is a header; '#' starts a
 * comment. A matrix must be a rotation to 1e-6 (R^T R = I, det R = 1).
 * Messages name `name` and the line. Replaces any orientations. */
MK_API mkResult mkScene_SetRotations(mkScene *scene, const char *text, const char *name,
	char *msg, size_t msglen);

/* Release what mkScene_Parse allocated; safe on a zeroed scene. */
MK_API void mkScene_Free(mkScene *scene);

/* The rotation R_o of orientation o (0 <= o < orientation_count): 2D the
 * rotation by headings[o], 3D rotations[o]. The robot there is its body (or
 * model) with map R_o M. */
MK_API mkMat2 mkScene2_Orientation(const mkScene *scene, int o);
MK_API mkMat3 mkScene3_Orientation(const mkScene *scene, int o);

MK_EXTERN_C_END

#endif
