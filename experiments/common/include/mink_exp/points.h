/* mink_exp/points.h - a CSV of points read from text: the input of `mink
 * verify --points` (what `mink sum` writes).
 *
 * Format: lines end in "\n" or "\r\n"; blank lines and lines starting with
 * '#' are skipped; fields are separated by commas, with spaces and tabs
 * around them ignored. The first other line is a header when its first
 * field is not a number: it must then name the columns x and y (and z in
 * 3D), in any position among any others; without a header the first
 * columns are x, y[, z]. Every later line must hold the columns as numbers
 * (strtod's syntax, whole field). */
#ifndef MINK_EXP_POINTS_H
#define MINK_EXP_POINTS_H

#include <stddef.h>

/* The points read: count of them in x, y (and z in 3D), allocated by the
 * reader (mkPoints_Free). */
typedef struct mkPoints {
	int dim, count, cap;
	double *x, *y, *z;
} mkPoints;

/* Parse text (modified in place: fields are cut out of it) as points of
 * dimension dim (2 or 3) into *out (emptied first). Returns 0, or -1 with
 * one line in msg naming the line and what is wrong ("line 3: 'abc' is not
 * a number"), also for text with no point and when memory runs out.
 * Either way *out is then released with mkPoints_Free. */
int mkPoints_Parse(char *text, int dim, mkPoints *out, char *msg, size_t msglen);

void mkPoints_Free(mkPoints *p);

#endif
