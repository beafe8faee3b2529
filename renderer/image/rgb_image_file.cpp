#include "renderer/image/rgb_image_file.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace gonio {

RgbImage ReadRgbImage(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error(path + ": cannot read the image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 3)
        throw std::runtime_error(path + ": the image has " + std::to_string(spec.nchannels) +
                                 " channels, not RGB");
    RgbImage image;
    image.width = spec.width, image.height = spec.height;
    image.floatingPoint = spec.format.is_floating_point();
    image.rgb.resize(size_t(spec.width) * size_t(spec.height) * 3);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.rgb.data()))
        throw std::runtime_error(path + ": cannot read the image: " + in->geterror());
    return image;
}

void WriteRgbImage(const std::string& path, const RgbImage& image) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error(path + ": no image writer for this file type");
    const bool floats = std::string(out->format_name()) == "openexr";
    const OIIO::ImageSpec spec(image.width, image.height, 3,
                               floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    const std::string temp = path + ".tmp." + std::to_string(::getpid());
    const bool written = out->open(temp, spec, OIIO::ImageOutput::Create) &&
                         out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data()) && out->close();
    if (!written || std::rename(temp.c_str(), path.c_str()) != 0) {
        std::remove(temp.c_str());
        throw std::runtime_error(path + ": cannot write the image: " + out->geterror());
    }
}

}  // namespace gonio
