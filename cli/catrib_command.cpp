// `gonio catrib FILE.rib|-`: parses a RIB file and prints its requests back as RIB. It shows what
// the parser understood (archives expanded, values normalised) and checks a file for errors
// without rendering it. Exit status: 0 ok, 1 errors in the RIB, 2 the file cannot be read.

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "base/diagnostics.h"
#include "commands.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/rib/rib_writer.h"

namespace gonio {
namespace {

// Says why `path` cannot be read, or returns an empty string.
std::string UnreadableReason(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) return "it is a directory";
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return std::strerror(errno);
    std::fclose(file);
    return "";
}

}  // namespace

void AddCatribCommand(CLI::App& app, int* exitCode) {
    CLI::App* command =
        app.add_subcommand("catrib", "Parse a RIB file and print its requests back as RIB");
    auto path = std::make_shared<std::string>();
    command->add_option("file", *path, "RIB file (plain or gzip-compressed), or - for stdin")
        ->required();
    command->callback([path, exitCode] {
        if (*path != "-") {
            const std::string why = UnreadableReason(*path);
            if (!why.empty()) {
                std::fprintf(stderr, "gonio catrib: cannot read %s: %s\n", path->c_str(),
                             why.c_str());
                *exitCode = 2;
                return;
            }
        }
        Diagnostics diagnostics(stderr);
        RibWriter writer(std::cout);
        const bool ok = ParseRibFile(*path, writer, diagnostics);
        std::cout.flush();
        *exitCode = ok ? 0 : 1;
    });
}

}  // namespace gonio
