#pragma once
// Option "pathtrace": turns the image render into a global-illumination path tracer
// (docs/path-tracing.md). Samples per pixel are PixelSamples, as for every render.
//
//   Option "pathtrace" "integer enable" [1]   # 0 (default): shade with the shaders as always
//                      "integer maxdepth" [16] # most bounces a path makes (0: emitters only)
//                      "integer rrdepth" [3]   # bounces before Russian roulette may end a path

#include "renderer/scene/frame.h"

namespace gonio {

struct PathTraceOptions {
    bool enabled = false;
    int maxDepth = 16;
    int rrDepth = 3;
};

PathTraceOptions ReadPathTraceOptions(const Frame& frame);

}  // namespace gonio
