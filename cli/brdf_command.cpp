// `gonio brdf ...`: the thesis's BRDF tools (Appendix C.3) and the helpers they share. The
// subcommands themselves live in brdf_make_commands.cpp and brdf_view_commands.cpp.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "base/math.h"
#include "brdf_cli.h"
#include "brdfsim/brdf_adaptive.h"
#include "brdfsim/brdf_grid.h"
#include "brdfsim/brdf_report.h"
#include "brdfsim/brdf_simple.h"
#include "brdfsim/photon_map.h"
#include "commands.h"

namespace gonio {

namespace brdfcli {

int RunGuarded(const std::string& name, const std::function<void()>& body) {
    auto fail = [&](const std::exception& e, int code) {
        std::fprintf(stderr, "gonio brdf %s: error: %s\n", name.c_str(), e.what());
        return code;
    };
    try {
        body();
        return 0;
    } catch (const PhotonMapIoError& e) {
        return fail(e, 2);
    } catch (const GrdIoError& e) {
        return fail(e, 2);
    } catch (const PhotonMapError& e) {
        return fail(e, 1);
    } catch (const GrdError& e) {
        return fail(e, 1);
    } catch (const std::invalid_argument& e) {
        return fail(e, 2);
    } catch (const std::exception& e) {
        return fail(e, 2);
    }
}

void RefuseToOverwriteAnInput(const std::vector<std::string>& inputs, const std::string& output) {
    for (const std::string& input : inputs) {
        std::error_code error;  // an output that does not exist yet is no input
        if (std::filesystem::equivalent(input, output, error))
            throw UsageError("the output " + output + " is also an input (" + input +
                             "): writing it would destroy what is being read");
    }
}

double ParseSpread(const std::string& text) {
    const bool degrees = text.size() > 3 && text.compare(text.size() - 3, 3, "deg") == 0;
    const std::string number = degrees ? text.substr(0, text.size() - 3) : text;
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(number, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != number.size() || !(value > 0)) {
        throw UsageError(
            "SPREAD must be a positive radius in radians (0.3) or degrees (17deg), "
            "got '" +
            text + "'");
    }
    return degrees ? value * kPi / 180.0 : value;
}

void ProgressLine::operator()(double fraction) {
    // On a terminal one line counts up; in a log, a line every 25%.
    static const bool terminal = ::isatty(::fileno(stderr));
    const int step = terminal ? 1 : 25;
    const int percent = static_cast<int>(fraction * 100) / step * step;
    if (percent == shown_) return;
    shown_ = percent;
    std::fprintf(stderr, terminal ? "\r%s: %3d%%" : "%s: %3d%%\n", label_.c_str(), percent);
    std::fflush(stderr);
}

void ProgressLine::Finish() {
    if (shown_ >= 0) std::fprintf(stderr, "\r%s: done\n", label_.c_str());
    shown_ = -1;
}

void AddNormOption(CLI::App* app, std::string* norm, std::string* horizon) {
    app->add_option("--norm", *norm, "distance norm: l1, l2 or linf (thesis eqs. 3.4-3.6)")
        ->capture_default_str();
    app->add_option("--horizon", *horizon,
                    "splats at the horizon: reflect (exact) or renormalize (thesis eqs. 4.9-4.10)")
        ->capture_default_str();
}

void AddKnnOption(CLI::App* app, int* knn) {
    app->add_option("--knn", *knn,
                    "photon-map input: adaptive radius, the distance to the K-th nearest photon "
                    "(SPREAD then only scales the splat weights)")
        ->check(CLI::NonNegativeNumber);
}

PhotonMapSettings MakeSettings(double spread, double energyMin, const std::string& norm,
                               const std::string& horizon) {
    PhotonMapSettings settings;
    settings.spread = spread;
    settings.energyMin = energyMin;
    settings.norm = ParseNorm(norm);
    settings.horizon = ParseHorizon(horizon);
    return settings;
}

LoadedBrdf LoadGrid(const std::string& path, bool useBaked) {
    LoadedBrdf loaded;
    loaded.grd = std::make_unique<GrdFile>(ReadGrd(path));
    loaded.brdf = useBaked ? &loaded.grd->Fastest() : loaded.grd->grid.get();
    return loaded;
}

LoadedBrdf LoadBrdf(const std::string& path, const PhotonMapSettings& settings, bool useBaked) {
    if (IsGrdFile(path)) return LoadGrid(path, useBaked);
    LoadedBrdf loaded;
    const PhotonMap map = ReadPhotonMap(path);
    SplatParams params;
    params.radius = settings.spread;
    params.norm = settings.norm;
    params.horizon = settings.horizon;
    params.energyMin = settings.energyMin;
    if (settings.isotropic >= 0) {
        params.isotropic = settings.isotropic;
    } else {
        params.isotropic = true;
        for (std::size_t i = 0; i < map.Size() && params.isotropic; ++i) {
            params.isotropic = map.Row(i)[kPhiIn] == 0.0f;
        }
    }
    auto splats = std::make_shared<const SplatSet>(map, params);
    if (settings.knn > 0) {
        loaded.owned = std::make_unique<BrdfAdaptive>(splats, settings.knn);
    } else if (settings.simple) {
        loaded.owned = std::make_unique<BrdfSimple>(splats);
    } else {
        int rings, rects;
        DefaultGridFor(params.radius, &rings, &rects);
        ProgressLine progress("building the splat grid");
        if (params.isotropic) {
            loaded.owned = std::make_unique<BrdfIsoGrid>(splats, rings, rects, std::ref(progress));
        } else {
            loaded.owned = std::make_unique<BrdfGrid>(splats, rings, rects, std::ref(progress));
        }
        progress.Finish();
    }
    loaded.brdf = loaded.owned.get();
    return loaded;
}

}  // namespace brdfcli

void AddBrdfCommand(CLI::App& app, int* exitCode) {
    CLI::App* brdf = app.add_subcommand(
        "brdf",
        "BRDFs from photon maps: synth, merge, opt, iopt, eval, info, section, sectslow, map");
    brdf->require_subcommand(1);
    brdfcli::AddMakeCommands(*brdf, exitCode);
    brdfcli::AddViewCommands(*brdf, exitCode);
}

}  // namespace gonio
