// Blobby (RISpec 3.2 §5.6): the field against Application Note #31's formulas written out here,
// the tessellated surface against analytic spheres and necks, the blending of per-leaf
// primitive variables, and the located errors for bad code arrays.

#include "renderer/geometry/blobby.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <utility>

#include "mesh_test_util.h"
#include "renderer/geometry/blobby_field.h"

namespace gonio {
namespace {

// The field of one unit-sphere leaf at squared distance s: (1 − s)³ inside, 0 outside.
double F(double s) { return s < 1 ? (1 - s) * (1 - s) * (1 - s) : 0; }

// A 4×4 matrix (row vectors, as RIB) that scales by `scale` and then translates to `at`.
std::vector<float> Matrix(V3f scale, V3f at) {
    return {scale.x, 0, 0, 0, 0, scale.y, 0, 0, 0, 0, scale.z, 0, at.x, at.y, at.z, 1};
}

std::vector<float> Concat(std::vector<std::vector<float>> parts) {
    std::vector<float> all;
    for (auto& p : parts) all.insert(all.end(), p.begin(), p.end());
    return all;
}

BlobbyField Field(const std::vector<int>& code, const std::vector<float>& floats,
                  const std::vector<std::string>& strings = {}) {
    std::vector<std::string> notes;
    auto program = DecodeBlobby(0, code, floats, strings, &notes);
    EXPECT_TRUE(program.Ok()) << (program.Ok() ? "" : program.Error());
    return BlobbyField(program.Take());
}

BlobbyMesh Mesh(const std::vector<int>& code, const std::vector<float>& floats,
                const PrimVarSet& vars = {}) {
    std::vector<std::string> notes;
    auto result = MakeBlobby(0, code, floats, {}, vars, BlobbyTessellation{}, &notes);
    EXPECT_TRUE(result.Ok()) << (result.Ok() ? "" : result.Error());
    return result.Ok() ? result.Take() : BlobbyMesh{};
}

// The radius where (1 − r²)³ = level.
double RadiusAt(double level) { return std::sqrt(1 - std::cbrt(level)); }

// Every edge of a closed mesh is shared by exactly two triangles, in opposite directions.
bool IsClosed(const TriangleMesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (size_t t = 0; t < m.TriangleCount(); ++t)
        for (int k = 0; k < 3; ++k)
            ++directed[{m.indices[3 * t + k], m.indices[3 * t + (k + 1) % 3]}];
    for (const auto& [edge, count] : directed)
        if (count != 1 || directed.count({edge.second, edge.first}) != 1) return false;
    return true;
}

TEST(BlobbyField, EllipsoidIsTheUnitSphereFieldCarriedByItsMatrix) {
    const V3f scale(2, 1, 0.5f), at(1, 2, 3);
    const BlobbyField field = Field({1001, 0}, Matrix(scale, at));
    std::vector<FieldSample> scratch;
    for (const V3f& p : {V3f(1, 2, 3), V3f(1.5f, 2.2f, 3.1f), V3f(2.9f, 2, 3), V3f(4, 2, 3)}) {
        const V3f q = (p - at) / scale;
        EXPECT_NEAR(field.Evaluate(p, &scratch).value, F(q.length2()), 1e-6) << p;
    }
}

TEST(BlobbyField, GradientIsTheFieldsDerivative) {
    // An ellipsoid, a segment blob and a repelling plane added, then multiplied and divided:
    // the analytic gradient against central differences at points where all are non-zero.
    const std::vector<float> floats = Concat({Matrix(V3f(1.5f, 1, 1), V3f(0)),
                                              {-0.5f, 0, 0, 0.5f, 0.2f, 0, 0.8f},
                                              Matrix(V3f(1), V3f(0.1f, 0, 0)),
                                              {2, 0.01f, 0.5f, 0.3f},
                                              {0.7f}});
    const BlobbyField field = Field(
        {1001, 0, 1002, 16, 1003, 0, 39, 1000, 43, 0, 3, 0, 1, 2, 1, 2, 0, 1, 5, 5, 3, 4, 4, 6},
        floats, {"ground"});
    std::vector<FieldSample> scratch;
    const float h = 1e-3f;
    for (const V3f& p : {V3f(0.2f, 0.1f, 0.3f), V3f(-0.3f, 0.2f, 0.4f), V3f(0.4f, -0.1f, 0.2f)}) {
        const FieldSample s = field.Evaluate(p, &scratch);
        for (int a = 0; a < 3; ++a) {
            V3f d(0);
            d[a] = h;
            const float numeric =
                (field.Evaluate(p + d, &scratch).value - field.Evaluate(p - d, &scratch).value) /
                (2 * h);
            EXPECT_NEAR(s.gradient[a], numeric, 2e-3f * (1 + std::fabs(numeric)))
                << "axis " << a << " at " << p;
        }
    }
}

TEST(BlobbyField, OperationsFollowTheirFormulas) {
    // Two unit spheres, A at the origin and B at (0.5, 0, 0), combined by each operation.
    const std::vector<float> floats =
        Concat({Matrix(V3f(1), V3f(0)), Matrix(V3f(1), V3f(0.5f, 0, 0))});
    struct Case {
        std::vector<int> operation;  // appended after "1001 0 1001 16"
        double (*formula)(double a, double b);
    };
    const Case cases[] = {
        {{0, 2, 0, 1}, [](double a, double b) { return a + b; }},
        {{1, 2, 0, 1}, [](double a, double b) { return a * b; }},
        {{2, 2, 0, 1}, [](double a, double b) { return std::max(a, b); }},
        {{3, 2, 0, 1}, [](double a, double b) { return std::min(a, b); }},
        {{4, 0, 1}, [](double a, double b) { return a - b; }},
        {{5, 0, 1}, [](double a, double b) { return b != 0 ? a / b : 0; }},
        {{6, 1}, [](double, double b) { return -b; }},
        {{7, 0}, [](double a, double) { return a; }},
    };
    std::vector<FieldSample> scratch;
    for (const Case& c : cases) {
        std::vector<int> code = {1001, 0, 1001, 16};
        code.insert(code.end(), c.operation.begin(), c.operation.end());
        const BlobbyField field = Field(code, floats);
        for (const V3f& p : {V3f(0.1f, 0.2f, 0), V3f(0.45f, -0.3f, 0.1f), V3f(0.9f, 0, 0.2f),
                             V3f(-0.6f, 0.1f, 0)}) {
            const double a = F(p.length2()), b = F((p - V3f(0.5f, 0, 0)).length2());
            EXPECT_NEAR(field.Evaluate(p, &scratch).value, c.formula(a, b), 1e-5)
                << "opcode " << c.operation[0] << " at " << p;
        }
    }
}

TEST(BlobbyField, LocalEvaluationInABoxIsTheFullField) {
    // Leaves at the origin, at (3, 0, 0) and (0, 3, 0), a constant, and every operation over
    // them; in boxes that some leaves' supports miss, their operands are folded into constants.
    const std::vector<float> floats = Concat({Matrix(V3f(1), V3f(0)),
                                              Matrix(V3f(1.2f), V3f(3, 0, 0)),
                                              Matrix(V3f(0.8f), V3f(0, 3, 0)),
                                              {0.3f}});
    const BlobbyField field = Field({1001, 0, 1001, 16, 1001, 32, 1000, 48,  // 0-3
                                     0,    3, 0,    1,  2,                   // 4 add
                                     2,    3, 0,    1,  3,                   // 5 max
                                     1,    3, 4,    3,  2,                   // 6 multiply
                                     3,    2, 5,    6,                       // 7 min
                                     4,    4, 7,                             // 8 subtract
                                     5,    8, 4,                             // 9 divide
                                     6,    9,                                // 10 negate
                                     0,    4, 10,   4,  5,    1},            // 11 add
                                    floats);
    std::vector<FieldSample> scratch;
    BlobbyField::Local local;
    int compared = 0;
    for (const V3f& corner : {V3f(-0.5f, -0.5f, -0.5f), V3f(2.5f, -0.2f, 0), V3f(0.1f, 2.6f, 0),
                              V3f(0.8f, 0.8f, 0.2f), V3f(5, 5, 5)}) {
        const Box3f box(corner, corner + V3f(0.9f));
        field.Localize(box, &local);
        for (int k = 0; k < 27; ++k) {
            const V3f p = corner + 0.9f * V3f((k % 3) / 2.f, (k / 3 % 3) / 2.f, (k / 9) / 2.f);
            const FieldSample full = field.Evaluate(p, &scratch);
            const FieldSample part = field.Evaluate(p, &local);
            EXPECT_NEAR(part.value, full.value, 1e-5f * (1 + std::fabs(full.value))) << p;
            EXPECT_NEAR((part.gradient - full.gradient).length(), 0, 1e-4f) << p;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 135);
}

TEST(BlobbyField, SegmentBlobIsTheFieldOfTheDistanceToTheSegment) {
    // Ends (−1, 0, 0) and (1, 0, 0), radius 0.5, moved by (0, 0, 2).
    const BlobbyField field =
        Field({1002, 0}, Concat({{-1, 0, 0, 1, 0, 0, 0.5f}, Matrix(V3f(1), V3f(0, 0, 2))}));
    std::vector<FieldSample> scratch;
    EXPECT_NEAR(field.Evaluate(V3f(0.3f, 0.2f, 2), &scratch).value, F(0.04 / 0.25), 1e-6);
    EXPECT_NEAR(field.Evaluate(V3f(1.3f, 0, 2.1f), &scratch).value, F((0.09 + 0.01) / 0.25), 1e-6);
    EXPECT_EQ(field.Evaluate(V3f(0, 0.6f, 2), &scratch).value, 0.f);
}

TEST(BlobbyField, RepellingPlaneIsTheAppNoteRepulsionOfTheHeight) {
    const float A = 2, B = 0.01f, C = 0.5f, D = 0.3f;
    const BlobbyField field = Field({1003, 0, 0}, {A, B, C, D}, {"ground.z"});
    auto bump = [](double r) {
        return r <= 0 || r >= 2
                   ? 0
                   : 8 * r * r * r - 12 * std::pow(r, 4) + 6 * std::pow(r, 5) - std::pow(r, 6);
    };
    auto ease = [](double r) { return r <= 0 ? 0 : r >= 1 ? 1 : 3 * r * r - 2 * r * r * r; };
    std::vector<FieldSample> scratch;
    for (float z : {0.1f, 0.5f, 0.9f, 1.5f}) {
        const double expected = (D * bump(z / C) - B / z) * (1 - ease(z / A));
        EXPECT_NEAR(field.Evaluate(V3f(3, -2, z), &scratch).value, expected, 1e-6) << z;
    }
    EXPECT_EQ(field.Evaluate(V3f(0, 0, 2.5f), &scratch).value, 0.f);
    EXPECT_TRUE(field.Bounds().isEmpty());
}

// A depth map seen straight down from 4 units above z = 0 of object space by an orthographic
// camera whose screen covers [-half, half]²: each texel holds the depth of `ground(x, y)` at
// its centre, 4 − ground.
std::shared_ptr<BlobbyDepthMap> TopDownMap(int n, float half,
                                           const std::function<float(float, float)>& ground) {
    std::vector<float> depth(size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = -half + (i + 0.5f) * 2 * half / n;
            const float y = half - (j + 0.5f) * 2 * half / n;  // row 0 is the top
            depth[size_t(j) * n + i] = 4 - ground(x, y);
        }
    const M44f cameraFromObject(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 4, 1);
    const M44f screenFromObject(1 / half, 0, 0, 0, 0, 1 / half, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1);
    return std::make_shared<BlobbyDepthMap>(n, n, std::move(depth), cameraFromObject,
                                            screenFromObject);
}

// A lone repelling plane (A = 2, B = 0.01, C = 0.5, D = 0.3) given `map` (none: z = 0).
BlobbyField PlaneField(std::shared_ptr<BlobbyDepthMap> map) {
    std::vector<std::string> notes;
    auto program = DecodeBlobby(0, {1003, 0, 0}, {2, 0.01f, 0.5f, 0.3f}, {"ground.z"}, &notes);
    EXPECT_TRUE(program.Ok());
    program.Value().leaves[0].depthMap = std::move(map);
    return BlobbyField(program.Take());
}

TEST(BlobbyField, AFlatDepthMapIsThePlaneZEqualsZero) {
    const BlobbyField plane = PlaneField(nullptr);
    const BlobbyField mapped = PlaneField(TopDownMap(8, 3, [](float, float) { return 0.f; }));
    std::vector<FieldSample> a, b;
    // Heights whose depths 4 − z are exact in float; points inside and beyond the map's edge.
    for (float z : {-0.5f, 0.f, 0.25f, 0.5f, 0.75f, 1.25f, 1.75f, 3.f})
        for (const V3f& xy : {V3f(0.3f, -0.7f, 0), V3f(2.9f, 2.9f, 0), V3f(-5, 7, 0)}) {
            const V3f p = xy + V3f(0, 0, z);
            const FieldSample expected = plane.Evaluate(p, &a), got = mapped.Evaluate(p, &b);
            EXPECT_EQ(got.value, expected.value) << p;
            EXPECT_EQ(got.gradient, expected.gradient) << p;
        }
}

TEST(BlobbyField, ATiltedDepthMapRepelsFromTheTiltedGround) {
    // The ground z = 0.2·x: the height above it is z − 0.2·x, and the field's gradient is the
    // flat plane's derivative times ∇(z − 0.2·x) = (−0.2, 0, 1). Bilinear interpolation
    // reproduces a linear ground exactly between the texel centres.
    const BlobbyField plane = PlaneField(nullptr);
    const BlobbyField tilted =
        PlaneField(TopDownMap(16, 3, [](float x, float) { return 0.2f * x; }));
    std::vector<FieldSample> a, b;
    for (const V3f& p : {V3f(0.4f, 0.3f, 0.5f), V3f(-1.7f, 1.1f, -0.1f), V3f(2.1f, -2.4f, 0.9f)}) {
        const float height = p.z - 0.2f * p.x;
        const FieldSample expected = plane.Evaluate(V3f(0, 0, height), &a);
        const FieldSample got = tilted.Evaluate(p, &b);
        EXPECT_NEAR(got.value, expected.value, 1e-4f * (1 + std::fabs(expected.value))) << p;
        const V3f gradient = expected.gradient.z * V3f(-0.2f, 0, 1);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(got.gradient[k], gradient[k], 1e-3f * (1 + std::fabs(gradient[k]))) << p;
    }
    // A point the map saw nothing under is not repelled.
    const BlobbyField empty = PlaneField(
        TopDownMap(4, 3, [](float, float) { return -std::numeric_limits<float>::infinity(); }));
    EXPECT_EQ(empty.Evaluate(V3f(0, 0, 0.1f), &b).value, 0.f);
}

// A unit ellipsoid at the origin (surface radius 0.4542) cut by a strongly repelling plane (D = 0,
// B = 0.01): below the ground the height is clamped and the field is about −B/10⁻⁶, so no
// surface reaches under it. The lowest vertex left of x = −0.1 and right of x = 0.1, with
// `ground`.
std::pair<float, float> LowestLeftAndRight(const std::function<float(float, float)>& ground) {
    const std::vector<float> floats = Concat({Matrix(V3f(1), V3f(0)), {1, 0.01f, 1, 0}});
    const std::shared_ptr<const BlobbyDepthMap> map = TopDownMap(64, 1, ground);
    std::vector<std::string> notes;
    auto result =
        MakeBlobby(2, {1001, 0, 1003, 0, 16, 0, 2, 0, 1}, floats, {"ground.z"}, {},
                   BlobbyTessellation{}, &notes, [&](const std::string& name, std::string*) {
                       EXPECT_EQ(name, "ground.z");
                       return map;
                   });
    EXPECT_TRUE(result.Ok());
    EXPECT_TRUE(notes.empty()) << notes.front();
    std::pair<float, float> lowest(1e9f, 1e9f);
    for (const V3f& p : result.Value().mesh.positions) {
        if (p.x < -0.1f) lowest.first = std::min(lowest.first, p.z);
        if (p.x > 0.1f) lowest.second = std::min(lowest.second, p.z);
    }
    return lowest;
}

TEST(Blobby, ASteppedDepthMapMovesTheRepelledSurface) {
    const auto [flatLeft, flatRight] = LowestLeftAndRight([](float, float) { return -0.1f; });
    EXPECT_GT(flatLeft, -0.1f);  // the sphere alone would reach z = −0.4542
    EXPECT_LT(flatLeft, 0.f);
    EXPECT_LT(flatRight, 0.f);
    // The ground raised to z = 0.15 for x > 0: the right half's surface stays above it.
    const auto [left, right] =
        LowestLeftAndRight([](float x, float) { return x > 0 ? 0.15f : -0.1f; });
    EXPECT_NEAR(left, flatLeft, 1e-4f);  // cells left of x = −0.1 never sample the step
    EXPECT_GT(right, 0.15f);
}

TEST(Blobby, ARepellingPlaneWithoutItsDepthMapIsZEqualsZeroWithANote) {
    std::vector<std::string> notes;
    auto result = MakeBlobby(
        2, {1001, 0, 1003, 0, 16, 0, 2, 0, 1}, Concat({Matrix(V3f(1), V3f(0)), {1, 0.01f, 1, 0}}),
        {"gone.z"}, {}, BlobbyTessellation{}, &notes, [](const std::string&, std::string* why) {
            *why = "no such file";
            return std::shared_ptr<const BlobbyDepthMap>();
        });
    ASSERT_TRUE(result.Ok());
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0],
              "the repelling plane's depth map \"gone.z\" is not used (no such file): the plane "
              "is z = 0 of object space, with z the height above it");
    float lowest = 1e9f;
    for (const V3f& p : result.Value().mesh.positions) lowest = std::min(lowest, p.z);
    EXPECT_GT(lowest, 0.f);
    EXPECT_LT(lowest, 0.1f);
}

TEST(Blobby, OneEllipsoidIsTheSphereWhereTheFieldIsOneHalf) {
    const double r = RadiusAt(0.5);  // (1 − r²)³ = 0.5: r ≈ 0.4542
    const V3f at(0.3f, -0.2f, 1);
    const BlobbyMesh blobby = Mesh({1001, 0}, Matrix(V3f(1), at));
    const TriangleMesh& m = blobby.mesh;
    ASSERT_GT(m.TriangleCount(), 200u);
    EXPECT_TRUE(IsClosed(m));
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const V3f radial = m.positions[i] - at;
        EXPECT_NEAR(radial.length(), r, 1e-5 * r);
        EXPECT_GT(m.normals[i].dot(radial.normalized()), 0.99999f);
    }
    double worst = 0;
    for (size_t t = 0; t < m.TriangleCount(); ++t) {
        V3f centroid(0);
        for (int k = 0; k < 3; ++k) centroid += m.positions[m.indices[3 * t + k]] / 3.f;
        worst = std::max(worst, r - (centroid - at).length());
        EXPECT_GT(test::TriangleNormal(m, t).dot(centroid - at), 0) << "triangle " << t;
    }
    EXPECT_LT(worst, 0.01 * r);  // flat facets between exact vertices
    // Area of the facets: within 1% of the sphere's.
    EXPECT_NEAR(test::MeshArea(m), 4 * M_PI * r * r, 0.01 * 4 * M_PI * r * r);
}

