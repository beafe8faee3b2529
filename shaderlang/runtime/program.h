#pragma once
// Compiled shader code: typed registers and three-address instructions (Pixie's .sdr in
// spirit). A register is uniform (one value per batch) or varying (one per point); an
// instruction is uniform exactly when its destination is, and then runs once per batch.
//
// Masks are a stack whose depth every instruction knows statically (`depth`): the points an
// instruction runs for are those of entry `depth`. Control instructions write the entries (see
// opcodes.h), so divergent if/while/for/break/continue/return need no run-time stack pointer.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "shaderlang/types.h"

namespace gonio::sl {

class RuntimeWarnings;  // interpreter.h

struct Register {
    TypeSpec type;
    bool varying = false;
    bool isString = false;
    int width = 0;          // floats per point (all elements); strings: element count
    bool constant = false;  // value in Program::constFloats / constStrings at constOffset
    int constOffset = -1;
    std::string name;          // variable name ("" for temporaries)
    int global = -1;           // GlobalId
    int param = -1;            // index in Shader::Params()
    bool temporary = true;     // written once (SSA-like); variables may be written many times
    bool fixedDetail = false;  // declared uniform/varying or a global: never re-inferred
    bool used = true;          // referenced by the code (unused registers get no memory)
};

struct Instr {
    uint16_t op = 0;
    uint8_t depth = 0;                   // mask-stack entry whose points this instruction runs for
    uint8_t argCount = 0;                // registers in args
    int32_t args[4] = {-1, -1, -1, -1};  // args[0] is the destination where there is one
    int32_t jump = -1;                   // control instructions: target (break/continue/return: the
                                         // region they leave)
    int32_t extra = 0;   // opcode-specific: mask entry, builtin row, call-list offset
    int32_t loc = 0;     // index into Program::locations (file:line) for run-time warnings
    int32_t region = 0;  // control region (for detail inference, see optimizer.cpp)
};

// Control regions: a nest of if/loop/function/light bodies. An instruction inside a region
// whose condition is varying runs under a varying mask.
struct Region {
    int parent = -1;
    int condition = -1;          // register; -1: none (function body, plain block)
    bool alwaysVarying = false;  // illuminance/illuminate/solar bodies
};

struct ParamCode {
    int reg = -1;
    int initBegin = 0, initEnd = 0;  // instructions that compute the default
};

// A parameter value set by the instance before the code runs: an override, or a primitive
// variable bound by name (with the override or constant default as the fallback).
struct Preset {
    int reg = -1;
    std::vector<float> floats;
    std::vector<std::string> strings;
    std::string primvar;  // non-empty: take the values from ShaderGlobals::primvars
};

struct Program {
    std::vector<Register> regs;
    std::vector<Instr> code;
    std::vector<int> callArgs;  // builtin calls: [result, args...] per call, at Instr::extra
    std::vector<float> constFloats;
    std::vector<std::string> constStrings;
    std::vector<std::string> locations;  // "file.sl:12"
    std::vector<Region> regions{Region{}};
    std::vector<ParamCode> params;     // by parameter index
    int globals[32];                   // register per GlobalId, -1 where unused
    int maxDepth = 1;                  // mask-stack entries needed
    std::map<std::string, int> named;  // top-level variables, parameters and globals
    std::vector<Preset> presets;
    bool ambientLight = true;                   // a light shader without illuminate or solar
    std::shared_ptr<RuntimeWarnings> warnings;  // shared by every instance's copy

    Program() {
        for (int& g : globals) g = -1;
    }
    int AddConstant(const std::vector<float>& values, TypeSpec type);
    int AddStringConstant(const std::vector<std::string>& values);
};

}  // namespace gonio::sl
