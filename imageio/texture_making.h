#pragma once
// Texture files made from pictures, as RISpec §7.1's MakeTexture, MakeLatLongEnvironment and
// MakeCubeFaceEnvironment make them: tiled and MIP-mapped by OpenImageIO's make_texture (what
// `maketx` runs) in the OpenImageIO plugin, written under a temporary name and renamed when
// complete.

#include <string>
#include <vector>

#include "base/texture_wrap.h"

namespace gonio {

enum class TextureFileKind { Texture, LatLongEnvironment, CubeFaceEnvironment };

struct TextureFileRequest {
    TextureFileKind kind = TextureFileKind::Texture;
    // The picture files: one, or the six cube faces in RISpec's order px nx py ny pz nz.
    std::vector<std::string> pictures;
    TextureWrapModes wrap;  // a plain texture's; environments wrap as their layout says
    std::string filter;     // OpenImageIO's filter name for the MIP levels; "" its default
    // The filter's widths, in pixels of the level being made; used with a filter only.
    float swidth = 1, twidth = 1;
    float fov = 90;  // the cube faces' full field of view, in degrees
};

// Makes the texture file `path`: a TIFF, or an OpenEXR file when the name says so (".exr").
// Environments are resampled into OpenImageIO's lat-long layout (imageio/environment_layout.h
// says why). Returns
// the reason on failure ("" on success), naming the picture that cannot be read; then `path` is
// left as it was.
std::string MakeTextureFile(const TextureFileRequest& request, const std::string& path);

}  // namespace gonio
