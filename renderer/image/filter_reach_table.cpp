#include "renderer/image/filter_reach_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gonio {

FilterReachTable::FilterReachTable(float radius, int margin,
                                   const std::function<float(float)>& weight)
    : rows_(size_t(kFloat4Lanes) * (kIntervals + 2), 0.f), radius_(radius) {
    const int lanes = 2 * margin + 1;
    for (int k = 0; k < kFloat4Lanes; ++k)
        // Lane k is pixel p − margin + k, centred at p − margin + k + 0.5; past the reach, an
        // offset that is never within the radius.
        offsets_[k] = k < lanes ? float(margin - k) - 0.5f : std::numeric_limits<float>::infinity();
    for (int i = 0; i <= kIntervals + 1; ++i) {
        const float f = float(i) / kIntervals;
        for (int k = 0; k < lanes; ++k)
            rows_[size_t(kFloat4Lanes * i + k)] =
                weight(std::min(std::fabs(f + offsets_[k]), radius));
    }
}

}  // namespace gonio
