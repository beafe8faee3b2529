#pragma once
// `gonio farm assemble JOBDIR`: checks that every task's output is there and valid (naming
// each one that is not), merges each BRDFLight frame's shards into one photon map (in path
// order: the unsplit run's map), runs the requested `gonio brdf opt/iopt` on it, and joins each
// tiled frame's tiles into its image.

#include <cstdio>
#include <string>
#include <vector>

#include "farm/manifest.h"

namespace gonio {

// One line per task whose output is missing or invalid: "task 5 (frame 1 shard 5/16):
// shards/frame_0001_shard_0005.pm: missing". Empty when all are complete.
std::vector<std::string> IncompleteTasks(const std::string& jobDir, const FarmManifest& manifest);

// Removes what assemble writes (merged maps, grids, joined images), before a job is submitted
// again: until the new assembly, `farm status` must not take the old results for done.
void RemoveAssembledOutputs(const std::string& jobDir, const FarmManifest& manifest);

// Returns the exit status: 0 done, 1 incomplete tasks or a failed step (reported on `log`).
int AssembleJob(const std::string& jobDir, const FarmManifest& manifest, std::FILE* log);

}  // namespace gonio
