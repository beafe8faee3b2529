// gonio spectral analyze SCENE.rib [--target-de D]: the colour error of each representation on
// the scene's own lights and surfaces, the thesis's principle of a colour space adapted to the
// scene (§6.1.2-6.1.3). The scene uses Option "spectral" "basis" "sampled"; its lights are the
// "lightcolor" of its light sources (a spectrum, RGB uplifted, or white), its surfaces the
// distinct Color of its shapes; one- and two-bounce paths among them, each light on its own.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "renderer/rib/declarations.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"
#include "renderer/scene/scene_colors.h"
#include "spectral/named_spectra.h"
#include "spectral/spectral_error.h"
#include "spectral_cli.h"

namespace gonio {
namespace {

using spectral::Spectrum;

// The scene's first frame, or an exception naming why there is none.
Frame FirstFrame(const std::string& scene) {
    Diagnostics diagnostics;
    std::unique_ptr<Frame> first;
    SceneBuilder builder(scene, diagnostics, [&](const Frame& frame) {
        if (!first) first = std::make_unique<Frame>(frame);
    });
    ParseRibFile(scene, builder, diagnostics);
    builder.Finish(FileLoc{std::make_shared<const std::string>(scene), 0, 0});
    if (diagnostics.ErrorCount() > 0)
        throw spectral::SpectralError(scene + ": the scene has errors (above)");
    if (!first) throw spectral::SpectralError(scene + ": no frame (WorldBegin ... WorldEnd)");
    return *first;
}

Spectrum OnGrid(const spectral::WavelengthGrid& grid, const std::vector<float>& samples) {
    return Spectrum::OnGrid(grid, std::vector<double>(samples.begin(), samples.end()));
}

// A light source's colour: its "lightcolor" as the scene gives it, else white.
Spectrum LightSpectrum(const Frame& frame, const SceneLight& light,
                       const spectral::WavelengthGrid& grid) {
    std::vector<float> colour(frame.options.wavelengths.size(), 1.0f);
    for (const Param& p : light.light.shader.params) {
        if (TokenName(p.token) != "lightcolor") continue;
        std::string error;
        if (!SceneColorsFromParam(frame.options, p, 1, &colour, &error))
            throw spectral::SpectralError(p.loc.ToString() + ": error: " + error);
    }
    return OnGrid(grid, colour);
}

// The distinct Color of the frame's shapes.
std::vector<Spectrum> SurfaceSpectra(const Frame& frame, const spectral::WavelengthGrid& grid) {
    std::vector<std::vector<float>> seen;
    auto add = [&](const Attributes& attributes) {
        for (const auto& colour : seen)
            if (colour == attributes.color) return;
        seen.push_back(attributes.color);
    };
    for (const SceneShape& shape : frame.shapes) add(*shape.attributes);
    for (const ObjectInstanceUse& use : frame.instances)
        for (const auto& attributes : use.shapeAttributes) add(*attributes);
    std::vector<Spectrum> spectra;
    for (const auto& colour : seen) spectra.push_back(OnGrid(grid, colour));
    return spectra;
}

void RunAnalyze(const std::string& scene, double targetDe) {
    const Frame frame = FirstFrame(scene);
    const std::vector<double>& nm = frame.options.wavelengths;
    if (nm.size() < 2)
        throw spectral::SpectralError(scene +
                                      ": analyze needs Option \"spectral\" \"basis\" \"sampled\"");
    const spectral::WavelengthGrid grid =
        spectral::WavelengthGrid::Make(nm.front(), nm.back(), nm[1] - nm[0]);
    const std::vector<Spectrum> surfaces = SurfaceSpectra(frame, grid);
    if (surfaces.empty() || frame.lights.empty())
        throw spectral::SpectralError(scene + ": analyze needs at least one light and one shape");
    const spectral::Observer observer = spectral::NamedObserver("CIE1931");
    const Spectrum d65 = spectral::NamedSpectrum("D65");
    std::vector<std::string> labels;
    std::vector<spectral::PatchScene> scenes;
    for (const SceneLight& light : frame.lights) {
        labels.push_back(light.light.shader.name + " " + light.light.handle.text);
        scenes.push_back(spectral::MakePatchScene(LightSpectrum(frame, light, grid), surfaces,
                                                  observer, d65, grid));
    }
    std::printf(
        "%s: %zu light(s), %zu surface colour(s); reference: the scene's %zu samples, "
        "%g-%g nm.\nΔE2000 in CIELAB relative to each light's white; two-bounce: all "
        "%zu ordered pairs.\n",
        scene.c_str(), scenes.size(), surfaces.size(), nm.size(), nm.front(), nm.back(),
        surfaces.size() * surfaces.size());
    PrintRepresentationErrors(labels, scenes, targetDe);
}

}  // namespace

void AddSpectralAnalyzeCommand(CLI::App& spectral, int* exitCode) {
    CLI::App* analyze = spectral.add_subcommand(
        "analyze", "Measure rgb, bands-k and svd-k on a scene's own lights and surfaces");
    auto scene = std::make_shared<std::string>();
    auto target = std::make_shared<double>(0.5);
    analyze->add_option("scene", *scene, "a RIB file with Option \"spectral\"")->required();
    analyze->add_option("--target-de", *target, "the mean ΔE2000 the smallest k must meet")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    analyze->callback([scene, target, exitCode] {
        RunSpectralGuarded(exitCode, [&] { RunAnalyze(*scene, *target); });
    });
}

}  // namespace gonio
