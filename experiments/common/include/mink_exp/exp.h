/* mink_exp/exp.h - everything the experiment drivers share: the driver
 * harness (options, --help, output paths, sidecar, CSV commit), result files
 * written atomically with a metadata sidecar and read back, seeded random
 * streams and the shared draws, clocks, progress on stderr, shards of a run,
 * and the summary tables' writer. */
#ifndef MINK_EXP_EXP_H
#define MINK_EXP_EXP_H

#include "args.h"
#include "clock.h"
#include "csv.h"
#include "doc.h"
#include "draw.h"
#include "driver.h"
#include "meta.h"
#include "outfile.h"
#include "paper.h"
#include "progress.h"
#include "rng.h"
#include "shard.h"
#include "table.h"

#endif
