// SplatSampler (brdfsim/splat_sampler.h): the directions it draws follow the pdf it reports
// (χ² goodness of fit as pbrt's and Mitsuba's BSDF tests do it), that pdf integrates to 1 over
// the hemisphere, and the sampled albedo estimator agrees with the evaluated BRDF's integral.

#include "brdfsim/splat_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "base/hash.h"
#include "base/math.h"
#include "brdfsim/brdf_grid.h"
#include "brdfsim/grd_file.h"
#include "sampler_chi_square.h"
#include "test_util.h"

namespace gonio {
namespace {

TEST(GammaQ, KnownChiSquareQuantiles) {
    // χ² quantiles at p = 0.05: 3.841 (1 dof), 18.307 (10 dof), 124.342 (100 dof).
    EXPECT_NEAR(test::GammaQ(0.5, 3.841459 / 2), 0.05, 1e-6);
    EXPECT_NEAR(test::GammaQ(5.0, 18.307038 / 2), 0.05, 1e-6);
    EXPECT_NEAR(test::GammaQ(50.0, 124.342113 / 2), 0.05, 1e-6);
}

constexpr int kTests = 9;  // the χ² tests of this executable

void CheckSampler(const std::shared_ptr<const SplatSet>& splats, const Brdf& exact,
                  double thetaInDeg, double phiIn) {
    test::CheckSampler(splats, exact, thetaInDeg, phiIn, kTests);
}

TEST(SplatSampler, AnisotropicPhongChiSquare) {
    auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 20000, false, false, 0.3);
    const BrdfGrid grid(splats, 4, 9);
    CheckSampler(splats, grid, 30, 0.7);
}

// At 80° the incoming horizon image and both outgoing images are in play.
TEST(SplatSampler, AnisotropicGrazingChiSquare) {
    auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 20000, false, false, 0.3);
    const BrdfGrid grid(splats, 4, 9);
    CheckSampler(splats, grid, 80, 2.0);
}

TEST(SplatSampler, AnisotropicL1AndLinfChiSquare) {
    for (Norm norm : {Norm::kL1, Norm::kLinf}) {
        auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 20000, false, false, 0.4, norm);
        const BrdfGrid grid(splats, 4, 9);
        CheckSampler(splats, grid, 50, -1.0);
    }
}

TEST(SplatSampler, RenormalizedChiSquare) {
    auto splats = test::SyntheticSplats("lambert:0.7", 20000, false, false, 0.4, Norm::kL2,
                                        Horizon::kRenormalize);
    const BrdfGrid grid(splats, 4, 9);
    CheckSampler(splats, grid, 60, 0.3);
}

// Isotropic: near the pole (image 1), mid-way, and near the horizon (image 2).
TEST(SplatSampler, IsotropicChiSquare) {
    auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 20000, true, false, 0.3);
    const BrdfIsoGrid grid(splats, 5, 11);
    for (double theta : {8.0, 45.0, 82.0}) CheckSampler(splats, grid, theta, 1.1);
}

// An isotropic set's W(θ') comes from a table (splat_sampler.h): against the direct sum
// Σ_a Σ_k w̄_k M(|θ'_a − θ'_k|) with M itself (KernelOutMarginal, the sampler's M is its table
// interpolated to 1e-6), at θ' near the pole (image 1), mid-way and near the horizon (image 2),
// for the smooth L2 kernel and the L1 one, whose M has a cusp at 0.
TEST(SplatSampler, IsotropicWeightMatchesTheDirectSum) {
    for (Norm norm : {Norm::kL2, Norm::kL1}) {
        const double radius = 0.3;
        auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 20000, true, false, radius, norm);
        const BrdfIsoGrid grid(splats, 5, 11);
        const SplatSampler sampler(splats, grid);
        for (double degrees : {3.0, 11.0, 45.0, 61.3, 79.0, 88.5}) {
            const double theta = degrees * kDegree;
            std::vector<double> images = {theta};
            if (theta < radius) images.push_back(-theta);
            if (theta > kPi / 2 - radius) images.push_back(kPi - theta);
            double direct = 0.0;
            for (std::size_t k = 0; k < splats->Size(); ++k) {
                const double w = splats->weights[k];  // one component
                for (double x : images) {
                    const double offset = std::abs(x - splats->geometry[k].thetaIn);
                    if (w > 0 && offset < radius)
                        direct += w * KernelOutMarginal(radius, norm, offset);
                }
            }
            SplatMixture mixture;
            sampler.Prepare(DirectionFromAngles(theta, 0.4), &mixture);
            EXPECT_NEAR(mixture.Total() / direct, 1.0, 2e-6)
                << "θ' = " << degrees << "°, norm " << int(norm);
        }
    }
}

// A .grd written with a baked table and read back: the sampler draws from the file's splats and
// evaluates its grid (the table is an interpolation, not the splat sum the pdf is exact for).
TEST(SplatSampler, GridFileChiSquareAndWhiteFurnace) {
    auto splats = test::SyntheticSplats("lambert:1", 20000, false, true, 0.3, Norm::kL2,
                                        Horizon::kReflect, 3);
    const BrdfGrid grid(splats, 4, 9);
    const BakedTable baked(grid, 8);
    const std::string path = test::TempPath("furnace.grd");
    WriteGrd(path, *splats, 4, 9, grid.Lists(), &baked);
    const GrdFile file = ReadGrd(path);
    CheckSampler(file.splats, *file.grid, 40, 0.5);
    // The furnace: a kd = 1 plane reflects all energy. The sampled estimator of its albedo,
    // f̄ cos θ / pdf = W cos θ, at 2·10⁵ samples has σ ≈ 1e-3; the splat estimate of 20000
    // photons itself lies within about 1% of 1 (reconstruction_test).
    const SplatSampler sampler(file.splats, *file.grid);
    SplatMixture mixture;
    sampler.Prepare(DirectionFromAngles(40 * kDegree, 0.5), &mixture);
    const test::Drawn drawn = test::Draw(sampler, mixture, 200000);
    EXPECT_NEAR(drawn.albedoSum / 200000, 1.0, 0.02);
}

}  // namespace
}  // namespace gonio
