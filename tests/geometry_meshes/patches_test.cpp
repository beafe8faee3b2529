#include "renderer/geometry/patches.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesh_test_util.h"

namespace gonio {
namespace {

using test::Var;
using test::WithP;

// The mesh vertex whose uv is closest to (u, v).
size_t VertexAt(const TriangleMesh& m, float u, float v) {
    size_t best = 0;
    for (size_t i = 1; i < m.uv.size(); ++i)
        if ((m.uv[i] - V2f(u, v)).length2() < (m.uv[best] - V2f(u, v)).length2()) best = i;
    return best;
}

std::vector<V3f> RandomPoints(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> d(-1, 1);
    std::vector<V3f> pts(n);
    for (V3f& p : pts) p = V3f(d(rng), d(rng), d(rng));
    return pts;
}

float Bernstein3(int i, float t) {
    const float c[4] = {1, 3, 3, 1};
    return c[i] * std::pow(t, float(i)) * std::pow(1 - t, float(3 - i));
}

TEST(Basis, NamedBasesAndSteps) {
    EXPECT_EQ(NamedBasis("bezier")->step, 3);
    EXPECT_EQ(NamedBasis("b-spline")->step, 1);
    EXPECT_EQ(NamedBasis("catmull-rom")->step, 1);
    EXPECT_EQ(NamedBasis("hermite")->step, 2);
    EXPECT_EQ(NamedBasis("power")->step, 4);
    EXPECT_FALSE(NamedBasis("bogus").has_value());
    // Bézier, B-spline and Catmull-Rom weights form a partition of unity.
    for (const char* name : {"bezier", "b-spline", "catmull-rom"})
        for (float t : {0.0f, 0.3f, 1.0f}) {
            const auto w = BasisWeights(NamedBasis(name)->matrix, t);
            EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0f, 1e-6) << name;
        }
    const auto w = BasisWeights(BezierBasis().matrix, 0.5f);
    EXPECT_FLOAT_EQ(w[1], 3.0f / 8);
}

TEST(Patch, BilinearInterpolatesCornersAndVaryingValues) {
    const std::vector<V3f> p = {{0, 0, 0}, {2, 0, 1}, {0, 1, 1}, {2, 1, -1}};
    auto vars = WithP(p, {Var("Cs", ParamClass::Varying, ParamType::Color, 3,
                              {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1})});
    auto r = MakePatch("bilinear", BezierBasis(), BezierBasis(), vars);
    ASSERT_TRUE(r.Ok()) << r.Error();
    const TriangleMesh& m = r.Value();
    const MeshVar* cs = test::FindVar(m, "Cs");
    ASSERT_NE(cs, nullptr);
    ASSERT_EQ(cs->rate, MeshRate::PerVertex);
    ASSERT_EQ(m.uv.size(), m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const float u = m.uv[i].x, v = m.uv[i].y;
        const V3f expected =
            (1 - v) * ((1 - u) * p[0] + u * p[1]) + v * ((1 - u) * p[2] + u * p[3]);
        EXPECT_NEAR((m.positions[i] - expected).length(), 0, 1e-5);
        const float* c = cs->var.Value(static_cast<int>(i));
        EXPECT_NEAR(c[0], (1 - u) * (1 - v) + u * v, 1e-5);
        EXPECT_NEAR(c[2], (1 - u) * v + u * v, 1e-5);
    }
    EXPECT_EQ(m.positions[VertexAt(m, 1, 1)], p[3]);
    EXPECT_GT(m.TriangleCount(), 2u);  // twisted: tessellated
    // Every triangle faces along dPdu × dPdv = (3v − 1, 6u − 2, 2) at its centroid.
    for (size_t t = 0; t < m.TriangleCount(); ++t) {
        V2f uv(0);
        for (int k = 0; k < 3; ++k) uv += m.uv[m.indices[3 * t + k]] / 3.0f;
        const V3f normal(3 * uv.y - 1, 6 * uv.x - 2, 2);
        EXPECT_GT(test::TriangleNormal(m, t).normalized().dot(normal.normalized()), 0.95f);
    }
}

TEST(Patch, FlatBilinearParallelogramIsTwoTriangles) {
    auto r = MakePatch("bilinear", BezierBasis(), BezierBasis(),
                       WithP({{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {1.5f, 1, 0}}));
    ASSERT_TRUE(r.Ok());
    EXPECT_EQ(r.Value().TriangleCount(), 2u);
    // u × v order (0,0) (1,0) (0,1) (1,1) gives dPdu × dPdv = +z.
    EXPECT_GT(test::TriangleNormal(r.Value(), 0).z, 0);
}

TEST(Patch, BezierReproducesCornersAndBernsteinInterior) {
    const std::vector<V3f> p = RandomPoints(16, 7);
    auto r = MakePatch("bicubic", BezierBasis(), BezierBasis(), WithP(p));
    ASSERT_TRUE(r.Ok());
    const TriangleMesh& m = r.Value();
    EXPECT_EQ(m.positions.size(), 17u * 17u);
    EXPECT_NEAR((m.positions[VertexAt(m, 0, 0)] - p[0]).length(), 0, 1e-6);
    EXPECT_NEAR((m.positions[VertexAt(m, 1, 0)] - p[3]).length(), 0, 1e-6);
    EXPECT_NEAR((m.positions[VertexAt(m, 0, 1)] - p[12]).length(), 0, 1e-6);
    EXPECT_NEAR((m.positions[VertexAt(m, 1, 1)] - p[15]).length(), 0, 1e-6);
    for (V2f uv : {V2f(0.5f, 0.5f), V2f(0.25f, 0.75f)}) {
        V3f expected(0);
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                expected += Bernstein3(i, uv.x) * Bernstein3(j, uv.y) * p[4 * j + i];
        EXPECT_NEAR((m.positions[VertexAt(m, uv.x, uv.y)] - expected).length(), 0, 1e-5);
    }
}

TEST(Patch, CatmullRomPatchPassesThroughInnerControlPoints) {
    const std::vector<V3f> p = RandomPoints(16, 3);
    auto r = MakePatch("bicubic", CatmullRomBasis(), CatmullRomBasis(), WithP(p));
    ASSERT_TRUE(r.Ok());
    const TriangleMesh& m = r.Value();
    EXPECT_NEAR((m.positions[VertexAt(m, 0, 0)] - p[5]).length(), 0, 1e-5);
    EXPECT_NEAR((m.positions[VertexAt(m, 1, 1)] - p[10]).length(), 0, 1e-5);
}

TEST(Patch, HeightFieldTakesXYFromTheParameters) {
    PrimVarSet vars;
    vars.vars.push_back(Var("Pz", ParamClass::Vertex, ParamType::Float, 1, {0, 1, 2, 4}));
    auto r = MakePatch("bilinear", BezierBasis(), BezierBasis(), vars);
    ASSERT_TRUE(r.Ok()) << r.Error();
    const TriangleMesh& m = r.Value();
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const float u = m.uv[i].x, v = m.uv[i].y;
        EXPECT_NEAR(m.positions[i].x, u, 1e-6);
        EXPECT_NEAR(m.positions[i].y, v, 1e-6);
        EXPECT_NEAR(m.positions[i].z, (1 - v) * u + v * (2 * (1 - u) + 4 * u), 1e-5);
    }
}

TEST(Patch, HomogeneousControlPointsAreRational) {
    // Pw = (w·P, w) with one weight raised pulls the surface towards that point.
    const std::vector<V3f> p = RandomPoints(16, 11);
    std::vector<float> pw;
    for (int i = 0; i < 16; ++i) {
        const float w = i == 5 ? 4.0f : 1.0f;
        pw.insert(pw.end(), {p[i].x * w, p[i].y * w, p[i].z * w, w});
    }
    PrimVarSet vars;
    vars.vars.push_back(Var("Pw", ParamClass::Vertex, ParamType::HPoint, 4, pw));
    auto r = MakePatch("bicubic", BezierBasis(), BezierBasis(), vars);
    ASSERT_TRUE(r.Ok());
    const TriangleMesh& m = r.Value();
    const float u = 0.25f, v = 0.5f;
    V3f num(0);
    float den = 0;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const float b = Bernstein3(i, u) * Bernstein3(j, v) * (4 * j + i == 5 ? 4.0f : 1.0f);
            num += b * p[4 * j + i];
            den += b;
        }
    EXPECT_NEAR((m.positions[VertexAt(m, u, v)] - num / den).length(), 0, 1e-5);
}

