#pragma once
// RenderMan's environment pictures in the layout OpenImageIO's environment() reads. RenderMan
// (RISpec §7.1; Aqsis reads them so) has lat-long pictures with +z up: the top row looks along
// +z, s = 1/2 + atan2(y, x)/2π, t = acos(z)/π. OpenImageIO reads a lat-long TIFF with +y up
// (s = 1/2 + atan2(-x, z)/2π, t = 1/2 - asin(y)/π), and a TIFF cannot say otherwise; and it
// looks environments up only as lat-long maps, whatever a file's "textureformat" says. So both
// MakeLatLongEnvironment's picture and MakeCubeFaceEnvironment's six faces are resampled into
// OpenImageIO's lat-long layout, so that environment() along a direction reads what the
// RenderMan picture shows in that direction.

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

// The picture (4n × 2n for faces n wide) in OpenImageIO's lat-long layout whose every pixel is
// the mean of 2 × 2 directions looked up in the faces (bilinear, edges clamped). The faces must
// have the same channels (checked by the caller); the result stores its samples as the first
// face does.
ImageFileContents LatLongFromCubeFaces(const CubeFaces& faces, float fovDegrees);

// A RenderMan (+z up) lat-long picture resampled the same way into OpenImageIO's layout, at
// the same size (bilinear, periodic in s, clamped in t).
ImageFileContents LatLongFromRenderManLatLong(const ImageFileContents& picture);

}  // namespace gonio
