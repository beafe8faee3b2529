// ShaderInstance: parameter overrides, primitive-variable bindings, the specialised code and
// what it needs of the renderer.

#include <algorithm>

#include "shaderlang/compiler/optimizer.h"
#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/global_vars.h"
#include "shaderlang/runtime/opcodes.h"
#include "shaderlang/runtime/program.h"
#include "shaderlang/shading_system.h"

namespace gonio::sl {

ShaderInstance::ShaderInstance(std::shared_ptr<const Shader> shader) : shader_(std::move(shader)) {}
ShaderInstance::~ShaderInstance() = default;

namespace {

int ValueCount(const ShaderParam& p, int ncomps) {
    const int elements = p.type.IsArray() ? p.type.arrayLength : 1;
    return p.type.base == BaseType::String ? elements : p.type.Width(ncomps) * elements;
}

}  // namespace

bool ShaderInstance::SetParameter(const std::string& name, const std::vector<float>& values,
                                  std::string* error) {
    const ShaderParam* p = shader_->FindParam(name);
    if (!p) {
        *error = "shader '" + shader_->Name() + "' has no parameter '" + name + "'";
        return false;
    }
    if (p->type.base == BaseType::String) {
        *error = "parameter '" + name + "' is a string, not numbers";
        return false;
    }
    const int want = ValueCount(*p, shader_->ColorComponents());
    if (int(values.size()) != want) {
        *error = "parameter '" + name + "' (" + ToString(p->type) + ") takes " +
                 std::to_string(want) + " numbers, not " + std::to_string(values.size());
        return false;
    }
    overrides_[name] = Override{values, {}};
    return true;
}

bool ShaderInstance::SetParameter(const std::string& name, const std::vector<std::string>& values,
                                  std::string* error) {
    const ShaderParam* p = shader_->FindParam(name);
    if (!p) {
        *error = "shader '" + shader_->Name() + "' has no parameter '" + name + "'";
        return false;
    }
    if (p->type.base != BaseType::String) {
        *error = "parameter '" + name + "' is a " + ToString(p->type) + ", not a string";
        return false;
    }
    if (int(values.size()) != ValueCount(*p, shader_->ColorComponents())) {
        *error = "parameter '" + name + "' takes " +
                 std::to_string(ValueCount(*p, shader_->ColorComponents())) + " strings";
        return false;
    }
    overrides_[name] = Override{{}, values};
    return true;
}

bool ShaderInstance::BindPrimvar(const std::string& name) {
    if (!shader_->FindParam(name)) return false;
    if (!IsBound(name)) bound_.push_back(name);
    return true;
}

bool ShaderInstance::IsBound(const std::string& name) const {
    return std::find(bound_.begin(), bound_.end(), name) != bound_.end();
}

std::string ShaderInstance::StringParameter(const std::string& name) const {
    auto it = overrides_.find(name);
    if (it != overrides_.end() && !it->second.strings.empty()) return it->second.strings[0];
    const ShaderParam* p = shader_->FindParam(name);
    if (p && !p->defaultStrings.empty()) return p->defaultStrings[0];
    return "";
}

std::vector<float> ShaderInstance::FloatParameter(const std::string& name) const {
    auto it = overrides_.find(name);
    if (it != overrides_.end() && !it->second.floats.empty()) return it->second.floats;
    const ShaderParam* p = shader_->FindParam(name);
    return p ? p->defaultFloats : std::vector<float>{};
}

void ShaderInstance::Specialize() {
    std::call_once(specialized_, [this] {
        auto program = std::make_shared<Program>(shader_->Code());
        const int ncomps = shader_->ColorComponents();
        OptimizeOptions options;
        options.colorComponents = ncomps;
        options.keepNamed = keepVariables_;
        const auto& params = shader_->Params();
        for (size_t i = 0; i < params.size() && i < program->params.size(); ++i) {
            const ShaderParam& param = params[i];
            const ParamCode code = program->params[i];
            Register& reg = program->regs[code.reg];
            auto override = overrides_.find(param.name);
            const bool bound = IsBound(param.name);
            if (param.output) options.pinned.push_back(code.reg);
            if (override == overrides_.end() && !bound) continue;
            // The default's code is skipped; the value comes from the instance.
            if (code.initEnd > code.initBegin) {
                Instr& first = program->code[code.initBegin];
                first = Instr{};
                first.op = uint16_t(Op::Jump);
                first.jump = code.initEnd;
            }
            Preset preset;
            preset.reg = code.reg;
            if (override != overrides_.end()) {
                preset.floats = override->second.floats;
                preset.strings = override->second.strings;
            } else {
                preset.floats = param.defaultFloats;
                preset.strings = param.defaultStrings;
            }
            const int count = ValueCount(param, ncomps);
            if (reg.isString) {
                preset.strings.resize(size_t(count));
            } else {
                preset.floats.resize(size_t(count), 0.0f);
            }
            if (bound) {
                preset.primvar = param.name;
                reg.varying = true;
                reg.fixedDetail = true;
                options.pinned.push_back(code.reg);
                program->presets.push_back(preset);
            } else if (!param.output &&
                       WritesOutside(*program, code.reg, code.initBegin, code.initEnd) == 0) {
                reg.constant = true;
                reg.varying = false;
                reg.fixedDetail = true;
                reg.constOffset = reg.isString ? program->AddStringConstant(preset.strings)
                                               : program->AddConstant(preset.floats, reg.type);
            } else {
                options.pinned.push_back(code.reg);
                program->presets.push_back(preset);
            }
        }
        Optimize(*program, options);
        program_ = program;
    });
}

const Program& ShaderInstance::Code() const { return program_ ? *program_ : shader_->Code(); }

ShaderNeeds ShaderInstance::Needs() const {
    ShaderNeeds needs;
    const Program& program = Code();
    for (const Instr& in : program.code) {
        if (in.op != uint16_t(Op::Call)) continue;
        const unsigned flags = BuiltinTable()[program.callArgs[in.extra]].flags;
        if (flags & kNeedsDerivatives) needs.derivatives = true;
        if (flags & kTracesRays) needs.trace = true;
    }
    for (int id = 0; id < kGlobalCount; ++id) {
        const int reg = program.globals[id];
        if (reg < 0 || !program.regs[reg].used) continue;
        needs.globalsRead.push_back(GlobalVar(id).name);
        if (id == kGlobalDu || id == kGlobalDv) needs.derivatives = true;
    }
    return needs;
}

}  // namespace gonio::sl
