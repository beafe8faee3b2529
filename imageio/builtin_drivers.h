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
// Pixar's depth file: one float channel and the spec's two matrices (identity where it has none).
std::string WriteZfileFile(const std::string& path, const ImageFileSpec& spec,
                           const PixelBuffer& pixels);

// Readers of the depth maps MakeShadow and shadow() take (depth_map_file.h), "" or the reason.
// Whether the first 4 bytes of a file are the zfile magic number (either byte order).
bool IsZfileMagic(const unsigned char bytes[4]);
std::string ReadZfileFile(const std::string& path, ImageFileContents* contents);
// A TIFF of one 32-bit float channel (tiff_reader.cpp), strips or tiles, with Pixar's matrix
// tags where it has them; any other TIFF is refused, saying what it holds.
std::string ReadFloatTiffFile(const std::string& path, ImageFileContents* contents);

// "YYYY:MM:DD hh:mm:ss" in local time, the DateTime OpenImageIO records in TIFF and OpenEXR, or
// $SOURCE_DATE_EPOCH in UTC when that is set.
std::string CurrentDateTime();

// The compression name and quality of a "name:quality" Display parameter (quality -1 if none).
std::pair<std::string, int> SplitCompression(const std::string& compression);

}  // namespace gonio
