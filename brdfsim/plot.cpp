#include "brdfsim/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "brdfsim/raster_plot.h"
#include "brdfsim/svg_plot.h"

namespace gonio {

namespace {

// Margins: room for the tick labels and the axis labels left and below, the title above and
// the legend on the right (as wide as its longest label needs, at most 45% of the plot).
constexpr double kLeft = 80, kTop = 40, kBottom = 60;
constexpr double kLegendLine = 48, kLegendChar = 6.2;  // the 10-point sans-serif's mean advance

std::size_t Characters(const std::string& utf8) {
    std::size_t n = 0;
    for (unsigned char c : utf8) n += (c & 0xC0) != 0x80;
    return n;
}

double LegendWidth(const std::vector<PlotSeries>& series, int width) {
    std::size_t longest = 0;
    for (const PlotSeries& s : series) longest = std::max(longest, Characters(s.label));
    return std::clamp(kLegendLine + kLegendChar * longest + 10, 100.0, 0.45 * width);
}

constexpr std::array<std::array<unsigned char, 3>, 8> kColours = {{{0x1f, 0x77, 0xb4},
                                                                   {0xd6, 0x27, 0x28},
                                                                   {0x2c, 0xa0, 0x2c},
                                                                   {0x94, 0x67, 0xbd},
                                                                   {0xff, 0x7f, 0x0e},
                                                                   {0x8c, 0x56, 0x4b},
                                                                   {0xe3, 0x77, 0xc2},
                                                                   {0x17, 0xbe, 0xcf}}};

bool EndsWith(const std::string& text, const std::string& end) {
    return text.size() >= end.size() &&
           text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

std::vector<double> NiceTicks(double lo, double hi, int count) {
    if (!(hi > lo)) hi = lo + 1;
    const double raw = (hi - lo) / std::max(count, 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        step = m * magnitude;
        if (step >= raw) break;
    }
    std::vector<double> ticks;
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
        ticks.push_back(t);
    }
    return ticks;
}

std::string TickText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", std::abs(value) < 1e-12 ? 0.0 : value);
    return text;
}

PlotLayout::PlotLayout(const PlotOptions& options, const std::vector<PlotSeries>& series)
    : width_(options.width),
      height_(options.height),
      left_(kLeft),
      top_(kTop),
      plotW_(options.width - kLeft - LegendWidth(series, options.width)),
      plotH_(options.height - kTop - kBottom) {
    if (width_ < 480 || height_ < 240 || width_ > 8192 || height_ > 8192) {
        throw std::invalid_argument("a plot must be 480x240 to 8192x8192 pixels, got " +
                                    std::to_string(width_) + "x" + std::to_string(height_));
    }
    double dataXMin = 1e300, dataXMax = -1e300, dataYMin = 0, dataYMax = 0;
    for (const PlotSeries& s : series) {
        for (double x : s.x) dataXMin = std::min(dataXMin, x), dataXMax = std::max(dataXMax, x);
        for (double y : s.y) {
            if (std::isfinite(y))
                dataYMin = std::min(dataYMin, y), dataYMax = std::max(dataYMax, y);
        }
    }
    if (dataXMin > dataXMax) dataXMin = 0, dataXMax = 1;
    xMin_ = options.xMin.value_or(dataXMin);
    xMax_ = options.xMax.value_or(dataXMax);
    if (xMax_ == xMin_ && !options.xMin && !options.xMax) xMax_ = xMin_ + 1;
    yMin_ = options.yMin.value_or(dataYMin);
    if (options.yMax) {
        yMax_ = *options.yMax;
        yTicks_ = NiceTicks(yMin_, yMax_, 6);
    } else {
        // Round the top up to a tick a little above the data, as a plotting library would.
        const double span = dataYMax > yMin_ ? dataYMax - yMin_ : 1.0;
        yTicks_ = NiceTicks(yMin_, yMin_ + span * 1.05, 6);
        if (yTicks_.size() >= 2 && yTicks_.back() < yMin_ + span) {
            yTicks_.push_back(2 * yTicks_.back() - yTicks_[yTicks_.size() - 2]);
        }
        yMax_ = std::max(yTicks_.back(), yMin_ + span);
    }
    if (!(xMax_ > xMin_) || !(yMax_ > yMin_)) {
        throw std::invalid_argument("a plot's axis range must not be empty");
    }
    yTicks_.erase(std::remove_if(yTicks_.begin(), yTicks_.end(),
                                 [&](double t) { return t > yMax_ + 1e-9 * (yMax_ - yMin_); }),
                  yTicks_.end());
    xTicks_ = NiceTicks(xMin_, xMax_, 8);
}

std::string PlotLayout::ColourHex(int i) {
    const auto& c = kColours[i % 8];
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", c[0], c[1], c[2]);
    return text;
}

std::array<float, 3> PlotLayout::ColourRgb(int i) {
    const auto& c = kColours[i % 8];
    return {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f};
}

void WritePlot(const std::string& path, const PlotLabels& labels,
               const std::vector<PlotSeries>& series, const PlotOptions& options) {
    if (EndsWith(path, ".svg") || EndsWith(path, ".SVG")) {
        WriteSvgPlot(path, labels, series, PlotLayout(options, series));
    } else {
        WriteRasterPlot(path, labels, series, options);
    }
}

}  // namespace gonio
