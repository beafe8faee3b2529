// Option "spectral" (a RIB extension, docs/rib-support.md): the representation of colour.
//
//   Option "spectral" "string basis" "sampled" "float[2] range" [380 780] "float step" [5]
//                     "int bands" [16] "int vectors" [6]
//
// "sampled": one colour component per wavelength of the range (81 at 5 nm over 380-780 nm by
// default), with ColorSamples' matrices from spectral/render_color_space.h, so that every
// shader, photon map and .grd carries spectra unchanged. "bands": "bands" averages over bands of
// those samples; "svd": "vectors" coordinates per light spectrum in a basis of what it makes the
// surfaces reflect; both chosen for each frame from its own spectra (color_plan.h). "rgb": three
// components, as without the option, and a colour given as a spectrum is reduced to its RGB, as
// an RGB renderer does. The error of each is measured by `gonio spectral patches`.

#include <algorithm>
#include <utility>

#include "base/limits.h"
#include "renderer/rib/declarations.h"
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
    state_->options.bands = state_->options.svdVectors = 0;  // ColorSamples fixes the components
    MutableAttributes().color.assign(n, 1.f);
    MutableAttributes().opacity.assign(n, 1.f);
}

void SceneBuilder::SetColorSpace(const spectral::RenderColorSpace& space) {
    SetColorComponents(int(space.toRgb.size() / 3), space.toRgb, space.fromRgb,
                       space.grid.Wavelengths());
    state_->options.colorFromSamples = space.fromSamples;
}

void SceneBuilder::SetColorPlan(ColorPlan plan) { state_->colorPlan = std::move(plan); }

void SceneBuilder::SpectralOption(const ParamDict& params, const FileLoc& loc) {
    const std::string basis = params.GetString("basis", "sampled");
    if (basis == "rgb") {
        SetColorComponents(3, {}, {}, {});
        state_->options.spectraAsRgb = true;
        return;
    }
    if (basis != "sampled" && basis != "bands" && basis != "svd") {
        diagnostics_.Error(params.Location("basis"),
                           "Option \"spectral\": basis \"" + basis +
                               "\" is not one a render can use (expected \"sampled\", \"bands\", "
                               "\"svd\" or \"rgb\")");
        return;
    }
    const int bands = basis == "bands" ? int(params.GetNumber("bands", 16)) : 0;
    const int vectors = basis == "svd" ? int(params.GetNumber("vectors", 6)) : 0;
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
        const auto [countName, count] =
            basis == "bands" ? std::pair{"bands", bands} : std::pair{"vectors", vectors};
        if (basis != "sampled" && (count < 1 || count > grid.Count())) {
            diagnostics_.Error(params.Location(countName), std::string("Option \"spectral\": \"") +
                                                               countName + "\" must be 1 to the " +
                                                               std::to_string(grid.Count()) +
                                                               " samples of the range");
            return;
        }
        SetColorSpace(spectral::SampledColorSpace(grid));
        state_->options.bands = bands;
        state_->options.svdVectors = vectors;
    } catch (const spectral::SpectralError& e) {
        diagnostics_.Error(params.FirstLocation().line ? params.FirstLocation() : loc,
                           std::string("Option \"spectral\": ") + e.what());
    }
}

void SceneBuilder::ApplyColorPlan(int ordinal) {
    state_->colorChoice = nullptr;
    if (!state_->options.FitsColorSpaceToFrame()) return;
    const auto choice = state_->colorPlan.find(ordinal);
    const int bands = state_->options.bands, vectors = state_->options.svdVectors;
    if (choice == state_->colorPlan.end()) {
        // Not chosen yet: built sampled, for ChooseColorSpace.
        SetColorSpace(spectral::SampledColorSpace(FrameGrid(state_->options)));
    } else {
        SetColorSpace(choice->second.space);
        state_->colorChoice = &choice->second;
    }
    // The next frame that asks for it is fitted to its own spectra again.
    state_->options.bands = bands, state_->options.svdVectors = vectors;
}

void SceneBuilder::ApplyPlannedLightColor(int index, LightInstance* light) const {
    if (!state_->colorChoice || state_->colorChoice->lightColors.empty()) return;
    const std::vector<float>& colour = state_->colorChoice->lightColors.at(size_t(index));
    Param planned{"color lightcolor",
                  std::vector<double>(colour.begin(), colour.end()),
                  {},
                  false,
                  light->shader.loc};
    ParamList& params = light->shader.params;
    for (Param& p : params)
        if (TokenName(p.token) == "lightcolor") p = planned;
    if (std::none_of(params.begin(), params.end(),
                     [](const Param& p) { return TokenName(p.token) == "lightcolor"; }))
        params.push_back(planned);
}

}  // namespace gonio
