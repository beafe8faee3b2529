// Curves without N are flat ribbons that face each ray (RenderMan's default): at a hit, the
// normal points back along the ray across the curve (Embree reports the tangent as Ng) and u
// runs from 0 to 1 across the width (Embree reports no such parameter).

#include <gtest/gtest.h>

#include "renderer/raytrace/shape_evaluation.h"

namespace gonio {
namespace {

CurveSet StraightRibbon(CurveSet::Basis basis) {
    CurveSet curves;
    curves.basis = basis;
    curves.ribbon = true;
    if (basis == CurveSet::Basis::Linear) {
        curves.controlPoints = {V3f(-1, 0, 0), V3f(1, 0, 0)};
        curves.radii = {0.5f, 0.5f};
    } else {  // a Bézier segment along the same line
        curves.controlPoints = {V3f(-1, 0, 0), V3f(-1.f / 3, 0, 0), V3f(1.f / 3, 0, 0),
                                V3f(1, 0, 0)};
        curves.radii = {0.5f, 0.5f, 0.5f, 0.5f};
    }
    curves.segmentFirst = {0};
    curves.segmentV0 = {0};
    curves.segmentV1 = {1};
    curves.curveOfSegment = {0};
    return curves;
}

TEST(Ribbon, FacesTheRayAndSpansUAcrossItsWidth) {
    for (CurveSet::Basis basis : {CurveSet::Basis::Linear, CurveSet::Basis::Bezier}) {
        const CurveSet curves = StraightRibbon(basis);
        const V3f dir(0, 0, 1), tangent(2, 0, 0);  // looking along +z at a curve along x
        // At t = 0.6 the centre is x = 0.2; the ribbon spans y in [-0.5, 0.5].
        for (float y : {-0.45f, -0.25f, 0.f, 0.25f, 0.45f}) {
            const ObjectHit hit =
                EvaluateCurve(curves, 0, 0.6f, 0.f, V3f(0.2f, y, 0), tangent, dir);
            EXPECT_NEAR(hit.geometry.Ng.z, -1, 1e-6) << "faces the ray";
            EXPECT_NEAR(hit.N.z, -1, 1e-6);
            // Across the width, from the side T × dir = -y: u = 0.5 - y / (2 r).
            EXPECT_NEAR(hit.geometry.u, 0.5f - y, 1e-5) << y;
            EXPECT_NEAR(hit.geometry.v, 0.6f, 1e-6);
        }
    }
}

// Seen at an angle, the normal is still across the tangent, turned towards the viewer.
TEST(Ribbon, AnObliqueRaySeesTheNormalAcrossTheTangent) {
    const CurveSet curves = StraightRibbon(CurveSet::Basis::Linear);
    const V3f dir = V3f(0.6f, 0.3f, 0.7f).normalized();
    const ObjectHit hit = EvaluateCurve(curves, 0, 0.5f, 0.f, V3f(0, 0, 0), V3f(2, 0, 0), dir);
    EXPECT_NEAR(hit.geometry.Ng.x, 0, 1e-6) << "perpendicular to the curve";
    EXPECT_LT(hit.geometry.Ng.dot(dir), 0) << "towards the viewer";
    EXPECT_NEAR(hit.geometry.Ng.length(), 1, 1e-6);
}

// Oriented curves (with N, not linear) keep the normal Embree gives.
TEST(Ribbon, OrientedCurvesKeepTheirNormal) {
    CurveSet curves = StraightRibbon(CurveSet::Basis::Bezier);
    curves.normals.assign(4, V3f(0, 1, 0));
    const ObjectHit hit =
        EvaluateCurve(curves, 0, 0.5f, 0.3f, V3f(0, 0, 0), V3f(0, 1, 0), V3f(0, 0, 1));
    EXPECT_EQ(hit.geometry.Ng, V3f(0, 1, 0));
    EXPECT_FLOAT_EQ(hit.geometry.u, 0.3f);
}

}  // namespace
}  // namespace gonio
