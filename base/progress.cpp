#include "base/progress.h"

#include <cstdio>

namespace gonio {

Progress::Progress(std::string label, uint64_t total, bool enabled)
    : label_(std::move(label)),
      total_(total ? total : 1),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { Done(); }

double Progress::ElapsedSeconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::Advance(uint64_t amount) {
    const uint64_t done = done_ += amount;
    if (!enabled_) return;
    const double elapsed = ElapsedSeconds();
    if (elapsed < 1.0) return;
    std::unique_lock<std::mutex> lock(drawMutex_, std::try_to_lock);
    if (!lock.owns_lock() || elapsed - lastDraw_ < 0.25) return;
    lastDraw_ = elapsed;
    Draw(done);
}

void Progress::Draw(uint64_t done) {
    const double elapsed = ElapsedSeconds();
    const double fraction = double(done) / double(total_);
    const double remaining = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
    std::fprintf(stderr, "\r%s: %5.1f%%  %6.1fs elapsed  %6.1fs left ", label_.c_str(),
                 100 * fraction, elapsed, remaining);
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::Done() {
    std::lock_guard<std::mutex> lock(drawMutex_);
    if (!drawn_) return;
    Draw(total_);
    std::fprintf(stderr, "\n");
    drawn_ = false;
}

}  // namespace gonio
