#pragma once
// Whether a task's output is complete and valid, so that a task can skip work already done, a
// corrupt output is redone, and assemble trusts what it joins. Outputs only get their final
// names once checked (task_runner.h), so a file under that name that fails here was damaged
// afterwards (or written by something else).

#include <string>

#include "farm/manifest.h"

namespace gonio {

// "" when the file at `path` is a valid output of `task`, else why not ("missing", "photon map
// line 12: ...", "its header counts 500 paths, the shard traces 625", "cannot read the image").
// A shard's map is read whole: every line must parse and the photon count match its header.
std::string CheckTaskOutput(const FarmTask& task, const std::string& path);

}  // namespace gonio
