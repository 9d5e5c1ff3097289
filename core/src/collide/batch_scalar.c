/* batch_scalar.c - batch_newton.h one lane at a time in plain doubles: the
 * reference of the vector builds and the lanes of processors without them. */
#include <math.h>
#include <string.h>

#include <mink/mink.h>

#define MK_BX_W 1
typedef double mkBV;
typedef long long mkBM;

static inline mkBV mkB_Load(const double *p) { return *p; }
static inline void mkB_Store(double *p, mkBV v) { *p = v; }
static inline mkBV mkB_Splat(double x) { return x; }
static inline mkBV mkB_Sqrt(mkBV v) { return sqrt(v); }
static inline mkBV mkB_Abs(mkBV v) { return fabs(v); }
static inline mkBV mkB_Sel(mkBM k, mkBV a, mkBV b) { return k ? a : b; }
static inline mkBM mkB_Lt(mkBV a, mkBV b) { return -(mkBM)(a < b); }
static inline mkBM mkB_Le(mkBV a, mkBV b) { return -(mkBM)(a <= b); }
static inline int mkB_Any(mkBM k) { return k != 0; }

#include "collide/batch_newton.h"

void mkBatch_EllipsoidLanesScalar(const mkBatchEllIn *in, mkBatchEllOut *out)
{
	mkBN_Run(in, out);
}
