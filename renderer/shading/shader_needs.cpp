#include "renderer/shading/shader_needs.h"

#include <algorithm>
#include <string>

namespace gonio {

int TraceMaxDepth(const Frame& frame) {
    auto it = frame.options.user.find("trace");
    if (it == frame.options.user.end()) return kDefaultTraceMaxDepth;
    return std::max(0, it->second.GetInt("maxdepth", kDefaultTraceMaxDepth));
}

}  // namespace gonio
