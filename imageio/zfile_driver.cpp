// Pixar's zfile depth format, as OpenImageIO 2.4 writes it: a 136-byte header (magic, width and
// height as 16-bit integers, the world-to-screen and world-to-camera matrices) and the float
// depths row by row, all in the machine's byte order; gzip-compressed unless "compression" is
// "none" or absent. Read back (plain or gzip-compressed, either byte order) for MakeShadow.
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
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

constexpr int32_t kZfileMagic = 0x2f0867ab;

template <typename T>
void SwapBytes(T* value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, value, sizeof(T));
    std::reverse(bytes, bytes + sizeof(T));
    std::memcpy(value, bytes, sizeof(T));
}

// A file written on a machine of the other byte order: every field and depth is swapped.
void SwapHeader(ZfileHeader* header) {
    SwapBytes(&header->magic);
    SwapBytes(&header->width);
    SwapBytes(&header->height);
    for (float& v : header->worldToScreen) SwapBytes(&v);
    for (float& v : header->worldToCamera) SwapBytes(&v);
}

}  // namespace

bool IsZfileMagic(const unsigned char bytes[4]) {
    int32_t magic;
    std::memcpy(&magic, bytes, 4);
    int32_t swapped = magic;
    SwapBytes(&swapped);
    return magic == kZfileMagic || swapped == kZfileMagic;
}

std::string ReadZfileFile(const std::string& path, ImageFileContents* contents) {
    // gzread reads plain files as they are, so one reader serves both.
    std::unique_ptr<gzFile_s, int (*)(gzFile)> file(gzopen(path.c_str(), "rb"), gzclose);
    if (!file) return "cannot open \"" + path + "\"";
    ZfileHeader header;
    if (gzread(file.get(), &header, sizeof header) != int(sizeof header))
        return "\"" + path + "\" is too short for a zfile header";
    const bool swapped = header.magic != kZfileMagic;
    if (swapped) SwapHeader(&header);
    if (header.magic != kZfileMagic) return "\"" + path + "\" is not a zfile (bad magic number)";
    if (header.width <= 0 || header.height <= 0)
        return "\"" + path + "\" has a zfile resolution of " + std::to_string(header.width) +
               " x " + std::to_string(header.height);
    ImageFileSpec& spec = contents->spec;
    spec = ImageFileSpec();
    spec.width = header.width, spec.height = header.height;
    spec.channelNames = {"z"};
    spec.zChannel = 0;
    spec.fileType = PixelType::Float;
    spec.worldToScreen.assign(header.worldToScreen, header.worldToScreen + 16);
    spec.worldToCamera.assign(header.worldToCamera, header.worldToCamera + 16);
    const size_t count = size_t(spec.width) * spec.height;
    if (count * sizeof(float) > size_t(std::numeric_limits<int>::max()))
        return "\"" + path + "\" is too large for a zfile reader (over 2 GB of depths)";
    contents->pixels.resize(count);
    const int bytes = int(count * sizeof(float));
    if (gzread(file.get(), contents->pixels.data(), unsigned(bytes)) != bytes)
        return "\"" + path + "\" is truncated: fewer depths than its " +
               std::to_string(spec.width) + " x " + std::to_string(spec.height) + " pixels";
    if (swapped)
        for (float& z : contents->pixels) SwapBytes(&z);
    return "";
}

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
    if (spec.worldToScreen.size() == 16)
        std::copy(spec.worldToScreen.begin(), spec.worldToScreen.end(), header.worldToScreen);
    if (spec.worldToCamera.size() == 16)
        std::copy(spec.worldToCamera.begin(), spec.worldToCamera.end(), header.worldToCamera);
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
