#pragma once
// gonio's description of a picture (imageio/image_file.h) in OpenImageIO's terms, for the parts
// of the plugin that hand pictures to OpenImageIO (writing images, making textures).

#include <OpenImageIO/imageio.h>

#include "imageio/image_file.h"

namespace gonio {

OIIO::TypeDesc OiioType(PixelType type);
OIIO::ImageSpec OiioSpec(const ImageFileSpec& spec);

}  // namespace gonio
