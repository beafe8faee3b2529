#pragma once
// Samples from one in-memory type to another, rounded and scaled as OpenImageIO converts them
// (so a driver given float data for an 8-bit file writes what OpenImageIO's would): float to
// integer codes as v × max + 0.5 clamped to [0, max] and truncated, codes to float as code / max.

#include <cstddef>
#include <vector>

#include "imageio/image_file.h"

namespace gonio {

// `count` samples of `pixels` as `to` (UInt8, UInt16 or Float).
std::vector<unsigned char> ConvertPixels(const PixelBuffer& pixels, size_t count, PixelType to);

}  // namespace gonio
