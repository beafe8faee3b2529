#pragma once
// The named CIE illuminants as the editor's presets (spectral/named_spectra.h).

#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gonio::viewer {

// The illuminants among the named spectra (D65, A, E, F1..F12, ...): the reflectances and the
// observers are not lights.
std::vector<std::string> IlluminantNames();

// {"name", "raw": the table at `wavelengths` (as `gonio render` samples a "lightcolor"),
//  "values": raw scaled so that its luminance Y under `cieToRgb` is 1, the Y of the constant
//  spectrum 1 (the equal-energy light a reflectance image is rendered with), "scale"}.
// 0 where the table has no data. Throws ViewerError for a name that is not an illuminant.
nlohmann::json IlluminantPreset(const std::string& name, const std::vector<double>& wavelengths,
                                const Eigen::Matrix3Xd& cieToRgb);

}  // namespace gonio::viewer
