// One of the two files of the viewer that include OpenImageIO (the other reads images).
#include "viewer/image_export.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "viewer/reflectance_image.h"

namespace gonio::viewer {

namespace {

// IEC 61966-2-1's transfer function of one linear value, clamped to [0, 1].
double EncodeSrgb(double linear) {
    const double v = std::clamp(linear, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

std::vector<uint8_t> SrgbBytes(const std::vector<float>& rgb) {
    std::vector<uint8_t> bytes(rgb.size());
    for (size_t i = 0; i < rgb.size(); ++i)
        bytes[i] = uint8_t(std::lround(255 * EncodeSrgb(rgb[i])));
    return bytes;
}

// Writes through an in-memory proxy, so that no temporary file is needed.
std::string Encode(const char* fileName, const OIIO::ImageSpec& spec, const void* pixels) {
    std::vector<unsigned char> buffer;
    OIIO::Filesystem::IOVecOutput proxy(buffer);
    auto output = OIIO::ImageOutput::create(fileName);
    if (!output || !output->set_ioproxy(&proxy))
        throw ViewerError(std::string("cannot encode ") + fileName);
    if (!output->open(fileName, spec) || !output->write_image(spec.format, pixels) ||
        !output->close())
        throw ViewerError(std::string("cannot encode ") + fileName + ": " + output->geterror());
    return std::string(buffer.begin(), buffer.end());
}

}  // namespace

ExportFormat ParseExportFormat(const std::string& name) {
    if (name == "png") return ExportFormat::Png;
    if (name == "exr") return ExportFormat::Exr;
    throw ViewerError("unknown image format \"" + name + "\": expected \"png\" or \"exr\"");
}

std::string EncodeImage(const std::vector<float>& rgb, int width, int height, ExportFormat format) {
    if (format == ExportFormat::Png) {
        const std::vector<uint8_t> bytes = SrgbBytes(rgb);
        return Encode("relit.png", OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8),
                      bytes.data());
    }
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    return Encode("relit.exr", spec, rgb.data());
}

}  // namespace gonio::viewer
