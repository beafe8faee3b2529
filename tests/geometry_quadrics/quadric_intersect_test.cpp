// Intersect: hits at evaluated points with their (u, v), clipping of partial sweeps, nearest-hit
// consistency, rays from far away, and degenerate parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "quadric_cases.h"

namespace gonio::test {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

V3d D(const V3f& v) { return V3d(v.x, v.y, v.z); }

// A ray from `height` above g.P along its normal, pointing back at it with a non-unit speed.
struct Probe {
    V3f org, dir;
    double expectedT;
};

Probe ProbeAt(const SurfaceGeometry& g, double height, double speed) {
    const V3d n = D(g.Ng);
    return {V3f(D(g.P) + height * n), V3f(-speed * n), height / speed};
}

class QuadricIntersect : public ::testing::TestWithParam<QuadricCase> {};

TEST_P(QuadricIntersect, RaysTowardsEvaluatedPointsHitThemWithTheirUV) {
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    std::mt19937 random(3);
    std::uniform_real_distribution<float> inside(0.02f, 0.98f);
    std::uniform_real_distribution<double> speed(0.1, 10);
    for (int k = 0; k < 500; ++k) {
        const SurfaceGeometry g = shape->Evaluate(inside(random), inside(random));
        const Probe probe = ProbeAt(g, 0.02 * c.scale, speed(random));
        QuadricHit hit;
        ASSERT_TRUE(shape->Intersect(probe.org, probe.dir, 0, kInfinity, &hit))
            << "u=" << g.u << " v=" << g.v;
        EXPECT_NEAR(hit.t, probe.expectedT, 1e-5 * probe.expectedT);
        const V3d p = D(probe.org) + double(hit.t) * D(probe.dir);
        EXPECT_LT((p - D(g.P)).length(), 1e-5 * c.scale);
        EXPECT_LT((D(shape->Evaluate(hit.u, hit.v).P) - D(g.P)).length(), 1e-5 * c.scale);
        if (c.uniqueUV) {
            EXPECT_NEAR(hit.u, g.u, 1e-5) << "v=" << g.v;
            EXPECT_NEAR(hit.v, g.v, 1e-5) << "u=" << g.u;
        }
    }
}

// Rays aimed at surface points just outside the parameter square (the formulas extrapolated)
// miss, and those just inside hit; tmax stops each ray shortly past its target.
TEST_P(QuadricIntersect, PartialSweepsAreClipped) {
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    const double height = 0.01 * c.scale;
    auto hits = [&](float u, float v) {
        const Probe probe = ProbeAt(shape->Evaluate(u, v), height, 1);
        QuadricHit hit;
        return shape->Intersect(probe.org, probe.dir, 0, float(1.5 * probe.expectedT), &hit);
    };
    const float delta = 0.01f;
    for (int k = 1; k < 20; ++k) {
        const float s = 0.05f * k;
        if (c.clipU) {
            EXPECT_FALSE(hits(-delta, s)) << s;
            EXPECT_FALSE(hits(1 + delta, s)) << s;
            EXPECT_TRUE(hits(delta, s)) << s;
            EXPECT_TRUE(hits(1 - delta, s)) << s;
        }
        if (c.clipV0) {
            EXPECT_FALSE(hits(s, -delta)) << s;
            EXPECT_TRUE(hits(s, delta)) << s;
        }
        if (c.clipV1) {
            EXPECT_FALSE(hits(s, 1 + delta)) << s;
            EXPECT_TRUE(hits(s, 1 - delta)) << s;
        }
    }
}

// Random rays through the bounding box: every hit lies on the surface at its own (u, v), and is
// the nearest one (nothing is hit before it, the next hit lies beyond it).
TEST_P(QuadricIntersect, RandomRaysFindTheNearestHitOnTheSurface) {
    const QuadricCase& c = GetParam();
    const auto shape = c.make();
    const Box3f box = shape->Bounds();
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(0, 1);
    std::normal_distribution<float> gauss;
    int hits = 0;
    for (int k = 0; k < 2000; ++k) {
        const V3f target(box.min.x + unit(random) * (box.max.x - box.min.x),
                         box.min.y + unit(random) * (box.max.y - box.min.y),
                         box.min.z + unit(random) * (box.max.z - box.min.z));
        const V3f dir = V3f(gauss(random), gauss(random), gauss(random)) * (0.5f + unit(random));
        const V3f org = target - dir * float(3 * c.scale / dir.length());
        QuadricHit hit;
        if (!shape->Intersect(org, dir, 0, kInfinity, &hit)) continue;
        ++hits;
        const V3d p = D(org) + double(hit.t) * D(dir);
        EXPECT_LT((D(shape->Evaluate(hit.u, hit.v).P) - p).length(), 1e-5 * c.scale);
        EXPECT_GE(hit.u, 0);
        EXPECT_LE(hit.u, 1);
        EXPECT_GE(hit.v, 0);
        EXPECT_LE(hit.v, 1);
        QuadricHit earlier, later;
        EXPECT_FALSE(shape->Intersect(org, dir, 0, hit.t * (1 - 1e-5f), &earlier));
        if (shape->Intersect(org, dir, hit.t * (1 + 1e-5f), kInfinity, &later)) {
            EXPECT_GT(later.t, hit.t);
        }
    }
    EXPECT_GT(hits, 100);
}

INSTANTIATE_TEST_SUITE_P(Quadrics, QuadricIntersect, ::testing::ValuesIn(AllQuadricCases()),
                         [](const auto& info) { return info.param.name; });

// The exact intersection of the float ray with a sphere about the origin, in long double.
long double ReferenceSphereT(const V3f& org, const V3f& dir, long double r) {
    const long double ox = org.x, oy = org.y, oz = org.z, dx = dir.x, dy = dir.y, dz = dir.z;
    const long double a = dx * dx + dy * dy + dz * dz;
    const long double tc = -(ox * dx + oy * dy + oz * dz) / a;
    const long double cx = ox + tc * dx, cy = oy + tc * dy, cz = oz + tc * dz;
    const long double half = std::sqrt((r * r - (cx * cx + cy * cy + cz * cz)) / a);
    return tc - half;
}

TEST(QuadricFarRays, SphereHitsAreExactToFloatPrecision) {
    // The conformance scenes' sphere of radius 100 seen from 440 units, and a unit sphere seen
    // from 1e3 units with short and long direction vectors.
    struct Setup {
        float radius, distance, speed;
    };
    for (const Setup s :
         {Setup{100, 440, 1}, Setup{1, 1000, 1}, Setup{1, 1000, 1e-3f}, Setup{1, 1000, 1e3f}}) {
        const auto sphere = MakeSphere(s.radius, -s.radius, s.radius, 360);
        std::mt19937 random(1);
        std::uniform_real_distribution<float> inside(0.05f, 0.95f);
        for (int k = 0; k < 200; ++k) {
            const SurfaceGeometry g = sphere->Evaluate(inside(random), inside(random));
            const Probe probe = ProbeAt(g, s.distance, s.speed);
            QuadricHit hit;
            ASSERT_TRUE(sphere->Intersect(probe.org, probe.dir, 0, kInfinity, &hit));
            const long double reference = ReferenceSphereT(probe.org, probe.dir, s.radius);
            EXPECT_NEAR(hit.t, double(reference), 2e-7 * double(reference));
            EXPECT_NEAR(hit.u, g.u, 1e-4);
            EXPECT_NEAR(hit.v, g.v, 1e-4);
        }
    }
}

TEST(QuadricFarRays, EveryShapeHitsAccuratelyFrom1000Units) {
    // Shapes whose outside is visible along the normal from any distance (convex pieces, the
    // outer half of a torus), hit from 1e3 units: the error allowed is a few float roundings
    // of the ray origin and direction (1e3 · 6e-8), far below a float solver's ~1e-2.
    const std::vector<QuadricCase> cases = AllQuadricCases();
    for (const char* name : {"SphereFull", "CylinderFull", "ConeFull", "DiskFull", "ParaboloidFull",
                             "TorusFull", "TorusPartial"}) {
        const QuadricCase& c =
            *std::find_if(cases.begin(), cases.end(), [&](auto& x) { return x.name == name; });
        const auto shape = c.make();
        std::mt19937 random(2);
        std::uniform_real_distribution<float> inside(0.05f, 0.95f);
        int tested = 0;
        for (int k = 0; k < 300; ++k) {
            const SurfaceGeometry g = shape->Evaluate(inside(random), inside(random));
            if (c.name.rfind("Torus", 0) == 0 && D(g.Ng).dot(D(g.P)) <= 0.1) continue;
            const Probe probe = ProbeAt(g, 1000, 0.5);
            QuadricHit hit;
            ASSERT_TRUE(shape->Intersect(probe.org, probe.dir, 0, kInfinity, &hit)) << name;
            const V3d p = D(probe.org) + double(hit.t) * D(probe.dir);
            EXPECT_LT((p - D(g.P)).length(), 5e-4 * c.scale) << name;
            EXPECT_NEAR(hit.u, g.u, 1e-3) << name;
            EXPECT_NEAR(hit.v, g.v, 1e-3) << name;
            ++tested;
        }
        EXPECT_GT(tested, 100) << name;
    }
}

TEST(QuadricDegenerate, NeverHitAndEvaluateToFiniteValues) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<std::unique_ptr<Quadric>> shapes;
    shapes.push_back(MakeSphere(0, -1, 1, 360));
    shapes.push_back(MakeSphere(1, -1, 1, 0));
    shapes.push_back(MakeSphere(1, 0.5f, 0.5f, 360));
    shapes.push_back(MakeSphere(1, 2, 3, 360));
    shapes.push_back(MakeSphere(nan, -1, 1, 360));
    shapes.push_back(MakeCylinder(0, -1, 1, 360));
    shapes.push_back(MakeCylinder(1, 1, 1, 360));
    shapes.push_back(MakeCylinder(1, -1, 1, 0));
    shapes.push_back(MakeCone(1, 0, 360));
    shapes.push_back(MakeCone(0, 0, 360));
    shapes.push_back(MakeDisk(0, 0, 360));
    shapes.push_back(MakeDisk(1, 1, 0));
    shapes.push_back(MakeHyperboloid(V3f(1, 1, 1), V3f(1, 1, 1), 360));
    shapes.push_back(MakeHyperboloid(V3f(0, 0, -1), V3f(0, 0, 1), 360));
    shapes.push_back(MakeParaboloid(0, 0, 1, 360));
    shapes.push_back(MakeParaboloid(1, 0, 0, 360));
    shapes.push_back(MakeParaboloid(1, 0.5f, 0.5f, 360));
    shapes.push_back(MakeTorus(1, 0, 0, 360, 360));
    shapes.push_back(MakeTorus(1, 0.5f, 90, 90, 360));
    shapes.push_back(MakeTorus(1, 0.5f, 0, 360, 0));
    shapes.push_back(MakeTorus(1, 0.5f, 1e20f, 1e20f, 360));  // huge equal angles
    shapes.push_back(MakeTorus(1, 0.5f, 0, 360, std::numeric_limits<float>::infinity()));
    std::mt19937 random(4);
    std::normal_distribution<float> gauss;
    for (size_t i = 0; i < shapes.size(); ++i) {
        const Box3f box = shapes[i]->Bounds();
        EXPECT_TRUE(
            std::isfinite(box.min.x + box.min.y + box.min.z + box.max.x + box.max.y + box.max.z))
            << i;
        for (int k = 0; k < 500; ++k) {
            const V3f org = V3f(gauss(random), gauss(random), gauss(random)) * 3.0f;
            const V3f dir = V3f(gauss(random), gauss(random), gauss(random));
            QuadricHit hit;
            EXPECT_FALSE(shapes[i]->Intersect(org, dir, 0, kInfinity, &hit)) << i;
            // Rays straight through the origin and along the axis, too.
            EXPECT_FALSE(shapes[i]->Intersect(org, -org, 0, kInfinity, &hit)) << i;
            EXPECT_FALSE(shapes[i]->Intersect(V3f(0, 0, 5), V3f(0, 0, -1), 0, kInfinity, &hit))
                << i;
        }
        for (float u : {0.0f, 0.5f, 1.0f}) {
            for (float v : {0.0f, 0.5f, 1.0f}) {
                const SurfaceGeometry g = shapes[i]->Evaluate(u, v);
                for (const V3f& x : {g.P, g.Ng, g.dPdu, g.dPdv})
                    EXPECT_TRUE(std::isfinite(x.x + x.y + x.z)) << i << " " << u << " " << v;
                EXPECT_NEAR(g.Ng.length(), 1, 1e-6) << i;
            }
        }
    }
}

