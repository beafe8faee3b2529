// The leaf optics of renderer/photon/leaf_optics.h (issue 18 item 2): the cuticle's albedo
// table, energy (r + t + a = 1 at every incidence), the white furnace (ρ + τ = 1 gives
// r + t = 1), reciprocity, χ² of the sampler against the pdf it reports, and, through the
// tracer, a thin sheet that sends t of the flux down.
#include "renderer/photon/leaf_optics.h"

#include <algorithm>

#include "base/random.h"
#include "bin_grid.h"
#include "renderer/photon/micro_brdf.h"

namespace gonio {
namespace {

using Imath::V3f;

constexpr double kZ999 = 3.09;  // standard normal quantile of a 0.1% tail
const V3f kUp(0, 0, 1);

V3f Dir(double theta, double phi) { return V3f(test::Direction(theta, phi)); }

// ∫ g(ω) dω over the sphere (side > 0: the upper hemisphere, < 0 the lower) by the midpoint
// rule on m × 2m (θ, φ) cells; g's peaks are a few degrees wide at the roughness used here.
double Hemisphere(const std::function<double(const V3f&)>& g, int side, int m = 600) {
    double sum = 0;
    const double dTheta = kPi / 2 / m, dPhi = kPi / m;
    for (int i = 0; i < m; ++i) {
        const double theta = (i + 0.5) * dTheta;
        for (int j = 0; j < 2 * m; ++j) {
            V3f w = Dir(theta, (j + 0.5) * dPhi);
            if (side < 0) w.z = -w.z;
            sum += g(w) * std::sin(theta);
        }
    }
    return sum * dTheta * dPhi;
}

LeafParams Leaf(float eta, float roughness, float rho, float tau) {
    LeafParams p;
    p.eta = eta;
    p.roughness = roughness;
    p.reflectance = {rho};
    p.transmittance = {tau};
    return p;
}

double F(const LeafOptics& leaf, const LeafOptics::Value& v) {
    return v.specular + v.diffuse * (v.transmitted ? leaf.Transmittance(0) : leaf.Reflectance(0));
}

// The table's E(μ) against an independent quadrature of the cuticle lobe in (θ, φ): the
// interpolation between its 65 nodes and its own rule stay within 1e-3.
TEST(LeafOptics, CuticleAlbedoTableMatchesQuadrature) {
    for (float alpha : {0.1f, 0.3f, 0.8f}) {
        const LeafOptics leaf(Leaf(1.5f, alpha, 0.5f, 0.3f));
        for (double thetaDeg : {0.0, 31.0, 55.0, 73.0, 85.0}) {
            const V3f wi = Dir(thetaDeg * kDegree, 0);
            const double e =
                Hemisphere([&](const V3f& wo) { return leaf.CuticleLobe(wi, wo) * wo.z; }, 1);
            std::printf("alpha %.1f theta_in %2.0f: E table %.5f, quadrature %.5f\n", alpha,
                        thetaDeg, leaf.CuticleAlbedo(wi.z), e);
            EXPECT_NEAR(leaf.CuticleAlbedo(wi.z), e, 1e-3);
        }
    }
    // η = 1: no cuticle, no reflection off it
    EXPECT_EQ(LeafOptics(Leaf(1, 0.3f, 0.5f, 0.3f)).CuticleAlbedo(0.5f), 0.0f);
}

// r and t by quadrature of f over the two hemispheres, against the model's closed forms, and
// r + t + a = 1 with a = (1 − E)(1 − ρ − τ), the interior's absorption.
TEST(LeafOptics, EnergyAtEveryIncidence) {
    const float rho = 0.45f, tau = 0.35f;
    const LeafOptics leaf(Leaf(1.45f, 0.3f, rho, tau));
    for (double thetaDeg = 0; thetaDeg <= 88; thetaDeg += 11) {
        const V3f wi = Dir(thetaDeg * kDegree, 0);
        auto cosWeighted = [&](const V3f& wo) {
            return F(leaf, leaf.Evaluate(kUp, wi, wo)) * std::abs(wo.z);
        };
        const double r = Hemisphere(cosWeighted, 1), t = Hemisphere(cosWeighted, -1);
        const double e = leaf.CuticleAlbedo(wi.z);
        const double a = (1 - e) * (1 - rho - tau);
        std::printf("theta_in %2.0f: r %.4f t %.4f a %.4f, r+t+a %.5f\n", thetaDeg, r, t, a,
                    r + t + a);
        EXPECT_NEAR(t, (1 - e) * tau, 1e-3);
        EXPECT_NEAR(r, e + (1 - e) * rho, 2e-3);
        EXPECT_NEAR(r + t + a, 1.0, 2e-3);
    }
}

// Mean sampled weight f|cos|/pdf per side, against the quadrature of the same f: the sampler
// and Evaluate agree on f and the pdf is normalised. With ρ + τ = 1 nothing is absorbed.
TEST(LeafOptics, WhiteFurnaceSampledWeights) {
    const LeafOptics leaf(Leaf(1.5f, 0.25f, 0.6f, 0.4f));
    constexpr int kSamples = 200000;
    for (double thetaDeg : {0.0, 40.0, 70.0, 86.0}) {
        const V3f wi = Dir(thetaDeg * kDegree, 0.3);
        double sum[2] = {0, 0}, sum2[2] = {0, 0};
        SampleRandom random(11, int(uint64_t(thetaDeg)), 0, 0);
        for (int i = 0; i < kSamples; ++i) {
            const auto s = leaf.Sample(kUp, wi, random.Next(), random.Next(), random.Next());
            ASSERT_GT(s.value.pdf, 0);
            const double w = F(leaf, s.value) * std::abs(s.wo.z) / s.value.pdf;
            const LeafOptics::Value again = leaf.Evaluate(kUp, wi, s.wo);
            ASSERT_NEAR(again.pdf, s.value.pdf, 1e-5 * s.value.pdf);
            sum[s.value.transmitted] += w;
            sum2[s.value.transmitted] += w * w;
        }
        const double e = leaf.CuticleAlbedo(wi.z);
        for (int side = 0; side < 2; ++side) {
            const double mean = sum[side] / kSamples;
            const double sigma = std::sqrt((sum2[side] / kSamples - mean * mean) / kSamples);
            const double expected = side ? (1 - e) * 0.4 : e + (1 - e) * 0.6;
            std::printf("theta_in %2.0f side %d: sampled %.5f +- %.5f, expected %.5f\n", thetaDeg,
                        side, mean, sigma, expected);
            // 4σ of noise plus the 2e-3 of the albedo table
            EXPECT_NEAR(mean, expected, 4 * sigma + 2e-3);
        }
        EXPECT_NEAR((sum[0] + sum[1]) / kSamples, 1.0,
                    4 * std::sqrt((sum2[0] + sum2[1]) / kSamples / kSamples) + 2e-3);
    }
}

// f(ωi → ωo) = f(ωo → ωi) for reflection, and for transmission with the light on the far side.
TEST(LeafOptics, Reciprocity) {
    const LeafOptics leaf(Leaf(1.45f, 0.3f, 0.4f, 0.3f));
    SampleRandom random(5, int(0), 0, 0);
    for (int i = 0; i < 2000; ++i) {
        const V3f a = Dir(std::acos(random.Next()), 2 * kPi * random.Next());
        V3f b = Dir(std::acos(random.Next()), 2 * kPi * random.Next());
        const double f = F(leaf, leaf.Evaluate(kUp, a, b));
        EXPECT_NEAR(F(leaf, leaf.Evaluate(kUp, b, a)), f, 1e-4 * f + 1e-7);
        b.z = -b.z;
        const double ft = F(leaf, leaf.Evaluate(kUp, a, b));
        EXPECT_NEAR(F(leaf, leaf.Evaluate(-kUp, b, a)), ft, 1e-4 * ft + 1e-7);
    }
}

// Pearson's χ² of sampled directions in 18 θ bands (the whole sphere) × 12 φ sectors against
// the pdf Evaluate reports, integrated over each bin; the pdf's total is 1.
void CheckSamplingChiSquare(const V3f& n, double thetaDeg, float alpha) {
    const LeafOptics leaf(Leaf(1.5f, alpha, 0.3f, 0.2f));
    // the light at θ_in from n, in n's frame
    V3f t, s;
    OrthonormalBasis(n, &t, &s);
    const V3f local = Dir(thetaDeg * kDegree, 0);
    const V3f wi = local.x * t + local.y * s + local.z * n;
    constexpr int kBands = 18, kSectors = 12, kSamples = 200000;
    auto binOf = [&](const V3f& w) {
        const double theta = std::acos(std::clamp(double(w.dot(n)), -1.0, 1.0));
        double phi = std::atan2(double(w.dot(s)), double(w.dot(t)));
        if (phi < 0) phi += 2 * kPi;
        return std::min(kBands - 1, int(theta / kPi * kBands)) * kSectors +
               std::min(kSectors - 1, int(phi / (2 * kPi) * kSectors));
    };
    std::vector<double> expected(kBands * kSectors, 0.0);
    constexpr int m = 40;  // per bin and axis
    for (int b = 0; b < kBands * kSectors; ++b) {
        const int band = b / kSectors, sector = b % kSectors;
        for (int i = 0; i < m; ++i) {
            const double theta = (band + (i + 0.5) / m) * kPi / kBands;
            for (int j = 0; j < m; ++j) {
                const double phi = (sector + (j + 0.5) / m) * 2 * kPi / kSectors;
                const V3f l = Dir(theta, phi);
                const V3f w = l.x * t + l.y * s + l.z * n;
                expected[b] += leaf.Evaluate(n, wi, w).pdf * std::sin(theta);
            }
        }
        expected[b] *= (kPi / kBands / m) * (2 * kPi / kSectors / m) * kSamples;
    }
    const double total = std::accumulate(expected.begin(), expected.end(), 0.0) / kSamples;
    EXPECT_NEAR(total, 1.0, 2e-3);
    std::vector<int> counts(expected.size(), 0);
    SampleRandom random(7, int(uint64_t(thetaDeg * 100 + alpha * 10)), 0, 0);
    for (int i = 0; i < kSamples; ++i)
        counts[binOf(leaf.Sample(n, wi, random.Next(), random.Next(), random.Next()).wo)]++;
    // Pearson over the bins expecting at least 20 samples; the rest pooled into one.
    double chi2 = 0, restCount = 0, restExpected = 0;
    int dof = 0;
    for (size_t b = 0; b < expected.size(); ++b) {
        if (expected[b] < 20) {
            restCount += counts[b];
            restExpected += expected[b];
            continue;
        }
        chi2 += (counts[b] - expected[b]) * (counts[b] - expected[b]) / expected[b];
        ++dof;
    }
    if (restExpected >= 20) {
        chi2 += (restCount - restExpected) * (restCount - restExpected) / restExpected;
        ++dof;
    }
    std::printf("sampling theta_in %.0f alpha %.2f: chi2 %.1f over %d bins\n", thetaDeg, alpha,
                chi2, dof);
    EXPECT_GT(dof, 100);
    EXPECT_LT(chi2, test::ChiSquareQuantile(dof - 1, kZ999));
}

TEST(LeafOptics, SamplingChiSquare) {
    CheckSamplingChiSquare(kUp, 20, 0.3f);
    CheckSamplingChiSquare(V3f(0.3f, -0.5f, 0.81f).normalized(), 65, 0.15f);
    CheckSamplingChiSquare(V3f(0, 0, -1), 80, 0.5f);
}

// Through the tracer: a horizontal leaf sheet lit from θ′ ≈ 30° reflects r up and sends t down
// (escaping below it), each path hitting it once; over a black ground the transmitted light is
// absorbed there and r still comes up.
TEST(LeafOptics, ThinSheetSendsTransmittanceDown) {
    const std::string leaf =
        "Attribute \"brdflight\" \"string model\" \"leaf\" \"float eta\" 1.45 "
        "\"float roughness\" 0.3 \"color reflectance\" [0.4 0.1 0.05] "
        "\"color transmittance\" [0.3 0.2 0]\n";
    PhotonTraceSettings s;
    s.paths = 400000;
    s.thetaMin = float(29 * kDegree);
    s.thetaMax = float(31 * kDegree);
    const auto open = test::TraceRib(test::World(leaf + test::Square(1)), s);
    const auto overBlack =
        test::TraceRib(test::World(leaf + test::Square(1) + "Surface \"matte\" \"Kd\" 0\n" +
                                   "Attribute \"brdflight\" \"string model\" \"phong\"\n" +
                                   test::Square(20, -0.5)),
                       s);
    EXPECT_EQ(open.stats.bounces, s.paths);
    EXPECT_EQ(open.stats.escapedUp + open.stats.escapedDown, s.paths);
    const LeafOptics optics(LeafParams{1.45f, 0.3f, {0.4f, 0.1f, 0.05f}, {0.3f, 0.2f, 0.0f}});
    // r and t averaged over the incidence band (cos θ′ uniform), 8-point Gauss in cos θ′
    const double c0 = std::cos(s.thetaMax), c1 = std::cos(s.thetaMin);
    for (int k = 0; k < 3; ++k) {
        double r = 0, t = 0;
        for (int g = 0; g < 8; ++g) {
            const double mu = 0.5 * (c0 + c1) + 0.5 * (c1 - c0) * test::kGaussX[g];
            const double e = optics.CuticleAlbedo(float(mu));
            r += 0.5 * test::kGaussW[g] * (e + (1 - e) * optics.Reflectance(k));
            t += 0.5 * test::kGaussW[g] * (1 - e) * optics.Transmittance(k);
        }
        // One photon's weight is at most 1/(1 − Ē) ≈ 1.1 (a diffuse sample) or 1 (a cuticle
        // sample), so σ ≤ 1.1/√N = 0.0017 at N = 400,000: 4σ is 0.007.
        const double up = open.stats.energyUp[k] / s.paths,
                     down = open.stats.energyDown[k] / s.paths;
        const double upBlack = overBlack.stats.energyUp[k] / s.paths;
        std::printf("sheet component %d: up %.4f (r %.4f), down %.4f (t %.4f), over black %.4f\n",
                    k, up, r, down, t, upBlack);
        EXPECT_NEAR(up, r, 0.007);
        EXPECT_NEAR(down, t, 0.007);
        EXPECT_NEAR(upBlack, r, 0.007);
        EXPECT_LT(overBlack.stats.energyDown[k] / s.paths, 1e-3);
    }
}

}  // namespace
}  // namespace gonio
