// TrimCurve's region (renderer/geometry/trim_curves.h): the exact rational circle becomes a
// polyline on the circle whose area is πr² to 0.05%; the odd winding rule keeps the inside of one
// loop and makes a second loop inside it a hole; bad argument counts are errors.

#include "renderer/geometry/trim_curves.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gonio {
namespace {

using Imath::V2f;

struct Curve {
    std::vector<int> order, n;
    std::vector<float> knot, min, max, u, v, w;
    void Add(int o, std::vector<float> k, float lo, float hi, std::vector<float> uu,
             std::vector<float> vv, std::vector<float> ww) {
        order.push_back(o), n.push_back(static_cast<int>(uu.size()));
        knot.insert(knot.end(), k.begin(), k.end());
        min.push_back(lo), max.push_back(hi);
        u.insert(u.end(), uu.begin(), uu.end());
        v.insert(v.end(), vv.begin(), vv.end());
        w.insert(w.end(), ww.begin(), ww.end());
    }
    GeometryResult<TrimRegion> Make(const std::vector<int>& ncurves) const {
        return MakeTrimRegion(ncurves, order, knot, min, max, n, u, v, w);
    }
};

// The circle of radius r about c as 9 homogeneous points (u·w, v·w, w), corners weighted √2/2
// (The NURBS Book §7.5).
void AddCircle(Curve* curve, V2f c, float r) {
    const float corners[9][2] = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                                 {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    std::vector<float> u, v, w;
    for (int i = 0; i < 9; ++i) {
        const float weight = i % 2 ? std::sqrt(0.5f) : 1.f;
        u.push_back((c.x + r * corners[i][0]) * weight);
        v.push_back((c.y + r * corners[i][1]) * weight);
        w.push_back(weight);
    }
    curve->Add(3, {0, 0, 0, 0.25f, 0.25f, 0.5f, 0.5f, 0.75f, 0.75f, 1, 1, 1}, 0, 1, u, v, w);
}

double PolygonArea(const std::vector<V2f>& loop) {
    double area = 0;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
        area += double(loop[j].x) * loop[i].y - double(loop[i].x) * loop[j].y;
    return std::fabs(area) / 2;
}

TEST(TrimCurves, RationalCircleBecomesAPolylineOnTheCircle) {
    Curve curve;
    AddCircle(&curve, V2f(0.5f, 0.5f), 0.4f);
    const auto region = curve.Make({1});
    ASSERT_TRUE(region.Ok()) << region.Error();
    ASSERT_EQ(region.Value().Loops().size(), 1u);
    const std::vector<V2f>& loop = region.Value().Loops()[0];
    EXPECT_EQ(loop.size(), 4u * 32 + 1);
    for (const V2f& p : loop) EXPECT_NEAR((p - V2f(0.5f, 0.5f)).length(), 0.4f, 1e-6f);
    EXPECT_NEAR(PolygonArea(loop), M_PI * 0.16, M_PI * 0.16 * 5e-4);
}

TEST(TrimCurves, InsideIsKeptAndANestedLoopIsAHole) {
    Curve curve;
    // The unit square as one linear curve of 5 points, then a circle inside it.
    curve.Add(2, {0, 0, 1, 2, 3, 4, 4}, 0, 4, {0, 1, 1, 0, 0}, {0, 0, 1, 1, 0}, {1, 1, 1, 1, 1});
    AddCircle(&curve, V2f(0.5f, 0.5f), 0.25f);
    const auto holed = curve.Make({1, 1});
    ASSERT_TRUE(holed.Ok()) << holed.Error();
    // A grid of points: kept exactly when in the square and out of the circle (away from edges).
    int checked = 0;
    for (int i = -10; i <= 110; ++i) {
        for (int j = -10; j <= 110; ++j) {
            const V2f p(i / 100.f + 0.003f, j / 100.f + 0.002f);
            const float d = (p - V2f(0.5f, 0.5f)).length();
            const bool inSquare = p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1;
            if (std::fabs(d - 0.25f) < 0.01f) continue;  // the polyline cuts the circle's arcs
            EXPECT_EQ(holed.Value().Contains(p), inSquare && d > 0.25f) << p.x << " " << p.y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 14000);
    const auto disc = [] {
        Curve c;
        AddCircle(&c, V2f(0.5f, 0.5f), 0.25f);
        return c.Make({1});
    }();
    EXPECT_TRUE(disc.Value().Contains(V2f(0.5f, 0.5f)));
    EXPECT_FALSE(disc.Value().Contains(V2f(0.9f, 0.9f)));
}

TEST(TrimCurves, BadArgumentsAreErrors) {
    Curve curve;
    AddCircle(&curve, V2f(0, 0), 1);
    EXPECT_EQ(curve.Make({2}).Error(),
              "TrimCurve: order, min, max and n need one value per curve (2)");
    Curve shortKnots = curve;
    shortKnots.knot.pop_back();
    EXPECT_EQ(shortKnots.Make({1}).Error(), "TrimCurve: knot needs 12 values, got 11");
    Curve badWeight = curve;
    badWeight.w[3] = 0;
    EXPECT_EQ(badWeight.Make({1}).Error(), "TrimCurve: curve 0 has a weight <= 0");
    EXPECT_EQ(curve.Make({0}).Error(), "TrimCurve: every loop needs at least one curve");
}

}  // namespace
}  // namespace gonio
