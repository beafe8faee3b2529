#include "shaderlang/compiler/optimizer.h"

#include <algorithm>
#include <sstream>

#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/interpreter.h"
#include "shaderlang/runtime/opcodes.h"

namespace gonio::sl {

namespace {

constexpr unsigned kRunTimeOnly = kVaryingResult | kReadsGlobals | kUsesLights | kHasSideEffects |
                                  kNeedsDerivatives | kReadsFiles | kTracesRays | kSamplesRays |
                                  kUsesSpaces | kDrawsRandom;

bool HasJumpTarget(Op op) {
    return op == Op::Jump || op == Op::If || op == Op::Else || op == Op::LoopTest ||
           op == Op::IllumNext || op == Op::Illuminate || op == Op::Solar;
}

bool HasOutputArgs(int row) {
    for (const BuiltinParameter& param : BuiltinSignatureOf(row).parameters) {
        if (param.output) return true;
    }
    return false;
}

// Registers an instruction reads and writes.
void Operands(const Program& p, const Instr& in, std::vector<int>* reads,
              std::vector<int>* writes) {
    reads->clear();
    writes->clear();
    const Op op = Op(in.op);
    if (op == Op::Call) {
        const int* list = &p.callArgs[in.extra];
        const BuiltinInfo& info = BuiltinTable()[list[0]];
        const std::vector<BuiltinParameter>& params = BuiltinSignatureOf(list[0]).parameters;
        if (list[2] >= 0) writes->push_back(list[2]);
        for (int k = 0; k < list[1]; ++k) {
            reads->push_back(list[3 + k]);
            const bool param = size_t(k) < params.size();
            if (param && params[size_t(k)].output) writes->push_back(list[3 + k]);
            // An output option's variable follows its name (a string constant).
            if (!param && k > 0 && (info.flags & (kOutputOptions | kOutputPairs))) {
                const Register& name = p.regs[list[3 + k - 1]];
                if (name.isString && name.constant &&
                    IsOutputOption(info.flags, p.constStrings[size_t(name.constOffset)]))
                    writes->push_back(list[3 + k]);
            }
        }
        return;
    }
    const bool writesFirst = OpTable(op).flags & kOpWrites;
    for (int k = 0; k < in.argCount; ++k) {
        if (in.args[k] < 0) continue;
        if (k == 0 && writesFirst) {
            writes->push_back(in.args[0]);
        } else {
            reads->push_back(in.args[k]);
        }
    }
    if (op == Op::IndexWrite) writes->push_back(in.args[0]);
}

bool Foldable(const Program& p, const Instr& in) {
    const Op op = Op(in.op);
    if (op == Op::Call) {
        const int row = p.callArgs[in.extra];
        return !(BuiltinTable()[size_t(row)].flags & kRunTimeOnly) && !HasOutputArgs(row) &&
               p.callArgs[in.extra + 2] >= 0;
    }
    return (OpTable(op).flags & kOpPure) && (OpTable(op).flags & kOpWrites);
}

class Optimizer {
  public:
    Optimizer(Program& p, const OptimizeOptions& o) : p_(p), o_(o) {}

    void Run() {
        if (o_.fold) {
            Fold();
            RemoveUnreachable();
        }
        RemoveDeadCode();
        Compact();
        RemoveJumpsToNext();
        InferDetail();
        MarkUsed();
    }

  private:
    void Fold();
    void FoldBranch(Instr& in);
    void RemoveUnreachable();
    void RemoveDeadCode();
    void Compact();
    void RemoveJumpsToNext();
    void InferDetail();
    void MarkUsed();
    bool Pinned(int r) const {
        return std::find(o_.pinned.begin(), o_.pinned.end(), r) != o_.pinned.end();
    }

