// CSG rendered end to end (in process, read back with OpenImageIO): orthographic views along the
// axis of solids built from spheres on it, so that every answer depends on the distance r from
// the axis alone. A pixel is a square of screen space with one sample somewhere inside (box
// filter 1 1, PixelSamples 1 1): where the analytic answer is the same all over the square the
// pixel must show it, and where it varies the pixel must lie within its range over the square.

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tests/csg/csg_oracle.h"
#include "tests/support/render_rib.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;
using test::CsgTree;
using test::Op;
using test::Sphere;
using test::V3d;

constexpr int kSize = 65;        // odd: one pixel is centred on the axis
constexpr double kCameraZ = -5;  // the camera's world position on the axis, looking along +z
constexpr double kPixel = 2.0 / kSize;

struct Image {
    std::vector<float> rgba, z;
    std::string messages;
    int errors = 0;
    float Alpha(int x, int y) const { return rgba[size_t(4 * (y * kSize + x) + 3)]; }
    float Red(int x, int y) const { return rgba[size_t(4 * (y * kSize + x))]; }
    float Depth(int x, int y) const { return z[size_t(y * kSize + x)]; }
};

std::vector<float> ReadExr(const std::string& path, int channels) {
    std::vector<float> pixels(size_t(kSize * kSize * channels), -1.f);
    auto in = OIIO::ImageInput::open(path);
    if (!in) return pixels;
    in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data());
    return pixels;
}

// Renders `world` (inside WorldBegin/WorldEnd) seen along +z from z = −5, the screen window
// [-1, 1]², with an RGBA and a depth display; `options` go before WorldBegin.
Image Render(const std::string& name, const std::string& world, const std::string& options = "") {
    const fs::path dir = fs::temp_directory_path() / ("gonio_csg_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string rgba = (dir / (name + ".exr")).string();
    const std::string z = (dir / (name + "_z.exr")).string();
    const std::string rib = options + "\nFormat " + std::to_string(kSize) + " " +
                            std::to_string(kSize) +
                            " 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
                            "Display \"" +
                            rgba +
                            "\" \"openexr\" \"rgba\"\n"
                            "Display \"+" +
                            z +
                            "\" \"openexr\" \"z\"\n"
                            "Projection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
                            "Translate 0 0 5\nWorldBegin\n" +
                            world + "\nWorldEnd\n";
    Image image;
    const test::RibRenderResult result = test::RenderRibString(rib, name + ".rib");
    image.errors = result.errors;
    image.messages = result.messages;
    image.rgba = ReadExr(rgba, 4);
    image.z = ReadExr(z, 1);
    fs::remove_all(dir);
    return image;
}

// The pixel's square in screen (= world x, y) space: the nearest and farthest distance of its
// points from the axis.
void RadiusRange(int x, int y, double* rmin, double* rmax) {
    const double x0 = -1 + x * kPixel, x1 = x0 + kPixel;
    const double y0 = 1 - (y + 1) * kPixel, y1 = y0 + kPixel;
    const double nx = (x0 <= 0 && x1 >= 0) ? 0 : std::min(std::fabs(x0), std::fabs(x1));
    const double ny = (y0 <= 0 && y1 >= 0) ? 0 : std::min(std::fabs(y0), std::fabs(y1));
    const double fx = std::max(std::fabs(x0), std::fabs(x1));
    const double fy = std::max(std::fabs(y0), std::fabs(y1));
    *rmin = std::hypot(nx, ny), *rmax = std::hypot(fx, fy);
}

// The oracle's depth (camera z) of the first surface at distance r from the axis, if any.
std::optional<double> Depth(const CsgTree& tree, double r) {
    const std::optional<test::Boundary> b =
        test::FirstBoundary(tree, V3d(r, 0, kCameraZ), V3d(0, 0, 1), 0);
    if (!b) return std::nullopt;
    return b->t;
}

// The oracle over a pixel's square, at 9 distances from the axis across it: how many see the
// solid, the range of their depths, and whether they all see the same primitive's surface.
struct PixelAnswer {
    int hits = 0;
    double lo = 1e30, hi = -1e30;
    bool oneLeaf = true;
};
constexpr int kRadii = 9;

PixelAnswer Answer(const CsgTree& tree, int x, int y) {
    double rmin, rmax;
    RadiusRange(x, y, &rmin, &rmax);
    PixelAnswer answer;
    int leaf = -1;
    for (int k = 0; k < kRadii; ++k) {
        const double r = rmin + (rmax - rmin) * k / (kRadii - 1);
        const std::optional<test::Boundary> b =
            test::FirstBoundary(tree, V3d(r, 0, kCameraZ), V3d(0, 0, 1), 0);
        if (!b) continue;
        ++answer.hits;
        answer.lo = std::min(answer.lo, b->t), answer.hi = std::max(answer.hi, b->t);
        if (leaf >= 0 && b->leaf != leaf) answer.oneLeaf = false;
        leaf = b->leaf;
    }
    return answer;
}

// Every pixel of a render of `tree` against the oracle: alpha 1 where every point of the square
// sees the solid, 0 where none does; depth within the oracle's range over the square where the
// whole square sees one primitive's surface (on which depth is monotonic in r: every sphere is
// centred on the axis, which passes through the centre pixel's centre). Returns how many pixels
// had an answer.
int CheckCoverageAndDepth(const Image& image, const CsgTree& tree) {
    int exact = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const PixelAnswer a = Answer(tree, x, y);
            if (a.hits == 0) {
                EXPECT_EQ(image.Alpha(x, y), 0.f) << "pixel " << x << "," << y;
                ++exact;
            } else if (a.hits == kRadii) {
                EXPECT_EQ(image.Alpha(x, y), 1.f) << "pixel " << x << "," << y;
                ++exact;
                if (a.oneLeaf) {
                    EXPECT_GE(image.Depth(x, y), a.lo - 1e-4) << "pixel " << x << "," << y;
                    EXPECT_LE(image.Depth(x, y), a.hi + 1e-4) << "pixel " << x << "," << y;
                }
            }
        }
    return exact;
}

