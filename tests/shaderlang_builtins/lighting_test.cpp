// Lighting built-ins over a fake context's lights: ambient, diffuse (N·L, hemisphere cone),
// specular (8/roughness), specularbrdf, phong, trace; masks respected.

#include <cmath>

#include "builtin_test_util.h"
#include "shaderlang/runtime/builtins_lighting.h"

namespace gonio::sl::testing {
namespace {

using V3 = Imath::V3f;

// A light whose L (surface to light) and colour are the same at all n points.
LightResult MakeLight(int n, const V3& L, float intensity, bool ambient = false) {
    LightResult light;
    light.L.resize(3 * n);
    light.Cl.resize(3 * n);
    light.Ol.assign(3 * n, 1.0f);
    light.lit.assign(n, 1);
    light.ambient = ambient;
    for (int p = 0; p < n; ++p) {
        for (int c = 0; c < 3; ++c) {
            light.L[c * n + p] = L[c];
            light.Cl[c * n + p] = intensity * (c + 1);
        }
    }
    return light;
}

TEST(LightingBuiltins, AmbientSumsAmbientLightsOnly) {
    FakeContext context(2);
    context.lights = {MakeLight(2, V3(0, 0, 1), 0.1f, true), MakeLight(2, V3(0, 0, 1), 5),
                      MakeLight(2, V3(0, 0, 1), 0.2f, true)};
    TestCall call(2);
    call.Mask({0, 1}).Result(TypeFromCode("c"), true).Context(&context);
    call.Run(FindKernel("ambient", "c", ""));
    EXPECT_NEAR(call.R(0, 1), 0.3f, 1e-6f);
    EXPECT_NEAR(call.R(2, 1), 0.9f, 1e-6f);
    EXPECT_EQ(call.R(0, 0), kSentinel);
}

TEST(LightingBuiltins, DiffuseIsClTimesCosineInTheHemisphere) {
    const int n = 4;
    FakeContext context(n);
    // A light at 60° from N (unnormalised L), one behind the surface, one unlit at point 3.
    LightResult tilted = MakeLight(n, V3(std::sqrt(3.0f), 0, 1) * 4, 1);
    tilted.lit[3] = 0;
    context.lights = {tilted, MakeLight(n, V3(0, 0, -1), 1), MakeLight(n, V3(0, 0, 1), 0, true)};
    TestCall call(n);
    call.Uniform(TypeFromCode("n"), {0, 0, 1}).Result(TypeFromCode("c"), true).Context(&context);
    call.Run(FindKernel("diffuse", "c", "n"));
    for (int p = 0; p < 3; ++p) {
        EXPECT_NEAR(call.R(0, p), 0.5f, 1e-6f);  // cos 60°, Cl = 1
        EXPECT_NEAR(call.R(2, p), 1.5f, 1e-6f);  // Cl blue = 3
    }
    EXPECT_EQ(call.R(0, 3), 0.0f);
}

TEST(LightingBuiltins, SpecularUsesEightOverRoughness) {
    const int n = 3;
    FakeContext context(n);
    V3 lightDir = V3(1, 0, 1).normalized();
    context.lights = {MakeLight(n, lightDir, 1)};
    // Viewer at the mirror direction: H = N, full highlight; elsewhere (N·H)^(8/r).
    std::vector<std::vector<float>> views = {{-lightDir.x, 0, lightDir.z}, {0, 0, 1}, {0, 1, 0}};
    TestCall call(n);
    call.Uniform(TypeFromCode("n"), {0, 0, 1}).Varying(TypeFromCode("v"), views).Float(0.1f);
    call.Result(TypeFromCode("c"), true).Context(&context);
    call.Run(FindKernel("specular", "c", "nvf"));
    EXPECT_NEAR(call.R(0, 0), 1.0f, 1e-5f);
    for (int p = 1; p < n; ++p) {
        V3 h = (lightDir + V3(views[p][0], views[p][1], views[p][2])).normalized();
        EXPECT_NEAR(call.R(0, p), std::pow(std::max(0.0f, h.z), 80.0f), 1e-6f);
    }
    EXPECT_EQ(gonio::sl::builtins::kSpecularExponentScale, 8.0f);

    TestCall brdf(1);
    brdf.Uniform(TypeFromCode("v"), {0, 0, 2}).Uniform(TypeFromCode("n"), {0, 0, 1});
    brdf.Uniform(TypeFromCode("v"), {0, std::sin(0.2f), std::cos(0.2f)}).Float(0.5f);
    brdf.Result(TypeFromCode("c"), false);
    brdf.Run(FindKernel("specularbrdf", "c", "vnvf"));
    EXPECT_NEAR(brdf.R(1), std::pow(std::cos(0.1f), 16.0f), 1e-5f);
}

TEST(LightingBuiltins, PhongPeaksAtTheMirrorDirection) {
    FakeContext context(2);
    V3 l = V3(0, 1, 1).normalized();
    context.lights = {MakeLight(2, l, 1)};
    TestCall call(2);
    call.Uniform(TypeFromCode("n"), {0, 0, 1})
        .Varying(TypeFromCode("v"), {{0, -1, 1}, {0, 0, 1}})
        .Float(10)
        .Result(TypeFromCode("c"), true)
        .Context(&context);
    call.Run(FindKernel("phong", "c", "nvf"));
    EXPECT_NEAR(call.R(0, 0), 1.0f, 1e-5f);
    EXPECT_NEAR(call.R(0, 1), std::pow(std::cos(float(M_PI / 4)), 10.0f), 1e-5f);
}

TEST(LightingBuiltins, TraceAsksTheRendererForActivePoints) {
    FakeContext context(2);
    TestCall call(2);
    call.Uniform(TypeFromCode("p"), {1, 2, 3}).Varying(TypeFromCode("v"), {{1, 0, 0}, {0, 1, 0}});
    call.Mask({1, 0}).Result(TypeFromCode("c"), true).Context(&context);
    call.Run(FindKernel("trace", "c", "pv"));
    EXPECT_EQ(call.R(0, 0), 2.0f);
    EXPECT_EQ(call.R(1, 0), 2.0f);
    EXPECT_EQ(call.R(0, 1), kSentinel);
}

}  // namespace
}  // namespace gonio::sl::testing
