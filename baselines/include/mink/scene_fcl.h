/* mink/scene_fcl.h - FCL 0.7's scene check on ellipsoids (the peer of
 * mink's scene query): obstacles in FCL's DynamicAABBTreeCollisionManager,
 * a robot of ellipsoid parts, yes/no per pose from FCL's broad phase and its
 * ellipsoid narrow phase (fcl::collide, default request). Rotations are
 * row-major 3x3 matrices, one per body. */
#ifndef MINK_SCENE_FCL_H
#define MINK_SCENE_FCL_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mkFclScene mkFclScene;

/* n obstacles (semi-axes axes[3i..3i+2], rotation rot[9i..], centre
 * pos[3i..]) and a robot of parts ellipsoids (semi-axes part_axes[3j..]).
 * NULL when out of memory. */
mkFclScene *mkFclScene_Create(int n, const double *axes, const double *rot, const double *pos, int parts,
	const double *part_axes);
/* The robot with part j at rot[9j..], pos[3j..] (world frame): 1 when FCL
 * finds a part in contact with an obstacle, else 0. */
int mkFclScene_Check(mkFclScene *s, const double *rot, const double *pos);
void mkFclScene_Destroy(mkFclScene *s);

#ifdef __cplusplus
}
#endif

#endif