const CsgTree kLens = Op("intersection", {Sphere(V3d(0, 0, 0.5), 1), Sphere(V3d(0, 0, -0.5), 1)});

std::string SolidWorld(const CsgTree& tree) { return "Surface \"constant\"\n" + test::Rib(tree); }

// The lens: covered exactly within radius sqrt(0.75), depth 5.5 − sqrt(1 − r²) (the far
// sphere's near side); the union's silhouette of radius 1 would fail the coverage.
TEST(CsgRender, LensCoverageAndDepth) {
    const Image image = Render("lens", SolidWorld(kLens));
    ASSERT_EQ(image.errors, 0) << image.messages;
    const double lensRadius = std::sqrt(1 - 0.25);
    EXPECT_NEAR(*Depth(kLens, 0), 5.5 - 1, 1e-12);  // the oracle agrees with the formula
    EXPECT_NEAR(*Depth(kLens, 0.6), 5.5 - std::sqrt(1 - 0.36), 1e-12);
    EXPECT_FALSE(Depth(kLens, lensRadius + 1e-6));
    EXPECT_GT(CheckCoverageAndDepth(image, kLens), kSize * kSize * 9 / 10);
    // Coverage: the count of covered pixels is the lens's area within its ring of edge pixels.
    int covered = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) covered += image.Alpha(x, y) > 0.5f;
    const double area = M_PI * lensRadius * lensRadius / (kPixel * kPixel);
    const double edge = 2 * M_PI * lensRadius / kPixel * std::sqrt(2.0);
    EXPECT_NEAR(covered, area, edge);
}

// The path tracer sees the same lens (its camera rays go through the same RayScene).
TEST(CsgRender, LensCoverageInThePathTracer) {
    const Image image =
        Render("lens_path", SolidWorld(kLens), "Option \"pathtrace\" \"integer enable\" [1]");
    ASSERT_EQ(image.errors, 0) << image.messages;
    CheckCoverageAndDepth(image, kLens);
}

