/* scenecache.h - what the motion checks (scenemotion.c) read from the
 * scene query's set-up (scenequery.c) instead of computing it again for
 * every motion (internal to libmink_cspace). */
#ifndef MINK_CSPACE_SCENECACHE_H
#define MINK_CSPACE_SCENECACHE_H

#include "mink/scenequery.h"

/* An upper bound of body b's distance from its centre in its first dim
 * axes (scenemotion.c). */
double mkSm_BodyRadius(mkBody3 b, int dim);

/* Obstacle i's outer model's exact axis-aligned box (3D form), as the set-up
 * computed it. */
void mkSq_ObstacleBox(const mkSceneQuery *q, int i, double lo[3], double hi[3]);

/* mkSm_BodyRadius of part j's outer model, as the set-up computed it. */
double mkSq_PartRadius(const mkSceneQuery *q, int j);

#endif
