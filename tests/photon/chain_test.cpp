// The whole chain through brdfsim's library (the photon map the tracer writes, splatted and
// gridded as `gonio brdf iopt` does): the Lambert plane gives kd/π and the Phong plane the
// analytic normalised lobe, smoothed by the splat as brdfsim's own validation predicts.
#include "brdfsim/analytic_brdf.h"
#include "brdfsim/brdf_grid.h"
#include "photon_test_util.h"

namespace gonio {
namespace {

std::shared_ptr<SplatSet> PlaneSplats(const std::string& body, uint64_t paths, double radius) {
    PhotonTraceSettings s;
    s.paths = paths;
    s.isotropic = true;
    s.seed = 5;
    const PhotonMap map = test::ToPhotonMap(test::TraceRib(test::World(body), s));
    SplatParams params;
    params.radius = radius;
    params.isotropic = true;
    return std::make_shared<SplatSet>(map, params);
}

TEST(Chain, LambertPlaneGivesKdOverPi) {
    const double kd = 0.7;
    const BrdfIsoGrid grid(PlaneSplats("Surface \"matte\" \"Kd\" 0.7\nPolygon \"P\" [-1 -1 0  1 "
                                       "-1 0  1 1 0  -1 1 0]",
                                       200000, 0.5),
                           4, 12);
    double sum = 0, worst = 0;
    int points = 0;
    float f[3];
    // Up to 70°: nearer the horizon the photons' 1/cos θ_out weights make 200k too few.
    for (double ti = 0; ti <= 70; ti += 10) {
        for (double to = 0; to <= 70; to += 10) {
            for (double po = 0; po < 360; po += 45) {
                grid.EvalAngles(ti * kDegree, 0, to * kDegree, po * kDegree, f);
                const double rel = f[0] / (kd / kPi) - 1;
                sum += rel;
                worst = std::max(worst, std::abs(rel));
                ++points;
            }
        }
    }
    std::printf("Lambert plane through the chain: mean %+.3f%%, worst %.3f%% over %d points\n",
                100 * sum / points, 100 * worst, points);
    EXPECT_LT(std::abs(sum / points), 0.01);
    EXPECT_LT(worst, 0.08);  // brdfsim's 5% bound is for 1M photons
    for (double ti : {0.0, 30.0, 60.0})
        EXPECT_NEAR(Albedo(grid, DirectionFromAngles(ti * kDegree, 0), 32)[0], kd, 0.01 * kd);
}

// Peak and width of the lobe in the plane of incidence against the analytic lobe smoothed by
// the splat (the prediction of brdfsim's validation_test.cpp for n = 25, R = 0.1).
TEST(Chain, PhongPlaneGivesTheAnalyticLobe) {
    const double n = 25, radius = 0.1;
    const BrdfIsoGrid grid(PlaneSplats("Surface \"metal\"\nAttribute \"brdflight\" \"float "
                                       "exponent\" 25\nPolygon \"P\" [-1 -1 0  1 -1 0  1 1 0  "
                                       "-1 1 0]",
                                       200000, radius),
                           15, 60);
    const double sigma2 = 1 / n, s2 = 0.1041 * radius * radius;
    const double peakFactor = std::sqrt(sigma2 / 2 / (sigma2 / 2 + s2) * sigma2 / (sigma2 + s2));
    const double predictedPeak = (n + 2) / (2 * kPi) * peakFactor;
    const double predictedFwhm =
        2 * std::acos(std::pow(0.5, 1 / n)) / kDegree * std::sqrt((sigma2 + 2 * s2) / sigma2);
    float f[3];
    for (double ti : {0.0, 30.0, 60.0}) {
        std::vector<double> xs, ys;
        for (double x = -89; x <= 89; x += 0.25) {
            grid.EvalAngles(ti * kDegree, kPi, std::abs(x) * kDegree, x < 0 ? kPi : 0, f);
            xs.push_back(x);
            ys.push_back(f[0]);
        }
        const size_t top = std::max_element(ys.begin(), ys.end()) - ys.begin();
        size_t lo = top, hi = top;
        while (lo > 0 && ys[lo - 1] >= ys[top] / 2) --lo;
        while (hi + 1 < ys.size() && ys[hi + 1] >= ys[top] / 2) ++hi;
        const double fwhm = xs[hi] - xs[lo] + 0.25;
        std::printf(
            "Phong plane through the chain, theta_in %2.0f: peak %.3f at %.2f (predicted "
            "%.3f), FWHM %.2f deg (predicted %.2f)\n",
            ti, ys[top], xs[top], predictedPeak, fwhm, predictedFwhm);
        EXPECT_NEAR(xs[top], ti, 1.5);
        EXPECT_NEAR(ys[top] / predictedPeak, 1.0, 0.05);
        EXPECT_NEAR(fwhm / predictedFwhm, 1.0, 0.05);
    }
}

}  // namespace
}  // namespace gonio
