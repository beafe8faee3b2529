#pragma once
// One axis of a separable pixel filter, tabulated for splatting. Every camera sample weighs
// each pixel it reaches by the filter at its offset, a few times a sample; evaluating the
// filter there (a Gaussian's exp, a sinc's sines) cost about a tenth of a render. The filters
// RenderMan names are even in the offset, so the table covers [0, radius] and interpolates
// linearly, with at least 1024 entries and 512 per pixel of offset: a Gaussian 2 2 is within
// 5e-7 of its exact value, a sinc (curvature up to π²) within 5e-6.

#include <functional>
#include <vector>

namespace gonio {

class FilterTable {
  public:
    FilterTable() = default;
    // `weight(d)` for 0 <= d <= radius; the table is 0 beyond the radius.
    FilterTable(float radius, const std::function<float(float)>& weight);

    // The weight at offset d (either sign); 0 when |d| > radius.
    float operator()(float d) const {
        const float x = (d < 0 ? -d : d) * scale_;
        if (!(x <= intervals_)) return 0;
        const int i = int(x);
        const float f = x - float(i);  // 0 at the last entry, whose copy follows it
        const float* table = table_.data();
        return table[i] + f * (table[i + 1] - table[i]);
    }

  private:
    // The weights at 0, radius / intervals_, ... radius, and the last once more, so that the
    // interpolation needs no test for the end.
    std::vector<float> table_ = std::vector<float>(2, 0.f);
    float intervals_ = 0;
    float scale_ = 0;  // entry intervals per unit offset
};

}  // namespace gonio
