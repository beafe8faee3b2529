#pragma once
// The texture files a scene's MakeTexture, MakeLatLongEnvironment and MakeCubeFaceEnvironment
// requests ask for (renderer/scene/texture_request.h), made through imageio's texture making
// (OpenImageIO's make_texture, as `maketx` makes them) at the request.

#include "base/diagnostics.h"
#include "renderer/scene/texture_request.h"

namespace gonio {

// Finds the request's pictures on its texture search path and makes its file, with RISpec's
// filter name mapped to OpenImageIO's. A picture that cannot be found or read is an error at
// the request's location, and no file is made; an unknown filter, the filter widths and any
// parameter are noted (OpenImageIO filters MIP levels at its own width for each filter).
// Returns whether the file was made.
bool MakeRequestedTexture(const TextureRequest& request, Diagnostics& diagnostics);

}  // namespace gonio
