/* normal_fma.c - MinkSum (Normal)'s solver (normal.h), the build for
 * processors with AVX2 and FMA: core/CMakeLists.txt gives this unit -mavx2
 * -mfma and lets the compiler contract a * b + c into one fused
 * multiply-add. collision.c calls it where the processor has them
 * (mkCollide3_Build says which build runs); its answers differ from the
 * portable build's by rounding only. */
#include "collide/normal.h"

mkResult mkCollide3_NormalAtFma(mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out)
{
	return mkNormal_Query(b1, b2, start, out);
}