TEST(Blobby, AnEllipsoidsMatrixScalesTheSphere) {
    const double r = RadiusAt(0.5);
    const V3f scale(2, 1, 0.5f), at(1, 2, 3);
    const TriangleMesh m = Mesh({1001, 0}, Matrix(scale, at)).mesh;
    ASSERT_GT(m.TriangleCount(), 100u);
    for (const V3f& p : m.positions) EXPECT_NEAR(((p - at) / scale).length(), r, 1e-4 * r);
}

TEST(Blobby, TwoSpheresAddedMeetInANeckWhereTwoFieldsMakeOneHalf) {
    // Centres at x = ±d: in the plane x = 0 the surface is the circle where 2·f(d² + ρ²) = 0.5.
    const float d = 0.4f;
    const double rho = std::sqrt(1 - std::cbrt(0.25) - d * d);  // ≈ 0.4583
    const std::vector<float> floats =
        Concat({Matrix(V3f(1), V3f(-d, 0, 0)), Matrix(V3f(1), V3f(d, 0, 0))});
    const TriangleMesh m = Mesh({1001, 0, 1001, 16, 0, 2, 0, 1}, floats).mesh;
    EXPECT_TRUE(IsClosed(m));
    // Where the mesh's edges cross x = 0, they lie on that circle (up to the facets).
    int crossings = 0;
    for (size_t t = 0; t < m.TriangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            const V3f a = m.positions[m.indices[3 * t + k]];
            const V3f b = m.positions[m.indices[3 * t + (k + 1) % 3]];
            if ((a.x < 0) == (b.x < 0)) continue;
            const V3f p = a + (b - a) * (a.x / (a.x - b.x));
            EXPECT_NEAR(std::hypot(p.y, p.z), rho, 0.01 * rho);
            ++crossings;
        }
    EXPECT_GT(crossings, 20);
}

