#include "renderer/shading/option_query.h"

namespace gonio {

bool QueryOption(const Options& o, const std::string& name, const sl::TypeSpec& type,
                 std::vector<float>* floats) {
    if (type.base != sl::BaseType::Float) return false;
    if (name == "Format") {
        floats->assign({float(o.xres), float(o.yres), o.pixelAspect});
    } else if (name == "FrameAspectRatio") {
        floats->assign({o.frameAspect > 0 ? o.frameAspect : o.xres * o.pixelAspect / o.yres});
    } else if (name == "CropWindow") {
        floats->assign(o.cropWindow, o.cropWindow + 4);
    } else if (name == "Clipping") {
        floats->assign({o.nearClip, o.farClip});
    } else if (name == "DepthOfField") {
        floats->assign({o.fstop, o.focalLength, o.focalDistance});
    } else if (name == "Shutter") {
        floats->assign({o.shutterOpen, o.shutterClose});
    } else {
        return false;
    }
    return true;
}

}  // namespace gonio
