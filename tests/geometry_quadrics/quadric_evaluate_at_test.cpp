// Quadric::EvaluateAt: the renderer's evaluation from a hit point must give what
// Evaluate(ParametersAt(point)) gives, up to float rounding, everywhere on every quadric: at the
// poles and apexes, on the seam and the edges of partial sweeps, and for reversed parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quadric_cases.h"

namespace gonio::test {
namespace {

class QuadricEvaluateAt : public ::testing::TestWithParam<QuadricCase> {};

V3d D(const V3f& v) { return V3d(v.x, v.y, v.z); }

// Within `relative` of the reference's length, or of `floor` where the reference vanishes.
void ExpectClose(const V3f& actual, const V3f& expected, double relative, double floor,
                 const char* what, const V3f& point) {
    const double error = (D(actual) - D(expected)).length();
    EXPECT_LE(error, relative * std::max(D(expected).length(), floor))
        << what << " at (" << point.x << ", " << point.y << ", " << point.z << "): (" << actual.x
        << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", " << expected.y
        << ", " << expected.z << ")";
}

void ExpectMatchesEvaluate(const QuadricCase& c, const Quadric& shape, const V3f& point) {
    const V2f uv = shape.ParametersAt(point);
    const SurfaceGeometry expected = shape.Evaluate(uv.x, uv.y);
    const SurfaceGeometry actual = shape.EvaluateAt(point);
    EXPECT_EQ(actual.u, uv.x);
    EXPECT_EQ(actual.v, uv.y);
    // P differs by the rounding of u (and a sphere's v) to float: up to about 4e-7 radians of
    // sweep at the largest |thetamax| of the cases.
    ExpectClose(actual.P, expected.P, 1e-6, c.scale, "P", point);
    ExpectClose(actual.dPdu, expected.dPdu, 1e-5, 1e-6 * c.scale, "dPdu", point);
    ExpectClose(actual.dPdv, expected.dPdv, 1e-5, 1e-6 * c.scale, "dPdv", point);
    ExpectClose(actual.Ng, expected.Ng, 1e-5, 1, "Ng", point);
    // The normal without parameters, where a quadric gives one (a sphere always: the
    // renderer's camera hits take it instead of EvaluateAt's), has the same sense.
    const V3f oriented = shape.OrientedNormalAt(point);
    if (c.name.rfind("Sphere", 0) == 0) {
        EXPECT_NE(oriented, V3f(0)) << c.name;
    }
    if (oriented != V3f(0)) {
        ExpectClose(oriented.normalized(), expected.Ng, 1e-5, 1, "OrientedNormalAt", point);
    }
}

TEST_P(QuadricEvaluateAt, MatchesEvaluateOnTheParameterGrid) {
    // The grid's rows and columns 0 and 1 are the seam, the edges of partial sweeps, the poles,
    // apexes and centres, and the z or φ limits.
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    constexpr int kSteps = 48;
    for (int i = 0; i <= kSteps; ++i)
        for (int j = 0; j <= kSteps; ++j)
            ExpectMatchesEvaluate(c, *shape,
                                  shape->Evaluate(i / float(kSteps), j / float(kSteps)).P);
}

TEST_P(QuadricEvaluateAt, MatchesEvaluateAtRayHits) {
    // The points the renderer evaluates: those IntersectPoint reports, from every side.
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0, 1), signedUnit(-1, 1);
    int hits = 0;
    for (int k = 0; k < 3000; ++k) {
        const V3f target = shape->Evaluate(unit(random), unit(random)).P;
        V3f away(signedUnit(random), signedUnit(random), signedUnit(random));
        if (!(away.length() > 0.1f)) continue;
        const V3f org = target + away.normalized() * float(3 * c.scale);
        float t;
        V3f point;
        if (!shape->IntersectPoint(org, target - org, 0, 1e30f, &t, &point)) continue;
        ++hits;
        ExpectMatchesEvaluate(c, *shape, point);
    }
    EXPECT_GT(hits, 2000);
}

std::vector<QuadricCase> Cases() {
    std::vector<QuadricCase> cases = AllQuadricCases();
    // Beyond the shared cases: profiles that cross the axis or lie on its far side.
    cases.push_back(LineCase(
        "CylinderNegativeRadius", [] { return MakeCylinder(-1, -1, 1, 250); }, V3d(-1, 0, -1),
        V3d(-1, 0, 1), 250, 1));
    cases.push_back(LineCase(
        "HyperboloidThroughAxis",
        [] { return MakeHyperboloid(V3f(1, 0.5, -1), V3f(-1, -0.5, 1), 300); }, V3d(1, 0.5, -1),
        V3d(-1, -0.5, 1), 300, 1));
    cases.push_back(ParaboloidCase("ParaboloidNegativeRmax", -1, 0, 2, -270));
    cases.push_back(SphereCase("SphereHemisphereNegativeTheta", 1, 0, 1, -360, -1));
    // Whole spheres (the renderer's lean path) in every orientation; Ng's sense is not at
    // issue here.
    cases.push_back(SphereCase("SphereWholeNegativeRadius", -1, -1, 1, 360, 0));
    cases.push_back(SphereCase("SphereWholeReversedNegativeTheta", 2, 2, -2, -360, 0));
    cases.push_back(SphereCase("SphereWholeTwice", 0.5, -0.5, 0.5, 720, 0));
    cases.push_back(TorusCase("TorusSpindle", 0.3, 1, -180, 180, 300));
    return cases;
}

INSTANTIATE_TEST_SUITE_P(AllQuadrics, QuadricEvaluateAt, ::testing::ValuesIn(Cases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace gonio::test