TEST(Blobby, ManyThinLeavesMakeOneClosedSurfaceAcrossTheBlocks) {
    // 120 segment blobs of radius 0.1 winding around a torus: a bound the surface fills little
    // of, so most blocks (more than 3 in 4) are skipped; the mesh still closes across the
    // blocks it samples, and every vertex lies on the level set.
    std::vector<int> code;
    std::vector<float> floats;
    auto at = [](int i) {
        const double u = 2 * M_PI * i / 120, v = 4 * u, r = 1 + 0.3 * std::cos(v);
        return V3f(float(r * std::cos(u)), float(r * std::sin(u)), float(0.3 * std::sin(v)));
    };
    for (int i = 0; i < 120; ++i) {
        code.insert(code.end(), {1002, int(floats.size())});
        const V3f a = at(i), b = at(i + 1);
        floats.insert(floats.end(), {a.x, a.y, a.z, b.x, b.y, b.z, 0.1f});
        const std::vector<float> identity = Matrix(V3f(1), V3f(0));
        floats.insert(floats.end(), identity.begin(), identity.end());
    }
    code.insert(code.end(), {0, 120});
    for (int i = 0; i < 120; ++i) code.push_back(i);
    const BlobbyMesh blobby = Mesh(code, floats);
    const TriangleMesh& m = blobby.mesh;
    ASSERT_GT(m.TriangleCount(), 1000u);
    EXPECT_TRUE(IsClosed(m));
    const BlobbyField field = Field(code, floats);
    const V3f cells = field.Bounds().size() / blobby.cell;
    EXPECT_LT(blobby.sampledPoints, 0.25 * cells.x * cells.y * cells.z);
    std::vector<FieldSample> scratch;
    for (const V3f& p : m.positions)
        EXPECT_NEAR(field.Evaluate(p, &scratch).value, BlobbyField::kThreshold, 1e-4);
}

