#pragma once
// Entry points of the RIB front end (Flex lexer + Bison grammar). The parser checks each
// request's positional arguments and calls the matching RiTarget method; it reports syntax errors
// and bad arguments with file:line:col, skips to the next request, and goes on so that one run
// reports every error. `ReadArchive` is followed inside the parser (relative to the including
// file, then the archive search path from `Option "searchpath" "archive"`), with a cycle check.
// Gzip-compressed files are read transparently; "-" reads standard input.

#include <string>

#include "base/diagnostics.h"
#include "renderer/rib/ri_target.h"

namespace gonio {

// Parses the file at `path` ("-": standard input). Returns false if any error was reported.
bool ParseRibFile(const std::string& path, RiTarget& target, Diagnostics& diagnostics);

// Parses RIB text held in memory; `name` is used in diagnostics and to resolve ReadArchive.
bool ParseRibString(const std::string& text, const std::string& name, RiTarget& target,
                    Diagnostics& diagnostics);

}  // namespace gonio
