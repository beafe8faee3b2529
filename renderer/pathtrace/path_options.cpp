#include "renderer/pathtrace/path_options.h"

#include <algorithm>

namespace gonio {

PathTraceOptions ReadPathTraceOptions(const Frame& frame) {
    PathTraceOptions options;
    auto it = frame.options.user.find("pathtrace");
    if (it == frame.options.user.end()) return options;
    const ParamDict& params = it->second;
    options.enabled = params.GetInt("enable", 0) != 0;
    options.maxDepth = std::max(0, params.GetInt("maxdepth", options.maxDepth));
    options.rrDepth = std::max(0, params.GetInt("rrdepth", options.rrDepth));
    return options;
}

}  // namespace gonio
