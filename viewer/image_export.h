#pragma once
// The relit image as a file the browser downloads (Appendix D.1.1's "Save RGB"): PNG (sRGB
// encoded, 8 bit, clamped to [0, 1]) or OpenEXR (linear float RGB, unclamped).

#include <string>
#include <vector>

namespace gonio::viewer {

enum class ExportFormat { Png, Exr };

// "png" or "exr"; throws ViewerError otherwise.
ExportFormat ParseExportFormat(const std::string& name);

// The file's bytes for linear RGB `rgb` (3 floats per pixel, top row first), written by the
// built-in drivers (imageio/). Throws ViewerError if it cannot be encoded.
std::string EncodeImage(const std::vector<float>& rgb, int width, int height, ExportFormat format);

}  // namespace gonio::viewer
