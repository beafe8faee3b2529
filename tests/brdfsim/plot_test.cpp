// Plots: the layout's axes, the raster writer's pixels read back from the PNG (curves where the
// data says, dashes with gaps, legend, text), and the SVG writer drawing the same layout.
#include "brdfsim/plot.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "brdfsim/brdf_grid.h"
#include "brdfsim/section.h"
#include "test_util.h"

namespace gonio {
namespace {

using test::TempPath;

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
    std::array<float, 3> At(int x, int y) const {
        const float* p = &pixels[(static_cast<std::size_t>(y) * width + x) * channels];
        return {p[0], p[1], p[2]};
    }
};

Image ReadImage(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
    Image image;
    if (!in) return image;
    image.width = in->spec().width;
    image.height = in->spec().height;
    image.channels = in->spec().nchannels;
    image.pixels.resize(static_cast<std::size_t>(image.width) * image.height * image.channels);
    EXPECT_TRUE(
        in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data()));
    return image;
}

float Distance(const std::array<float, 3>& a, const std::array<float, 3>& b) {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

// The row of column x (inside rows [top, bottom)) whose colour is nearest to `colour`, and how
// near it is.
std::pair<int, float> NearestRow(const Image& image, int x, int top, int bottom,
                                 const std::array<float, 3>& colour) {
    int best = -1;
    float bestDistance = 1e9f;
    for (int y = top; y < bottom; ++y) {
        const float d = Distance(image.At(x, y), colour);
        if (d < bestDistance) bestDistance = d, best = y;
    }
    return {best, bestDistance};
}

double Curve(double x) { return 0.5 + 0.35 * std::sin(x * kDegree * 2); }

std::vector<PlotSeries> TwoSeries() {
    PlotSeries wave{"wave", {}, {}, false}, flat{"flat", {}, {}, true};
    for (int i = 0; i <= 360; i += 2) {
        wave.x.push_back(i), wave.y.push_back(Curve(i));
        flat.x.push_back(i), flat.y.push_back(0.2);
    }
    return {wave, flat};
}

PlotOptions FixedAxes() {
    PlotOptions options;
    options.width = 640, options.height = 360;
    options.yMax = 1.0;
    return options;
}

TEST(PlotLayout, AxesCoverTheDataAndTicksStayInside) {
    const PlotLayout layout(PlotOptions{}, TwoSeries());
    EXPECT_DOUBLE_EQ(layout.X(0), layout.Left());
    EXPECT_DOUBLE_EQ(layout.X(360), layout.Left() + layout.PlotWidth());
    EXPECT_DOUBLE_EQ(layout.Y(0), layout.Top() + layout.PlotHeight());
    EXPECT_GE(layout.YTicks().back(), 0.85);  // the top of the wave is inside the frame
    EXPECT_LE(layout.Y(0.85), layout.Y(0.8));
    EXPECT_GE(layout.Y(0.85), layout.Top());
    for (double t : layout.XTicks()) EXPECT_TRUE(t >= 0 && t <= 360) << t;

    const PlotLayout fixed(FixedAxes(), TwoSeries());
    EXPECT_DOUBLE_EQ(fixed.Y(1.0), fixed.Top());
    EXPECT_LE(fixed.YTicks().back(), 1.0 + 1e-12);
}

TEST(PlotLayout, RejectsBadSizesAndEmptyRanges) {
    PlotOptions tiny;
    tiny.width = 100;
    EXPECT_THROW(PlotLayout(tiny, TwoSeries()), std::invalid_argument);
    PlotOptions empty;
    empty.yMax = 0.0;  // the y axis starts at 0
    EXPECT_THROW(PlotLayout(empty, TwoSeries()), std::invalid_argument);
}

TEST(RasterPlot, PngHasTheSizeAndTheCurvesWhereTheDataSays) {
    const std::string path = TempPath("plot.png");
    const std::vector<PlotSeries> series = TwoSeries();
    WritePlot(path, {"title", "x (degrees)", "f (1/sr)"}, series, FixedAxes());
    const Image image = ReadImage(path);
    ASSERT_EQ(image.width, 640);
    ASSERT_EQ(image.height, 360);
    ASSERT_GE(image.channels, 3);

    const PlotLayout layout(FixedAxes(), series);
    const int top = static_cast<int>(layout.Top()) + 2;
    const int bottom = static_cast<int>(layout.Top() + layout.PlotHeight()) - 2;
    const std::array<float, 3> blue = PlotLayout::ColourRgb(0);
    int checked = 0;
    for (int px = static_cast<int>(layout.Left()) + 3; px < layout.Left() + layout.PlotWidth() - 3;
         px += 7) {
        const double x = (px + 0.5 - layout.Left()) / layout.PlotWidth() * 360.0;
        const auto [row, distance] = NearestRow(image, px, top, bottom, blue);
        EXPECT_LT(distance, 0.6f) << "no curve pixel in column " << px;
        EXPECT_NEAR(row + 0.5, layout.Y(Curve(x)), 2.5) << "column " << px << ", x " << x;
        ++checked;
    }
    EXPECT_GT(checked, 40);

    // The dashed line at 0.2: on about 6 of every 10 pixels, never solid, never missing.
    const std::array<float, 3> red = PlotLayout::ColourRgb(1);
    const int row = static_cast<int>(layout.Y(0.2));
    int on = 0, columns = 0;
    for (int px = static_cast<int>(layout.Left()) + 2; px < layout.Left() + layout.PlotWidth() - 2;
         ++px, ++columns) {
        const auto [found, distance] = NearestRow(image, px, row - 2, row + 3, red);
        if (distance < 0.5f) ++on;
    }
    EXPECT_GT(on, columns * 0.45);
    EXPECT_LT(on, columns * 0.8);

    // Away from curves, grid lines and text the plot area is white.
    const double midX = (layout.XTicks()[0] + layout.XTicks()[1]) / 2;
    const std::array<float, 3> white = {1, 1, 1};
    EXPECT_LT(Distance(image.At(static_cast<int>(layout.X(midX)), static_cast<int>(layout.Y(0.95))),
                       white),
              0.05f);
    std::remove(path.c_str());
}

TEST(RasterPlot, LegendAndTextAreDrawn) {
    const std::string path = TempPath("legend.png");
    const std::vector<PlotSeries> series = TwoSeries();
    WritePlot(path, {"A title", "x", "f"}, series, FixedAxes());
    const Image image = ReadImage(path);
    ASSERT_EQ(image.width, 640);
    const PlotLayout layout(FixedAxes(), series);
    for (int i = 0; i < 2; ++i) {
        const int y = static_cast<int>(layout.LegendY(i));
        const int x = static_cast<int>(layout.LegendLineX0()) + 3;  // inside the first dash
        const auto [row, distance] = NearestRow(image, x, y - 2, y + 3, PlotLayout::ColourRgb(i));
        EXPECT_LT(distance, 0.5f) << "legend entry " << i;
    }
    // Dark text pixels in the title band, in the legend text and left of the frame (y ticks).
    auto darkIn = [&](int x0, int x1, int y0, int y1) {
        int dark = 0;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) dark += image.At(x, y)[1] < 0.4f;
        }
        return dark;
    };
    EXPECT_GT(darkIn(0, 640, 0, static_cast<int>(layout.Top()) - 2), 20);
    EXPECT_GT(darkIn(static_cast<int>(layout.LegendTextX()), 640, 0, 80), 20);
    EXPECT_GT(darkIn(0, static_cast<int>(layout.Left()) - 2, 0, 360), 20);
    std::remove(path.c_str());
}

