// Geometric built-ins: components, lengths, ptlined, rotate, faceforward, reflect, refract,
// fresnel energy, depth, and the space transforms with a fake ShadingContext.

#include <Imath/ImathMatrix.h>

#include <cmath>

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

using V3 = Imath::V3f;
using Values = std::vector<std::vector<float>>;

std::vector<float> Vec(const V3& v) { return {v.x, v.y, v.z}; }
V3 AsV3(const std::vector<float>& v) { return V3(v[0], v[1], v[2]); }

const Values kA = {{1, 2, 3}, {-1, 0.5f, 2}, {0, 0, 1}, {3, -4, 0}, {0.2f, 0.1f, -0.7f}};
const Values kB = {{0, 1, 0}, {2, 2, 2}, {1, 0, 0}, {0, 0, -1}, {-0.3f, 0.5f, 0.2f}};

TEST(GeometricBuiltins, ComponentsAndLengths) {
    for (int axis = 0; axis < 3; ++axis) {
        const char* names[] = {"xcomp", "ycomp", "zcomp"};
        ExpectAllVariants(names[axis], "f", "p", {kA},
                          [axis](const PointArgs& a) { return std::vector<float>{a[0][axis]}; });
    }
    ExpectAllVariants("length", "f", "v", {kA},
                      [](const PointArgs& a) { return std::vector<float>{AsV3(a[0]).length()}; });
    ExpectAllVariants("normalize", "v", "v", {kA},
                      [](const PointArgs& a) { return Vec(AsV3(a[0]).normalized()); });
    ExpectAllVariants("distance", "f", "pp", {kA, kB}, [](const PointArgs& a) {
        return std::vector<float>{(AsV3(a[0]) - AsV3(a[1])).length()};
    });
    TestCall set(2);
    set.Varying(TypeFromCode("P"), {{1, 2, 3}, {4, 5, 6}}).Float(9).Mask({1, 0});
    set.Run(FindKernel("setycomp", "x", "Pf"));
    EXPECT_EQ(set.Arg(0, 1, 0), 9.0f);
    EXPECT_EQ(set.Arg(0, 1, 1), 5.0f);  // masked: unchanged
}

TEST(GeometricBuiltins, PtlinedMeasuresToTheSegment) {
    // Segment from (0,0,0) to (2,0,0).
    const Values p0(4, {0, 0, 0}), p1(4, {2, 0, 0});
    const Values q = {{1, 3, 0}, {-3, 4, 0}, {5, 0, 4}, {0.5f, 0, 0}};
    const std::vector<float> expected = {3, 5, 5, 0};
    ExpectAllVariants("ptlined", "f", "ppp", {p0, p1, q}, [&](const PointArgs& a) {
        V3 x = AsV3(a[2]);
        float t = std::clamp(x.x / 2.0f, 0.0f, 1.0f);
        return std::vector<float>{(x - V3(2 * t, 0, 0)).length()};
    });
    TestCall call(1);
    call.Uniform(TypeFromCode("p"), {0, 0, 0}).Uniform(TypeFromCode("p"), {2, 0, 0});
    call.Uniform(TypeFromCode("p"), {-3, 4, 0}).Result(TypeFromCode("f"), false);
    call.Run(FindKernel("ptlined", "f", "ppp"));
    EXPECT_FLOAT_EQ(call.R(0), 5.0f);
}

TEST(GeometricBuiltins, RotateAboutAnAxis) {
    // A quarter turn about the z axis through (1,0,0) takes (2,0,5) to (1,1,5).
    TestCall call(1);
    call.Uniform(TypeFromCode("p"), {2, 0, 5}).Float(static_cast<float>(M_PI / 2));
    call.Uniform(TypeFromCode("p"), {1, 0, 0}).Uniform(TypeFromCode("p"), {1, 0, 1});
    call.Result(TypeFromCode("p"), false);
    call.Run(FindKernel("rotate", "p", "pfpp"));
    EXPECT_NEAR(call.R(0), 1.0f, 1e-6f);
    EXPECT_NEAR(call.R(1), 1.0f, 1e-6f);
    EXPECT_NEAR(call.R(2), 5.0f, 1e-6f);
}

