#pragma once
// The batched interpreter's state: register memory for n points, the mask stack, and what the
// control opcodes need (lights, the lit mask). Opcode functions (ops_*.cpp) work on it; each
// runs once per instruction per batch and loops over the points inside.

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "shaderlang/runtime/batch.h"
#include "shaderlang/runtime/globals_view.h"
#include "shaderlang/runtime/program.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl {

// Run-time warnings are reported once per source line (and message) for all instances of a
// shader, whatever the thread.
class RuntimeWarnings {
  public:
    bool First(int loc, const std::string& message) {
        std::lock_guard<std::mutex> lock(mutex_);
        return seen_.insert(std::to_string(loc) + message).second;
    }

  private:
    std::mutex mutex_;
    std::set<std::string> seen_;
};

struct MaskEntry {
    std::vector<uint8_t> bits;
    bool all = true;  // every point of the batch is active (bits not used)
};

// A register as the opcodes see it.
struct RegRef {
    float* data = nullptr;
    int width = 0;
    bool varying = false;
    int n = 1;
    // Component c (a float operand is broadcast: every component reads its one plane).
    float* Plane(int c) const {
        if (width == 1) c = 0;
        return data + (varying ? size_t(c) * n : size_t(c));
    }
    int Stride() const { return varying ? 1 : 0; }
};

struct ExecState final : GlobalsView {
    const Program* program = nullptr;
    int n = 0;
    int colorComponents = 3;
    std::vector<float> arena;
    std::vector<size_t> offsets;                    // per register, into arena
    std::vector<std::vector<std::string>> strings;  // per string register
    std::vector<MaskEntry> masks;
    ShadingContext* context = nullptr;
    RuntimeWarnings* warnings = nullptr;
    bool foldMode = false;  // constant folding: no context; a warning cancels the fold
    bool warned = false;
    int pc = 0;
    // The run's time budget (ShadingContext::ShaderTimeout), checked at loops' backward jumps;
    // past it the run is stopped (`stopped` ends every Execute) with an error.
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
    unsigned backwardJumps = 0;
    bool stopped = false;
    // Light loops. inputP: the P the run was given, at which the context's cached lights are
    // computed (a surface shader may since have written P).
    const float* inputP = nullptr;
    const std::vector<LightResult>* lights = nullptr;
    int lightIndex = -1;
    std::vector<uint8_t> lit;
    std::vector<float> illuminancePosition;  // a uniform illuminance position, replicated
    bool illuminated = false;
    bool solar = false;  // a solar() statement lit some point: the light is at infinity
    // Per point: solar() without an axis lit it (light from all directions, no L of its own).
    std::vector<uint8_t> allDirections;
    bool anyAllDirections = false;

    RegRef Reg(int r) const {
        const Register& info = program->regs[r];
        return RegRef{const_cast<float*>(arena.data()) + offsets[r], info.width, info.varying, n};
    }
    std::string& Str(int r, int element = 0) { return strings[r][element]; }
    // The points `in` runs for; nullptr: all.
    const uint8_t* Mask(const Instr& in) const {
        const MaskEntry& e = masks[in.depth];
        return e.all ? nullptr : e.bits.data();
    }
    bool Active(const uint8_t* mask, int i) const { return !mask || mask[i]; }
    void Warn(const Instr& in, const std::string& message);
    // At a loop's backward jump: stops the run once it is past its deadline.
    void CheckBudget(const Instr& in);

    // Lays out registers for `program` and n points (reusing memory when unchanged).
    void Prepare(const Program& program, int n, int colorComponents);
    // Runs program instructions [begin, end).
    void Execute(int begin, int end);

    FloatArg Get(const std::string& name) const override;
    const LightResult* CurrentLight() const override {
        const bool inLoop = lights && lightIndex >= 0 && lightIndex < int(lights->size());
        return inLoop ? &(*lights)[size_t(lightIndex)] : nullptr;
    }
};

// Copies entry `from` into `to`, optionally and-ed with a condition register (negated if
// `negate`); returns the number of active points (n when all are).
int SetMask(ExecState& x, int to, int from, const RegRef* cond, bool negate);

}  // namespace gonio::sl
