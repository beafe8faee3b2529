#pragma once
// Shared helpers of the brdfsim tests: synthetic maps and error statistics over a dense set of
// (ω', ω) up to a largest zenith angle.

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "analytic_brdf.h"
#include "brdf.h"
#include "splat_set.h"
#include "synth.h"

namespace gonio::test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

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
                    const Imath::V3f wIn = DirectionFromAngles(ti * kDeg, phiIn);
                    const Imath::V3f wOut = DirectionFromAngles(to * kDeg, phiOut);
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

}  // namespace gonio::test
