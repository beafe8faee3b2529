// Math built-ins: analytic values under every uniform/varying combination, masks respected.

#include "base/math.h"

#include <cmath>

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

using Values = std::vector<std::vector<float>>;

Values Floats(std::initializer_list<float> v) {
    Values out;
    for (float x : v) out.push_back({x});
    return out;
}

Reference Unary(float (*f)(float)) {
    return [f](const PointArgs& a) { return std::vector<float>{f(a[0][0])}; };
}

TEST(MathBuiltins, TrigonometryAndPowers) {
    const Values x = Floats({0.1f, 0.5f, -0.7f, 0.9f, 0.3f});
    ExpectAllVariants("sin", "f", "f", {x}, Unary([](float v) { return std::sin(v); }));
    ExpectAllVariants("cos", "f", "f", {x}, Unary([](float v) { return std::cos(v); }));
    ExpectAllVariants("tan", "f", "f", {x}, Unary([](float v) { return std::tan(v); }));
    ExpectAllVariants("asin", "f", "f", {x}, Unary([](float v) { return std::asin(v); }));
    ExpectAllVariants("acos", "f", "f", {x}, Unary([](float v) { return std::acos(v); }));
    ExpectAllVariants("atan", "f", "f", {x}, Unary([](float v) { return std::atan(v); }));
    ExpectAllVariants("exp", "f", "f", {x}, Unary([](float v) { return std::exp(v); }));
    ExpectAllVariants("radians", "f", "f", {Floats({180, 90, -45, 0, 360})},
                      Unary([](float v) { return v * kPiF / 180.0f; }));
    ExpectAllVariants("degrees", "f", "f", {Floats({kPiF, kPiF / 2, -1, 0, 2})},
                      Unary([](float v) { return v * 180.0f / kPiF; }), 1e-4f);
    const Values positive = Floats({0.25f, 4.0f, 9.0f, 2.0f, 100.0f});
    ExpectAllVariants("sqrt", "f", "f", {positive}, Unary([](float v) { return std::sqrt(v); }));
    ExpectAllVariants("inversesqrt", "f", "f", {positive},
                      Unary([](float v) { return 1.0f / std::sqrt(v); }));
    ExpectAllVariants("log", "f", "f", {positive}, Unary([](float v) { return std::log(v); }));
    ExpectAllVariants("log", "f", "ff", {positive, Floats({2, 10, 3, 2, 10})},
                      [](const PointArgs& a) {
                          return std::vector<float>{std::log(a[0][0]) / std::log(a[1][0])};
                      });
    ExpectAllVariants(
        "pow", "f", "ff", {positive, Floats({0.5f, 2, -1, 3, 0})},
        [](const PointArgs& a) { return std::vector<float>{std::pow(a[0][0], a[1][0])}; }, 1e-3f);
    ExpectAllVariants(
        "atan", "f", "ff", {Floats({1, -1, 0, 2, -3}), Floats({1, 1, -1, -2, 0.5f})},
        [](const PointArgs& a) { return std::vector<float>{std::atan2(a[0][0], a[1][0])}; });
}

TEST(MathBuiltins, KnownValues) {
    TestCall call(1);
    call.Float(1.0f).Result(TypeFromCode("f"), false);
    call.Run(FindKernel("asin", "f", "f"));
    EXPECT_NEAR(call.R(0), kPiF / 2, 1e-6f);
    // Out-of-range arguments are clamped rather than giving NaN.
    TestCall acos(1);
    acos.Float(1.0000001f).Result(TypeFromCode("f"), false);
    acos.Run(FindKernel("acos", "f", "f"));
    EXPECT_EQ(acos.R(0), 0.0f);
}

TEST(MathBuiltins, Rounding) {
    const Values x = Floats({-1.5f, -0.2f, 0.0f, 0.5f, 2.7f});
    ExpectAllVariants("abs", "f", "f", {x}, Unary([](float v) { return std::fabs(v); }));
    ExpectAllVariants("floor", "f", "f", {x}, Unary([](float v) { return std::floor(v); }));
    ExpectAllVariants("ceil", "f", "f", {x}, Unary([](float v) { return std::ceil(v); }));
    ExpectAllVariants("round", "f", "f", {x}, Unary([](float v) { return std::round(v); }));
    ExpectAllVariants("sign", "f", "f", {x}, [](const PointArgs& a) {
        float v = a[0][0];
        return std::vector<float>{v > 0 ? 1.0f : v < 0 ? -1.0f : 0.0f};
    });
    // mod has the sign of the divisor: mod(-1, 3) = 2.
    ExpectAllVariants("mod", "f", "ff", {Floats({-1, 7, 5.5f, -7, 2}), Floats({3, 3, 2, 3, 0.5f})},
                      [](const PointArgs& a) {
                          float x = a[0][0], y = a[1][0];
                          return std::vector<float>{x - y * std::floor(x / y)};
                      });
    TestCall call(1);
    call.Float(-1).Float(3).Result(TypeFromCode("f"), false);
    call.Run(FindKernel("mod", "f", "ff"));
    EXPECT_FLOAT_EQ(call.R(0), 2.0f);
}

