#pragma once
// Plots written as SVG by hand (no plotting library), drawn from a PlotLayout (plot.h).

#include <string>
#include <vector>

#include "brdfsim/plot.h"

namespace gonio {

// Writes under a temporary name, then renames; throws std::runtime_error on I/O failure.
void WriteSvgPlot(const std::string& path, const PlotLabels& labels,
                  const std::vector<PlotSeries>& series, const PlotLayout& layout);

}  // namespace gonio