TEST(Blobby, VertexColoursAreTheLeavesNearTheirOwnBlob) {
    // Two spheres whose supports only touch at the origin: each one's vertices take its own
    // colour exactly; two overlapping ones share colours in proportion to their fields.
    const PrimVarSet colours = {
        {test::Var("Cs", ParamClass::Vertex, ParamType::Color, 3, {1, 0, 0, 0, 0, 1})}};
    for (float d : {1.f, 0.4f}) {
        const std::vector<float> floats =
            Concat({Matrix(V3f(1), V3f(-d, 0, 0)), Matrix(V3f(1), V3f(d, 0, 0))});
        const TriangleMesh m = Mesh({1001, 0, 1001, 16, 0, 2, 0, 1}, floats, colours).mesh;
        const MeshVar* cs = test::FindVar(m, "Cs");
        ASSERT_NE(cs, nullptr);
        EXPECT_EQ(cs->rate, MeshRate::PerVertex);
        ASSERT_EQ(cs->var.ValueCount(), int(m.positions.size()));
        for (size_t i = 0; i < m.positions.size(); ++i) {
            const float* c = cs->var.Value(int(i));
            const V3f p = m.positions[i];
            const double a = F((p + V3f(d, 0, 0)).length2()), b = F((p - V3f(d, 0, 0)).length2());
            EXPECT_NEAR(c[0], a / (a + b), 1e-5) << p;
            EXPECT_NEAR(c[2], b / (a + b), 1e-5) << p;
            if (d == 1.f) {
                EXPECT_EQ(c[0], p.x < 0 ? 1.f : 0.f) << p;
            }
        }
    }
}

