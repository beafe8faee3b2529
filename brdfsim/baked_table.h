#pragma once
// A reconstructed BRDF resampled onto a regular grid of angles, for O(1) interpolated lookups in
// the renderer (beyond the thesis). Anisotropic: θ_in × φ_in × θ_out × φ_out; isotropic:
// θ_in × θ_out × Δφ. θ nodes run from 0 to π/2 inclusive, φ nodes are periodic.

#include <array>
#include <vector>

#include "brdfsim/brdf.h"
#include "brdfsim/cell_lists.h"

namespace gonio {

class BakedTable : public Brdf {
  public:
    // Samples `source` with `resolution` θ nodes and 2·resolution φ nodes per hemisphere.
    BakedTable(const Brdf& source, int resolution, const ProgressFn& progress = {});
    // From stored values (.grd): dims = {θ_in, φ_in, θ_out, φ_out} node counts (φ_in = 1 when
    // isotropic), values in that order with the component fastest.
    BakedTable(bool isotropic, int ncomps, std::array<int, 4> dims, std::vector<float> values);

    int NumComponents() const override { return ncomps_; }
    bool IsIsotropic() const override { return isotropic_; }
    void Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const override;
    std::size_t MemoryBytes() const override { return values_.size() * sizeof(float); }

    const std::array<int, 4>& Dims() const { return dims_; }
    const std::vector<float>& Values() const { return values_; }

  private:
    std::size_t Index(int ti, int pi, int to, int po) const {
        return ((static_cast<std::size_t>(ti) * dims_[1] + pi) * dims_[2] + to) * dims_[3] + po;
    }

    bool isotropic_;
    int ncomps_;
    std::array<int, 4> dims_;
    std::vector<float> values_;
};

}  // namespace gonio
