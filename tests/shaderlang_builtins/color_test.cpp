// Colour built-ins: comp/setcomp, ctransform round trips and known values, luminance.

#include <cmath>

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

std::vector<float> Ctransform(const std::string& from, const std::string& to,
                              const std::vector<float>& c, FakeContext* context = nullptr) {
    TestCall call(1);
    std::string args = "sc";
    if (!from.empty()) {
        call.String(from);
        args = "ssc";
    }
    call.String(to).Uniform(TypeFromCode("c"), c).Result(TypeFromCode("c"), false);
    call.Context(context);
    call.Run(FindKernel("ctransform", "c", args));
    return {call.R(0), call.R(1), call.R(2)};
}

TEST(ColorBuiltins, CompAndSetcomp) {
    using Values = std::vector<std::vector<float>>;
    const Values c = {{0.1f, 0.2f, 0.3f}, {1, 2, 3}, {4, 5, 6}};
    ExpectAllVariants("comp", "f", "cf", {c, {{0}, {1}, {2}}}, [](const PointArgs& a) {
        return std::vector<float>{a[0][static_cast<int>(a[1][0])]};
    });
    TestCall set(3);
    set.Varying(TypeFromCode("C"), c).Float(1).Varying(TypeFromCode("f"), {{7}, {8}, {9}});
    set.Mask({1, 0, 1}).Run(FindKernel("setcomp", "x", "Cff"));
    EXPECT_EQ(set.Arg(0, 1, 0), 7.0f);
    EXPECT_EQ(set.Arg(0, 1, 1), 2.0f);
    EXPECT_EQ(set.Arg(0, 1, 2), 9.0f);
}

TEST(ColorBuiltins, KnownConversions) {
    auto hsv = Ctransform("", "hsv", {1, 0, 0});
    EXPECT_NEAR(hsv[0], 0.0f, 1e-6f);
    EXPECT_NEAR(hsv[1], 1.0f, 1e-6f);
    EXPECT_NEAR(hsv[2], 1.0f, 1e-6f);
    auto cyan = Ctransform("hsv", "rgb", {0.5f, 1, 1});
    EXPECT_NEAR(cyan[0], 0.0f, 1e-6f);
    EXPECT_NEAR(cyan[1], 1.0f, 1e-6f);
    EXPECT_NEAR(cyan[2], 1.0f, 1e-6f);
    auto hsl = Ctransform("rgb", "hsl", {0.5f, 0.5f, 0.5f});
    EXPECT_NEAR(hsl[1], 0.0f, 1e-6f);
    EXPECT_NEAR(hsl[2], 0.5f, 1e-6f);
    // White has Y = 1 and the D65 chromaticity (0.3127, 0.3290).
    auto xyY = Ctransform("rgb", "xyY", {1, 1, 1});
    EXPECT_NEAR(xyY[0], 0.3127f, 2e-4f);
    EXPECT_NEAR(xyY[1], 0.3290f, 2e-4f);
    EXPECT_NEAR(xyY[2], 1.0f, 1e-4f);
    auto yiq = Ctransform("rgb", "YIQ", {1, 1, 1});
    EXPECT_NEAR(yiq[0], 1.0f, 1e-5f);
    EXPECT_NEAR(yiq[1], 0.0f, 1e-5f);
    EXPECT_NEAR(yiq[2], 0.0f, 1e-5f);
}

TEST(ColorBuiltins, RoundTrips) {
    const std::vector<std::vector<float>> colours = {
        {0.2f, 0.4f, 0.6f}, {0.9f, 0.1f, 0.3f}, {0.5f, 0.5f, 0.1f}, {0.05f, 0.8f, 0.7f}};
    for (const char* space : {"hsv", "hsl", "xyz", "XYZ", "xyY", "YIQ"}) {
        for (const auto& c : colours) {
            auto there = Ctransform("", space, c);
            auto back = Ctransform(space, "rgb", there);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], c[i], 1e-5f) << space;
            auto direct = Ctransform(space, "hsv", there);
            auto viaRgb = Ctransform("", "hsv", c);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(direct[i], viaRgb[i], 1e-4f) << space;
        }
    }
}

TEST(ColorBuiltins, UnknownSpaceWarnsAndKeepsTheColour) {
    FakeContext context(1);
    auto c = Ctransform("", "lab", {0.1f, 0.2f, 0.3f}, &context);
    EXPECT_FLOAT_EQ(c[1], 0.2f);
    EXPECT_EQ(context.warnings.size(), 1u);
}

TEST(ColorBuiltins, Luminance) {
    ExpectAllVariants("luminance", "f", "c", {{{1, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                      [](const PointArgs& a) {
                          return std::vector<float>{0.212671f * a[0][0] + 0.715160f * a[0][1] +
                                                    0.072169f * a[0][2]};
                      });
}

}  // namespace
}  // namespace gonio::sl::testing
