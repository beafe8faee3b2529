#pragma once
// The display drivers gonio has built in, one file each, for the formats people render to.
// Each writes exactly the file OpenImageIO 2.4's writer for its format writes from the same
// ImageFileSpec (the same tags, chunks and attributes, the same default compression), so that
// images do not change with the driver; the pixels come already in the file's type (UInt8,
// UInt16 or Float; Half files get Float). Each returns the reason on failure, "" on success;
// the caller writes under a temporary name and renames (image_formats.cpp).

#include <string>

#include "imageio/image_file.h"

namespace gonio {

std::string WriteTiffFile(const std::string& path, const ImageFileSpec& spec,
                          const PixelBuffer& pixels);
std::string WritePngFile(const std::string& path, const ImageFileSpec& spec,
                         const PixelBuffer& pixels);
std::string WriteExrFile(const std::string& path, const ImageFileSpec& spec,
                         const PixelBuffer& pixels);
// Pixar's depth file: one float channel and two matrices (identity: gonio records none).
std::string WriteZfileFile(const std::string& path, const ImageFileSpec& spec,
                           const PixelBuffer& pixels);

// "YYYY:MM:DD hh:mm:ss" in local time, the DateTime OpenImageIO records in TIFF and OpenEXR, or
// $SOURCE_DATE_EPOCH in UTC when that is set.
std::string CurrentDateTime();

// The compression name and quality of a "name:quality" Display parameter (quality -1 if none).
std::pair<std::string, int> SplitCompression(const std::string& compression);

}  // namespace gonio
