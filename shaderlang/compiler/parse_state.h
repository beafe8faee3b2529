#pragma once
// State shared by the reentrant lexer and the grammar of one parse (internal to the compiler).

#include <memory>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "shaderlang/compiler/ast.h"
#include "shaderlang/compiler/parser.h"

namespace gonio::sl {

struct ParseState {
    SyntaxTree* tree = nullptr;
    Diagnostics* diagnostics = nullptr;
    int file = 0;  // current file index (changed by #line markers)
    int line = 1;
    int column = 1;
    int errors = 0;
    // The parser's stacks once they outgrow their first 200 entries (sl_grammar.y's yyoverflow).
    std::vector<std::unique_ptr<char[]>> parserStacks;

    void Error(const SourceLoc& loc, const std::string& message) {
        ++errors;
        diagnostics->Error(ToFileLoc(*tree, loc), message);
    }
    // A `#line N "file"` or `# N "file"` marker: the next line is line N of `file`.
    void LineMarker(const char* text);
    int FileIndex(const std::string& name);
};

}  // namespace gonio::sl
