// Execution: expressions, assignments, masks of divergent control flow, user functions.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sl_test_util.h"

namespace gonio::sl {
namespace {

using testing::Shade;

TEST(ShadeExec, ArithmeticOverTheGrid) {
    auto r = Shade("surface t(float Kd = 0.5;) { Ci = color(u, v, 0.5) * Kd + 1; }", 2, 2, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 0), 0.25f * 0.5f + 1);
    EXPECT_FLOAT_EQ(r.At(0, 1), 0.75f * 0.5f + 1);
    EXPECT_FLOAT_EQ(r.At(1, 2), 0.75f * 0.5f + 1);
    EXPECT_FLOAT_EQ(r.At(2, 3), 1.25f);
}

}  // namespace
}  // namespace gonio::sl

namespace gonio::sl {
namespace {

using testing::Shade;

// u over a 4x1 grid: 0.125, 0.375, 0.625, 0.875.
TEST(ShadeExec, DivergentIfElse) {
    auto r = Shade(R"(surface t() {
        float x = 0;
        if (u < 0.5) x = 1; else x = 2;
        Ci = x;
    })",
                   4, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(r.At(0, 0), 1);
    EXPECT_EQ(r.At(0, 1), 1);
    EXPECT_EQ(r.At(0, 2), 2);
    EXPECT_EQ(r.At(0, 3), 2);
}

TEST(ShadeExec, DivergentWhileRunsEachPointItsOwnCount) {
    auto r = Shade(R"(surface t() {
        float i = 0, count = 0;
        while (i < u * 8) { count += 1; i += 1; }
        Ci = count;
    })",
                   4, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(r.At(0, 0), 1);  // u*8 = 1
    EXPECT_EQ(r.At(0, 1), 3);
    EXPECT_EQ(r.At(0, 2), 5);
    EXPECT_EQ(r.At(0, 3), 7);
}

TEST(ShadeExec, BreakAndContinueWithMasks) {
    auto r = Shade(R"(surface t() {
        float i, sum = 0;
        for (i = 0; i < 10; i += 1) {
            if (i == 2) continue;
            if (i > u * 8) break;
            sum += i;
        }
        Ci = sum;
    })",
                   4, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(r.At(0, 0), 0 + 1);      // i <= 1
    EXPECT_EQ(r.At(0, 1), 0 + 1 + 3);  // i <= 3, skipping 2
    EXPECT_EQ(r.At(0, 2), 0 + 1 + 3 + 4 + 5);
    EXPECT_EQ(r.At(0, 3), 0 + 1 + 3 + 4 + 5 + 6 + 7);
}

TEST(ShadeExec, BreakOutOfTwoLoops) {
    auto r = Shade(R"(surface t() {
        float i, j, n = 0;
        for (i = 0; i < 4; i += 1) {
            for (j = 0; j < 4; j += 1) {
                if (i * 4 + j >= u * 16) break 2;
                n += 1;
            }
        }
        Ci = n;
    })",
                   4, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(r.At(0, 0), 2);  // u*16 = 2
    EXPECT_EQ(r.At(0, 1), 6);
    EXPECT_EQ(r.At(0, 3), 14);
}

TEST(ShadeExec, UserFunctionWithOutputArgumentAndEarlyReturn) {
    auto r = Shade(R"(
        float twice(float x; output float y) {
            y = x * 3;
            if (x < 0.5) return 0;
            return x * 2;
        }
        surface t() {
            float y = 0;
            float z = twice(u, y);
            Ci = color(z, y, 0);
        })",
                   4, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 0), 0);
    EXPECT_FLOAT_EQ(r.At(1, 0), 0.375f);
    EXPECT_FLOAT_EQ(r.At(0, 3), 1.75f);
    EXPECT_FLOAT_EQ(r.At(1, 3), 2.625f);
}

// A return whose value calls user functions, nested: inlining them while the return is being
// compiled must not lose the returning function's frame (it once read freed memory).
TEST(ShadeExec, ReturnValueCallsOtherFunctions) {
    auto r = Shade(R"(
        float g(float x) { return x + 1; }
        float f(float x) { return g(x) * 2; }
        float h(float x) { return f(g(x)) + f(x) + g(g(g(x))); }
        surface t() { Ci = color(f(u), h(u), 0); })",
                   4, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    for (int i = 0; i < 4; ++i) {
        const float u = (float(i) + 0.5f) / 4;
        EXPECT_FLOAT_EQ(r.At(0, i), (u + 1) * 2) << i;
        EXPECT_FLOAT_EQ(r.At(1, i), (u + 2) * 2 + (u + 1) * 2 + (u + 3)) << i;
    }
}

