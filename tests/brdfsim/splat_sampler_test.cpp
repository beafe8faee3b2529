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
#include "test_util.h"

namespace gonio {
namespace {

// Upper regularised incomplete gamma Q(s, x) (Numerical Recipes §6.2: series below s + 1, Lentz's
// continued fraction above): the χ² survival function is Q(dof / 2, χ² / 2).
double GammaQ(double s, double x) {
    if (x <= 0) return 1.0;
    const double logPrefix = -x + s * std::log(x) - std::lgamma(s);
    if (x < s + 1) {
        double term = 1.0 / s, sum = term;
        for (int n = 1; n < 10000 && std::abs(term) > 1e-16 * std::abs(sum); ++n) {
            term *= x / (s + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(logPrefix);
    }
    const double tiny = 1e-300;
    double b = x + 1 - s, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - s);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-16) break;
    }
    return std::exp(logPrefix) * h;
}

TEST(GammaQ, KnownChiSquareQuantiles) {
    // χ² quantiles at p = 0.05: 3.841 (1 dof), 18.307 (10 dof), 124.342 (100 dof).
    EXPECT_NEAR(GammaQ(0.5, 3.841459 / 2), 0.05, 1e-6);
    EXPECT_NEAR(GammaQ(5.0, 18.307038 / 2), 0.05, 1e-6);
    EXPECT_NEAR(GammaQ(50.0, 124.342113 / 2), 0.05, 1e-6);
}

// Bins over the upper hemisphere: equal steps of cos θ and of φ (equal solid angles).
constexpr int kCosBins = 10, kPhiBins = 20;
// Every χ² test of this file counts against one significance level (Bonferroni).
constexpr int kTests = 9;
constexpr double kSignificance = 0.01;

int BinOf(const Imath::V3f& w) {
    const int i = std::min(kCosBins - 1, static_cast<int>(w.z * kCosBins));
    double phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * kPi;
    const int j = std::min(kPhiBins - 1, static_cast<int>(phi / (2 * kPi) * kPhiBins));
    return i * kPhiBins + j;
}

// ∫ pdf dω over each bin, by a 16 × 16 midpoint rule in (cos θ, φ) (dω = d cos θ dφ).
std::vector<double> IntegratedPdf(const SplatSampler& sampler, const SplatMixture& mixture) {
    constexpr int kSub = 16;
    std::vector<double> mass(kCosBins * kPhiBins, 0.0);
    const double du = 1.0 / (kCosBins * kSub), dphi = 2 * kPi / (kPhiBins * kSub);
    for (int i = 0; i < kCosBins * kSub; ++i) {
        const double z = (i + 0.5) * du, r = std::sqrt(1 - z * z);
        for (int j = 0; j < kPhiBins * kSub; ++j) {
            const double phi = (j + 0.5) * dphi;
            const Imath::V3f w(r * std::cos(phi), r * std::sin(phi), z);
            mass[(i / kSub) * kPhiBins + j / kSub] += sampler.Pdf(mixture, w) * du * dphi;
        }
    }
    return mass;
}

struct Drawn {
    std::vector<double> counts;
    int failed = 0;
    double albedoSum = 0, albedoSum2 = 0;  // f̄ cos θ / pdf, failures count 0
};

Drawn Draw(const SplatSampler& sampler, const SplatMixture& mixture, int samples) {
    Drawn drawn;
    drawn.counts.assign(kCosBins * kPhiBins, 0.0);
    uint64_t state = 99;
    std::vector<float> f(sampler.Exact().NumComponents());
    for (int n = 0; n < samples; ++n) {
        const float u = ToUnitFloat(SplitMix64(state));
        Imath::V3f w;
        if (!sampler.Sample(mixture, u, SplitMix64(state), &w)) {
            ++drawn.failed;
            continue;
        }
        const double pdf = sampler.Pdf(mixture, w, f.data());
        if (!(w.z > 0) || std::abs(w.length() - 1) > 1e-5f || !(pdf > 0)) {
            ADD_FAILURE() << "a sampled direction must be unit, above the surface, with a "
                             "positive pdf: ("
                          << w.x << ", " << w.y << ", " << w.z << "), pdf " << pdf;
            return drawn;
        }
        drawn.counts[BinOf(w)] += 1;
        double mean = 0;
        for (float v : f) mean += v;
        const double x = mean / f.size() * w.z / pdf;
        drawn.albedoSum += x;
        drawn.albedoSum2 += x * x;
    }
    return drawn;
}

// pbrt's test: bins expected to hold fewer than 5 samples are pooled; a sample in a bin of zero
// expectation fails at once.
double ChiSquarePValue(const std::vector<double>& observed, const std::vector<double>& expected) {
    double chi2 = 0, pooledObserved = 0, pooledExpected = 0;
    int dof = -1;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] == 0) {
            if (observed[i] > 0) return 0.0;
            continue;
        }
        if (expected[i] < 5) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++dof;
    }
    if (pooledExpected > 0) {
        chi2 +=
            (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++dof;
    }
    return dof > 0 ? GammaQ(0.5 * dof, 0.5 * chi2) : 1.0;
}

