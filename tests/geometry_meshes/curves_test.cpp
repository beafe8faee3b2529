#include "renderer/geometry/curves.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh_test_util.h"
#include "renderer/geometry/points.h"

namespace gonio {
namespace {

using test::Var;
using test::WithP;

V3f BezierAt(const CurveSet& set, size_t segment, float t) {
    const V3f* b = &set.controlPoints[set.segmentFirst[segment]];
    const float s = 1 - t;
    return s * s * s * b[0] + 3 * s * s * t * b[1] + 3 * s * t * t * b[2] + t * t * t * b[3];
}

// The uniform cubic B-spline from its textbook blending functions, independent of basis.cpp.
V3f BSplineAt(const std::vector<V3f>& p, int first, float t) {
    const float s = 1 - t;
    const float w[4] = {s * s * s / 6, (3 * t * t * t - 6 * t * t + 4) / 6,
                        (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, t * t * t / 6};
    V3f out(0);
    for (int k = 0; k < 4; ++k) out += w[k] * p[(first + k) % p.size()];
    return out;
}

// Catmull-Rom: 0.5·(2P1 + (−P0 + P2)t + (2P0 − 5P1 + 4P2 − P3)t² + (−P0 + 3P1 − 3P2 + P3)t³).
V3f CatmullRomAt(const std::vector<V3f>& p, int f, float t) {
    const V3f &p0 = p[f], &p1 = p[f + 1], &p2 = p[f + 2], &p3 = p[f + 3];
    return 0.5f * (2.0f * p1 + (p2 - p0) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t * t +
                   (3.0f * p1 - p0 - 3.0f * p2 + p3) * t * t * t);
}

const std::vector<V3f> kWiggle = {{0, 0, 0}, {1, 2, 0},  {2, -1, 1}, {3, 0, 2},
                                  {4, 3, 0}, {5, 1, -1}, {6, 0, 0}};

TEST(Curves, BezierControlPointsPassThroughUnchanged) {
    const std::vector<V3f> p(kWiggle.begin(), kWiggle.end());
    auto r = MakeCurves("cubic", {7}, "nonperiodic", BezierBasis(), WithP(p));
    ASSERT_TRUE(r.Ok()) << r.Error();
    const CurveSet& set = r.Value();
    EXPECT_EQ(set.basis, CurveSet::Basis::Bezier);
    ASSERT_EQ(set.segmentFirst.size(), 2u);
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR((set.controlPoints[set.segmentFirst[0] + k] - p[k]).length(), 0, 1e-6);
        EXPECT_NEAR((set.controlPoints[set.segmentFirst[1] + k] - p[3 + k]).length(), 0, 1e-6);
    }
    EXPECT_FLOAT_EQ(set.segmentV0[1], 0.5f);
    EXPECT_FLOAT_EQ(set.segmentV1[1], 1.0f);
}

TEST(Curves, BSplineSegmentsReproduceTheOriginalCubic) {
    auto r = MakeCurves("cubic", {7}, "nonperiodic", BSplineBasis(), WithP(kWiggle));
    ASSERT_TRUE(r.Ok());
    const CurveSet& set = r.Value();
    ASSERT_EQ(set.segmentFirst.size(), 4u);
    for (size_t s = 0; s < 4; ++s)
        for (float t : {0.0f, 0.3f, 0.5f, 1.0f})
            EXPECT_NEAR((BezierAt(set, s, t) - BSplineAt(kWiggle, int(s), t)).length(), 0, 1e-5);
}

TEST(Curves, CatmullRomSegmentsReproduceTheOriginalCubic) {
    auto r = MakeCurves("cubic", {7}, "nonperiodic", CatmullRomBasis(), WithP(kWiggle));
    ASSERT_TRUE(r.Ok());
    const CurveSet& set = r.Value();
    ASSERT_EQ(set.segmentFirst.size(), 4u);
    for (size_t s = 0; s < 4; ++s)
        for (float t : {0.0f, 0.25f, 0.7f, 1.0f})
            EXPECT_NEAR((BezierAt(set, s, t) - CatmullRomAt(kWiggle, int(s), t)).length(), 0, 1e-5);
    EXPECT_NEAR((BezierAt(set, 0, 0) - kWiggle[1]).length(), 0, 1e-6);
}

TEST(Curves, PeriodicBSplineWrapsAround) {
    const std::vector<V3f> ring = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0.5f, -0.5f, 0}};
    auto r = MakeCurves("cubic", {5}, "periodic", BSplineBasis(), WithP(ring));
    ASSERT_TRUE(r.Ok()) << r.Error();
    const CurveSet& set = r.Value();
    ASSERT_EQ(set.segmentFirst.size(), 5u);
    for (size_t s = 0; s < 5; ++s) {
        EXPECT_NEAR((BezierAt(set, s, 0.4f) - BSplineAt(ring, int(s), 0.4f)).length(), 0, 1e-5);
        // Closed: each segment ends where the next begins.
        EXPECT_NEAR((BezierAt(set, s, 1) - BezierAt(set, (s + 1) % 5, 0)).length(), 0, 1e-5);
    }
}

TEST(Curves, VaryingWidthIsLinearAlongEachSegment) {
    auto vars = WithP(kWiggle,
                      {Var("width", ParamClass::Varying, ParamType::Float, 1, {0.2f, 0.4f, 1.0f})});
    auto r = MakeCurves("cubic", {7}, "nonperiodic", BezierBasis(), vars);
    ASSERT_TRUE(r.Ok()) << r.Error();
    const std::vector<float>& radii = r.Value().radii;
    ASSERT_EQ(radii.size(), 8u);
    EXPECT_FLOAT_EQ(radii[0], 0.1f);
    EXPECT_FLOAT_EQ(radii[3], 0.2f);
    EXPECT_NEAR(radii[1], 0.1f + 0.1f / 3, 1e-6);
    EXPECT_FLOAT_EQ(radii[4], 0.2f);
    EXPECT_FLOAT_EQ(radii[7], 0.5f);
    EXPECT_FALSE(r.Value().ribbon);
}

