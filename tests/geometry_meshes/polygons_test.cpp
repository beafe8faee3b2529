#include "renderer/geometry/polygons.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh_test_util.h"

namespace gonio {
namespace {

using test::MeshArea;
using test::TriangleNormal;
using test::Var;
using test::WithP;

// Every triangle must face the way the polygon does, and none may be degenerate.
void ExpectWoundLike(const TriangleMesh& mesh, const V3f& normal) {
    for (size_t t = 0; t < mesh.TriangleCount(); ++t)
        EXPECT_GT(TriangleNormal(mesh, t).dot(normal), 0) << "triangle " << t;
}

TEST(Polygon, ConvexQuadIsTwoTrianglesOfItsArea) {
    auto r = MakePolygon(WithP({{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}}));
    ASSERT_TRUE(r.Ok()) << r.Error();
    EXPECT_EQ(r.Value().TriangleCount(), 2u);
    EXPECT_NEAR(MeshArea(r.Value()), 6.0, 1e-6);
    ExpectWoundLike(r.Value(), V3f(0, 0, 1));
}

TEST(Polygon, ClockwiseOutlineKeepsItsWinding) {
    auto r = MakePolygon(WithP({{0, 0, 0}, {0, 3, 0}, {2, 3, 0}, {2, 0, 0}}));
    ASSERT_TRUE(r.Ok());
    ExpectWoundLike(r.Value(), V3f(0, 0, -1));
}

TEST(Polygon, ConcaveArrowhead) {
    // A "V" shape whose notch vertex is reflex; a fan from vertex 1 would cross the notch.
    const std::vector<V3f> pts = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 1, 0}, {0, 4, 0}};
    auto r = MakePolygon(WithP(pts));
    ASSERT_TRUE(r.Ok());
    EXPECT_EQ(r.Value().TriangleCount(), 3u);
    EXPECT_NEAR(MeshArea(r.Value()), std::abs(NewellNormal(pts).z) / 2, 1e-5);
    EXPECT_NEAR(MeshArea(r.Value()), 10.0, 1e-5);
    ExpectWoundLike(r.Value(), V3f(0, 0, 1));
}

TEST(Polygon, TShapeInTiltedPlane) {
    // A T (area 5) rotated out of every coordinate plane.
    std::vector<V2f> outline = {{1, 0}, {2, 0}, {2, 2}, {3, 2}, {3, 3}, {0, 3}, {0, 2}, {1, 2}};
    const V3f ex = V3f(1, 1, 0).normalized(), ey = V3f(-1, 1, 1).normalized();
    std::vector<V3f> pts;
    for (const V2f& p : outline) pts.push_back(V3f(5, -2, 7) + ex * p.x + ey * p.y);
    auto r = MakePolygon(WithP(pts));
    ASSERT_TRUE(r.Ok());
    EXPECT_NEAR(MeshArea(r.Value()), 5.0, 1e-4);
    ExpectWoundLike(r.Value(), ex.cross(ey));
}

TEST(Polygon, NonPlanarQuadIsCoveredWithOutlineWinding) {
    auto r = MakePolygon(WithP({{0, 0, 0}, {1, 0, 0.3f}, {1, 1, 0}, {0, 1, 0.3f}}));
    ASSERT_TRUE(r.Ok());
    EXPECT_EQ(r.Value().TriangleCount(), 2u);
    ExpectWoundLike(r.Value(), V3f(0, 0, 1));
}

TEST(Polygon, DegenerateInputsGiveNoTriangles) {
    auto two = MakePolygon(WithP({{0, 0, 0}, {1, 0, 0}}));
    ASSERT_TRUE(two.Ok());
    EXPECT_EQ(two.Value().TriangleCount(), 0u);
    auto line = MakePolygon(WithP({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}));
    ASSERT_TRUE(line.Ok());
    EXPECT_EQ(line.Value().TriangleCount(), 0u);
}

TEST(Polygon, CollinearAndDuplicateVerticesAddNoSlivers) {
    const std::vector<V3f> pts = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    auto r = MakePolygon(WithP(pts));
    ASSERT_TRUE(r.Ok());
    EXPECT_NEAR(MeshArea(r.Value()), 4.0, 1e-6);
    ExpectWoundLike(r.Value(), V3f(0, 0, 1));
}

