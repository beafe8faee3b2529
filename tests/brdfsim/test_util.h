#pragma once
// Shared helpers of the brdfsim tests: synthetic maps and error statistics over a dense set of
// (ω', ω) up to a largest zenith angle.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "base/math.h"
#include "brdfsim/analytic_brdf.h"
#include "brdfsim/brdf.h"
#include "brdfsim/splat_set.h"
#include "brdfsim/synth.h"

namespace gonio::test {

// A scratch file name of the running test: ctest runs tests in parallel processes, so two tests
// must never share a file.
inline std::string TempPath(const std::string& name) {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    return ::testing::TempDir() + "brdf_" + test->test_suite_name() + "_" + test->name() + "_" +
           name;
}

inline std::shared_ptr<SplatSet> SyntheticSplats(const std::string& model, std::uint64_t paths,
                                                 bool isotropic, bool stratified, double radius,
                                                 Norm norm = Norm::kL2,
                                                 Horizon horizon = Horizon::kReflect,
                                                 int ncomps = 1) {
    SynthOptions options;
    options.paths = paths;
    options.isotropic = isotropic;
    options.stratified = stratified;
    options.ncomps = ncomps;
    options.seed = 11;
    const PhotonMap map = SynthesizePhotonMap(AnalyticBrdf::Parse(model), options);
    SplatParams params;
    params.radius = radius;
    params.norm = norm;
    params.horizon = horizon;
    params.isotropic = isotropic;
    return std::make_shared<SplatSet>(map, params);
}

struct ErrorStats {
    double meanRelative = 0.0;  // mean of f / reference - 1
    double maxRelative = 0.0;   // largest |f / reference - 1|
    int points = 0;
};

// Dense set: θ in 0..thetaMax step 5°, φ_in 4 values (1 when isotropic), φ_out 8 values.
inline ErrorStats CompareOnDenseSet(const Brdf& brdf, const AnalyticBrdf& reference,
                                    double thetaMaxDeg, bool isotropic) {
    ErrorStats stats;
    double sum = 0.0;
    std::vector<float> f(brdf.NumComponents());
    for (double ti = 0; ti <= thetaMaxDeg + 1e-9; ti += 5) {
        for (int pi = 0; pi < (isotropic ? 1 : 4); ++pi) {
            for (double to = 0; to <= thetaMaxDeg + 1e-9; to += 5) {
                for (int po = 0; po < 8; ++po) {
                    const double phiIn = pi * kPi / 2 + 0.3, phiOut = po * kPi / 4 + 0.1;
                    const Imath::V3f wIn = DirectionFromAngles(ti * kDegree, phiIn);
                    const Imath::V3f wOut = DirectionFromAngles(to * kDegree, phiOut);
                    brdf.Eval(wIn, wOut, f.data());
                    const double ref = reference.Eval(Imath::V3d(wIn.x, wIn.y, wIn.z),
                                                      Imath::V3d(wOut.x, wOut.y, wOut.z));
                    const double rel = f[0] / ref - 1.0;
                    sum += rel;
                    stats.maxRelative = std::max(stats.maxRelative, std::abs(rel));
                    ++stats.points;
                }
            }
        }
    }
    stats.meanRelative = sum / stats.points;
    return stats;
}

// Peak and full width at half maximum of a sampled curve; the half-maximum crossings are
// interpolated linearly between samples.
struct Lobe {
    double peak = 0, peakAt = 0, fwhm = 0;
};

inline Lobe MeasureLobe(const std::vector<double>& x, const std::vector<double>& y) {
    Lobe lobe;
    std::size_t top = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (y[i] > y[top]) top = i;
    }
    lobe.peak = y[top];
    lobe.peakAt = x[top];
    const double half = lobe.peak / 2;
    std::size_t lo = top, hi = top;
    while (lo > 0 && y[lo - 1] >= half) --lo;
    while (hi + 1 < y.size() && y[hi + 1] >= half) ++hi;
    const double left =
        lo > 0 ? x[lo - 1] + (half - y[lo - 1]) / (y[lo] - y[lo - 1]) * (x[lo] - x[lo - 1]) : x[lo];
    const double right = hi + 1 < y.size()
                             ? x[hi] + (y[hi] - half) / (y[hi] - y[hi + 1]) * (x[hi + 1] - x[hi])
                             : x[hi];
    lobe.fwhm = right - left;
    return lobe;
}

// A cut through the plane of incidence of an isotropic BRDF lit from φ = π: x < 0 lies towards
// the light, the mirror direction is at x = θ_in.
inline Lobe PlaneOfIncidenceLobe(const Brdf& brdf, double thetaInDeg) {
    std::vector<double> xs, ys;
    std::vector<float> f(brdf.NumComponents());
    for (double x = -89; x <= 89; x += 0.25) {
        brdf.EvalAngles(thetaInDeg * kDegree, kPi, std::abs(x) * kDegree, x < 0 ? kPi : 0,
                        f.data());
        xs.push_back(x);
        ys.push_back(f[0]);
    }
    return MeasureLobe(xs, ys);
}

}  // namespace gonio::test
