// What the peer compilers (Pixie's sdrc, Aqsis's aqsl) accept beyond RISpec 3.2, and what it
// computes here (docs/shading-language.md, "Beyond RISpec"): unsized array formals and
// arraylength(), colours and point-likes converting to each other, Ns in light shaders, P
// written by a surface shader, and macro calls over several lines.

#include <gtest/gtest.h>

#include "sl_test_util.h"

namespace gonio::sl {
namespace {

using testing::CapturedDiagnostics;
using testing::Compile;
using testing::Errors;
using testing::Grid;
using testing::Shade;

TEST(PeerCompat, UnsizedArrayParameterTakesItsDefaultsLength) {
    auto r =
        Shade("surface a(float k[] = {1, 2, 5}) { Ci = arraylength(k) * 10 + k[2]; }", 1, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 0), 35.0f);
    CapturedDiagnostics d;
    auto shader = Compile("surface a(color c[] = {1, 0.5}) { Ci = c[1]; }", d);
    ASSERT_TRUE(shader) << d.Text();
    const auto& params = shader->Params();
    ASSERT_EQ(params.size(), 1u);
    EXPECT_EQ(params[0].type.arrayLength, 2);
}

TEST(PeerCompat, UnsizedArrayParameterNeedsAListDefault) {
    std::string e = Errors("surface a(float k[] = 1) { Ci = k[0]; }\n");
    EXPECT_NE(e.find("test.sl:1:17: error: unsized array parameter 'k' needs a {...} default"),
              std::string::npos)
        << e;
    e = Errors("surface a() { float x = 1; Ci = arraylength(x); }\n");
    EXPECT_NE(e.find("error: arraylength() takes one array, not (float)"), std::string::npos) << e;
}

// A function's `float a[]` takes each call's array, whatever its length; arraylength() in the
// body is that argument's.
TEST(PeerCompat, UnsizedFunctionFormalTakesEachArgumentsLength) {
    auto r = Shade(R"(
        float total(float a[]) {
            float sum = 0, i;
            for (i = 0; i < arraylength(a); i += 1) sum += a[i];
            return sum;
        }
        float count(float a[]) { return arraylength(a); }
        surface t() {
            float x[3] = {1, 2, 3};
            float y[2] = {10, 20 * u};
            Ci = color(total(x), total(y), count(y) * 100 + count(x));
        })",
                   2, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    for (int i = 0; i < 2; ++i) {
        const float u = (i + 0.5f) / 2;
        EXPECT_FLOAT_EQ(r.At(0, i), 6.0f);
        EXPECT_FLOAT_EQ(r.At(1, i), 10 + 20 * u);
        EXPECT_FLOAT_EQ(r.At(2, i), 203.0f);
    }
    std::string e = Errors("float f(float a[]) { return a[0]; } surface t() { Ci = f(u); }\n");
    EXPECT_NE(e.find("error: no version of function 'f' takes (float)"), std::string::npos) << e;
}

// color(N), color c = P, point p = Cs and passing a point for a colour copy the 3 components.
TEST(PeerCompat, ColoursAndPointLikesConvertComponentByComponent) {
    auto r = Shade(R"(
        float red(color c) { return comp(c, 0); }
        surface t() {
            color c = P;
            point p = color(1, 2, 3);
            Ci = color(N) + c * 10 + color(red(P + vector(100, 0, 0)), 0, comp(color(p), 2));
        })",
                   2, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    for (int i = 0; i < 2; ++i) {
        const float u = (i + 0.5f) / 2, v = 0.5f;
        EXPECT_FLOAT_EQ(r.At(0, i), 0 + 10 * u + (u + 100)) << i;
        EXPECT_FLOAT_EQ(r.At(1, i), 0 + 10 * v) << i;
        EXPECT_FLOAT_EQ(r.At(2, i), -1 + 0 + 3) << i;
    }
}

// Where colours are not triples (ColorSamples) the conversion has no meaning: an error.
TEST(PeerCompat, ColourPointConversionNeedsThreeComponents) {
    CapturedDiagnostics d;
    auto shader = Compile("surface t() {\n  color c = P;\n  Ci = color(N);\n}\n", d, 5);
    EXPECT_FALSE(shader);
    const std::string e = d.Text();
    EXPECT_NE(e.find("test.sl:2:13: error: cannot convert point to color: colors have 5 "
                     "components here (ColorSamples), not 3"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("test.sl:3:8: error: cannot convert normal to color"), std::string::npos) << e;
    // Arithmetic still keeps them apart (neither peer gives a colour + point one meaning).
    EXPECT_NE(Errors("surface t() { Ci = Cs + P; }").find("cannot apply '+' to color and point"),
              std::string::npos);
}

// In a light shader Ns is the normal of the surface point being lit.
TEST(PeerCompat, NsInALightShaderIsTheSurfaceNormal) {
    CapturedDiagnostics d;
    auto surface = Compile("surface s() { Ci = 0; illuminance (P) { Ci += Cl; } }", d);
    auto light = Compile(
        "light b() { illuminate (P, Ns, PI) { Cl = color(xcomp(Ns), ycomp(Ns), zcomp(Ns)); } }", d);
    ASSERT_TRUE(surface && light) << d.Text();
    SimpleShadingContext context(d.Get());
    context.AddLight(std::make_shared<ShaderInstance>(light));
    ShaderInstance instance(surface);
    Grid grid(3, 1);
    const int n = 3;
    for (int i = 0; i < n; ++i)  // a normal of its own at each point
        grid.N[i] = 0.1f * (i + 1), grid.N[n + i] = -0.2f * i, grid.N[2 * n + i] = -1;
    context.BeginBatch(grid.globals, 3);
    ShaderExecutor exec;
    exec.Run(instance, grid.globals, context);
    FloatArg Ci = exec.Output("Ci");
    ASSERT_TRUE(Ci.data) << d.Text();
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(Ci.At(c, i), grid.N[c * n + i]) << i << c;
    EXPECT_NE(
        Errors("surface s() { Ci = color(Ns); }").find("'Ns' is not available in surface shaders"),
        std::string::npos);
}

// A surface shader that writes P (Pixie's displacement inside a surface shader) sees the new P
// from then on, and its lights are gathered there.
TEST(PeerCompat, SurfaceShaderWritesP) {
    CapturedDiagnostics d;
    auto surface = Compile(R"(surface s() {
        P += N * 1.5;
        color lit = 0;
        illuminance (P) { lit += Cl; }
        Ci = lit;
        Oi = color(P);
    })",
                           d);
    auto light = Compile("light pt() { illuminate (point(0, 0, -2)) { Cl = 1 / (L . L); } }", d);
    ASSERT_TRUE(surface && light) << d.Text();
    SimpleShadingContext context(d.Get());
    context.AddLight(std::make_shared<ShaderInstance>(light));
    ShaderInstance instance(surface);
    Grid grid(2, 1);
    context.BeginBatch(grid.globals, 3);
    ShaderExecutor exec;
    exec.Run(instance, grid.globals, context);
    FloatArg Ci = exec.Output("Ci"), Oi = exec.Output("Oi");
    ASSERT_TRUE(Ci.data && Oi.data) << d.Text();
    for (int i = 0; i < 2; ++i) {
        const float u = (i + 0.5f) / 2, v = 0.5f, z = -1.5f;  // P = (u, v, 0) + (0, 0, -1.5)
        EXPECT_FLOAT_EQ(Oi.At(2, i), z);
        EXPECT_FLOAT_EQ(Ci.At(0, i), 1 / (u * u + v * v + (z + 2) * (z + 2))) << i;
    }
    EXPECT_NE(Errors("light l() { P = 0; }")
                  .find("cannot assign to 'P': it is read-only in "
                        "light shaders"),
              std::string::npos);
}

