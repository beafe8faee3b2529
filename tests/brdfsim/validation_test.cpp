// The validation at full size (labelled slow): synthetic Lambert, albedo 0.5, 1M photon
// paths, L2, R = 0.5, evaluated on a dense set up to θ = 85° (horizon included): mean within 1% of
// 0.5/π and no point further than 5%, in 4D and isotropic form; Phong n = 25 at 1M photons.
#include <gtest/gtest.h>

#include <cstdio>

#include "brdfsim/brdf_grid.h"
#include "test_util.h"

namespace gonio {
namespace {

const AnalyticBrdf kLambert = AnalyticBrdf::Parse("lambert:0.5");

TEST(Validation, Lambert1MAnisotropic) {
    BrdfGrid grid(test::SyntheticSplats("lambert:0.5", 1000000, false, true, 0.5), 4, 12);
    const auto stats = test::CompareOnDenseSet(grid, kLambert, 85, false);
    std::printf("4D Lambert, 1M paths, R 0.5, L2: mean %+.4f%%, max %.3f%% over %d points\n",
                100 * stats.meanRelative, 100 * stats.maxRelative, stats.points);
    EXPECT_LT(std::abs(stats.meanRelative), 0.01);
    EXPECT_LT(stats.maxRelative, 0.05);
}

TEST(Validation, Lambert1MIsotropic) {
    BrdfIsoGrid grid(test::SyntheticSplats("lambert:0.5", 1000000, true, true, 0.5), 4, 12);
    const auto stats = test::CompareOnDenseSet(grid, kLambert, 85, true);
    std::printf("iso Lambert, 1M paths, R 0.5, L2: mean %+.4f%%, max %.3f%% over %d points\n",
                100 * stats.meanRelative, 100 * stats.maxRelative, stats.points);
    EXPECT_LT(std::abs(stats.meanRelative), 0.01);
    EXPECT_LT(stats.maxRelative, 0.05);
}

TEST(Validation, Phong1MPeakAndWidth) {
    // As in reconstruction_test.cpp, with R = 0.1 and 1M photons: the smoothing prediction
    // holds to 2% for the peak and 3% for the width.
    const double n = 25, radius = 0.1;
    BrdfIsoGrid grid(test::SyntheticSplats("phong:0,1,25", 1000000, true, true, radius), 15, 60);
    const double sigma2 = 1 / n, s2 = 0.1041 * radius * radius;
    const double peakFactor = std::sqrt(sigma2 / 2 / (sigma2 / 2 + s2) * sigma2 / (sigma2 + s2));
    const double analyticPeak = (n + 2) / (2 * kPi);
    const double predictedFwhm =
        2 * std::acos(std::pow(0.5, 1 / n)) / kDegree * std::sqrt((sigma2 + 2 * s2) / sigma2);
    for (double ti : {0.0, 30.0, 60.0}) {
        const test::Lobe lobe = test::PlaneOfIncidenceLobe(grid, ti);
        std::printf(
            "Phong n=25, 1M, R 0.1, theta_in %2.0f: peak %.3f at %.2f (predicted %.3f, "
            "analytic %.3f), FWHM %.2f deg (predicted %.2f)\n",
            ti, lobe.peak, lobe.peakAt, analyticPeak * peakFactor, analyticPeak, lobe.fwhm,
            predictedFwhm);
        EXPECT_NEAR(lobe.peakAt, ti, 1.0);
        EXPECT_NEAR(lobe.peak / (analyticPeak * peakFactor), 1.0, 0.025);
        EXPECT_NEAR(lobe.fwhm / predictedFwhm, 1.0, 0.03);
    }
}

}  // namespace
}  // namespace gonio
