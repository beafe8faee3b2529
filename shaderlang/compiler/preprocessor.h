#pragma once
// The C-style preprocessor that runs before the shading-language parser (RISpec §14 leaves it
// to cpp): comments, line splicing, #include with a search path, object- and function-like
// #define, #undef, #if/#ifdef/#ifndef/#elif/#else/#endif with defined() and integer
// expressions, #line, #error. The output carries `#line N "file"` markers so the parser reports
// every error at its original file and line. Not supported: the # and ## operators, and macro
// calls whose arguments span lines.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/diagnostics.h"

namespace gonio::sl {

struct PreprocessOptions {
    std::vector<std::string> includeDirs;
    std::vector<std::pair<std::string, std::string>> defines;  // name, value ("1" if empty)
};

// Preprocesses `source`, whose name for messages and relative includes is `fileName`. Returns
// false (after reporting) if there were errors.
bool Preprocess(const std::string& source, const std::string& fileName,
                const PreprocessOptions& options, std::string* output, Diagnostics& diagnostics);

// Shader sources and their includes are at most this large (a larger one is not a shader).
constexpr std::uintmax_t kMaxSourceBytes = 64u << 20;

// Reads a whole regular file of at most kMaxSourceBytes; false, with the reason in *why when
// given, if it is missing, not a regular file (/dev/zero, a folder), too large or unreadable.
bool ReadTextFile(const std::string& path, std::string* text, std::string* why = nullptr);

}  // namespace gonio::sl
