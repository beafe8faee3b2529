#include "imageio/image_formats.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>

#include "base/interrupt_cleanup.h"
#include "imageio/builtin_drivers.h"
#include "imageio/oiio_plugin.h"
#include "imageio/pixel_conversion.h"

namespace gonio {

namespace {

namespace fs = std::filesystem;

using Driver = std::string (*)(const std::string&, const ImageFileSpec&, const PixelBuffer&);

std::string Lowercase(std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// The type a built-in driver stores: TIFF its own (float for half: OpenImageIO's TIFF writer
// writes half only when asked by a global switch), PNG 8 or 16 bits, OpenEXR and zfile float.
PixelType StoredType(const std::string& format, PixelType fileType) {
    if (format == "png")
        return fileType == PixelType::UInt16 ? PixelType::UInt16 : PixelType::UInt8;
    if (format == "tiff" && fileType != PixelType::Half) return fileType;
    return PixelType::Float;
}

// The built-in driver of a format, or null. TIFF's "jpeg" and "ccittrle" compressions are
// left to OpenImageIO, which converts colour for them.
Driver BuiltInDriver(const std::string& format, const ImageFileSpec& spec) {
    if (format == "tiff") {
        const std::string compression = SplitCompression(spec.compression).first;
        if (compression == "jpeg" || compression == "ccittrle") return nullptr;
        return WriteTiffFile;
    }
    if (format == "png") return WritePngFile;
    if (format == "openexr") return WriteExrFile;
    if (format == "zfile") return WriteZfileFile;
    return nullptr;
}

std::string WriteThroughDriver(const std::string& format, const std::string& path,
                               const ImageFileSpec& spec, const PixelBuffer& pixels) {
    if (const Driver driver = BuiltInDriver(format, spec)) {
        const PixelType stored = StoredType(format, spec.fileType);
        const size_t count = size_t(spec.width) * spec.height * spec.Channels();
        const std::vector<unsigned char> bytes = ConvertPixels(pixels, count, stored);
        return driver(path, spec, PixelBuffer{stored, bytes.data()});
    }
    try {
        return LoadOiioPlugin("writing the " + format + " file \"" + path + "\"")
            .WriteImage(format, path, spec, pixels);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
}

std::string TemporaryName(const std::string& name) {
    fs::path path(name);
    std::string temporary = "." + path.filename().string() + ".tmp" + std::to_string(getpid());
    return (path.parent_path() / temporary).string();
}

}  // namespace

std::string BuiltInFormatForExtension(const std::string& extension) {
    // OpenImageIO's extensions of these formats, so that the choice does not change with it.
    static const std::map<std::string, std::string> kFormats = {
        {"tif", "tiff"},    {"tiff", "tiff"},   {"tx", "tiff"},    {"env", "tiff"},
        {"sm", "tiff"},     {"vsm", "tiff"},    {"png", "png"},    {"exr", "openexr"},
        {"sxr", "openexr"}, {"mxr", "openexr"}, {"zfile", "zfile"}};
    auto found = kFormats.find(Lowercase(extension));
    return found == kFormats.end() ? std::string() : found->second;
}

std::string FormatForFileName(const std::string& fileName) {
    std::string extension = fs::path(fileName).extension().string();
    if (extension.empty()) return "";
    extension.erase(0, 1);
    const std::string builtIn = BuiltInFormatForExtension(extension);
    if (!builtIn.empty()) return builtIn;
    return LoadOiioPlugin("the format of \"" + fileName +
                          "\" (an extension the built-in TIFF, PNG, OpenEXR and zfile drivers "
                          "do not know)")
        .FormatForExtension(Lowercase(extension));
}

std::string WriteThroughTemporary(const std::string& path,
                                  const std::function<std::string(const std::string&)>& write) {
    fs::path folder = fs::path(path).parent_path();
    std::error_code statError;
    if (!folder.empty() && !fs::is_directory(folder, statError))
        return "the folder \"" + folder.string() + "\" does not exist";
    const std::string temporary = TemporaryName(path);
    const PendingTemporary pending(temporary);
    std::string error = write(temporary);
    if (error.empty()) {
        std::error_code renameError;
        fs::rename(temporary, path, renameError);
        if (!renameError) return "";
        error = renameError.message();
    }
    std::error_code ignored;
    fs::remove(temporary, ignored);
    if (error.empty()) return "the writer failed without saying why";
    for (size_t at = error.find(temporary); at != std::string::npos; at = error.find(temporary))
        error.replace(at, temporary.size(), path);
    return error;
}

std::string WriteImageFile(const std::string& format, const std::string& path,
                           const ImageFileSpec& spec, const PixelBuffer& pixels) {
    return WriteThroughTemporary(path, [&](const std::string& temporary) {
        return WriteThroughDriver(format, temporary, spec, pixels);
    });
}

}  // namespace gonio
