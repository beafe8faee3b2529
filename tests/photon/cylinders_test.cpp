// The tracer on curved micro geometry against an exact answer: brushed metal with a diffuse micro
// BRDF, single scattering (maxdepth 1), lit across the cylinders, binned energy against the
// parallel-cylinder BRDF of Poulin & Fournier (parallel_cylinders.h) at several incidences.
#include <regex>

#include "bin_grid.h"
#include "parallel_cylinders.h"

namespace gonio {
namespace {

void CheckCylinders(const std::string& rib, double thetaMinDeg, double thetaMaxDeg) {
    PhotonTraceSettings s;
    s.paths = 100000;
    s.isotropic = true;  // φ′ = 0: the light in the xz plane, across the cylinders
    s.maxDepth = 1;
    s.thetaMin = float(thetaMinDeg * kDegree);
    s.thetaMax = float(thetaMaxDeg * kDegree);
    const auto r = test::TraceRib(rib, s);
    const test::BinGrid grid;
    const auto measured = test::Bin(
        r, grid.Size(), [&](const float* row) { return grid.BinOf(row[kThetaOut], row[kPhiOut]); },
        [](const float* row) { return double(row[kFirstColour]); });
    const auto brdf = [](const Imath::V3d& wIn, const Imath::V3d& wOut) {
        return test::CylinderRowBrdf(wIn, wOut, 1.0, 240);
    };
    const auto expected = test::ExpectedBinEnergy(grid, s.thetaMin, s.thetaMax, brdf, 6);
    const test::ChiSquare chi = test::Compare(measured, expected, 2e-4);
    double total = 0, expectedTotal = 0;
    for (int b = 0; b < grid.Size(); ++b) total += measured.mean[b], expectedTotal += expected[b];
    std::printf(
        "cylinders theta_in %.0f-%.0f: single-scattered energy %.4f (exact %.4f), chi2 "
        "%.1f over %d bins, worst |z| %.2f\n",
        thetaMinDeg, thetaMaxDeg, total, expectedTotal, chi.value, chi.dof, chi.worstZ);
    EXPECT_NEAR(total / expectedTotal, 1.0, 0.01);
    EXPECT_GE(chi.dof, 30);
    EXPECT_LT(chi.value, test::ChiSquareQuantile(chi.dof, 3.09));
}

TEST(ParallelCylinders, DiffuseSingleScatteringMatchesPoulinFournier) {
    std::string rib = test::ReadRib("brushed_metal.rib");
    rib = std::regex_replace(rib, std::regex("\"float kd\" 0 \"float ks\" 1"),
                             "\"float kd\" 1 \"float ks\" 0");
    ASSERT_NE(rib.find("\"float kd\" 1 \"float ks\" 0"), std::string::npos);
    CheckCylinders(rib, 0, 4);
    CheckCylinders(rib, 29, 31);
    CheckCylinders(rib, 59, 61);
    CheckCylinders(rib, 74, 76);
}

}  // namespace
}  // namespace gonio
