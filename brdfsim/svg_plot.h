#pragma once
// Line plots written as SVG by hand (no plotting library): axes with ticks, labels, a legend,
// several series, for cross sections like the thesis's figures.

#include <string>
#include <vector>

namespace gonio {

struct PlotSeries {
    std::string label;
    std::vector<double> x, y;
    bool dashed = false;  // analytic overlays
};

struct PlotLabels {
    std::string title, xLabel, yLabel;
};

// Writes under a temporary name, then renames; throws std::runtime_error on I/O failure.
void WriteSvgPlot(const std::string& path, const PlotLabels& labels,
                  const std::vector<PlotSeries>& series);

// "Nice" tick positions covering [lo, hi] (about `count` of them).
std::vector<double> NiceTicks(double lo, double hi, int count);

}  // namespace gonio
