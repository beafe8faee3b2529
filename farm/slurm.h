#pragma once
// The Slurm side of a farm job: the batch scripts `gonio farm plan` writes, `sbatch` to submit
// them, `squeue` to follow them. A job is two Slurm jobs: an array of the tasks (throttled,
// --array=0-N%M) and an assemble job that starts after all of them succeeded
// (--dependency=afterok). No accounting is needed: `farm status` reads squeue and the outputs.

#include <map>
#include <string>

#include "farm/manifest.h"

namespace gonio {

inline constexpr const char* kTasksScript = "slurm/tasks.sbatch";
inline constexpr const char* kAssembleScript = "slurm/assemble.sbatch";
inline constexpr const char* kSubmittedFile = "slurm/submitted";  // "TASKS_ID ASSEMBLE_ID"

// Writes JOBDIR/slurm/tasks.sbatch and assemble.sbatch (and creates logs/). Throws FarmError.
void WriteSlurmScripts(const std::string& jobDir, const FarmManifest& manifest);

struct SubmittedJobs {
    std::string tasks, assemble;  // Slurm job ids
};

// sbatch of both scripts; records the ids in JOBDIR/slurm/submitted. Throws FarmError with
// sbatch's exit status when it fails.
SubmittedJobs SubmitToSlurm(const std::string& jobDir);

// The ids of the last submission, or {} when the job was never submitted to Slurm.
SubmittedJobs ReadSubmitted(const std::string& jobDir);

// Slurm states of the submitted jobs' array tasks and of the assemble job, as squeue lists them
// (PENDING, RUNNING, ...), counted; jobs no longer in the queue are absent.
struct QueueState {
    std::map<std::string, int> tasks;
    std::string assemble;  // "" when it has left the queue (or never was there)
};
QueueState QueryQueue(const SubmittedJobs& jobs);

}  // namespace gonio
