#pragma once
// Importance sampling of a splat BRDF (issue 17 item 4; beyond the thesis, which only evaluates
// it). At a fixed incoming direction ω' the BRDF is a sum of kernels,
//   f(ω'→ω) = Σ_k Σ_a Σ_b w_k K(‖d(ω'_a, c'_k), d(ω_b, c_k)‖ / R)
// over splats k and the images a (incoming side) and b (outgoing side) of splat_set.h. The
// sampler picks a term (k, a) with probability W_ka / W, W_ka = w̄_k M(d(ω'_a, c'_k)), where
// w̄_k is the splat's weight averaged over colour components and M(a) = ∫ K(‖a, d(ω, c)‖ / R) dω
// over the whole sphere (KernelOutMarginal); then a direction ω on the sphere with density
// K(‖a, d(ω, c_k)‖ / R) / M(a), by rejection from the uniform cap the kernel covers. A direction
// below the horizon is mirrored (the image b), so the density over the upper hemisphere is
//   p(ω) = Σ_{k,a} (W_ka / W) Σ_b K(...) / M = f̄(ω'→ω) / W,
// f̄ the BRDF averaged over components: the exact pdf of the whole mixture, which is what
// multiple importance sampling needs. Without reflection (Horizon::kRenormalize) f has no b
// images: a direction below the horizon is a failed sample, and p integrates to less than 1.
// M comes from a table interpolated to 1e-6; everything else is exact.

#include <Imath/ImathVec.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "brdfsim/brdf.h"
#include "brdfsim/kernel.h"
#include "brdfsim/splat_set.h"

namespace gonio {

// The mixture at one incoming direction: the terms (k, a) that reach it, with their running
// weight sums. Prepared once per path vertex and reused for sampling and pdfs there.
struct SplatMixture {
    struct Term {
        std::uint32_t splat;
        std::uint32_t image;  // a: 0 the query itself, 1 and 2 its images (splat_set.h)
        double dIn;           // distance on the incoming side
    };
    Imath::V3f wIn;
    std::vector<Term> terms;
    std::vector<double> cumulative;  // Σ W over terms[0..i]
    double Total() const { return cumulative.empty() ? 0.0 : cumulative.back(); }
};

class SplatSampler {
  public:
    // `exact` evaluates the same splats exactly (BrdfSimple, BrdfGrid, BrdfIsoGrid; not a baked
    // table, which is interpolated): the pdf is its value over W.
    SplatSampler(std::shared_ptr<const SplatSet> splats, const Brdf& exact);

    const Brdf& Exact() const { return exact_; }
    void Prepare(const Imath::V3f& wIn, SplatMixture* mixture) const;
    // Draws ω (unit, z > 0) with u choosing the term and `seed` the rejection steps; false when
    // nothing reaches ω' or the direction falls below the horizon without reflection.
    bool Sample(const SplatMixture& mixture, float u, std::uint64_t seed, Imath::V3f* wOut) const;
    // Density of Sample's ω per steradian of the upper hemisphere, and the BRDF there (f of the
    // exact representation, NumComponents() values, is written when f is not null).
    double Pdf(const SplatMixture& mixture, const Imath::V3f& wOut, float* f = nullptr) const;
    double Pdf(const Imath::V3f& wIn, const Imath::V3f& wOut) const;

  private:
    void GatherAnisotropic(const Imath::V3f& query, std::uint32_t image,
                           SplatMixture* mixture) const;
    void GatherIsotropic(double theta, std::uint32_t image, SplatMixture* mixture) const;
    void AddTerm(std::uint32_t k, std::uint32_t image, double dIn, SplatMixture* mixture) const;
    Imath::V3d OutCentre(const SplatMixture::Term& term) const;

    std::shared_ptr<const SplatSet> splats_;
    const Brdf& exact_;
    KernelOutMarginalTable marginal_;
    std::vector<float> meanWeight_;  // w̄_k
    // Splats by where their incoming centre lies: anisotropic sets in (θ', φ') cells, isotropic
    // ones by θ'. order_ holds splat indices, cellStart_ each cell's first position.
    std::vector<std::uint32_t> order_;
    std::vector<std::uint32_t> cellStart_;
    std::vector<float> sortedTheta_;  // isotropic: θ' of order_[i]
};

}  // namespace gonio
