#include "renderer/shading/shader_needs.h"

#include <algorithm>
#include <string>

#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/global_vars.h"
#include "shaderlang/runtime/opcodes.h"
#include "shaderlang/runtime/program.h"

namespace gonio {

ShaderNeeds ScanShaderNeeds(const sl::ShaderInstance* instance) {
    ShaderNeeds needs;
    if (!instance) return needs;
    // The specialised code: a derivative in a branch that the instance's constants remove
    // costs nothing.
    const sl::Program& program = instance->Code();
    for (const sl::Instr& in : program.code) {
        if (in.op != uint16_t(sl::Op::Call)) continue;
        const sl::BuiltinInfo& info = sl::BuiltinTable()[program.callArgs[in.extra]];
        if (info.flags & sl::kNeedsDerivatives) needs.derivatives = true;
        if (std::string(info.name) == "trace") needs.trace = true;
    }
    for (int id : {sl::kGlobalDu, sl::kGlobalDv}) {
        const int reg = program.globals[id];
        if (reg >= 0 && program.regs[reg].used) needs.derivatives = true;
    }
    return needs;
}

int TraceMaxDepth(const Frame& frame) {
    auto it = frame.options.user.find("trace");
    if (it == frame.options.user.end()) return kDefaultTraceMaxDepth;
    for (const Param& p : it->second) {
        // "maxdepth", "integer maxdepth", "uniform float maxdepth", ...
        const size_t space = p.token.rfind(' ');
        const std::string name = space == std::string::npos ? p.token : p.token.substr(space + 1);
        if (name == "maxdepth" && !p.isString && !p.numbers.empty())
            return std::max(0, int(p.numbers[0]));
    }
    return kDefaultTraceMaxDepth;
}

}  // namespace gonio
