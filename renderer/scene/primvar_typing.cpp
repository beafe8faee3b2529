#include "renderer/scene/primvar_typing.h"

namespace gonio {
bool TypeParam(const Param& param, const Declarations& declarations, int colorComponents,
               Diagnostics& diagnostics, PrimVar* out) {
    std::string error;
    std::optional<ParamDecl> decl = declarations.Resolve(param.token, &error);
    if (!decl) {
        diagnostics.Error(param.loc, error);
        return false;
    }
    const bool wantsStrings = decl->type == ParamType::String;
    const bool empty = param.numbers.empty() && param.strings.empty();
    if (!empty && wantsStrings != param.isString) {
        diagnostics.Error(param.loc, "parameter \"" + param.token + "\" is declared " +
                                         ToString(decl->type) + " but has " +
                                         (param.isString ? "string" : "numeric") + " values");
        return false;
    }
    out->decl = *decl;
    out->components = decl->ComponentCount(colorComponents);
    if (wantsStrings) {
        out->strings = param.strings;
        return true;
    }
    if (param.numbers.size() % out->components != 0) {
        diagnostics.Error(param.loc, "parameter \"" + param.token + "\" needs a multiple of " +
                                         std::to_string(out->components) + " numbers, got " +
                                         std::to_string(param.numbers.size()));
        return false;
    }
    out->values.assign(param.numbers.begin(), param.numbers.end());
    return true;
}

bool TypePrimVars(const ParamList& params, const Declarations& declarations, int colorComponents,
                  Diagnostics& diagnostics, PrimVarSet* out) {
    bool ok = true;
    for (const Param& param : params) {
        PrimVar var;
        if (TypeParam(param, declarations, colorComponents, diagnostics, &var))
            out->vars.push_back(std::move(var));
        else
            ok = false;
    }
    return ok;
}

}  // namespace gonio
