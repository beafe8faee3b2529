#pragma once
// The search paths a scene's options set (`Option "searchpath" "shader" | "texture"`), with the
// defaults that depend on where the scene file is: shared by the shading of a frame and the
// texture-making requests, which find their pictures before any frame exists.

#include <string>
#include <vector>

#include "renderer/scene/options.h"

namespace gonio {

// The folder of the scene's RIB file ("." for standard input or a name without a folder).
std::string SceneFolder(const std::string& sceneFile);

// `Option "searchpath" kind` of these options, its '&' and '@' standing for `standard`;
// `standard` when unset.
std::vector<std::string> OptionSearchPath(const Options& options, const std::string& kind,
                                          const std::vector<std::string>& standard);

// Where textures, their pictures and .grd files are looked for: the working folder, then the
// scene's folder (Option "searchpath" "texture" changes it).
std::vector<std::string> TextureSearchPath(const Options& options, const std::string& sceneFile);

}  // namespace gonio
