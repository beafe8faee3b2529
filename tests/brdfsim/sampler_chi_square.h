#pragma once
// χ² goodness of fit of a SplatSampler's directions against its pdf, as pbrt's and Mitsuba's
// BSDF tests do it, with the other checks of one sampler at one incoming direction
// (CheckSampler): shared by the brdfsim tests (synthetic maps) and the photon tests (maps the
// BRDFLight tracer writes).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "base/hash.h"
#include "base/math.h"
#include "brdfsim/brdf.h"
#include "brdfsim/splat_sampler.h"

namespace gonio::test {

// Upper regularised incomplete gamma Q(s, x) (Numerical Recipes §6.2: series below s + 1, Lentz's
// continued fraction above): the χ² survival function is Q(dof / 2, χ² / 2).
inline double GammaQ(double s, double x) {
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

// Bins over the upper hemisphere: equal steps of cos θ and of φ (equal solid angles).
constexpr int kCosBins = 10, kPhiBins = 20;
constexpr double kSignificance = 0.01;  // for all the χ² tests of one executable together

inline int BinOf(const Imath::V3f& w) {
    const int i = std::min(kCosBins - 1, static_cast<int>(w.z * kCosBins));
    double phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * kPi;
    const int j = std::min(kPhiBins - 1, static_cast<int>(phi / (2 * kPi) * kPhiBins));
    return i * kPhiBins + j;
}

// ∫ pdf dω over each bin, by a 16 × 16 midpoint rule in (cos θ, φ) (dω = d cos θ dφ).
inline std::vector<double> IntegratedPdf(const SplatSampler& sampler, const SplatMixture& mixture) {
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

inline Drawn Draw(const SplatSampler& sampler, const SplatMixture& mixture, int samples) {
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
inline double ChiSquarePValue(const std::vector<double>& observed,
                              const std::vector<double>& expected) {
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
// `tests`: how many χ² tests the executable runs, which share the significance (Bonferroni).
inline void CheckSampler(const std::shared_ptr<const SplatSet>& splats, const Brdf& exact,
                         double thetaInDeg, double phiIn, int tests) {
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
    const double threshold = 1 - std::pow(1 - kSignificance, 1.0 / tests);
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

}  // namespace gonio::test
