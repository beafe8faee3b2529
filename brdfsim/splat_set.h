#pragma once
// Photons turned into splats (thesis §4.2, DESIGN.md "Splats"): each photon becomes a kernel of
// radius R in the product domain, weighted by β / (N · p_in · cos θ_out · mass) so that the sum of
// the splats estimates f(ω'→ω) in 1/sr. The horizon (and for isotropic maps the pole) is handled
// by images: a query is also evaluated at its mirror points, which is the same as adding the
// photon's mirror images. Splats are sorted by where they lie, so the splats of one grid cell
// sit close together in memory.

#include <Imath/ImathVec.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "base/math.h"
#include "brdfsim/kernel.h"
#include "brdfsim/photon_map.h"

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
    return wide ? kHalfPiF - 2.0f * p : p;
}

// Great-circle distance from the squared chord: accurate for small distances, unlike acos(dot).
inline float GreatCircleFromChord2(float chord2) {
    return 2.0f * FastAsin(0.5f * std::sqrt(chord2));
}

// The squared chords a splat can reach, chord² < chordRadius2 = (2 sin(R/2))², fall in one of
// three ranges, each with its own polynomial below.
enum class ChordRange {
    kSmall,   // chord² <= 0.25: R <= 2 asin(1/4) = 0.505 (the thesis's radii)
    kMedium,  // chord² <= 1: R <= π/3
    kLarge,   // chord² <= 2: R <= π/2, the largest radius allowed
};

inline ChordRange ChordRangeFor(float chordRadius2) {
    return chordRadius2 <= 0.25f
               ? ChordRange::kSmall
               : (chordRadius2 <= 1.0f ? ChordRange::kMedium : ChordRange::kLarge);
}

// Squared great-circle distance from the squared chord s = c² of two unit vectors, without a
// square root or an asin: d² = 4 asin²(c/2) = s + s² (1/12 + s/90 + s²/560 + ...), a series in
// s. Each range has the minimax polynomial for (d² - s) / s² (relative errors 1.1e-8, 7.2e-10
// and 5.9e-9), evaluated by Estrin's scheme for a short chain of dependent operations; in float
// within 1e-7 of the exact value (kernel_test).
template <ChordRange kRange>
inline float ArcLength2FromChord2(float s) {
    const float s2 = s * s;
    float q;
    if constexpr (kRange == ChordRange::kSmall) {
        q = (8.33347067e-2f + 1.10839354e-2f * s) + s2 * 1.95572595e-3f;
    } else if constexpr (kRange == ChordRange::kMedium) {
        const float s4 = s2 * s2;
        q = ((8.33332613e-2f + 1.11121824e-2f * s) + s2 * (1.77949702e-3f + 3.34390410e-4f * s)) +
            s4 * (3.71466267e-5f + 2.62284084e-5f * s);
    } else {
        const float s4 = s2 * s2;
        q = ((8.33328739e-2f + 1.11169806e-2f * s) + s2 * (1.75709452e-3f + 3.86479165e-4f * s)) +
            s4 * ((-3.14992431e-5f + 8.08928962e-5f * s) +
                  s2 * (-2.58345844e-5f + 5.71914006e-6f * s));
    }
    return s + s2 * q;
}

// Squared length of a difference of two points, summed in this order everywhere.
inline float Chord2(float x, float y, float z) { return x * x + y * y + z * z; }

// The kernel value of one splat seen from one query image: thesis eq. 4.4 at the distance of
// eqs. 3.4-3.6, from the squared incoming chord (isotropic sets: the squared θ_in offset) and
// the squared outgoing chord; 0 outside the splat. The one definition of a splat's term, shared
// by SplatSet::Accumulate and SplatTree's leaf loop: it uses selects only, so the leaf loop
// vectorises it and both compute the same floats.
template <ChordRange kRange, Norm kNorm, bool kIso>
inline float SplatKernelFromChords(float in2, float chordOut2, float chordRadius2,
                                   float invRadius2) {
    const float dIn2 = kIso ? in2 : ArcLength2FromChord2<kRange>(in2);
    const float dOut2 = ArcLength2FromChord2<kRange>(chordOut2);
    float k2;  // (distance / R)²
    if constexpr (kNorm == Norm::kL1) {
        const float d = std::sqrt(dIn2) + std::sqrt(dOut2);
        k2 = d * d * invRadius2;
    } else if constexpr (kNorm == Norm::kL2) {
        k2 = (dIn2 + dOut2) * invRadius2;
    } else {
        k2 = (dIn2 > dOut2 ? dIn2 : dOut2) * invRadius2;
    }
    const float value = SplatKernelPolynomial(k2);
    // The chord tests keep the polynomials inside their ranges; past R the kernel polynomial
    // rises again, and rounding can leave it just below 0 at R.
    const bool inside = ((kIso || in2 < chordRadius2) & (chordOut2 < chordRadius2)) &
                        ((k2 < 1.0f) & (value > 0.0f));
    return inside ? value : 0.0f;
}

template <ChordRange kRange, bool kIso>
inline float SplatKernelForNorm(Norm norm, float in2, float chordOut2, float chordRadius2,
                                float invRadius2) {
    switch (norm) {
        case Norm::kL1:
            return SplatKernelFromChords<kRange, Norm::kL1, kIso>(in2, chordOut2, chordRadius2,
                                                                  invRadius2);
        case Norm::kL2:
            return SplatKernelFromChords<kRange, Norm::kL2, kIso>(in2, chordOut2, chordRadius2,
                                                                  invRadius2);
        default:
            return SplatKernelFromChords<kRange, Norm::kLinf, kIso>(in2, chordOut2, chordRadius2,
                                                                    invRadius2);
    }
}

template <bool kIso>
inline float SplatKernelForSet(const SplatSet& s, float in2, float chordOut2) {
    const float invRadius2 = s.invRadius * s.invRadius;
    switch (ChordRangeFor(s.chordRadius2)) {
        case ChordRange::kSmall:
            return SplatKernelForNorm<ChordRange::kSmall, kIso>(s.params.norm, in2, chordOut2,
                                                                s.chordRadius2, invRadius2);
        case ChordRange::kMedium:
            return SplatKernelForNorm<ChordRange::kMedium, kIso>(s.params.norm, in2, chordOut2,
                                                                 s.chordRadius2, invRadius2);
        default:
            return SplatKernelForNorm<ChordRange::kLarge, kIso>(s.params.norm, in2, chordOut2,
                                                                s.chordRadius2, invRadius2);
    }
}

inline void SplatSet::Accumulate(std::size_t k, int v, const SplatQuery& q, double* acc) const {
    const SplatGeometry& g = geometry[k];
    const float chordOut2 = Chord2(q.outX[v] - g.outX, q.outY[v] - g.outY, q.outZ[v] - g.outZ);
    // Most splats are out of reach: decide that before anything else (the kernel would be 0).
    if (chordOut2 >= chordRadius2) return;
    float kernel;
    if (params.isotropic) {
        const float t = q.thetaIn[v] - g.thetaIn;
        kernel = SplatKernelForSet<true>(*this, t * t, chordOut2);
    } else {
        const float chordIn2 = Chord2(q.inX[v] - g.inX, q.inY[v] - g.inY, q.inZ[v] - g.inZ);
        if (chordIn2 >= chordRadius2) return;
        kernel = SplatKernelForSet<false>(*this, chordIn2, chordOut2);
    }
    if (kernel == 0.0f) return;
    const float* w = &weights[k * ncomps];
    for (int c = 0; c < ncomps; ++c) acc[c] += static_cast<double>(kernel * w[c]);
}

}  // namespace gonio
