#pragma once
// Renders one Frame to its Display outputs: camera rays over tiles in parallel (oneTBB),
// stratified pixel samples, shading, the film and the pixel filter, and image output.

#include <cstdint>
#include <string>

#include "base/diagnostics.h"
#include "scene/frame.h"

namespace gonio {

struct RenderSettings {
    uint64_t seed = 0;
    bool progress = false;
    // Replaces the first Display's file name (gonio render -o); for several frames a "#" in it
    // is replaced by the frame number.
    std::string outputOverride;
};

struct RenderStats {
    double seconds = 0;
    uint64_t cameraRays = 0;
    uint64_t raysTraced = 0;  // including continuation rays through transparent surfaces
    int width = 0, height = 0;
};

// Returns false if an output could not be written (already reported).
bool RenderFrame(const Frame& frame, const RenderSettings& settings, Diagnostics& diagnostics,
                 RenderStats* stats);

}  // namespace gonio
