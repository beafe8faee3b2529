#include "brdfsim/brdf.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "base/math.h"

namespace gonio {

namespace {}

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

void EvalPlanes(const Brdf& brdf, int colorComponents, int count, const float* wIn,
                const float* wOut, const uint8_t* active, float* out) {
    const int brdfComponents = brdf.NumComponents();
    std::vector<float> f(static_cast<size_t>(brdfComponents));
    auto component = [&](int c) {
        if (brdfComponents == colorComponents) return f[size_t(c)];
        if (brdfComponents == 1) return f[0];
        float sum = 0.0f;
        for (float value : f) sum += value;
        return sum / static_cast<float>(brdfComponents);
    };
    for (int p = 0; p < count; ++p) {
        if (active && !active[p]) continue;
        brdf.Eval(Imath::V3f(wIn[p], wIn[count + p], wIn[2 * count + p]),
                  Imath::V3f(wOut[p], wOut[count + p], wOut[2 * count + p]), f.data());
        for (int c = 0; c < colorComponents; ++c) out[size_t(c) * count + p] = component(c);
    }
}

}  // namespace gonio