TEST(QuadricRays, ZeroOrNonFiniteDirectionsMiss) {
    const auto sphere = MakeSphere(1, -1, 1, 360);
    QuadricHit hit;
    EXPECT_FALSE(sphere->Intersect(V3f(0, 0, 5), V3f(0), 0, kInfinity, &hit));
    EXPECT_FALSE(sphere->Intersect(V3f(0, 0, 5), V3f(0, 0, -kInfinity), 0, kInfinity, &hit));
    EXPECT_TRUE(sphere->Intersect(V3f(0, 0, 5), V3f(0, 0, -1), 0, kInfinity, &hit));
    EXPECT_FLOAT_EQ(hit.t, 4);
    // From inside, the far wall; behind tmin, nothing.
    EXPECT_TRUE(sphere->Intersect(V3f(0), V3f(2, 0, 0), 0, kInfinity, &hit));
    EXPECT_FLOAT_EQ(hit.t, 0.5f);
    EXPECT_FALSE(sphere->Intersect(V3f(0, 0, 5), V3f(0, 0, 1), 0, kInfinity, &hit));
}

TEST(QuadricRays, TorusIsHitFourTimesAlongADiameter) {
    const auto torus = MakeTorus(2, 0.5f, 0, 360, 360);
    const V3f org(-10, 0, 0), dir(1, 0, 0);
    std::vector<float> ts;
    QuadricHit hit;
    float tmin = 0;
    while (torus->Intersect(org, dir, tmin, kInfinity, &hit)) {
        ts.push_back(hit.t);
        tmin = hit.t + 1e-4f;
    }
    ASSERT_EQ(ts.size(), 4u);
    const float expected[4] = {7.5f, 8.5f, 11.5f, 12.5f};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(ts[i], expected[i], 1e-5) << i;
}

