#include "renderer/image/pixel_filter.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gonio {
namespace {

PixelFilter MakeFilter(const std::string& name, float xwidth, float ywidth) {
    std::string error;
    auto filter = PixelFilter::FromRib(name, xwidth, ywidth, error);
    EXPECT_TRUE(filter.has_value()) << error;
    return filter.value_or(PixelFilter());
}

// Midpoint rule over the footprint.
double Integrate(const PixelFilter& filter) {
    const int n = 400;
    double xr = filter.XRadius(), yr = filter.YRadius(), sum = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            sum += filter.Evaluate(float(-xr + (i + 0.5) * 2 * xr / n),
                                   float(-yr + (j + 0.5) * 2 * yr / n));
    return sum * (2 * xr / n) * (2 * yr / n);
}

struct FilterCase {
    const char* name;
    float xwidth, ywidth;
    float atCentre;
    double integral;  // analytic integral over the footprint
};

class EveryFilter : public ::testing::TestWithParam<FilterCase> {};

TEST_P(EveryFilter, PeaksAtTheCentre) {
    const FilterCase& c = GetParam();
    PixelFilter filter = MakeFilter(c.name, c.xwidth, c.ywidth);
    EXPECT_NEAR(filter.Evaluate(0, 0), c.atCentre, 1e-6);
    for (float d : {0.1f, 0.4f, 0.7f})
        EXPECT_LE(filter.Evaluate(d * filter.XRadius(), d * filter.YRadius()), c.atCentre);
}

TEST_P(EveryFilter, IsSymmetricInBothAxes) {
    const FilterCase& c = GetParam();
    PixelFilter filter = MakeFilter(c.name, c.xwidth, c.ywidth);
    for (float dx : {0.13f, 0.6f, 1.1f, 1.7f}) {
        for (float dy : {0.0f, 0.37f, 0.9f}) {
            float w = filter.Evaluate(dx, dy);
            EXPECT_FLOAT_EQ(filter.Evaluate(-dx, dy), w);
            EXPECT_FLOAT_EQ(filter.Evaluate(dx, -dy), w);
            EXPECT_FLOAT_EQ(filter.Evaluate(-dx, -dy), w);
        }
    }
}

TEST_P(EveryFilter, VanishesOutsideTheFootprint) {
    const FilterCase& c = GetParam();
    PixelFilter filter = MakeFilter(c.name, c.xwidth, c.ywidth);
    EXPECT_FLOAT_EQ(filter.XRadius(), c.xwidth / 2);
    EXPECT_FLOAT_EQ(filter.YRadius(), c.ywidth / 2);
    EXPECT_EQ(filter.Evaluate(filter.XRadius() * 1.01f, 0), 0.0f);
    EXPECT_EQ(filter.Evaluate(0, -filter.YRadius() * 1.01f), 0.0f);
}

TEST_P(EveryFilter, IntegratesToItsAnalyticValue) {
    const FilterCase& c = GetParam();
    PixelFilter filter = MakeFilter(c.name, c.xwidth, c.ywidth);
    double integral = Integrate(filter);
    EXPECT_GT(integral, 0.0);
    EXPECT_NEAR(integral, c.integral, 2e-3 * c.integral);
}

// ∫_{-1}^{1} exp(-2 x²) dx = sqrt(pi/2) erf(sqrt 2).
const double kGaussianUnit = std::sqrt(M_PI / 2) * std::erf(std::sqrt(2.0));

INSTANTIATE_TEST_SUITE_P(
    PixelFilter, EveryFilter,
    ::testing::Values(FilterCase{"box", 1, 1, 1, 1},  //
                      FilterCase{"box", 3, 2, 1, 6},
                      FilterCase{"triangle", 2, 4, 1, 1 * 2},  // (xw/2)(yw/2)
                      // Scaled to the width: ∫ over [-r, r] = r ∫_{-1}^{1} exp(-2u²) du.
                      FilterCase{"gaussian", 2, 2, 1, kGaussianUnit* kGaussianUnit},
                      FilterCase{"gaussian", 4, 3, 1, 2 * kGaussianUnit * 1.5 * kGaussianUnit},
                      // The whole cubic (width 4) integrates to 1 per axis.
                      FilterCase{"catmull-rom", 4, 4, 1, 1},
                      FilterCase{"mitchell", 4, 2, 8.0f / 9 * 8.0f / 9, 2.0 / 2 * 1.0 / 2},
                      FilterCase{"disk", 2, 3, 1, M_PI * 1 * 1.5}),
    [](const auto& info) {
        std::string name = info.param.name;
        for (char& ch : name)
            if (ch == '-') ch = '_';
        return name + "_" + std::to_string(int(info.param.xwidth)) + "x" +
               std::to_string(int(info.param.ywidth));
    });

TEST(PixelFilter, DefaultIsRiSpecGaussianTwoByTwo) {
    PixelFilter filter;
    EXPECT_EQ(filter.Name(), "gaussian");
    EXPECT_FLOAT_EQ(filter.XRadius(), 1.0f);
    EXPECT_FLOAT_EQ(filter.YRadius(), 1.0f);
}

TEST(PixelFilter, GaussianFollowsRiGaussianFilter) {
    PixelFilter filter = MakeFilter("gaussian", 2, 4);
    // exp(-2 ((2x/xw)² + (2y/yw)²)).
    EXPECT_NEAR(filter.Evaluate(1, 0), std::exp(-2.0), 1e-6);
    EXPECT_NEAR(filter.Evaluate(0, 2), std::exp(-2.0), 1e-6);
    EXPECT_NEAR(filter.Evaluate(0.5f, 1), std::exp(-2.0 * (0.25 + 0.25)), 1e-6);
}

TEST(PixelFilter, TriangleFallsToZeroAtTheRadius) {
    PixelFilter filter = MakeFilter("triangle", 2, 2);
    EXPECT_FLOAT_EQ(filter.Evaluate(1, 0), 0.0f);
    EXPECT_FLOAT_EQ(filter.Evaluate(0.5f, 0.5f), 0.25f);
}

TEST(PixelFilter, CatmullRomInterpolatesIntegerSamples) {
    PixelFilter filter = MakeFilter("catmull-rom", 4, 4);
    EXPECT_NEAR(filter.Evaluate(1, 0), 0.0f, 1e-6);
    EXPECT_NEAR(filter.Evaluate(0, 1), 0.0f, 1e-6);
    EXPECT_NEAR(filter.Evaluate(2, 0), 0.0f, 1e-6);
    EXPECT_NEAR(filter.Evaluate(1.5f, 0), -0.0625f, 1e-6);  // the negative lobe
    EXPECT_NEAR(filter.Evaluate(0.5f, 0.5f), 0.5625f * 0.5625f, 1e-6);
}

TEST(PixelFilter, SincIsWindowedAsInTheRenderManBinding) {
    PixelFilter filter = MakeFilter("sinc", 4, 4);
    EXPECT_NEAR(filter.Evaluate(1, 0), 0.0f, 1e-6);
    EXPECT_NEAR(filter.Evaluate(2, 0), 0.0f, 1e-6);
    // sin(pi x)/(pi x) · cos(pi x / (2 xwidth)) at x = 0.5, width 4.
    double expected = std::sin(M_PI / 2) / (M_PI / 2) * std::cos(M_PI * 0.5 / 8);
    EXPECT_NEAR(filter.Evaluate(0.5f, 0), expected, 1e-6);
    EXPECT_LT(filter.Evaluate(1.5f, 0), 0.0f);
}

// ∫_{-w/2}^{w/2} sin(pi x)/(pi x) cos(pi x / (2w)) dx by the midpoint rule.
double WindowedSincIntegral(double width) {
    const int n = 20000;
    double h = width / n, sum = 0.0;
    for (int i = 0; i < n; ++i) {
        double x = -width / 2 + (i + 0.5) * h;
        sum += std::sin(M_PI * x) / (M_PI * x) * std::cos(M_PI * x / (2 * width));
    }
    return sum * h;
}

TEST(PixelFilter, SincIntegratesToTheProductOfItsAxes) {
    PixelFilter filter = MakeFilter("sinc", 4, 3);
    double expected = WindowedSincIntegral(4) * WindowedSincIntegral(3);
    EXPECT_GT(expected, 0.5);
    EXPECT_NEAR(Integrate(filter), expected, 1e-3 * expected);
}

TEST(PixelFilter, RejectsUnknownNamesAndBadWidths) {
    std::string error;
    EXPECT_FALSE(PixelFilter::FromRib("lanczos", 2, 2, error));
    EXPECT_NE(error.find("lanczos"), std::string::npos) << error;
    EXPECT_FALSE(PixelFilter::FromRib("box", 0, 2, error));
    EXPECT_NE(error.find("positive"), std::string::npos) << error;
    EXPECT_FALSE(PixelFilter::FromRib("box", 1, -1, error));
    EXPECT_FALSE(PixelFilter::FromRib("box", 1, NAN, error));
}

}  // namespace
}  // namespace gonio
