// Reading goes through the OpenImageIO plugin (any format); writing through imageio's drivers,
// built in for TIFF, PNG and OpenEXR.
#include "renderer/image/rgb_image_file.h"

#include <stdexcept>

#include "imageio/image_formats.h"
#include "imageio/oiio_plugin.h"

namespace gonio {

RgbImage ReadRgbImage(const std::string& path) {
    std::string error;
    const ImageFileContents contents =
        LoadOiioPlugin("reading the image \"" + path + "\"").ReadImage(path, &error);
    if (!error.empty()) throw std::runtime_error(path + ": cannot read the image: " + error);
    const ImageFileSpec& spec = contents.spec;
    const int n = spec.Channels();
    if (n < 3)
        throw std::runtime_error(path + ": the image has " + std::to_string(n) +
                                 " channels, not RGB");
    RgbImage image;
    image.width = spec.width, image.height = spec.height;
    image.floatingPoint = spec.fileType == PixelType::Half || spec.fileType == PixelType::Float;
    image.rgb.resize(size_t(spec.width) * size_t(spec.height) * 3);
    for (size_t p = 0; p < image.rgb.size() / 3; ++p)
        for (int c = 0; c < 3; ++c) image.rgb[p * 3 + c] = contents.pixels[p * n + c];
    return image;
}

void WriteRgbImage(const std::string& path, const RgbImage& image) {
    const std::string format = FormatForFileName(path);
    if (format.empty()) throw std::runtime_error(path + ": no image writer for this file type");
    ImageFileSpec spec;
    spec.width = image.width, spec.height = image.height;
    spec.channelNames = {"R", "G", "B"};
    spec.fileType = format == "openexr" ? PixelType::Float : PixelType::UInt8;
    const std::string error =
        WriteImageFile(format, path, spec, PixelBuffer{PixelType::Float, image.rgb.data()});
    if (!error.empty()) throw std::runtime_error(path + ": cannot write the image: " + error);
}

}  // namespace gonio