// A unit sphere minus a sphere of radius 0.5 offset 0.8 towards the camera: at the centre the
// camera sees the small sphere's far side, depth 5 − 0.8 + 0.5 = 4.7.
TEST(CsgRender, DifferenceShowsTheSubtractedSphere) {
    const CsgTree tree = Op("difference", {Sphere(V3d(0), 1), Sphere(V3d(0, 0, -0.8), 0.5)});
    const Image image = Render("difference", SolidWorld(tree));
    ASSERT_EQ(image.errors, 0) << image.messages;
    EXPECT_NEAR(*Depth(tree, 0), 4.7, 1e-12);
    const int centre = kSize / 2;
    double rmin, rmax;
    RadiusRange(centre, centre, &rmin, &rmax);
    EXPECT_NEAR(image.Depth(centre, centre), 4.7, 4.7 - *Depth(tree, rmax) + 1e-4);
    CheckCoverageAndDepth(image, tree);
}

// Pixel for pixel: a union renders as the same spheres without SolidBegin did, and a
// difference whose second solid misses the first renders as the first alone.
TEST(CsgRender, UnionAndEmptyDifferenceMatchPlainRenders) {
    const std::string a =
        "TransformBegin Translate -0.3 0 0 Sphere 0.6 -0.6 0.6 360 TransformEnd\n";
    const std::string b =
        "TransformBegin Translate 0.3 0 0.2 Sphere 0.6 -0.6 0.6 360 TransformEnd\n";
    const std::string far = "TransformBegin Translate 3 0 0 Sphere 0.6 -0.6 0.6 360 TransformEnd\n";
    const std::string lit =
        "LightSource \"distantlight\" 1 \"from\" [1 1 -1] \"to\" [0 0 0]\n"
        "Surface \"plastic\"\n";
    const Image plain = Render("plain", lit + a + b);
    const Image solid = Render("union", lit + "SolidBegin \"union\"\n" + a + b + "SolidEnd\n");
    ASSERT_EQ(plain.errors + solid.errors, 0) << plain.messages << solid.messages;
    EXPECT_EQ(plain.rgba, solid.rgba);
    EXPECT_EQ(plain.z, solid.z);
    const Image first = Render("first", lit + a);
    const Image carved =
        Render("carved", lit + "SolidBegin \"difference\"\n" + a + far + "SolidEnd\n");
    ASSERT_EQ(first.errors + carved.errors, 0) << first.messages << carved.messages;
    EXPECT_EQ(first.rgba, carved.rgba);
}

// A blue unit sphere with a hole bored along the view (an ellipsoid of radii 0.4, 0.4, 3), over a
// white matte floor
// at z = 2, under a distant light shining along the view with shadows: through the hole the
// camera sees the floor, fully lit (matte Kd 1: red 1), which it is only if the shadow rays
// from the floor pass through the hole too.
TEST(CsgRender, ShadowThroughTheHole) {
    const CsgTree tree =
        Op("difference", {Sphere(V3d(0), 1),
                          test::Leaf(test::Primitive::Kind::Ellipsoid, V3d(0), V3d(0.4, 0.4, 3))});
    const std::string world =
        "Attribute \"light\" \"shadows\" \"on\"\n"
        "LightSource \"distantlight\" 1 \"from\" [0 0 -10] \"to\" [0 0 0]\n"
        "Surface \"matte\" \"Kd\" 1\n"
        "AttributeBegin Color 0 0 1\n" +
        test::Rib(tree) +
        "AttributeEnd\n"
        "Polygon \"P\" [-3 -3 2  3 -3 2  3 3 2  -3 3 2]\n";
    const Image image = Render("shadow", world);
    ASSERT_EQ(image.errors, 0) << image.messages;
    int lit = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            double rmin, rmax;
            RadiusRange(x, y, &rmin, &rmax);
            const PixelAnswer a = Answer(tree, x, y);
            if (a.hits == 0 && rmax < 1) {
                EXPECT_NEAR(image.Red(x, y), 1, 1e-5) << "pixel " << x << "," << y;
                EXPECT_NEAR(image.Depth(x, y), 7, 1e-5) << "pixel " << x << "," << y;
                ++lit;
            } else if (a.hits == kRadii) {
                EXPECT_EQ(image.Red(x, y), 0) << "pixel " << x << "," << y;  // the blue sphere
            }
        }
    EXPECT_GT(lit, 300);  // the hole is about 0.38 wide where it leaves the sphere: ~480 pixels
}

}  // namespace
}  // namespace gonio
