// The hemisphere subdivision and the splat grids: exact cell distances, grids equal to summing
// every splat, and the thesis's Table 4.1 (splats per cell) reproduced as a report.
#include <gtest/gtest.h>

#include <random>

#include "brdfsim/brdf_grid.h"
#include "brdfsim/brdf_report.h"
#include "brdfsim/brdf_simple.h"
#include "brdfsim/hemisphere_grid.h"
#include "test_util.h"

namespace gonio {
namespace {

TEST(HemisphereGrid, CellsPerBandFollowEquation414) {
    // thesis eq. 4.14 with 4 bands and n_max = 5 gives 2, 4, 5, 5 (the thesis's text says
    // 2, 4, 4, 5 for its figure 4.3; round(5 sin 67.5°) = round(4.62) = 5).
    const HemisphereGrid grid(4, 5);
    EXPECT_EQ(grid.RectsInBand(0), 2);
    EXPECT_EQ(grid.RectsInBand(1), 4);
    EXPECT_EQ(grid.RectsInBand(2), 5);
    EXPECT_EQ(grid.RectsInBand(3), 5);
    EXPECT_EQ(grid.NumCells(), 16);
    EXPECT_EQ(HemisphereGrid(5, 1).NumCells(), 5);  // at least one cell per band
}

TEST(HemisphereGrid, CellOfFindsBandAndRect) {
    const HemisphereGrid grid(4, 5);
    EXPECT_EQ(grid.CellOf(DirectionFromAngles(10 * kDegree, 10 * kDegree)), 0);
    EXPECT_EQ(grid.CellOf(DirectionFromAngles(10 * kDegree, 190 * kDegree)), 1);
    EXPECT_EQ(grid.CellOf(DirectionFromAngles(30 * kDegree, 100 * kDegree)), 2 + 1);
    EXPECT_EQ(grid.CellOf(DirectionFromAngles(89 * kDegree, 359 * kDegree)), 15);
}

TEST(HemisphereGrid, DistanceToCellIsTheExactMinimum) {
    const HemisphereGrid grid(5, 9);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 300; ++trial) {
        const double thetaC = std::acos(1 - 2 * u(rng));  // anywhere, mirror images included
        const double phiC = 2 * kPi * u(rng);
        const Imath::V3d c(std::sin(thetaC) * std::cos(phiC), std::sin(thetaC) * std::sin(phiC),
                           std::cos(thetaC));
        const int cell = static_cast<int>(u(rng) * grid.NumCells());
        const double d = grid.DistanceToCell(cell, thetaC, phiC);
        // Brute force: the nearest of many points of the cell (found through CellOf).
        double brute = 10;
        for (int i = 0; i <= 200; ++i) {
            for (int j = 0; j <= 400; ++j) {
                const Imath::V3f p = DirectionFromAngles(0.5 * kPi * i / 200, 2 * kPi * j / 400);
                if (grid.CellOf(p) != cell) continue;
                brute = std::min(
                    brute, std::acos(std::clamp(c.dot(Imath::V3d(p.x, p.y, p.z)), -1.0, 1.0)));
            }
        }
        EXPECT_LE(d, brute + 1e-6);  // the brute-force points are floats
        EXPECT_NEAR(d, brute, 0.02) << "cell " << cell << " theta " << thetaC << " phi " << phiC;
    }
}

// Points spread over the domain, with the pole and the horizon in.
std::vector<std::array<double, 4>> ProbePoints(int count) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<std::array<double, 4>> points = {{0, 0, 0, 0},
                                                 {0, 1, 89.5 * kDegree, 2},
                                                 {89.5 * kDegree, 3, 89.5 * kDegree, 1},
                                                 {1.2, 0, 0, 0}};
    while (static_cast<int>(points.size()) < count) {
        points.push_back(
            {0.5 * kPi * u(rng), 2 * kPi * u(rng), 0.5 * kPi * u(rng), 2 * kPi * u(rng)});
    }
    return points;
}

