#include "brdf.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace gonio {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Imath::V3f DirectionFromAngles(double theta, double phi) {
    return Imath::V3f(static_cast<float>(std::sin(theta) * std::cos(phi)),
                      static_cast<float>(std::sin(theta) * std::sin(phi)),
                      static_cast<float>(std::cos(theta)));
}

void Brdf::EvalAngles(double thetaIn, double phiIn, double thetaOut, double phiOut,
                      float* f) const {
    Eval(DirectionFromAngles(thetaIn, phiIn), DirectionFromAngles(thetaOut, phiOut), f);
}

std::vector<double> Albedo(const Brdf& brdf, const Imath::V3f& wIn, int thetaSteps) {
    const int n = brdf.NumComponents();
    const int phiSteps = 2 * thetaSteps;
    std::vector<double> rows(static_cast<std::size_t>(thetaSteps) * n, 0.0);
    // cos θ dω = ½ d(sin²θ) dφ: equal steps in s = sin²θ weight every point alike.
    tbb::parallel_for(0, thetaSteps, [&](int i) {
        const double s = (i + 0.5) / thetaSteps;
        const double theta = std::asin(std::sqrt(s));
        std::vector<float> f(n);
        for (int j = 0; j < phiSteps; ++j) {
            brdf.Eval(wIn, DirectionFromAngles(theta, 2 * kPi * (j + 0.5) / phiSteps), f.data());
            for (int c = 0; c < n; ++c) rows[i * n + c] += f[c];
        }
    });
    std::vector<double> albedo(n, 0.0);
    const double weight = 0.5 / thetaSteps * (2 * kPi / phiSteps);
    for (int i = 0; i < thetaSteps; ++i) {
        for (int c = 0; c < n; ++c) albedo[c] += rows[i * n + c] * weight;
    }
    return albedo;
}

}  // namespace gonio
