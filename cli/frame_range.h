#pragma once
// Frame ranges on the command line ("A-B" or "A", FrameBegin numbers), as `gonio render
// --frames` and `gonio farm plan --frames` read them.

#include <string>

namespace gonio {

struct FrameRange {
    int first = 0, last = -1;  // inclusive; empty (first > last) when not given

    bool Given() const { return first <= last; }
    bool Contains(int frame) const { return !Given() || (frame >= first && frame <= last); }
};

// Parses "A-B" (A <= B) or "A" into *range; returns the reason on failure, "" on success.
std::string ParseFrameRange(const std::string& text, FrameRange* range);

}  // namespace gonio
