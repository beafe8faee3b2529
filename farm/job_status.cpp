#include "farm/job_status.h"

#include <filesystem>

#include "farm/process.h"
#include "farm/slurm.h"

namespace gonio {
namespace {

bool Exists(const std::string& jobDir, const std::string& relative) {
    std::error_code error;
    return std::filesystem::is_regular_file(JobPath(jobDir, relative), error);
}

// The final outputs of the job: what assemble writes, and frame tasks' images.
bool Assembled(const std::string& jobDir, const FarmManifest& m) {
    for (const FarmMerge& merge : m.merges) {
        if (!Exists(jobDir, merge.output)) return false;
        if (!merge.brdfOutput.empty() && !Exists(jobDir, merge.brdfOutput)) return false;
    }
    for (const FarmImage& image : m.images)
        if (!Exists(jobDir, image.output)) return false;
    return true;
}

}  // namespace

JobProgress ProgressOf(const std::string& jobDir, const FarmManifest& m) {
    JobProgress p;
    p.total = int(m.tasks.size());
    for (const FarmTask& task : m.tasks) p.done += Exists(jobDir, task.output);
    p.assembled = p.done == p.total && Assembled(jobDir, m);
    return p;
}

std::string StatusLine(const std::string& jobDir, const FarmManifest& m) {
    const JobProgress p = ProgressOf(jobDir, m);
    std::string line = "farm: " + std::to_string(p.done) + "/" + std::to_string(p.total) +
                       " tasks done (" + std::to_string(100 * p.done / p.total) + "%)";
    const SubmittedJobs jobs = ReadSubmitted(jobDir);
    if (!jobs.tasks.empty() && OnPath("squeue")) {
        const QueueState queue = QueryQueue(jobs);
        std::string states;
        for (const auto& [state, count] : queue.tasks)
            states += (states.empty() ? "" : ", ") + std::to_string(count) + " " + state;
        line += "; slurm job " + jobs.tasks + ": " + (states.empty() ? "none queued" : states);
        if (!queue.assemble.empty()) line += "; assemble " + queue.assemble;
    }
    return line + (p.assembled ? "; assembled" : "; not assembled");
}

}  // namespace gonio
