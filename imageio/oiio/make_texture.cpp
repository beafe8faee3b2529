// MakeTexture and MakeLatLongEnvironment through OpenImageIO's make_texture, the function
// `maketx` runs: a tiled, MIP-mapped file whose metadata (textureformat, wrapmodes) its
// TextureSystem reads back. make_texture filters its MIP levels at its own width for each
// filter; RISpec's MakeTexture gives the widths, so the levels are filtered here and handed to
// make_texture as custom levels.
#include <OpenImageIO/filter.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "imageio/oiio/oiio_parts.h"
#include "imageio/oiio/oiio_spec.h"

namespace gonio {

namespace {

// The picture's float samples in an ImageBuf of its size, channels and windows.
OIIO::ImageBuf PictureBuffer(const ImageFileContents& picture) {
    OIIO::ImageSpec spec = OiioSpec(picture.spec);
    spec.set_format(OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buffer(spec);
    buffer.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, picture.pixels.data());
    return buffer;
}

// Writes the MIP levels below the picture to `options.levelFiles`, each half the size of the
// one above (as make_texture halves: a side of 1 stays 1) and filtered from it with the
// requested filter at the requested widths, in pixels of the level made. Returns the reason on
// failure, "" on success.
std::string WriteFilteredLevels(const OIIO::ImageBuf& picture, const TextureMakeOptions& options) {
    const std::unique_ptr<OIIO::Filter2D, void (*)(OIIO::Filter2D*)> filter(
        OIIO::Filter2D::create(options.filter, options.swidth, options.twidth),
        OIIO::Filter2D::destroy);
    if (!filter) return "OpenImageIO has no filter \"" + options.filter + "\"";
    // Levels span their pixels from the origin, as make_texture's set_full_to_pixels makes them.
    OIIO::ImageBuf level = picture.copy(OIIO::TypeDesc::FLOAT);
    level.set_origin(0, 0);
    level.set_full(0, level.spec().width, 0, level.spec().height, 0, 1);
    for (const std::string& file : options.levelFiles) {
        OIIO::ImageSpec spec(std::max(1, level.spec().width / 2),
                             std::max(1, level.spec().height / 2), level.nchannels(),
                             OIIO::TypeDesc::FLOAT);
        spec.channelnames = level.spec().channelnames;
        OIIO::ImageBuf smaller(spec);
        if (!OIIO::ImageBufAlgo::resize(smaller, level, filter.get())) return smaller.geterror();
        if (!smaller.write(file, OIIO::TypeDesc::FLOAT, "tiff")) return smaller.geterror();
        level = std::move(smaller);
    }
    return "";
}

std::string Joined(const std::vector<std::string>& names, const char* separator) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : separator) + name;
    return text;
}

OIIO::ImageSpec MakeTextureConfig(const ImageFileContents& picture,
                                  const TextureMakeOptions& options) {
    OIIO::ImageSpec config;
    // The samples keep the picture's type: an 8-bit picture makes an 8-bit texture.
    config.set_format(OiioType(picture.spec.fileType));
    config.attribute("wrapmodes", std::string(TextureWrapName(options.wrap.s)) + "," +
                                      TextureWrapName(options.wrap.t));
    if (!options.filter.empty()) config.attribute("maketx:filtername", options.filter);
    if (!options.levelFiles.empty())
        config.attribute("maketx:mipimages", Joined(options.levelFiles, ";"));
    config.attribute("maketx:fileformatname", options.format);
    // s and t span the pixels the picture holds, also for a cropped render's data window.
    config.attribute("maketx:set_full_to_pixels", 1);
    return config;
}

}  // namespace

std::string MakeOiioTexture(const ImageFileContents& picture, const std::string& path,
                            const TextureMakeOptions& options) {
    const OIIO::ImageBuf buffer = PictureBuffer(picture);
    if (buffer.has_error()) return buffer.geterror();
    if (!options.levelFiles.empty()) {
        const std::string error = WriteFilteredLevels(buffer, options);
        if (!error.empty()) return error;
    }
    const auto mode = options.latLongEnvironment ? OIIO::ImageBufAlgo::MakeTxEnvLatl
                                                 : OIIO::ImageBufAlgo::MakeTxTexture;
    if (OIIO::ImageBufAlgo::make_texture(mode, buffer, path, MakeTextureConfig(picture, options)))
        return "";
    const std::string error = OIIO::geterror();
    return error.empty() ? "OpenImageIO could not make the texture" : error;
}

}  // namespace gonio
