/* normal_portable.c - MinkSum (Normal)'s solver (normal.h), the portable
 * build: the library's flags (plus -O3, core/CMakeLists.txt), the same bits
 * on every x86-64 processor. */
#include "collide/normal.h"

mkResult mkCollide3_NormalAtPortable(mkBody3 b1, mkBody3 b2, const mkVec3 *start, mkCollision3 *out)
{
	return mkNormal_Query(b1, b2, start, out);
}