TEST(PatchMesh, BSplineMeshIsContinuousAcrossPatches) {
    // 7 × 4 control points, nonperiodic B-spline: 4 patches in u, 1 in v.
    std::vector<V3f> p;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> d(-0.5f, 0.5f);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 7; ++i) p.push_back(V3f(float(i), float(j), d(rng)));
    std::vector<float> kd = {0.1f, 0.2f, 0.3f, 0.4f};
    auto r =
        MakePatchMesh("bicubic", 7, "nonperiodic", 4, "nonperiodic", BSplineBasis(), BSplineBasis(),
                      WithP(p, {Var("Kd", ParamClass::Uniform, ParamType::Float, 1, kd)}));
    ASSERT_TRUE(r.Ok()) << r.Error();
    const TriangleMesh& m = r.Value();
    const int columns = 4 * 16 + 1;
    ASSERT_EQ(m.positions.size(), size_t(columns) * 17);
    // At each patch boundary u = k/4 on the row v = 0: the uniform B-spline value
    // (P[k] + 4 P[k+1] + P[k+2]) / 6 in u, blended likewise in v, with the same tangent on both
    // sides (C1).
    for (int k = 1; k < 4; ++k) {
        const int c = 16 * k;
        V3f expected(0);
        const float wv[3] = {1 / 6.0f, 4 / 6.0f, 1 / 6.0f};
        for (int j = 0; j < 3; ++j)
            expected += wv[j] * (p[7 * j + k] + 4.0f * p[7 * j + k + 1] + p[7 * j + k + 2]) / 6.0f;
        EXPECT_NEAR((m.positions[c] - expected).length(), 0, 1e-5);
        auto slope = [&](int i) { return m.positions[i + 1] - m.positions[i]; };
        // Across the boundary the slope changes no more than between neighbours on either
        // side (a kink would change it by O(h), not O(h²)).
        const float across = (slope(c) - slope(c - 1)).length();
        const float within =
            (slope(c - 1) - slope(c - 2)).length() + (slope(c + 1) - slope(c)).length();
        EXPECT_LT(across, 0.75f * within);
    }
    // Uniform values follow the patches: triangles in the first column of cells are patch 0.
    EXPECT_EQ(m.faceOfTriangle.front(), 0u);
    EXPECT_EQ(m.faceOfTriangle[2 * 16], 1u);
    EXPECT_EQ(m.faceOfTriangle.back(), 3u);
    EXPECT_EQ(test::FindVar(m, "Kd")->rate, MeshRate::PerFace);
}

