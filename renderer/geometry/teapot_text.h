#pragma once
// The text of data/teapot.txt (the Newell teapot's 32 Bézier patches, format in its header),
// embedded at build time by embed_text_file.cmake, so that Geometry "teapot" needs no file at
// run time.

#include <string_view>

namespace gonio {

std::string_view TeapotText();

}  // namespace gonio
