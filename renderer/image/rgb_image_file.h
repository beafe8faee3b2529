#pragma once
// Reading and writing plain RGB pictures by file name (any format OpenImageIO knows), for the
// tools that compare and show renders: `gonio spectral diff` and its ΔE2000 maps.

#include <string>
#include <vector>

namespace gonio {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<float> rgb;      // 3 floats a pixel, rows from the top
    bool floatingPoint = false;  // stored as float or half: linear values, as gonio writes them
};

// The first three channels of the file's first subimage, as floats (linear as stored; an 8-bit
// file's values are divided by 255). Throws std::runtime_error naming the file.
RgbImage ReadRgbImage(const std::string& path);

// By the extension: float for OpenEXR, 8 bits (values clamped to [0, 1]) otherwise. Written
// under a temporary name, then renamed; throws std::runtime_error naming the file.
void WriteRgbImage(const std::string& path, const RgbImage& image);

}  // namespace gonio
