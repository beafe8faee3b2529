#include "shaderlang/message_passing.h"

#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/opcodes.h"
#include "shaderlang/runtime/program.h"

namespace gonio::sl {

void MessageShaders::Set(MessageSource source, const ShaderInstance* instance,
                         const ShaderExecutor* executor) {
    if (source == MessageSource::Light) return;  // lights answer through LightResult
    entries_[int(source)] = Entry{instance, executor};
}

bool MessageShaders::Find(MessageSource source, const std::string& name,
                          MessageValue* value) const {
    if (source == MessageSource::Light) return false;
    const Entry& entry = entries_[int(source)];
    if (!entry.instance || !entry.executor) return false;
    const ShaderParam* param = entry.instance->Master().FindParam(name);
    if (!param) return false;
    value->type = param->type;
    value->floats = FloatArg{};
    value->text = nullptr;
    if (param->type.base == BaseType::String) {
        value->text = entry.executor->OutputString(name);
        return value->text != nullptr;
    }
    value->floats = entry.executor->Output(name);
    return value->floats.data != nullptr;
}

void CaptureLightParameters(const ShaderInstance& instance, const ShaderExecutor& executor, int n,
                            LightResult* result) {
    result->parameters.clear();
    for (const ShaderParam& param : instance.Master().Params()) {
        LightResult::Parameter copy;
        copy.name = param.name;
        copy.type = param.type;
        if (param.type.base == BaseType::String) {
            const std::string* text = executor.OutputString(param.name);
            if (!text) continue;
            copy.text = *text;
        } else {
            const FloatArg value = executor.Output(param.name);
            if (!value.data) continue;
            copy.varying = value.varying;
            copy.width = value.width;
            const size_t count = size_t(value.width) * (value.varying ? size_t(n) : 1);
            copy.floats.assign(value.data, value.data + count);
        }
        result->parameters.push_back(std::move(copy));
    }
}

bool CallsBuiltin(const ShaderInstance& instance, const std::string& name) {
    const Program& program = instance.Code();
    for (const Instr& in : program.code) {
        if (in.op == uint16_t(Op::Call) && name == BuiltinTable()[program.callArgs[in.extra]].name)
            return true;
    }
    return false;
}

}  // namespace gonio::sl
