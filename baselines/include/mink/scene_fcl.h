/* mink/scene_fcl.h - the peers of mink's scene query (mink/scenequery.h):
 * a robot of parts at a pose against obstacles in FCL 0.7's broad phase
 * (DynamicAABBTreeCollisionManager), yes/no per pose, with one of two
 * narrow phases behind it:
 *  - MK_FCL_NARROW_FCL: FCL's own (fcl::collide, default request) on FCL's
 *    geometry of each body: its native ellipsoid for an ellipsoid placed by
 *    a rotation, else the convex polytope (fcl::Convex) of its surface
 *    mesh (mkFclMesh_Superquadric of mink/fcl_mesh.hpp: mesh_res rings of
 *    2 mesh_res vertices between the poles, 4 mesh_res^2 triangles, every
 *    vertex on the surface: the mesh lies inside the body, so it can miss
 *    contacts);
 *  - MK_FCL_NARROW_CCD: libccd's GJK (the registry's ccd-gjk: exact
 *    support functions) on the exact bodies, the broad phase on FCL
 *    shapes that hold them (the ellipsoid; a box of the semi-axes for a
 *    superquadric placed by a rotation; else a sphere of radius
 *    max(a, b, c) |M|_F).
 * Both stop at the first contact found. Bodies are superquadrics under
 * linear maps (mkBody3); rotations are row-major 3x3 matrices. */
#ifndef MINK_SCENE_FCL_H
#define MINK_SCENE_FCL_H

#include <mink/body.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mkFclScene mkFclScene;

enum { MK_FCL_NARROW_FCL = 0, MK_FCL_NARROW_CCD = 1 };

/* n obstacles (world frame) and a robot of parts bodies (robot frame),
 * mesh_res in [2, 1000], narrow MK_FCL_NARROW_FCL or _CCD. NULL on a bad
 * argument or when out of memory. */
mkFclScene *mkFclScene_Create(int n, const mkBody3 *obstacles, int parts, const mkBody3 *robot, int mesh_res,
	int narrow);
/* As mkFclScene_Create, with obstacle i the box t + M [-h, h] (the M and t
 * of obstacles[i], half sizes h = box_half[3i .. 3i + 2]) wherever
 * box_half[3i] > 0 (box_half may be NULL: no boxes): for
 * MK_FCL_NARROW_FCL its exact mesh (12 triangles, mkFclMesh_Box, as
 * fcl::Convex); for MK_FCL_NARROW_CCD FCL's native fcl::Box (M a rotation)
 * and fcl::collide for the pairs it is in (libccd's GJK inside FCL). */
mkFclScene *mkFclScene_CreateBoxes(int n, const mkBody3 *obstacles, const double *box_half, int parts,
	const mkBody3 *robot, int mesh_res, int narrow);
/* The robot at rotation R (9 values) and position c (3): 1 when a part is found in contact
 * with an obstacle, else 0. */
int mkFclScene_Check(mkFclScene *s, const double *R, const double *c);
/* Triangles of FCL's meshes (obstacles and parts), for the record. */
long mkFclScene_Triangles(const mkFclScene *s);
void mkFclScene_Destroy(mkFclScene *s);

#ifdef __cplusplus
}
#endif

#endif
