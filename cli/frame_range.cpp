#include "frame_range.h"

#include <charconv>

namespace gonio {
namespace {

bool ParseInt(const std::string& text, int* value) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, *value);
    return ec == std::errc() && ptr == end && !text.empty();
}

}  // namespace

std::string ParseFrameRange(const std::string& text, FrameRange* range) {
    // A leading '-' is a negative first frame, not the separator.
    const size_t dash = text.find('-', 1);
    const std::string first = text.substr(0, dash);
    const std::string last = dash == std::string::npos ? first : text.substr(dash + 1);
    FrameRange parsed;
    if (!ParseInt(first, &parsed.first) || !ParseInt(last, &parsed.last))
        return "expected frames as A-B or A (FrameBegin numbers), got '" + text + "'";
    if (parsed.first > parsed.last)
        return "the frame range " + text + " is empty (its first frame is after its last)";
    *range = parsed;
    return "";
}

}  // namespace gonio
