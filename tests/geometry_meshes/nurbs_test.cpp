#include "renderer/geometry/nurbs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "mesh_test_util.h"
#include "renderer/geometry/patches.h"

namespace gonio {
namespace {

using test::Var;
using test::WithP;

// The unit circle as a rational quadratic NURBS of 9 control points (Piegl & Tiller §7.5),
// swept from z = 0 to z = 2 by a linear v direction: a cylinder.
struct Cylinder {
    std::vector<float> uknot = {0, 0, 0, 0.25f, 0.25f, 0.5f, 0.5f, 0.75f, 0.75f, 1, 1, 1};
    std::vector<float> vknot = {0, 0, 1, 1};
    PrimVarSet vars;

    Cylinder() {
        const float xy[9][2] = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                                {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
        std::vector<float> pw;
        for (float z : {0.0f, 2.0f})
            for (int i = 0; i < 9; ++i) {
                const float w = i % 2 ? std::sqrt(0.5f) : 1.0f;
                pw.insert(pw.end(), {xy[i][0] * w, xy[i][1] * w, z * w, w});
            }
        vars.vars.push_back(Var("Pw", ParamClass::Vertex, ParamType::HPoint, 4, pw));
    }
};

TEST(NuPatch, RationalCylinderLiesAtItsRadius) {
    Cylinder c;
    auto r = MakeNuPatch(9, 3, c.uknot, 0, 1, 2, 2, c.vknot, 0, 1, c.vars);
    ASSERT_TRUE(r.Ok()) << r.Error();
    const TriangleMesh& m = r.Value();
    EXPECT_EQ(m.TriangleCount(), 4u * 16 * 2);
    for (const V3f& p : m.positions) {
        EXPECT_NEAR(std::hypot(p.x, p.y), 1.0f, 1e-5);
        EXPECT_TRUE(p.z == 0.0f || std::abs(p.z - 2.0f) < 1e-5);
    }
    // Uniform values belong to knot spans, the empty (repeated-knot) ones included.
    const std::set<uint32_t> faces(m.faceOfTriangle.begin(), m.faceOfTriangle.end());
    EXPECT_EQ(faces, (std::set<uint32_t>{0, 2, 4, 6}));
    // The seam closes: u = 0 and u = 1 give the same point.
    EXPECT_NEAR((m.positions.front() - m.positions[64]).length(), 0, 1e-6);
    EXPECT_EQ(m.uv[64], V2f(1, 0));
    // Outward normals: dPdu × dPdv for a counter-clockwise circle swept up +z points out.
    const V3f n = test::TriangleNormal(m, 0);
    EXPECT_GT(n.dot(m.positions[m.indices[0]]), 0);
}

TEST(NuPatch, ParameterRangeSelectsPartOfTheSurface) {
    Cylinder c;
    auto r = MakeNuPatch(9, 3, c.uknot, 0.25f, 0.5f, 2, 2, c.vknot, 0, 1, c.vars);
    ASSERT_TRUE(r.Ok()) << r.Error();
    for (const V3f& p : r.Value().positions) {
        EXPECT_LE(p.x, 1e-5f);
        EXPECT_GE(p.y, -1e-5f);
    }
    EXPECT_EQ(r.Value().uv.front().x, 0.25f);
}

TEST(NuPatch, ClampedCubicEqualsBezierPatch) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> d(-1, 1);
    std::vector<V3f> p(16);
    for (V3f& q : p) q = V3f(d(rng), d(rng), d(rng));
    const std::vector<float> knots = {0, 0, 0, 0, 1, 1, 1, 1};
    std::vector<float> st(2 * 4);
    for (int i = 0; i < 8; ++i) st[i] = float(i);
    auto vars = WithP(p, {Var("st", ParamClass::Varying, ParamType::Float, 2, st)});
    auto nurbs = MakeNuPatch(4, 4, knots, 0, 1, 4, 4, knots, 0, 1, vars);
    auto bezier = MakePatch("bicubic", BezierBasis(), BezierBasis(), vars);
    ASSERT_TRUE(nurbs.Ok()) << nurbs.Error();
    ASSERT_TRUE(bezier.Ok());
    ASSERT_EQ(nurbs.Value().positions.size(), bezier.Value().positions.size());
    for (size_t i = 0; i < nurbs.Value().positions.size(); ++i)
        EXPECT_NEAR((nurbs.Value().positions[i] - bezier.Value().positions[i]).length(), 0, 1e-5);
    const MeshVar* a = test::FindVar(nurbs.Value(), "st");
    const MeshVar* b = test::FindVar(bezier.Value(), "st");
    ASSERT_TRUE(a && b);
    for (size_t i = 0; i < a->var.values.size(); ++i)
        EXPECT_NEAR(a->var.values[i], b->var.values[i], 1e-5);
}

TEST(NuPatch, BasisFunctionsPartitionUnity) {
    const std::vector<float> knots = {0, 0, 0, 1, 2, 4, 4, 4};
    for (double u : {0.0, 0.5, 1.5, 3.9}) {
        const int span = u < 1 ? 2 : u < 2 ? 3 : 4;
        double sum = 0;
        for (double n : BSplineBasisFunctions(knots, span, 3, u)) sum += n;
        EXPECT_NEAR(sum, 1.0, 1e-12);
    }
}

TEST(NuPatch, BadKnotsAndRangesAreReported) {
    Cylinder c;
    std::vector<float> decreasing = c.uknot;
    decreasing[4] = 0.1f;
    auto r = MakeNuPatch(9, 3, decreasing, 0, 1, 2, 2, c.vknot, 0, 1, c.vars);
    ASSERT_FALSE(r.Ok());
    EXPECT_NE(r.Error().find("must not decrease"), std::string::npos);
    EXPECT_FALSE(MakeNuPatch(9, 3, {0, 1}, 0, 1, 2, 2, c.vknot, 0, 1, c.vars).Ok());
    EXPECT_FALSE(MakeNuPatch(9, 10, c.uknot, 0, 1, 2, 2, c.vknot, 0, 1, c.vars).Ok());
    EXPECT_FALSE(MakeNuPatch(9, 3, c.uknot, 2, 3, 2, 2, c.vknot, 0, 1, c.vars).Ok());
    EXPECT_FALSE(MakeNuPatch(9, 3, c.uknot, 0, 1, 2, 2, c.vknot, 0, 1, PrimVarSet{}).Ok());
    Cylinder bad;
    bad.vars.vars.push_back(Var("Cs", ParamClass::Varying, ParamType::Color, 3, {1, 1, 1}));
    EXPECT_FALSE(MakeNuPatch(9, 3, c.uknot, 0, 1, 2, 2, c.vknot, 0, 1, bad.vars).Ok());
}

}  // namespace
}  // namespace gonio
