#pragma once
// RIB parameter lists applied to shader instances (Surface "plastic" "Kd" 0.5 ...): the
// renderer's side of the boundary, so that the shading language knows nothing of RIB.

#include <Imath/ImathMatrix.h>

#include "base/diagnostics.h"
#include "renderer/rib/declarations.h"
#include "renderer/rib/param_list.h"
#include "renderer/scene/options.h"
#include "shaderlang/shading_system.h"

namespace gonio {

// Types each parameter by its inline declaration, else by the shader's own declaration (a bare
// token takes the shader's over a global Declare). A type or count that does not match the
// shader's declaration is an error at the parameter's RIB location. Point-like values are in
// shader space and are moved to current space with `currentFromShader` (row vectors). Unknown
// names get a warning. False after any error.
// Colour values take the frame's components (options.colorComponents), or under
// Option "spectral" also RGB (uplifted) or a named spectrum or spectrum file (scene_colors.h).
bool ApplyRibParameters(sl::ShaderInstance& instance, const ParamList& params,
                        const Declarations& declarations, const Options& options,
                        const Imath::M44f& currentFromShader, Diagnostics& diagnostics);

}  // namespace gonio