TEST(MathBuiltins, MinMaxClampMixPerComponent) {
    const Values a = {{0, 5, -1}, {1, 1, 1}, {2, -2, 0}, {0.5f, 0.5f, 0.5f}, {3, 0, 9}};
    const Values b = {{1, 1, 1}, {0, 2, 0}, {2, 2, 2}, {-1, 1, 0}, {4, -1, 8}};
    const Values c = {{-5, 3, 0}, {0.5f, 0.5f, 4}, {1, 1, 1}, {0, 0, 0}, {3.5f, 1, 1}};
    for (const char* t : {"c", "p", "v", "n"}) {
        const std::string T(t);
        ExpectAllVariants("min", T, T + T + T, {a, b, c}, [](const PointArgs& x) {
            std::vector<float> r(3);
            for (int i = 0; i < 3; ++i) r[i] = std::min({x[0][i], x[1][i], x[2][i]});
            return r;
        });
        ExpectAllVariants("max", T, T + T, {a, b}, [](const PointArgs& x) {
            std::vector<float> r(3);
            for (int i = 0; i < 3; ++i) r[i] = std::max(x[0][i], x[1][i]);
            return r;
        });
        ExpectAllVariants("clamp", T, T + T + T, {a, Values(5, {0, 0, 0}), Values(5, {1, 2, 3})},
                          [](const PointArgs& x) {
                              std::vector<float> r(3);
                              for (int i = 0; i < 3; ++i) {
                                  r[i] = std::min(std::max(x[0][i], x[1][i]), x[2][i]);
                              }
                              return r;
                          });
        ExpectAllVariants("mix", T, T + T + "f", {a, b, Floats({0, 1, 0.5f, 0.25f, 2})},
                          [](const PointArgs& x) {
                              std::vector<float> r(3);
                              float t = x[2][0];
                              for (int i = 0; i < 3; ++i) r[i] = (1 - t) * x[0][i] + t * x[1][i];
                              return r;
                          });
    }
    ExpectAllVariants("max", "f", "fffff",
                      {Floats({1, 2, 3, 4, 5}), Floats({5, 4, 3, 2, 1}), Floats({0, 9, 0, 0, 0}),
                       Floats({-1, -1, 8, -1, -1}), Floats({2, 2, 2, 7, 2})},
                      [](const PointArgs& x) {
                          float m = x[0][0];
                          for (auto& v : x) m = std::max(m, v[0]);
                          return std::vector<float>{m};
                      });
}

TEST(MathBuiltins, ColorsWithMoreComponents) {
    // ColorSamples 5: per-component kernels cover every component.
    const Values a = {{0, 1, 2, 3, 4}, {4, 3, 2, 1, 0}};
    const Values b = {{1, 1, 1, 1, 1}, {2, 2, 2, 2, 2}};
    ExpectAllVariants(
        "min", "c", "cc", {a, b},
        [](const PointArgs& x) {
            std::vector<float> r(5);
            for (int i = 0; i < 5; ++i) r[i] = std::min(x[0][i], x[1][i]);
            return r;
        },
        0.0f, 5);
}

TEST(MathBuiltins, StepSmoothstep) {
    ExpectAllVariants(
        "step", "f", "ff", {Floats({0.5f, 0.5f, 1, -1, 0}), Floats({0.4f, 0.5f, 2, -2, 0})},
        [](const PointArgs& a) { return std::vector<float>{a[1][0] < a[0][0] ? 0.0f : 1.0f}; });
    ExpectAllVariants(
        "smoothstep", "f", "fff",
        {Floats({0, 0, 1, 0, 2}), Floats({1, 2, 3, 1, 4}), Floats({0.5f, -1, 2, 1, 2.5f})},
        [](const PointArgs& a) {
            float lo = a[0][0], hi = a[1][0], x = a[2][0];
            if (x < lo) return std::vector<float>{0};
            if (x >= hi) return std::vector<float>{1};
            float t = (x - lo) / (hi - lo);
            return std::vector<float>{t * t * (3 - 2 * t)};
        });
}