// An if / else if chain of 100: the parser's stacks grow past their first 200 entries (a chain
// of 33 once ran out of them), and each point takes its own branch.
TEST(ShadeExec, LongElseIfChains) {
    std::string source = "surface t() { float y = -1;\nif (u < 0.01) y = 0;\n";
    for (int i = 1; i < 100; ++i)
        source +=
            "else if (u < " + std::to_string(0.01 * (i + 1)) + ") y = " + std::to_string(i) + ";\n";
    source += "else y = 100;\nCi = y; }\n";
    auto r = Shade(source, 4, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    for (int i = 0; i < 4; ++i) {
        const float u = (float(i) + 0.5f) / 4;  // 0.125, 0.375, ...: branch floor(100 u)
        EXPECT_FLOAT_EQ(r.At(0, i), std::floor(100 * u)) << i;
    }
}

// C's float suffix, as Pixie's and Aqsis's compilers take it: 0.5f is 0.5, 1e-1F is 0.1.
TEST(ShadeExec, FloatSuffixes) {
    auto r = Shade("surface t() { Ci = color(0.5f, 1e-1F, 2.f); }", 1, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 0), 0.5f);
    EXPECT_FLOAT_EQ(r.At(1, 0), 0.1f);
    EXPECT_FLOAT_EQ(r.At(2, 0), 2.0f);
}

// A file with CR LF line ends: a backslash before the CR still splices the next line.
TEST(ShadeExec, CrLfLineContinuations) {
    auto r =
        Shade("#define TWICE(x) \\\r\n    (2 * (x))\r\nsurface t() {\r\n  Ci = TWICE(u);\r\n}\r\n",
              4, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(r.At(0, i), 2 * (float(i) + 0.5f) / 4) << i;
}

TEST(ShadeExec, ExternReachesTheEnclosingShader) {
    auto r = Shade(R"(surface t() {
        float k = 2;
        float f(float a) { extern float k; return a * k; }
        Ci = f(3);
    })",
                   1, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(r.At(0, 0), 6);
}

TEST(ShadeExec, OperatorsOnTriplesAndMatrices) {
    auto r = Shade(R"(surface t() {
        vector a = (1, 0, 0), b = (0, 1, 0);
        vector c = a ^ b;
        float d = (a + b) . (a + 2 * b);
        matrix m = 2;
        matrix q = m * m;
        matrix inv = 1 / m;
        Ci = color(zcomp(c), d, comp(q, 0, 0) + comp(inv, 1, 1));
    })",
                   1, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 0), 1);
    EXPECT_FLOAT_EQ(r.At(1, 0), 3);
    EXPECT_FLOAT_EQ(r.At(2, 0), 4.5f);
}

TEST(ShadeExec, ArraysAndTernary) {
    auto r = Shade(R"(surface t(float w[3] = {1, 2, 3};) {
        float a[3];
        a[0] = 10; a[1] = 20; a[2] = w[2];
        float i = u < 0.5 ? 1 : 2;
        Ci = a[i];
    })",
                   2, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(r.At(0, 0), 20);
    EXPECT_EQ(r.At(0, 1), 3);
}

TEST(ShadeExec, ColorSpaceCasts) {
    auto r = Shade(R"(surface t() { Ci = color "hsv" (0, 1, 1) + color "hsl" (1.0/3, 1, 0.5); })",
                   1, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_FLOAT_EQ(r.At(0, 0), 1);
    EXPECT_FLOAT_EQ(r.At(1, 0), 1);
    EXPECT_FLOAT_EQ(r.At(2, 0), 0);
}

TEST(ShadeExec, FiveColorComponents) {
    testing::CapturedDiagnostics d;
    auto shader =
        testing::Compile("surface t(color c = (1, 2, 3, 4, 5);) { Ci = c * 2 + ncomps; }", d, 5);
    ASSERT_TRUE(shader) << d.Text();
    ShaderInstance instance(shader);
    auto r = testing::Run(instance, 1, 1, "Ci");
    ASSERT_EQ(r.width, 5);
    EXPECT_EQ(r.At(4, 0), 15);
}

// A surface shader may assign to I, as Pixie's mirror.sl does (I = normalize(I)): later reads
// see the new value.
TEST(ShadeExec, SurfaceShaderWritesI) {
    auto r = Shade(R"(surface t() {
        I = vector(3, 0, 4);
        I = normalize(I);
        Ci = color(xcomp(I), ycomp(I), zcomp(I));
    })",
                   2, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    for (int i = 0; i < 2; ++i) {
        EXPECT_FLOAT_EQ(r.At(0, i), 0.6f);
        EXPECT_FLOAT_EQ(r.At(1, i), 0.f);
        EXPECT_FLOAT_EQ(r.At(2, i), 0.8f);
    }
}

}  // namespace
}  // namespace gonio::sl