TEST(RasterPlot, UnknownFormatIsAnErrorAndLeavesNoFile) {
    const std::string path = TempPath("plot.nosuchformat");
    EXPECT_THROW(WritePlot(path, {}, TwoSeries()), std::runtime_error);
    std::ifstream left(path);
    EXPECT_FALSE(left.good());
}

TEST(SvgPlot, DrawsTheSameLayout) {
    const std::string path = TempPath("plot.svg");
    const std::vector<PlotSeries> series = TwoSeries();
    WritePlot(path, {"t", "x", "f"}, series, FixedAxes());
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    const PlotLayout layout(FixedAxes(), series);
    std::ostringstream firstPoint;
    firstPoint << "points=\"" << layout.X(0) << "," << layout.Y(Curve(0)) << " ";
    EXPECT_NE(text.str().find("width=\"640\" height=\"360\""), std::string::npos);
    EXPECT_NE(text.str().find(firstPoint.str()), std::string::npos) << firstPoint.str();
    EXPECT_NE(text.str().find("stroke-dasharray"), std::string::npos);
    std::remove(path.c_str());
}

TEST(Section, RelativeCutCountsPhiOutFromPhiIn) {
    SectionCut cut;
    cut.thetaIn = 45, cut.phiIn = 90, cut.thetaOut = 60;
    cut.vary = SectionAxis::kPhiOut;
    cut.relativePhi = true;
    double ti, pi, to, po;
    CutAngles(cut, 30, &ti, &pi, &to, &po);
    EXPECT_NEAR(pi, 90 * kDegree, 1e-12);
    EXPECT_NEAR(po, 120 * kDegree, 1e-12);
    cut.relativePhi = false;
    CutAngles(cut, 30, &ti, &pi, &to, &po);
    EXPECT_NEAR(po, 30 * kDegree, 1e-12);
}

// A reciprocal cut evaluates the samples where θ_out > θ_in with the directions exchanged and
// the others as they are: on a synthetic Phong grid, whose splat estimate is not reciprocal
// towards grazing, each sample of a reciprocal θ_out cut at θ_in = 60° is the plain evaluation
// at (θ_out, φ_out) → (θ_in, φ_in) above 60° and the plain cut's value below, and the two cuts
// differ somewhere above.
TEST(Section, ReciprocalCutPutsTheMoreGrazingDirectionIn) {
    auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 20000, true, false, 0.4);
    const BrdfIsoGrid grid(splats, 4, 9);
    SectionCut cut;
    cut.thetaIn = 60, cut.phiIn = 0, cut.phiOut = 180;
    cut.vary = SectionAxis::kThetaOut;
    cut.from = 0, cut.to = 85, cut.samples = 18;
    const Section plain = ComputeSection(grid, cut);
    cut.reciprocal = true;
    const Section swapped = ComputeSection(grid, cut);
    EXPECT_NE(cut.Label().find("reciprocal"), std::string::npos);
    double largest = 0;
    for (int i = 0; i < cut.samples; ++i) {
        if (swapped.x[i] <= 60) {
            EXPECT_EQ(swapped.f[i][0], plain.f[i][0]) << "θ_out = " << swapped.x[i];
            continue;
        }
        float f = 0;
        grid.EvalAngles(swapped.x[i] * kDegree, kPi, 60 * kDegree, 0, &f);
        EXPECT_EQ(swapped.f[i][0], f) << "θ_out = " << swapped.x[i];
        largest = std::max(largest, std::abs(double(plain.f[i][0]) - f) / f);
    }
    EXPECT_GT(largest, 1e-3) << "the plain and reciprocal cuts should differ above 60°";
}

}  // namespace
}  // namespace gonio
