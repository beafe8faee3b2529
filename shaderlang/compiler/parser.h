#pragma once
// Parses preprocessed shader source (with `#line N "file"` markers from the preprocessor) into
// a SyntaxTree. Syntax errors go to `diagnostics` as `file.sl:LINE:COL: error: ...`; parsing
// recovers at `;` and `}` so that one run reports several.

#include <string>

#include "base/diagnostics.h"
#include "shaderlang/compiler/ast.h"

namespace gonio::sl {

// Returns false if there were syntax errors (the tree then holds what could be parsed).
bool ParseShader(const std::string& source, const std::string& fileName, SyntaxTree* tree,
                 Diagnostics& diagnostics);

// The diagnostics location of a source location of `tree`.
FileLoc ToFileLoc(const SyntaxTree& tree, const SourceLoc& loc);

}  // namespace gonio::sl
