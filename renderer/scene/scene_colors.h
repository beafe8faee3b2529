#pragma once
// How a colour given in a scene becomes the frame's n colour components: n numbers as they are;
// under Option "spectral", also 3 numbers (RGB, uplifted by ColorSamples' RGBn matrix: RISpec's
// own linear map, spectral/render_color_space.h) or a named spectrum or spectrum file sampled
// at the frame's wavelengths.

#include <string>
#include <vector>

#include "renderer/rib/param_list.h"
#include "renderer/scene/options.h"

namespace gonio {

// `values` holds `count` colours of the options' components, or of RGB when the frame is
// spectral; false (with *error saying what was expected) otherwise.
bool SceneColorsFromNumbers(const Options& options, const std::vector<float>& values, int count,
                            std::vector<float>* out, std::string* error);

// A named spectrum ("F11", "TCS09", "blackbody:3200") or a spectrum file, at the frame's
// wavelengths (under "basis" "rgb": its RGB, as an RGB renderer is given it); false (with *error,
// naming the file and line for a bad file) when the frame is not spectral or the spectrum
// cannot be read or does not cover them.
bool SceneColorFromSpectrum(const Options& options, const std::string& nameOrFile,
                            std::vector<float>* out, std::string* error);

// A colour parameter as the RIB gives it: `count` colours of numbers (SceneColorsFromNumbers)
// or one spectrum name or file (SceneColorFromSpectrum).
bool SceneColorsFromParam(const Options& options, const Param& param, int count,
                          std::vector<float>* out, std::string* error);

}  // namespace gonio
