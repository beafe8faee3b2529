#pragma once
// The adaptive-radius estimate (beyond the thesis's fixed spread, as photon mapping does it): at
// each query the splat radius is the distance to the k-th nearest photon image in the product
// domain, so dense lobes get small splats and sparse regions large ones. Every splat is visited
// (like BrdfSimple), so this is for sections and maps, not for rendering.

#include <memory>

#include "brdfsim/brdf.h"
#include "brdfsim/splat_set.h"

namespace gonio {

class BrdfAdaptive : public Brdf {
  public:
    // `splats` must reflect at the horizon; their weights are re-normalised for each radius.
    // The radius is clamped to [minRadius, π/2].
    BrdfAdaptive(std::shared_ptr<const SplatSet> splats, int neighbours, double minRadius = 0.02);

    int NumComponents() const override { return splats_->NumComponents(); }
    bool IsIsotropic() const override { return splats_->Params().isotropic; }
    void Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const override;
    std::size_t MemoryBytes() const override { return SplatSetBytes(*splats_); }

    // The radius the estimate uses at this point (radians).
    double RadiusAt(const Imath::V3f& wIn, const Imath::V3f& wOut) const;

  private:
    // Distance of every active image of every splat from the query, in the product domain.
    void Distances(const SplatQuery& q, std::vector<float>& d) const;
    double KthDistance(std::vector<float> d) const;

    std::shared_ptr<const SplatSet> splats_;
    int neighbours_;
    double minRadius_;
};

}  // namespace gonio
