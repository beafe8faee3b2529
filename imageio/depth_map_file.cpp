#include "imageio/depth_map_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "imageio/builtin_drivers.h"
#include "imageio/image_formats.h"

namespace gonio {

namespace {

enum class DepthFileKind { Zfile, Tiff, Unknown };

// By content, not by name: zfiles are named .z, .zfile, .depth, ... and gzip-compressed ones
// start with gzip's magic instead of their own.
DepthFileKind Sniff(const std::string& path, std::string* error) {
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) {
        *error = "cannot open \"" + path + "\": " + std::strerror(errno);
        return DepthFileKind::Unknown;
    }
    unsigned char magic[4] = {0, 0, 0, 0};
    const size_t got = std::fread(magic, 1, 4, file.get());
    const bool gzip = got >= 2 && magic[0] == 0x1f && magic[1] == 0x8b;
    if (gzip || (got == 4 && IsZfileMagic(magic))) return DepthFileKind::Zfile;
    const bool tiff = got == 4 && ((magic[0] == 'I' && magic[1] == 'I' && magic[2] == 42) ||
                                   (magic[0] == 'M' && magic[1] == 'M' && magic[3] == 42));
    if (tiff) return DepthFileKind::Tiff;
    *error = "\"" + path + "\" is neither a zfile nor a TIFF depth map";
    return DepthFileKind::Unknown;
}

}  // namespace

std::string ReadDepthMapFile(const std::string& path, ImageFileContents* map) {
    std::string error;
    switch (Sniff(path, &error)) {
        case DepthFileKind::Zfile:
            return ReadZfileFile(path, map);
        case DepthFileKind::Tiff:
            return ReadFloatTiffFile(path, map);
        case DepthFileKind::Unknown:
            break;
    }
    return error;
}

std::string WriteShadowMapFile(const std::string& path, const ImageFileContents& map) {
    ImageFileSpec spec = map.spec;
    spec.x = spec.y = spec.fullWidth = spec.fullHeight = 0;
    spec.channelNames = {"z"};
    spec.zChannel = 0;
    spec.alphaChannel = -1;
    spec.fileType = PixelType::Float;
    spec.attributes = {{"Software", "gonio"}, {"textureformat", "Shadow"}};
    return WriteImageFile("tiff", path, spec, PixelBuffer{PixelType::Float, map.pixels.data()});
}

std::string MakeShadowMapFile(const std::string& picture, const std::string& shadowMap) {
    ImageFileContents map;
    std::string error = ReadDepthMapFile(picture, &map);
    if (!error.empty()) return error;
    if (map.spec.worldToCamera.size() != 16 || map.spec.worldToScreen.size() != 16)
        return "\"" + picture +
               "\" records no camera (the world-to-camera and world-to-screen matrices a "
               "shadow map is looked up with)";
    return WriteShadowMapFile(shadowMap, map);
}

}  // namespace gonio