TEST(GeneralPolygon, SquareWithTwoHoles) {
    // 10×10 square with a 2×2 hole and a triangular hole (area 2), given in either direction.
    const std::vector<V3f> pts = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0},  // outline
                                  {2, 2, 0}, {2, 4, 0},  {4, 4, 0},   {4, 2, 0},   // clockwise
                                  {6, 6, 0}, {8, 6, 0},  {6, 8, 0}};               // ccw
    auto r = MakeGeneralPolygon({4, 4, 3}, WithP(pts));
    ASSERT_TRUE(r.Ok()) << r.Error();
    EXPECT_NEAR(MeshArea(r.Value()), 100.0 - 4.0 - 2.0, 1e-4);
    ExpectWoundLike(r.Value(), V3f(0, 0, 1));
    // Triangulated with bridges: n + 2 per hole vertices give n + 2·holes − 2 triangles.
    EXPECT_EQ(r.Value().TriangleCount(), 11u + 2 * 2 - 2);
}

TEST(GeneralPolygon, ConcaveOutlineWithHoleInItsArm) {
    // An L shape, area 3·1 + 1·2 = 5, with a 0.5×0.5 hole in the upper arm.
    const std::vector<V3f> pts = {{0, 0, 0},        {3, 0, 0},       {3, 1, 0},     {1, 1, 0},
                                  {1, 3, 0},        {0, 3, 0},       {0.25f, 2, 0}, {0.75f, 2, 0},
                                  {0.75f, 2.5f, 0}, {0.25f, 2.5f, 0}};
    auto r = MakeGeneralPolygon({6, 4}, WithP(pts));
    ASSERT_TRUE(r.Ok());
    EXPECT_NEAR(MeshArea(r.Value()), 5.0 - 0.25, 1e-5);
    ExpectWoundLike(r.Value(), V3f(0, 0, 1));
}

TEST(PointsPolygons, SharedVerticesAndClassMapping) {
    // Two unit squares sharing an edge: 6 points, 8 corners.
    const std::vector<V3f> pts = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    std::vector<float> st;
    for (int i = 0; i < 8; ++i) st.insert(st.end(), {float(i), float(10 * i)});
    auto vars = WithP(
        pts, {Var("Kd", ParamClass::Uniform, ParamType::Float, 1, {0.25f, 0.75f}),
              Var("Cs", ParamClass::Varying, ParamType::Color, 3, std::vector<float>(18, 0.5f)),
              Var("st", ParamClass::FaceVarying, ParamType::Float, 2, st),
              Var("id", ParamClass::Constant, ParamType::Float, 1, {7}),
              Var("N", ParamClass::Vertex, ParamType::Normal, 3, std::vector<float>(18, 1.0f))});
    auto r = MakePointsPolygons({4, 4}, {0, 1, 4, 3, 1, 2, 5, 4}, vars);
    ASSERT_TRUE(r.Ok()) << r.Error();
    const TriangleMesh& m = r.Value();
    EXPECT_EQ(m.positions.size(), 6u);
    ASSERT_EQ(m.TriangleCount(), 4u);
    EXPECT_EQ(m.faceOfTriangle, (std::vector<uint32_t>{0, 0, 1, 1}));
    EXPECT_EQ(m.normals.size(), 6u);
    EXPECT_TRUE(m.cornerNormals.empty());
    EXPECT_EQ(test::FindVar(m, "Kd")->rate, MeshRate::PerFace);
    EXPECT_EQ(test::FindVar(m, "Cs")->rate, MeshRate::PerVertex);
    EXPECT_EQ(test::FindVar(m, "id")->rate, MeshRate::Constant);
    EXPECT_EQ(test::FindVar(m, "N"), nullptr);
    const MeshVar* stVar = test::FindVar(m, "st");
    ASSERT_NE(stVar, nullptr);
    EXPECT_EQ(stVar->rate, MeshRate::PerCorner);
    ASSERT_EQ(stVar->var.values.size(), 4u * 3 * 2);
    // Each corner's st must be the facevarying value of the face corner it came from: corner k of
    // face f has st = (4f + k, 10·(4f + k)), and its vertex index is the k-th index of face f.
    const std::vector<int> verts = {0, 1, 4, 3, 1, 2, 5, 4};
    for (size_t c = 0; c < 12; ++c) {
        const int fv = static_cast<int>(stVar->var.values[2 * c]);
        EXPECT_EQ(stVar->var.values[2 * c + 1], 10.0f * fv);
        EXPECT_EQ(static_cast<int>(m.indices[c]), verts[fv]);
        EXPECT_EQ(fv / 4, static_cast<int>(m.faceOfTriangle[c / 3]));
    }
}