    Program& p_;
    const OptimizeOptions& o_;
    std::vector<bool> removed_;
};

void Optimizer::Fold() {
    removed_.assign(p_.code.size(), false);
    std::vector<int> writeCount(p_.regs.size(), 0);
    std::vector<int> reads, writes;
    for (const Instr& in : p_.code) {
        Operands(p_, in, &reads, &writes);
        for (int w : writes) ++writeCount[w];
    }
    ExecState fx;
    fx.foldMode = true;
    fx.Prepare(p_, 1, o_.colorComponents);
    for (size_t i = 0; i < p_.code.size(); ++i) {
        Instr& in = p_.code[i];
        if (OpTable(in.op).flags & kOpControl) {
            FoldBranch(in);
            continue;
        }
        if (!Foldable(p_, in)) continue;
        Operands(p_, in, &reads, &writes);
        if (writes.size() != 1) continue;
        const int d = writes[0];
        Register& reg = p_.regs[d];
        if (writeCount[d] != 1 || reg.global >= 0 || Pinned(d) || reg.constant) continue;
        bool constantInputs = true;
        for (int r : reads) constantInputs = constantInputs && p_.regs[r].constant;
        if (!constantInputs) continue;
        fx.warned = false;
        fx.Execute(int(i), int(i) + 1);
        if (fx.warned) continue;  // keep it, so the warning comes at run time
        if (reg.isString) {
            reg.constOffset = p_.AddStringConstant(fx.strings[d]);
        } else {
            const float* v = fx.Reg(d).data;
            reg.constOffset = p_.AddConstant(std::vector<float>(v, v + reg.width), reg.type);
        }
        reg.constant = true;
        reg.varying = false;
        reg.fixedDetail = true;
        removed_[i] = true;
    }
}

void Optimizer::FoldBranch(Instr& in) {
    const Op op = Op(in.op);
    if ((op != Op::If && op != Op::Else && op != Op::LoopTest) || !p_.regs[in.args[0]].constant) {
        return;
    }
    const bool value = p_.constFloats[p_.regs[in.args[0]].constOffset] != 0.0f;
    const bool taken = op == Op::Else ? !value : value;  // the branch's points run
    if (op == Op::LoopTest && taken) return;
    if (taken) {
        in.op = uint16_t(Op::Enter);
        in.argCount = 0;
        in.args[0] = -1;
    } else {
        in.op = uint16_t(Op::Jump);
        in.argCount = 0;
        in.args[0] = -1;
    }
}

void Optimizer::RemoveUnreachable() {
    std::vector<bool> reached(p_.code.size(), false);
    std::vector<int> work{0};
    while (!work.empty()) {
        int i = work.back();
        work.pop_back();
        if (i >= int(p_.code.size()) || reached[i]) continue;
        reached[i] = true;
        const Instr& in = p_.code[i];
        const Op op = Op(in.op);
        if (HasJumpTarget(op)) work.push_back(in.jump);
        if (op != Op::Jump) work.push_back(i + 1);
    }
    for (size_t i = 0; i < p_.code.size(); ++i) {
        if (!reached[i]) removed_[i] = true;
    }
}

void Optimizer::RemoveDeadCode() {
    if (removed_.size() != p_.code.size()) removed_.assign(p_.code.size(), false);
    std::vector<bool> root(p_.regs.size(), false);
    for (size_t r = 0; r < p_.regs.size(); ++r) {
        const Register& reg = p_.regs[r];
        if (reg.global >= 0 || Pinned(int(r))) root[r] = true;
    }
    for (const auto& [name, r] : p_.named) {
        if (o_.keepNamed || p_.regs[r].param >= 0) root[r] = true;
    }
    std::vector<int> reads, writes;
    for (bool changed = true; changed;) {
        changed = false;
        std::vector<bool> read(p_.regs.size(), false);
        for (size_t i = 0; i < p_.code.size(); ++i) {
            if (removed_[i]) continue;
            Operands(p_, p_.code[i], &reads, &writes);
            for (int r : reads) read[r] = true;
        }
        for (size_t i = 0; i < p_.code.size(); ++i) {
            if (removed_[i]) continue;
            const Instr& in = p_.code[i];
            const Op op = Op(in.op);
            bool removable = (OpTable(op).flags & kOpPure) || op == Op::SetComp ||
                             op == Op::IndexWrite || op == Op::SpaceCast ||
                             (op == Op::Call && Foldable(p_, in));
            if (op == Op::Call) {
                const int row = p_.callArgs[in.extra];
                removable =
                    !(BuiltinTable()[size_t(row)].flags & kHasSideEffects) && !HasOutputArgs(row);
            }
            if (!removable) continue;
            Operands(p_, in, &reads, &writes);
            bool needed = false;
            for (int w : writes) needed = needed || read[w] || root[w];
            if (!needed) {
                removed_[i] = true;
                changed = true;
            }
        }
    }
}

void Optimizer::Compact() {
    const int size = int(p_.code.size());
    std::vector<int> newIndex(size_t(size) + 1);
    int kept = 0;
    for (int i = 0; i < size; ++i) {
        newIndex[i] = kept;
        if (!removed_[i]) ++kept;
    }
    newIndex[size] = kept;
    std::vector<Instr> code;
    code.reserve(size_t(kept));
    for (int i = 0; i < size; ++i) {
        if (removed_[i]) continue;
        Instr in = p_.code[i];
        if (HasJumpTarget(Op(in.op))) in.jump = newIndex[std::min(in.jump, size)];
        code.push_back(in);
    }
    for (ParamCode& pc : p_.params) {
        pc.initBegin = newIndex[pc.initBegin];
        pc.initEnd = newIndex[pc.initEnd];
    }
    p_.code = std::move(code);
    removed_.assign(p_.code.size(), false);
}

void Optimizer::RemoveJumpsToNext() {
    bool any = false;
    for (size_t i = 0; i < p_.code.size(); ++i) {
        const Instr& in = p_.code[i];
        if (Op(in.op) == Op::Jump && in.jump == int(i) + 1) {
            removed_[i] = true;
            any = true;
        }
    }
    if (any) Compact();
}

void Optimizer::InferDetail() {
    std::vector<bool> candidate(p_.regs.size(), false);
    for (size_t r = 0; r < p_.regs.size(); ++r) {
        Register& reg = p_.regs[r];
        if (!reg.fixedDetail && !reg.constant && !reg.isString) {
            candidate[r] = true;
            reg.varying = false;
        }
    }
    const size_t regionCount = p_.regions.size();
    std::vector<bool> exitVarying(regionCount, false), regionVarying(regionCount, false);
    std::vector<int> reads, writes;
    for (bool changed = true; changed;) {
        changed = false;
        for (size_t r = 0; r < regionCount; ++r) {
            const Region& region = p_.regions[r];
            bool v = region.alwaysVarying || exitVarying[r] ||
                     (region.condition >= 0 && p_.regs[region.condition].varying);
            if (region.parent >= 0 && r > 0) v = v || regionVarying[region.parent];
            regionVarying[r] = v;
        }
        for (const Instr& in : p_.code) {
            const Op op = Op(in.op);
            const bool control = regionVarying[in.region];
            if (op == Op::Exit && control && !exitVarying[in.jump]) {
                exitVarying[in.jump] = true;
                changed = true;
            }
            Operands(p_, in, &reads, &writes);
            if (writes.empty()) continue;
            bool v = false;
            for (int r : reads) v = v || p_.regs[r].varying;
            if (op == Op::Call &&
                (BuiltinTable()[p_.callArgs[in.extra]].flags &
                 (kVaryingResult | kReadsGlobals | kUsesLights | kNeedsDerivatives))) {
                v = true;
            }
            for (int w : writes) {
                bool wv = v || (control && !p_.regs[w].temporary);
                if (op == Op::IndexWrite && w == in.args[0]) {
                    wv = p_.regs[in.args[1]].varying || p_.regs[in.args[2]].varying || control;
                }
                if (wv && candidate[w] && !p_.regs[w].varying) {
                    p_.regs[w].varying = true;
                    changed = true;
                }
            }
        }
    }
}

void Optimizer::MarkUsed() {
    for (Register& reg : p_.regs) reg.used = reg.global >= 0 || reg.param >= 0;
    for (const auto& [name, r] : p_.named) p_.regs[r].used = true;
    for (const Preset& preset : p_.presets) p_.regs[preset.reg].used = true;
    std::vector<int> reads, writes;
    for (const Instr& in : p_.code) {
        Operands(p_, in, &reads, &writes);
        for (int r : reads) p_.regs[r].used = true;
        for (int r : writes) p_.regs[r].used = true;
    }
}

}  // namespace

void Optimize(Program& program, const OptimizeOptions& options) {
    Optimizer(program, options).Run();
}

bool EvaluateDefault(const Program& p, int param, int colorComponents, std::vector<float>* floats,
                     std::vector<std::string>* strings) {
    if (param < 0 || param >= int(p.params.size())) return false;
    const ParamCode& code = p.params[param];
    std::vector<bool> written(p.regs.size(), false);
    written[code.reg] = true;  // array elements are stored one by one
    std::vector<int> reads, writes;
    for (int i = code.initBegin; i < code.initEnd; ++i) {
        const Instr& in = p.code[i];
        if (!Foldable(p, in) && Op(in.op) != Op::IndexWrite && Op(in.op) != Op::SetComp)
            return false;
        Operands(p, in, &reads, &writes);
        for (int r : reads) {
            if (!p.regs[r].constant && !written[r]) return false;
        }
        for (int w : writes) written[w] = true;
    }
    ExecState fx;
    fx.foldMode = true;
    fx.Prepare(p, 1, colorComponents);
    fx.Execute(code.initBegin, code.initEnd);
    const Register& reg = p.regs[code.reg];
    if (reg.isString) {
        *strings = fx.strings[code.reg];
    } else {
        const float* v = fx.Reg(code.reg).data;
        floats->assign(v, v + reg.width);
    }
    return true;
}

int WritesOutside(const Program& p, int reg, int begin, int end) {
    int count = 0;
    std::vector<int> reads, writes;
    for (int i = 0; i < int(p.code.size()); ++i) {
        if (i >= begin && i < end) continue;
        Operands(p, p.code[i], &reads, &writes);
        for (int w : writes) count += w == reg;
    }
    return count;
}

std::string Disassemble(const Program& p) {
    std::ostringstream out;
    auto reg = [&](int r) {
        if (r < 0) return std::string("-");
        const Register& info = p.regs[r];
        std::string s = info.name.empty() ? "$" + std::to_string(r) : info.name;
        if (info.constant) {
            s = info.isString ? "\"" + p.constStrings[info.constOffset] + "\""
                              : std::to_string(p.constFloats[info.constOffset]);
            if (info.width > 1 && !info.isString) s = "(" + s + ",...)";
        }
        return s;
    };
    for (size_t i = 0; i < p.code.size(); ++i) {
        const Instr& in = p.code[i];
        const Op op = Op(in.op);
        out << i << ":\t" << std::string(size_t(in.depth), ' ') << OpTable(op).name;
        if (op == Op::Call) {
            const int* list = &p.callArgs[in.extra];
            out << " " << BuiltinTable()[list[0]].name << " " << reg(list[2]);
            for (int k = 0; k < list[1]; ++k) out << " " << reg(list[3 + k]);
        } else {
            for (int k = 0; k < in.argCount; ++k) out << " " << reg(in.args[k]);
        }
        if (HasJumpTarget(op)) out << " -> " << in.jump;
        if (in.argCount && in.args[0] >= 0 && (OpTable(op).flags & kOpWrites)) {
            out << (p.regs[in.args[0]].varying ? "\t[varying]" : "\t[uniform]");
        }
        out << "\n";
    }
    return out.str();
}

}  // namespace gonio::sl
