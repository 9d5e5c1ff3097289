/* points.h - reading a point set from a CSV file, for the subcommands that
 * take one (`mink verify`, `mink score`). */
#ifndef MINK_CLI_POINTS_H
#define MINK_CLI_POINTS_H

#include <mink/registry.h>

/* Read the points of `path` ("-": standard input) into out (dimension dim,
 * 2 or 3): a CSV with a header naming columns x, y (and z), as `mink sum`
 * writes, or no header and x, y[, z] first; blank lines and lines starting
 * with # are skipped, as is a trailing carriage return. Returns 0, or -1
 * after one message on stderr, "mink CMD: --points FILE line L, column C:
 * ..." for a field that is not a finite or infinite number, a missing
 * column, or no points at all. */
int mkPoints_Read(const char *cmd, const char *path, int dim, mkPointSet *out);

#endif
