#include "farm/local_backend.h"

#include <sys/wait.h>

#include <algorithm>
#include <map>
#include <thread>

#include "farm/assemble.h"
#include "farm/process.h"

namespace gonio {

int RunLocally(const std::string& jobDir, const FarmManifest& m, int jobs, std::FILE* log) {
    const int arrayTasks = m.ArrayTasks();
    jobs = std::clamp(jobs, 1, arrayTasks);
    const int threads = std::max(1, int(std::thread::hardware_concurrency()) / jobs);
    std::map<pid_t, int> running;  // pid -> array index
    int next = 0, failed = 0;
    while (next < arrayTasks || !running.empty()) {
        while (next < arrayTasks && int(running.size()) < jobs) {
            std::string error;
            const pid_t pid = StartProcess({m.gonio, "farm", "task", jobDir, std::to_string(next),
                                            "--threads", std::to_string(threads)},
                                           &error);
            if (pid < 0) {
                std::fprintf(log, "farm: array task %d: %s\n", next, error.c_str());
                ++failed;
            } else {
                running[pid] = next;
            }
            ++next;
        }
        if (running.empty()) break;
        int raw = 0;
        const pid_t pid = ::waitpid(-1, &raw, 0);
        const auto it = running.find(pid);
        if (it == running.end()) continue;  // EINTR, or a child that is not ours
        if (!WIFEXITED(raw) || WEXITSTATUS(raw) != 0) {
            std::fprintf(log, "farm: array task %d failed\n", it->second);
            ++failed;
        }
        running.erase(it);
    }
    if (failed > 0) {
        std::fprintf(log, "farm: %d of %d array tasks failed; not assembled\n", failed, arrayTasks);
        return 1;
    }
    return AssembleJob(jobDir, m, log);
}

}  // namespace gonio
