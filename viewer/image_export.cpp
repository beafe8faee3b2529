#include "viewer/image_export.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "imageio/image_formats.h"
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

// The built-in drivers write files: a temporary one of this process, read back and removed.
std::string Encode(const char* format, const char* extension, const ImageFileSpec& spec,
                   const PixelBuffer& pixels) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("gonio_view_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + extension);
    const std::string error = WriteImageFile(format, path.string(), spec, pixels);
    if (!error.empty()) throw ViewerError(std::string("cannot encode the image: ") + error);
    std::ifstream file(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    std::filesystem::remove(path);
    if (!file) throw ViewerError("cannot read back the encoded image");
    return bytes.str();
}

ImageFileSpec RgbSpec(int width, int height, PixelType type) {
    ImageFileSpec spec;
    spec.width = width, spec.height = height;
    spec.channelNames = {"R", "G", "B"};
    spec.fileType = type;
    return spec;
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
        return Encode("png", ".png", RgbSpec(width, height, PixelType::UInt8),
                      PixelBuffer{PixelType::UInt8, bytes.data()});
    }
    ImageFileSpec spec = RgbSpec(width, height, PixelType::Float);
    spec.compression = "zip";
    return Encode("openexr", ".exr", spec, PixelBuffer{PixelType::Float, rgb.data()});
}

}  // namespace gonio::viewer
