#include "renderer/geometry/subdivision.h"

#include <gtest/gtest.h>

#include "mesh_test_util.h"

namespace gonio {
namespace {

using test::Var;
using test::WithP;

// A cube: 8 points, 6 quads.
const std::vector<V3f> kCube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<int> kCounts(6, 4);
const std::vector<int> kIndices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                                   1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};

TEST(SubdivisionMesh, CageWithTags) {
    std::vector<std::string> notes;
    auto r = MakeSubdivisionMesh(
        "catmull-clark", kCounts, kIndices,
        {"crease", "corner", "hole", "interpolateboundary", "facevaryingpropagatecorners"},
        {3, 1, 2, 2, 1, 0, 0, 0, 0, 0}, {0, 1, 2, 4, 6, 5}, {2.5f, 10, 3},
        WithP(kCube,
              {Var("Cs", ParamClass::Varying, ParamType::Color, 3, std::vector<float>(24, 1))}),
        &notes);
    ASSERT_TRUE(r.Ok()) << r.Error();
    const SubdivisionCage& c = r.Value();
    EXPECT_EQ(c.positions.size(), 8u);
    EXPECT_EQ(c.indices.size(), 24u);
    EXPECT_EQ(c.creaseEdges, (std::vector<uint32_t>{0, 1, 1, 2}));
    EXPECT_EQ(c.creaseWeights, (std::vector<float>{2.5f, 2.5f}));
    EXPECT_EQ(c.cornerVertices, (std::vector<uint32_t>{4, 6}));
    EXPECT_EQ(c.cornerWeights, (std::vector<float>{10, 3}));
    EXPECT_EQ(c.holeFaces, (std::vector<uint32_t>{5}));
    EXPECT_TRUE(c.interpolateBoundary);
    EXPECT_NE(c.vars.Find("Cs"), nullptr);
    EXPECT_EQ(c.vars.Find("P"), nullptr);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("facevaryingpropagatecorners"), std::string::npos);
}

TEST(SubdivisionMesh, BadInputIsReported) {
    auto scheme = MakeSubdivisionMesh("loop", kCounts, kIndices, {}, {}, {}, {}, WithP(kCube));
    ASSERT_FALSE(scheme.Ok());
    EXPECT_NE(scheme.Error().find("loop"), std::string::npos);
    std::vector<int> bad = kIndices;
    bad[3] = 8;
    EXPECT_FALSE(
        MakeSubdivisionMesh("catmull-clark", kCounts, bad, {}, {}, {}, {}, WithP(kCube)).Ok());
    EXPECT_FALSE(
        MakeSubdivisionMesh("catmull-clark", {4, 4}, kIndices, {}, {}, {}, {}, WithP(kCube)).Ok());
    EXPECT_FALSE(MakeSubdivisionMesh("catmull-clark", kCounts, kIndices, {"crease"}, {2, 1}, {0},
                                     {1}, WithP(kCube))
                     .Ok());
    EXPECT_FALSE(MakeSubdivisionMesh("catmull-clark", kCounts, kIndices, {"hole"}, {1, 0}, {6}, {},
                                     WithP(kCube))
                     .Ok());
    EXPECT_FALSE(MakeSubdivisionMesh("catmull-clark", kCounts, kIndices, {"hole"}, {1}, {0}, {},
                                     WithP(kCube))
                     .Ok());
    EXPECT_FALSE(MakeSubdivisionMesh("catmull-clark", kCounts, kIndices, {}, {}, {}, {},
                                     WithP(kCube, {Var("st", ParamClass::FaceVarying,
                                                       ParamType::Float, 2, {0, 0})}))
                     .Ok());
}

}  // namespace
}  // namespace gonio
