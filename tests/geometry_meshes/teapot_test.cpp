// Geometry "teapot": the embedded data against data/teapot.txt read here independently, and the
// patch-text parser's errors.

#include "renderer/geometry/teapot.h"

#include <Imath/ImathBox.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "renderer/geometry/bezier_patch_text.h"

namespace gonio {
namespace {

// data/teapot.txt read with a plain loop (not the renderer's parser): its control points and
// each patch's 16 indices.
struct TeapotFile {
    std::vector<V3f> vertices;
    std::vector<std::vector<int>> patches;
};

TeapotFile ReadTeapotFile() {
    std::ifstream file(GONIO_TEAPOT_DATA);
    TeapotFile data;
    std::string line, section;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream in(line);
        if (line.rfind("vertices", 0) == 0 || line.rfind("patches", 0) == 0) {
            in >> section;
        } else if (section == "vertices") {
            V3f p;
            in >> p.x >> p.y >> p.z;
            data.vertices.push_back(p);
        } else {
            std::string name;
            std::vector<int> indices(16);
            in >> name;
            for (int& i : indices) in >> i;
            data.patches.push_back(indices);
        }
    }
    return data;
}

Imath::Box3f MeshBounds(const std::vector<TriangleMesh>& meshes) {
    Imath::Box3f box;
    for (const TriangleMesh& m : meshes)
        for (const V3f& p : m.positions) box.extendBy(p);
    return box;
}

TEST(Teapot, HasThe32PatchesOfTheDataFile) {
    const TeapotFile file = ReadTeapotFile();
    ASSERT_EQ(file.vertices.size(), 290u);
    ASSERT_EQ(file.patches.size(), 32u);
    auto teapot = MakeTeapot();
    ASSERT_TRUE(teapot.Ok()) << teapot.Error();
    EXPECT_EQ(teapot.Value().size(), 32u);
}

// A Bézier patch passes through its corner control points and lies inside the hull of all 16:
// the tessellation's box contains the corners' box and is contained in the control points' box.
TEST(Teapot, BoundsLieBetweenTheCornersAndTheControlPoints) {
    const TeapotFile file = ReadTeapotFile();
    Imath::Box3f corners, hull;
    for (const std::vector<int>& patch : file.patches) {
        for (int i : {0, 3, 12, 15}) corners.extendBy(file.vertices[patch[i]]);
        for (int i : patch) hull.extendBy(file.vertices[i]);
    }
    auto teapot = MakeTeapot();
    ASSERT_TRUE(teapot.Ok()) << teapot.Error();
    const Imath::Box3f box = MeshBounds(teapot.Value());
    constexpr float kEps = 1e-4f;
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(box.min[axis], corners.min[axis] + kEps) << axis;
        EXPECT_GE(box.max[axis], corners.max[axis] - kEps) << axis;
        EXPECT_GE(box.min[axis], hull.min[axis] - kEps) << axis;
        EXPECT_LE(box.max[axis], hull.max[axis] + kEps) << axis;
    }
    // The documented height: on z = 0, 3.15 high; the handle reaches x = -3 (a corner), the
    // spout's tip lies short of its outermost control point, x = 3.525.
    EXPECT_NEAR(box.min.z, 0, kEps);
    EXPECT_NEAR(box.max.z, 3.15, kEps);
    EXPECT_NEAR(box.min.x, -3, 0.05);
    EXPECT_GT(box.max.x, 3.3);
    EXPECT_LT(box.max.x, 3.525);
}

TEST(Teapot, DegeneratePatchesHaveNoNanNormals) {
    auto teapot = MakeTeapot();
    ASSERT_TRUE(teapot.Ok()) << teapot.Error();
    for (const TriangleMesh& m : teapot.Value())
        for (const V3f& n : m.normals)
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
}

std::string ParseError(const std::string& text) {
    auto r = ParseBezierPatchText(text);
    return r ? "(parsed)" : r.Error();
}

TEST(BezierPatchText, ErrorsNameTheLine) {
    const std::string sixteen = " 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n";
    EXPECT_EQ(ParseError(""), "at the end of the text: expected 'vertices N'");
    EXPECT_EQ(ParseError("# c\nvertices 2\n1 2 3\n"),
              "at the end of the text: expected vertex 1 as 'x y z'");
    EXPECT_EQ(ParseError("vertices 1\n1 2\n"), "line 2: expected vertex 0 as 'x y z'");
    EXPECT_EQ(ParseError("vertices 1\n1 2 3\npatch 1\n"), "line 3: expected 'patches N'");
    EXPECT_EQ(ParseError("vertices 1\n1 2 3\npatches 1\np 0 0 1" + sixteen.substr(6)),
              "line 4: patch 'p' needs 16 vertex indices in [0, 1)");
    EXPECT_EQ(ParseError("vertices 1\n1 2 3\npatches 1\np 0 0\n"),
              "line 4: patch 'p' needs 16 vertex indices in [0, 1)");
    EXPECT_EQ(ParseError("vertices 1\n1 2 3\npatches 1\np" + sixteen + "x\n"),
              "line 5: unexpected text after the patches");
    EXPECT_EQ(ParseError("vertices 1\n1 2 3\npatches 1\np 0" + sixteen),
              "line 4: patch 'p' has more than 16 indices");
    auto ok = ParseBezierPatchText("vertices 1\n1 2 3\npatches 1\np" + sixteen);
    ASSERT_TRUE(ok.Ok()) << ok.Error();
    EXPECT_EQ(ok.Value()[0].controlPoints[15], V3f(1, 2, 3));
}

}  // namespace
}  // namespace gonio