void ExpectSameAsSimple(const Brdf& grid, const Brdf& simple) {
    int nonzero = 0;
    for (const auto& p : ProbePoints(150)) {
        float g[1], s[1];
        grid.EvalAngles(p[0], p[1], p[2], p[3], g);
        simple.EvalAngles(p[0], p[1], p[2], p[3], s);
        // The same float terms, summed in double in another order.
        EXPECT_NEAR(g[0], s[0], 1e-6 * std::abs(s[0]) + 1e-12)
            << p[0] << " " << p[1] << " " << p[2] << " " << p[3];
        nonzero += s[0] > 0;
    }
    EXPECT_GT(nonzero, 100);
}

class GridEqualsSimple : public ::testing::TestWithParam<std::tuple<Norm, Horizon>> {};

TEST_P(GridEqualsSimple, Anisotropic) {
    const auto [norm, horizon] = GetParam();
    auto splats =
        test::SyntheticSplats("phong:0.4,0.6,10", 20000, false, false, 0.4, norm, horizon);
    ExpectSameAsSimple(BrdfGrid(splats, 4, 9), BrdfSimple(splats));
}

TEST_P(GridEqualsSimple, Isotropic) {
    const auto [norm, horizon] = GetParam();
    auto splats = test::SyntheticSplats("phong:0.4,0.6,10", 20000, true, false, 0.4, norm, horizon);
    ExpectSameAsSimple(BrdfIsoGrid(splats, 5, 11), BrdfSimple(splats));
}

INSTANTIATE_TEST_SUITE_P(Norms, GridEqualsSimple,
                         ::testing::Combine(::testing::Values(Norm::kL1, Norm::kL2, Norm::kLinf),
                                            ::testing::Values(Horizon::kReflect,
                                                              Horizon::kRenormalize)),
                         [](const auto& info) {
                             return std::string(NormName(std::get<0>(info.param))) + "_" +
                                    HorizonName(std::get<1>(info.param));
                         });

TEST(GridEqualsSimple, CoarseAndFineGridsAgree) {
    auto splats = test::SyntheticSplats("lambert:0.7", 20000, false, false, 0.6);
    ExpectSameAsSimple(BrdfGrid(splats, 1, 1), BrdfGrid(splats, 12, 48));
}

// Thesis Table 4.1: 100,000 photons, widths 0.3 (Lambert) and 0.15 (Phong), 5 bands, 5 rects:
// average splats per cell ≈ 7000 (ratio 0.07) and ≈ 5000 (0.05). Our lists are tighter (the exact
// product-domain test instead of a norm-independent one) and count horizon images as entries.
TEST(Table41, SplatsPerCellReport) {
    struct Case {
        const char* name;
        const char* model;
        double radius;
        double thesisRatio;
    };
    for (const Case& c : {Case{"lambertian", "lambert:0.5", 0.3, 0.07},
                          Case{"phong", "phong:0,1,25", 0.15, 0.05}}) {
        auto splats = test::SyntheticSplats(c.model, 100000, false, false, c.radius);
        const GridStats coarse = BrdfGrid(splats, 5, 5).Stats();
        int rings, rects;
        DefaultGridFor(c.radius, &rings, &rects);
        const GridStats fine = BrdfGrid(splats, rings, rects).Stats();
        std::printf(
            "Table 4.1  %-10s 100,000 photons  width %.2f  5 bands 5 rects: average %7.0f "
            "ratio %.4f (thesis %.2f) | default %d bands %d rects: average %6.0f ratio "
            "%.4f\n",
            c.name, c.radius, coarse.averageSplats, coarse.ratio, c.thesisRatio, rings, rects,
            fine.averageSplats, fine.ratio);
        EXPECT_GT(coarse.ratio, 0.2 * c.thesisRatio);
        EXPECT_LT(coarse.ratio, 1.5 * c.thesisRatio);
        EXPECT_LT(fine.ratio, 0.5 * coarse.ratio);
    }
}

// A reader checks a file's cell count against CellCount without building the grid.
TEST(HemisphereGrid, CellCountIsTheBuiltGridsCount) {
    for (const auto& [bands, rects] : {std::pair{1, 1}, {4, 8}, {7, 3}, {30, 60}, {90, 181}})
        EXPECT_EQ(HemisphereGrid::CellCount(bands, rects),
                  std::uint64_t(HemisphereGrid(bands, rects).NumCells()))
            << bands << " x " << rects;
}

}  // namespace
}  // namespace gonio
