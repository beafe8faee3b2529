#pragma once
// Image files by format name (OpenImageIO's names: "tiff", "png", "openexr", "zfile", "jpeg",
// ...): TIFF, PNG, OpenEXR and zfile are written by gonio's built-in drivers; any other format
// through the OpenImageIO plugin (oiio_plugin.h), which is loaded only then.

#include <functional>
#include <string>

#include "imageio/image_file.h"

namespace gonio {

// The built-in format with this file name extension (no dot, any case), "" if none.
std::string BuiltInFormatForExtension(const std::string& extension);

// The format of a file name's extension: a built-in one, else OpenImageIO's (which loads the
// plugin, and throws std::runtime_error naming the file when it cannot be loaded); "" when the
// name has no extension or no format has it.
std::string FormatForFileName(const std::string& fileName);

// Runs `write(temporary)`, which writes the file under a temporary name in the folder of `path`
// and returns the reason it failed ("" on success), then renames the file into place, so that
// readers never see a partial file and a failure leaves nothing (nor a temporary after Ctrl-C).
// Returns the reason on failure, naming only `path`, never the temporary name; "" on success.
std::string WriteThroughTemporary(const std::string& path,
                                  const std::function<std::string(const std::string&)>& write);

// Writes `pixels` as `spec` says in `format` under a temporary name in the folder of `path`,
// then renames it into place, so that readers never see a partial file and a failure leaves
// nothing. The pixels are converted to the file's type as OpenImageIO converts them. Returns
// the reason on failure (naming only `path`, never the temporary name), "" on success.
std::string WriteImageFile(const std::string& format, const std::string& path,
                           const ImageFileSpec& spec, const PixelBuffer& pixels);

}  // namespace gonio
