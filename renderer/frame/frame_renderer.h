#pragma once
// Renders one Frame to its Display outputs: camera rays over tiles in parallel (oneTBB),
// stratified pixel samples, shading, the film and the pixel filter, and image output.

#include <cstdint>
#include <string>

#include "base/diagnostics.h"
#include "renderer/raytrace/ray_counts.h"
#include "renderer/scene/frame.h"
#include "renderer/scene/render_settings.h"

namespace gonio {

struct RenderStats {
    double seconds = 0;
    uint64_t cameraRays = 0;  // one per pixel sample
    RayCounts rays;           // every ray traced, by kind
    int width = 0, height = 0;
};

// Returns false if an output could not be written (already reported). A frame too large for
// this machine's memory is an error in the scene (reported at its Format): nothing is rendered
// and it returns true.
bool RenderFrame(const Frame& frame, const RenderSettings& settings, Diagnostics& diagnostics,
                 RenderStats* stats);

}  // namespace gonio
