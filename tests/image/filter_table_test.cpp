// FilterTable: the film's tabulated filter axes against the filters they tabulate.

#include "renderer/image/filter_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

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

// The four-lane lookup the film's splat uses gives the scalar one's weights exactly, lane by
// lane, and 0 where a lane is out of reach, beyond the radius, or not a number.
TEST(FilterTable, FourLanesAreFourScalarLookups) {
    std::string error;
    const auto filter = PixelFilter::FromRib("gaussian", 2, 2, error);
    ASSERT_TRUE(filter) << error;
    const FilterTable table(filter->XRadius(), [&](float d) { return filter->XWeight(d); });
    const float r = filter->XRadius();
    for (int i = -300; i <= 300; ++i) {
        const float d0 = r * (float(i) + 0.37f) / 201.f;  // up to 1.5 radii
        const Float4 d = {d0, -0.5f * d0, 0.25f * d0 + 0.01f, -d0};
        const Float4 weights = table(d, Int4{-1, -1, -1, -1});
        for (int lane = 0; lane < kFloat4Lanes; ++lane)
            ASSERT_EQ(weights[lane], table(d[lane])) << d[lane];
        const Float4 masked = table(d, Int4{0, -1, 0, -1});
        EXPECT_EQ(masked[0], 0.f);
        EXPECT_EQ(masked[1], weights[1]);
        EXPECT_EQ(masked[2], 0.f);
    }
    const float nan = std::nanf("");
    const Float4 odd = table(Float4{nan, 0, 2 * r, -2 * r}, Int4{-1, -1, -1, -1});
    EXPECT_EQ(odd[0], 0.f);
    EXPECT_EQ(odd[1], table(0.f));
    EXPECT_EQ(odd[2], 0.f);
    EXPECT_EQ(odd[3], 0.f);
}

}  // namespace
}  // namespace gonio
