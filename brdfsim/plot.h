#pragma once
// Line plots of cross sections like the thesis's figures: the plot's content (series, labels,
// axis ranges) and its layout (frame, ticks, legend, colours), shared by the SVG writer
// (svg_plot.h) and the raster writer (raster_plot.h) so that both draw the same picture.

#include <array>
#include <optional>
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

// What the caller may fix; everything left empty is chosen from the data.
struct PlotOptions {
    int width = 800, height = 450;  // pixels (SVG user units)
    std::optional<double> xMin, xMax, yMin, yMax;
};

// Where everything goes, in pixels from the top-left corner.
class PlotLayout {
  public:
    // Throws std::invalid_argument for a size below 240×160 or above 8192, or an empty range.
    PlotLayout(const PlotOptions& options, const std::vector<PlotSeries>& series);

    int Width() const { return width_; }
    int Height() const { return height_; }
    double Left() const { return left_; }
    double Top() const { return top_; }
    double PlotWidth() const { return plotW_; }
    double PlotHeight() const { return plotH_; }
    double X(double x) const { return left_ + (x - xMin_) / (xMax_ - xMin_) * plotW_; }
    double Y(double y) const { return top_ + plotH_ - (y - yMin_) / (yMax_ - yMin_) * plotH_; }
    const std::vector<double>& XTicks() const { return xTicks_; }
    const std::vector<double>& YTicks() const { return yTicks_; }

    // The legend entry of series i: a short line from (x0, y) to (x1, y), the text at textX.
    double LegendLineX0() const { return left_ + plotW_ + 12; }
    double LegendLineX1() const { return left_ + plotW_ + 36; }
    double LegendTextX() const { return left_ + plotW_ + 42; }
    double LegendY(int i) const { return top_ + 10 + 20.0 * i; }

    // Series i's colour, as "#rrggbb" and as RGB in [0, 1].
    static std::string ColourHex(int i);
    static std::array<float, 3> ColourRgb(int i);

  private:
    int width_, height_;
    double left_, top_, plotW_, plotH_;
    double xMin_, xMax_, yMin_, yMax_;
    std::vector<double> xTicks_, yTicks_;
};

// "Nice" tick positions covering [lo, hi] (about `count` of them).
std::vector<double> NiceTicks(double lo, double hi, int count);

// A tick label: %g, with -0 printed as 0.
std::string TickText(double value);

// Writes `path` by its extension: .svg as SVG, anything else through OpenImageIO (.png, .tif,
// .jpg, ...). Writes under a temporary name, then renames; throws std::runtime_error when the
// file cannot be written or no writer knows the extension.
void WritePlot(const std::string& path, const PlotLabels& labels,
               const std::vector<PlotSeries>& series, const PlotOptions& options = {});

}  // namespace gonio
