// Where lights are gathered: illuminance(P', ...) runs the light shaders at P' (RISpec §13.3.1),
// the cached lights serve when P' is the surface's P; solar() without an axis is light from all
// directions (§13.3.2); incident() and opposite() find no volume shader (§15.8).

#include <gtest/gtest.h>

#include <cmath>

#include "sl_test_util.h"

namespace gonio::sl {
namespace {

using testing::CapturedDiagnostics;
using testing::Compile;
using testing::Grid;

// A `gonio shade` context that counts how often the lights run away from the surface's P.
class CountingContext : public SimpleShadingContext {
  public:
    using SimpleShadingContext::SimpleShadingContext;
    const std::vector<LightResult>& LightsAt(const float* P, const uint8_t* active) override {
        ++movedCalls;
        return SimpleShadingContext::LightsAt(P, active);
    }
    int movedCalls = 0;
};

struct Lit {
    std::vector<float> values;  // the output's planes over the grid
    int movedCalls = 0;
    std::string diagnostics;
    float At(int component, int point, int n) const {
        return values[size_t(component) * n + point];
    }
};

// Runs `surface` over a w × h grid (P = (u, v, 0), N = (0, 0, -1)) lit by `light`; returns
// the output `name`.
Lit RunLit(const std::string& surface, const std::string& light, int w, int h,
           const std::string& name) {
    CapturedDiagnostics d;
    auto surfaceShader = Compile(surface, d);
    auto lightShader = Compile(light, d);
    Lit result;
    if (!surfaceShader || !lightShader) {
        result.diagnostics = d.Text();
        return result;
    }
    CountingContext context(d.Get());
    context.AddLight(std::make_shared<ShaderInstance>(lightShader));
    ShaderInstance instance(surfaceShader);
    instance.KeepVariables();
    Grid grid(w, h);
    context.BeginBatch(grid.globals, 3);
    ShaderExecutor exec;
    exec.Run(instance, grid.globals, context);
    FloatArg out = exec.Output(name);
    const int n = w * h;
    for (int c = 0; c < out.width; ++c)
        for (int i = 0; i < n; ++i) result.values.push_back(out.At(c, i));
    result.movedCalls = context.movedCalls;
    result.diagnostics = d.Text();
    return result;
}

const char* kPointLight = R"(light pt(point from = (0, 0, -2);) {
    illuminate (from) { Cl = 1 / (L . L); }
})";

// 1/d² from the light at (0, 0, -2) to (x, y, z).
float Falloff(float x, float y, float z) { return 1 / (x * x + y * y + (z + 2) * (z + 2)); }

TEST(LightPosition, IlluminanceAtAnOffsetPositionSeesTheLightFromThere) {
    // The left column gathers 1 unit further from the light, the right column at P itself.
    auto r = RunLit(R"(surface s() {
        vector offset = u < 0.5 ? vector(0, 0, 1) : vector(0);
        color sum = 0;
        illuminance (P + offset) { sum += Cl; }
        Ci = sum;
    })",
                    kPointLight, 2, 2, "Ci");
    ASSERT_EQ(r.values.size(), 12u) << r.diagnostics;
    EXPECT_EQ(r.movedCalls, 1);
    for (int i = 0; i < 4; ++i) {
        const float x = (i % 2 + 0.5f) / 2, y = (i / 2 + 0.5f) / 2;
        const float z = x < 0.5f ? 1.0f : 0.0f;
        EXPECT_NEAR(r.At(0, i, 4), Falloff(x, y, z), 1e-6f) << "point " << i;
    }
}

TEST(LightPosition, LIsMeasuredFromTheGivenPosition) {
    auto r = RunLit(R"(surface s() {
        vector Lseen = 0;
        illuminance (point(0, 0, 3)) { Lseen = L; }
        Ci = color(xcomp(Lseen), ycomp(Lseen), zcomp(Lseen));
    })",
                    kPointLight, 1, 1, "Ci");
    ASSERT_EQ(r.values.size(), 3u) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 0, 1), 0);
    EXPECT_FLOAT_EQ(r.At(1, 0, 1), 0);
    EXPECT_FLOAT_EQ(r.At(2, 0, 1), -5);  // from (0, 0, 3) to the light at (0, 0, -2)
}

