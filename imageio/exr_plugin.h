#pragma once
// The OpenEXR display driver is a plugin, libgonio_exr.so (imageio/exr/), opened with dlopen the
// first time an OpenEXR file is written: OpenEXR and its Iex and IlmThread bring 43% of the
// symbols the dynamic loader binds at every start of gonio (LD_DEBUG=bindings: 2,681 of 6,300),
// which every command paid, a TIFF render or `gonio catrib` as much as an OpenEXR render.
// WriteExrFile (builtin_drivers.h) is the loader's side; nothing else changes for its callers.

#include <string>

#include "imageio/image_file.h"

namespace gonio {

// What the plugin's entry point returns: its WriteExrFile.
using ExrWriter = std::string (*)(const std::string& path, const ImageFileSpec& spec,
                                  const PixelBuffer& pixels);
using ExrPluginEntry = ExrWriter (*)();
inline constexpr const char* kExrPluginEntry = "GonioExrWriter";

}  // namespace gonio