TEST(MathBuiltins, FilterstepIsABoxFilteredStep) {
    // With an explicit interval [s1, s2] the result is the fraction beyond the edge.
    ExpectAllVariants(
        "filterstep", "f", "fff",
        {Floats({0.5f, 0.5f, 0.5f, 0, 0}), Floats({0, 0.4f, 0.6f, -1, 1}),
         Floats({1, 0.6f, 0.8f, -0.5f, 2})},
        [](const PointArgs& a) {
            float e = a[0][0];
            float lo = std::min(a[1][0], a[2][0]), hi = std::max(a[1][0], a[2][0]);
            return std::vector<float>{std::clamp((hi - e) / (hi - lo), 0.0f, 1.0f)};
        },
        1e-5f, 3, "ff*");
    // Without s2, the footprint is s's change to the grid neighbour; no context: plain step.
    TestCall noContext(2);
    noContext.Float(0.5f)
        .Varying(TypeFromCode("f"), {{0.4f}, {0.6f}})
        .Result(TypeFromCode("f"), true);
    noContext.Run(FindKernel("filterstep", "f", "ff*"));
    EXPECT_EQ(noContext.R(0, 0), 0.0f);
    EXPECT_EQ(noContext.R(0, 1), 1.0f);

    FakeContext context(2);
    context.uNeighbours = {1, -1};
    TestCall withNeighbours(2);
    withNeighbours.Float(0.5f)
        .Varying(TypeFromCode("f"), {{0.4f}, {0.6f}})
        .Result(TypeFromCode("f"), true)
        .Context(&context);
    withNeighbours.Run(FindKernel("filterstep", "f", "ff*"));
    // Footprint 0.2 (forward difference at 0, backward at 1): [0.3, 0.5] and [0.5, 0.7].
    EXPECT_NEAR(withNeighbours.R(0, 0), 0.0f, 1e-6f);
    EXPECT_NEAR(withNeighbours.R(0, 1), 1.0f, 1e-6f);
    TestCall straddling(2);
    straddling.Float(0.5f)
        .Varying(TypeFromCode("f"), {{0.45f}, {0.65f}})
        .Result(TypeFromCode("f"), true)
        .Context(&context);
    straddling.Run(FindKernel("filterstep", "f", "ff*"));
    EXPECT_NEAR(straddling.R(0, 0), 0.25f, 1e-5f);  // [0.35, 0.55]: a quarter past the edge

    TestCall widened(1);
    widened.Float(0.5f).Float(0.45f).String("width").Float(1.0f).Result(TypeFromCode("f"), false);
    widened.Run(FindKernel("filterstep", "f", "ff*"));
    EXPECT_EQ(widened.R(0), 0.0f);  // uniform s has no footprint: a plain step
}

TEST(MathBuiltins, SplineBases) {
    // Catmull-Rom passes through the interior knots: at x = 0 the 2nd knot, at 1 the 3rd-last.
    auto spline = [](const std::string& basis, float x, std::vector<float> knots) {
        TestCall call(1);
        std::string args = basis.empty() ? "f" : "sf";
        if (!basis.empty()) call.String(basis);
        call.Float(x);
        for (float k : knots) {
            call.Float(k);
            args += "f";
        }
        call.Result(TypeFromCode("f"), false);
        call.Run(FindKernel("spline", "f", args));
        return call.R(0);
    };
    const std::vector<float> knots = {0, 1, 4, 9, 16};
    EXPECT_NEAR(spline("", 0.0f, knots), 1.0f, 1e-6f);
    EXPECT_NEAR(spline("", 0.5f, knots), 4.0f, 1e-6f);
    EXPECT_NEAR(spline("", 1.0f, knots), 9.0f, 1e-6f);
    EXPECT_NEAR(spline("catmull-rom", 0.25f, knots), 2.25f, 1e-5f);  // exact for quadratics
    // Linear: straight lines between the interior knots.
    EXPECT_NEAR(spline("linear", 0.25f, knots), 2.5f, 1e-6f);
    // Bezier with 4 knots: the endpoints and the Bernstein midpoint.
    EXPECT_NEAR(spline("bezier", 0.0f, {1, 2, 3, 5}), 1.0f, 1e-6f);
    EXPECT_NEAR(spline("bezier", 1.0f, {1, 2, 3, 5}), 5.0f, 1e-6f);
    EXPECT_NEAR(spline("bezier", 0.5f, {0, 1, 1, 0}), 0.75f, 1e-6f);
    // B-spline of constant knots is that constant; of linear knots the linear function.
    EXPECT_NEAR(spline("bspline", 0.3f, {2, 2, 2, 2}), 2.0f, 1e-6f);
    EXPECT_NEAR(spline("bspline", 0.5f, {0, 1, 2, 3}), 1.5f, 1e-6f);
    // Hermite (P0, T0, P1, T1): endpoints, and the cubic's midpoint.
    EXPECT_NEAR(spline("hermite", 0.0f, {1, 0, 3, 0}), 1.0f, 1e-6f);
    EXPECT_NEAR(spline("hermite", 0.5f, {1, 0, 3, 0}), 2.0f, 1e-6f);
    EXPECT_NEAR(spline("hermite", 0.5f, {0, 1, 0, -1}), 0.25f, 1e-6f);
}

