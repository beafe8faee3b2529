// `gonio spectral info NAME|FILE` and `gonio spectral patches [--lights F2,F11] [--target-de D]`:
// the spectral colour tools (thesis ch. 6). `info` prints a spectrum's range, sampling, XYZ
// (Y = 100) and chromaticity; `patches` measures the colour representations on the CIE test
// colours TCS01-14 under the given lights against 81 samples. Exit status: 0 ok, 1 an error in
// the input (the message names it), 2 a bad command line.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "spectral/colorimetry.h"
#include "spectral/named_spectra.h"
#include "spectral/patch_analysis.h"
#include "spectral/render_color_space.h"
#include "spectral/spectral_error.h"
#include "spectral_cli.h"

namespace gonio {
namespace {

using namespace gonio::spectral;

// The part of the CIE 15 reference grid (380-780 nm at 5 nm) the spectrum covers.
WavelengthGrid InfoGrid(const Spectrum& spectrum) {
    const WavelengthGrid reference = ReferenceGrid();
    const double start =
        std::max(reference.start,
                 std::ceil(spectrum.MinWavelength() / reference.step - 1e-9) * reference.step);
    const double end =
        std::min(reference.end,
                 std::floor(spectrum.MaxWavelength() / reference.step + 1e-9) * reference.step);
    if (!(end > start))
        throw SpectralError("the spectrum does not overlap 380-780 nm: it has no colour");
    return WavelengthGrid::Make(start, end, reference.step);
}

void RunInfo(const std::string& nameOrPath) {
    const Spectrum spectrum = LookupSpectrum(nameOrPath);
    const WavelengthGrid grid = InfoGrid(spectrum);
    const Xyz xyz = EmissiveXyz(spectrum, SampleObserver(NamedObserver("CIE1931"), grid));
    const Eigen::Vector2d xy = Chromaticity(xyz);
    std::printf("%s\n", nameOrPath.c_str());
    std::printf("  range     %g-%g nm\n", spectrum.MinWavelength(), spectrum.MaxWavelength());
    std::printf("  sampling  %s\n", spectrum.DescribeSampling().c_str());
    std::printf(
        "  XYZ       %.4f %.4f %.4f  (CIE 1931 2°, summed over %g-%g nm at %g nm, Y = 100)\n",
        xyz.x(), xyz.y(), xyz.z(), grid.start, grid.end, grid.step);
    std::printf("  xy        %.5f %.5f\n", xy.x(), xy.y());
    if (grid.start != ReferenceGrid().start || grid.end != ReferenceGrid().end) return;
    // What a spectral render displays for it (E white adapted to D65), and so what an RGB scene
    // would give for it: the RGB to match (gonio spectral match) to make a metamer.
    const Rgb rgb = DisplayRgb(spectrum) / LinearSrgbToXyz(DisplayRgb(spectrum)).y();
    std::printf("  RGB       %.5f %.5f %.5f  (linear sRGB as a spectral render shows it, Y = 1)\n",
                rgb[0], rgb[1], rgb[2]);
}

std::vector<std::string> SplitCommas(const std::string& text) {
    std::vector<std::string> parts;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find(',', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) parts.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return parts;
}

void PrintRow(const std::string& light, const RepresentationError& e, const std::string& note) {
    std::printf("%-10s %-22s %8.3f %8.3f %10.3f %8.3f%s%s\n", light.c_str(),
                RepresentationName(e.kind, e.k).c_str(), e.oneBounce.mean, e.oneBounce.max,
                e.twoBounce.mean, e.twoBounce.max, note.empty() ? "" : "  ", note.c_str());
}

}  // namespace

void PrintRepresentationErrors(const std::vector<std::string>& lights,
                               const std::vector<PatchScene>& scenes, double targetDe) {
    const int bandsK = SmallestK(scenes, RepresentationKind::Bands, targetDe);
    const int svdK = SmallestK(scenes, RepresentationKind::SvdExactDirect, targetDe);
    std::printf("k: the smallest meeting mean ΔE2000 ≤ %g (one- and two-bounce, every light).\n\n",
                targetDe);
    std::printf("%-10s %-22s %8s %8s %10s %8s\n", "light", "representation", "1b mean", "1b max",
                "2b mean", "2b max");
    const int most = MaxK(scenes.front(), RepresentationKind::SvdExactDirect);
    for (size_t l = 0; l < scenes.size(); ++l) {
        const PatchScene& scene = scenes[l];
        PrintRow(lights[l], EvaluateRepresentation(scene, RepresentationKind::Rgb, 3), "");
        if (bandsK > 0)
            PrintRow(lights[l], EvaluateRepresentation(scene, RepresentationKind::Bands, bandsK),
                     "smallest k");
        else
            std::printf("%-10s bands-k: no k up to %d meets the target\n", lights[l].c_str(),
                        MaxK(scene, RepresentationKind::Bands));
        const int k = svdK > 0 ? svdK : most;
        PrintRow(lights[l], EvaluateRepresentation(scene, RepresentationKind::SvdExactDirect, k),
                 svdK > 0 ? "smallest k" : "no k meets the target; k = all surfaces");
        PrintRow(lights[l], EvaluateRepresentation(scene, RepresentationKind::SvdRendered, k),
                 "as basis \"svd\" renders it: second bounce component-wise");
        PrintRow(lights[l], EvaluateRepresentation(scene, RepresentationKind::SvdEq69, k),
                 "thesis eq. 6.9 as written: wrong for an SVD basis");
        // The k the patch test (tests/spectral) checks, for comparison.
        if (bandsK != 16 && MaxK(scene, RepresentationKind::Bands) >= 16)
            PrintRow(lights[l], EvaluateRepresentation(scene, RepresentationKind::Bands, 16),
                     "the patch test's k");
        if (svdK != 6 && most >= 6)
            PrintRow(lights[l],
                     EvaluateRepresentation(scene, RepresentationKind::SvdExactDirect, 6),
                     "the patch test's k");
    }
}

namespace {

void RunPatches(const std::string& lightList, double targetDe) {
    const std::vector<std::string> lights = SplitCommas(lightList);
    if (lights.empty()) throw SpectralError("--lights names no light");
    std::printf(
        "CIE test colours TCS01-TCS14; reference: 81 samples at 5 nm, 380-780 nm; CIE 1931 2°.\n"
        "ΔE2000 in CIELAB relative to each light's white; two-bounce: all 196 ordered pairs.\n");
    PrintRepresentationErrors(lights, TestColourScenes(lights), targetDe);
}

}  // namespace

void RunSpectralGuarded(int* exitCode, const std::function<void()>& body) {
    try {
        body();
        *exitCode = 0;
    } catch (const std::exception& e) {
        const std::string text = e.what();
        // Located messages already read `file:line: error: ...`.
        if (text.find(": error: ") != std::string::npos)
            std::fprintf(stderr, "%s\n", text.c_str());
        else
            std::fprintf(stderr, "gonio spectral: error: %s\n", text.c_str());
        *exitCode = 1;
    }
}

void AddSpectralCommand(CLI::App& app, int* exitCode) {
    CLI::App* command =
        app.add_subcommand("spectral", "Spectral colour: spectra, colorimetry, representations");
    command->require_subcommand(1);

    CLI::App* info = command->add_subcommand(
        "info", "Print a spectrum's range, sampling, XYZ (Y = 100) and chromaticity xy");
    auto name = std::make_shared<std::string>();
    info->add_option("spectrum", *name,
                     "a named spectrum (D65, A, F1..F12, TCS01..TCS15, CIE1931, blackbody:6500, "
                     "...) or a file (.sp/.cmf CGATS, or the thesis's cspec/curve format)")
        ->required();
    info->callback([name, exitCode] { RunSpectralGuarded(exitCode, [&] { RunInfo(*name); }); });

    CLI::App* patches = command->add_subcommand(
        "patches", "Measure rgb, bands-k and svd-k on the CIE test colours TCS01-14 (ΔE2000)");
    auto lights = std::make_shared<std::string>("F2,F11");
    auto target = std::make_shared<double>(0.5);
    patches->add_option("--lights", *lights, "comma-separated lights (names or files)")
        ->capture_default_str();
    patches->add_option("--target-de", *target, "the mean ΔE2000 the smallest k must meet")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    patches->callback([lights, target, exitCode] {
        RunSpectralGuarded(exitCode, [&] { RunPatches(*lights, *target); });
    });
    AddSpectralAnalyzeCommand(*command, exitCode);
    AddSpectralDiffCommand(*command, exitCode);
    AddSpectralMatchCommand(*command, exitCode);
}

}  // namespace gonio
