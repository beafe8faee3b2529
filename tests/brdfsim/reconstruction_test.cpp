// The estimator against analytic answers on synthetic photon maps (stratified, so that noise does
// not hide bias): a constant BRDF comes back without bias up to the horizon, energy is conserved
// at every incidence, the Phong lobe has the peak and width that kernel smoothing predicts, and
// reconstructions of reciprocal BRDFs are reciprocal. The 1M-photon runs of the issue are in
// validation_test.cpp.
#include <gtest/gtest.h>

#include <map>

#include "brdfsim/brdf_adaptive.h"
#include "brdfsim/brdf_grid.h"
#include "brdfsim/brdf_report.h"
#include "brdfsim/brdf_simple.h"
#include "test_util.h"

namespace gonio {
namespace {

const AnalyticBrdf kLambert = AnalyticBrdf::Parse("lambert:0.5");
const AnalyticBrdf kPhong = AnalyticBrdf::Parse("phong:0,1,25");

const BrdfIsoGrid& LambertIso(Horizon horizon) {
    static std::map<Horizon, std::unique_ptr<BrdfIsoGrid>> grids;
    auto& grid = grids[horizon];
    if (!grid) {
        grid = std::make_unique<BrdfIsoGrid>(
            test::SyntheticSplats("lambert:0.5", 200000, true, true, 0.5, Norm::kL2, horizon), 4,
            12);
    }
    return *grid;
}

// Phong n = 25, R = 0.15: the lobe is about as wide as the splats, so smoothing shows.
const BrdfIsoGrid& PhongIso() {
    static const BrdfIsoGrid grid(test::SyntheticSplats("phong:0,1,25", 300000, true, true, 0.15),
                                  10, 40);
    return grid;
}

TEST(Reconstruction, LambertIsotropicIsUnbiasedToTheHorizon) {
    const auto stats = test::CompareOnDenseSet(LambertIso(Horizon::kReflect), kLambert, 85, true);
    EXPECT_LT(std::abs(stats.meanRelative), 0.01);
    EXPECT_LT(stats.maxRelative, 0.05);  // 2.2% measured with 200k photons
}

TEST(Reconstruction, LambertAnisotropicIsUnbiased) {
    // 300k photons in 4D leave a noise of a few percent per point (the error falls as
    // N^(-1/2) R^(-2)); the mean shows the bias alone. 6.6% max measured; 1M: see validation_test.
    BrdfGrid grid(test::SyntheticSplats("lambert:0.5", 300000, false, true, 0.5), 4, 12);
    double sum = 0, worst = 0;
    int n = 0;
    float f[1];
    for (double ti : {0, 10, 20, 30, 40, 50, 60, 70, 80, 85}) {
        for (double to : {0, 10, 20, 30, 40, 50, 60, 70, 80, 85}) {
            for (int pi = 0; pi < 4; ++pi) {
                for (int po = 0; po < 8; ++po) {
                    grid.EvalAngles(ti * kDegree, pi * kPi / 2 + 0.3, to * kDegree,
                                    po * kPi / 4 + 0.1, f);
                    const double rel = f[0] / (0.5 / kPi) - 1;
                    sum += rel;
                    worst = std::max(worst, std::abs(rel));
                    ++n;
                }
            }
        }
    }
    EXPECT_LT(std::abs(sum / n), 0.01);
    EXPECT_LT(worst, 0.10);
}

double MeanErrorAtThetaOut(const Brdf& brdf, double thetaOutDeg) {
    double sum = 0;
    int n = 0;
    float f[1];
    for (double ti = 0; ti <= 85; ti += 5) {
        for (int po = 0; po < 8; ++po) {
            brdf.EvalAngles(ti * kDegree, 0, thetaOutDeg * kDegree, po * kPi / 4, f);
            sum += f[0] / (0.5 / kPi) - 1;
            ++n;
        }
    }
    return sum / n;
}

TEST(Reconstruction, ReflectionBeatsTheThesisRenormalisationAtTheHorizon) {
    // DESIGN.md: renormalising cut splats (thesis eqs. 4.9-4.10) conserves energy but biases f
    // near the horizon; reflection does not. Measured: -10% (85°) and -26% (89°) against <0.1%.
    for (double thetaOut : {85.0, 89.0}) {
        EXPECT_LT(std::abs(MeanErrorAtThetaOut(LambertIso(Horizon::kReflect), thetaOut)), 0.005);
        EXPECT_GT(std::abs(MeanErrorAtThetaOut(LambertIso(Horizon::kRenormalize), thetaOut)), 0.05);
    }
}

TEST(Reconstruction, EnergyMatchesThePhotonsAtEveryIncidence) {
    // ∫ f cos θ_out dω_out against the photons' own escaped energy at that incidence (smoothed
    // in θ_in by the same kernel), and against the analytic albedo where that is flat or the
    // smoothing small. The Phong albedo falls steeply towards grazing incidence, so at 80° the
    // reconstruction (like the photons) sees it smoothed over ±R: 1.6% above the analytic value.
    for (double ti : {0.0, 30.0, 60.0, 80.0}) {
        const Imath::V3f wIn = DirectionFromAngles(ti * kDegree, 0);
        const double lambert = Albedo(LambertIso(Horizon::kReflect), wIn, 32)[0];
        EXPECT_NEAR(lambert, 0.5, 0.005) << ti;
        EXPECT_NEAR(lambert / PhotonEnergyAt(LambertIso(Horizon::kReflect).Splats(), wIn)[0], 1.0,
                    0.01)
            << ti;
        const double phong = Albedo(PhongIso(), wIn, 48)[0];  // a sharp lobe needs more points
        EXPECT_NEAR(phong / PhotonEnergyAt(PhongIso().Splats(), wIn)[0], 1.0, 0.01) << ti;
        EXPECT_NEAR(phong / kPhong.Albedo(ti * kDegree), 1.0, ti < 70 ? 0.01 : 0.025) << ti;
    }
}

TEST(Reconstruction, PhongPeakAndWidthAsSmoothingPredicts) {
    // Normalised Phong cosⁿα ≈ exp(-α²/2σ²), σ² = 1/n. The 3D kernel has a per-axis variance
    // s² = 0.1041 R² (∫x⁴k / 3∫x²k over the unit ball). Smoothing the lobe, which is sharp along
    // θ_out - θ_in (variance σ²/2) and across the plane (σ²), scales the peak by
    // sqrt(σ²/2 / (σ²/2 + s²)) · sqrt(σ² / (σ² + s²)) and widens a θ_out cut to variance
    // σ² + 2s². Measured at 300k stratified photons, R = 0.15: peak within 1.6%, width within
    // 1.5%.
    const double n = 25, radius = 0.15;
    const double sigma2 = 1 / n, s2 = 0.1041 * radius * radius;
    const double peakFactor = std::sqrt(sigma2 / 2 / (sigma2 / 2 + s2) * sigma2 / (sigma2 + s2));
    const double analyticPeak = (n + 2) / (2 * kPi);
    const double analyticFwhm = 2 * std::acos(std::pow(0.5, 1 / n)) / kDegree;
    const double predictedFwhm = analyticFwhm * std::sqrt((sigma2 + 2 * s2) / sigma2);
    for (double ti : {0.0, 30.0, 60.0}) {
        const test::Lobe lobe = test::PlaneOfIncidenceLobe(PhongIso(), ti);
        std::printf(
            "Phong n=25, 300k, R 0.15, theta_in %2.0f: peak %.3f (predicted %.3f), "
            "FWHM %.2f deg (predicted %.2f)\n",
            ti, lobe.peak, analyticPeak * peakFactor, lobe.fwhm, predictedFwhm);
        EXPECT_NEAR(lobe.peakAt, ti, 1.0);
        EXPECT_NEAR(lobe.peak / (analyticPeak * peakFactor), 1.0, 0.03) << ti;
        EXPECT_NEAR(lobe.fwhm / predictedFwhm, 1.0, 0.04) << ti;
    }
}

TEST(Reconstruction, ReciprocalBrdfsReconstructReciprocally) {
    // Mean |f(a→b) − f(b→a)| / f over 400 pairs up to 80°: 2.6% measured (noise and the
    // asymmetry of smoothing θ_in linearly and ω on the sphere); a lobe that is not reciprocal,
    // the Phong lobe multiplied by cos θ_in, scores far higher.
    EXPECT_LT(ReciprocityError(PhongIso(), 400), 0.04);
    BrdfGrid lambert4d(test::SyntheticSplats("lambert:0.5", 100000, false, true, 0.5), 4, 12);
    EXPECT_LT(ReciprocityError(lambert4d, 400), 0.03);
}

TEST(Reconstruction, NonReciprocalLobeIsDetected) {
    // The metric itself: f·cos θ_in is not reciprocal and must score well above the bound above.
    class CosineWeighted : public Brdf {
      public:
        int NumComponents() const override { return 1; }
        bool IsIsotropic() const override { return true; }
        void Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const override {
            f[0] = static_cast<float>(
                kPhong.Eval(Imath::V3d(wIn.x, wIn.y, wIn.z), Imath::V3d(wOut.x, wOut.y, wOut.z)) *
                wIn.z);
        }
        std::size_t MemoryBytes() const override { return 0; }
    };
    EXPECT_GT(ReciprocityError(CosineWeighted(), 400), 0.10);
}

TEST(Reconstruction, AdaptiveRadiusFollowsThePhotonDensity) {
    // The k-nearest-photon radius is small where photons crowd (the Phong peak) and large where
    // they are sparse; at any point the estimate equals the fixed-radius one at the radius it
    // picked; and a constant BRDF comes back at 0.5/π (noise about 1/sqrt(k): 2.4% at k = 8000).
    auto phong = test::SyntheticSplats("phong:0,1,25", 50000, true, true, 0.15);
    const BrdfAdaptive lobe(phong, 100);
    const Imath::V3f light = DirectionFromAngles(30 * kDegree, kPi);
    const Imath::V3f mirror = DirectionFromAngles(30 * kDegree, 0);
    const double atPeak = lobe.RadiusAt(light, mirror);
    EXPECT_LT(atPeak, 0.5 * lobe.RadiusAt(light, DirectionFromAngles(60 * kDegree, kPi / 2)));
    SynthOptions options;
    options.paths = 50000;
    options.isotropic = true;
    options.stratified = true;
    options.ncomps = 1;
    options.seed = 11;
    SplatParams params;
    params.radius = atPeak;
    params.isotropic = true;
    const BrdfSimple fixed(std::make_shared<SplatSet>(
        SynthesizePhotonMap(AnalyticBrdf::Parse("phong:0,1,25"), options), params));
    float adaptive[1], reference[1];
    lobe.Eval(light, mirror, adaptive);
    fixed.Eval(light, mirror, reference);
    EXPECT_NEAR(adaptive[0], reference[0], 1e-4 * reference[0]);

    const BrdfAdaptive flat(test::SyntheticSplats("lambert:0.5", 50000, true, true, 0.3), 8000);
    float f[1];
    for (double ti : {0.0, 40.0, 85.0}) {
        for (double to : {0.0, 50.0, 85.0}) {
            flat.EvalAngles(ti * kDegree, 0, to * kDegree, 2.0, f);
            EXPECT_NEAR(f[0] / (0.5 / kPi), 1.0, 0.04) << ti << " " << to;
        }
    }
}

}  // namespace
}  // namespace gonio
