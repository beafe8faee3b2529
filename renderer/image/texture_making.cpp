#include "renderer/image/texture_making.h"

#include <map>

#include "base/search_path.h"
#include "imageio/texture_making.h"

namespace gonio {

namespace {

// RISpec's filter names (those of PixelFilter, and "lanczos" as some RIBs write it) to
// OpenImageIO's; null where it has no such filter.
const char* OiioFilterName(const std::string& name) {
    static const std::map<std::string, const char*> kNames = {
        {"box", "box"},           {"triangle", "triangle"},
        {"gaussian", "gaussian"}, {"catmull-rom", "catmull-rom"},
        {"sinc", "sinc"},         {"b-spline", "bspline"},
        {"mitchell", "mitchell"}, {"disk", "disk"},
        {"lanczos", "lanczos3"},  {"blackman-harris", "blackman-harris"}};
    auto found = kNames.find(name);
    return found == kNames.end() ? nullptr : found->second;
}

TextureFileKind FileKind(TextureRequest::Kind kind) {
    switch (kind) {
        case TextureRequest::Kind::LatLongEnvironment:
            return TextureFileKind::LatLongEnvironment;
        case TextureRequest::Kind::CubeFaceEnvironment:
            return TextureFileKind::CubeFaceEnvironment;
        default:
            return TextureFileKind::Texture;
    }
}

std::string Listed(const std::vector<std::string>& folders) {
    std::string text;
    for (const std::string& folder : folders) text += (text.empty() ? "" : ", ") + folder;
    return text;
}

// The notes for what OpenImageIO's make_texture cannot honour: the filter's widths and the
// parameter list (PRMan's "float bias" and the like).
void NoteUnusedArguments(const TextureRequest& request, Diagnostics& diagnostics) {
    const std::string what = request.request;
    diagnostics.NoteOnce(what + " widths", request.loc,
                         what + ": the filter widths are OpenImageIO's own for each filter (" +
                             std::to_string(request.swidth) + " " + std::to_string(request.twidth) +
                             " given)");
    for (const Param& param : request.params)
        diagnostics.NoteOnce(what + " " + param.token, param.loc,
                             what + ": parameter \"" + param.token + "\" is ignored");
}

}  // namespace

bool MakeRequestedTexture(const TextureRequest& request, Diagnostics& diagnostics) {
    const std::string what = request.request;
    TextureFileRequest file;
    file.kind = FileKind(request.kind);
    file.wrap = request.wrap;
    file.fov = request.fov;
    if (const char* filter = OiioFilterName(request.filter)) {
        file.filter = filter;
    } else {
        diagnostics.WarningOnce(what + " filter " + request.filter, request.loc,
                                what + ": unknown filter \"" + request.filter +
                                    "\": the MIP levels are made with OpenImageIO's default");
    }
    NoteUnusedArguments(request, diagnostics);
    for (const std::string& picture : request.pictures) {
        const std::string found = FindOnSearchPath(picture, request.searchPath);
        if (found.empty()) {
            diagnostics.Error(request.loc, what + ": cannot find the picture \"" + picture +
                                               "\" (looked in " + Listed(request.searchPath) + ")");
            return false;
        }
        file.pictures.push_back(found);
    }
    const std::string error = MakeTextureFile(file, request.texture);
    if (error.empty()) return true;
    diagnostics.Error(request.loc, what + " \"" + request.texture + "\": " + error);
    return false;
}

}  // namespace gonio
