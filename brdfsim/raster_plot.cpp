#include "brdfsim/raster_plot.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "imageio/image_formats.h"
#include "imageio/oiio_plugin.h"

namespace gonio {

namespace {

using Align = PlotCanvas::Align;
using Rgb = std::array<float, 3>;

// Drawn at twice the size and box-filtered down: render_line draws aliased one-pixel lines.
constexpr int kScale = 2;
constexpr Rgb kBlack = {0, 0, 0}, kGrid = {0.878f, 0.878f, 0.878f};

// OpenImageIO 2.4's render_text decodes UTF-8 wrongly (it draws θ as "8": OpenImageIO issue
// #3933, fixed in a later release), so text is spelled in ASCII: the symbols our labels use get
// names, anything else becomes '?'. Text reaches the canvas already spelled so.
std::string AsciiText(const std::string& utf8) {
    static const std::pair<const char*, const char*> kNames[] = {
        {"θ", "theta"}, {"φ", "phi"}, {"Δ", "d"},   {"°", ""},  {"×", "x"},  {"−", "-"},
        {"′", "'"},     {"ω", "w"},   {"ρ", "rho"}, {"·", "."}, {"…", "..."}};
    std::string out;
    for (std::size_t i = 0; i < utf8.size();) {
        if (static_cast<unsigned char>(utf8[i]) < 0x80) {
            out += utf8[i++];
            continue;
        }
        bool named = false;
        for (const auto& [symbol, name] : kNames) {
            if (utf8.compare(i, std::strlen(symbol), symbol) == 0) {
                out += name, i += std::strlen(symbol), named = true;
                break;
            }
        }
        if (named) continue;
        out += '?';
        for (++i; i < utf8.size() && (static_cast<unsigned char>(utf8[i]) & 0xC0) == 0x80;) ++i;
    }
    return out;
}

class Canvas {
  public:
    Canvas(const PlotLayout& layout, std::string path)
        : path_(std::move(path)),
          canvas_(LoadOiioPlugin("the raster plot \"" + path_ + "\" (its text)")
                      .NewPlotCanvas(layout.Width() * kScale, layout.Height() * kScale)),
          frame_{S(layout.Left()), S(layout.Left() + layout.PlotWidth()) + 1, S(layout.Top()),
                 S(layout.Top() + layout.PlotHeight()) + 1} {}

    // Layout pixels to canvas pixels.
    static int S(double v) { return static_cast<int>(std::lround(v * kScale)); }

    // A line about `width` layout pixels wide, as parallel one-pixel lines; `clip` keeps it in the
    // frame.
    void Line(double x0, double y0, double x1, double y1, const Rgb& colour, double width,
              bool clip) {
        const int n = std::max(1, static_cast<int>(std::lround(width * kScale)));
        const int lo = -(n - 1) / 2, hi = n / 2;
        for (int dy = lo; dy <= hi; ++dy) {
            for (int dx = lo; dx <= hi; ++dx) {
                canvas_->Line(S(x0) + dx, S(y0) + dy, S(x1) + dx, S(y1) + dy, colour.data(),
                              clip ? &frame_ : nullptr);
            }
        }
    }

    // A polyline, dashed as SVG's stroke-dasharray="6,4" when asked.
    void Polyline(const std::vector<std::pair<double, double>>& points, const Rgb& colour,
                  bool dashed, bool clip, double width = 1.5) {
        constexpr double kOn = 6, kOff = 4;
        double phase = 0;  // distance along the dash pattern
        for (std::size_t i = 1; i < points.size(); ++i) {
            auto [x0, y0] = points[i - 1];
            const auto [x1, y1] = points[i];
            const double length = std::hypot(x1 - x0, y1 - y0);
            if (!dashed || length == 0) {
                if (!dashed) Line(x0, y0, x1, y1, colour, width, clip);
                continue;
            }
            double done = 0;
            while (done < length) {
                const bool on = phase < kOn;
                const double step = std::min(length - done, on ? kOn - phase : kOn + kOff - phase);
                const double t0 = done / length, t1 = (done + step) / length;
                if (on) {
                    Line(x0 + (x1 - x0) * t0, y0 + (y1 - y0) * t0, x0 + (x1 - x0) * t1,
                         y0 + (y1 - y0) * t1, colour, width, clip);
                }
                done += step;
                phase = std::fmod(phase + step, kOn + kOff);
            }
        }
    }

