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
    // gonio render --crop: the part of the scene's own CropWindow (xmin xmax ymin ymax, as
    // fractions of it) to render, so that a farm renders one image as tiles.
    float crop[4] = {0, 1, 0, 1};
    // gonio render --photon-shard I/N: of a BRDFLight frame's paths, trace only shard I of N
    // (photon_frame.h says which paths those are).
    uint64_t photonShard = 0, photonShards = 1;
};

}  // namespace gonio