// The sampled directions against the integrated pdf, the pdf's total against the fraction of
// successful samples, and the sampled albedo against the evaluated one.
void CheckSampler(const std::shared_ptr<const SplatSet>& splats, const Brdf& exact,
                  double thetaInDeg, double phiIn) {
    const SplatSampler sampler(splats, exact);
    SplatMixture mixture;
    const Imath::V3f wIn = DirectionFromAngles(thetaInDeg * kDegree, phiIn);
    sampler.Prepare(wIn, &mixture);
    ASSERT_GT(mixture.Total(), 0.0);
    constexpr int kSamples = 200000;
    const Drawn drawn = Draw(sampler, mixture, kSamples);
    const std::vector<double> mass = IntegratedPdf(sampler, mixture);
    std::vector<double> expected(mass.size());
    double totalMass = 0;
    for (std::size_t i = 0; i < mass.size(); ++i) {
        expected[i] = mass[i] * kSamples;
        totalMass += mass[i];
    }
    const double threshold = 1 - std::pow(1 - kSignificance, 1.0 / kTests);
    const double p = ChiSquarePValue(drawn.counts, expected);
    EXPECT_GT(p, threshold) << "χ² rejects the sampled directions at θ_in " << thetaInDeg;
    // With reflection the pdf is a density on the hemisphere (∫ = 1); without it, samples below
    // the horizon fail, and the pdf's integral is the fraction that succeed (binomial noise).
    const double success = 1.0 - double(drawn.failed) / kSamples;
    if (splats->Params().horizon == Horizon::kReflect) {
        EXPECT_EQ(drawn.failed, 0);
        EXPECT_NEAR(totalMass, 1.0, 2e-3);  // the midpoint rule, not noise
    } else {
        const double sigma = std::sqrt(success * (1 - success) / kSamples);
        EXPECT_NEAR(totalMass, success, 4 * sigma + 2e-3);
    }
    // E[f̄ cos θ / pdf] = ∫ f̄ cos θ dω: the estimator's own standard error, 4σ, plus the 96-step
    // midpoint rule's error (~1e-3 on these smooth lobes).
    const double mean = drawn.albedoSum / kSamples;
    const double sigma = std::sqrt((drawn.albedoSum2 / kSamples - mean * mean) / kSamples);
    double evaluated = 0;
    for (double a : Albedo(exact, wIn, 96)) evaluated += a;
    evaluated /= exact.NumComponents();
    EXPECT_NEAR(mean, evaluated, 4 * sigma + 1e-3 * evaluated)
        << "sampled albedo " << mean << " ± " << sigma << ", evaluated " << evaluated;
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
    const Drawn drawn = Draw(sampler, mixture, 200000);
    EXPECT_NEAR(drawn.albedoSum / 200000, 1.0, 0.02);
}

}  // namespace
}  // namespace gonio