    void Text(double x, double y, const std::string& text, int size, Align align) {
        if (text.empty()) return;
        const std::string error = canvas_->Text(S(x), S(y), text, size * kScale, kPlotFont, align);
        if (!error.empty()) FontMissing(error);
    }

    // Text turned 90° counter-clockwise, centred on (x, y).
    void VerticalText(double x, double y, const std::string& text, int size) {
        if (text.empty()) return;
        const std::string error = canvas_->VerticalText(S(x), S(y), text, size * kScale, kPlotFont);
        if (!error.empty()) FontMissing(error);
    }

    // Box-filtered down to the layout's size; float for OpenEXR and HDR files, else 8 bits.
    void Write(const std::string& format, int width, int height) {
        const std::vector<float> pixels = canvas_->Downsampled(width, height);
        ImageFileSpec spec;
        spec.width = width, spec.height = height;
        spec.channelNames = {"R", "G", "B"};
        const bool floats = format == "openexr" || format == "hdr";
        spec.fileType = floats ? PixelType::Float : PixelType::UInt8;
        const std::string error =
            WriteImageFile(format, path_, spec, PixelBuffer{PixelType::Float, pixels.data()});
        if (!error.empty()) throw std::runtime_error(path_ + ": cannot write the plot: " + error);
    }

  private:
    [[noreturn]] void FontMissing(const std::string& error) const {
        throw std::runtime_error(path_ + ": cannot draw the plot's text: " + error + " (the font " +
                                 kPlotFont + " comes with Debian's fonts-dejavu-core)");
    }

    std::string path_;
    std::unique_ptr<PlotCanvas> canvas_;
    PlotCanvas::Box frame_;
};

}  // namespace

void WriteRasterPlot(const std::string& path, const PlotLabels& utf8Labels,
                     const std::vector<PlotSeries>& utf8Series, const PlotOptions& options) {
    const std::string format = FormatForFileName(path);
    if (format.empty()) {  // before any drawing: a clear error, no file
        throw std::runtime_error(path + ": no image writer for this file type");
    }
    // The legend's width follows the labels as they will be drawn.
    std::vector<PlotSeries> series = utf8Series;
    for (PlotSeries& s : series) s.label = AsciiText(s.label);
    const PlotLabels labels = {AsciiText(utf8Labels.title), AsciiText(utf8Labels.xLabel),
                               AsciiText(utf8Labels.yLabel)};
    const PlotLayout layout(options, series);
    Canvas canvas(layout, path);
    const double left = layout.Left(), top = layout.Top();
    const double right = left + layout.PlotWidth(), bottom = top + layout.PlotHeight();
    for (double t : layout.XTicks()) {
        canvas.Line(layout.X(t), top, layout.X(t), bottom, kGrid, 1, false);
        canvas.Text(layout.X(t), bottom + 18, TickText(t), 12, Align::Center);
    }
    for (double t : layout.YTicks()) {
        canvas.Line(left, layout.Y(t), right, layout.Y(t), kGrid, 1, false);
        canvas.Text(left - 8, layout.Y(t) + 4, TickText(t), 12, Align::Right);
    }
    canvas.Polyline({{left, top}, {right, top}, {right, bottom}, {left, bottom}, {left, top}},
                    kBlack, false, false, 1);
    canvas.Text(left + layout.PlotWidth() / 2, 22, labels.title, 14, Align::Center);
    canvas.Text(left + layout.PlotWidth() / 2, layout.Height() - 15, labels.xLabel, 12,
                Align::Center);
    canvas.VerticalText(20, top + layout.PlotHeight() / 2, labels.yLabel, 12);
    for (std::size_t i = 0; i < series.size(); ++i) {
        const PlotSeries& s = series[i];
        const Rgb colour = PlotLayout::ColourRgb(static_cast<int>(i));
        std::vector<std::pair<double, double>> points;
        for (std::size_t j = 0; j < s.x.size() && j < s.y.size(); ++j) {
            if (std::isfinite(s.y[j])) points.emplace_back(layout.X(s.x[j]), layout.Y(s.y[j]));
        }
        canvas.Polyline(points, colour, s.dashed, true);
        const double ly = layout.LegendY(static_cast<int>(i));
        canvas.Polyline({{layout.LegendLineX0(), ly}, {layout.LegendLineX1(), ly}}, colour,
                        s.dashed, false);
        canvas.Text(layout.LegendTextX(), ly + 4, s.label, 10, Align::Left);
    }
    canvas.Write(format, layout.Width(), layout.Height());
}

}  // namespace gonio