TEST(LightPosition, TheSurfacePointUsesTheCachedLights) {
    // P itself, and a position equal to P at every point: no second run of the lights.
    auto r = RunLit(R"(surface s() {
        color a = 0, b = 0;
        illuminance (P, N, PI / 2) { a += Cl; }
        illuminance (P + vector(0)) { b += Cl; }
        Ci = a + b + diffuse(N);
    })",
                    kPointLight, 2, 1, "Ci");
    ASSERT_EQ(r.values.size(), 6u) << r.diagnostics;
    EXPECT_EQ(r.movedCalls, 0);
    const float d2 = 1 / Falloff(0.25f, 0.5f, 0);
    EXPECT_NEAR(r.At(0, 0, 2), 2 / d2 + 2 / d2 / std::sqrt(d2), 1e-6f);
}

const char* kSkyLight = R"(light sky() { solar () { Cl = 0.5; } })";
// Ci = the L that illuminance (P) without an axis sees.
const char* kShowL = R"(surface s() {
    vector Lseen = 0;
    illuminance (P) { Lseen = L; }
    Ci = color(xcomp(Lseen), ycomp(Lseen), zcomp(Lseen));
})";

TEST(LightPosition, SolarWithoutAxisCountsFullyAlongTheIlluminanceAxis) {
    auto r = RunLit(R"(surface s() {
        vector axis = vector(1, 2, 2);
        color sum = 0;
        vector Lseen = 0;
        illuminance (P, axis, 0.01) { sum += Cl * (normalize(L) . normalize(axis)); Lseen = L; }
        Ci = sum;
        Oi = color(xcomp(Lseen), ycomp(Lseen), zcomp(Lseen));
    })",
                    kSkyLight, 1, 1, "Ci");
    ASSERT_EQ(r.values.size(), 3u) << r.diagnostics;
    EXPECT_NEAR(r.At(0, 0, 1), 0.5f, 1e-6f);
}

TEST(LightPosition, SolarWithoutAxisArrivesAlongNWithoutAnAxis) {
    auto r = RunLit(kShowL, kSkyLight, 1, 1, "Ci");
    ASSERT_EQ(r.values.size(), 3u) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 0, 1), 0);
    EXPECT_FLOAT_EQ(r.At(1, 0, 1), 0);
    EXPECT_FLOAT_EQ(r.At(2, 0, 1), -1);  // the grid's N
}

TEST(LightPosition, SolarWithoutAxisLightsDiffuseAndSpecularFully) {
    // Facing either way: diffuse(N) and diffuse(-N) both get Cl, as N·L = 1 for each.
    auto r = RunLit(R"(surface s() {
        Ci = diffuse(N) + diffuse(-N);
        Oi = specular(N, -I, 0.1);
    })",
                    kSkyLight, 1, 1, "Ci");
    ASSERT_EQ(r.values.size(), 3u) << r.diagnostics;
    EXPECT_NEAR(r.At(0, 0, 1), 1.0f, 1e-6f);
}

TEST(LightPosition, SolarWithAnAxisKeepsItsDirection) {
    auto r =
        RunLit(kShowL, R"(light sun() { solar (vector(0, 1, 0), 0) { Cl = 1; } })", 1, 1, "Ci");
    ASSERT_EQ(r.values.size(), 3u) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(1, 0, 1), -1);  // towards the light: against the axis
}

TEST(VolumeMessages, IncidentAndOppositeFindNoShaderAndLeaveTheOutput) {
    auto r = testing::Shade(R"(surface s() {
        float f = 7;
        color c = color(1, 2, 3);
        float found = incident("density", f) + opposite("Cs", c) + incident("x", c);
        Ci = color(found, f, comp(c, 2));
    })",
                            1, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(r.At(0, 0), 0);
    EXPECT_EQ(r.At(1, 0), 7);
    EXPECT_EQ(r.At(2, 0), 3);
}

TEST(VolumeMessages, IncidentAndOppositeTakeANameAndAnOutput) {
    EXPECT_NE(testing::Errors("surface s() { float f = 0; float r = incident(1, f); }"), "");
    EXPECT_NE(testing::Errors("surface s() { float r = opposite(\"x\"); }"), "");
    EXPECT_EQ(testing::Errors("surface s() { matrix m = 1; float r = opposite(\"x\", m); }"), "");
}

}  // namespace
}  // namespace gonio::sl
