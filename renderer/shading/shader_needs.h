#pragma once
// What a frame's shaders need from the renderer beyond running them: neighbour points for
// derivatives, and the ray tracer for trace(), read off their compiled code once per frame; and
// the options that bound trace().

#include "renderer/scene/frame.h"
#include "shaderlang/shading_system.h"

namespace gonio {

struct ShaderNeeds {
    bool derivatives = false;  // calls Du, Dv, Deriv, area, calculatenormal, texture,
                               // filterstep, ... or reads the globals du, dv
    bool trace = false;        // calls trace()
};

// The needs of a specialised instance (null: none).
ShaderNeeds ScanShaderNeeds(const sl::ShaderInstance* instance);

// Option "trace" "maxdepth" [n]: the deepest ray trace() follows (camera rays have depth 0,
// the rays a shader of a camera-ray hit traces depth 1, ...).
constexpr int kDefaultTraceMaxDepth = 6;
int TraceMaxDepth(const Frame& frame);

}  // namespace gonio
