#pragma once
// Plots drawn into an image (OpenImageIO's ImageBufAlgo render_line and render_text, in the
// OpenImageIO plugin: imageio/oiio_plugin.h) and written by extension (.png, .tif, .jpg, .exr,
// ...): the same picture as svg_plot.h, for viewers and documents that want pixels.

#include <string>
#include <vector>

#include "brdfsim/plot.h"

namespace gonio {

// The text font, found by OpenImageIO's font search (/usr/share/fonts, $OPENIMAGEIO_FONTS):
// Debian's fonts-dejavu-core.
inline constexpr const char* kPlotFont = "DejaVuSans";

// Text is drawn in ASCII (θ as "theta": raster_plot.cpp says why), and the layout is that of
// the series with their labels so spelled. Writes under a temporary name, then renames; throws
// std::runtime_error when no writer knows the extension, the font is missing, or the file cannot be
// written.
void WriteRasterPlot(const std::string& path, const PlotLabels& labels,
                     const std::vector<PlotSeries>& series, const PlotOptions& options);

}  // namespace gonio
