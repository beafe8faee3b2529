// Reading a one-channel float TIFF through libtiff: the shadow maps MakeShadow writes and those
// other tools make (maketx --shadow, txmake: tiled), with Pixar's world-to-camera and
// world-to-screen matrix tags. Only what a depth map needs; other pictures go through the
// OpenImageIO plugin.
#include <tiffio.h>

#include <algorithm>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <vector>

#include "imageio/builtin_drivers.h"

namespace gonio {

namespace {

thread_local std::string readError;

void KeepReadError(const char* module, const char* format, va_list args) {
    char text[512];
    std::vsnprintf(text, sizeof text, format, args);
    readError = module ? std::string(module) + ": " + text : text;
}

// What a TIFF holds, for the message that refuses it: "3 channels of 8-bit integers".
std::string Holds(int channels, int bits, int format) {
    return std::to_string(channels) + (channels == 1 ? " channel of " : " channels of ") +
           std::to_string(bits) + "-bit " + (format == SAMPLEFORMAT_IEEEFP ? "floats" : "integers");
}

std::vector<float> Matrix(TIFF* tif, uint32_t tag) {
    float* values = nullptr;
    if (!TIFFGetField(tif, tag, &values) || !values) return {};
    return std::vector<float>(values, values + 16);
}

bool ReadStrips(TIFF* tif, int width, int height, float* out) {
    for (int y = 0; y < height; ++y)
        if (TIFFReadScanline(tif, out + size_t(y) * width, uint32_t(y)) < 0) return false;
    return true;
}

bool ReadTiles(TIFF* tif, int width, int height, float* out) {
    uint32_t tileWidth = 0, tileHeight = 0;
    TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tileWidth);
    TIFFGetField(tif, TIFFTAG_TILELENGTH, &tileHeight);
    if (tileWidth == 0 || tileHeight == 0) return false;
    std::vector<float> tile(size_t(tileWidth) * tileHeight);
    for (uint32_t y0 = 0; y0 < uint32_t(height); y0 += tileHeight)
        for (uint32_t x0 = 0; x0 < uint32_t(width); x0 += tileWidth) {
            if (TIFFReadTile(tif, tile.data(), x0, y0, 0, 0) < 0) return false;
            const uint32_t w = std::min(tileWidth, uint32_t(width) - x0);
            const uint32_t h = std::min(tileHeight, uint32_t(height) - y0);
            for (uint32_t y = 0; y < h; ++y)
                std::copy_n(&tile[size_t(y) * tileWidth], w, out + size_t(y0 + y) * width + x0);
        }
    return true;
}

}  // namespace

std::string ReadFloatTiffFile(const std::string& path, ImageFileContents* contents) {
    TIFFSetErrorHandler(KeepReadError);
    TIFFSetWarningHandler(nullptr);
    readError.clear();
    std::unique_ptr<TIFF, void (*)(TIFF*)> tif(TIFFOpen(path.c_str(), "r"), TIFFClose);
    if (!tif) return readError.empty() ? "cannot open \"" + path + "\"" : readError;
    uint32_t width = 0, height = 0;
    uint16_t channels = 1, bits = 1, format = SAMPLEFORMAT_UINT;
    TIFFGetField(tif.get(), TIFFTAG_IMAGEWIDTH, &width);
    TIFFGetField(tif.get(), TIFFTAG_IMAGELENGTH, &height);
    TIFFGetFieldDefaulted(tif.get(), TIFFTAG_SAMPLESPERPIXEL, &channels);
    TIFFGetFieldDefaulted(tif.get(), TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif.get(), TIFFTAG_SAMPLEFORMAT, &format);
    if (channels != 1 || bits != 32 || format != SAMPLEFORMAT_IEEEFP)
        return "\"" + path + "\" holds " + Holds(channels, bits, format) +
               "; a depth map is one channel of 32-bit floats";
    if (width == 0 || height == 0 || width > 65535 || height > 65535)
        return "\"" + path + "\" has a resolution of " + std::to_string(width) + " x " +
               std::to_string(height);
    ImageFileSpec& spec = contents->spec;
    spec = ImageFileSpec();
    spec.width = int(width), spec.height = int(height);
    spec.channelNames = {"z"};
    spec.zChannel = 0;
    spec.fileType = PixelType::Float;
    spec.worldToScreen = Matrix(tif.get(), TIFFTAG_PIXAR_MATRIX_WORLDTOSCREEN);
    spec.worldToCamera = Matrix(tif.get(), TIFFTAG_PIXAR_MATRIX_WORLDTOCAMERA);
    char* textureFormat = nullptr;
    if (TIFFGetField(tif.get(), TIFFTAG_PIXAR_TEXTUREFORMAT, &textureFormat) && textureFormat)
        spec.attributes.emplace_back("textureformat", textureFormat);
    contents->pixels.assign(size_t(width) * height, 0.f);
    const bool ok = TIFFIsTiled(tif.get())
                        ? ReadTiles(tif.get(), int(width), int(height), contents->pixels.data())
                        : ReadStrips(tif.get(), int(width), int(height), contents->pixels.data());
    if (!ok) return readError.empty() ? "cannot read the pixels of \"" + path + "\"" : readError;
    return "";
}

}  // namespace gonio
