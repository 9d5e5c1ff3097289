/* faces.h - `mink score --faces FILE`: the triangles of a 3D point set, read
 * and checked to close a convex surface over the points. */
#ifndef MINK_CLI_FACES_H
#define MINK_CLI_FACES_H

#include <mink/registry.h>

/* What the check found: the face count and the volume the faces enclose
 * (divergence theorem, |sum of det(a, b, c)| / 6). */
typedef struct mkFaces_Check {
	int faces;
	double volume;
} mkFaces_Check;

/* Read FILE (lines i,j,k of 0-based indices into pts, comma- or
 * space-separated; an optional header naming columns i, j, k, as the
 * .faces.csv of 'mink scene', selects them; # comments and blank lines
 * skipped) and check that the triangles close a convex surface over pts:
 * every directed edge once and its reverse once (closed, consistently
 * oriented), no triangle of zero area, and every point of pts on the inner
 * side of every triangle's plane within 1e-9 of the points' extent. Then
 * the surface is the boundary of the points' convex hull, the set the
 * measure scores. Returns 0, or -1 after a message on stderr naming the
 * file, line and column (bad index: the allowed range) or the failed
 * condition. */
int mkFaces_Check3(const char *path, const mkPointSet *pts, mkFaces_Check *out);

#endif
