/* mink_exp/exp.h - everything the experiment drivers share: result files
 * written atomically with a metadata sidecar, seeded random streams,
 * progress on stderr, shards of a run, and command-line values. */
#ifndef MINK_EXP_EXP_H
#define MINK_EXP_EXP_H

#include "args.h"
#include "csv.h"
#include "meta.h"
#include "outfile.h"
#include "progress.h"
#include "rng.h"
#include "shard.h"

#endif
