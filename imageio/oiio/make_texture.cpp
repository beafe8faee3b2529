// MakeTexture and MakeLatLongEnvironment through OpenImageIO's make_texture, the function
// `maketx` runs: a tiled, MIP-mapped file whose metadata (textureformat, wrapmodes) its
// TextureSystem reads back.
#include <OpenImageIO/imagebufalgo.h>

#include <string>

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

OIIO::ImageSpec MakeTextureConfig(const ImageFileContents& picture,
                                  const TextureMakeOptions& options) {
    OIIO::ImageSpec config;
    // The samples keep the picture's type: an 8-bit picture makes an 8-bit texture.
    config.set_format(OiioType(picture.spec.fileType));
    config.attribute("wrapmodes", std::string(TextureWrapName(options.wrap.s)) + "," +
                                      TextureWrapName(options.wrap.t));
    if (!options.filter.empty()) config.attribute("maketx:filtername", options.filter);
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
    const auto mode = options.latLongEnvironment ? OIIO::ImageBufAlgo::MakeTxEnvLatl
                                                 : OIIO::ImageBufAlgo::MakeTxTexture;
    if (OIIO::ImageBufAlgo::make_texture(mode, buffer, path, MakeTextureConfig(picture, options)))
        return "";
    const std::string error = OIIO::geterror();
    return error.empty() ? "OpenImageIO could not make the texture" : error;
}

}  // namespace gonio
