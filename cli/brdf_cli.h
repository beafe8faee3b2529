#pragma once
// Shared pieces of the `gonio brdf ...` subcommands: exit codes from exceptions, the spread
// argument, a progress line, and loading a BRDF from a .grd or a .pm.

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <string>

#include "brdfsim/brdf.h"
#include "brdfsim/grd_file.h"
#include "brdfsim/kernel.h"

namespace gonio::brdfcli {

// Runs `body`; returns 0, 1 for bad input data (malformed photon map or .grd), 2 for usage and
// I/O errors, after printing "gonio brdf NAME: error: ..." on stderr.
int RunGuarded(const std::string& name, const std::function<void()>& body);

// A usage error raised after parsing (a bad option value).
class UsageError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

// Throws a UsageError when the output names one of the inputs (`brdf opt 4 8 17deg 0 a.pm a.pm`
// would replace the photon map with the grid made from it).
void RefuseToOverwriteAnInput(const std::vector<std::string>& inputs, const std::string& output);

// The splat radius: radians as in the thesis (0.3), or degrees with a "deg" suffix (17deg).
double ParseSpread(const std::string& text);

// "\rLABEL: 42%" on stderr, updated at each whole percent, ended by Finish().
class ProgressLine {
  public:
    explicit ProgressLine(std::string label) : label_(std::move(label)) {}
    void operator()(double fraction);
    void Finish();

  private:
    std::string label_;
    int shown_ = -1;
};

struct LoadedBrdf {
    std::unique_ptr<GrdFile> grd;  // set for a .grd
    std::unique_ptr<Brdf> owned;   // set for a .pm
    const Brdf* brdf = nullptr;
};

struct PhotonMapSettings {
    double spread = 0.3;
    double energyMin = 0.0;
    Norm norm = Norm::kL2;
    Horizon horizon = Horizon::kReflect;
    int isotropic = -1;   // -1: decide from the map (all φ_in = 0 means isotropic)
    bool simple = false;  // BrdfSimple instead of a grid (sectslow)
    int knn = 0;          // > 0: adaptive radius from the knn-th nearest photon
};

// A .grd is read as it is (its baked table used when `useBaked`); a .pm is turned into splats
// with `settings` and a grid of DefaultGridFor, summed directly when settings.simple, or
// estimated with an adaptive radius when settings.knn > 0.
LoadedBrdf LoadBrdf(const std::string& path, const PhotonMapSettings& settings, bool useBaked);
// A .grd whatever its name (eval and section read nothing else, from a file or a pipe).
LoadedBrdf LoadGrid(const std::string& path, bool useBaked);

// Options shared by the tools that read photon maps.
void AddNormOption(CLI::App* app, std::string* norm, std::string* horizon);
void AddKnnOption(CLI::App* app, int* knn);
PhotonMapSettings MakeSettings(double spread, double energyMin, const std::string& norm,
                               const std::string& horizon);

void AddMakeCommands(CLI::App& brdf, int* exitCode);  // synth, merge, opt, iopt
void AddViewCommands(CLI::App& brdf, int* exitCode);  // eval, info, section, sectslow, map

}  // namespace gonio::brdfcli