TEST(QuadricRays, HyperboloidThroughTheAxisIsADoubleCone) {
    // The line (1, 0, −1) → (−1, 0, 1) sweeps x² + y² = z²; above z = 0 the profile lies at
    // x < 0, so the point (0.5, 0, 0.5) is reached by turning it half a turn.
    const auto cone = MakeHyperboloid(V3f(1, 0, -1), V3f(-1, 0, 1), 360);
    QuadricHit hit;
    ASSERT_TRUE(cone->Intersect(V3f(5, 0, 0.5f), V3f(-1, 0, 0), 0, kInfinity, &hit));
    EXPECT_NEAR(hit.t, 4.5, 1e-6);
    EXPECT_NEAR(hit.u, 0.5, 1e-6);
    EXPECT_NEAR(hit.v, 0.75, 1e-6);
    const SurfaceGeometry g = cone->Evaluate(hit.u, hit.v);
    EXPECT_NEAR((D(g.P) - V3d(0.5, 0, 0.5)).length(), 0, 1e-6);
    EXPECT_NEAR((D(g.Ng) - V3d(1, 0, -1) / std::sqrt(2.0)).length(), 0, 1e-6);
    // At the apex Ng is the limit from above (v > 0.5), which points down and out.
    const SurfaceGeometry apex = cone->Evaluate(0, 0.5f);
    EXPECT_NEAR((D(apex.Ng) - V3d(-1, 0, -1) / std::sqrt(2.0)).length(), 0, 1e-6);
}

