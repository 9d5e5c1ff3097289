/* mink/mink.h - the public C interface of the pure library, libmink: bodies,
 * SPEC strings, the closed-form sums, metrics, the method interface and the
 * collision queries. It never allocates and starts no threads. Scenes and
 * certified C-obstacles are the C-space library's: mink/cspace.h. */
#ifndef MINK_MINK_H
#define MINK_MINK_H

#include "base.h"
#include "geom.h"
#include "body.h"
#include "sum.h"
#include "metrics.h"
#include "spec.h"
#include "method.h"
#include "collision.h"
#include "batch.h"

#endif
