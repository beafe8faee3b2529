#pragma once
// A progress line on stderr for long work: percentage, elapsed and estimated remaining time. It
// stays silent for the first second so quick runs print nothing, and redraws at most a few
// times per second whichever thread calls Advance.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace gonio {

class Progress {
  public:
    Progress(std::string label, uint64_t total, bool enabled);
    ~Progress();
    void Advance(uint64_t amount = 1);
    // Ends the line (if one was drawn).
    void Done();
    double ElapsedSeconds() const;

  private:
    void Draw(uint64_t done);

    std::string label_;
    uint64_t total_;
    bool enabled_;
    std::atomic<uint64_t> done_{0};
    std::chrono::steady_clock::time_point start_;
    std::mutex drawMutex_;
    double lastDraw_ = 0;
    bool drawn_ = false;
};

}  // namespace gonio
