#pragma once
// Whole-file text I/O for the spectral formats: a read that says why it failed, and a write that
// never leaves a half-written file behind (it writes a temporary name and renames it on success).

#include <string>
#include <vector>

namespace gonio::spectral {

// The file's lines, without their newlines. Throws SpectralError `path: error: cannot read ...`.
std::vector<std::string> ReadTextLines(const std::string& path);

// Writes `text` to `path.tmp<pid>`, checks every write and the close, then renames it over
// `path`. On any failure the temporary is removed and a SpectralError names the reason.
void WriteTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace gonio::spectral