// Area lights normalise their sample point's N in place, as Pixie's arealight.sl does.
TEST(PeerCompat, LightShaderWritesN) {
    CapturedDiagnostics d;
    EXPECT_TRUE(Compile("light a() { N = normalize(N); illuminate (P, N, PI / 2) { Cl = 1; } }", d))
        << d.Text();
}

TEST(PeerCompat, ImagerReadsST) {
    CapturedDiagnostics d;
    EXPECT_TRUE(Compile("imager i() { Ci *= color(s, t, 1); }", d)) << d.Text();
}

// A call of a function-like macro may spread its arguments over lines, as in C; the lines
// after it keep their numbers.
TEST(PeerCompat, MacroCallOverSeveralLines) {
    auto r =
        Shade("#define ADD(a, b) ((a) + (b))\nsurface t() {\n  Ci = ADD(1,\n   ADD(u,\n 2));\n}\n",
              2, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 1), 3.75f);
    std::string e =
        Errors("#define ADD(a, b) ((a) + (b))\nsurface t() {\n  Ci = ADD(1,\n 2);\n  Ci = x;\n}\n");
    EXPECT_NE(e.find("test.sl:5:8: error: unknown variable 'x'"), std::string::npos) << e;
    e = Errors("#define ADD(a, b) ((a) + (b))\nsurface t() {\n  Ci = ADD(1,\n");
    EXPECT_NE(e.find("test.sl:3:8: error: unterminated call of macro 'ADD'"), std::string::npos)
        << e;
}

}  // namespace
}  // namespace gonio::sl
