#pragma once
// Text files written whole or not at all: under a temporary name in the same folder, renamed
// into place when complete, so that a reader (or a farm task that checks whether its output is
// done) never sees a partial file, and a failure leaves the old file, if any, untouched.

#include <string>

namespace gonio {

// Writes `text` to `path` atomically; returns the reason on failure (strerror), "" on success.
std::string WriteFileAtomically(const std::string& path, const std::string& text);

}  // namespace gonio
