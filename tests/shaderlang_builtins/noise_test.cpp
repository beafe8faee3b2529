// noise, pnoise, cellnoise: range, lattice values, continuity, periodicity, cell constancy.

#include <cmath>

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

// Evaluates a noise row at many points: args[a] holds per-point values of argument a.
std::vector<std::vector<float>> Evaluate(const std::string& name, const std::string& ret,
                                         const std::string& codes,
                                         const std::vector<std::vector<std::vector<float>>>& args) {
    const int n = static_cast<int>(args[0].size());
    TestCall call(n);
    for (size_t a = 0; a < codes.size(); ++a)
        call.Varying(TypeFromCode(codes.substr(a, 1)), args[a]);
    call.Result(TypeFromCode(ret), true);
    call.Run(FindKernel(name, ret, codes));
    const int w = WidthOfCode(ret[0], 3);
    std::vector<std::vector<float>> out(n, std::vector<float>(w));
    for (int p = 0; p < n; ++p) {
        for (int c = 0; c < w; ++c) out[p][c] = call.R(c, p);
    }
    return out;
}

// Deterministic pseudo-random inputs spread over [-50, 50].
std::vector<std::vector<float>> Spread(int n, int width, unsigned seed) {
    std::vector<std::vector<float>> v(n, std::vector<float>(width));
    unsigned state = seed;
    for (auto& point : v) {
        for (float& x : point) {
            state = state * 1664525u + 1013904223u;
            x = (state >> 8) * (100.0f / 16777216.0f) - 50.0f;
        }
    }
    return v;
}

TEST(NoiseBuiltins, RangeMeanAndLatticeValue) {
    const int n = 20000;
    for (const auto& [codes, widths] : std::vector<std::pair<std::string, std::vector<int>>>{
             {"f", {1}}, {"ff", {1, 1}}, {"p", {3}}, {"pf", {3, 1}}}) {
        std::vector<std::vector<std::vector<float>>> args;
        for (size_t a = 0; a < widths.size(); ++a) args.push_back(Spread(n, widths[a], 7 + a));
        for (const char* ret : {"f", "c", "p", "v"}) {
            auto out = Evaluate("noise", ret, codes, args);
            double sum = 0, lo = 1, hi = 0;
            for (auto& point : out) {
                for (float v : point) {
                    EXPECT_GE(v, 0.0f);
                    EXPECT_LE(v, 1.0f);
                    sum += v;
                    lo = std::min<double>(lo, v);
                    hi = std::max<double>(hi, v);
                }
            }
            double mean = sum / (out.size() * out[0].size());
            EXPECT_NEAR(mean, 0.5, 0.03) << "noise " << ret << "(" << codes << ")";
            EXPECT_GT(hi - lo, 0.5) << "noise " << ret << "(" << codes << ") spans too little";
        }
        // At integer lattice points every gradient term vanishes: float noise = 0.5 exactly.
        std::vector<std::vector<std::vector<float>>> lattice;
        for (size_t a = 0; a < widths.size(); ++a) {
            auto v = Spread(50, widths[a], 3 + a);
            for (auto& point : v) {
                for (float& x : point) x = std::round(x);
            }
            lattice.push_back(v);
        }
        // (Only the first component: the others are evaluated at offset inputs.)
        for (auto& point : Evaluate("noise", "f", codes, lattice)) {
            for (float v : point) EXPECT_FLOAT_EQ(v, 0.5f);
        }
    }
}

TEST(NoiseBuiltins, ContinuousAcrossCellBoundaries) {
    // Values just either side of a lattice plane, and the largest jump along a fine line.
    const int n = 4001;
    std::vector<std::vector<float>> line(n);
    for (int i = 0; i < n; ++i) line[i] = {-2.0f + i * 0.001f, 0.37f, 1.61f};
    auto out = Evaluate("noise", "f", "p", {line});
    float maxJump = 0;
    for (int i = 1; i < n; ++i) maxJump = std::max(maxJump, std::fabs(out[i][0] - out[i - 1][0]));
    EXPECT_LT(maxJump, 0.01f);
}

