#pragma once
// `gonio farm status JOBDIR`: a progress line from the outputs (a task's output gets its final
// name only once checked, so its presence means done) and, for a job submitted to Slurm, from
// squeue (no accounting database needed).

#include <string>

#include "farm/manifest.h"

namespace gonio {

struct JobProgress {
    int done = 0, total = 0;
    bool assembled = false;  // every merged map, grid and joined image is there
};

JobProgress ProgressOf(const std::string& jobDir, const FarmManifest& manifest);

// "farm: 12/16 tasks done (75%); slurm: 3 RUNNING, 1 PENDING; assemble PENDING".
std::string StatusLine(const std::string& jobDir, const FarmManifest& manifest);

}  // namespace gonio
