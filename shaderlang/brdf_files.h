#pragma once
// The .grd files a shader instance's brdf() calls read, where its code names them by constants
// (after the instance's parameters are folded in, so a `string grid` parameter set in the RIB
// counts): what the path tracer samples such a surface with (renderer/pathtrace/).

#include <string>
#include <vector>

#include "shaderlang/shading_system.h"

namespace gonio::sl {

// In order of first call; empty when the shader calls no brdf() or names its file at run time.
// The instance must be specialised (ShaderInstance::Specialize), as a frame's are.
std::vector<std::string> BrdfFiles(const ShaderInstance& instance);

}  // namespace gonio::sl