TEST(Blobby, MaximumGivesTheColourOfTheLeafItChose) {
    const PrimVarSet colours = {
        {test::Var("Cs", ParamClass::Varying, ParamType::Color, 3, {1, 0, 0, 0, 0, 1})}};
    const std::vector<float> floats =
        Concat({Matrix(V3f(1), V3f(-0.3f, 0, 0)), Matrix(V3f(1), V3f(0.3f, 0, 0))});
    const TriangleMesh m = Mesh({1001, 0, 1001, 16, 2, 2, 0, 1}, floats, colours).mesh;
    const MeshVar* cs = test::FindVar(m, "Cs");
    ASSERT_NE(cs, nullptr);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        if (std::fabs(m.positions[i].x) < 1e-4f) continue;  // the two fields tie there
        EXPECT_EQ(cs->var.Value(int(i))[0], m.positions[i].x < 0 ? 1.f : 0.f);
    }
}

TEST(Blobby, ConstantAndUniformVariablesPassThrough) {
    const PrimVarSet vars = {{test::Var("Kd", ParamClass::Constant, ParamType::Float, 1, {0.25f}),
                              test::Var("id", ParamClass::Uniform, ParamType::Float, 1, {7})}};
    const TriangleMesh m = Mesh({1001, 0}, Matrix(V3f(1), V3f(0)), vars).mesh;
    ASSERT_NE(test::FindVar(m, "Kd"), nullptr);
    EXPECT_EQ(test::FindVar(m, "Kd")->rate, MeshRate::Constant);
    EXPECT_EQ(test::FindVar(m, "id")->rate, MeshRate::PerFace);
    EXPECT_EQ(m.faceOfTriangle.size(), m.TriangleCount());
}

