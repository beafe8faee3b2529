#include "imageio/oiio/oiio_spec.h"

namespace gonio {

OIIO::TypeDesc OiioType(PixelType type) {
    switch (type) {
        case PixelType::UInt8:
            return OIIO::TypeDesc::UINT8;
        case PixelType::UInt16:
            return OIIO::TypeDesc::UINT16;
        case PixelType::Half:
            return OIIO::TypeDesc::HALF;
        default:
            return OIIO::TypeDesc::FLOAT;
    }
}

OIIO::ImageSpec OiioSpec(const ImageFileSpec& spec) {
    OIIO::ImageSpec out(spec.width, spec.height, spec.Channels(), OiioType(spec.fileType));
    out.x = spec.x;
    out.y = spec.y;
    out.full_x = 0;
    out.full_y = 0;
    out.full_width = spec.FullWidth();
    out.full_height = spec.FullHeight();
    out.channelnames = spec.channelNames;
    out.alpha_channel = spec.alphaChannel;
    out.z_channel = spec.zChannel;
    if (!spec.compression.empty()) out.attribute("compression", spec.compression);
    for (const auto& [name, value] : spec.attributes) out.attribute(name, value);
    return out;
}

}  // namespace gonio
