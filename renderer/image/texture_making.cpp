#include "renderer/image/texture_making.h"

#include <map>

#include "base/limits.h"
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

// The notes for the parameter list (PRMan's "float bias" and the like), which no RISpec
// request defines.
void NoteUnusedParameters(const TextureRequest& request, Diagnostics& diagnostics) {
    for (const Param& param : request.params)
        diagnostics.NoteOnce(
            std::string(request.request) + " " + param.token, param.loc,
            std::string(request.request) + ": parameter \"" + param.token + "\" is ignored");
}

// RISpec's filter widths are pixels of the level made; past PixelFilter's limit (256) the
// filtering would take quadratically long for nothing.
bool CheckFilterWidths(const TextureRequest& request, Diagnostics& diagnostics) {
    const auto ok = [](float width) { return width > 0 && width <= kMaxFilterWidth; };
    if (ok(request.swidth) && ok(request.twidth)) return true;
    diagnostics.Error(request.loc,
                      std::string(request.request) + ": the filter widths must be in (0, " +
                          FormatNumber(kMaxFilterWidth) + "] pixels, got " +
                          FormatNumber(request.swidth) + " " + FormatNumber(request.twidth));
    return false;
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
    NoteUnusedParameters(request, diagnostics);
    if (!CheckFilterWidths(request, diagnostics)) return false;
    file.swidth = request.swidth, file.twidth = request.twidth;
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
