#pragma once
// Photons turned into splats (thesis §4.2, DESIGN.md "Splats"): each photon becomes a kernel of
// radius R in the product domain, weighted by β / (N · p_in · cos θ_out · mass) so that the sum of
// the splats estimates f(ω'→ω) in 1/sr. The horizon (and for isotropic maps the pole) is handled
// by images: a query is also evaluated at its mirror points, which is the same as adding the
// photon's mirror images. Splats are sorted by where they lie, so the splats of one grid cell
// sit close together in memory.

#include <Imath/ImathVec.h>

#include <cstdint>
#include <vector>

#include "kernel.h"
#include "photon_map.h"

namespace gonio {

struct SplatParams {
    double radius = 0.3;  // R, radians
    Norm norm = Norm::kL2;
    Horizon horizon = Horizon::kReflect;
    bool isotropic = false;  // domain θ_in × (θ_out, Δφ) instead of ω' × ω
    double energyMin = 0.0;  // photons whose largest colour value is below are skipped (thesis)
};

// One evaluation point in every image position: index v of SplatSet::Image.
struct SplatQuery {
    float inX[6], inY[6], inZ[6], thetaIn[6], outX[6], outY[6], outZ[6];
    unsigned activeMask = 0;  // images that can reach the domain from this point
};

// One splat's centre, 32 bytes so that a lookup touches one cache line per splat. The incoming
// direction is unused by isotropic sets (θ_in is), kept for statistics and plots.
struct SplatGeometry {
    float inX, inY, inZ, thetaIn, outX, outY, outZ, pad;
};

class SplatSet {
  public:
    SplatSet() = default;
    SplatSet(const PhotonMap& map, const SplatParams& params);

    std::size_t Size() const { return geometry.size(); }
    int NumComponents() const { return ncomps; }
    const SplatParams& Params() const { return params; }
    // 4 images in 4D (mirror of ω' × mirror of ω), 6 for isotropic maps (θ' itself, its
    // reflection through the pole, its reflection at the horizon × mirror of ω); 1 when
    // renormalising instead of reflecting.
    int NumImages() const;

    // Local frame, z the normal, both directions away from the surface.
    SplatQuery MakeQuery(const Imath::V3f& wIn, const Imath::V3f& wOut) const;
    // The image v of splat k: its centre on the (possibly mirrored) incoming and outgoing spheres.
    void ImageCentre(std::size_t k, int v, Imath::V3d* in, double* thetaIn, Imath::V3d* out) const;

    // Adds the contribution of splat k seen from image v of the query to acc[0..ncomps).
    inline void Accumulate(std::size_t k, int v, const SplatQuery& q, double* acc) const;

    // Total escaped energy per traced path, (1/N) Σ β / p, per component: what ∫∫ f cos dω dω'
    // must return for an anisotropic map.
    std::vector<double> EnergyPerPath() const;

    // Public for the .grd reader/writer and the grids; kept consistent by the constructors.
    SplatParams params;
    int ncomps = 0;
    std::uint64_t paths = 0;
    std::uint64_t photons = 0;  // photons in the map, including those below energyMin
    double mass = 0.0;          // kernel mass on the sphere (per photon in renormalise mode)
    float chordRadius2 = 0.0f;  // (2 sin(R/2))²: squared chord of the splat radius
    float invRadius = 0.0f;
    std::vector<SplatGeometry> geometry;
    std::vector<float> weights;   // Size() × ncomps
    std::vector<float> energies;  // Size() × ncomps: β / p (for statistics)
};

// Bytes held by the splat arrays.
std::size_t SplatSetBytes(const SplatSet& splats);

// asin for x in [0, 1] to float precision without the library call's overhead (Cephes asinf).
inline float FastAsin(float x) {
    const bool wide = x > 0.5f;
    const float z = wide ? 0.5f * (1.0f - x) : x * x;
    const float s = wide ? std::sqrt(z) : x;
    const float p = ((((4.2163199048e-2f * z + 2.4181311049e-2f) * z + 4.5470025998e-2f) * z +
                      7.4953002686e-2f) *
                         z +
                     1.6666752422e-1f) *
                        z * s +
                    s;
    return wide ? 1.5707963267948966f - 2.0f * p : p;
}

// Great-circle distance from the squared chord: accurate for small distances, unlike acos(dot).
inline float GreatCircleFromChord2(float chord2) {
    return 2.0f * FastAsin(0.5f * std::sqrt(chord2));
}

inline void SplatSet::Accumulate(std::size_t k, int v, const SplatQuery& q, double* acc) const {
    const SplatGeometry& g = geometry[k];
    const float ox = q.outX[v] - g.outX, oy = q.outY[v] - g.outY, oz = q.outZ[v] - g.outZ;
    const float chordOut2 = ox * ox + oy * oy + oz * oz;
    if (chordOut2 >= chordRadius2) return;
    float dIn;
    if (params.isotropic) {
        dIn = std::abs(q.thetaIn[v] - g.thetaIn) * invRadius;
        if (dIn >= 1.0f) return;
    } else {
        const float ix = q.inX[v] - g.inX, iy = q.inY[v] - g.inY, iz = q.inZ[v] - g.inZ;
        const float chordIn2 = ix * ix + iy * iy + iz * iz;
        if (chordIn2 >= chordRadius2) return;
        dIn = GreatCircleFromChord2(chordIn2) * invRadius;
    }
    const float dOut = GreatCircleFromChord2(chordOut2) * invRadius;
    float k2;
    switch (params.norm) {
        case Norm::kL1:
            k2 = (dIn + dOut) * (dIn + dOut);
            break;
        case Norm::kL2:
            k2 = dIn * dIn + dOut * dOut;
            break;
        default:
            k2 = dIn > dOut ? dIn * dIn : dOut * dOut;
            break;
    }
    const float kernel = SplatKernelSquared(k2);
    if (kernel <= 0.0f) return;
    const float* w = &weights[k * ncomps];
    for (int c = 0; c < ncomps; ++c) acc[c] += static_cast<double>(kernel * w[c]);
}

}  // namespace gonio
