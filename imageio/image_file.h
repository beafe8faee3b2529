#pragma once
// A picture as a file holds it, described without any image library's types: the size, the
// data and display windows, the channels, the pixel type and the string metadata. The built-in
// drivers (TIFF, PNG, OpenEXR, zfile) and the OpenImageIO plugin both write and read this.

#include <string>
#include <utility>
#include <vector>

namespace gonio {

// How the samples are stored: in memory (UInt8, UInt16, Float) and in a file (also Half, which
// OpenEXR stores and the drivers convert float data to).
enum class PixelType { UInt8, UInt16, Half, Float };

struct ImageFileSpec {
    int width = 0, height = 0;
    // The data window's origin in the frame and the frame's size (the display window); a full
    // size of 0 means the data window is the frame.
    int x = 0, y = 0;
    int fullWidth = 0, fullHeight = 0;
    std::vector<std::string> channelNames;
    int alphaChannel = -1, zChannel = -1;
    PixelType fileType = PixelType::UInt8;
    // The Display parameter "compression" as the user gave it ("zip", "piz", "lzw:9", ...);
    // empty: the format's default.
    std::string compression;
    // String metadata, in order: "Software", "ImageDescription", "spectralLayoutVersion", ...
    std::vector<std::pair<std::string, std::string>> attributes;
    // The camera a depth map was rendered from, as Pixar's zfile and shadow-map TIFF record it
    // (OpenImageIO's "worldtocamera" and "worldtoscreen"): 16 floats each, row-major, for row
    // vectors (p · M, as RenderMan writes matrices); screen space with the frame's screen window
    // mapped to [-1, 1]². Empty: the file records none.
    std::vector<float> worldToCamera, worldToScreen;

    int Channels() const { return int(channelNames.size()); }
    int FullWidth() const { return fullWidth > 0 ? fullWidth : width; }
    int FullHeight() const { return fullHeight > 0 ? fullHeight : height; }
};

// Interleaved pixels, rows from the top, in `type` (UInt8, UInt16 or Float).
struct PixelBuffer {
    PixelType type = PixelType::Float;
    const void* data = nullptr;
};

// A picture read back: every channel of the first subimage as float, and the string metadata.
struct ImageFileContents {
    ImageFileSpec spec;  // fileType: how the file stores the samples
    std::vector<float> pixels;
};

}  // namespace gonio
