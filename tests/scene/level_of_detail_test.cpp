// Level of detail (Detail, DetailRange, RelativeDetail): which representation of a model the
// scene keeps at the raster area its Detail bound covers.
#include <gtest/gtest.h>

#include <limits>

#include "renderer/rib/rib_parser.h"
#include "renderer/scene/attributes.h"
#include "renderer/scene/scene_builder.h"
#include "renderer/scene/view_frustum.h"
#include "tests/support/captured_diagnostics.h"

namespace gonio {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(ShownAtDetail, WhollyBetweenTheTransitionsAndNotBeyondTheLimits) {
    const float range[4] = {10, 20, 30, 40};
    EXPECT_TRUE(ShownAtDetail(20, range));
    EXPECT_TRUE(ShownAtDetail(25, range));
    EXPECT_TRUE(ShownAtDetail(30, range));
    EXPECT_FALSE(ShownAtDetail(9.9f, range));
    EXPECT_FALSE(ShownAtDetail(40.1f, range));
    EXPECT_FALSE(ShownAtDetail(kInf, range));
    // More than half faded in; at least half faded out.
    EXPECT_FALSE(ShownAtDetail(15, range));
    EXPECT_TRUE(ShownAtDetail(15.1f, range));
    EXPECT_TRUE(ShownAtDetail(35, range));
    EXPECT_FALSE(ShownAtDetail(35.1f, range));
}

TEST(ShownAtDetail, OfTwoRepresentationsWhoseTransitionsMeetExactlyOneShows) {
    const float coarse[4] = {0, 0, 20, 30}, fine[4] = {20, 30, kInf, kInf};
    for (float detail = 0; detail <= 60; detail += 0.25f)
        EXPECT_NE(ShownAtDetail(detail, coarse), ShownAtDetail(detail, fine)) << detail;
    EXPECT_TRUE(ShownAtDetail(kInf, fine));  // no Detail given: the finest
}

TEST(BoxDetail, IsTheRasterAreaOfTheProjectedBound) {
    // fov 90 on a square 100×100 frame: the screen window [-1, 1]² spans 100 pixels. A cube of
    // side 2 whose near face lies at z = 9 projects to a square 2/9 of the window wide.
    Options options;
    options.xres = options.yres = 100;
    options.projection = "perspective";
    options.fov = 90;
    Imath::M44f cameraFromObject;
    cameraFromObject.setTranslation(Imath::V3f(0, 0, 10));
    const float bound[6] = {-1, 1, -1, 1, -1, 1};
    const float side = 2.f / 9 / 2 * 100;
    EXPECT_NEAR(BoxDetail(options, cameraFromObject, bound), side * side, 1e-3);
    cameraFromObject.setTranslation(Imath::V3f(0, 0, 0.5f));  // reaching behind the eye
    EXPECT_EQ(BoxDetail(options, cameraFromObject, bound), kInf);
}

struct Built {
    std::string messages;
    std::vector<Frame> frames;
};

Built Build(const std::string& rib) {
    Built result;
    test::CapturedDiagnostics captured;
    Diagnostics& diagnostics = captured.Get();
    SceneBuilder builder("test.rib", diagnostics,
                         [&](const Frame& frame) { result.frames.push_back(frame); });
    ParseRibString(rib, "test.rib", builder, diagnostics);
    builder.Finish(FileLoc{std::make_shared<const std::string>("test.rib"), 0, 0});
    result.messages = captured.Text();
    return result;
}

// Three representations of one unit sphere 10 units in front of the camera of a 100×100
// frame at fov 90: its Detail bound (the cube about it) covers 123.5 pixels (BoxDetail above).
std::string ThreeRepresentations(const std::string& relativeDetail) {
    return "Format 100 100 1\nProjection \"perspective\" \"fov\" [90]\n" + relativeDetail +
           "WorldBegin\nTranslate 0 0 10\nDetail [-1 1 -1 1 -1 1]\n"
           "DetailRange [0 0 20 30]\nColor [0 0 1]\nSphere 1 -1 1 360\n"
           "DetailRange [20 30 100 200]\nColor [0 1 0]\nSphere 1 -1 1 360\n"
           "DetailRange [100 200 1e38 1e38]\nColor [1 0 0]\nSphere 1 -1 1 360\nWorldEnd\n";
}

float GreenOfTheOneShape(const Built& built) {
    EXPECT_EQ(built.messages, "");
    if (built.frames.size() != 1 || built.frames[0].shapes.size() != 1) {
        ADD_FAILURE() << "expected one shape";
        return -1;
    }
    return built.frames[0].shapes[0].attributes->color[1];
}

TEST(LevelOfDetail, KeepsTheRepresentationOfTheBoundsArea) {
    // 123.5 pixels lie in the transition from the second to the third, closer to its start.
    EXPECT_EQ(GreenOfTheOneShape(Build(ThreeRepresentations(""))), 1);
}

TEST(LevelOfDetail, RelativeDetailScalesTheArea) {
    EXPECT_EQ(GreenOfTheOneShape(Build(ThreeRepresentations("RelativeDetail 0.1\n"))), 0);
    const Built fine = Build(ThreeRepresentations("RelativeDetail 10\n"));
    ASSERT_EQ(fine.frames.size(), 1u);
    ASSERT_EQ(fine.frames[0].shapes.size(), 1u);
    EXPECT_EQ(fine.frames[0].shapes[0].attributes->color[0], 1);
}

TEST(LevelOfDetail, BadRangesAndFactorsAreErrors) {
    const Built r = Build(
        "RelativeDetail -1\nWorldBegin\nDetailRange [0 10 5 20]\nDetail [0 1 0 1]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:1:1: error: RelativeDetail must be a finite number >= 0\n"
              "test.rib:3:1: error: DetailRange expects minvisible <= lowertransition <= "
              "uppertransition <= maxvisible\n"
              "test.rib:4:8: error: Detail expects 6 numbers, got 4\n");
}

}  // namespace
}  // namespace gonio
