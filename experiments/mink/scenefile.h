/* scenefile.h - reading a scene file for the `mink` subcommands. */
#ifndef MINK_EXP_SCENEFILE_H
#define MINK_EXP_SCENEFILE_H

#include <mink/cspace.h>

/* Read and parse the scene FILE ("-": standard input) and, for 3D, its
 * rotations file (relative to the scene's folder). Returns 0, or 2 after
 * printing "mink CMD: FILE: line L: ..." */
int mkSceneCmd_LoadFile(const char *cmd, const char *file, mkScene *scene);

#endif
