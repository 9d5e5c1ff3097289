/* registry_internal.h - what the method files give the table in
 * registry.c: each family's run and accept functions, with the family's
 * parameter (which closed form, which hull library) as an argument, and the
 * pieces the families share. The table binds the parameter per entry. */
#ifndef MINK_REGISTRY_INTERNAL_H
#define MINK_REGISTRY_INTERNAL_H

#include <stddef.h>
#include <mink/mink.h>

/* mkAcceptAny2/3 and mkRefuse, which every method uses, are public
 * (mink/registry.h). */

/* Body 1's surface parameters, the ones every method that is not sampled
 * answers at (mink/registry.h): the n unit vectors of mkSample2_Angles, or
 * the n*n of mkSample3_Grid, structure-of-arrays in *u (allocated here,
 * freed by the caller with free, NULL on failure), and out resized to as
 * many points. Returns MK_ERR_MEMORY, or the sampler's or the resize's
 * error. (closed.c) */
mkResult mkSurface2_Params(int n, mkPointSet *out, double **u);
mkResult mkSurface3_Params(int n, mkPointSet *out, double **u);

/* The core's closed forms in form `form`, one point per surface parameter.
 * (closed.c) */
mkResult mkClosed2_Run(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out, mkForm form, mkPrecision prec);
mkResult mkClosed3_Run(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out, mkForm form, mkPrecision prec);

/* The geometric formula (body 2 an ellipse / ellipsoid). (geometric.c) */
int mkGeometric2_Accepts(mkBody2 b1, mkBody2 b2, mkSet set, char *msg, size_t msglen);
int mkGeometric3_Accepts(mkBody3 b1, mkBody3 b2, mkSet set, char *msg, size_t msglen);
mkResult mkGeometric2_Run(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out);
mkResult mkGeometric3_Run(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out);

/* The convex hull, by `hull`, of all pairwise sums of n samples per body
 * (3D: n x n grids), and edge sorting. (sampled.c) */
typedef mkResult (*mkHullFn)(const double *pts, int count, mkPointSet *out);
mkResult mkHullSums2_Run(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out, mkHullFn hull);
mkResult mkHullSums3_Run(mkBody3 b1, mkBody3 b2, mkSet set, int n, mkPointSet *out, mkHullFn hull);
mkResult mkEdgeSort2_Run(mkBody2 b1, mkBody2 b2, mkSet set, int n, mkPointSet *out);

#endif
