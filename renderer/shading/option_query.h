#pragma once
// The shading language's option() (RISpec §15.8): the frame's options a shader may read,
// whether it runs on the scene's surfaces or as the imager over the finished image.

#include <string>
#include <vector>

#include "renderer/scene/options.h"
#include "shaderlang/types.h"

namespace gonio {

// "Format" (x, y, pixel aspect), "FrameAspectRatio", "CropWindow", "Clipping", "DepthOfField",
// "Shutter", as floats; false for another name or a non-float output.
bool QueryOption(const Options& options, const std::string& name, const sl::TypeSpec& type,
                 std::vector<float>* floats);

}  // namespace gonio
