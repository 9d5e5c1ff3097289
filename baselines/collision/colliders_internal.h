/* colliders_internal.h - the registry entries (one file each) and small
 * helpers they share. Not a public header. */
#ifndef MINK_COLLIDERS_INTERNAL_H
#define MINK_COLLIDERS_INTERNAL_H

#include <mink/collide.h>
#include <mink/colliders.h>

MK_EXTERN_C_BEGIN

extern const mkCollider mkCollider_MinkNormal;
extern const mkCollider mkCollider_MinkRay;
extern const mkCollider mkCollider_MinkNormalLm;
extern const mkCollider mkCollider_MinkRayLm;
extern const mkCollider mkCollider_CommonNormal;
extern const mkCollider mkCollider_Implicit;
extern const mkCollider mkCollider_GjkPoly;
extern const mkCollider mkCollider_CcdGjk;
extern const mkCollider mkCollider_CcdMpr;
extern const mkCollider mkCollider_CcdGjkEpa;
extern const mkCollider mkCollider_CcdGjkEpa6;
extern const mkCollider mkCollider_CcdGjkEpa8;
extern const mkCollider mkCollider_CcdGjkEpa10;
extern const mkCollider mkCollider_Fcl;
extern const mkCollider mkCollider_Asc;
extern const mkCollider mkCollider_AscEigen;
extern const mkCollider mkCollider_Referee;

/* The answer of a legacy query (mink/collide.h) as an mkCollision3:
 * collide 1 -> overlapping (touching is not told apart), 0 -> separated. */
void mkCollision3_FromLegacy(mkCollide c, mkCollision3 *out);

MK_EXTERN_C_END

#endif
