#pragma once
// A texture-making request of RISpec §7.1 (MakeTexture, MakeLatLongEnvironment,
// MakeCubeFaceEnvironment) as the scene builder hands it over, at the request and in RIB order:
// its arguments checked, and the texture search path in force there, on which its pictures are
// found. Making the file is the image stage's job (renderer/image/texture_making.h).

#include <string>
#include <vector>

#include "base/file_loc.h"
#include "base/texture_wrap.h"
#include "renderer/rib/param_list.h"

namespace gonio {

struct TextureRequest {
    enum class Kind { Texture, LatLongEnvironment, CubeFaceEnvironment };
    Kind kind = Kind::Texture;
    const char* request = "MakeTexture";  // the RIB request's name, for messages
    // The pictures as the RIB names them: one, or the cube faces px nx py ny pz nz.
    std::vector<std::string> pictures;
    std::string texture;    // the file to make, relative to the working folder
    TextureWrapModes wrap;  // MakeTexture's swrap and twrap (never Default)
    std::string filter;     // RISpec's filter name, as written
    float swidth = 1, twidth = 1;
    float fov = 90;    // MakeCubeFaceEnvironment's full field of view of a face, degrees
    ParamList params;  // the request's parameter list (none is used)
    std::vector<std::string> searchPath;
    FileLoc loc;
};

}  // namespace gonio
