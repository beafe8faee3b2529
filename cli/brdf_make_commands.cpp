// `gonio brdf synth | merge | opt | iopt`: photon maps made and combined, and turned into
// optimised splat grids (thesis GPBRDFOpt, GPIBRDFOpt).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/limits.h"
#include "brdf_cli.h"
#include "brdfsim/analytic_brdf.h"
#include "brdfsim/baked_table.h"
#include "brdfsim/brdf_grid.h"
#include "brdfsim/grd_file.h"
#include "brdfsim/photon_map.h"
#include "brdfsim/photon_map_merge.h"
#include "brdfsim/synth.h"

namespace gonio::brdfcli {

namespace {

// Checked on the text, before CLI11 converts it: an unsigned option would take -5 as 2^64 - 5
// and trace paths for ever.
std::string PositiveCount(const std::string& text) {
    const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
    if (digits && text.find_first_not_of('0') != std::string::npos) return {};
    return "must be a positive whole number, got '" + text + "'";
}

void AddSynth(CLI::App& brdf, int* exitCode) {
    auto* cmd = brdf.add_subcommand(
        "synth", "draw a synthetic photon map from lambert:ALBEDO or phong:KD,KS,EXPONENT");
    auto model = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    auto options = std::make_shared<SynthOptions>();
    auto brdfSampling = std::make_shared<bool>(false);
    cmd->add_option("MODEL", *model, "lambert:ALBEDO or phong:KD,KS,EXPONENT")->required();
    cmd->add_option("-n,--paths", options->paths, "photon paths to trace")
        ->required()
        ->check(PositiveCount);
    cmd->add_option("--seed", options->seed, "random seed")->capture_default_str();
    cmd->add_flag("--isotropic", options->isotropic, "phi_in = 0, theta_in uniform (for iopt)");
    cmd->add_flag("--stratified", options->stratified,
                  "low-discrepancy points instead of independent random numbers");
    cmd->add_option("--components", options->ncomps, "colour values per photon")
        ->capture_default_str()
        ->check(CLI::Range(1, kMaxColorComponents));
    cmd->add_flag("--brdf-sampling", *brdfSampling,
                  "exits from the BRDF's importance sampling alone, as a tracer draws them");
    cmd->add_option("-o,--output", *out, "output photon map (.pm)")->required();
    cmd->callback([=] {
        *exitCode = RunGuarded("synth", [&] {
            options->defensive = !*brdfSampling;
            const AnalyticBrdf analytic = AnalyticBrdf::Parse(*model);
            if (options->paths < 1) throw UsageError("-n must be at least 1");
            const PhotonMapHeader header = WriteSyntheticPhotonMap(analytic, *options, *out);
            std::printf("%s: %llu photons of %llu paths from %s\n", out->c_str(),
                        static_cast<unsigned long long>(header.count),
                        static_cast<unsigned long long>(header.paths), model->c_str());
        });
    });
}

// The bounce counts `--bounces` keeps: "N" or "N:M" (inclusive).
BounceRange ParseBounceRange(const std::string& text) {
    BounceRange range;
    const std::size_t colon = text.find(':');
    try {
        std::size_t used = 0;
        range.low = static_cast<std::uint32_t>(std::stoul(text.substr(0, colon), &used));
        if (used != std::min(colon, text.size())) throw std::invalid_argument(text);
        range.high = range.low;
        if (colon != std::string::npos) {
            range.high = static_cast<std::uint32_t>(std::stoul(text.substr(colon + 1), &used));
            if (used != text.size() - colon - 1) throw std::invalid_argument(text);
        }
    } catch (const std::logic_error&) {
        throw UsageError("--bounces: expected N or N:M (bounce counts), got '" + text + "'");
    }
    if (range.low > range.high)
        throw UsageError("--bounces: expected N <= M in N:M, got '" + text + "'");
    return range;
}

void AddMerge(CLI::App& brdf, int* exitCode) {
    auto* cmd = brdf.add_subcommand("merge", "combine photon maps of several runs into one");
    auto inputs = std::make_shared<std::vector<std::string>>();
    auto out = std::make_shared<std::string>();
    auto bounces = std::make_shared<std::string>();
    cmd->add_option("INPUTS", *inputs, "photon maps (.pm)")->required()->expected(1, -1);
    cmd->add_option("-o,--output", *out, "output photon map (.pm)")->required();
    cmd->add_option("--bounces", *bounces,
                    "keep only photons scattered N times (N:M: N to M times); the inputs need "
                    "bounce tags, and every traced path still counts");
    cmd->callback([=] {
        *exitCode = RunGuarded("merge", [&] {
            RefuseToOverwriteAnInput(*inputs, *out);
            const BounceRange range = bounces->empty() ? BounceRange{} : ParseBounceRange(*bounces);
            const PhotonMapHeader total =
                MergePhotonMaps(*inputs, *out, bounces->empty() ? nullptr : &range);
            std::printf("%s: %llu photons of %llu paths from %zu maps\n", out->c_str(),
                        static_cast<unsigned long long>(total.count),
                        static_cast<unsigned long long>(total.paths), inputs->size());
        });
    });
}

struct OptArgs {
    int rings = 0, rects = 0;
    std::string spread, input, output, norm = "l2", horizon = "reflect";
    double energyMin = 0.0;
    int bake = 0;
};

void RunOpt(const OptArgs& args, bool isotropic) {
    const auto start = std::chrono::steady_clock::now();
    SplatParams params;
    params.radius = ParseSpread(args.spread);
    params.energyMin = args.energyMin;
    params.norm = ParseNorm(args.norm);
    params.horizon = ParseHorizon(args.horizon);
    params.isotropic = isotropic;
    if (args.rings < 1 || args.rects < 1) throw UsageError("RINGS and RECTS must be at least 1");
    RefuseToOverwriteAnInput({args.input}, args.output);
    std::fprintf(stderr, "reading %s\n", args.input.c_str());
    const PhotonMap map = ReadPhotonMap(args.input);
    auto splats = std::make_shared<const SplatSet>(map, params);
    ProgressLine progress(isotropic ? "iopt: splat lists" : "opt: splat lists");
    std::unique_ptr<Brdf> grid;
    const CellLists* lists;
    if (isotropic) {
        auto iso =
            std::make_unique<BrdfIsoGrid>(splats, args.rings, args.rects, std::ref(progress));
        lists = &iso->Lists();
        grid = std::move(iso);
    } else {
        auto full = std::make_unique<BrdfGrid>(splats, args.rings, args.rects, std::ref(progress));
        lists = &full->Lists();
        grid = std::move(full);
    }
    progress.Finish();
    std::unique_ptr<BakedTable> baked;
    if (args.bake > 0) {
        ProgressLine bakeProgress("baking the table");
        baked = std::make_unique<BakedTable>(*grid, args.bake, std::ref(bakeProgress));
        bakeProgress.Finish();
    }
    WriteGrd(args.output, *splats, args.rings, args.rects, *lists, baked.get());
    const GridStats stats = ComputeGridStats(*lists, splats->Size());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "%s: %zu splats (%s, R = %.4f rad, %s), %zu cells, %.1f splats per cell "
        "(ratio %.4f), %.1f MB, %.2f s\n",
        args.output.c_str(), splats->Size(), isotropic ? "isotropic" : "anisotropic", params.radius,
        NormName(params.norm), stats.cells, stats.averageSplats, stats.ratio,
        (grid->MemoryBytes() + (baked ? baked->MemoryBytes() : 0)) / 1e6, seconds);
}

void AddOpt(CLI::App& brdf, int* exitCode, bool isotropic) {
    const char* name = isotropic ? "iopt" : "opt";
    auto* cmd = brdf.add_subcommand(
        name, isotropic ? "optimise an isotropic photon map into a .grd (GPIBRDFOpt)"
                        : "optimise a photon map into a 4D splat grid .grd (GPBRDFOpt)");
    auto args = std::make_shared<OptArgs>();
    cmd->add_option("RINGS", args->rings, "bands per hemisphere (θ_in ranges for iopt)")
        ->required();
    cmd->add_option("RECTS", args->rects, "cells in the widest band")->required();
    cmd->add_option("SPREAD", args->spread, "splat radius: radians, or degrees as 17deg")
        ->required();
    cmd->add_option("ENERGY_MIN", args->energyMin, "photons with less energy are skipped")
        ->required();
    cmd->add_option("INPUT", args->input, "photon map (.pm)")->required();
    cmd->add_option("OUTPUT", args->output, "output grid (.grd)")->required();
    AddNormOption(cmd, &args->norm, &args->horizon);
    cmd->add_option("--bake", args->bake, "also store a baked table with RES θ nodes")
        ->check(CLI::Range(0, 256));
    cmd->callback([=] { *exitCode = RunGuarded(name, [&] { RunOpt(*args, isotropic); }); });
}

}  // namespace

void AddMakeCommands(CLI::App& brdf, int* exitCode) {
    AddSynth(brdf, exitCode);
    AddMerge(brdf, exitCode);
    AddOpt(brdf, exitCode, false);
    AddOpt(brdf, exitCode, true);
}

}  // namespace gonio::brdfcli
