// AreaLightGeometry (renderer/raytrace/area_light_geometry.h) on scenes built from RIB: which
// shapes an AreaLightSource owns, their exact areas, and sample means against the analytic
// centroid and mean normal of each surface. The Monte Carlo means use 2^16 stratified samples
// (a 256 × 256 grid, one jittered point per cell): their standard error is far below the
// tolerances, which are set by the surfaces' exact moments, not widened to pass.

#include "renderer/raytrace/area_light_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "base/math.h"
#include "renderer/raytrace/shadow_transmission.h"
#include "tests/support/parse_world.h"

namespace gonio {
namespace {

using Imath::V3f;

using Built = test::BuiltWorld;

Built Parse(const std::string& world) { return test::ParseWorld(world); }

// The geometry of the frame's first light.
AreaLightGeometry LightOf(const std::string& world) {
    const Built built = Parse(world);
    EXPECT_EQ(built.frames.size(), 1u);
    const Frame& frame = built.frames.at(0);
    EXPECT_FALSE(frame.lights.empty());
    return AreaLightGeometry::Build(frame, frame.lights.at(0));
}

struct Moments {
    V3f meanP{0}, meanN{0};
    float minPdf = 1e30f, maxPdf = 0;
    float minRadius = 1e30f, maxRadius = 0;  // |P|
};

Moments SampleMoments(const AreaLightGeometry& light, int count = 1 << 16) {
    // A Halton-Hammersley set, ((k + ½)/count, radical inverses of k in bases 2 and 3), shifted
    // by one random offset: stratified in u0 (which picks the piece) and in (u1, u2) alike.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0, 1);
    const float shift[3] = {uniform(rng), uniform(rng), uniform(rng)};
    auto radical = [](uint32_t k, uint32_t base) {
        double inverse = 0, digit = 1.0 / base;
        for (; k > 0; k /= base, digit /= base) inverse += (k % base) * digit;
        return inverse;
    };
    auto wrap = [](double x) { return float(std::min(x - std::floor(x), 0.99999994)); };
    Moments m;
    double sx = 0, sy = 0, sz = 0, nx = 0, ny = 0, nz = 0, weight = 0;
    for (int k = 0; k < count; ++k) {
        const AreaLightSample s =
            light.Sample(wrap((k + 0.5) / count + shift[0]), wrap(radical(k, 2) + shift[1]),
                         wrap(radical(k, 3) + shift[2]));
        // Weighted by 1/(pdf·Area): exactly 1 where sampling is uniform, and an unbiased
        // uniform-area mean where it is only nearly so.
        const double w = 1.0 / (s.pdfArea * light.Area());
        sx += w * s.P.x, sy += w * s.P.y, sz += w * s.P.z;
        nx += w * s.N.x, ny += w * s.N.y, nz += w * s.N.z, weight += w;
        m.minPdf = std::min(m.minPdf, s.pdfArea), m.maxPdf = std::max(m.maxPdf, s.pdfArea);
        m.minRadius = std::min(m.minRadius, s.P.length());
        m.maxRadius = std::max(m.maxRadius, s.P.length());
    }
    const double n = count;
    m.meanP = V3f(float(sx / n), float(sy / n), float(sz / n));
    m.meanN = V3f(float(nx / n), float(ny / n), float(nz / n));
    EXPECT_NEAR(weight / n, 1.0, 2e-3);
    return m;
}

void ExpectNear(const V3f& got, const V3f& want, float tolerance, const char* what) {
    EXPECT_NEAR(got.x, want.x, tolerance) << what;
    EXPECT_NEAR(got.y, want.y, tolerance) << what;
    EXPECT_NEAR(got.z, want.z, tolerance) << what;
}

TEST(AreaLightShapes, ThePrimitivesOfTheBlockAfterTheLight) {
    const Built built = Parse(
        "Sphere 1 -1 1 360\n"  // before the light: not its geometry
        "AttributeBegin\n"
        "  AreaLightSource \"arealight\" 1\n"
        "  Disk 0 1 360\n"
        "  AttributeBegin\n    Polygon \"P\" [0 0 0 1 0 0 1 1 0]\n  AttributeEnd\n"
        "  Points \"P\" [0 0 0] \"constantwidth\" [0.1]\n"
        "AttributeEnd\n"
        "Disk 0 1 360\n");  // after the block: not its geometry
    ASSERT_EQ(built.frames.size(), 1u);
    const Frame& frame = built.frames[0];
    ASSERT_EQ(frame.lights.size(), 1u);
    EXPECT_TRUE(frame.lights[0].light.isArea);
    EXPECT_EQ(frame.lights[0].shapes, (std::vector<size_t>{1, 2}));
    EXPECT_EQ(frame.shapes.size(), 5u);  // all of them are still rendered
    EXPECT_NE(built.messages.find("test.rib:9:3: warning: curves and points are not area light "
                                  "geometry"),
              std::string::npos)
        << built.messages;
}

TEST(AreaLightShapes, ObjectInstancesAreNotLightGeometry) {
    const Built built = Parse(
        "ObjectBegin 1\n  Disk 0 1 360\nObjectEnd\n"
        "AreaLightSource \"arealight\" 1\nObjectInstance 1\n");
    ASSERT_EQ(built.frames.size(), 1u);
    EXPECT_TRUE(built.frames[0].lights[0].shapes.empty());
    EXPECT_NE(built.messages.find("test.rib:6:1: warning: an object instance is not area light"),
              std::string::npos)
        << built.messages;
}

TEST(ShadowTransmission, TheWordsOfTheAttribute) {
    const Built built = Parse(
        "Sphere 1 -1 1 360\n"
        "Attribute \"visibility\" \"transmission\" \"opaque\"\nSphere 1 -1 1 360\n"
        "Attribute \"visibility\" \"transmission\" \"transparent\"\nSphere 1 -1 1 360\n"
        "Attribute \"visibility\" \"transmission\" \"shader\"\nSphere 1 -1 1 360\n"
        "Attribute \"visibility\" \"transmission\" \"glass\"\nSphere 1 -1 1 360\n");
    ASSERT_EQ(built.frames.size(), 1u);
    const std::vector<SceneShape>& shapes = built.frames[0].shapes;
    ASSERT_EQ(shapes.size(), 5u);
    EXPECT_EQ(TransmissionOf(*shapes[0].attributes), Transmission::Opacity);  // unset: Os
    EXPECT_EQ(TransmissionOf(*shapes[1].attributes), Transmission::Opaque);
    EXPECT_EQ(TransmissionOf(*shapes[2].attributes), Transmission::Transparent);
    EXPECT_EQ(TransmissionOf(*shapes[3].attributes), Transmission::Opacity);
    EXPECT_EQ(TransmissionOf(*shapes[4].attributes), Transmission::Opacity);
    EXPECT_NE(built.messages.find("test.rib:9:1: warning: Attribute \"visibility\" "
                                  "\"transmission\" must be opaque, transparent, Os or shader, "
                                  "got \"glass\" (taken as Os)"),
              std::string::npos)
        << built.messages;
    // Opacity 1 everywhere and no "transparent": one any-hit ray answers every shadow ray.
    EXPECT_FALSE(AllShadowsOpaque(built.frames[0]));
    EXPECT_TRUE(AllShadowsOpaque(Parse("Sphere 1 -1 1 360\n").frames.at(0)));
    EXPECT_FALSE(AllShadowsOpaque(Parse("Opacity [1 0.5 1]\nSphere 1 -1 1 360\n").frames.at(0)));
}

TEST(AreaLightGeometry, DiskAreaCentroidAndNormal) {
    // A disk of radius 2 at height 3, turned to face −z by Orientation "inside".
    const AreaLightGeometry light =
        LightOf("AreaLightSource \"arealight\" 1\nOrientation \"inside\"\nDisk 3 2 360\n");
    EXPECT_NEAR(light.Area(), kPi * 4, 1e-4 * kPi * 4);
    const Moments m = SampleMoments(light);
    ExpectNear(m.meanP, V3f(0, 0, 3), 5e-3f, "mean P");
    ExpectNear(m.meanN, V3f(0, 0, -1), 1e-6f, "mean N");
    // Uniform exactly: the disk's area element is linear in v.
    EXPECT_NEAR(m.minPdf * light.Area(), 1, 1e-3);
    EXPECT_NEAR(m.maxPdf * light.Area(), 1, 1e-3);
}

TEST(AreaLightGeometry, AMovingLightWhereItsMotionStarts) {
    const AreaLightGeometry light = LightOf(
        "AreaLightSource \"arealight\" 1\n"
        "MotionBegin [0 1]\n  Translate 0 0 2\n  Translate 5 0 2\nMotionEnd\nDisk 0 1 360\n");
    ExpectNear(SampleMoments(light, 4096).meanP, V3f(0, 0, 2), 5e-3f, "mean P");
}

TEST(AreaLightGeometry, PartialDiskSweepCentroid) {
    // A half disk (θ in [0°, 180°]) of radius 1: centroid y = 4/(3π).
    const AreaLightGeometry light = LightOf("AreaLightSource \"arealight\" 1\nDisk 0 1 180\n");
    EXPECT_NEAR(light.Area(), kPi / 2, 1e-4);
    ExpectNear(SampleMoments(light).meanP, V3f(0, 4 / (3 * kPi), 0), 5e-3f, "mean P");
}

TEST(AreaLightGeometry, SphereAreaAndSymmetry) {
    const AreaLightGeometry light =
        LightOf("AreaLightSource \"arealight\" 1\nTranslate 1 2 3\nSphere 0.5 -0.5 0.5 360\n");
    // Area() integrates the area element by the trapezoid rule over 256 bands in v: for the
    // sphere's cos φ that is low by (π/256)²/12 ≈ 1.3e-5 of the area.
    EXPECT_NEAR(light.Area(), kPi, 2e-5 * kPi);
    const Moments m = SampleMoments(light);
    ExpectNear(m.meanP, V3f(1, 2, 3), 5e-3f, "mean P");
    ExpectNear(m.meanN, V3f(0), 5e-3f, "mean N");  // a closed surface's normals cancel
    EXPECT_NEAR(m.minPdf * light.Area(), 1, 1e-3);
    EXPECT_NEAR(m.maxPdf * light.Area(), 1, 1e-3);
}

TEST(AreaLightGeometry, HemisphereCentroid) {
    // The upper hemisphere of radius 1: Archimedes' z-uniform area puts its centroid at z = 1/2.
    const AreaLightGeometry light = LightOf("AreaLightSource \"arealight\" 1\nSphere 1 0 1 360\n");
    EXPECT_NEAR(light.Area(), 2 * kPi, 2e-5 * 2 * kPi);
    ExpectNear(SampleMoments(light).meanP, V3f(0, 0, 0.5f), 5e-3f, "mean P");
}

TEST(AreaLightGeometry, NonUniformlyScaledCylinder) {
    // A unit cylinder of height 1 squashed to an elliptic one (x·2): its area is the ellipse's
    // perimeter (semi-axes 2 and 1, Ramanujan's second formula, error ~1e-6) times the height.
    const AreaLightGeometry light =
        LightOf("AreaLightSource \"arealight\" 1\nScale 2 1 1\nCylinder 1 0 1 360\n");
    const float a = 2, b = 1, h = (a - b) * (a - b) / ((a + b) * (a + b));
    const float perimeter = kPi * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
    EXPECT_NEAR(light.Area(), perimeter, 1e-3 * perimeter);
    ExpectNear(SampleMoments(light).meanP, V3f(0, 0, 0.5f), 5e-3f, "mean P");
}

TEST(AreaLightGeometry, ScaledPolygonAndMirroredNormal) {
    // A unit square scaled by 3 × 2: area 6. Scale −1 in z mirrors the space: the normal is
    // the object normal +z carried by the inverse transpose, −z, as the ray tracer shades it.
    const AreaLightGeometry light = LightOf(
        "AreaLightSource \"arealight\" 1\nScale 3 2 1\n"
        "Polygon \"P\" [0 0 0  1 0 0  1 1 0  0 1 0]\n");
    EXPECT_NEAR(light.Area(), 6, 1e-5);
    const Moments m = SampleMoments(light);
    ExpectNear(m.meanP, V3f(1.5f, 1, 0), 5e-3f, "mean P");
    ExpectNear(m.meanN, V3f(0, 0, 1), 1e-6f, "mean N");
    const AreaLightGeometry mirrored = LightOf(
        "AreaLightSource \"arealight\" 1\nScale 1 1 -1\n"
        "Polygon \"P\" [0 0 0  1 0 0  1 1 0  0 1 0]\n");
    ExpectNear(SampleMoments(mirrored, 256).meanN, V3f(0, 0, -1), 1e-6f, "mirrored N");
}

TEST(AreaLightGeometry, ShapesSampledInProportionToArea) {
    // A unit square at x in [0,1] and one of side 2 at x in [10,12]: the mean x is the
    // area-weighted (1·0.5 + 4·11)/5.
    const AreaLightGeometry light = LightOf(
        "AreaLightSource \"arealight\" 1\n"
        "Polygon \"P\" [0 0 0  1 0 0  1 1 0  0 1 0]\n"
        "Polygon \"P\" [10 0 0  12 0 0  12 2 0  10 2 0]\n");
    EXPECT_NEAR(light.Area(), 5, 1e-5);
    EXPECT_NEAR(SampleMoments(light).meanP.x, (0.5f + 4 * 11) / 5, 0.05f);
}

TEST(AreaLightGeometry, SubdivisionCubeIsOnItsLimitSurface) {
    // The Catmull-Clark limit of the cube [−1, 1]³ lies between its face centres' limit, at
    // (16·1 + 4·3 + 20/9)/36 ≈ 0.8395 from the centre (Halstead et al.'s rule after one
    // refinement), and its corners' limit, (9 + 4 − 1)/24·(1, 1, 1) at 0.866. The sampled
    // triangles are chords of it: after three refinements a quad spans about θ = √2·(π/2)/8 ≈
    // 0.28 rad across its diagonal, so its middle lies inside by up to r(1 − cos(θ/2)) ≈ 0.008.
    const AreaLightGeometry light = LightOf(
        "AreaLightSource \"arealight\" 1\n"
        "SubdivisionMesh \"catmull-clark\" [4 4 4 4 4 4]\n"
        "  [0 3 2 1  4 5 6 7  0 1 5 4  1 2 6 5  2 3 7 6  3 0 4 7] [] [] [] []\n"
        "  \"P\" [-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1]\n");
    ASSERT_FALSE(light.Empty());
    const float rMin = 0.8395f - 0.009f, rMax = 0.8661f;
    EXPECT_GT(light.Area(), 4 * kPi * rMin * rMin);
    EXPECT_LT(light.Area(), 4 * kPi * rMax * rMax);
    const Moments m = SampleMoments(light);
    EXPECT_GT(m.minRadius, rMin);
    EXPECT_LT(m.maxRadius, rMax);
    ExpectNear(m.meanP, V3f(0), 1e-3f, "mean P");
    ExpectNear(m.meanN, V3f(0), 1e-3f, "mean N");  // closed: the normals cancel
    // Outward, as the cage's faces are wound.
    const AreaLightSample s = light.Sample(0.5f, 0.5f, 0.5f);
    EXPECT_GT(s.N.dot(s.P), 0.9f * s.P.length());
}

}  // namespace
}  // namespace gonio
