#include "renderer/image/filter_table.h"

#include <algorithm>
#include <cmath>

namespace gonio {

FilterTable::FilterTable(float radius, const std::function<float(float)>& weight) {
    const int intervals = radius > 0 ? std::max(1024, int(std::ceil(512 * radius))) : 0;
    scale_ = radius > 0 ? float(intervals) / radius : 0;
    intervals_ = float(intervals);
    table_.resize(size_t(intervals) + 2);
    for (int i = 0; i <= intervals; ++i)
        table_[size_t(i)] = weight(intervals > 0 ? radius * float(i) / float(intervals) : 0);
    table_[size_t(intervals) + 1] = table_[size_t(intervals)];
}

}  // namespace gonio
