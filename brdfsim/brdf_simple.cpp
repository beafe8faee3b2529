#include "brdfsim/brdf_simple.h"

#include <vector>

namespace gonio {

void BrdfSimple::Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const {
    const int n = splats_->NumComponents();
    std::vector<double> acc(n, 0.0);
    if (wIn.z > 0 && wOut.z > 0) {
        const SplatQuery q = splats_->MakeQuery(wIn, wOut);
        for (int v = 0; v < splats_->NumImages(); ++v) {
            if (!(q.activeMask & (1u << v))) continue;
            for (std::size_t k = 0; k < splats_->Size(); ++k) {
                splats_->Accumulate(k, v, q, acc.data());
            }
        }
    }
    for (int c = 0; c < n; ++c) f[c] = static_cast<float>(acc[c]);
}

std::size_t BrdfSimple::MemoryBytes() const { return SplatSetBytes(*splats_); }

}  // namespace gonio
