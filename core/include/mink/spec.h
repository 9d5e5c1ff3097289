/* mink/spec.h - the SPEC text that names a body on the command line:
 *
 *   KIND key=value ...
 *
 * KIND: circle, ellipse, superellipse (2D); sphere, ellipsoid, superquadric (3D).
 * keys: a, b, c (semi-axes), eps (2D), eps1, eps2 (3D);
 *       rot=ANGLE (2D, radians) or quat=w,x,y,z (3D);
 *       shear=S (2D: [1 S; 0 1], applied before the rotation: M = R S);
 *       M=m11,m12,... (any invertible map, row-major; excludes rot/quat/shear);
 *       at=x,y[,z] (the centre).
 * circle/sphere take a (the radius); ellipse a, b; ellipsoid a, b, c; the
 * super kinds also take their exponents. Every shape key of the kind is
 * required; pose keys are optional (identity map, centre at the origin).
 * The body is at + M B_canonical. */
#ifndef MINK_SPEC_H
#define MINK_SPEC_H

#include <stddef.h>
#include "body.h"

MK_EXTERN_C_BEGIN

typedef enum mkKind {
	MK_KIND_CIRCLE, MK_KIND_ELLIPSE, MK_KIND_SUPERELLIPSE,
	MK_KIND_SPHERE, MK_KIND_ELLIPSOID, MK_KIND_SUPERQUADRIC
} mkKind;

typedef struct mkSpec {
	int dim;       /* 2 or 3 */
	mkKind kind;
	mkBody2 body2; /* valid when dim == 2 */
	mkBody3 body3; /* valid when dim == 3 */
} mkSpec;

MK_API const char *mkKind_Name(mkKind k);

/* Parse and validate. dim is 2 or 3 (the kind must match it). `what` names
 * the body in messages ("body1"). On failure returns MK_ERR_ARGUMENT or
 * MK_ERR_RANGE and writes one line to msg naming the field, the value and the
 * allowed range. Never reads past the terminating NUL. */
MK_API mkResult mkSpec_Parse(const char *text, int dim, const char *what,
	mkSpec *out, char *msg, size_t msglen);

MK_EXTERN_C_END

#endif
