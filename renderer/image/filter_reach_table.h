#pragma once
// One axis of a narrow separable pixel filter (radius up to 1.5 pixels, so that a sample
// reaches at most three pixels a side: the Gaussian 2 2 RenderMan starts with, box, triangle)
// tabulated by where the sample lies within its own pixel: one lookup gives its weights for
// all the pixels it can reach, side by side in a Float4, where FilterTable takes one lookup
// per pixel. 512 intervals across the pixel, linear in between, like FilterTable; the reach's
// edges are exact: a pixel counts a sample when -radius <= d < radius, d the offset from its
// centre.

#include <functional>
#include <vector>

#include "base/float4.h"

namespace gonio {

class FilterReachTable {
  public:
    // Whether a filter of this radius reaches few enough pixels.
    static bool Covers(float radius) { return radius <= 1.5f; }

    FilterReachTable() = default;
    // `weight(d)` for 0 <= d <= radius (Covers(radius)); `margin` the pixels reached each way
    // beyond the sample's own (0 or 1).
    FilterReachTable(float radius, int margin, const std::function<float(float)>& weight);

    // For a sample at fraction f in [0, 1] across its pixel p, the weights of pixels
    // p − margin, p − margin + 1, ...: 0 for those beyond the radius and in the lanes past
    // 2·margin + 1.
    Float4 operator()(float f) const {
        const float x = f * kIntervals;
        const int i = int(x);
        const float t = x - float(i);
        const float* row = rows_.data() + kFloat4Lanes * i;
        const Float4 at = Load4(row), next = Load4(row + kFloat4Lanes);
        const Float4 d = f + offsets_;  // from each pixel's centre
        return Select4((d >= -radius_) & (d < radius_), at + t * (next - at), Float4{});
    }

  private:
    static constexpr int kIntervals = 512;
    // Per row i (f = i / kIntervals, and one more row past f = 1), each lane's weight, the
    // filter's value at the radius where the offset lies beyond it.
    std::vector<float> rows_;
    Float4 offsets_ = {};  // f + offsets_[k] is the offset from lane k's pixel centre
    float radius_ = 0;
};

}  // namespace gonio