TEST(GeometricBuiltins, FaceforwardReflectRefract) {
    const Values n(5, {0, 0, 1});
    const Values i = {{0, 0, -1}, {0, 0, 1}, {1, 0, -1}, {1, 0, 1}, {0.3f, 0.4f, -0.5f}};
    ExpectAllVariants("faceforward", "n", "nvn", {n, i, n}, [](const PointArgs& a) {
        V3 nn = AsV3(a[0]);
        return Vec(AsV3(a[1]).dot(AsV3(a[2])) > 0 ? -nn : nn);
    });
    ExpectAllVariants("reflect", "v", "vn", {i, n}, [](const PointArgs& a) {
        V3 in = AsV3(a[0]), nn = AsV3(a[1]);
        return Vec(in - 2 * in.dot(nn) * nn);
    });
    // Two-argument faceforward takes Nref = Ng from the globals.
    FakeGlobals globals(2);
    globals.SetVarying("Ng", 3, {0, 0, 0, 0, 1, -1});
    TestCall two(2);
    two.Uniform(TypeFromCode("n"), {0, 0, 1}).Uniform(TypeFromCode("v"), {0, 0, -1});
    two.Result(TypeFromCode("n"), true).Globals(&globals);
    two.Run(FindKernel("faceforward", "n", "nv"));
    EXPECT_EQ(two.R(2, 0), 1.0f);   // Ng faces the viewer: N kept
    EXPECT_EQ(two.R(2, 1), -1.0f);  // Ng faces away: N flipped

    // Snell's law: sin θt = eta sin θi; total internal reflection gives 0.
    const float eta = 1.0f / 1.5f;
    V3 in = V3(std::sin(0.6f), 0, -std::cos(0.6f));
    TestCall refract(1);
    refract.Uniform(TypeFromCode("v"), Vec(in)).Uniform(TypeFromCode("n"), {0, 0, 1}).Float(eta);
    refract.Result(TypeFromCode("v"), false);
    refract.Run(FindKernel("refract", "v", "vnf"));
    V3 t(refract.R(0), refract.R(1), refract.R(2));
    EXPECT_NEAR(t.length(), 1.0f, 1e-5f);
    EXPECT_NEAR(t.x, eta * std::sin(0.6f), 1e-5f);
    EXPECT_LT(t.z, 0.0f);
    TestCall tir(1);
    tir.Uniform(TypeFromCode("v"), Vec(V3(0.9f, 0, -std::sqrt(1 - 0.81f))));
    tir.Uniform(TypeFromCode("n"), {0, 0, 1}).Float(1.5f).Result(TypeFromCode("v"), false);
    tir.Run(FindKernel("refract", "v", "vnf"));
    EXPECT_EQ(V3(tir.R(0), tir.R(1), tir.R(2)), V3(0.0f));
}

TEST(GeometricBuiltins, FresnelConservesEnergy) {
    const int n = 90;
    Values in(n), normal(n, {0, 0, 1});
    for (int k = 0; k < n; ++k) {
        float theta = k * (1.55f / n);
        in[k] = {std::sin(theta), 0, -std::cos(theta)};
    }
    for (float eta : {1.0f / 1.5f, 1.5f, 1.0f / 1.33f}) {
        TestCall call(n);
        call.Varying(TypeFromCode("v"), in).Varying(TypeFromCode("n"), normal).Float(eta);
        call.Varying(TypeFromCode("F"), Values(n, {0})).Varying(TypeFromCode("F"), Values(n, {0}));
        call.Varying(TypeFromCode("V"), Values(n, {0, 0, 0}));
        call.Varying(TypeFromCode("V"), Values(n, {0, 0, 0}));
        call.Run(FindKernel("fresnel", "x", "vnfFFVV"));
        for (int k = 0; k < n; ++k) {
            float kr = call.Arg(3, 0, k), kt = call.Arg(4, 0, k);
            EXPECT_NEAR(kr + kt, 1.0f, 1e-6f);
            EXPECT_GE(kr, 0.0f);
            EXPECT_LE(kr, 1.0f);
            EXPECT_NEAR(call.Arg(5, 2, k), -in[k][2], 1e-5f);  // R mirrors I
        }
        // Normal incidence: ((m-1)/(m+1))², the same either way round (0.04 for glass).
        float m = 1.0f / eta;
        EXPECT_NEAR(call.Arg(3, 0, 0), std::pow((m - 1) / (m + 1), 2.0f), 1e-5f);
        if (eta > 1.0f) {
            EXPECT_EQ(call.Arg(3, 0, n - 1), 1.0f);  // total internal reflection
        }
    }
    // Brewster's angle (glass, from air): the p-polarised part vanishes, Kr = Rs/2.
    float brewster = std::atan(1.5f);
    TestCall call(1);
    call.Uniform(TypeFromCode("v"), {std::sin(brewster), 0, -std::cos(brewster)});
    call.Uniform(TypeFromCode("n"), {0, 0, 1}).Float(1 / 1.5f);
    call.Uniform(TypeFromCode("F"), {0}).Uniform(TypeFromCode("F"), {0});
    call.Run(FindKernel("fresnel", "x", "vnfFF"));
    float ci = std::cos(brewster), ct = std::sqrt(1 - std::pow(std::sin(brewster) / 1.5f, 2));
    float rs = std::pow((ci - 1.5f * ct) / (ci + 1.5f * ct), 2);
    EXPECT_NEAR(call.Arg(3, 0), 0.5f * rs, 1e-5f);
}

