#pragma once
// `gonio farm task JOBDIR INDEX`: what one Slurm array task runs. For each of its tasks (the
// manifest's chunk of them):
//  * idempotent: a task whose output is already complete and valid is skipped; an invalid one
//    (damaged, truncated) is removed and redone;
//  * atomic: the render writes a temporary name beside the output, which is checked and then
//    renamed into place, so that the final name only ever holds a checked output;
//  * retried inside the task: each attempt is a child `gonio render`, so that an attempt killed
//    by a signal (the OOM killer, a node problem) leaves this process to run the next. Slurm's
//    own requeue would wait in the queue again and break the assemble job's afterok
//    dependency. A render that reports errors in the scene (exit status 1) is not retried:
//    it would fail the same way.
// While an attempt runs, its pid is in JOBDIR/run/task_NNNN.pid (for a person, or a test, to
// look at it or kill it).

#include <cstdio>
#include <string>

#include "farm/manifest.h"

namespace gonio {

// Runs task `index` of the manifest with `threads` render threads (0: all cores), logging to
// `log`. Returns "" on success, else why it failed (after its retries).
std::string RunFarmTask(const std::string& jobDir, const FarmManifest& manifest, int index,
                        int threads, std::FILE* log);

// Runs the tasks of array task `arrayIndex` (chunk consecutive tasks); returns how many failed.
// Throws FarmError for an array index out of range.
int RunArrayTask(const std::string& jobDir, const FarmManifest& manifest, int arrayIndex,
                 int threads, std::FILE* log);

// The pid file of task `index` while an attempt runs.
std::string TaskPidPath(const std::string& jobDir, int index);

}  // namespace gonio
