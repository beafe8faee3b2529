#include "brdfsim/brdf_adaptive.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/math.h"

namespace gonio {

namespace {

// Radii are rounded to this step so kernel masses can be cached.
constexpr double kRadiusStep = 1e-3;

}  // namespace

BrdfAdaptive::BrdfAdaptive(std::shared_ptr<const SplatSet> splats, int neighbours, double minRadius)
    : splats_(std::move(splats)), neighbours_(neighbours), minRadius_(minRadius) {
    if (splats_->Params().horizon != Horizon::kReflect) {
        throw std::invalid_argument("the adaptive radius needs horizon reflection");
    }
    if (neighbours < 1 || static_cast<std::size_t>(neighbours) > splats_->Size()) {
        throw std::invalid_argument("--knn must be between 1 and the number of photons");
    }
}

void BrdfAdaptive::Distances(const SplatQuery& q, std::vector<float>& d) const {
    const SplatSet& s = *splats_;
    d.clear();
    for (int v = 0; v < s.NumImages(); ++v) {
        if (!(q.activeMask & (1u << v))) continue;
        for (std::size_t k = 0; k < s.Size(); ++k) {
            const SplatGeometry& g = s.geometry[k];
            const float ox = q.outX[v] - g.outX, oy = q.outY[v] - g.outY, oz = q.outZ[v] - g.outZ;
            const float dOut = GreatCircleFromChord2(std::min(4.0f, ox * ox + oy * oy + oz * oz));
            float dIn;
            if (s.Params().isotropic) {
                dIn = std::abs(q.thetaIn[v] - g.thetaIn);
            } else {
                const float ix = q.inX[v] - g.inX, iy = q.inY[v] - g.inY, iz = q.inZ[v] - g.inZ;
                dIn = GreatCircleFromChord2(std::min(4.0f, ix * ix + iy * iy + iz * iz));
            }
            d.push_back(static_cast<float>(CombineDistances(s.Params().norm, dIn, dOut)));
        }
    }
}

double BrdfAdaptive::KthDistance(std::vector<float> d) const {
    const std::size_t k = std::min<std::size_t>(neighbours_, d.size()) - 1;
    std::nth_element(d.begin(), d.begin() + k, d.end());
    const double radius = std::clamp<double>(d[k], minRadius_, kHalfPi);
    return std::max(kRadiusStep, std::round(radius / kRadiusStep) * kRadiusStep);
}

double BrdfAdaptive::RadiusAt(const Imath::V3f& wIn, const Imath::V3f& wOut) const {
    // All images are considered, so the query must not restrict them to the fixed radius.
    SplatQuery q = splats_->MakeQuery(wIn, wOut);
    q.activeMask = (1u << splats_->NumImages()) - 1;
    std::vector<float> d;
    Distances(q, d);
    return KthDistance(d);
}

void BrdfAdaptive::Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const {
    const SplatSet& s = *splats_;
    const int n = s.NumComponents();
    std::fill(f, f + n, 0.0f);
    if (wIn.z <= 0 || wOut.z <= 0) return;
    SplatQuery q = s.MakeQuery(wIn, wOut);
    q.activeMask = (1u << s.NumImages()) - 1;
    std::vector<float> d;
    Distances(q, d);
    const double radius = KthDistance(d);
    // Balloon estimate: every splat takes the query's radius; the weights were normalised with
    // the map's fixed radius, so rescale by the ratio of the kernel masses.
    const double fixedMass = s.mass;
    const double mass = s.Params().isotropic ? SphereKernelMass3D(radius, s.Params().norm)
                                             : SphereKernelMass4D(radius, s.Params().norm);
    const double scale = fixedMass / mass;
    std::vector<double> acc(n, 0.0);
    for (std::size_t i = 0; i < d.size(); ++i) {
        const double kernel = SplatKernel(d[i] / radius);
        if (kernel <= 0.0) continue;
        const std::size_t k = i % s.Size();
        for (int c = 0; c < n; ++c) acc[c] += kernel * s.weights[k * n + c];
    }
    for (int c = 0; c < n; ++c) f[c] = static_cast<float>(acc[c] * scale);
}

}  // namespace gonio
