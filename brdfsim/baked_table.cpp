#include "brdfsim/baked_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "base/math.h"
#include "brdfsim/splat_set.h"

namespace gonio {

namespace {

double ThetaNode(int i, int n) { return kHalfPi * i / (n - 1); }
double PhiNode(int j, int n) { return kTwoPi * j / n; }

// atan2 to about 1e-5 radians (a minimax polynomial for atan on [0, 1]): ample for interpolating
// between nodes a few degrees apart, at a fraction of the library call's cost.
float FastAtan2(float y, float x) {
    const float ax = std::abs(x), ay = std::abs(y);
    const float lo = std::min(ax, ay), hi = std::max(ax, ay);
    if (hi == 0.0f) return 0.0f;
    const float a = lo / hi, s = a * a;
    float r =
        a * (0.99997726f +
             s * (-0.33262347f +
                  s * (0.19354346f + s * (-0.11643287f + s * (0.05265332f - s * 0.0117212f)))));
    if (ay > ax) r = 0.5f * kPiF - r;
    if (x < 0) r = kPiF - r;
    return y < 0 ? -r : r;
}

// Position of θ (radians) between nodes: index of the lower node and the fraction above it.
void ThetaCoordinate(float cosTheta, int n, int* i, float* t) {
    const float theta = 0.5f * kPiF - FastAsin(std::clamp(cosTheta, 0.0f, 1.0f));
    const float u = std::clamp(theta / (0.5f * kPiF) * (n - 1), 0.0f, n - 1.0f);
    *i = std::min(static_cast<int>(u), n - 2);
    *t = u - *i;
}

void PhiCoordinate(float y, float x, int n, int* j, float* t) {
    float phi = FastAtan2(y, x);
    if (phi < 0) phi += 2 * kPiF;
    const float u = phi / (2 * kPiF) * n;
    *j = std::min(static_cast<int>(u), n - 1);
    *t = u - *j;
}

}  // namespace

BakedTable::BakedTable(const Brdf& source, int resolution, const ProgressFn& progress)
    : isotropic_(source.IsIsotropic()), ncomps_(source.NumComponents()) {
    if (resolution < 2 || resolution > 256) {
        throw std::invalid_argument("bake resolution must be in 2..256");
    }
    dims_ = {resolution, isotropic_ ? 1 : 2 * resolution, resolution, 2 * resolution};
    values_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2] * dims_[3] * ncomps_,
                   0.0f);
    const int slices = dims_[0] * dims_[1];
    std::atomic<int> done{0};
    std::mutex mutex;
    tbb::parallel_for(0, slices, [&](int slice) {
        const int ti = slice / dims_[1], pi = slice % dims_[1];
        // Grazing nodes are evaluated just inside the domain, where Eval is defined.
        const double thetaIn = std::min(ThetaNode(ti, dims_[0]), kHalfPi - 1e-4);
        const Imath::V3f wIn = DirectionFromAngles(thetaIn, PhiNode(pi, dims_[1]));
        for (int to = 0; to < dims_[2]; ++to) {
            const double thetaOut = std::min(ThetaNode(to, dims_[2]), kHalfPi - 1e-4);
            for (int po = 0; po < dims_[3]; ++po) {
                const double phiOut = PhiNode(po, dims_[3]);
                source.Eval(wIn, DirectionFromAngles(thetaOut, phiOut),
                            &values_[Index(ti, pi, to, po) * ncomps_]);
            }
        }
        if (progress) {
            const int n = ++done;
            std::lock_guard<std::mutex> lock(mutex);
            progress(static_cast<double>(n) / slices);
        }
    });
}

BakedTable::BakedTable(bool isotropic, int ncomps, std::array<int, 4> dims,
                       std::vector<float> values)
    : isotropic_(isotropic), ncomps_(ncomps), dims_(dims), values_(std::move(values)) {}

void BakedTable::Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const {
    std::fill(f, f + ncomps_, 0.0f);
    if (wIn.z <= 0 || wOut.z <= 0) return;
    int ti, to, pi = 0, po;
    float tt, tto, tp = 0.0f, tpo;
    ThetaCoordinate(wIn.z, dims_[0], &ti, &tt);
    ThetaCoordinate(wOut.z, dims_[2], &to, &tto);
    Imath::V3f out = wOut;
    if (isotropic_) {  // rotate ω by -φ_in: the table holds Δφ
        const float s = std::sqrt(wIn.x * wIn.x + wIn.y * wIn.y);
        if (s > 1e-7f) {
            const float c = wIn.x / s, sn = wIn.y / s;
            out = Imath::V3f(c * wOut.x + sn * wOut.y, -sn * wOut.x + c * wOut.y, wOut.z);
        }
    } else {
        PhiCoordinate(wIn.y, wIn.x, dims_[1], &pi, &tp);
    }
    PhiCoordinate(out.y, out.x, dims_[3], &po, &tpo);
    const int pi1 = isotropic_ ? 0 : (pi + 1) % dims_[1];
    const int po1 = (po + 1) % dims_[3];
    for (int a = 0; a < 2; ++a) {
        const float wa = a ? tt : 1 - tt;
        for (int b = 0; b < (isotropic_ ? 1 : 2); ++b) {
            const float wb = isotropic_ ? 1.0f : (b ? tp : 1 - tp);
            for (int c = 0; c < 2; ++c) {
                const float wc = c ? tto : 1 - tto;
                const float w3 = wa * wb * wc;
                const float* lo = &values_[Index(ti + a, b ? pi1 : pi, to + c, po) * ncomps_];
                const float* hi = &values_[Index(ti + a, b ? pi1 : pi, to + c, po1) * ncomps_];
                for (int k = 0; k < ncomps_; ++k) f[k] += w3 * ((1 - tpo) * lo[k] + tpo * hi[k]);
            }
        }
    }
}

}  // namespace gonio
