#include "renderer/shading/rib_shader_parameters.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "renderer/scene/scene_colors.h"

namespace gonio {

bool ApplyRibParameters(sl::ShaderInstance& instance, const ParamList& params,
                        const Declarations& declarations, const Options& options,
                        const Imath::M44f& currentFromShader, Diagnostics& diagnostics) {
    const sl::Shader& shader = instance.Master();
    bool ok = true;
    for (const Param& param : params) {
        const std::string bare = TokenName(param.token);
        const sl::ShaderParam* p = shader.FindParam(bare);
        if (!p) {
            diagnostics.Warning(param.loc, "shader '" + shader.Name() + "' has no parameter '" +
                                               bare + "' (ignored)");
            continue;
        }
        std::string error;
        std::optional<ParamDecl> decl = declarations.Resolve(param.token, &error);
        if (decl && bare == param.token && !decl->name.empty()) {
            // A bare token takes the shader's declaration over a global Declare.
            decl.reset();
        }
        if (decl) {
            sl::BaseType want = p->type.base;
            bool match = false;
            switch (decl->type) {
                case ParamType::Float:
                case ParamType::Integer:
                    match = want == sl::BaseType::Float;
                    break;
                case ParamType::String:
                    match = want == sl::BaseType::String;
                    break;
                case ParamType::Color:
                    match = want == sl::BaseType::Color;
                    break;
                case ParamType::Point:
                case ParamType::Vector:
                case ParamType::Normal:
                    match = p->type.IsPointLike();
                    break;
                case ParamType::Matrix:
                    match = want == sl::BaseType::Matrix;
                    break;
                default:
                    match = false;
            }
            if (!match) {
                diagnostics.Error(param.loc, "parameter '" + bare + "' is declared " +
                                                 ToString(decl->type) + " in the RIB but " +
                                                 ToString(p->type) + " in shader '" +
                                                 shader.Name() + "'");
                ok = false;
                continue;
            }
        }
        bool set;
        if (p->type.base == sl::BaseType::String) {
            set = instance.SetParameter(bare, param.strings, &error);
        } else if (p->type.base == sl::BaseType::Color) {
            std::vector<float> values;
            set = SceneColorsFromParam(options, param, std::max(1, p->type.arrayLength), &values,
                                       &error) &&
                  instance.SetParameter(bare, values, &error);
            if (!set) error = "parameter '" + bare + "': " + error;
        } else {
            std::vector<float> values(param.numbers.begin(), param.numbers.end());
            if (p->type.IsPointLike() && values.size() % 3 == 0) {
                // Points in a RIB parameter list are in shader space (RISpec §11.2).
                for (size_t k = 0; k + 2 < values.size(); k += 3) {
                    Imath::V3f v(values[k], values[k + 1], values[k + 2]), r;
                    if (p->type.base == sl::BaseType::Point) {
                        currentFromShader.multVecMatrix(v, r);
                    } else if (p->type.base == sl::BaseType::Vector) {
                        currentFromShader.multDirMatrix(v, r);
                    } else {
                        currentFromShader.inverse().transposed().multDirMatrix(v, r);
                    }
                    values[k] = r.x, values[k + 1] = r.y, values[k + 2] = r.z;
                }
            }
            set = param.isString ? false : instance.SetParameter(bare, values, &error);
            if (param.isString) error = "parameter '" + bare + "' takes numbers, not strings";
        }
        if (!set) {
            diagnostics.Error(param.loc, error);
            ok = false;
        }
    }
    return ok;
}

}  // namespace gonio
