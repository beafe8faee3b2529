#pragma once
// The tiles of one frame joined into its image (gonio farm assemble). Each tile is a crop-window
// render whose data window says where it lies (TIFF, OpenEXR); the joined image is their
// bounding window (the frame, or the scene's own CropWindow) and must be covered by exactly one
// tile at every pixel. Pixels are copied, never resampled: joined tiles equal the unsplit render.

#include <string>
#include <vector>

namespace gonio {

// Reads `tiles`, joins them and writes `output` (temporary name, then rename) in the tiles'
// channels, pixel type and metadata. Returns the reason on failure, naming the tile, "" on
// success.
std::string JoinTiles(const std::vector<std::string>& tiles, const std::string& output);

}  // namespace gonio
