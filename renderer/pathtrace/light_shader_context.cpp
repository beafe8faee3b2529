#include "renderer/pathtrace/light_shader_context.h"

namespace gonio {

LightShaderContext::LightShaderContext(const Frame& frame, Diagnostics& diagnostics)
    : frame_(frame), diagnostics_(diagnostics) {
    n_ = 1;
    colorComponents_ = frame.options.colorComponents;
}

void LightShaderContext::Begin(const ShaderInstance* lightShader, uint64_t seed) {
    shader_ = lightShader;
    SeedRandom(&seed);
}

bool LightShaderContext::CurrentFromSpace(const std::string& space, int, Imath::M44f* m) const {
    const Imath::M44f& currentFromWorld = frame_.options.cameraFromWorld;
    if (space == "current" || space == "camera") {
        *m = Imath::M44f();
    } else if (space == "world") {
        *m = currentFromWorld;
    } else if (space == "shader") {
        *m = (shader_ ? shader_->worldFromShader : Imath::M44f()) * currentFromWorld;
    } else {
        auto it = frame_.namedSpaces.find(space);
        if (it == frame_.namedSpaces.end()) return false;
        *m = it->second * currentFromWorld;
    }
    return true;
}

void LightShaderContext::RuntimeWarning(const std::string& key, const std::string& message) {
    const std::string& where = Statement();
    diagnostics_.WarningOnce(where + key, sl::StatementLoc(where, "light shader"), message);
}

}  // namespace gonio
