// The texture-making requests (RISpec §7.1): checked here, made by the handler that
// `gonio render` gives the builder (renderer/image/texture_making.h) at the request, so that a
// texture exists before the frames that follow it in the RIB. Valid anywhere in the RIB.

#include <optional>

#include "renderer/scene/scene_builder.h"
#include "renderer/scene/scene_builder_state.h"
#include "renderer/scene/search_paths.h"

namespace gonio {

namespace {

// MakeTexture's swrap or twrap: RISpec names "periodic", "clamp" and "black" only.
bool ReadWrap(const char* which, const std::string& name, const FileLoc& loc,
              Diagnostics& diagnostics, TextureWrap* out) {
    const std::optional<TextureWrap> wrap = TextureWrapFromName(name);
    if (!wrap || *wrap == TextureWrap::Default) {
        diagnostics.Error(loc, std::string("MakeTexture: ") + which +
                                   " must be \"periodic\", \"clamp\" or \"black\", got \"" + name +
                                   "\"");
        return false;
    }
    *out = *wrap;
    return true;
}

TextureRequest NewRequest(TextureRequest::Kind kind, const char* name, const std::string& texture,
                          const std::string& filter, float swidth, float twidth,
                          const ParamList& params, const FileLoc& loc) {
    TextureRequest request;
    request.kind = kind;
    request.request = name;
    request.texture = texture;
    request.filter = filter;
    request.swidth = swidth, request.twidth = twidth;
    request.params = params;
    request.loc = loc;
    return request;
}

}  // namespace

void SceneBuilder::SetTextureHandler(TextureHandler onTexture) {
    onTexture_ = std::move(onTexture);
}

void SceneBuilder::SubmitTextureRequest(TextureRequest request) {
    if (!onTexture_) return IgnoredRequest(request.request, request.loc);
    for (const std::string& name : request.pictures) {
        if (!name.empty()) continue;
        diagnostics_.Error(request.loc, std::string(request.request) + ": a picture name is empty");
        return;
    }
    if (request.texture.empty()) {
        diagnostics_.Error(request.loc,
                           std::string(request.request) + ": the texture file name is empty");
        return;
    }
    request.searchPath = TextureSearchPath(state_->options, sceneFile_);
    onTexture_(request);
}

void SceneBuilder::MakeTexture(const std::string& picture, const std::string& texture,
                               const std::string& swrap, const std::string& twrap,
                               const std::string& filter, float swidth, float twidth,
                               const ParamList& params, const FileLoc& loc) {
    TextureRequest request = NewRequest(TextureRequest::Kind::Texture, "MakeTexture", texture,
                                        filter, swidth, twidth, params, loc);
    request.pictures = {picture};
    if (!ReadWrap("swrap", swrap, loc, diagnostics_, &request.wrap.s) ||
        !ReadWrap("twrap", twrap, loc, diagnostics_, &request.wrap.t))
        return;
    SubmitTextureRequest(std::move(request));
}

void SceneBuilder::MakeLatLongEnvironment(const std::string& picture, const std::string& texture,
                                          const std::string& filter, float swidth, float twidth,
                                          const ParamList& params, const FileLoc& loc) {
    TextureRequest request =
        NewRequest(TextureRequest::Kind::LatLongEnvironment, "MakeLatLongEnvironment", texture,
                   filter, swidth, twidth, params, loc);
    request.pictures = {picture};
    SubmitTextureRequest(std::move(request));
}

void SceneBuilder::MakeCubeFaceEnvironment(const std::vector<std::string>& faces,
                                           const std::string& texture, float fov,
                                           const std::string& filter, float swidth, float twidth,
                                           const ParamList& params, const FileLoc& loc) {
    // RISpec: fov is the full angle each face sees; beyond (0, 180) a face sees nothing sane.
    if (!(fov > 0 && fov < 180)) {
        diagnostics_.Error(loc, "MakeCubeFaceEnvironment: fov must lie in (0, 180) degrees, got " +
                                    std::to_string(fov));
        return;
    }
    TextureRequest request =
        NewRequest(TextureRequest::Kind::CubeFaceEnvironment, "MakeCubeFaceEnvironment", texture,
                   filter, swidth, twidth, params, loc);
    request.pictures = faces;
    request.fov = fov;
    SubmitTextureRequest(std::move(request));
}

}  // namespace gonio