TEST(MathBuiltins, SplineOfColoursAndArrays) {
    const Values knots = {{0, 0, 0}, {1, 2, 3}, {2, 4, 6}, {3, 6, 9}};
    ExpectAllVariants("spline", "c", "fcccc",
                      {Floats({0, 0.5f}), Values(2, knots[0]), Values(2, knots[1]),
                       Values(2, knots[2]), Values(2, knots[3])},
                      [](const PointArgs& a) {
                          float x = a[0][0];
                          return std::vector<float>{1 + x, 2 + 2 * x, 3 + 3 * x};
                      });
    TypeSpec array{BaseType::Float, 5};
    TestCall call(2);
    call.Varying(TypeFromCode("f"), {{0.0f}, {1.0f}})
        .Uniform(array, {0, 1, 4, 9, 16})
        .Result(TypeFromCode("f"), true);
    call.Run(FindKernel("spline", "f", "ff[]"));
    EXPECT_NEAR(call.R(0, 0), 1.0f, 1e-6f);
    EXPECT_NEAR(call.R(0, 1), 9.0f, 1e-6f);
}

TEST(MathBuiltins, RandomIsVaryingUniformInUnitInterval) {
    const BuiltinInfo* row = FindRow("random", "f", "");
    ASSERT_NE(row, nullptr);
    EXPECT_TRUE(row->flags & kVaryingResult);
    const int n = 4000;
    TestCall call(n);
    std::vector<uint8_t> mask(n, 1);
    mask[7] = 0;
    call.Mask(mask).Result(TypeFromCode("c"), true);
    call.Run(row->kernel);
    double sum = 0;
    for (int p = 0; p < n; ++p) {
        if (p == 7) {
            EXPECT_EQ(call.R(0, p), kSentinel);
            continue;
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(call.R(c, p), 0.0f);
            EXPECT_LT(call.R(c, p), 1.0f);
            sum += call.R(c, p);
        }
    }
    EXPECT_NEAR(sum / (3 * (n - 1)), 0.5, 0.02);
    EXPECT_NE(call.R(0, 0), call.R(0, 1));
}

// random() stored in a uniform (compiler/uniform_random.h): one value per component for all
// active points, even in a varying register.
TEST(MathBuiltins, UniformRandomGivesEveryActivePointOneValue) {
    const BuiltinInfo* row = FindRow("__uniform_random", "c", "");
    ASSERT_NE(row, nullptr);
    EXPECT_FALSE(row->flags & kVaryingResult);
    EXPECT_TRUE(row->flags & kDrawsRandom);  // never folded to a constant
    const int n = 16;
    TestCall call(n);
    std::vector<uint8_t> mask(n, 1);
    mask[5] = 0;
    call.Mask(mask).Result(TypeFromCode("c"), true);
    call.Run(row->kernel);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GE(call.R(c, 0), 0.0f);
        EXPECT_LT(call.R(c, 0), 1.0f);
        for (int p = 1; p < n; ++p) EXPECT_EQ(call.R(c, p), p == 5 ? kSentinel : call.R(c, 0));
    }
    EXPECT_NE(call.R(0, 0), call.R(1, 0));
}

}  // namespace
}  // namespace gonio::sl::testing
