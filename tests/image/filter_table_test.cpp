// FilterTable: the film's tabulated filter axes against the filters they tabulate.

#include "renderer/image/filter_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/image/filter_reach_table.h"
#include "renderer/image/pixel_filter.h"

namespace gonio {
namespace {

struct Case {
    const char* name;
    float width;
    float tolerance;  // the interpolation error the table's spacing allows
};

TEST(FilterTable, MatchesEveryFilterOverItsFootprint) {
    const Case cases[] = {{"box", 1, 0},
                          {"triangle", 2, 1e-6f},
                          {"gaussian", 2, 1e-6f},
                          {"gaussian", 3.5f, 1e-6f},
                          {"catmull-rom", 4, 5e-6f},
                          {"sinc", 6, 1e-5f},
                          {"mitchell", 4, 5e-6f},
                          {"sinc", 40, 1e-5f}};
    for (const Case& c : cases) {
        std::string error;
        const auto filter = PixelFilter::FromRib(c.name, c.width, c.width, error);
        ASSERT_TRUE(filter) << c.name << ": " << error;
        const FilterTable table(filter->XRadius(), [&](float d) { return filter->XWeight(d); });
        float worst = 0;
        // Offsets off the table's grid, of both signs, up to the radius.
        for (int i = -4000; i <= 4000; ++i) {
            const float d = filter->XRadius() * (float(i) + 0.37f) / 4001.f;
            worst = std::max(worst, std::fabs(table(d) - filter->XWeight(d)));
        }
        EXPECT_LE(worst, c.tolerance) << c.name << " " << c.width;
        EXPECT_EQ(table(filter->XRadius() * 1.01f), 0.f) << c.name;
        EXPECT_EQ(table(-filter->XRadius() * 1.01f), 0.f) << c.name;
    }
}

// FilterReachTable, the film's usual splat: for a sample anywhere in its pixel, each lane is the
// filter's weight for one pixel of its reach, exactly 0 beyond the radius (the film's rule:
// -radius <= d < radius counts) and in the lanes past the reach.
TEST(FilterReachTable, LanesAreTheReachedPixelsWeights) {
    // Tolerances: linear interpolation's bound h²/8 · max|w''| at h = 1/512 pixel; a Gaussian
    // of width W is exp(−8 d² / W²), whose |w''| peaks at 16 / W² (at d = 0). The triangle's
    // kinks (d = 0 and the radius) lie on the grid, so it is exact up to rounding. Each adds
    // 5e-7 for the rounding of float weights near 1 (a few ulps).
    const Case cases[] = {{"box", 1, 0},
                          {"triangle", 2, 1e-6f},
                          {"gaussian", 2, 2.4e-6f},
                          {"gaussian", 3, 1.35e-6f},
                          {"gaussian", 1.5f, 3.9e-6f}};
    for (const Case& c : cases) {
        std::string error;
        const auto filter = PixelFilter::FromRib(c.name, c.width, c.width, error);
        ASSERT_TRUE(filter) << c.name << ": " << error;
        const float radius = filter->XRadius();
        ASSERT_TRUE(FilterReachTable::Covers(radius)) << c.name << " " << c.width;
        const int margin = std::max(0, int(std::ceil(0.5f + radius)) - 1);
        const FilterReachTable table(radius, margin, [&](float d) { return filter->XWeight(d); });
        for (int i = 0; i <= 1000; ++i) {
            const float f = float(i) / 1000;  // both ends of the pixel included
            const Float4 weights = table(f);
            for (int k = 0; k < kFloat4Lanes; ++k) {
                const float d = f - (float(k - margin) + 0.5f);
                const bool reached = k <= 2 * margin && d >= -radius && d < radius;
                if (!reached) {
                    EXPECT_EQ(weights[k], 0.f) << c.name << " f " << f << " lane " << k;
                    continue;
                }
                EXPECT_NEAR(weights[k], filter->XWeight(d), c.tolerance)
                    << c.name << " " << c.width << " f " << f << " lane " << k;
            }
        }
    }
    EXPECT_FALSE(FilterReachTable::Covers(2));  // gaussian 4 4 takes the per-sample path
}

}  // namespace
}  // namespace gonio
