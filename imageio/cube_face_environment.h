#pragma once
// MakeCubeFaceEnvironment's six face pictures (RISpec §7.1) resampled into one lat-long
// environment picture. OpenImageIO's TextureSystem looks environments up only as lat-long maps
// (its environment() assumes that layout, whatever the file's "textureformat" says), so the
// faces are not stored as a cube: the lat-long map is what gonio's environment() reads.

#include <array>

#include "imageio/image_file.h"

namespace gonio {

// The face pictures in RISpec's order px nx py ny pz nz.
using CubeFaces = std::array<ImageFileContents, 6>;

// Where a direction falls on a cube face of full field of view `fovDegrees`: the face (index in
// CubeFaces) and the point on its picture, x to the right and y down, each in [0, 1] when the
// face sees the direction (beyond for fov < 90).
struct CubeFacePoint {
    int face = 0;
    float x = 0, y = 0;
};
CubeFacePoint CubeFacePointOf(float dx, float dy, float dz, float fovDegrees);

// The lat-long picture (4n × 2n for faces n wide, OpenImageIO's layout: the top row looks along
// +z, s = 1/2 + atan2(y, x)/2π) whose every pixel is the mean of 2 × 2 directions looked up in
// the faces (bilinear, edges clamped). The faces must have the same channels (checked by the
// caller); the result stores its samples as the first face does.
ImageFileContents LatLongFromCubeFaces(const CubeFaces& faces, float fovDegrees);

}  // namespace gonio
