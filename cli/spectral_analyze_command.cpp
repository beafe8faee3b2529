// gonio spectral analyze SCENE.rib [--target-de D]: the colour error of each representation on
// the scene's own lights and surfaces, the thesis's principle of a colour space adapted to the
// scene (§6.1.2-6.1.3). The scene uses Option "spectral" "basis" "sampled"; its lights are the
// "lightcolor" of its light sources (a spectrum, RGB uplifted, or white), its surfaces the
// distinct Color of its shapes; one- and two-bounce paths among them, each light on its own.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"
#include "renderer/scene/scene_spectra.h"
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

void RunAnalyze(const std::string& scene, double targetDe) {
    const Frame frame = FirstFrame(scene);
    if (frame.options.wavelengths.size() < 2 || !frame.options.colorFromSamples.empty())
        throw spectral::SpectralError(scene +
                                      ": analyze needs Option \"spectral\" \"basis\" \"sampled\"");
    const SceneSpectra spectra = CollectSceneSpectra(frame);
    if (spectra.surfaces.empty() || spectra.lights.empty())
        throw spectral::SpectralError(scene + ": analyze needs at least one light and one shape");
    const spectral::Observer observer = spectral::NamedObserver("CIE1931");
    const Spectrum d65 = spectral::NamedSpectrum("D65");
    std::vector<spectral::PatchScene> scenes;
    for (const Spectrum& light : spectra.lights)
        scenes.push_back(
            spectral::MakePatchScene(light, spectra.surfaces, observer, d65, spectra.grid));
    const std::vector<double> nm = spectra.grid.Wavelengths();
    std::printf(
        "%s: %zu light(s), %zu surface colour(s); reference: the scene's %zu samples, "
        "%g-%g nm.\nΔE2000 in CIELAB relative to each light's white; two-bounce: all "
        "%zu ordered pairs.\n",
        scene.c_str(), scenes.size(), spectra.surfaces.size(), nm.size(), nm.front(), nm.back(),
        spectra.surfaces.size() * spectra.surfaces.size());
    PrintRepresentationErrors(spectra.lightLabels, scenes, targetDe);
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
