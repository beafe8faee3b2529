#pragma once
// Every splat summed at every evaluation (the thesis's GPBRDFSimple): slow, and the reference the
// grids must reproduce.

#include <memory>

#include "brdfsim/brdf.h"
#include "brdfsim/splat_set.h"

namespace gonio {

class BrdfSimple : public Brdf {
  public:
    explicit BrdfSimple(std::shared_ptr<const SplatSet> splats) : splats_(std::move(splats)) {}

    int NumComponents() const override { return splats_->NumComponents(); }
    bool IsIsotropic() const override { return splats_->Params().isotropic; }
    void Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const override;
    std::size_t MemoryBytes() const override;

  private:
    std::shared_ptr<const SplatSet> splats_;
};

}  // namespace gonio
