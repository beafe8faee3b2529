// A RunProgram procedural's program as a child process with two pipes, driven by poll() so that
// neither a program that stops reading nor one that never answers can hang the renderer.

#include "renderer/rib/procedural_program.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>

extern char** environ;

namespace gonio {
namespace {

using Clock = std::chrono::steady_clock;

// The byte that ends a program's answer (RISpec App. C.3).
constexpr char kEndOfAnswer = '\377';

struct Pipe {
    int read = -1, write = -1;
    bool Open() {
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0) return false;
        read = fds[0], write = fds[1];
        return true;
    }
};

void Close(int* fd) {
    if (*fd >= 0) close(*fd);
    *fd = -1;
}

std::string ExitDescription(int status) {
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return std::string("was killed by ") + strsignal(WTERMSIG(status));
    return "ended abnormally";
}

// Starts `/bin/sh -c command` with its standard input and output on the pipes; -1 on failure.
pid_t Spawn(const std::string& command, Pipe& in, Pipe& out) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in.read, 0);
    posix_spawn_file_actions_adddup2(&actions, out.write, 1);
    // The child starts with no blocked signals and SIGPIPE at its default, whatever ours are.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t none, pipeSignal;
    sigemptyset(&none);
    sigemptyset(&pipeSignal);
    sigaddset(&pipeSignal, SIGPIPE);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setsigdefault(&attributes, &pipeSignal);
    // A process group of its own, so that a time-out kills what the shell started too.
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(
        &attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);
    const char* argv[] = {"sh", "-c", command.c_str(), nullptr};
    pid_t pid = -1;
    const int error = posix_spawn(&pid, "/bin/sh", &actions, &attributes,
                                  const_cast<char* const*>(argv), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    return error == 0 ? pid : -1;
}

// Feeds `request` to `toChild` and collects the answer from `fromChild` until 0377, the end of
// the output, or the deadline (none when `timeoutSeconds` <= 0). Returns false at the deadline.
bool Exchange(int toChild, int fromChild, const std::string& request, double timeoutSeconds,
              Clock::time_point deadline, std::string* answer) {
    fcntl(toChild, F_SETFL, O_NONBLOCK);
    std::size_t written = 0;
    char buffer[1 << 16];
    for (;;) {
        if (toChild >= 0 && written == request.size()) Close(&toChild);
        pollfd fds[2] = {{fromChild, POLLIN, 0}, {toChild, POLLOUT, 0}};
        int waitMs = -1;
        if (timeoutSeconds > 0) {
            const auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
            if (left.count() <= 0) break;
            waitMs = static_cast<int>(left.count());
        }
        if (poll(fds, toChild >= 0 ? 2 : 1, waitMs) < 0 && errno != EINTR) break;
        if (toChild >= 0 && (fds[1].revents & (POLLOUT | POLLERR | POLLHUP))) {
            const ssize_t n = write(toChild, request.data() + written, request.size() - written);
            // A program that does not read its input gets none: that is its business.
            if (n < 0 && errno != EAGAIN && errno != EINTR) written = request.size();
            if (n > 0) written += static_cast<std::size_t>(n);
        }
        if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) {
            const ssize_t n = read(fromChild, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;  // the end of its output
            const char* end = static_cast<const char*>(std::memchr(buffer, kEndOfAnswer, n));
            answer->append(buffer, end ? end - buffer : n);
            if (end) break;
        }
    }
    Close(&toChild);
    return timeoutSeconds <= 0 || Clock::now() < deadline;
}

// Waits for the child to exit, until the deadline if there is one. Returns false at the deadline.
bool WaitForExit(pid_t pid, double timeoutSeconds, Clock::time_point deadline, int* status) {
    for (;;) {
        const pid_t done = waitpid(pid, status, timeoutSeconds > 0 ? WNOHANG : 0);
        if (done == pid || (done < 0 && errno != EINTR)) return true;
        if (done == 0) {
            if (Clock::now() >= deadline) return false;
            usleep(2000);
        }
    }
}

std::string Seconds(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g s", seconds);
    return text;
}

}  // namespace

ProgramRun RunProceduralProgram(const std::string& command, const std::string& request,
                                double timeoutSeconds) {
    ProgramRun run;
    Pipe in, out;
    if (!in.Open() || !out.Open()) {
        run.error = std::string("cannot make a pipe: ") + std::strerror(errno);
        Close(&in.read), Close(&in.write), Close(&out.read);
        return run;
    }
    // Writing to a program that has exited must not raise SIGPIPE in the renderer.
    sigset_t pipeSignal, saved;
    sigemptyset(&pipeSignal);
    sigaddset(&pipeSignal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipeSignal, &saved);
    const pid_t pid = Spawn(command, in, out);
    Close(&in.read);
    Close(&out.write);
    const auto deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(
                           std::chrono::duration<double>(timeoutSeconds > 0 ? timeoutSeconds : 0));
    bool inTime = true;
    if (pid < 0) {
        run.error = "cannot start /bin/sh";
        Close(&in.write);
    } else {
        inTime = Exchange(in.write, out.read, request, timeoutSeconds, deadline, &run.rib);
    }
    Close(&out.read);
    timespec zero{0, 0};
    while (sigtimedwait(&pipeSignal, nullptr, &zero) > 0) {
    }
    pthread_sigmask(SIG_SETMASK, &saved, nullptr);
    if (pid < 0) return run;
    int status = 0;
    inTime = inTime && WaitForExit(pid, timeoutSeconds, deadline, &status);
    if (!inTime) {
        kill(-pid, SIGKILL);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        run.error = "did not finish within " + Seconds(timeoutSeconds) +
                    " (Option \"limits\" \"proceduraltimeout\") and was killed";
    } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        run.error = ExitDescription(status);
    } else {
        run.ok = true;
    }
    return run;
}

}  // namespace gonio
