// Placeholder until the brdf command lands; replaced by its owner.
#include <cstdio>

#include "commands.h"

namespace gonio {

void AddBrdfCommand(CLI::App& app, int* exitCode) {
    app.add_subcommand("brdf", "(not yet available)")->callback([exitCode] {
        std::fprintf(stderr, "gonio brdf: not yet available\n");
        *exitCode = 2;
    });
}

}  // namespace gonio
