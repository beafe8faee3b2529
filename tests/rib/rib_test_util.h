#pragma once
// Helpers for the RIB front-end tests: parse text or a file into a RecordingTarget while
// capturing the diagnostics, and make scratch files.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/diagnostics.h"
#include "recording_target.h"
#include "renderer/rib/rib_parser.h"

namespace gonio {

struct ParseResult {
    RecordingTarget target;
    std::string messages;  // everything Diagnostics printed
    bool ok = false;
    int errors = 0;
};

// Runs `parse(target, diagnostics)` with diagnostics going to a temporary file, then reads it.
template <typename ParseFunction>
ParseResult Capture(ParseFunction parse) {
    ParseResult result;
    std::FILE* sink = std::tmpfile();
    {
        Diagnostics diagnostics(sink);
        result.ok = parse(result.target, diagnostics);
        result.errors = diagnostics.ErrorCount();
    }
    std::rewind(sink);
    char buffer[4096];
    for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, sink)) > 0;)
        result.messages.append(buffer, got);
    std::fclose(sink);
    return result;
}

inline ParseResult ParseText(const std::string& rib, const std::string& name = "test.rib") {
    return Capture([&](RiTarget& target, Diagnostics& diagnostics) {
        return ParseRibString(rib, name, target, diagnostics);
    });
}

inline ParseResult ParseFile(const std::string& path) {
    return Capture([&](RiTarget& target, Diagnostics& diagnostics) {
        return ParseRibFile(path, target, diagnostics);
    });
}

// A fresh, empty folder for one test.
inline std::filesystem::path ScratchFolder(const std::string& name) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("gonio_rib_tests_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

inline void WriteText(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

}  // namespace gonio