TEST(QuadricRays, FlatHyperboloidFacesDownWhenItsLineRunsOutwards) {
    // RISpec's example "Hyperboloid 0 0 0 .5 0 0 270": a disk whose v runs from the centre
    // out, the opposite of Disk, so its Ng is −z.
    const auto flat = MakeHyperboloid(V3f(0, 0, 0), V3f(0.5f, 0, 0), 270);
    QuadricHit hit;
    ASSERT_TRUE(flat->Intersect(V3f(0, 0.25f, 1), V3f(0, 0, -1), 0, kInfinity, &hit));
    EXPECT_NEAR(hit.t, 1, 1e-6);
    EXPECT_NEAR(hit.u, 90.0 / 270, 1e-6);
    EXPECT_NEAR(hit.v, 0.5, 1e-6);
    EXPECT_NEAR(flat->Evaluate(hit.u, hit.v).Ng.z, -1, 1e-6);
    EXPECT_FALSE(flat->Intersect(V3f(0.1f, -0.25f, 1), V3f(0, 0, -1), 0, kInfinity, &hit));
}

TEST(QuadricRays, SpindleTorusAndOverSweptSphere) {
    // Spindle torus (r > R): its inner lemon is the tube's far side swept around.
    const auto spindle = MakeTorus(0.5f, 1, 0, 360, 360);
    QuadricHit hit;
    ASSERT_TRUE(spindle->Intersect(V3f(0, 0, 0), V3f(1, 0, 0), 0, kInfinity, &hit));
    EXPECT_NEAR(hit.t, 0.5, 1e-6);  // the lemon's equator, radius r − R
    EXPECT_NEAR(hit.u, 0.5, 1e-6);  // reached by the half plane θ = 180°
    ASSERT_TRUE(spindle->Intersect(V3f(0, 0, 0), V3f(1, 0, 0), 0.6f, kInfinity, &hit));
    EXPECT_NEAR(hit.t, 1.5, 1e-6);  // the apple's equator, R + r
    EXPECT_NEAR(hit.u, 0, 1e-6);
    ASSERT_TRUE(spindle->Intersect(V3f(0, 0, -5), V3f(0, 0, 1), 0, kInfinity, &hit));
    EXPECT_NEAR(hit.t, 5 - std::sqrt(0.75), 1e-5);  // the lemon's tip at z = −√(r² − R²)
    // A torus with no hole radius is a sphere swept twice over.
    const auto ball = MakeTorus(0, 1, 0, 360, 360);
    ASSERT_TRUE(ball->Intersect(V3f(0.5f, 0, 5), V3f(0, 0, -1), 0, kInfinity, &hit));
    EXPECT_NEAR(hit.t, 5 - std::sqrt(0.75), 1e-6);
    EXPECT_NEAR((D(ball->Evaluate(hit.u, hit.v).P) - V3d(0.5, 0, std::sqrt(0.75))).length(), 0,
                1e-6);
    // thetamax beyond 360 sweeps twice: the smallest u is reported.
    const auto twice = MakeSphere(1, -1, 1, 720);
    ASSERT_TRUE(twice->Intersect(V3f(0, 5, 0), V3f(0, -1, 0), 0, kInfinity, &hit));
    EXPECT_NEAR(hit.u, 0.125, 1e-6);
}

