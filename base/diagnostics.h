#pragma once
// Compiler-style error reporting shared by every stage. Errors are collected, not thrown, so a run
// reports all of them; the caller decides from ErrorCount() whether the result may be used.

#include <cstdio>
#include <mutex>
#include <set>
#include <string>

#include "base/file_loc.h"

namespace gonio {

// A number as messages show it, with %g: -5, 0.25, 1e+30 (std::to_string writes -5.000000).
std::string FormatNumber(double value);

enum class Severity { Note, Warning, Error };

class Diagnostics {
  public:
    explicit Diagnostics(std::FILE* sink = stderr) : sink_(sink) {}

    void Report(Severity severity, const FileLoc& loc, const std::string& message);
    void Error(const FileLoc& loc, const std::string& message) {
        Report(Severity::Error, loc, message);
    }
    void Warning(const FileLoc& loc, const std::string& message) {
        Report(Severity::Warning, loc, message);
    }
    void Note(const FileLoc& loc, const std::string& message) {
        Report(Severity::Note, loc, message);
    }
    // Reports `message` only the first time `key` is seen, for notes such as "ShadingRate is
    // ignored by a ray tracer" that would otherwise repeat once per request.
    void NoteOnce(const std::string& key, const FileLoc& loc, const std::string& message) {
        ReportOnce(Severity::Note, key, loc, message);
    }
    void WarningOnce(const std::string& key, const FileLoc& loc, const std::string& message) {
        ReportOnce(Severity::Warning, key, loc, message);
    }
    void ErrorOnce(const std::string& key, const FileLoc& loc, const std::string& message) {
        ReportOnce(Severity::Error, key, loc, message);
    }
    void ReportOnce(Severity severity, const std::string& key, const FileLoc& loc,
                    const std::string& message);

    // While set, every message is also reported to `to` (null: no more): a silent reading of a
    // scene passes on the messages of what only it reads.
    void ForwardTo(Diagnostics* to) {
        std::lock_guard<std::mutex> lock(mutex_);
        forward_ = to;
    }

    int ErrorCount() const { return errors_; }
    int WarningCount() const { return warnings_; }

  private:
    std::FILE* sink_;
    Diagnostics* forward_ = nullptr;
    std::mutex mutex_;
    std::set<std::string> seenKeys_;
    int errors_ = 0;
    int warnings_ = 0;
};

}  // namespace gonio
