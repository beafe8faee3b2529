#pragma once
// The options and attributes that bound trace() and the ray-traced built-ins. What a shader needs
// of the renderer (derivatives, traced rays) is the shading system's to say:
// sl::ShaderInstance::Needs().

#include "renderer/scene/frame.h"
#include "shaderlang/shading_system.h"

namespace gonio {

// Option "trace" "maxdepth" [n]: the deepest ray trace() follows (camera rays have depth 0,
// the rays a shader of a camera-ray hit traces depth 1, ...).
constexpr int kDefaultTraceMaxDepth = 6;
int TraceMaxDepth(const Frame& frame);

// Attribute "trace" "maxdiffusedepth" [n] of the shaded object (Pixie's and PRMan's): the
// deepest ray whose hits its indirectdiffuse() and gather() rays shade (beyond, a hit brings
// black; an environment map lights only misses). Each level multiplies the rays by the
// samples, so the default is 1: camera-ray hits gather shaded light, the hits they shade
// gather none.
constexpr int kDefaultTraceMaxDiffuseDepth = 1;
int TraceMaxDiffuseDepth(const Attributes& attributes);
// Attribute "trace" "bias" [b]: where the ray-traced built-ins' rays start (current-space
// distance) when their "bias" option does not say; negative (the default): trace()'s offset.
float TraceBias(const Attributes& attributes);

}  // namespace gonio