TEST(PatchMesh, PeriodicWrapClosesTheSurfaceExactly) {
    // A B-spline tube: 8 control points around z in u (periodic), 4 rows along z.
    std::vector<V3f> p;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 8; ++i) {
            const float a = 2 * float(M_PI) * i / 8;
            p.push_back(V3f(std::cos(a), std::sin(a), float(j)));
        }
    std::vector<float> cs(8 * 2 * 3);
    for (int i = 0; i < 16; ++i) cs[3 * i] = float(i % 8);  // red = u corner number
    auto r =
        MakePatchMesh("bicubic", 8, "periodic", 4, "nonperiodic", BSplineBasis(), BSplineBasis(),
                      WithP(p, {Var("Cs", ParamClass::Varying, ParamType::Color, 3, cs)}));
    ASSERT_TRUE(r.Ok()) << r.Error();
    const TriangleMesh& m = r.Value();
    const int columns = 8 * 16 + 1;
    ASSERT_EQ(m.positions.size(), size_t(columns) * 17);
    for (int row = 0; row < 17; ++row) {
        EXPECT_EQ(m.positions[row * columns], m.positions[row * columns + columns - 1]);
        EXPECT_EQ(m.uv[row * columns + columns - 1].x, 1.0f);
        // A uniform B-spline circle of 8 points lies between radius cos(π/8)·... and 1.
        const float radius = std::hypot(m.positions[row * columns].x, m.positions[row * columns].y);
        EXPECT_GT(radius, 0.85f);
        EXPECT_LT(radius, 1.0f);
    }
    // Varying values wrap too: halfway through the last patch red blends corners 7 and 0.
    const float* red = test::FindVar(m, "Cs")->var.Value(7 * 16 + 8);
    EXPECT_NEAR(red[0], 3.5f, 1e-5);
    EXPECT_EQ(m.faceOfTriangle[2 * (8 * 16 - 1)], 7u);
}

TEST(PatchMesh, CountsAndErrors) {
    const std::vector<V3f> p5(5 * 4, V3f(0));
    auto bezier5 = MakePatchMesh("bicubic", 5, "nonperiodic", 4, "nonperiodic", BezierBasis(),
                                 BezierBasis(), WithP(p5));
    ASSERT_FALSE(bezier5.Ok());
    EXPECT_NE(bezier5.Error().find("step 3"), std::string::npos);
    EXPECT_FALSE(MakePatch("trilinear", BezierBasis(), BezierBasis(), WithP(p5)).Ok());
    EXPECT_FALSE(MakePatchMesh("bilinear", 2, "sometimes", 2, "periodic", BezierBasis(),
                               BezierBasis(), WithP({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}))
                     .Ok());
    // Bilinear 3 × 2 nonperiodic: 2 patches, varying 3·2, so 4 varying values are wrong.
    const std::vector<V3f> p6(6, V3f(0));
    auto badVarying = MakePatchMesh(
        "bilinear", 3, "nonperiodic", 2, "nonperiodic", BezierBasis(), BezierBasis(),
        WithP(p6, {Var("s", ParamClass::Varying, ParamType::Float, 1, {0, 1, 2, 3})}));
    ASSERT_FALSE(badVarying.Ok());
    EXPECT_NE(badVarying.Error().find("needs 6"), std::string::npos);
    EXPECT_FALSE(MakePatch("bilinear", BezierBasis(), BezierBasis(), WithP(p6)).Ok());
    PrimVarSet heights;
    heights.vars.push_back(Var("Pz", ParamClass::Vertex, ParamType::Float, 1, {0, 0, 0, 0}));
    EXPECT_FALSE(MakePatchMesh("bilinear", 2, "periodic", 2, "nonperiodic", BezierBasis(),
                               BezierBasis(), heights)
                     .Ok());
}

}  // namespace
}  // namespace gonio