TEST(QuadricRays, OnlyWholeSpheresHaveTheCompleteSphereTest) {
    // The ray tracer's callback calls AsCompleteSphere's test in place of IntersectPoint: only
    // a sphere with nothing cut away may have one, as it clips nothing.
    EXPECT_NE(MakeSphere(1, -1, 1, 360)->AsCompleteSphere(), nullptr);
    EXPECT_NE(MakeSphere(-2, -3, 3, 720)->AsCompleteSphere(), nullptr);  // zmin, zmax beyond r
    EXPECT_EQ(MakeSphere(1, -0.5f, 1, 360)->AsCompleteSphere(), nullptr);
    EXPECT_EQ(MakeSphere(1, -1, 1, 270)->AsCompleteSphere(), nullptr);
    EXPECT_EQ(MakeSphere(0, -1, 1, 360)->AsCompleteSphere(), nullptr);  // degenerate
    EXPECT_EQ(MakeCylinder(1, -1, 1, 360)->AsCompleteSphere(), nullptr);
    EXPECT_EQ(MakeTorus(1, 0.5f, 0, 360, 360)->AsCompleteSphere(), nullptr);
    EXPECT_NE(MakeTorus(0, 1, 0, 360, 360)->AsCompleteSphere(), nullptr);  // a sphere twice over
    // It reports IntersectPoint's hits: the nearer root past tmin, else the farther one.
    const CompleteSphere& sphere = *MakeSphere(2, -2, 2, 360)->AsCompleteSphere();
    float t;
    V3f p;
    ASSERT_TRUE(sphere.Intersect(V3f(0, 0, 5), V3f(0, 0, -2), 0, kInfinity, &t, &p));
    EXPECT_FLOAT_EQ(t, 1.5f);
    EXPECT_EQ(p, V3f(0, 0, 2));
    ASSERT_TRUE(sphere.Intersect(V3f(0, 0, 5), V3f(0, 0, -2), 1.6f, kInfinity, &t, &p));
    EXPECT_FLOAT_EQ(t, 3.5f);
    EXPECT_EQ(p, V3f(0, 0, -2));
    EXPECT_FALSE(sphere.Intersect(V3f(0, 0, 5), V3f(0, 0, -2), 1.6f, 3.4f, &t, &p));
    EXPECT_FALSE(sphere.Intersect(V3f(2.01f, 0, 5), V3f(0, 0, -1), 0, kInfinity, &t, &p));
}

}  // namespace
}  // namespace gonio::test