TEST(Curves, LinearPeriodicCurvesConstantWidthAndVars) {
    const std::vector<V3f> a = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    const std::vector<V3f> b = {{5, 0, 0}, {6, 0, 0}, {6, 1, 0}, {5, 1, 0}};
    std::vector<V3f> both = a;
    both.insert(both.end(), b.begin(), b.end());
    std::vector<float> s = {0, 1, 2, 10, 11, 12, 13};  // varying: one per vertex when periodic
    auto vars =
        WithP(both, {Var("constantwidth", ParamClass::Constant, ParamType::Float, 1, {0.5f}),
                     Var("s", ParamClass::Varying, ParamType::Float, 1, s),
                     Var("Kd", ParamClass::Uniform, ParamType::Float, 1, {1, 2})});
    auto r = MakeCurves("linear", {3, 4}, "periodic", BezierBasis(), vars);
    ASSERT_TRUE(r.Ok()) << r.Error();
    const CurveSet& set = r.Value();
    EXPECT_EQ(set.basis, CurveSet::Basis::Linear);
    ASSERT_EQ(set.controlPoints.size(), 4u + 5u);
    EXPECT_EQ(set.controlPoints[3], a[0]);
    EXPECT_EQ(set.controlPoints[8], b[0]);
    ASSERT_EQ(set.segmentFirst.size(), 7u);
    EXPECT_EQ(set.segmentFirst[3], 4u);
    EXPECT_EQ(set.curveOfSegment[6], 1u);
    for (float r0 : set.radii) EXPECT_FLOAT_EQ(r0, 0.25f);
    const PrimVar* sv = set.vars.Find("s");
    ASSERT_NE(sv, nullptr);
    ASSERT_EQ(sv->values.size(), 14u);
    EXPECT_EQ(sv->values[4], 2.0f);  // segment 2 of curve 0 runs from s = 2 ...
    EXPECT_EQ(sv->values[5], 0.0f);  // ... back to s = 0
    EXPECT_EQ(sv->values[13], 10.0f);
    EXPECT_EQ(set.vars.Find("Kd")->values.size(), 2u);
    EXPECT_EQ(set.vars.Find("constantwidth"), nullptr);
}

TEST(Curves, NormalsMakeOrientedRibbons) {
    std::vector<float> n = {0, 0, 1, 0, 1, 0, 1, 0, 0};
    auto r = MakeCurves("cubic", {7}, "nonperiodic", BezierBasis(),
                        WithP(kWiggle, {Var("N", ParamClass::Varying, ParamType::Normal, 3, n)}));
    ASSERT_TRUE(r.Ok());
    EXPECT_TRUE(r.Value().ribbon);
    ASSERT_EQ(r.Value().normals.size(), r.Value().controlPoints.size());
    EXPECT_EQ(r.Value().normals[4], V3f(0, 1, 0));
}

TEST(Curves, BadInputIsReported) {
    EXPECT_FALSE(
        MakeCurves("cubic", {5}, "nonperiodic", BezierBasis(), WithP(std::vector<V3f>(5, V3f(0))))
            .Ok());
    EXPECT_FALSE(MakeCurves("quadratic", {4}, "nonperiodic", BezierBasis(),
                            WithP(std::vector<V3f>(4, V3f(0))))
                     .Ok());
    EXPECT_FALSE(
        MakeCurves("linear", {1}, "nonperiodic", BezierBasis(), WithP(std::vector<V3f>(1, V3f(0))))
            .Ok());
    auto badWidth = MakeCurves(
        "cubic", {7}, "nonperiodic", BezierBasis(),
        WithP(kWiggle, {Var("width", ParamClass::Varying, ParamType::Float, 1, {1, 1})}));
    ASSERT_FALSE(badWidth.Ok());
    EXPECT_NE(badWidth.Error().find("width"), std::string::npos);
    EXPECT_FALSE(
        MakeCurves("linear", {4}, "nonperiodic", BezierBasis(), WithP(std::vector<V3f>(3, V3f(0))))
            .Ok());
}

TEST(Points, WidthsAndDefaults) {
    const std::vector<V3f> p = {{0, 0, 0}, {1, 0, 0}};
    auto plain = MakePoints(WithP(p));
    ASSERT_TRUE(plain.Ok());
    EXPECT_EQ(plain.Value().radii, (std::vector<float>{0.5f, 0.5f}));
    auto constant = MakePoints(
        WithP(p, {Var("constantwidth", ParamClass::Constant, ParamType::Float, 1, {0.1f})}));
    EXPECT_EQ(constant.Value().radii, (std::vector<float>{0.05f, 0.05f}));
    auto varying = MakePoints(
        WithP(p, {Var("width", ParamClass::Varying, ParamType::Float, 1, {2, 4}),
                  Var("Cs", ParamClass::Varying, ParamType::Color, 3, {1, 0, 0, 0, 1, 0})}));
    ASSERT_TRUE(varying.Ok());
    EXPECT_EQ(varying.Value().radii, (std::vector<float>{1, 2}));
    EXPECT_NE(varying.Value().vars.Find("Cs"), nullptr);
    EXPECT_EQ(varying.Value().vars.Find("width"), nullptr);
    EXPECT_FALSE(
        MakePoints(WithP(p, {Var("width", ParamClass::Varying, ParamType::Float, 1, {2})})).Ok());
    EXPECT_FALSE(MakePoints(PrimVarSet{}).Ok());
}

}  // namespace
}  // namespace gonio
