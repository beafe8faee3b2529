#include "renderer/scene/scene_spectra.h"

#include "renderer/rib/declarations.h"
#include "renderer/scene/scene_colors.h"
#include "spectral/spectral_error.h"

namespace gonio {
namespace {

using spectral::Spectrum;

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

}  // namespace

spectral::WavelengthGrid FrameGrid(const Options& options) {
    const std::vector<double>& nm = options.wavelengths;
    if (nm.size() < 2) throw spectral::SpectralError("the frame is not spectral");
    return spectral::WavelengthGrid::Make(nm.front(), nm.back(), nm[1] - nm[0]);
}

SceneSpectra CollectSceneSpectra(const Frame& frame) {
    SceneSpectra spectra;
    spectra.grid = FrameGrid(frame.options);
    for (const SceneLight& light : frame.lights) {
        spectra.lightLabels.push_back(light.light.shader.name + " " + light.light.handle.text);
        spectra.lights.push_back(LightSpectrum(frame, light, spectra.grid));
    }
    spectra.surfaces = SurfaceSpectra(frame, spectra.grid);
    return spectra;
}

}  // namespace gonio
