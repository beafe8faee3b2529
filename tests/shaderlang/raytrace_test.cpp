// The ray-traced built-ins (occlusion, indirectdiffuse, gather, transmission, visibility) and
// the gather loop, against a context whose scene is analytic: the plane z = 1 above the grid
// (P at z = 0, so the plane lies at distance d = 1 along +z), of colour kPlane and opacity 0.25.
// Cosine-distributed rays about +z hit it within "maxdist" D when 1/cos θ <= D, with probability
// sin²θ0 = 1 - 1/D² (Malley's method, pbrt-v3 §13.6.3); the end-to-end checks with the real
// renderer are tests/render/raybuiltins_checks.py.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/shaderlang/sl_test_util.h"

namespace gonio::sl {
namespace {

using testing::Compile;
using testing::Errors;
using testing::Grid;

constexpr float kPlane[3] = {0.8f, 0.4f, 0.2f};

class PlaneContext : public SimpleShadingContext {
  public:
    using SimpleShadingContext::SimpleShadingContext;
    int rays = 0;

    bool TraceSampledRays(const std::string&, const SampledRays& r, SampledHits* h) override {
        const int count = r.count;
        rays += count;
        h->hit.assign(count, 0), h->t.assign(count, 0);
        h->P.assign(3 * size_t(count), 0), h->N.assign(3 * size_t(count), 0);
        h->colour.assign(3 * size_t(count), r.kind == SampledRays::Kind::Transmission ? 1 : 0);
        for (int k = 0; k < count; ++k) {
            const float oz = r.org[2 * count + k], dz = r.dir[2 * count + k];
            const float t = dz > 0 ? (1 - oz) / dz : -1;
            if (!(t > 0 && t <= r.maxdist[k])) continue;
            h->hit[k] = 1, h->t[k] = t;
            for (int c = 0; c < 3; ++c) {
                h->P[size_t(c) * count + k] =
                    r.org[size_t(c) * count + k] + t * r.dir[c * count + k];
                h->N[size_t(c) * count + k] = c == 2 ? -1.f : 0.f;
                float& colour = h->colour[size_t(c) * count + k];
                colour = r.kind == SampledRays::Kind::Transmission ? 0.75f
                         : r.kind == SampledRays::Kind::Shaded     ? kPlane[c]
                                                                   : 0.f;
            }
        }
        return true;
    }
};

struct Result {
    std::vector<float> values;  // width planes of n
    int n = 0;
    std::string diagnostics;
    float At(int c, int p) const { return values[size_t(c) * n + p]; }
};

// Runs `body` (a surface shader's body writing Ci) over an 8 × 8 grid with N = +z.
Result Shade(const std::string& body, bool planeScene = true) {
    test::CapturedDiagnostics d;
    auto shader = Compile("surface t() {\n" + body + "\n}", d);
    Result r;
    if (!shader) {
        r.diagnostics = d.Text();
        return r;
    }
    ShaderInstance instance(shader);
    Grid grid(8, 8);
    r.n = 64;
    for (int i = 0; i < r.n; ++i) grid.N[2 * r.n + i] = 1;
    PlaneContext plane(d.Get());
    SimpleShadingContext none(d.Get());
    SimpleShadingContext& context = planeScene ? plane : none;
    context.BeginBatch(grid.globals, 3);
    ShaderExecutor exec;
    exec.Run(instance, grid.globals, context);
    FloatArg ci = exec.Output("Ci");
    for (int c = 0; c < 3; ++c)
        for (int p = 0; p < r.n; ++p) r.values.push_back(ci.At(c, p));
    r.diagnostics = d.Text();
    return r;
}

// The largest deviation from `want` of component c over the grid.
float Worst(const Result& r, int c, float want) {
    float worst = 0;
    for (int p = 0; p < r.n; ++p) worst = std::max(worst, std::abs(r.At(c, p) - want));
    return worst;
}

// Stratified over 32 × 32 cells, a target bounded in u1 only leaves one column of 32 cells
// straddling its edge: σ <= sqrt(32 / 4) / 1024 = 0.0028 at 1024 samples (plain Monte Carlo:
// up to 0.016). 0.01 is over 3.5σ of the stratified estimate.
constexpr float kStratifiedTolerance = 0.01f;

TEST(RayBuiltins, OcclusionIsTheCosineWeightedFractionWithinMaxdist) {
    Result r = Shade("Ci = occlusion(P, N, 1024, \"maxdist\", 2);");
    ASSERT_EQ(r.diagnostics, "");
    EXPECT_LE(Worst(r, 0, 0.75f), kStratifiedTolerance);
    // Without maxdist the plane covers the whole hemisphere.
    EXPECT_LE(Worst(Shade("Ci = occlusion(P, N, 1024);"), 0, 1.0f), 1e-6f);
}

TEST(RayBuiltins, UniformDistributionAndConeAngle) {
    // Uniform in solid angle: P(cos θ >= 1/D) = 1 - 1/D = 0.5 for D = 2.
    Result u = Shade("Ci = occlusion(P, N, 1024, \"maxdist\", 2, \"distribution\", \"uniform\");");
    EXPECT_LE(Worst(u, 0, 0.5f), kStratifiedTolerance);
    // A cone of π/4: cos θ >= 1/D = 0.8 is sin²θ0 = 0.36 of sin²(π/4) = 0.5, so 0.72.
    Result c = Shade("Ci = occlusion(P, N, 1024, \"maxdist\", 1.25, \"coneangle\", PI / 4);");
    EXPECT_LE(Worst(c, 0, 0.72f), kStratifiedTolerance);
}

TEST(RayBuiltins, StratificationBeatsPlainMonteCarlo) {
    Result r = Shade("Ci = occlusion(P, N, 1024, \"maxdist\", 2);");
    double sum = 0, sum2 = 0;
    for (int p = 0; p < r.n; ++p) sum += r.At(0, p), sum2 += r.At(0, p) * r.At(0, p);
    const double mean = sum / r.n, sigma = std::sqrt(std::max(0.0, sum2 / r.n - mean * mean));
    // The bound above; independent rays would give sqrt(0.75 · 0.25 / 1024) = 0.0135.
    EXPECT_LT(sigma, 0.0028);
    EXPECT_NEAR(mean, 0.75, 3 * 0.0028 / std::sqrt(64.0));
}

TEST(RayBuiltins, IndirectDiffuseIsTheMeanColourOfTheRays) {
    Result r = Shade("Ci = indirectdiffuse(P, N, 1024, \"maxdist\", 2);");
    for (int c = 0; c < 3; ++c) EXPECT_LE(Worst(r, c, 0.75f * kPlane[c]), kStratifiedTolerance);
}

TEST(RayBuiltins, GatherRunsItsBodiesPerSampleWithTheOutputs) {
    // Hits within D = 2: 0.75; their mean length E[1/cos θ | cos θ >= 1/2] = 2(1 - 1/2)/0.75;
    // each hit's surface:Ci is the plane's colour; misses look below 60° from the axis.
    Result r = Shade(R"(
        float hits = 0, misses = 0, len = 0, sum = 0, steep = 0;
        color c = 0, csum = 0;
        vector d = 0;
        gather("illuminance", P, N, PI / 2, 1024, "maxdist", 2, "ray:length", len,
               "surface:Ci", c, "ray:direction", d) {
            hits += 1; sum += len; csum += c;
        } else {
            misses += 1;
            if (zcomp(d) >= 0.5) steep += 1;
        }
        Ci = color(hits / 1024, sum / hits, hits + misses == 1024 && steep == 0 ? comp(csum, 0) / hits : -1);
    )");
    ASSERT_EQ(r.diagnostics, "");
    EXPECT_LE(Worst(r, 0, 0.75f), kStratifiedTolerance);
    EXPECT_LE(Worst(r, 1, 4.0f / 3.0f), 0.01f * 4 / 3);
    EXPECT_LE(Worst(r, 2, kPlane[0]), 1e-5f);
}

TEST(RayBuiltins, BreakLeavesTheGatherLoop) {
    Result r = Shade(R"(
        float n = 0;
        gather("", P, N, PI / 2, 64) { n += 1; if (n >= 10) break; } else { n += 1; if (n >= 10) break; }
        Ci = n;
    )");
    ASSERT_EQ(r.diagnostics, "");
    EXPECT_EQ(Worst(r, 0, 10.0f), 0.0f);
}

TEST(RayBuiltins, TransmissionAndVisibilityAcrossThePlane) {
    Result r = Shade(R"(
        point far = P + vector(0, 0, 2), near = P + vector(0, 0, 0.5);
        Ci = color(visibility(P, far), comp(transmission(P, far), 0), visibility(P, near));
    )");
    ASSERT_EQ(r.diagnostics, "");
    EXPECT_EQ(Worst(r, 0, 0.0f), 0.0f);
    EXPECT_EQ(Worst(r, 1, 0.75f), 0.0f);
    EXPECT_EQ(Worst(r, 2, 1.0f), 0.0f);
}

TEST(RayBuiltins, WithoutASceneTheyGiveZeroWithAWarning) {
    Result r = Shade("Ci = 1 - occlusion(P, N, 16);", false);
    EXPECT_EQ(Worst(r, 0, 1.0f), 0.0f);
    EXPECT_NE(r.diagnostics.find("there is no scene to trace here"), std::string::npos)
        << r.diagnostics;
}

TEST(RayBuiltins, MalformedGathersAndOptionsAreCompileErrors) {
    EXPECT_NE(Errors("surface t() { color c; gather(\"\", P, N, 1, 4, \"surface:Oi\", c) {} }")
                  .find("output \"surface:Oi\" is not supported"),
              std::string::npos);
    EXPECT_NE(Errors("surface t() { gather(\"\", P, N, 1) {} }").find("gather expects"),
              std::string::npos);
    EXPECT_NE(Errors("surface t() { float x = 0; noise(x) { x = 1; } }")
                  .find("cannot be followed by a block"),
              std::string::npos);
    EXPECT_NE(Errors("surface t() { float f; Ci = occlusion(P, N, 4, \"environmentcolor\", f); }")
                  .find("is a color variable it writes"),
              std::string::npos);
    // A shader may still be called gather.
    EXPECT_EQ(Errors("surface gather() { Ci = 1; }"), "");
}

TEST(RayBuiltins, EnvironmentColorIsAnOutput) {
    // No map: the colour is 0 where it is written, and the variable is written.
    Result r = Shade(R"(
        color e = 1;
        float o = occlusion(P, N, 16, "environmentcolor", e);
        Ci = e + o * 0;
    )");
    ASSERT_EQ(r.diagnostics, "");
    EXPECT_EQ(Worst(r, 0, 0.0f), 0.0f);
}

}  // namespace
}  // namespace gonio::sl
