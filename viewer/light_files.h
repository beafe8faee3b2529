#pragma once
// The thesis's light-source files (`cspec` samples and `curve` Catmull-Rom control points,
// Appendix D.2.3) as the page sees them: JSON in, file text out, and back (Load Light, Save
// Light, Save Curve of Appendix D.1.2). The files themselves are spectral/spectrum_file.h's.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gonio::viewer {

// Parses a light file's text. The answer:
//   {"kind": "curve"|"samples", "wavelengths": [...], "values": [...],
//    "before": p, "after": p  (curve only: the phantom control points),
//    "atImage": [...]         (the light at `imageWavelengths`, 0 where the file has no data),
//    "note": "..."            (present when the file does not cover the image's wavelengths)}
// Throws ViewerError with spectral's `name:line: error:` text for a bad file.
nlohmann::json LoadLightFile(const std::string& text, const std::string& name,
                             const std::vector<double>& imageWavelengths);

// The file text of a light in the page's JSON. {"format": "cspec", "start", "step", "values"}
// writes point samples (the thesis's Save Light); {"format": "curve", "wavelengths", "values",
// "before"?, "after"?} control points (Save Curve). Throws ViewerError for a bad request.
std::string SaveLightFile(const nlohmann::json& request);

}  // namespace gonio::viewer
