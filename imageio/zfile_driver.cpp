// Pixar's zfile depth format, as OpenImageIO 2.4 writes it: a 136-byte header (magic, width and
// height as 16-bit integers, the world-to-screen and world-to-camera matrices) and the float
// depths row by row, all in the machine's byte order; gzip-compressed unless "compression" is
// "none" or absent.
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <memory>

#include "imageio/builtin_drivers.h"

namespace gonio {

namespace {

struct ZfileHeader {
    int32_t magic = 0x2f0867ab;
    int16_t width = 0, height = 0;
    float worldToScreen[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    float worldToCamera[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
};
static_assert(sizeof(ZfileHeader) == 136, "the zfile header has no padding");

}  // namespace

std::string WriteZfileFile(const std::string& path, const ImageFileSpec& spec,
                           const PixelBuffer& pixels) {
    if (spec.Channels() != 1)
        return "Zfile only supports 1 channel, not " + std::to_string(spec.Channels());
    if (spec.width > 32767 || spec.height > 32767)
        return "zfile image resolution maximum is 32767, you asked for " +
               std::to_string(spec.width) + " x " + std::to_string(spec.height);
    if (pixels.type != PixelType::Float) return "zfiles are written from float pixels";
    ZfileHeader header;
    header.width = int16_t(spec.width), header.height = int16_t(spec.height);
    const size_t bytes = size_t(spec.width) * spec.height * sizeof(float);
    const bool gzip = !spec.compression.empty() && spec.compression != "none";
    bool ok = false;
    if (gzip) {
        gzFile file = gzopen(path.c_str(), "wb");
        if (!file) return "could not open \"" + path + "\"";
        ok = gzwrite(file, &header, sizeof header) == int(sizeof header) &&
             gzwrite(file, pixels.data, unsigned(bytes)) == int(bytes);
        ok &= gzclose(file) == Z_OK;
    } else {
        std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "wb"), std::fclose);
        if (!file) return "could not open \"" + path + "\"";
        ok = std::fwrite(&header, sizeof header, 1, file.get()) == 1 &&
             std::fwrite(pixels.data, 1, bytes, file.get()) == bytes;
        ok &= std::fclose(file.release()) == 0;
    }
    return ok ? "" : "could not write \"" + path + "\"";
}

}  // namespace gonio
