// Option "spectral" (a RIB extension, docs/rib-support.md): the representation of colour.
//
//   Option "spectral" "string basis" "sampled" "float[2] range" [380 780] "float step" [5]
//                     "int bands" [16]
//
// "sampled": one colour component per wavelength of the range (81 at 5 nm over 380-780 nm by
// default), with ColorSamples' matrices from spectral/render_color_space.h, so that every
// shader, photon map and .grd carries spectra unchanged. "bands": "bands" averages over bands of
// those samples, the bands chosen for each frame from its own spectra (band_plan.h). "rgb": three
// components, as without the option, and a colour given as a spectrum is reduced to its RGB, as an
// RGB renderer does. The error of each is measured by `gonio spectral patches`.

#include "base/limits.h"
#include "renderer/scene/scene_builder_state.h"
#include "renderer/scene/scene_spectra.h"
#include "spectral/render_color_space.h"
#include "spectral/spectral_error.h"

namespace gonio {

void SceneBuilder::SetColorComponents(int n, std::vector<float> toRgb, std::vector<float> fromRgb,
                                      std::vector<double> wavelengths) {
    state_->options.colorComponents = n;
    state_->options.colorToRgb = std::move(toRgb);
    state_->options.colorFromRgb = std::move(fromRgb);
    state_->options.wavelengths = std::move(wavelengths);
    state_->options.colorFromSamples.clear();
    state_->options.spectraAsRgb = false;
    state_->options.bands = 0;
    MutableAttributes().color.assign(n, 1.f);
    MutableAttributes().opacity.assign(n, 1.f);
}

void SceneBuilder::SetColorSpace(const spectral::RenderColorSpace& space, int bands) {
    SetColorComponents(int(space.toRgb.size() / 3), space.toRgb, space.fromRgb,
                       space.grid.Wavelengths());
    state_->options.colorFromSamples = space.fromSamples;
    state_->options.bands = bands;
}

void SceneBuilder::SetBandPlan(BandPlan plan) { state_->bandPlan = std::move(plan); }

void SceneBuilder::SpectralOption(const ParamDict& params, const FileLoc& loc) {
    const std::string basis = params.GetString("basis", "sampled");
    if (basis == "rgb") {
        SetColorComponents(3, {}, {}, {});
        state_->options.spectraAsRgb = true;
        return;
    }
    if (basis != "sampled" && basis != "bands") {
        diagnostics_.Error(params.Location("basis"),
                           "Option \"spectral\": basis \"" + basis +
                               "\" is not one a render can use (expected \"sampled\", \"bands\" "
                               "or \"rgb\"; `gonio spectral patches` measures svd)");
        return;
    }
    const int bands = basis == "bands" ? int(params.GetNumber("bands", 16)) : 0;
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
        if (basis == "bands" && (bands < 1 || bands > grid.Count())) {
            diagnostics_.Error(params.Location("bands"),
                               "Option \"spectral\": \"bands\" must be 1 to the " +
                                   std::to_string(grid.Count()) + " samples of the range");
            return;
        }
        SetColorSpace(spectral::SampledColorSpace(grid), bands);
    } catch (const spectral::SpectralError& e) {
        diagnostics_.Error(params.FirstLocation().line ? params.FirstLocation() : loc,
                           std::string("Option \"spectral\": ") + e.what());
    }
}

void SceneBuilder::ApplyBandPlan(int ordinal) {
    if (state_->options.bands == 0) return;
    const spectral::WavelengthGrid grid = FrameGrid(state_->options);
    const auto choice = state_->bandPlan.find(ordinal);
    if (choice == state_->bandPlan.end()) {
        // Not chosen yet: built sampled, for ChooseBands.
        SetColorSpace(spectral::SampledColorSpace(grid), state_->options.bands);
        return;
    }
    const std::vector<double>& light = choice->second.light;
    SetColorSpace(spectral::BandColorSpace(
                      grid, choice->second.edges,
                      Eigen::Map<const Eigen::VectorXd>(light.data(), Eigen::Index(light.size()))),
                  state_->options.bands);
}

}  // namespace gonio
