// Evaluate: derivatives, normals, orientation, the implicit equations and the bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quadric_cases.h"

namespace gonio::test {
namespace {

class QuadricGeometry : public ::testing::TestWithParam<QuadricCase> {};

V3d D(const V3f& v) { return V3d(v.x, v.y, v.z); }

// The distance from p to the implicit surface, to first order: F / |∇F|.
double DistanceToSurface(const QuadricCase& c, const V3d& p) {
    const double h = 1e-6 * c.scale;
    V3d gradient;
    for (int axis = 0; axis < 3; ++axis) {
        V3d step(0);
        step[axis] = h;
        gradient[axis] = (c.implicit(p + step) - c.implicit(p - step)) / (2 * h);
    }
    return std::fabs(c.implicit(p)) / gradient.length();
}

TEST_P(QuadricGeometry, PointsLieOnTheImplicitSurfaceAndInsideTheBounds) {
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    const Box3f bounds = shape->Bounds();
    for (int i = 0; i <= 40; ++i) {
        for (int j = 0; j <= 40; ++j) {
            const SurfaceGeometry g = shape->Evaluate(i / 40.0f, j / 40.0f);
            EXPECT_LT(DistanceToSurface(c, D(g.P)), 1e-6 * c.scale) << i << " " << j;
            EXPECT_TRUE(bounds.intersects(g.P)) << i << " " << j;
            EXPECT_EQ(g.u, i / 40.0f);
            EXPECT_EQ(g.v, j / 40.0f);
        }
    }
}

TEST_P(QuadricGeometry, BoundsAreTight) {
    // Every face of the box is touched by the surface, up to the grid's resolution.
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    const Box3f bounds = shape->Bounds();
    Box3f sampled;
    for (int i = 0; i <= 360; ++i)
        for (int j = 0; j <= 60; ++j) sampled.extendBy(shape->Evaluate(i / 360.0f, j / 60.0f).P);
    const float slack = 0.01f * float(c.scale);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(bounds.min[axis], sampled.min[axis], slack) << axis;
        EXPECT_NEAR(bounds.max[axis], sampled.max[axis], slack) << axis;
    }
}

TEST_P(QuadricGeometry, DerivativesMatchFiniteDifferences) {
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    std::mt19937 random(7);
    std::uniform_real_distribution<float> inside(0.05f, 0.95f);
    const float h = 1e-3f;
    for (int k = 0; k < 200; ++k) {
        const float u = inside(random), v = inside(random);
        const SurfaceGeometry g = shape->Evaluate(u, v);
        const V3d dPdu =
            (D(shape->Evaluate(u + h, v).P) - D(shape->Evaluate(u - h, v).P)) / (2.0 * h);
        const V3d dPdv =
            (D(shape->Evaluate(u, v + h).P) - D(shape->Evaluate(u, v - h).P)) / (2.0 * h);
        const double tolerance = 2e-3 * (c.scale + D(g.dPdu).length() + D(g.dPdv).length());
        EXPECT_LT((dPdu - D(g.dPdu)).length(), tolerance) << u << " " << v;
        EXPECT_LT((dPdv - D(g.dPdv)).length(), tolerance) << u << " " << v;
    }
}

TEST_P(QuadricGeometry, NormalIsTheUnitCrossProductOfTheDerivatives) {
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    std::mt19937 random(11);
    std::uniform_real_distribution<float> unit(0, 1);
    for (int k = 0; k < 500; ++k) {
        const SurfaceGeometry g = shape->Evaluate(unit(random), unit(random));
        const V3d n = D(g.Ng), dPdu = D(g.dPdu), dPdv = D(g.dPdv);
        EXPECT_NEAR(n.length(), 1, 1e-6);
        EXPECT_LT(std::fabs(n.dot(dPdu)), 1e-5 * dPdu.length() + 1e-12);
        EXPECT_LT(std::fabs(n.dot(dPdv)), 1e-5 * dPdv.length() + 1e-12);
        const V3d cross = dPdu.cross(dPdv);
        if (cross.length() > 1e-3 * dPdu.length() * dPdv.length() + 1e-12) {
            EXPECT_GT(n.dot(cross.normalized()), 1 - 1e-5) << g.u << " " << g.v;
        }
    }
}

TEST_P(QuadricGeometry, NormalPointsOutsideForTheStandardOrientation) {
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    if (c.orientation == 0) {  // a flat piece with no outside: Ng is at least vertical
        for (int i = 0; i <= 20; ++i)
            for (int j = 0; j <= 20; ++j)
                EXPECT_NEAR(std::fabs(shape->Evaluate(i / 20.0f, j / 20.0f).Ng.z), 1, 1e-6);
        return;
    }
    int checked = 0;
    for (int i = 0; i <= 20; ++i) {
        for (int j = 0; j <= 20; ++j) {
            const SurfaceGeometry g = shape->Evaluate(i / 20.0f, j / 20.0f);
            const V3d outside = c.outside(D(g.P));
            if (outside.length() < 1e-3 * c.scale) continue;  // on the axis: no "outside"
            EXPECT_GT(c.orientation * D(g.Ng).dot(outside.normalized()), 0.1)
                << i << " " << j << " P=" << g.P << " Ng=" << g.Ng;
            ++checked;
        }
    }
    EXPECT_GT(checked, 300);
}

INSTANTIATE_TEST_SUITE_P(Quadrics, QuadricGeometry, ::testing::ValuesIn(AllQuadricCases()),
                         [](const auto& info) { return info.param.name; });

TEST(QuadricLimits, PolesAndApexesGetTheLimitNormal) {
    const auto sphere = MakeSphere(2, -2, 2, 360);
    for (float u : {0.0f, 0.3f, 1.0f}) {
        EXPECT_NEAR(sphere->Evaluate(u, 1).Ng.z, 1, 1e-6);
        EXPECT_NEAR(sphere->Evaluate(u, 0).Ng.z, -1, 1e-6);
    }
    const auto disk = MakeDisk(1, 2, 360);
    EXPECT_NEAR(disk->Evaluate(0.4f, 1).Ng.z, 1, 1e-6);
    EXPECT_NEAR(MakeDisk(1, 2, -90)->Evaluate(0.4f, 1).Ng.z, -1, 1e-6);

    // Cone of height 2, radius 1: the normal along a generator is (2 cos θ, 2 sin θ, 1)/√5.
    const auto cone = MakeCone(2, 1, 360);
    const SurfaceGeometry apex = cone->Evaluate(0.25f, 1);
    EXPECT_NEAR(apex.Ng.x, 0, 1e-6);
    EXPECT_NEAR(apex.Ng.y, 2 / std::sqrt(5.0), 1e-6);
    EXPECT_NEAR(apex.Ng.z, 1 / std::sqrt(5.0), 1e-6);
    EXPECT_NEAR((apex.Ng - cone->Evaluate(0.25f, 0.5f).Ng).length(), 0, 1e-6);

    const SurfaceGeometry bottom = MakeParaboloid(1, 0, 1, 360)->Evaluate(0.7f, 0);
    EXPECT_NEAR(bottom.Ng.z, -1, 1e-6);
    EXPECT_TRUE(std::isfinite(bottom.dPdv.length()));
}

TEST(QuadricParameters, FollowTheRISpecFormulas) {
    // Sphere 1 −0.5 0.5 180 at (u, v) = (0.5, 0.5): θ = 90°, φ = 0.
    const SurfaceGeometry s = MakeSphere(1, -0.5f, 0.5f, 180)->Evaluate(0.5f, 0.5f);
    EXPECT_NEAR((D(s.P) - V3d(0, 1, 0)).length(), 0, 1e-6);
    EXPECT_NEAR((D(s.dPdu) - V3d(-M_PI, 0, 0)).length(), 0, 1e-5);
    EXPECT_NEAR((D(s.dPdv) - V3d(0, 0, M_PI / 3)).length(), 0, 1e-5);  // φ spans ±30°
    // Paraboloid .5 .2 .7 270 at v = 0: z = zmin, r = rmax·√(zmin/zmax).
    const SurfaceGeometry p = MakeParaboloid(0.5f, 0.2f, 0.7f, 270)->Evaluate(0, 0);
    EXPECT_NEAR(p.P.x, 0.5 * std::sqrt(0.2 / 0.7), 1e-6);
    EXPECT_NEAR(p.P.z, 0.2, 1e-6);
    // Torus 1 .25 0 180 90 at (1, 0.5): θ = 90°, φ = 90°.
    const SurfaceGeometry t = MakeTorus(1, 0.25f, 0, 180, 90)->Evaluate(1, 0.5f);
    EXPECT_NEAR((D(t.P) - V3d(0, 1, 0.25)).length(), 0, 1e-6);
    EXPECT_NEAR((D(t.Ng) - V3d(0, 0, 1)).length(), 0, 1e-6);
    // Hyperboloid: the line's own point, rotated.
    const SurfaceGeometry h =
        MakeHyperboloid(V3f(1, 0, 0), V3f(0, 1, 2), 360)->Evaluate(0.25f, 0.5f);
    EXPECT_NEAR((D(h.P) - V3d(-0.5, 0.5, 1)).length(), 0, 1e-6);
}

}  // namespace
}  // namespace gonio::test
