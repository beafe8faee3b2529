#include "farm/process.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

extern char** environ;

namespace gonio {
namespace {

std::vector<char*> ArgvOf(const std::vector<std::string>& argv) {
    std::vector<char*> out;
    for (const std::string& a : argv) out.push_back(const_cast<char*>(a.c_str()));
    out.push_back(nullptr);
    return out;
}

pid_t Spawn(const std::vector<std::string>& argv, const posix_spawn_file_actions_t* actions,
            std::string* error) {
    std::vector<char*> args = ArgvOf(argv);
    pid_t pid = -1;
    const int status = posix_spawnp(&pid, args[0], actions, nullptr, args.data(), environ);
    if (status != 0) {
        *error = "cannot run " + argv[0] + ": " + std::strerror(status);
        return -1;
    }
    return pid;
}

}  // namespace

std::string ChildStatus::Describe() const {
    if (!started) return "could not be started";
    if (signal != 0)
        return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
    return "exit status " + std::to_string(exitCode);
}

pid_t StartProcess(const std::vector<std::string>& argv, std::string* error) {
    return Spawn(argv, nullptr, error);
}

ChildStatus WaitProcess(pid_t pid) {
    ChildStatus status;
    int raw = 0;
    while (::waitpid(pid, &raw, 0) < 0) {
        if (errno != EINTR) {
            status.started = false;
            return status;
        }
    }
    // posix_spawnp reports a missing program as the child's exit status 127.
    if (WIFEXITED(raw)) status.exitCode = WEXITSTATUS(raw);
    if (WIFSIGNALED(raw)) status.signal = WTERMSIG(raw);
    return status;
}

ChildStatus RunCapturing(const std::vector<std::string>& argv, std::string* output) {
    int fds[2];
    ChildStatus status;
    if (::pipe(fds) != 0) {
        status.started = false;
        return status;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    std::string error;
    const pid_t pid = Spawn(argv, &actions, &error);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    output->clear();
    char buffer[4096];
    ssize_t got;
    while ((got = ::read(fds[0], buffer, sizeof buffer)) != 0) {
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) break;
        output->append(buffer, size_t(got));
    }
    ::close(fds[0]);
    if (pid < 0) {
        status.started = false;
        return status;
    }
    return WaitProcess(pid);
}

bool OnPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::string folders = path;
    size_t start = 0;
    while (start <= folders.size()) {
        size_t end = folders.find(':', start);
        if (end == std::string::npos) end = folders.size();
        const std::filesystem::path candidate =
            std::filesystem::path(folders.substr(start, end - start)) / program;
        if (::access(candidate.c_str(), X_OK) == 0) return true;
        start = end + 1;
    }
    return false;
}

}  // namespace gonio
