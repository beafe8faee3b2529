#pragma once
// `gonio farm submit --backend local`: the job on this machine without Slurm. The array tasks
// run as child `gonio farm task` processes, `jobs` at a time (the array throttle), each with an
// equal share of the cores; once all succeeded, the job is assembled.

#include <cstdio>
#include <string>

#include "farm/manifest.h"

namespace gonio {

// Returns the exit status: 0 done, 1 a task or the assembly failed (reported on `log`).
int RunLocally(const std::string& jobDir, const FarmManifest& manifest, int jobs, std::FILE* log);

}  // namespace gonio
