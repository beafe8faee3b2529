#include "shaderlang/brdf_files.h"

#include <algorithm>

#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/opcodes.h"
#include "shaderlang/runtime/program.h"

namespace gonio::sl {

std::vector<std::string> BrdfFiles(const ShaderInstance& instance) {
    std::vector<std::string> files;
    const Program& program = instance.Code();
    for (const Instr& in : program.code) {
        if (in.op != uint16_t(Op::Call)) continue;
        // callArgs at Instr::extra: builtin row, argument count, result, arguments (codegen.cpp)
        const int* call = &program.callArgs[size_t(in.extra)];
        if (std::string(BuiltinTable()[size_t(call[0])].name) != "brdf" || call[1] < 1) continue;
        const Register& grid = program.regs[size_t(call[3])];
        if (!grid.constant || !grid.isString) continue;
        const std::string& name = program.constStrings[size_t(grid.constOffset)];
        if (std::find(files.begin(), files.end(), name) == files.end()) files.push_back(name);
    }
    return files;
}

}  // namespace gonio::sl
