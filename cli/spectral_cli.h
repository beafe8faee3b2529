#pragma once
// Shared pieces of the `gonio spectral ...` subcommands.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "spectral/patch_analysis.h"

namespace gonio {

// Runs `body`; an exception becomes its message on stderr ("file:line: error: ..." as it is,
// anything else after "gonio spectral: error: ") and exit status 1.
void RunSpectralGuarded(int* exitCode, const std::function<void()>& body);

// The table of `gonio spectral patches` and `analyze`: per light (labelled by `lights`), rgb,
// the smallest bands-k and svd-k meeting `targetDe` (mean ΔE2000 one- and two-bounce), and the
// thesis's eq. 6.9 at that k.
void PrintRepresentationErrors(const std::vector<std::string>& lights,
                               const std::vector<spectral::PatchScene>& scenes, double targetDe);

// `gonio spectral analyze SCENE.rib`: the same table for the scene's own lights and surfaces.
void AddSpectralAnalyzeCommand(CLI::App& spectral, int* exitCode);

// `gonio spectral match LIGHT --rgb R G B`: the viewer's Match RGB (thesis §6.2.2).
void AddSpectralMatchCommand(CLI::App& spectral, int* exitCode);

}  // namespace gonio
