#pragma once
// The C-style preprocessor that runs before the shading-language parser (RISpec §14 leaves it
// to cpp): comments, line splicing, #include with a search path, object- and function-like
// #define, #undef, #if/#ifdef/#ifndef/#elif/#else/#endif with defined() and integer
// expressions, #line, #error. The output carries `#line N "file"` markers so the parser reports
// every error at its original file and line. Not supported: the # and ## operators, and macro
// calls whose arguments span lines.

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

// Reads a whole file; false if it cannot be read.
bool ReadTextFile(const std::string& path, std::string* text);

}  // namespace gonio::sl
