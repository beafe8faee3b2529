#include "renderer/shading/shader_needs.h"

#include <algorithm>
#include <string>

namespace gonio {

int TraceMaxDepth(const Frame& frame) {
    auto it = frame.options.user.find("trace");
    if (it == frame.options.user.end()) return kDefaultTraceMaxDepth;
    return std::max(0, it->second.GetInt("maxdepth", kDefaultTraceMaxDepth));
}

int TraceMaxDiffuseDepth(const Attributes& attributes) {
    auto it = attributes.user.find("trace");
    if (it == attributes.user.end()) return kDefaultTraceMaxDiffuseDepth;
    return std::max(0, it->second.GetInt("maxdiffusedepth", kDefaultTraceMaxDiffuseDepth));
}

float TraceBias(const Attributes& attributes) {
    auto it = attributes.user.find("trace");
    return it == attributes.user.end() ? -1.f : it->second.GetFloat("bias", -1.f);
}

}  // namespace gonio
