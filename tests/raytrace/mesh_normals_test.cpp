// A triangle mesh's camera hits take their geometric normal from Embree's, which the
// intersection computed from the vertices as built in the record's space, instead of from the
// object-space vertices: under every transform (mirroring ones too), in object instances and
// with either orientation, it must be the normal the object-space cross product gives, which a
// mesh with normals of its own ("N") still uses.
#include <gtest/gtest.h>

#include <string>

#include "renderer/raytrace/ray_scene.h"
#include "tests/support/captured_diagnostics.h"
#include "tests/support/parse_world.h"

namespace gonio {
namespace {

using Imath::V3f;

// The world Ng at the centre of the one shape of `world`, seen from (0, 0, -8).
V3f NgAtCentre(const std::string& world) {
    const test::BuiltWorld built = test::ParseWorld(world);
    EXPECT_EQ(built.errors, 0) << built.messages;
    if (built.frames.size() != 1) return V3f(0);
    test::CapturedDiagnostics diagnostics;
    const RayScene scene(built.frames[0], diagnostics.Get());
    const V3f org(0.05f, 0.1f, -8), dir(0, 0, 1);
    RayHit hit;
    EXPECT_TRUE(scene.Intersect(org, dir, 0, 1e30f, 0, &hit)) << world;
    return scene.Evaluate(org, dir, hit).Ng;
}

// A square in the plane z = 0 of its object space; with "N", normals that make it smooth and so
// take the object-space path (they are the face's own normal, so they change no shading).
std::string Square(const std::string& transform, bool withNormals) {
    std::string square = "Polygon \"P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]";
    if (withNormals) square += " \"N\" [0 0 1  0 0 1  0 0 1  0 0 1]";
    return "AttributeBegin " + transform + " " + square + " AttributeEnd\n";
}

TEST(MeshNormals, EmbreesNormalIsTheObjectSpaceNormalUnderEveryTransform) {
    const char* const transforms[] = {"",
                                      "Rotate 30 0 1 0",
                                      "Scale -1 1 1",
                                      "Scale 2 -0.5 3 Rotate 20 1 1 0",
                                      "ReverseOrientation",
                                      "ReverseOrientation Scale 1 1 -1 Rotate 170 0 1 0",
                                      "Orientation \"rh\""};
    for (const char* transform : transforms) {
        const V3f flat = NgAtCentre(Square(transform, false));
        const V3f smooth = NgAtCentre(Square(transform, true));
        EXPECT_NEAR((flat - smooth).length(), 0, 1e-5f) << transform;
        EXPECT_NEAR(flat.length(), 1, 1e-6f) << transform;
    }
}

TEST(MeshNormals, EmbreesNormalInAnInstanceIsTheObjectSpaceNormal) {
    for (const char* placement : {"Rotate 25 1 0 0", "Scale -1 2 1"}) {
        for (bool withNormals : {false, true}) {
            const std::string world =
                "ObjectBegin 1 " + Square("Scale 1 -1 1 Rotate 10 0 1 0", withNormals) +
                "ObjectEnd\nAttributeBegin " + placement + " ObjectInstance 1 AttributeEnd\n";
            const V3f n = NgAtCentre(world);
            const V3f expected =
                NgAtCentre("AttributeBegin " + std::string(placement) + " " +
                           Square("Scale 1 -1 1 Rotate 10 0 1 0", true) + "AttributeEnd\n");
            EXPECT_NEAR((n - expected).length(), 0, 1e-5f) << placement << " " << withNormals;
        }
    }
}

}  // namespace
}  // namespace gonio