TEST(GeometricBuiltins, DepthUsesTheClippingPlanes) {
    FakeContext context(3);
    context.floatInfo["Clipping"] = {1, 11};
    TestCall call(3);
    call.Varying(TypeFromCode("p"), {{0, 0, 1}, {5, 5, 6}, {0, 0, 11}});
    call.Result(TypeFromCode("f"), true).Context(&context);
    call.Run(FindKernel("depth", "f", "p"));
    EXPECT_FLOAT_EQ(call.R(0, 0), 0.0f);
    EXPECT_FLOAT_EQ(call.R(0, 1), 0.5f);
    EXPECT_FLOAT_EQ(call.R(0, 2), 1.0f);
}

TEST(GeometricBuiltins, TransformsBetweenNamedSpaces) {
    // "world" is translated by (10, 0, 0) and scaled by 2 along y relative to "current".
    FakeContext context(5);
    Imath::M44f currentFromWorld;
    currentFromWorld.setScale(V3(1, 2, 1));
    currentFromWorld = currentFromWorld * Imath::M44f().setTranslation(V3(10, 0, 0));
    context.currentFromSpace["world"] = currentFromWorld;
    Imath::M44f currentFromObject;
    currentFromObject.setTranslation(V3(0, 0, 5));
    context.currentFromSpace["object"] = currentFromObject;
    auto run = [&](const std::string& name, const std::string& ret, const std::string& args,
                   const std::vector<std::string>& spaces, const std::vector<float>& x,
                   const Imath::M44f& matrix = Imath::M44f()) {
        TestCall call(1);
        size_t s = 0;
        for (char code : args.substr(0, args.size() - 1)) {
            if (code == 's')
                call.String(spaces[s++]);
            else
                call.Uniform(TypeFromCode("m"), std::vector<float>(matrix[0], matrix[0] + 16));
        }
        call.Uniform(TypeFromCode(ret), x).Result(TypeFromCode(ret), false).Context(&context);
        call.Run(FindKernel(name, ret, args));
        return V3(call.R(0), call.R(1), call.R(2));
    };
    // current -> world: invert (scale then translate).
    EXPECT_EQ(run("transform", "p", "sp", {"world"}, {12, 4, 1}), V3(2, 2, 1));
    EXPECT_EQ(run("transform", "p", "ssp", {"world", "current"}, {2, 2, 1}), V3(12, 4, 1));
    EXPECT_EQ(run("transform", "p", "ssp", {"object", "world"}, {0, 0, 0}), V3(-10, 0, 5));
    // Vectors ignore translation.
    EXPECT_EQ(run("vtransform", "v", "ssv", {"world", "current"}, {1, 1, 1}), V3(1, 2, 1));
    // Normals use the inverse transpose: the normal of the plane y = x stays perpendicular.
    V3 normal = run("ntransform", "n", "ssn", {"world", "current"}, {1, -1, 0});
    V3 tangent = run("vtransform", "v", "ssv", {"world", "current"}, {1, 1, 0});
    EXPECT_NEAR(normal.dot(tangent), 0.0f, 1e-6f);
    // Matrix forms.
    Imath::M44f m;
    m.setTranslation(V3(1, 2, 3));
    EXPECT_EQ(run("transform", "p", "mp", {}, {1, 1, 1}, m), V3(2, 3, 4));
    EXPECT_EQ(run("transform", "p", "smp", {"object"}, {0, 0, 0}, m), V3(1, 2, 8));
    // An unknown space warns and leaves the point alone.
    EXPECT_EQ(run("transform", "p", "sp", {"nowhere"}, {1, 2, 3}), V3(1, 2, 3));
    EXPECT_EQ(context.warnings.count("space:nowhere"), 1u);
}

TEST(GeometricBuiltins, TransformVariantsAndMasks) {
    FakeContext context(5);
    Imath::M44f world;
    world.setTranslation(V3(1, 0, 0));
    context.currentFromSpace["world"] = world;
    BuiltinKernel kernel = FindKernel("transform", "p", "ssp");
    TestCall call(5);
    call.String("world").String("current").Varying(TypeFromCode("p"), kA);
    call.Mask({1, 1, 0, 1, 0}).Result(TypeFromCode("p"), true).Context(&context);
    call.Run(kernel);
    for (int p = 0; p < 5; ++p) {
        if (p == 2 || p == 4) {
            EXPECT_EQ(call.R(0, p), kSentinel);
        } else {
            EXPECT_FLOAT_EQ(call.R(0, p), kA[p][0] + 1);
        }
    }
}

}  // namespace
}  // namespace gonio::sl::testing
