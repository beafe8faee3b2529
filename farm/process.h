#pragma once
// Child processes of the farm: the `gonio render` of a task attempt (run apart, so that an
// attempt killed by a signal or the out-of-memory killer leaves the task alive to retry it),
// `gonio brdf` in assemble, and sbatch / squeue.

#include <sys/types.h>

#include <string>
#include <vector>

namespace gonio {

struct ChildStatus {
    bool started = true;  // false: the program could not be run at all
    int exitCode = -1;    // when it exited
    int signal = 0;       // when a signal ended it

    bool Ok() const { return started && signal == 0 && exitCode == 0; }
    std::string Describe() const;  // "exit status 1", "killed by signal 9 (Killed)", ...
};

// Starts argv[0] (looked up on PATH when it has no '/') with argv; stdout and stderr are
// inherited. Returns the pid, or -1 (with *error set) when it cannot be started.
pid_t StartProcess(const std::vector<std::string>& argv, std::string* error);

// Waits for a child of StartProcess.
ChildStatus WaitProcess(pid_t pid);

// Runs argv to completion, its stdout into *output (stderr inherited).
ChildStatus RunCapturing(const std::vector<std::string>& argv, std::string* output);

// Whether a program of this name is on PATH (sbatch, squeue).
bool OnPath(const std::string& program);

}  // namespace gonio
