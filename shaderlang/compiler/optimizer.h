#pragma once
// Optimisation of compiled code, run on each instance once its parameter values are known
// (instance specialisation): constant folding (by running the opcodes themselves on one
// point), branch folding, dead-code and unreachable-code removal, and uniform/varying
// inference, which makes every local and temporary uniform unless a varying value or a varying
// condition reaches it.

#include <string>
#include <vector>

#include "shaderlang/runtime/program.h"

namespace gonio::sl {

struct OptimizeOptions {
    int colorComponents = 3;
    bool fold = true;
    bool keepNamed = false;   // keep top-level variables alive (for `gonio shade --print`)
    std::vector<int> pinned;  // registers never made constant (overridable parameters)
};

void Optimize(Program& program, const OptimizeOptions& options);

// The value of parameter `param`'s default when it is a constant expression (false if it
// depends on globals or other run-time values).
bool EvaluateDefault(const Program& program, int param, int colorComponents,
                     std::vector<float>* floats, std::vector<std::string>* strings);

// How often `reg` is written outside the instructions [begin, end).
int WritesOutside(const Program& program, int reg, int begin, int end);

// The bytecode as text, one instruction per line.
std::string Disassemble(const Program& program);

}  // namespace gonio::sl
