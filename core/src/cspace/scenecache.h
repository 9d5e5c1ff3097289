/* scenecache.h - what the motion checks (scenemotion.c) read from the
 * scene query's set-up (scenequery.c) instead of computing it again for
 * every motion (internal to libmink_cspace). */
#ifndef MINK_CSPACE_SCENECACHE_H
#define MINK_CSPACE_SCENECACHE_H

#include "mink/scenequery.h"

/* Obstacle i's outer model's exact axis-aligned box (3D form), as the set-up
 * computed it; 0 when there is no obstacle i. */
int mkSq_ObstacleBox(const mkSceneQuery *q, int i, double lo[3], double hi[3]);

/* An upper bound of part j's outer model's distance from its centre in the
 * scene's dimensions, at any rotation, as the set-up computed it. */
double mkSq_PartRadius(const mkSceneQuery *q, int j);

#endif
