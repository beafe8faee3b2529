#include "renderer/scene/depth_map_camera.h"

#include "imageio/depth_map_file.h"

namespace gonio {

namespace {

Imath::M44f FromRowMajor(const std::vector<float>& values) {
    Imath::M44f m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = values[i];
    return m;
}

}  // namespace

std::unique_ptr<DepthMapCamera> ReadDepthMapCamera(const std::string& path, std::string* error) {
    ImageFileContents file;
    *error = ReadDepthMapFile(path, &file);
    if (!error->empty()) return nullptr;
    if (file.spec.worldToCamera.size() != 16 || file.spec.worldToScreen.size() != 16) {
        *error = "\"" + path + "\" records no camera (world-to-camera and world-to-screen)";
        return nullptr;
    }
    auto map = std::make_unique<DepthMapCamera>();
    map->width = file.spec.width;
    map->height = file.spec.height;
    map->depth = std::move(file.pixels);
    map->cameraFromWorld = FromRowMajor(file.spec.worldToCamera);
    map->screenFromWorld = FromRowMajor(file.spec.worldToScreen);
    return map;
}

}  // namespace gonio
