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
 *   obstacle SPEC                any number; index 0, 1, ... in order
 *   headings N | headings a1,a2,...       2D: 2 pi k / N, or these radians
 *   quaternions w,x,y,z;w,x,y,z;...       3D
 *   rotations FILE                        3D: rotations read by the caller
 * The robot at orientation R (2D: the rotation by the heading) is the body
 * whose map is R M, M the robot's own map.
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

typedef struct mkSceneBody {
	int dim;
	mkSceneKind kind;
	/* SMOOTH: the body. BOX/CYLINDER: spec.body2/body3 carry the pose (M, t);
	 * their shape fields are unused. */
	mkSpec spec;
	/* BOX: full side lengths l, w[, h]. CYLINDER: radius, full height. */
	double size[3];
} mkSceneBody;

typedef struct mkScene {
	int dim;
	mkSceneBody robot;
	mkSceneBody *obstacles;
	int obstacle_count;
	int orientation_count;
	double *headings;    /* 2D: orientation_count angles (radians) */
	mkMat3 *rotations;   /* 3D: orientation_count rotation matrices */
	/* 3D `rotations FILE`: the file name as written (the caller reads it
	 * with mkScene_SetRotations); empty when the scene lists quaternions. */
	char rotations_file[1024];
	int rotations_line;  /* the line of `rotations FILE`, for messages */
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
