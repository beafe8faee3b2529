// The splat tree behind grid lookups (issue 4) must give the plain splat sum: every splat and
// every active image through SplatSet::Accumulate, as BrdfSimple computes it, at many random
// points, for every norm, both horizon modes, both domains, every range of the chord polynomials
// (radii up to π/2), grey and coloured splats (a grey set keeps one weight a splat) and other
// numbers of colour components than the fast path's three.
#include "brdfsim/splat_tree.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "test_util.h"

namespace gonio {
namespace {

#if defined(GONIO_SPLAT_TREE_ONLY_AVX2)
// The AVX2 copy built alone (CMakeLists.txt) runs only where the CPU has AVX2.
class NeedsAvx2 : public ::testing::Environment {
  public:
    void SetUp() override {
        if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this CPU has no AVX2";
    }
};
const auto* const kNeedsAvx2 = ::testing::AddGlobalTestEnvironment(new NeedsAvx2);
#endif

std::vector<double> ReferenceSum(const SplatSet& splats, const SplatQuery& q) {
    std::vector<double> acc(splats.NumComponents(), 0.0);
    for (int v = 0; v < splats.NumImages(); ++v) {
        if (!(q.activeMask & (1u << v))) continue;
        for (std::size_t k = 0; k < splats.Size(); ++k) splats.Accumulate(k, v, q, acc.data());
    }
    return acc;
}

Imath::V3f Direction(double theta, double phi) {
    return Imath::V3f(static_cast<float>(std::sin(theta) * std::cos(phi)),
                      static_cast<float>(std::sin(theta) * std::sin(phi)),
                      static_cast<float>(std::cos(theta)));
}

struct Case {
    bool isotropic;
    Norm norm;
    Horizon horizon;
    double radius;
    int ncomps;
    bool coloured = false;
};

// Synthetic maps are grey; this tints every splat differently.
void Tint(SplatSet& splats) {
    const int n = splats.NumComponents();
    for (std::size_t i = 0; i < splats.weights.size(); ++i) {
        splats.weights[i] *= 1.0f + 0.3f * static_cast<float>(i % n) + 0.01f * (i / n % 7);
    }
}

void ExpectTreeEqualsReference(const Case& c) {
    const auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 6000, c.isotropic, false,
                                              c.radius, c.norm, c.horizon, c.ncomps);
    if (c.coloured) Tint(*splats);
    const SplatTree tree(*splats);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    int nonzero = 0;
    for (int i = 0; i < 600; ++i) {
        // Uniform in θ, so that the pole and the horizon (where images act) are well covered.
        const double thetaIn = i < 4 ? (i & 1 ? 1e-4 : 0.5 * kPi - 1e-3) : 0.5 * kPi * u(rng);
        const double thetaOut = i < 4 ? (i & 2 ? 1e-4 : 0.5 * kPi - 1e-3) : 0.5 * kPi * u(rng);
        const SplatQuery q = splats->MakeQuery(Direction(thetaIn, 2 * kPi * u(rng)),
                                               Direction(thetaOut, 2 * kPi * u(rng)));
        const std::vector<double> expected = ReferenceSum(*splats, q);
        std::vector<double> got(c.ncomps, 0.0);
        tree.Accumulate(q, got.data());
        for (int k = 0; k < c.ncomps; ++k) {
            // The same float terms; partial sums of 4 in float, then double.
            EXPECT_NEAR(got[k], expected[k], 1e-6 * std::abs(expected[k]) + 1e-12)
                << "point " << i << " component " << k;
        }
        nonzero += expected[0] > 0;
    }
    EXPECT_GT(nonzero, 400);
}

class SplatTreeEqualsSum
    : public ::testing::TestWithParam<std::tuple<bool, Norm, Horizon, double>> {};

TEST_P(SplatTreeEqualsSum, AtRandomPoints) {
    const auto [isotropic, norm, horizon, radius] = GetParam();
    ExpectTreeEqualsReference({isotropic, norm, horizon, radius, 3});
    ExpectTreeEqualsReference({isotropic, norm, horizon, radius, 3, true});
}

INSTANTIATE_TEST_SUITE_P(
    Domains, SplatTreeEqualsSum,
    ::testing::Combine(::testing::Bool(), ::testing::Values(Norm::kL1, Norm::kL2, Norm::kLinf),
                       ::testing::Values(Horizon::kReflect, Horizon::kRenormalize),
                       ::testing::Values(0.4, 1.2)),
    [](const auto& info) {
        return std::string(std::get<0>(info.param) ? "iso_" : "aniso_") +
               NormName(std::get<1>(info.param)) + "_" + HorizonName(std::get<2>(info.param)) +
               (std::get<3>(info.param) > 1 ? "_wide" : "_narrow");
    });

// Each polynomial of ArcLength2FromChord2 (ChordRange) is its own copy of the leaf loop: the
// parameterised cases above cover the small one (R = 0.4) and the large one (R = 1.2); here the
// medium one and the largest radius allowed, π/2.
TEST(SplatTree, EveryChordRange) {
    for (const double radius : {0.8, kPi / 2}) {
        for (const Norm norm : {Norm::kL1, Norm::kL2, Norm::kLinf}) {
            ExpectTreeEqualsReference({false, norm, Horizon::kReflect, radius, 3});
        }
        ExpectTreeEqualsReference({true, Norm::kL2, Horizon::kReflect, radius, 3});
    }
}

TEST(SplatTree, ManyComponents) {
    for (const bool coloured : {false, true}) {
        ExpectTreeEqualsReference({false, Norm::kL2, Horizon::kReflect, 0.5, 6, coloured});
        ExpectTreeEqualsReference({true, Norm::kL2, Horizon::kReflect, 0.5, 6, coloured});
    }
}

TEST(SplatTree, KeepsOneWeightPerGreySplat) {
    const auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 6000, false, false, 0.5,
                                              Norm::kL2, Horizon::kReflect, 3);
    const SplatTree grey(*splats);
    Tint(*splats);
    const SplatTree coloured(*splats);
    // Per splat: six coordinates and one weight instead of three.
    EXPECT_LT(grey.MemoryBytes(), coloured.MemoryBytes() * 0.85);
}

TEST(SplatTree, ZeroWhereNoSplatReaches) {
    // A narrow lobe: only the photons that leave near the mirror direction carry energy.
    const auto splats = test::SyntheticSplats("phong:0,1,2000", 20000, false, false, 0.2);
    const SplatTree tree(*splats);
    for (const double phiOut : {0.5 * kPi, kPi}) {
        const SplatQuery q = splats->MakeQuery(Direction(0.3, 0.0), Direction(0.3, phiOut));
        double acc[1] = {0.0};
        tree.Accumulate(q, acc);
        const double expected = ReferenceSum(*splats, q)[0];
        EXPECT_NEAR(acc[0], expected, 1e-6 * expected) << phiOut;
        if (phiOut == kPi) {
            EXPECT_GT(acc[0], 0.0);
        } else {
            EXPECT_EQ(acc[0], 0.0);
        }
    }
}

}  // namespace
}  // namespace gonio
