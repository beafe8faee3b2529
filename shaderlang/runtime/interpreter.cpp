#include "shaderlang/runtime/interpreter.h"

#include <cstring>

#include "shaderlang/runtime/global_vars.h"
#include "shaderlang/runtime/ops.h"

namespace gonio::sl {

namespace {

const OpInfo kOpTable[] = {
#define GONIO_SL_ROW(name, flags, fn) {#name, flags, fn},
    GONIO_SL_OPCODES(GONIO_SL_ROW)
#undef GONIO_SL_ROW
};

}  // namespace

const OpInfo& OpTable(Op op) { return kOpTable[int(op)]; }

int Program::AddConstant(const std::vector<float>& values, TypeSpec type) {
    int offset = int(constFloats.size());
    constFloats.insert(constFloats.end(), values.begin(), values.end());
    (void)type;
    return offset;
}

int Program::AddStringConstant(const std::vector<std::string>& values) {
    int offset = int(constStrings.size());
    constStrings.insert(constStrings.end(), values.begin(), values.end());
    return offset;
}

void ExecState::Prepare(const Program& p, int points, int ncomps) {
    program = &p;
    n = points;
    colorComponents = ncomps;
    offsets.assign(p.regs.size(), 0);
    strings.resize(p.regs.size());
    size_t size = 0;
    for (size_t r = 0; r < p.regs.size(); ++r) {
        const Register& reg = p.regs[r];
        if (!reg.used) continue;
        if (reg.isString) {
            strings[r].assign(size_t(std::max(1, reg.width)), std::string());
            continue;
        }
        offsets[r] = size;
        size += size_t(reg.width) * (reg.varying ? size_t(n) : 1);
        size = (size + 7) & ~size_t(7);  // 32-byte alignment of every plane set
    }
    if (arena.size() < size + 16) arena.resize(size + 16);
    for (size_t r = 0; r < p.regs.size(); ++r) {
        const Register& reg = p.regs[r];
        if (!reg.used || !reg.constant) continue;
        if (reg.isString) {
            for (int k = 0; k < reg.width; ++k) strings[r][k] = p.constStrings[reg.constOffset + k];
        } else if (reg.varying) {
            for (int c = 0; c < reg.width; ++c) {
                std::fill_n(&arena[offsets[r] + size_t(c) * n], n,
                            p.constFloats[reg.constOffset + c]);
            }
        } else {
            std::memcpy(&arena[offsets[r]], &p.constFloats[reg.constOffset],
                        sizeof(float) * size_t(reg.width));
        }
    }
    masks.resize(size_t(p.maxDepth) + 2);
    for (MaskEntry& e : masks) {
        e.bits.resize(size_t(n));
        e.all = true;
    }
    lit.assign(size_t(n), 0);
    allDirections.assign(size_t(n), 0);
    anyAllDirections = false;
    illuminated = false;
    solar = false;
    lights = nullptr;
    deadline = std::chrono::steady_clock::time_point::max();
    backwardJumps = 0;
    stopped = false;
}

void ExecState::Execute(int begin, int end) {
    const Instr* code = program->code.data();
    pc = begin;
    while (pc < end && !stopped) {
        const Instr& in = code[pc++];
        kOpTable[in.op].run(*this, in);
    }
}

void ExecState::CheckBudget(const Instr& in) {
    // The clock is read every 1024 iterations: a loop body costs far more than that check.
    if (deadline == std::chrono::steady_clock::time_point::max() || ++backwardJumps % 1024 != 0)
        return;
    if (std::chrono::steady_clock::now() < deadline) return;
    stopped = true;
    if (!context) return;
    context->SetStatement(&program->locations[in.loc]);
    context->ShaderTimedOut(context->ShaderTimeout());
}

void ExecState::Warn(const Instr& in, const std::string& message) {
    warned = true;
    if (foldMode || !context) return;
    if (warnings && !warnings->First(in.loc, message)) return;
    context->SetStatement(&program->locations[in.loc]);
    context->RuntimeWarning(message, message);
}

FloatArg ExecState::Get(const std::string& name) const {
    auto it = program->named.find(name);
    if (it == program->named.end()) return FloatArg{};
    const Register& reg = program->regs[it->second];
    if (reg.isString || !reg.used) return FloatArg{};
    RegRef r = Reg(it->second);
    return FloatArg{r.data, reg.width, reg.varying, n};
}

}  // namespace gonio::sl
