// χ² tests of the photon distributions of the Lambert and Phong planes against the analytic ones.
#include "bin_grid.h"

namespace gonio {
namespace {

constexpr double kZ999 = 3.09;  // standard normal quantile of a 0.1% tail

// Pearson's χ² of photon counts in equal-probability bins.
double CountChiSquare(const std::vector<int>& counts, double expectedEach) {
    double chi2 = 0;
    for (int c : counts) chi2 += (c - expectedEach) * (c - expectedEach) / expectedEach;
    return chi2;
}

TEST(Distribution, LambertPlaneDirectionsChiSquare) {
    PhotonTraceSettings s;
    s.paths = 100000;
    s.seed = 3;
    const auto r = test::TraceRib(test::World("Surface \"matte\"\n" + test::Square(1)), s);
    ASSERT_EQ(r.stats.escapedUp, s.paths);
    // Equal-probability bins: sin²θ_out (cosine law) and cos θ_in (uniform on the hemisphere)
    // in 10 bands, φ in 8 sectors.
    std::vector<int> out(80, 0), in(80, 0);
    for (size_t i = 0; i < s.paths; ++i) {
        const float* row = r.rows.data() + i * test::Stride(r);
        const double sin2 = std::pow(std::sin(row[kThetaOut]), 2);
        out[std::min(9, int(sin2 * 10)) * 8 + std::min(7, int(row[kPhiOut] / (2 * kPi) * 8))]++;
        const double cosIn = std::cos(row[kThetaIn]);
        in[std::min(9, int((1 - cosIn) * 10)) * 8 +
           std::min(7, int(row[kPhiIn] / (2 * kPi) * 8))]++;
        ASSERT_FLOAT_EQ(row[kProbability], float(1 / (2 * kPi)));
    }
    const double limit = test::ChiSquareQuantile(79, kZ999);
    EXPECT_LT(CountChiSquare(out, s.paths / 80.0), limit);
    EXPECT_LT(CountChiSquare(in, s.paths / 80.0), limit);
}

// The energy of the Phong plane (ks = 1, n = 25) in 108 direction bins, for light from a band
// of θ′, against ∫∫ f cos θ of the normalised Phong lobe.
void CheckPhongPlane(double thetaDeg) {
    const double n = 25;
    PhotonTraceSettings s;
    s.paths = 100000;
    s.isotropic = true;
    s.thetaMin = float((thetaDeg - 1) * kDegree);
    s.thetaMax = float((thetaDeg + 1) * kDegree);
    const std::string body = "Surface \"metal\"\nAttribute \"brdflight\" \"float exponent\" 25\n";
    const auto r = test::TraceRib(test::World(body + test::Square(1)), s);
    const test::BinGrid grid;
    const auto measured = test::Bin(
        r, grid.Size(), [&](const float* row) { return grid.BinOf(row[kThetaOut], row[kPhiOut]); },
        [](const float* row) { return double(row[kFirstColour]); });
    const auto phong = [n](const Imath::V3d& wIn, const Imath::V3d& wOut) {
        const double cosAlpha = Imath::V3d(-wIn.x, -wIn.y, wIn.z).dot(wOut);
        return cosAlpha > 0 ? (n + 2) / (2 * kPi) * std::pow(cosAlpha, n) : 0.0;
    };
    const auto expected = test::ExpectedBinEnergy(grid, s.thetaMin, s.thetaMax, phong, 24);
    const test::ChiSquare chi = test::Compare(measured, expected, 1e-4);
    std::printf("Phong plane theta_in %.0f: chi2 %.1f over %d bins, worst |z| %.2f\n", thetaDeg,
                chi.value, chi.dof, chi.worstZ);
    EXPECT_GE(chi.dof, 8);
    EXPECT_LT(chi.value, test::ChiSquareQuantile(chi.dof, kZ999));
}

TEST(Distribution, PhongPlaneEnergyChiSquare) {
    CheckPhongPlane(30);
    CheckPhongPlane(70);
}

}  // namespace
}  // namespace gonio
