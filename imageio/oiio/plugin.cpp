// The OpenImageIO plugin (libgonio_oiio.so): image files in any format OpenImageIO knows, its
// texture system and its drawing, behind imageio/oiio_plugin.h. The only code of gonio that
// includes OpenImageIO, so that only this library links it.
#include <OpenImageIO/imageio.h>

#include <map>

#include "imageio/oiio/oiio_parts.h"
#include "imageio/oiio/oiio_spec.h"

namespace gonio {

namespace {

PixelType GonioType(OIIO::TypeDesc type) {
    if (type == OIIO::TypeDesc::UINT8) return PixelType::UInt8;
    if (type == OIIO::TypeDesc::UINT16) return PixelType::UInt16;
    if (type == OIIO::TypeDesc::HALF) return PixelType::Half;
    return PixelType::Float;
}

ImageFileSpec GonioSpec(const OIIO::ImageSpec& spec) {
    ImageFileSpec out;
    out.width = spec.width, out.height = spec.height;
    out.x = spec.x, out.y = spec.y;
    out.fullWidth = spec.full_width, out.fullHeight = spec.full_height;
    out.channelNames = spec.channelnames;
    out.alphaChannel = spec.alpha_channel, out.zChannel = spec.z_channel;
    out.fileType = GonioType(spec.format);
    out.compression = spec.get_string_attribute("compression");
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        if (p.type() == OIIO::TypeDesc::STRING && p.name() != "compression")
            out.attributes.emplace_back(p.name().string(), p.get_string());
    return out;
}

// OpenImageIO's formats by extension, from its own "extension_list" ("tiff:tif,tiff;...").
std::map<std::string, std::string> FormatsByExtension() {
    std::map<std::string, std::string> result;
    const std::string list = OIIO::get_string_attribute("extension_list");
    for (size_t start = 0; start < list.size();) {
        size_t end = list.find(';', start);
        if (end == std::string::npos) end = list.size();
        const std::string entry = list.substr(start, end - start);
        const size_t colon = entry.find(':');
        for (size_t e = colon + 1; colon != std::string::npos && e < entry.size();) {
            size_t comma = entry.find(',', e);
            if (comma == std::string::npos) comma = entry.size();
            result.emplace(entry.substr(e, comma - e), entry.substr(0, colon));
            e = comma + 1;
        }
        start = end + 1;
    }
    return result;
}

class Plugin : public OiioPlugin {
  public:
    std::string FormatForExtension(const std::string& extension) override {
        static const std::map<std::string, std::string> formats = FormatsByExtension();
        auto found = formats.find(extension);
        return found == formats.end() ? std::string() : found->second;
    }

    std::string WriteImage(const std::string& format, const std::string& path,
                           const ImageFileSpec& spec, const PixelBuffer& pixels) override {
        auto out = OIIO::ImageOutput::create(format);
        if (!out) return "OpenImageIO has no writer for " + format + ": " + OIIO::geterror();
        std::string error;
        if (!out->open(path, OiioSpec(spec))) return out->geterror();
        if (!out->write_image(OiioType(pixels.type), pixels.data)) error = out->geterror();
        if (!out->close() && error.empty()) error = out->geterror();
        return error;
    }

    ImageFileContents ReadImage(const std::string& path, std::string* error) override {
        ImageFileContents contents;
        auto in = OIIO::ImageInput::open(path);
        if (!in) {
            *error = OIIO::geterror();
            return contents;
        }
        const OIIO::ImageSpec& spec = in->spec();
        contents.spec = GonioSpec(spec);
        contents.pixels.resize(size_t(spec.width) * spec.height * spec.nchannels);
        if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, contents.pixels.data()))
            *error = in->geterror();
        return contents;
    }

    std::string MakeTexture(const ImageFileContents& picture, const std::string& path,
                            const TextureMakeOptions& options) override {
        return MakeOiioTexture(picture, path, options);
    }

    std::unique_ptr<TextureSystem> NewTextureSystem() override { return NewOiioTextureSystem(); }

    std::unique_ptr<PlotCanvas> NewPlotCanvas(int width, int height) override {
        return NewOiioPlotCanvas(width, height);
    }
};

}  // namespace

}  // namespace gonio

extern "C" __attribute__((visibility("default"))) gonio::OiioPlugin* GonioOiioPlugin() {
    static gonio::Plugin plugin;
    return &plugin;
}
