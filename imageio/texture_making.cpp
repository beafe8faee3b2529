#include "imageio/texture_making.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "base/interrupt_cleanup.h"
#include "imageio/environment_layout.h"
#include "imageio/image_formats.h"
#include "imageio/oiio_plugin.h"

namespace gonio {

namespace {

// The picture's every channel as float; the reason in `error` when it cannot be read.
ImageFileContents ReadPicture(OiioPlugin& plugin, const std::string& path, std::string* error) {
    std::string why;
    ImageFileContents picture = plugin.ReadImage(path, &why);
    if (why.empty() && picture.spec.Channels() == 0) why = "it holds no channels";
    if (!why.empty()) *error = "cannot read the picture \"" + path + "\": " + why;
    return picture;
}

// The six faces, each read and with the first face's channels; the reason in `error` if not.
CubeFaces ReadCubeFaces(OiioPlugin& plugin, const std::vector<std::string>& paths,
                        std::string* error) {
    CubeFaces faces;
    for (size_t f = 0; f < faces.size() && error->empty(); ++f) {
        faces[f] = ReadPicture(plugin, paths[f], error);
        if (error->empty() && faces[f].spec.Channels() != faces[0].spec.Channels())
            *error = "the cube face \"" + paths[f] + "\" has " +
                     std::to_string(faces[f].spec.Channels()) + " channels, \"" + paths[0] + "\" " +
                     std::to_string(faces[0].spec.Channels());
    }
    return faces;
}

// The picture the texture is made from: the one picture, or for an environment the lat-long
// map in OpenImageIO's layout (environment_layout.h).
ImageFileContents SourcePicture(OiioPlugin& plugin, const TextureFileRequest& request,
                                std::string* error) {
    if (request.kind == TextureFileKind::Texture)
        return ReadPicture(plugin, request.pictures.at(0), error);
    if (request.kind == TextureFileKind::LatLongEnvironment) {
        const ImageFileContents picture = ReadPicture(plugin, request.pictures.at(0), error);
        return error->empty() ? LatLongFromRenderManLatLong(picture) : ImageFileContents{};
    }
    if (request.pictures.size() != 6) {
        *error = "a cube face environment needs 6 pictures, got " +
                 std::to_string(request.pictures.size());
        return {};
    }
    const CubeFaces faces = ReadCubeFaces(plugin, request.pictures, error);
    return error->empty() ? LatLongFromCubeFaces(faces, request.fov) : ImageFileContents{};
}

// The number of MIP levels below a picture of width × height: each halves its sides (a side
// of 1 stays 1) until both are 1, as make_texture halves them.
int LevelsBelow(int width, int height) {
    int levels = 0;
    for (; width > 1 || height > 1; ++levels)
        width = std::max(1, width / 2), height = std::max(1, height / 2);
    return levels;
}

// Names for the filtered MIP levels beside the texture's temporary file, each removed when this
// object goes (and on Ctrl-C, base/interrupt_cleanup.h) so that none is left behind.
class LevelFiles {
  public:
    LevelFiles(const std::string& temporary, int levels) {
        for (int level = 1; level <= levels; ++level) {
            names_.push_back(temporary + ".level" + std::to_string(level) + ".tif");
            pending_.push_back(std::make_unique<PendingTemporary>(names_.back()));
        }
    }
    ~LevelFiles() {
        for (const std::string& name : names_) std::remove(name.c_str());
    }
    LevelFiles(const LevelFiles&) = delete;
    LevelFiles& operator=(const LevelFiles&) = delete;
    const std::vector<std::string>& Names() const { return names_; }

  private:
    std::vector<std::string> names_;
    std::vector<std::unique_ptr<PendingTemporary>> pending_;
};

}  // namespace

std::string MakeTextureFile(const TextureFileRequest& request, const std::string& path) {
    OiioPlugin* plugin = nullptr;
    try {
        plugin = &LoadOiioPlugin("making the texture \"" + path + "\"");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    std::string error;
    const ImageFileContents picture = SourcePicture(*plugin, request, &error);
    if (!error.empty()) return error;
    TextureMakeOptions options;
    options.latLongEnvironment = request.kind != TextureFileKind::Texture;
    // An environment is periodic in longitude and clamped at the poles, as OpenImageIO's
    // environment() reads it whatever the file says; the file says so too.
    options.wrap = options.latLongEnvironment
                       ? TextureWrapModes{TextureWrap::Periodic, TextureWrap::Clamp}
                       : request.wrap;
    options.filter = request.filter;
    options.swidth = request.swidth, options.twidth = request.twidth;
    options.format = FormatForFileName(path) == "openexr" ? "openexr" : "tiff";
    const int levels =
        request.filter.empty() ? 0 : LevelsBelow(picture.spec.width, picture.spec.height);
    return WriteThroughTemporary(path, [&](const std::string& temporary) {
        const LevelFiles levelFiles(temporary, levels);
        options.levelFiles = levelFiles.Names();
        return plugin->MakeTexture(picture, temporary, options);
    });
}

}  // namespace gonio
