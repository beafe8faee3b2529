// random() in a uniform context (compiler/uniform_random.h): one value per run, shared by every
// point of the grid; random() elsewhere stays varying, and so does a function that calls it.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "sl_test_util.h"

namespace gonio::sl {
namespace {

using testing::Errors;
using testing::RunResult;
using testing::Shade;

constexpr int kW = 4, kH = 3, kN = kW * kH;

// The distinct values of component c over the grid.
std::set<float> ValuesOf(const RunResult& r, int c) {
    std::set<float> values;
    for (int p = 0; p < kN; ++p) values.insert(r.At(c, p));
    return values;
}

TEST(UniformRandom, InitialisedUniformColourIsTheSameAtEveryPoint) {
    // The form two peer shaders use.
    const std::string source = R"(surface t() {
        uniform color c = color(random(), random(), random());
        Ci = c;
    })";
    EXPECT_EQ(Errors(source), "");
    const RunResult r = Shade(source, kW, kH, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    std::set<float> components;
    for (int c = 0; c < 3; ++c) {
        const std::set<float> values = ValuesOf(r, c);
        ASSERT_EQ(values.size(), 1u) << "component " << c << " differs between points";
        EXPECT_GE(*values.begin(), 0.0f);
        EXPECT_LT(*values.begin(), 1.0f);
        components.insert(*values.begin());
    }
    // Three draws from the run's stream, not one value repeated.
    EXPECT_EQ(components.size(), 3u);
}

TEST(UniformRandom, AssignedUniformIsTheSameAtEveryPoint) {
    const RunResult r = Shade(R"(surface t() {
        uniform float k;
        k = random();
        k += random();
        Ci = k;
    })",
                              kW, kH, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(ValuesOf(r, 0).size(), 1u);
    EXPECT_LT(*ValuesOf(r, 0).begin(), 2.0f);
}

TEST(UniformRandom, VaryingRandomDiffersBetweenPoints) {
    const RunResult r = Shade(R"(surface t() {
        float k = random();
        Ci = k;
    })",
                              kW, kH, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(ValuesOf(r, 0).size(), size_t(kN));
}

TEST(UniformRandom, IsDeterministicForTheSameSeeds) {
    const std::string source = R"(surface t() {
        uniform float a = random();
        uniform float b = random();
        Ci = color(a, b, random());
    })";
    const RunResult first = Shade(source, kW, kH, "Ci");
    const RunResult second = Shade(source, kW, kH, "Ci");
    ASSERT_EQ(first.width, 3) << first.diagnostics;
    EXPECT_EQ(first.values, second.values);
    // Successive uniform draws differ, and a varying one beside them still varies.
    EXPECT_NE(first.At(0, 0), first.At(1, 0));
    EXPECT_EQ(ValuesOf(first, 2).size(), size_t(kN));
}

TEST(UniformRandom, AVaryingOperandStillMakesTheValueVarying) {
    EXPECT_NE(Errors("surface t() { uniform float k = random() * u; }")
                  .find("cannot initialise uniform 'k' with a varying value"),
              std::string::npos);
}

TEST(UniformRandom, AFunctionThatCallsRandomIsVarying) {
    // Without a varying argument or global, only its call of random() makes the result vary:
    // storing it in a uniform is the error a varying value gets.
    EXPECT_NE(Errors(R"(float r() { return random(); }
        surface t() { uniform float k = r(); Ci = k; })")
                  .find("cannot initialise uniform 'k' with a varying value"),
              std::string::npos);
    // Through a varying local the function's result is varying at run time too.
    const RunResult r = Shade(R"(float r() { return random(); }
        surface t() { float k = r(); Ci = k; })",
                              kW, kH, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(ValuesOf(r, 0).size(), size_t(kN));
}

TEST(UniformRandom, AUserFunctionNamedRandomIsCalledAsWritten) {
    const RunResult r = Shade(R"(float random() { return 0.25; }
        surface t() { uniform float k = random(); Ci = k; })",
                              kW, kH, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(ValuesOf(r, 0), std::set<float>{0.25f});
}

}  // namespace
}  // namespace gonio::sl
