// MakeShadow (RISpec §4.1.4 / §8.1): a depth map (a zfile, or a float TIFF that records its
// camera) made into a shadow map file for shadow(), at once, so that a later frame of the same
// RIB can look it up: the usual two-pass scene renders the depth from the light in one frame
// and the picture in the next.
#include "imageio/depth_map_file.h"
#include "renderer/scene/scene_builder.h"

namespace gonio {

void SceneBuilder::MakeShadow(const std::string& picture, const std::string& texture,
                              const ParamList& params, const FileLoc& loc) {
    if (!params.empty())
        diagnostics_.WarningOnce("MakeShadow parameters", loc,
                                 "MakeShadow takes no parameters here; they are ignored");
    const std::string error = MakeShadowMapFile(picture, texture);
    if (!error.empty())
        diagnostics_.Error(loc, "MakeShadow cannot make \"" + texture + "\": " + error);
}

}  // namespace gonio
