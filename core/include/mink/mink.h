/* mink/mink.h - the whole public C interface of the core library. */
#ifndef MINK_MINK_H
#define MINK_MINK_H

#include "base.h"
#include "geom.h"
#include "body.h"
#include "sum.h"
#include "metrics.h"
#include "spec.h"
#include "method.h"
#include "scene.h"
#include "cobstacle.h"
#include "collision.h"

#endif
