// Option "spectral" (a RIB extension, docs/rib-support.md): the representation of colour.
//
//   Option "spectral" "string basis" "sampled" "float[2] range" [380 780] "float step" [5]
//
// "sampled": one colour component per wavelength of the range (81 at 5 nm over 380-780 nm by
// default), with ColorSamples' matrices from spectral/render_color_space.h, so that every
// shader, photon map and .grd carries spectra unchanged. "rgb": three components, as without
// the option, and a colour given as a spectrum is reduced to its RGB, as an RGB renderer does. The
// error of either is measured by `gonio spectral patches`.

#include "base/limits.h"
#include "renderer/scene/scene_builder_state.h"
#include "spectral/render_color_space.h"
#include "spectral/spectral_error.h"

namespace gonio {

void SceneBuilder::SetColorComponents(int n, std::vector<float> toRgb, std::vector<float> fromRgb,
                                      std::vector<double> wavelengths) {
    state_->options.colorComponents = n;
    state_->options.colorToRgb = std::move(toRgb);
    state_->options.colorFromRgb = std::move(fromRgb);
    state_->options.wavelengths = std::move(wavelengths);
    state_->options.spectraAsRgb = false;
    MutableAttributes().color.assign(n, 1.f);
    MutableAttributes().opacity.assign(n, 1.f);
}

void SceneBuilder::SpectralOption(const ParamDict& params, const FileLoc& loc) {
    const std::string basis = params.GetString("basis", "sampled");
    if (basis == "rgb") {
        SetColorComponents(3, {}, {}, {});
        state_->options.spectraAsRgb = true;
        return;
    }
    if (basis != "sampled") {
        diagnostics_.Error(params.Location("basis"),
                           "Option \"spectral\": basis \"" + basis +
                               "\" is not one a render can use yet (expected \"sampled\" or "
                               "\"rgb\"; `gonio spectral patches` measures bands and svd)");
        return;
    }
    double start = 380, end = 780;
    if (const TypedParam* range = params.Find("range")) {
        if (range->numbers.size() != 2) {
            diagnostics_.Error(params.Location("range"),
                               "Option \"spectral\": \"range\" expects 2 numbers (nm)");
            return;
        }
        start = range->numbers[0], end = range->numbers[1];
    }
    try {
        const spectral::WavelengthGrid grid =
            spectral::WavelengthGrid::Make(start, end, params.GetNumber("step", 5));
        if (grid.Count() > kMaxColorComponents) {
            diagnostics_.Error(loc, "Option \"spectral\": " + std::to_string(grid.Count()) +
                                        " samples, at most " + std::to_string(kMaxColorComponents) +
                                        " (a larger step?)");
            return;
        }
        const spectral::RenderColorSpace space = spectral::SampledColorSpace(grid);
        SetColorComponents(grid.Count(), space.toRgb, space.fromRgb, grid.Wavelengths());
    } catch (const spectral::SpectralError& e) {
        diagnostics_.Error(params.FirstLocation().line ? params.FirstLocation() : loc,
                           std::string("Option \"spectral\": ") + e.what());
    }
}

}  // namespace gonio
