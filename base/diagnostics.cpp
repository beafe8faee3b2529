#include "base/diagnostics.h"

namespace gonio {

std::string FormatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string FileLoc::ToString() const {
    std::string text = file ? *file : std::string("<unknown>");
    if (line > 0) {
        text += ":" + std::to_string(line);
        if (column > 0) text += ":" + std::to_string(column);
    }
    return text;
}

void Diagnostics::Report(Severity severity, const FileLoc& loc, const std::string& message) {
    static const char* const kLabels[] = {"note", "warning", "error"};
    Diagnostics* forward = nullptr;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        forward = forward_;
        if (severity == Severity::Error) ++errors_;
        if (severity == Severity::Warning) ++warnings_;
        if (sink_ && loc.file)
            std::fprintf(sink_, "%s: %s: %s\n", loc.ToString().c_str(),
                         kLabels[static_cast<int>(severity)], message.c_str());
        else if (sink_)
            std::fprintf(sink_, "gonio: %s: %s\n", kLabels[static_cast<int>(severity)],
                         message.c_str());
    }
    if (forward) forward->Report(severity, loc, message);  // outside the lock: it takes its own
}

void Diagnostics::ReportOnce(Severity severity, const std::string& key, const FileLoc& loc,
                             const std::string& message) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!seenKeys_.insert(key).second) return;
    }
    Report(severity, loc, message);
}

}  // namespace gonio
