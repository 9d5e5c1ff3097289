/* sceneprep.h - the scene query's poses prepared side by side (internal to
 * libmink_cspace): for up to MK_SQ_PREP 3D poses at once (a task's), their
 * rotations and, for the robot's first parts, each part's centre and the
 * float box of the sphere that holds it, grown by a bound (the part's query
 * box before any pair is known); the test of the poses' values; and, for a
 * scene of few obstacles, the obstacles near a part by their spheres.
 *
 * The values are those of the one-pose path to the bit (mkMat3_FromQuatInline
 * for the rotation, R t + c for a centre, mkSw_Down / mkSw_Up of centre -+
 * half): the same operations in the same order, lane by lane, with no
 * contraction, so that the loops may run in vector registers. */
#ifndef MINK_CSPACE_SCENEPREP_H
#define MINK_CSPACE_SCENEPREP_H

#include <stdint.h>

#include "mink/geom.h"
#include "mink/sum.h"

#define MK_SQ_PREP 256       /* poses prepared at once, at most */
#define MK_SQ_PREP_PARTS 4   /* parts whose centres and boxes are prepared */
#define MK_SQ_PREP_WORDS 4   /* words of 32 obstacles near a part, at most (a scene of at most 128 obstacles) */

/* 1 when two spheres whose centres are (dx, dy, dz) apart, of radii ra and
 * rb, are certainly more than b apart: the centres farther apart than
 * (ra + rb + b) (1 + 1e-12) (the scene query's test of a part's and an
 * obstacle's spheres, here and in scenequery.c). */
static inline int mkSqPrep_Apart(double dx, double dy, double dz, double ra, double rb, double b)
{
	double r = (ra + rb + b) * (1.0 + 1e-12);
	return dx * dx + dy * dy + dz * dz > r * r;
}

/* The half-width of a part's query box on an axis: the part's exact box's
 * half-width h (0 while it is tested by its sphere), the sphere's reach and
 * the bound b, with a rounding allowance (here and in scenequery.c). */
static inline double mkSqPrep_Half(double h, double reach, double b) { return (h + reach + b) * (1.0 + 1e-12); }

typedef struct mkSqPrep {
	double R[9][MK_SQ_PREP];                      /* row-major rotation, lane by lane */
	double pc[3 * MK_SQ_PREP_PARTS][MK_SQ_PREP];  /* part j's centre: [3 j + axis] */
	float lo[3 * MK_SQ_PREP_PARTS][MK_SQ_PREP], hi[3 * MK_SQ_PREP_PARTS][MK_SQ_PREP];
	double eh[3 * MK_SQ_PREP_PARTS][MK_SQ_PREP];  /* an ellipsoid part's exact box's half-widths (the parts in ell) */
	uint32_t near[MK_SQ_PREP_PARTS][MK_SQ_PREP_WORDS][MK_SQ_PREP];   /* with spheres: the obstacles near part j, word w */
} mkSqPrep;

/* A scene's obstacles' spheres for the test of the obstacles near each
 * prepared part: their centres (x, y, z [i], i < n <= 32 MK_SQ_PREP_WORDS)
 * and part j's squared radii rr[j * stride + i] (mkSqPrep_Radius2). */
typedef struct mkSqPrepSpheres {
	const double *x, *y, *z, *rr;
	int n, stride;
} mkSqPrepSpheres;

/* poses: n <= MK_SQ_PREP poses of 7 values (x, y, z, quaternion w, x, y, z),
 * each with a finite positive squared quaternion norm; the first
 * MK_SQ_PREP_PARTS of the parts, with their centres t[j] in the robot's
 * frame and their boxes' half-widths half[j] (half NULL: no boxes, lo and
 * hi left as they are); for the parts j whose bit
 * is set in ell (smooth ellipsoids of semi-axes abc[j] and matrix M[j]) the
 * half-widths of their exact boxes at the pose, |diag(a, b, c) (R M)^T e_i|
 * rounded up by 1e-13 of them (R M as mkMat3_MulInline forms it). With
 * spheres (else NULL), for each prepared part j and lane k, near[j][w][k]:
 * the masks mkSqPrep_Near gives at the part's centre pc (words w <
 * (spheres->n + 31) / 32, the spheres 32 w onwards), the lanes side by side.
 * One source (sceneprep_body.h) built for each instruction set: the same
 * values from each. */
typedef void (*mkSqPrepFn)(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *spheres, mkSqPrep *out);

void mkSqPrep_RunScalar(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *spheres, mkSqPrep *out);
void mkSqPrep_RunAvx2(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *spheres, mkSqPrep *out);
void mkSqPrep_RunAvx512(const double *poses, int n, int parts, const mkVec3 *t, const double *half, const mkMat3 *M,
	const double (*abc)[3], unsigned ell, const mkSqPrepSpheres *spheres, mkSqPrep *out);

/* The first of n 3D poses whose values are not all finite and of
 * magnitude at most 1e150 or whose quaternion's squared norm is not
 * positive, n when none (the scene query's test of its poses);
 * mkSqPrep_PickFirstBad: the build for impl as mkSqPrep_Pick. */
typedef long (*mkSqFirstBadFn)(const double *poses, long n);
long mkSqPrep_FirstBadScalar(const double *poses, long n);
long mkSqPrep_FirstBadAvx2(const double *poses, long n);
long mkSqPrep_FirstBadAvx512(const double *poses, long n);
mkSqFirstBadFn mkSqPrep_PickFirstBad(mkImpl impl);

/* The squared radius of the test of a part's sphere (radius prad) and an
 * obstacle's (radius r) for the bound b: ((prad + r + b) (1 + 1e-12))^2,
 * mkSqPrep_Apart's operations; formed once a part for max_clearance. */
static inline double mkSqPrep_Radius2(double prad, double r, double b)
{
	double x = (prad + r + b) * (1.0 + 1e-12);
	return x * x;
}

/* The obstacles near a part, at most 32 at a time (a scene of few
 * obstacles, tested without a hierarchy, takes as many calls as it needs):
 * bit i of the mask returned is 0 when the squared distance between the
 * part's centre c and obstacle i's sphere's centre (x, y, z [i]) exceeds
 * rr[i] = mkSqPrep_Radius2(prad, r_i, b) (the two spheres certainly more
 * than b apart, as mkSqPrep_Apart says), else 1. Portable, AVX2 and
 * AVX-512F builds (the same masks), picked with the preparation's
 * (mkSqPrep_PickNear). */
typedef uint32_t (*mkSqNearFn)(const double *x, const double *y, const double *z, const double *rr, int n, const double c[3]);
uint32_t mkSqPrep_Near(const double *x, const double *y, const double *z, const double *rr, int n, const double c[3]);
uint32_t mkSqPrep_NearAvx2(const double *x, const double *y, const double *z, const double *rr, int n, const double c[3]);
uint32_t mkSqPrep_NearAvx512(const double *x, const double *y, const double *z, const double *rr, int n, const double c[3]);
mkSqNearFn mkSqPrep_PickNear(mkImpl impl);

/* The build for impl (MK_IMPL_AUTO: the widest the CPU runs),
 * NULL when the CPU or the build lacks it. */
mkSqPrepFn mkSqPrep_Pick(mkImpl impl);

#endif
