// RayScene::IntersectCoherent, the camera's packets of 8, must find exactly the hits Intersect
// finds one ray at a time: the same primitive at the same t, on quadrics, meshes, object
// instances and moving shapes, for any number of rays (partial packets) and for frames that
// take the rays one by one (solids).
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "renderer/raytrace/ray_scene.h"
#include "tests/support/captured_diagnostics.h"
#include "tests/support/parse_world.h"

namespace gonio {
namespace {

using Imath::V3f;

// Rays from near one point fanning over the scene, as a pinhole camera's neighbouring samples
// do, with times across the shutter.
std::vector<RayScene::CoherentRay> Fan(int count, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0, 1);
    std::vector<RayScene::CoherentRay> rays;
    for (int i = 0; i < count; ++i) {
        const V3f dir(unit(random) * 0.8f - 0.4f, unit(random) * 0.8f - 0.4f, 1);
        rays.push_back({V3f(0, 0, -8) + 0.01f * V3f(unit(random), unit(random), 0), dir, 0, 1e30f,
                        unit(random)});
    }
    return rays;
}

void ExpectSameHits(const std::string& world, int count) {
    const test::BuiltWorld built = test::ParseWorld(world);
    ASSERT_EQ(built.errors, 0) << built.messages;
    ASSERT_EQ(built.frames.size(), 1u);
    test::CapturedDiagnostics diagnostics;
    const RayScene scene(built.frames[0], diagnostics.Get());
    const std::vector<RayScene::CoherentRay> rays = Fan(count, 17);
    std::vector<RayHit> hits(rays.size());
    std::vector<uint8_t> found(rays.size());
    scene.IntersectCoherent(count, rays.data(), hits.data(), found.data());
    int hitCount = 0;
    for (int i = 0; i < count; ++i) {
        const RayScene::CoherentRay& r = rays[size_t(i)];
        RayHit expected;
        const bool expectedFound =
            scene.Intersect(r.org, r.dir, r.tnear, r.tfar, r.time, &expected);
        ASSERT_EQ(bool(found[size_t(i)]), expectedFound) << "ray " << i;
        if (!expectedFound) continue;
        ++hitCount;
        const RayHit& hit = hits[size_t(i)];
        EXPECT_EQ(hit.t, expected.t) << "ray " << i;
        EXPECT_EQ(hit.geomID, expected.geomID) << "ray " << i;
        EXPECT_EQ(hit.primID, expected.primID) << "ray " << i;
        EXPECT_EQ(hit.instID, expected.instID) << "ray " << i;
        EXPECT_EQ(hit.objectP, expected.objectP) << "ray " << i;
        EXPECT_EQ(hit.Ng, expected.Ng) << "ray " << i;
        EXPECT_EQ(hit.u, expected.u) << "ray " << i;
        EXPECT_EQ(hit.v, expected.v) << "ray " << i;
    }
    // Enough of each to mean something: the fan covers the shapes and the space around them.
    EXPECT_GT(hitCount, count / 10);
    EXPECT_LT(hitCount, count);
}

const char* const kShapes =
    "Sphere 1 -1 1 360\n"
    "AttributeBegin Translate 2 0 1 Cylinder 0.5 -1 1 270 AttributeEnd\n"
    "AttributeBegin Translate -2 0 1 Polygon \"P\" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] AttributeEnd\n"
    "ObjectBegin 1 Sphere 0.4 -0.4 0.4 360 ObjectEnd\n"
    "AttributeBegin Translate 0 2 0 ObjectInstance 1 AttributeEnd\n"
    "AttributeBegin MotionBegin [0 1] Translate 0 -2 0 Translate 1 -2 0 MotionEnd\n"
    "Sphere 0.5 -0.5 0.5 360 AttributeEnd\n";

TEST(CoherentRays, FindWhatSingleRaysFind) { ExpectSameHits(kShapes, 4096); }

TEST(CoherentRays, FindWhatSingleRaysFindInAPartialPacket) { ExpectSameHits(kShapes, 8 * 37 + 5); }

TEST(CoherentRays, FindWhatSingleRaysFindWithSolids) {
    ExpectSameHits(std::string(kShapes) +
                       "SolidBegin \"difference\" Sphere 1.5 -1.5 1.5 360 "
                       "AttributeBegin Translate 0 0 -1 Sphere 1 -1 1 360 AttributeEnd SolidEnd\n",
                   1000);
}

}  // namespace
}  // namespace gonio
