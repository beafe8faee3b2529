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
//
// An isotropic set's W_ka depends on θ' alone, and the splats are sorted by θ'_k: W(θ') is
// tabulated once, exactly at points Δ apart (Δ the spacing of M's table) and linear between them
// (within 4e-7 of the direct sum with the exact M in splat_sampler_test), and a term is drawn by
// picking a splat within R of an image's θ' in proportion to w̄_k from prefix sums, accepted with
// probability M(|θ' − θ'_k|) / max M, which leaves it drawn with probability W_ka / W exactly.
// Gathering the terms of such a set (38% of its splats at R = 0.3) took nearly all of a path
// vertex's time.

#include <Imath/ImathVec.h>

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "brdfsim/brdf.h"
#include "brdfsim/kernel.h"
#include "brdfsim/splat_set.h"

namespace gonio {

// The mixture at one incoming direction: for anisotropic sets the terms (k, a) that reach it,
// for isotropic ones the images a of its θ', each with the running sum of W. Prepared once per
// path vertex and reused for sampling and pdfs there.
struct SplatMixture {
    struct Term {
        std::uint32_t splat;
        std::uint32_t image;  // a: 0 the query itself, 1 and 2 its images (splat_set.h)
        float in;             // the incoming chord (isotropic sets: |θ' offset|)
        double cumulative;    // Σ W over the terms up to this one
    };
    struct Image {
        std::uint32_t image;  // a, as in Term
        float theta;          // the image's θ'
        double cumulative;    // Σ W over the images up to this one
    };
    Imath::V3f wIn;
    std::vector<Term> terms;
    std::vector<Image> images;
    double Total() const {
        if (!images.empty()) return images.back().cumulative;
        return terms.empty() ? 0.0 : terms.back().cumulative;
    }
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
    // W of an isotropic set at θ' (one image), from the table TabulateIsotropicWeight makes,
    // and the range of sorted_ within R of θ'.
    void TabulateIsotropicWeight();
    double IsotropicWeight(float theta) const;
    std::pair<std::size_t, std::size_t> IsotropicRange(float theta) const;
    // The term: for anisotropic sets the one u picks from the list; for isotropic ones a splat
    // of the image u picks, drawn by rejection with the random numbers of `state`.
    SplatMixture::Term PickTerm(const SplatMixture& mixture, float u, std::uint64_t* state) const;
    SplatMixture::Term PickIsotropicTerm(const SplatMixture::Image& image,
                                         std::uint64_t* state) const;
    // The incoming distance of a term: the great circle of its chord, or the θ' offset.
    double IncomingDistance(const SplatMixture::Term& term) const;
    Imath::V3d OutCentre(const SplatMixture::Term& term) const;
    // M at an incoming chord (isotropic sets: at a θ' offset), linearly interpolated from
    // kMarginalSteps + 1 values: the gather loop takes no asin per splat.
    double Marginal(float in) const;

    static constexpr int kMarginalSteps = 1024;
    std::shared_ptr<const SplatSet> splats_;
    const Brdf& exact_;
    std::vector<double> marginal_;
    float inLimit_;      // the largest incoming chord (θ' offset) a splat reaches: 2 sin(R/2) (R)
    float chordLimit2_;  // (2 sin(R/2))²
    // Splats by where their incoming centre lies: anisotropic sets in (θ', φ') cells, isotropic
    // ones by θ', and per position in that order the splat's index, incoming centre (x, y, z,
    // or θ' in x) and w̄_k, its weight averaged over colour components: the gather loop reads
    // them in sequence. cellStart_ is each cell's first position (anisotropic sets).
    struct Sorted {
        float x, y, z, meanWeight;
        std::uint32_t splat;
    };
    std::vector<Sorted> sorted_;
    std::vector<std::uint32_t> cellStart_;
    // Isotropic sets: prefix_[i] = Σ w̄ of sorted_[0, i) (weights ≤ 0 counted as 0, as the
    // mixture leaves them out), and the largest M, the rejection's bound.
    std::vector<double> prefix_;
    double marginalMax_ = 0;
    // Isotropic sets: W at θ' = weightStart_ + j · weightStep_.
    std::vector<double> weightTable_;
    float weightStart_ = 0, weightStep_ = 1;
};

}  // namespace gonio
