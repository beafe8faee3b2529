#pragma once
// The options that bound trace(). What a shader needs of the renderer (derivatives, traced
// rays) is the shading system's to say: sl::ShaderInstance::Needs().

#include "renderer/scene/frame.h"
#include "shaderlang/shading_system.h"

namespace gonio {

// Option "trace" "maxdepth" [n]: the deepest ray trace() follows (camera rays have depth 0,
// the rays a shader of a camera-ray hit traces depth 1, ...).
constexpr int kDefaultTraceMaxDepth = 6;
int TraceMaxDepth(const Frame& frame);

}  // namespace gonio
