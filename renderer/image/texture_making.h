#pragma once
// The texture files a scene's MakeTexture, MakeLatLongEnvironment and MakeCubeFaceEnvironment
// requests ask for (renderer/scene/texture_request.h), made through imageio's texture making
// (OpenImageIO's make_texture, as `maketx` makes them) at the request.

#include "base/diagnostics.h"
#include "renderer/scene/texture_request.h"

namespace gonio {

// Finds the request's pictures on its texture search path and makes its file, with RISpec's
// filter name mapped to OpenImageIO's and the MIP levels filtered at the request's widths. A
// picture that cannot be found or read, or a width outside (0, 256], is an error at the
// request's location, and no file is made; an unknown filter and any parameter are noted.
// Returns whether the file was made.
bool MakeRequestedTexture(const TextureRequest& request, Diagnostics& diagnostics);

}  // namespace gonio