TEST(PointsPolygons, FaceVaryingNormalsBecomeCornerNormals) {
    const std::vector<V3f> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    auto vars = WithP(pts, {Var("N", ParamClass::FaceVarying, ParamType::Normal, 3,
                                {0, 0, 1, 0, 1, 0, 1, 0, 0})});
    auto r = MakePointsPolygons({3}, {0, 1, 2}, vars);
    ASSERT_TRUE(r.Ok());
    ASSERT_EQ(r.Value().cornerNormals.size(), 3u);
    EXPECT_EQ(r.Value().cornerNormals[1], V3f(0, 1, 0));
    EXPECT_TRUE(r.Value().normals.empty());
}

TEST(PointsGeneralPolygons, FacesWithAndWithoutHoles) {
    const std::vector<V3f> pts = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {1, 1, 0},
                                  {1, 3, 0}, {3, 3, 0}, {3, 1, 0}, {5, 0, 0}};
    auto r =
        MakePointsGeneralPolygons({2, 1}, {4, 4, 3}, {0, 1, 2, 3, 4, 5, 6, 7, 1, 8, 2}, WithP(pts));
    ASSERT_TRUE(r.Ok()) << r.Error();
    EXPECT_NEAR(MeshArea(r.Value()), 16.0 - 4.0 + 2.0, 1e-5);
    ExpectWoundLike(r.Value(), V3f(0, 0, 1));
}

TEST(GeneralPolygon, CombWithManyHolesInTiltedPlane) {
    // A comb of 20 teeth (strongly concave) with a square hole in each tooth's base block,
    // placed in a tilted plane far from the origin. Area: base 20×1 + teeth 20·(0.5×2) − holes.
    const V3f origin(100, -50, 30),
        ex = V3f(2, 1, 0).normalized(),
        ey = V3f(-1, 2, 3).normalized().cross(ex).cross(ex).normalized();
    auto at = [&](float x, float y) { return origin + ex * x + ey * y; };
    std::vector<V3f> pts = {at(0, 0), at(20, 0)};
    for (int t = 19; t >= 0; --t)
        for (V2f q : {V2f(t + 1.0f, 1), V2f(t + 1.0f, 3), V2f(t + 0.5f, 3), V2f(t + 0.5f, 1)})
            pts.push_back(at(q.x, q.y));
    pts.push_back(at(0, 1));
    std::vector<int> loops = {static_cast<int>(pts.size())};
    for (int t = 0; t < 20; ++t) {
        for (V2f q :
             {V2f(t + 0.3f, 0.3f), V2f(t + 0.3f, 0.7f), V2f(t + 0.7f, 0.7f), V2f(t + 0.7f, 0.3f)})
            pts.push_back(at(q.x, q.y));
        loops.push_back(4);
    }
    auto r = MakeGeneralPolygon(loops, WithP(pts));
    ASSERT_TRUE(r.Ok());
    EXPECT_NEAR(MeshArea(r.Value()), 20.0 + 20.0 - 20 * 0.16, 1e-3);
    ExpectWoundLike(r.Value(), ey.cross(ex) * -1.0f);
}

TEST(PolygonErrors, BadInputIsReported) {
    const std::vector<V3f> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_FALSE(MakePolygon(PrimVarSet{}).Ok());
    auto outOfRange = MakePointsPolygons({3}, {0, 1, 3}, WithP(pts));
    ASSERT_FALSE(outOfRange.Ok());
    EXPECT_NE(outOfRange.Error().find("out of range"), std::string::npos);
    EXPECT_FALSE(MakePointsPolygons({4}, {0, 1, 2}, WithP(pts)).Ok());
    EXPECT_FALSE(MakePointsPolygons({-1, 4}, {0, 1, 2}, WithP(pts)).Ok());
    EXPECT_FALSE(MakePointsGeneralPolygons({2}, {3}, {0, 1, 2}, WithP(pts)).Ok());
    auto badCount = MakePolygon(
        WithP(pts, {Var("Cs", ParamClass::Varying, ParamType::Color, 3, {1, 1, 1, 0, 0, 0})}));
    ASSERT_FALSE(badCount.Ok());
    EXPECT_NE(badCount.Error().find("Cs"), std::string::npos);
}

TEST(Polygon, HomogeneousPositionsAreDividedByW) {
    PrimVarSet vars;
    vars.vars.push_back(
        Var("Pw", ParamClass::Vertex, ParamType::HPoint, 4, {0, 0, 0, 2, 4, 0, 0, 2, 0, 4, 0, 2}));
    auto r = MakePolygon(vars);
    ASSERT_TRUE(r.Ok());
    EXPECT_EQ(r.Value().positions[1], V3f(2, 0, 0));
    EXPECT_NEAR(MeshArea(r.Value()), 2.0, 1e-6);
}

}  // namespace
}  // namespace gonio
