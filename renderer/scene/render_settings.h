#pragma once
// What one `gonio render` run asks of every frame it renders, image or photon map, beside what
// the scene itself says.

#include <cstdint>
#include <string>

namespace gonio {

struct RenderSettings {
    uint64_t seed = 0;
    bool progress = false;
    // Replaces the first Display's file name (gonio render -o); for several frames a "#" in it
    // is replaced by the frame number.
    std::string outputOverride;
};

}  // namespace gonio