TEST(NoiseBuiltins, ComponentsOfVectorNoiseDiffer) {
    auto out = Evaluate("noise", "p", "p", {Spread(100, 3, 11)});
    int same = 0;
    for (auto& point : out) same += point[0] == point[1] || point[1] == point[2];
    EXPECT_LT(same, 5);
}

TEST(NoiseBuiltins, PnoiseIsPeriodic) {
    const int n = 200;
    auto x = Spread(n, 3, 5);
    auto t = Spread(n, 1, 9);
    std::vector<std::vector<float>> shifted(n), shiftedT(n), period(n, {4, 3, 5}), periodT(n, {6});
    for (int i = 0; i < n; ++i) {
        shifted[i] = {x[i][0] + 8, x[i][1] - 3, x[i][2] + 15};
        shiftedT[i] = {t[i][0] - 12};
    }
    auto a = Evaluate("pnoise", "f", "pp", {x, period});
    auto b = Evaluate("pnoise", "f", "pp", {shifted, period});
    auto c = Evaluate("pnoise", "c", "pfpf", {x, t, period, periodT});
    auto d = Evaluate("pnoise", "c", "pfpf", {shifted, shiftedT, period, periodT});
    for (int i = 0; i < n; ++i) {
        EXPECT_NEAR(a[i][0], b[i][0], 1e-4f) << i;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[i][k], d[i][k], 1e-4f) << i;
    }
    // 1D and 2D, across zero.
    std::vector<std::vector<float>> xs(n), xsShift(n), p1(n, {3});
    for (int i = 0; i < n; ++i) xs[i] = {x[i][0]}, xsShift[i] = {x[i][0] + 3};
    auto e = Evaluate("pnoise", "f", "ff", {xs, p1});
    auto f = Evaluate("pnoise", "f", "ff", {xsShift, p1});
    for (int i = 0; i < n; ++i) EXPECT_NEAR(e[i][0], f[i][0], 1e-4f);
}

TEST(NoiseBuiltins, CellnoiseIsConstantPerCellAndUniform) {
    const int n = 20000;
    auto x = Spread(n, 3, 21);
    std::vector<std::vector<float>> sameCell(n);
    for (int i = 0; i < n; ++i) {
        sameCell[i] = {std::floor(x[i][0]) + 0.01f, std::floor(x[i][1]) + 0.99f,
                       std::floor(x[i][2]) + 0.5f};
    }
    auto a = Evaluate("cellnoise", "c", "p", {x});
    auto b = Evaluate("cellnoise", "c", "p", {sameCell});
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(a[i][k], b[i][k]);
            EXPECT_GE(a[i][k], 0.0f);
            EXPECT_LT(a[i][k], 1.0f);
            sum += a[i][k];
        }
    }
    EXPECT_NEAR(sum / (3 * n), 0.5, 0.01);
}

TEST(NoiseBuiltins, UniformAndVaryingAgree) {
    // Uniform/varying operand variants, masks: reference is the varying evaluation itself.
    auto x = Spread(6, 3, 1);
    auto t = Spread(6, 1, 2);
    auto reference = Evaluate("noise", "v", "pf", {x, t});
    ExpectAllVariants("noise", "v", "pf", {x, t}, [&](const PointArgs& a) {
        TestCall one(1);
        one.Uniform(TypeFromCode("p"), a[0]).Uniform(TypeFromCode("f"), a[1]);
        one.Result(TypeFromCode("v"), false);
        one.Run(FindKernel("noise", "v", "pf"));
        return std::vector<float>{one.R(0), one.R(1), one.R(2)};
    });
    EXPECT_EQ(reference.size(), 6u);
}

}  // namespace
}  // namespace gonio::sl::testing
