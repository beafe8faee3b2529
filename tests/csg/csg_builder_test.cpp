// The scene builder's CSG trees (Frame::solids, SceneShape::solid) and its messages about
// solids: unknown operations, surfaces that do not enclose a volume, solids it cannot keep.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/parse_world.h"

namespace gonio {
namespace {

using Op = SolidNode::Operation;

using Built = test::BuiltWorld;

Built Parse(const std::string& world) { return test::ParseWorld(world); }

const char* const kCube =
    "PointsPolygons [4 4 4 4 4 4] [0 2 3 1  4 5 7 6  0 1 5 4  2 6 7 3  0 4 6 2  1 3 7 5] "
    "\"P\" [-1 -1 -1  1 -1 -1  -1 1 -1  1 1 -1  -1 -1 1  1 -1 1  -1 1 1  1 1 1]\n";
// The same cube without its last face.
const char* const kOpenBox =
    "PointsPolygons [4 4 4 4 4] [0 2 3 1  4 5 7 6  0 1 5 4  2 6 7 3  0 4 6 2] "
    "\"P\" [-1 -1 -1  1 -1 -1  -1 1 -1  1 1 -1  -1 -1 1  1 -1 1  -1 1 1  1 1 1]\n";

// difference(intersection(primitive(sphere, cube), sphere), cube): nodes in RIB order, parents
// first, and each shape names its primitive solid; a bare shape inside an operation gets a
// primitive of its own.
TEST(CsgBuilder, TreeOfSolids) {
    const Built built = Parse(std::string("SolidBegin \"difference\"\n"
                                          " SolidBegin \"intersection\"\n"
                                          "  SolidBegin \"primitive\"\n"
                                          "   Sphere 1 -1 1 360\n") +
                              kCube +
                              "  SolidEnd\n"
                              "  Sphere 2 -2 2 360\n"
                              " SolidEnd\n " +
                              kCube +
                              "SolidEnd\n"
                              "Sphere 1 -1 1 360\n");
    ASSERT_EQ(built.errors, 0) << built.messages;
    ASSERT_EQ(built.frames.size(), 1u);
    const Frame& frame = built.frames[0];
    ASSERT_EQ(frame.solids.size(), 5u);
    EXPECT_EQ(frame.solids[0].operation, Op::Difference);
    EXPECT_EQ(frame.solids[0].parent, -1);
    EXPECT_EQ(frame.solids[0].children, (std::vector<int>{1, 4}));
    EXPECT_EQ(frame.solids[1].operation, Op::Intersection);
    EXPECT_EQ(frame.solids[1].children, (std::vector<int>{2, 3}));
    EXPECT_EQ(frame.solids[2].operation, Op::Primitive);
    EXPECT_EQ(frame.solids[3].operation, Op::Primitive);
    EXPECT_EQ(frame.solids[3].parent, 1);
    EXPECT_EQ(frame.solids[4].parent, 0);
    ASSERT_EQ(frame.shapes.size(), 5u);
    const std::vector<int> expected{2, 2, 3, 4, -1};
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(frame.shapes[i].solid, expected[i]) << i;
    EXPECT_EQ(built.messages, "");  // every primitive solid is closed
}

TEST(CsgBuilder, UnknownOperationIsALocatedError) {
    const Built built = Parse("SolidBegin \"xor\"\nSphere 1 -1 1 360\nSolidEnd\n");
    EXPECT_EQ(built.errors, 1);
    EXPECT_NE(built.messages.find("test.rib:2:1: error: SolidBegin: unknown operation \"xor\""),
              std::string::npos)
        << built.messages;
}

TEST(CsgBuilder, OpenSurfacesAreWarnedAbout) {
    for (const std::string& open :
         {std::string("Sphere 1 -0.5 1 360\n"), std::string("Sphere 1 -1 1 180\n"),
          std::string("Cylinder 1 -1 1 360\n"), std::string(kOpenBox),
          std::string("Torus 1 0.25 0 180 360\n")}) {
        const Built built = Parse("SolidBegin \"union\"\n" + open + "SolidEnd\n");
        EXPECT_EQ(built.errors, 0) << built.messages;
        EXPECT_NE(built.messages.find("test.rib:3:1: warning: a primitive solid whose surfaces do "
                                      "not enclose a volume"),
                  std::string::npos)
            << open << built.messages;
    }
    for (const std::string& closed : {std::string("Sphere 1 -1 1 360\n"), std::string(kCube),
                                      std::string("Torus 1 0.25 0 360 360\n")}) {
        const Built built = Parse("SolidBegin \"union\"\n" + closed + "SolidEnd\n");
        EXPECT_EQ(built.messages, "") << closed;
    }
    // A cylinder capped by disks is not checked (a mixture of quadrics): no message.
    const Built capped = Parse(
        "SolidBegin \"primitive\"\nCylinder 1 -1 1 360\nDisk 1 1 360\nDisk -1 1 -360\nSolidEnd\n");
    EXPECT_EQ(capped.messages, "");
}

// A tree nested past 1000 levels is a located error, not a stack overflow at render time.
TEST(CsgBuilder, DeepNestingIsAnError) {
    std::string rib;
    for (int k = 0; k < 1001; ++k) rib += "SolidBegin \"union\"\n";
    rib += "Sphere 1 -1 1 360\n";
    for (int k = 0; k < 1001; ++k) rib += "SolidEnd\n";
    const Built built = Parse(rib);
    EXPECT_EQ(built.errors, 1);
    EXPECT_NE(built.messages.find("test.rib:1002:1: error: SolidBegin nested more than 1000 deep"),
              std::string::npos)
        << built.messages.substr(0, 300);
}

// Solids inside ObjectBegin are not kept; an instance inside a solid joins it as copies.
TEST(CsgBuilder, ObjectsAndSolids) {
    const Built inside = Parse(
        "ObjectBegin 1\nSolidBegin \"difference\"\nSphere 1 -1 1 360\nSolidEnd\nObjectEnd\n"
        "ObjectInstance 1\n");
    EXPECT_NE(inside.messages.find("warning: SolidBegin inside ObjectBegin"), std::string::npos)
        << inside.messages;
    ASSERT_EQ(inside.frames.size(), 1u);
    EXPECT_TRUE(inside.frames[0].solids.empty());
    const Built instanced = Parse(
        "ObjectBegin 1\nSphere 1 -1 1 360\nObjectEnd\n"
        "SolidBegin \"difference\"\nObjectInstance 1\nTranslate 0 0 1\nObjectInstance 1\n"
        "SolidEnd\n");
    ASSERT_EQ(instanced.errors, 0) << instanced.messages;
    ASSERT_EQ(instanced.frames.size(), 1u);
    const Frame& frame = instanced.frames[0];
    EXPECT_TRUE(frame.instances.empty());
    ASSERT_EQ(frame.shapes.size(), 2u);
    EXPECT_EQ(frame.solids.size(), 3u);
    EXPECT_EQ(frame.shapes[0].solid, 1);
    EXPECT_EQ(frame.shapes[1].solid, 2);
    EXPECT_EQ(frame.shapes[1].worldFromObject[3][2], 1);
}

}  // namespace
}  // namespace gonio
