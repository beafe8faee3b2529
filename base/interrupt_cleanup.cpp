#include "base/interrupt_cleanup.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace gonio {
namespace {

// A fixed table, so that the handler touches no allocator and no lock: a slot is free, being
// filled, or ready (its path complete); the handler removes only the ready ones.
enum SlotState : int { kFree, kFilling, kReady };
constexpr int kSlots = 64;
constexpr size_t kMaxPath = 4096;

// Every member has an initialiser, so the table is constant-initialised (zeros in .bss): a
// constructor run at start-up would touch its 64 pages, a page fault each, in every command.
struct Slot {
    std::atomic<int> state{kFree};
    char path[kMaxPath] = {};
};

Slot g_slots[kSlots];

void WriteMessage(const char* text) {
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;  // nothing is left to report a failed write to
}

// Only async-signal-safe calls: unlink, write, signal, raise.
extern "C" void OnInterrupt(int signal) {
    for (Slot& slot : g_slots)
        if (slot.state.load() == kReady) ::unlink(slot.path);
    WriteMessage(signal == SIGINT ? "gonio: interrupted (SIGINT): partial files removed\n"
                                  : "gonio: terminated (SIGTERM): partial files removed\n");
    ::signal(signal, SIG_DFL);
    ::raise(signal);
}

}  // namespace

void RemoveTemporariesOnInterrupt() {
    struct sigaction action {};
    action.sa_handler = OnInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

PendingTemporary::PendingTemporary(const std::string& path) {
    if (path.size() >= kMaxPath) return;
    for (int s = 0; s < kSlots; ++s) {
        int expected = kFree;
        if (!g_slots[s].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(g_slots[s].path, path.c_str(), path.size() + 1);
        g_slots[s].state.store(kReady);
        slot_ = s;
        return;
    }
}

PendingTemporary::~PendingTemporary() {
    if (slot_ >= 0) g_slots[slot_].state.store(kFree);
}

}  // namespace gonio
