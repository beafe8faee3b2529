// CSG (SolidBegin, RISpec 3.2 §5.9) in RayScene against the interval oracle of csg_oracle.h:
// for a grid of orthographic rays and for random rays starting anywhere (inside solids too, as
// shadow rays from a surface do), Intersect finds the oracle's first boundary of the combined
// solid (t within 1e-4), on the primitive the oracle names, with the combined solid's outward
// normal (a carved part shows the subtracting primitive's surface turned round), and Occluded
// agrees. Rays passing within 1e-3 of a tangent or of another crossing are skipped: float
// cannot decide them and the oracle's double can.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "renderer/raytrace/ray_scene.h"
#include "tests/csg/csg_oracle.h"
#include "tests/support/captured_diagnostics.h"
#include "tests/support/parse_world.h"

namespace gonio {
namespace {

using Imath::V3f;
using test::CsgTree;
using test::Op;
using test::Primitive;
using test::Sphere;
using test::V3d;

using Built = test::BuiltWorld;

Built Parse(const std::string& world) { return test::ParseWorld(world); }

V3f ToF(const V3d& v) { return V3f(float(v.x), float(v.y), float(v.z)); }

constexpr double kUndecidable = 1e-3;

struct Counts {
    int hits = 0, misses = 0, skipped = 0;
};

// One ray against the scene and the oracle; returns false when the ray was skipped.
bool CheckRay(const RayScene& scene, const CsgTree& tree, const std::vector<Primitive>& leaves,
              const V3d& org, const V3d& dir, Counts* counts) {
    if (test::NearestCrossingGap(tree, org, dir) < kUndecidable) {
        ++counts->skipped;
        return false;
    }
    const std::optional<test::Boundary> expected = test::FirstBoundary(tree, org, dir, 0);
    // The first crossing must also be clear of the ray's start (a shadow ray's offset).
    if (expected && expected->t < kUndecidable) {
        ++counts->skipped;
        return false;
    }
    RayHit hit;
    const bool found = scene.Intersect(ToF(org), ToF(dir), 0, 1e30f, 0, &hit);
    const std::string ray = "ray from (" + std::to_string(org.x) + ", " + std::to_string(org.y) +
                            ", " + std::to_string(org.z) + ") along (" + std::to_string(dir.x) +
                            ", " + std::to_string(dir.y) + ", " + std::to_string(dir.z) + ")";
    EXPECT_EQ(found, expected.has_value()) << ray;
    EXPECT_EQ(scene.Occluded(ToF(org), ToF(dir), 0, 1e30f, 0), expected.has_value()) << ray;
    if (!found || !expected) {
        ++counts->misses;
        return true;
    }
    ++counts->hits;
    EXPECT_NEAR(hit.t, expected->t, 1e-4) << ray;
    // Occluded stops at tfar: just short of the boundary nothing blocks the ray.
    EXPECT_FALSE(scene.Occluded(ToF(org), ToF(dir), 0, float(expected->t - kUndecidable / 2), 0))
        << ray;
    const SurfacePoint sp = scene.Evaluate(ToF(org), ToF(dir), hit);
    const V3d point = org + expected->t * dir;
    const V3d outward = test::OutwardNormal(leaves[size_t(expected->leaf)], point);
    // The combined solid's outward normal faces against the ray where the ray enters it.
    const V3d solidNormal = (outward.dot(dir) < 0) == expected->entering ? outward : -outward;
    const V3f ng = sp.Ng;
    EXPECT_GT(V3d(ng.x, ng.y, ng.z).dot(solidNormal), 0.999) << ray;
    EXPECT_GT(V3d(sp.N.x, sp.N.y, sp.N.z).dot(solidNormal), 0.999) << ray;
    return true;
}

// Orthographic rays along −z over [-1.6, 1.6]², and 4000 random rays from points in
// [-1.6, 1.6]³ in random directions.
Counts CheckTree(const CsgTree& tree, bool explicitPrimitives = true) {
    const Built built = Parse(test::Rib(tree, explicitPrimitives));
    EXPECT_EQ(built.errors, 0) << built.messages;
    if (built.frames.size() != 1) return {};
    test::CapturedDiagnostics captured;
    const RayScene scene(built.frames[0], captured.Get());
    const std::vector<Primitive> leaves = test::Leaves(tree);
    Counts counts;
    for (int i = 0; i <= 80; ++i)
        for (int j = 0; j <= 80; ++j) {
            const V3d org(-1.6 + 3.2 * i / 80, -1.6 + 3.2 * j / 80, 5);
            CheckRay(scene, tree, leaves, org, V3d(0, 0, -1), &counts);
        }
    std::mt19937 rng(20);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int k = 0; k < 4000; ++k) {
        const V3d org(1.6 * uniform(rng), 1.6 * uniform(rng), 1.6 * uniform(rng));
        V3d dir;
        do dir = V3d(uniform(rng), uniform(rng), uniform(rng));
        while (dir.length2() > 1 || dir.length2() < 1e-4);
        CheckRay(scene, tree, leaves, org, dir.normalized(), &counts);
    }
    return counts;
}

// Each case must decide most of its rays, and must show both hits and misses: a test that
// skipped everything would prove nothing.
void ExpectDecided(const Counts& counts) {
    EXPECT_GT(counts.hits, 1000);
    EXPECT_GT(counts.misses, 500);
    EXPECT_LT(counts.skipped, (counts.hits + counts.misses) / 10);
}

// Two unit spheres with centres 1 apart along the view: the lens of radius sqrt(1 − 0.25).
TEST(CsgRays, IntersectionOfTwoSpheresIsTheLens) {
    ExpectDecided(
        CheckTree(Op("intersection", {Sphere(V3d(0, 0, 0.5), 1), Sphere(V3d(0, 0, -0.5), 1)})));
}

// A sphere minus a smaller one offset towards the camera: the carved part is the small
// sphere's far side, its normal turned round to face out of the solid.
TEST(CsgRays, DifferenceShowsTheSubtractedSurfaceTurnedRound) {
    const CsgTree tree = Op("difference", {Sphere(V3d(0), 1), Sphere(V3d(0, 0, 0.8), 0.5)});
    ExpectDecided(CheckTree(tree));
    const Built built = Parse(test::Rib(tree));
    test::CapturedDiagnostics captured;
    const RayScene scene(built.frames.at(0), captured.Get());
    RayHit hit;
    ASSERT_TRUE(scene.Intersect(V3f(0, 0, 5), V3f(0, 0, -1), 0, 1e30f, 0, &hit));
    EXPECT_NEAR(hit.t, 5 - 0.3, 1e-5);  // the small sphere's far side, z = 0.8 − 0.5
    const SurfacePoint sp = scene.Evaluate(V3f(0, 0, 5), V3f(0, 0, -1), hit);
    EXPECT_NEAR(sp.Ng.z, 1, 1e-5);  // towards the camera, against the small sphere's outward −z
}

TEST(CsgRays, DifferenceWithNothingOverlappingIsTheFirstSolid) {
    ExpectDecided(CheckTree(Op("difference", {Sphere(V3d(0), 1), Sphere(V3d(4, 0, 0), 1)})));
}

TEST(CsgRays, UnionOfOverlappingSpheres) {
    ExpectDecided(
        CheckTree(Op("union", {Sphere(V3d(-0.5, 0, 0), 0.8), Sphere(V3d(0.5, 0, 0), 0.8)})));
}

// A difference of an intersection: the lens with a hole bored through it by an ellipsoid,
// and a box cut away from one side; leaves given as bare geometry inside the operations.
TEST(CsgRays, NestedTrees) {
    const CsgTree lens =
        Op("intersection", {Sphere(V3d(0, 0, 0.5), 1), Sphere(V3d(0, 0, -0.5), 1)});
    const CsgTree tree =
        Op("difference", {lens, test::Leaf(Primitive::Kind::Ellipsoid, V3d(0), V3d(0.3, 0.3, 3)),
                          test::Leaf(Primitive::Kind::Box, V3d(0.8, 0, 0), V3d(0.35, 0.35, 0.35))});
    ExpectDecided(CheckTree(tree));
    ExpectDecided(CheckTree(tree, false));
}

// Meshes as primitives: a box minus a sphere and a box intersected with a sphere (the box's
// faces give the normals, from its polygons' winding).
TEST(CsgRays, BoxesAndSpheres) {
    const CsgTree box = test::Leaf(Primitive::Kind::Box, V3d(0), V3d(0.8, 0.8, 0.8));
    ExpectDecided(CheckTree(Op("difference", {box, Sphere(V3d(0.5, 0.5, 0.5), 0.6)})));
    ExpectDecided(CheckTree(Op("intersection", {box, Sphere(V3d(0), 1.0)})));
}

// A shadow ray from a point of the carved surface out through the hole is not blocked; one
// from the same point back into the solid is.
TEST(CsgRays, ShadowRayThroughTheHoleIsNotBlocked) {
    const CsgTree tree =
        Op("difference",
           {Sphere(V3d(0), 1), test::Leaf(Primitive::Kind::Ellipsoid, V3d(0), V3d(0.3, 0.3, 3))});
    const Built built = Parse(test::Rib(tree));
    test::CapturedDiagnostics captured;
    const RayScene scene(built.frames.at(0), captured.Get());
    // On the hole's wall (x = 0.3 at z = 0): along the hole, leaning to its axis (inside the
    // ellipsoid until it has left the sphere), nothing blocks; across the hole towards −x the ray
    // meets the wall on the other side.
    const V3f wall(0.3f, 0, 0);
    EXPECT_FALSE(scene.Occluded(wall, V3f(-0.1f, 0, 1).normalized(), 1e-4f, 100, 0));
    EXPECT_TRUE(scene.Occluded(wall, V3f(-1, 0, 0), 1e-4f, 100, 0));
    RayHit hit;
    ASSERT_TRUE(scene.Intersect(wall, V3f(-1, 0, 0), 1e-4f, 100, 0, &hit));
    EXPECT_NEAR(hit.t, 0.6, 1e-5);
    // From inside the solid's material, outward along +x: the sphere's surface at x = 1.
    ASSERT_TRUE(scene.Intersect(V3f(0.5f, 0, 0), V3f(1, 0, 0), 0, 100, 0, &hit));
    EXPECT_NEAR(hit.t, 0.5, 1e-5);
}

}  // namespace
}  // namespace gonio
