// The kernel and its normalisation: the flat integrals against the thesis's closed forms, the
// sphere integrals against an independent Monte Carlo estimate, and the in-domain masses.
#include "brdfsim/kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "base/math.h"
#include "brdfsim/splat_set.h"

namespace gonio {
namespace {

TEST(Kernel, PolynomialShape) {
    EXPECT_DOUBLE_EQ(SplatKernel(0.0), 1.0);
    EXPECT_NEAR(SplatKernel(1.0 - 1e-9), 0.0, 1e-12);
    EXPECT_EQ(SplatKernel(1.5), 0.0);
    // zero slope at both ends (thesis §4.2.1)
    EXPECT_NEAR((SplatKernel(1e-4) - 1.0) / 1e-4, 0.0, 1e-3);
    EXPECT_NEAR((SplatKernel(1.0) - SplatKernel(1.0 - 1e-4)) / 1e-4, 0.0, 1e-3);
    EXPECT_NEAR(SplatKernelSquared(0.25f), SplatKernel(0.5), 1e-6);
}

TEST(Kernel, FlatMassesMatchThesisClosedForms) {
    for (double r : {0.1, 0.3, 0.9}) {
        const double r4 = std::pow(r, 4);
        EXPECT_NEAR(FlatKernelMass4D(r, Norm::kL1) / (37.0 / 1620 * kPi * kPi * r4), 1.0, 1e-9);
        EXPECT_NEAR(FlatKernelMass4D(r, Norm::kL2) / (37.0 / 540 * kPi * kPi * r4), 1.0, 1e-9);
        EXPECT_NEAR(FlatKernelMass4D(r, Norm::kLinf) / (37.0 / 270 * kPi * kPi * r4), 1.0, 1e-9);
        EXPECT_NEAR(FlatKernelMass3D(r, Norm::kL2) / (736 * kPi / 2835 * r * r * r), 1.0, 1e-9);
    }
}

TEST(Kernel, SphereMassIsBelowFlatAsDesignSays) {
    // DESIGN.md: planar integrals overstate the mass by 0.6% at R = 0.3 and 6.5% at R = 1 (L2).
    const double at03 = FlatKernelMass4D(0.3, Norm::kL2) / SphereKernelMass4D(0.3, Norm::kL2);
    EXPECT_NEAR(at03 - 1.0, 0.006, 0.0015);
    EXPECT_LT(SphereKernelMass4D(0.1, Norm::kL2), FlatKernelMass4D(0.1, Norm::kL2));
}

// Monte Carlo over sphere × sphere: points uniform on each whole sphere (density 1/4π each).
double MonteCarloMass4D(double radius, Norm norm, int samples) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        // distance from the pole of a uniform point on the sphere: cos d uniform in [cos R, 1]
        // is enough, since the kernel vanishes beyond R; weight by that cap's share.
        const double capShare = (1 - std::cos(radius)) / 2;
        const double d1 = std::acos(1 - u(rng) * (1 - std::cos(radius)));
        const double d2 = std::acos(1 - u(rng) * (1 - std::cos(radius)));
        sum += SplatKernel(CombineDistances(norm, d1, d2) / radius) * capShare * capShare;
    }
    return sum / samples * 16 * kPi * kPi;
}

TEST(Kernel, SphereMassAgreesWithMonteCarlo) {
    for (Norm norm : {Norm::kL1, Norm::kL2, Norm::kLinf}) {
        const double exact = SphereKernelMass4D(0.7, norm);
        EXPECT_NEAR(MonteCarloMass4D(0.7, norm, 400000) / exact, 1.0, 0.01) << NormName(norm);
    }
}

TEST(Kernel, InDomainMassIsFullAwayFromTheHorizonAndHalfOnIt) {
    const double r = 0.3;
    const double full4 = SphereKernelMass4D(r, Norm::kL2);
    EXPECT_NEAR(InDomainKernelMass(r, Norm::kL2, false, 0.5, 0.5) / full4, 1.0, 1e-6);
    EXPECT_NEAR(InDomainKernelMass(r, Norm::kL2, false, 0.5, kPi / 2) / full4, 0.5, 1e-3);
    EXPECT_NEAR(InDomainKernelMass(r, Norm::kL2, false, kPi / 2, kPi / 2) / full4, 0.25, 1e-3);
    const double full3 = SphereKernelMass3D(r, Norm::kL2);
    EXPECT_NEAR(InDomainKernelMass(r, Norm::kL2, true, 0.0, 0.5) / full3, 0.5, 1e-3);
    EXPECT_NEAR(InDomainKernelMass(r, Norm::kL2, true, 0.7, 0.5) / full3, 1.0, 1e-6);
}

// ArcLength2FromChord2 replaces 4 asin²(c/2) (two square roots and an asin per splat) by a
// polynomial in c²: it must agree with the exact value to float rounding over each range, every
// chord a splat of any radius up to π/2 can reach, down to tiny chords.
template <ChordRange kRange>
double WorstRelativeError(float hi) {
    double worst = 0.0;
    auto check = [&](float s) {
        const double exact = std::pow(2.0 * std::asin(0.5 * std::sqrt(static_cast<double>(s))), 2);
        worst = std::max(worst, std::abs(ArcLength2FromChord2<kRange>(s) / exact - 1.0));
    };
    constexpr int kSteps = 100000;
    for (int i = 1; i <= kSteps; ++i) check(hi * static_cast<float>(i) / kSteps);
    for (float s = hi; s > 1e-30f; s *= 0.37f) check(s);
    return worst;
}

TEST(Kernel, ArcLengthPolynomialsMatchTheExactDistance) {
    EXPECT_LT(WorstRelativeError<ChordRange::kSmall>(0.25f), 1e-7);
    EXPECT_LT(WorstRelativeError<ChordRange::kMedium>(1.0f), 1e-7);
    EXPECT_LT(WorstRelativeError<ChordRange::kLarge>(2.0f), 1e-7);
}

TEST(Kernel, ChordRangeCoversTheSplatRadius) {
    for (double r : {0.05, 0.3, 0.5, 0.505, 0.6, 1.0, kPi / 3, 1.2, kPi / 2}) {
        const float chordRadius2 = static_cast<float>(std::pow(2.0 * std::sin(0.5 * r), 2));
        const float limit[] = {0.25f, 1.0f, 2.0f};
        const ChordRange range = ChordRangeFor(chordRadius2);
        EXPECT_LE(chordRadius2, limit[static_cast<int>(range)]) << r;
        if (range != ChordRange::kSmall) {
            EXPECT_GT(chordRadius2, limit[static_cast<int>(range) - 1]) << r;
        }
    }
    EXPECT_EQ(ChordRangeFor(static_cast<float>(std::pow(2.0 * std::sin(0.25), 2))),
              ChordRange::kSmall);  // R = 0.5, the thesis's brushed metal
}

TEST(Kernel, ParsesNormNames) {
    EXPECT_EQ(ParseNorm("l1"), Norm::kL1);
    EXPECT_EQ(ParseNorm("linf"), Norm::kLinf);
    EXPECT_THROW(ParseNorm("l3"), std::invalid_argument);
}

}  // namespace
}  // namespace gonio
