#pragma once
// Depth maps and shadow maps as files (RISpec §4.1.4 MakeShadow, §15.7.3 shadow()). A depth map
// is a zfile (`Display "x.z" "zfile" "z"`) or a TIFF of one float channel; a shadow map is a
// float TIFF tagged textureformat "Shadow" with the camera it was rendered from, as PRMan's
// `.sm` files and `maketx --shadow` record it (Pixar's matrix tags, OpenImageIO's
// "worldtocamera" and "worldtoscreen"). Built in: no OpenImageIO.

#include <string>

#include "imageio/image_file.h"

namespace gonio {

// Reads a depth map or shadow map into one float channel "z" with its matrices: a zfile
// (recognised by its magic number, whatever its name; plain or gzip-compressed) or a TIFF of one
// 32-bit float channel. Returns "" or why the file is not one (it names the file).
std::string ReadDepthMapFile(const std::string& path, ImageFileContents* map);

// Writes `map` (one float channel with both matrices) as a shadow map, under a temporary name
// renamed into place when complete. Returns "" or the reason.
std::string WriteShadowMapFile(const std::string& path, const ImageFileContents& map);

// MakeShadow: the depth map `picture` made into the shadow map `shadowMap`. A depth map that
// records no camera (a float TIFF without the matrix tags) is refused. Returns "" or the reason.
std::string MakeShadowMapFile(const std::string& picture, const std::string& shadowMap);

}  // namespace gonio
