#include "farm/task_runner.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "base/atomic_file.h"
#include "farm/process.h"
#include "farm/task_output.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

// Beside the output, keeping its extension (the renderer picks the format by it), unique per
// process and attempt.
std::string AttemptPath(const std::string& output, int attempt) {
    const fs::path path(output);
    return (path.parent_path() /
            ("." + path.stem().string() + ".attempt" + std::to_string(::getpid()) + "-" +
             std::to_string(attempt) + path.extension().string()))
        .string();
}

// The attempt's output and what a killed render leaves of its own temporary files, whose names
// contain the attempt's (the image and photon map writers' temp + rename).
void RemoveAttemptFiles(const std::string& attempt) {
    const fs::path path(attempt);
    const std::string name = path.filename().string();
    std::error_code error;  // a folder that cannot be listed holds nothing to remove
    for (const fs::directory_entry& entry : fs::directory_iterator(path.parent_path(), error)) {
        if (entry.path().filename().string().find(name) != std::string::npos)
            fs::remove(entry.path(), error);
    }
}

std::vector<std::string> AttemptArgv(const FarmManifest& m, const FarmTask& task,
                                     const std::string& output, int threads) {
    std::vector<std::string> argv = {m.gonio};
    argv.insert(argv.end(), task.args.begin(), task.args.end());
    argv.insert(argv.end(), {"-o", output});
    if (threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(threads)});
    return argv;
}

// One attempt: "" when its output is checked and in place, else why not.
std::string Attempt(const std::string& jobDir, const FarmManifest& m, int index, int attempt,
                    int threads, ChildStatus* status) {
    const FarmTask& task = m.tasks[index];
    const std::string output = JobPath(jobDir, task.output);
    const std::string temporary = AttemptPath(output, attempt);
    std::string error;
    const pid_t pid = StartProcess(AttemptArgv(m, task, temporary, threads), &error);
    if (pid < 0) {
        status->started = false;
        return error;
    }
    const std::string pidFile = TaskPidPath(jobDir, index);
    WriteFileAtomically(pidFile,
                        std::to_string(pid) + "\n");  // for people (and the tests) to look at
    *status = WaitProcess(pid);
    std::error_code ignored;  // a pid file left behind names a finished process: harmless
    fs::remove(pidFile, ignored);
    std::string reason = status->Ok() ? CheckTaskOutput(task, temporary) : status->Describe();
    std::error_code renameError;
    if (reason.empty()) fs::rename(temporary, output, renameError);
    if (renameError) reason = "cannot rename it into place: " + renameError.message();
    if (!reason.empty()) RemoveAttemptFiles(temporary);
    return reason;
}

}  // namespace

std::string TaskPidPath(const std::string& jobDir, int index) {
    char name[32];
    std::snprintf(name, sizeof name, "run/task_%04d.pid", index);
    return JobPath(jobDir, name);
}

std::string RunFarmTask(const std::string& jobDir, const FarmManifest& m, int index, int threads,
                        std::FILE* log) {
    const FarmTask& task = m.tasks[index];
    const std::string output = JobPath(jobDir, task.output);
    const std::string existing = CheckTaskOutput(task, output);
    if (existing.empty()) {
        std::fprintf(log, "farm task %d (%s): %s is complete, skipped\n", index, task.name.c_str(),
                     task.output.c_str());
        return "";
    }
    if (existing != "missing") {
        std::fprintf(log, "farm task %d (%s): %s is not valid (%s): redoing it\n", index,
                     task.name.c_str(), task.output.c_str(), existing.c_str());
    }
    std::error_code error;
    fs::remove(output, error);  // "missing" or invalid: nothing worth keeping
    fs::create_directories(fs::path(output).parent_path(), error);
    fs::create_directories(fs::path(TaskPidPath(jobDir, index)).parent_path(), error);
    std::string reason;
    for (int attempt = 1; attempt <= 1 + task.retries; ++attempt) {
        ChildStatus status;
        reason = Attempt(jobDir, m, index, attempt, threads, &status);
        if (reason.empty()) {
            std::fprintf(log, "farm task %d (%s): wrote %s (attempt %d)\n", index,
                         task.name.c_str(), task.output.c_str(), attempt);
            return "";
        }
        std::fprintf(log, "farm task %d (%s): attempt %d of %d failed: %s\n", index,
                     task.name.c_str(), attempt, 1 + task.retries, reason.c_str());
        std::fflush(log);
        if (status.started && status.signal == 0 && status.exitCode == 1) break;
    }
    return reason;
}

int RunArrayTask(const std::string& jobDir, const FarmManifest& m, int arrayIndex, int threads,
                 std::FILE* log) {
    if (arrayIndex < 0 || arrayIndex >= m.ArrayTasks())
        throw FarmError(ManifestPath(jobDir) + ": error: array task " + std::to_string(arrayIndex) +
                        " is out of range: the job has " + std::to_string(m.ArrayTasks()) + " (0-" +
                        std::to_string(m.ArrayTasks() - 1) + ")");
    int failed = 0;
    const int first = arrayIndex * m.chunk;
    const int last = std::min<int>(first + m.chunk, int(m.tasks.size()));
    for (int i = first; i < last; ++i) failed += !RunFarmTask(jobDir, m, i, threads, log).empty();
    return failed;
}

}  // namespace gonio