std::string ErrorOf(const std::vector<int>& code, const std::vector<float>& floats,
                    const std::vector<std::string>& strings = {}, const PrimVarSet& vars = {}) {
    std::vector<std::string> notes;
    auto result = MakeBlobby(1, code, floats, strings, vars, BlobbyTessellation{}, &notes);
    return result.Ok() ? "no error" : result.Error();
}

TEST(Blobby, BadCodeArraysAreNamedByTheirPosition) {
    const std::vector<float> identity = Matrix(V3f(1), V3f(0));
    EXPECT_EQ(ErrorOf({1001, 10}, identity),
              "code[1]: the ellipsoid's 16 floats start at 10, but the float array has 16");
    EXPECT_EQ(ErrorOf({1002, 0}, identity),
              "code[1]: the segment blob's 23 floats start at 0, but the float array has 16");
    EXPECT_EQ(ErrorOf({1001, 0, 9, 0}, identity),
              "code[2]: unknown opcode 9 (operations are 0-7, primitive fields 1000-1004)");
    EXPECT_EQ(ErrorOf({1005, 0}, identity),
              "code[0]: unknown opcode 1005 (primitive fields are 1000-1004)");
    // A forward reference (instruction 0 adding instruction 1) and an instruction using itself:
    // both would be cycles.
    EXPECT_EQ(ErrorOf({0, 2, 0, 1, 1001, 0}, identity),
              "code[2]: instruction 0 uses instruction 0, which is not an earlier one (an "
              "operation may only use earlier instructions: no forward references or cycles)");
    EXPECT_EQ(ErrorOf({1001, 0, 6, 1}, identity),
              "code[3]: instruction 1 uses instruction 1, which is not an earlier one (an "
              "operation may only use earlier instructions: no forward references or cycles)");
    EXPECT_EQ(ErrorOf({1001, 0, 0, 3, 0}, identity),
              "code[3]: operand count 3 must be at least 1 and fit in the code array");
    EXPECT_EQ(ErrorOf({1001}, identity), "code[0]: the code array ends before the float index");
    EXPECT_EQ(ErrorOf({}, identity), "code[0]: the code array is empty");
    EXPECT_EQ(ErrorOf({1003, 1, 0}, {1, 0, 1, 0}, {"ground"}),
              "code[1]: the repelling plane's string index 1 is outside the string array (1 "
              "strings)");
    EXPECT_EQ(ErrorOf({1001, 0}, Matrix(V3f(0), V3f(0))),
              "code[0]: the ellipsoid's matrix is singular");
    EXPECT_EQ(
        ErrorOf({1001, 0}, identity, {},
                {{test::Var("Cs", ParamClass::Vertex, ParamType::Color, 3, {1, 0, 0, 0, 0, 1})}}),
        "vertex variable \"Cs\" needs 1 values, got 2");
}

}  // namespace
}  // namespace gonio
