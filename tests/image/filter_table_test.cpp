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

}  // namespace
}  // namespace gonio
