/* mink/cspace.h - the public C interface of the C-space library,
 * libmink_cspace, on top of libmink (mink/mink.h): scenes (scene files,
 * boxes, cylinders) and certified C-obstacles. It allocates what it returns
 * and runs its work on POSIX threads. */
#ifndef MINK_CSPACE_H
#define MINK_CSPACE_H

#include "mink.h"
#include "scene.h"
#include "cobstacle.h"
#include "scenequery.h"

#endif
