#pragma once
// The subcommands of `gonio`. Each Add*Command registers its subcommand on `app`; when the
// subcommand runs it stores its exit status in `*exitCode` (0 ok, 1 errors in the input, 2 usage
// or I/O problems).

#include <CLI/CLI.hpp>

namespace gonio {

void AddRenderCommand(CLI::App& app, int* exitCode);
void AddCatribCommand(CLI::App& app, int* exitCode);
void AddBrdfCommand(CLI::App& app, int* exitCode);
void AddShaderCommand(CLI::App& app, int* exitCode);
void AddShadeCommand(CLI::App& app, int* exitCode);
void AddSpectralCommand(CLI::App& app, int* exitCode);
void AddViewCommand(CLI::App& app, int* exitCode);
void AddFarmCommand(CLI::App& app, int* exitCode);

}  // namespace gonio
