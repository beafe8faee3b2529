// Spectra: resampling, the Catmull-Rom curve (interpolating, clamped at 0, equal to the thesis's
// corrected uniform matrix on even knots) and Planck's law (Wien's law, the Planckian locus).
#include "spectral/spectrum.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "spectral/catmull_rom.h"
#include "spectral/colorimetry.h"
#include "spectral/named_spectra.h"
#include "spectral/spectral_error.h"

namespace gonio::spectral {
namespace {

TEST(Spectrum, LinearResamplingOntoARunTimeGrid) {
    const Spectrum s = Spectrum::Regular(400, 10, {0, 10, 40});
    const std::vector<double> v = s.Sample(WavelengthGrid::Make(400, 420, 2.5));
    ASSERT_EQ(v.size(), 9u);
    EXPECT_DOUBLE_EQ(v[0], 0);
    EXPECT_DOUBLE_EQ(v[2], 5);
    EXPECT_DOUBLE_EQ(v[4], 10);
    EXPECT_DOUBLE_EQ(v[6], 25);
    EXPECT_DOUBLE_EQ(v[8], 40);
}

TEST(Spectrum, ArbitraryKnots) {
    const Spectrum s({400, 401, 450}, {1, 2, 3});
    EXPECT_FALSE(s.IsRegular());
    EXPECT_DOUBLE_EQ(s.Evaluate(425.5), 2.5);
}

TEST(Spectrum, RefusesARangeItDoesNotCover) {
    const Spectrum s = Spectrum::Regular(400, 10, {1, 2, 3});
    try {
        s.Sample(ReferenceGrid());
        FAIL() << "no error";
    } catch (const SpectralError& e) {
        EXPECT_NE(std::string(e.what()).find("400-420 nm"), std::string::npos) << e.what();
    }
    EXPECT_THROW(WavelengthGrid::Make(380, 781, 5), SpectralError);
    EXPECT_THROW(WavelengthGrid::Make(380, 780, 0), SpectralError);
    EXPECT_THROW(Spectrum({400, 400}, {1, 2}), SpectralError);
}

TEST(CatmullRom, InterpolatesItsControlPoints) {
    const std::vector<double> t{400, 430, 500, 520, 700}, p{0.5, 0.9, 0.1, 0.7, 0.5};
    Spectrum s(t, p, Interpolation::CatmullRom);
    for (size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(s.Evaluate(t[i]), p[i], 1e-12);
}

TEST(CatmullRom, EvenKnotsMatchTheThesisMatrixCorrected) {
    // Thesis §6.2.2 with the third row -1 0 1 0, phantom points duplicating the ends.
    const std::vector<double> p{0.2, 0.8, 0.3, 0.6, 0.4};
    const Spectrum s = Spectrum::Regular(400, 50, p, Interpolation::CatmullRom);
    auto at = [&](int i) { return p[std::clamp(i, 0, int(p.size()) - 1)]; };
    for (int seg = 0; seg + 1 < int(p.size()); ++seg)
        for (double u : {0.0, 0.25, 0.5, 0.8, 1.0}) {
            const double uniform =
                UniformCatmullRom(at(seg - 1), at(seg), at(seg + 1), at(seg + 2), u);
            EXPECT_NEAR(s.Evaluate(400 + 50 * (seg + u)), uniform, 1e-12);
        }
    // The misprinted row (-1 0 1 1) would not interpolate P_{i-2} at s = 0: ours does.
    EXPECT_DOUBLE_EQ(UniformCatmullRom(1, 2, 3, 4, 0), 2);
    EXPECT_DOUBLE_EQ(UniformCatmullRom(1, 2, 3, 4, 1), 3);
}

TEST(CatmullRom, IsClampedAtZero) {
    // A sharp drop to 0 overshoots below zero between the knots; the SPD must not.
    const std::vector<double> t{400, 450, 500, 550, 600}, p{1, 1, 0, 0, 1};
    const Spectrum s(t, p, Interpolation::CatmullRom);
    double lowestRaw = 0;
    for (double nm = 400; nm <= 600; nm += 0.5) {
        EXPECT_GE(s.Evaluate(nm), 0) << nm;
        lowestRaw = std::min(lowestRaw, CatmullRomHermite(t, p, p.front(), p.back(), nm));
    }
    EXPECT_LT(lowestRaw, -0.01) << "the test curve should overshoot";
    EXPECT_GT(s.Evaluate(525, Resampling::Linear), -1e-12);
}

TEST(Blackbody, WiensDisplacementLaw) {
    // λ_max T = b, b = 2.897771955e-3 m·K (CODATA 2018).
    for (double kelvin : {3000.0, 5000.0, 6504.0}) {
        double best = 0, bestNm = 0;
        for (double nm = 200; nm <= 1500; nm += 0.01) {
            const double v = PlanckRadiance(nm, kelvin);
            if (v > best) best = v, bestNm = nm;
        }
        EXPECT_NEAR(bestNm * kelvin, 2.897771955e6, 0.02 * kelvin) << kelvin;
    }
}

TEST(Blackbody, PlanckianLocusAt6504K) {
    // CIE 1931 Planckian locus at 6504 K: (0.3135, 0.3236).
    const Eigen::Vector2d xy = Chromaticity(
        EmissiveXyz(Blackbody(6504), SampleObserver(NamedObserver("CIE1931"), ReferenceGrid())));
    EXPECT_NEAR(xy.x(), 0.3135, 0.002);
    EXPECT_NEAR(xy.y(), 0.3236, 0.002);
    std::printf("blackbody 6504 K: x %.5f y %.5f\n", xy.x(), xy.y());
}

}  // namespace
}  // namespace gonio::spectral
